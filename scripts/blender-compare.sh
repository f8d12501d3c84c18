#!/usr/bin/env bash
# Blender Cycles comparison for the accuracy report (docs/accuracy.md, "Against Blender Cycles").
# Optional: needs Debian's blender and python3-numpy (its glTF importer uses numpy); nothing in
# the build, the tests or CI needs them.
#
#   scripts/blender-compare.sh [OUT_DIR]     default OUT_DIR: build/report/blender
#
# Writes into OUT_DIR: lights.json (the comparison lights, from accuracy_report), calibration.txt
# (bench/blender_bake.py --calibrate: each light mapping against a value computed by hand),
# cycles-S.txt and cycles-times.txt (the Cycles bakes, S samples each, one thread) and
# vlit-bake.txt (stage times of `vlit bake --explain` on the same asset and lights, three runs).
# scripts/accuracy-report.sh runs this when blender is installed and reads OUT_DIR; the report
# program computes the errors. Samples: VLIT_CYCLES_SAMPLES (default 1,4,16,64,256,1024).
# Exit status 3 when blender is not installed (nothing written).
set -euo pipefail
cd "$(dirname "$0")/.."

if ! command -v blender >/dev/null; then
  echo "blender-compare: blender not found (Debian: apt-get install blender python3-numpy); no Cycles data" >&2
  exit 3
fi
build=${VLIT_REPORT_BUILD_DIR:-build/report}
out=${1:-$build/blender}
samples=${VLIT_CYCLES_SAMPLES:-1,4,16,64,256,1024}
# docs/accuracy.md used DamagedHelmet.glb (Khronos sample, not vendored); default: the vendored Avocado.
asset=${VLIT_ACCURACY_ASSET:-assets/samples/Avocado/Avocado.gltf}

if [[ ! -f "$build/CMakeCache.txt" ]]; then
  cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
cmake --build "$build" --target accuracy_report vlit -j2 >/dev/null

rm -rf "$out"
mkdir -p "$out"
"$build/bench/accuracy_report" --asset "$asset" --write-blender-lights "$out/lights.json"
echo "blender-compare: calibration (one light at a time over a plane) ..." >&2
blender -b --factory-startup --python-exit-code 1 --python bench/blender_bake.py -- --calibrate --threads 1 --out "$out" \
  > "$out/blender-calibrate.log" 2>&1 || { echo "blender-compare: calibration failed, see $out/blender-calibrate.log" >&2; exit 1; }
grep '^blender_bake:' "$out/blender-calibrate.log" >&2
echo "blender-compare: Cycles bakes of $(basename "$asset"), samples $samples, one thread ..." >&2
blender -b --factory-startup --python-exit-code 1 --python bench/blender_bake.py -- --asset "$asset" --lights "$out/lights.json" \
  --samples "$samples" --threads 1 --out "$out" > "$out/blender-bake.log" 2>&1 \
  || { echo "blender-compare: Cycles bake failed, see $out/blender-bake.log" >&2; exit 1; }
grep '^blender_bake:' "$out/blender-bake.log" >&2
: > "$out/vlit-bake.txt"
for run in 1 2 3; do
  "$build/vlit" bake "$asset" --lights "$out/lights.json" --no-file-lights --color-format float --explain --quiet \
    -o "$out/vlit-baked.glb" | grep '^time:' >> "$out/vlit-bake.txt"
done
cat "$out/vlit-bake.txt" >&2
echo "blender-compare: wrote $out" >&2
