#!/usr/bin/env bash
# Blender Cycles with shadows against vlit's exact shadows (docs/shadows.md, "Against Blender Cycles with shadows").
# Optional: needs Debian's blender and python3-numpy; nothing in the build, the tests or CI
# needs them.
#
#   scripts/cycles-shadows-compare.sh ASSET LIGHTS.json [OUT_DIR]   default OUT_DIR: build/cycles-shadows/NAME
#
# 1. Cycles bakes ASSET under LIGHTS.json with shadows on (bench/blender_bake.py --shadows; white
#    diffuse, direct light, one thread), samples VLIT_CYCLES_SAMPLES (default 1,4,16,64,256);
# 2. vlit probe --occluders ASSET --snap-to-vertices computes the exact shadowed diffuse at
#    Cycles' face corners;
# 3. vlit bake --shadows on (one thread, three runs) gives vlit's time for the whole asset;
# 4. bench/cycles_shadow_errors.py prints the table (Cycles' error against vlit per sample count,
#    and the time ratio) and writes plot.gp, drawn into OUT_DIR/cycles-vs-vlit.png by gnuplot.
# Exit status 3 when blender is not installed (nothing written).
set -euo pipefail
cd "$(dirname "$0")/.."
if [[ $# -lt 2 ]]; then
  echo "usage: scripts/cycles-shadows-compare.sh ASSET LIGHTS.json [OUT_DIR]" >&2
  exit 2
fi
asset=$1
lights=$2
name=$(basename "${asset%.*}")
out=${3:-build/cycles-shadows/$name}
samples=${VLIT_CYCLES_SAMPLES:-1,4,16,64,256}
for f in "$asset" "$lights"; do
  [[ -f "$f" ]] || { echo "cycles-shadows-compare: $f: no such file" >&2; exit 2; }
done
if ! command -v blender >/dev/null; then
  echo "cycles-shadows-compare: blender not found (Debian: apt-get install blender python3-numpy); nothing compared" >&2
  exit 3
fi
build=${VLIT_BUILD_DIR:-build/release}
[[ -x "$build/vlit" ]] || { echo "cycles-shadows-compare: $build/vlit not built (cmake --preset release && cmake --build build/release)" >&2; exit 2; }

rm -rf "$out"
mkdir -p "$out"
echo "cycles-shadows-compare: Cycles bakes of $name with shadows, samples $samples, one thread ..." >&2
blender -b --factory-startup --python-exit-code 1 --python bench/blender_bake.py -- --asset "$asset" --lights "$lights" \
  --samples "$samples" --threads 1 --shadows --out "$out" > "$out/blender-bake.log" 2>&1 \
  || { echo "cycles-shadows-compare: Cycles bake failed, see $out/blender-bake.log" >&2; exit 1; }
grep '^blender_bake:' "$out/blender-bake.log" >&2

first=$(echo "$samples" | cut -d, -f1)
# Probe points: Cycles' corners (position, corner normal); eye and shininess do not matter for
# the diffuse. Cycles writes single-precision world positions; --snap-to-vertices puts each back
# on the vertex it stands for (exactly, also under node transforms): a probe point a rounding
# error off a vertex is not that vertex, and its own triangles can hide the light from it.
python3 - "$out/cycles-$first.txt" > "$out/corners.csv" <<'PY'
import struct, sys
single = lambda x: struct.unpack("f", struct.pack("f", float(x)))[0]
print("px,py,pz,nx,ny,nz,ex,ey,ez,m")
for line in open(sys.argv[1]):
    x, y, z, nx, ny, nz = (float(v) for v in line.split()[:6])
    p = [single(x), single(y), single(z)]
    print(",".join(repr(v) for v in p + [nx, ny, nz, p[0] + nx, p[1] + ny, p[2] + nz, 1.0]))
PY
"$build/vlit" probe --lights "$lights" --points "$out/corners.csv" --occluders "$asset" --snap-to-vertices --specular none \
  > "$out/probe.csv" 2> "$out/probe.log"
cat "$out/probe.log" >&2

: > "$out/vlit-times.txt"
for run in 1 2 3; do
  rm -f "$out/vlit-baked.glb"  # vlit never overwrites an output
  OMP_NUM_THREADS=1 "$build/vlit" bake "$asset" --lights "$lights" --no-file-lights --shadows on --color-format float \
    --explain --quiet -o "$out/vlit-baked.glb" \
    | sed -n 's/^time: .*light \([0-9.]*\) s.*/\1/p' >> "$out/vlit-times.txt"
done
python3 bench/cycles_shadow_errors.py "$out" "$name" | tee "$out/table.md"
if command -v gnuplot >/dev/null; then
  (cd "$out" && gnuplot plot.gp) && echo "cycles-shadows-compare: plot in $out/cycles-vs-vlit.png" >&2
else
  echo "cycles-shadows-compare: gnuplot not found, $out/plot.gp not drawn (Debian: apt-get install gnuplot-nox)" >&2
fi
