#!/usr/bin/env bash
# Byte-for-byte comparison of two vlit binaries on the same inputs: bakes (demo, paper scenes with
# each of their light sets, with and without shadows, file lights, the vendored samples), renders
# of the paper scenes (shaded, wireframe, normals) and probes (every specular method, double and
# float, with occluders). For refactors that must not change any output.
#
#   scripts/compare-outputs.sh OLD_VLIT NEW_VLIT [WORK_DIR]
#
# Prints one line per output that differs or that only one binary wrote, then a summary; exit 0
# when every output is identical, 1 otherwise. WORK_DIR (default: a new temporary directory)
# keeps the outputs for inspection.
set -euo pipefail
cd "$(dirname "$0")/.."
if [[ $# -lt 2 ]]; then
  echo "usage: scripts/compare-outputs.sh OLD_VLIT NEW_VLIT [WORK_DIR]" >&2
  exit 2
fi
old=$(realpath "$1")
new=$(realpath "$2")
for b in "$old" "$new"; do
  [[ -x "$b" ]] || { echo "compare-outputs: $b: not an executable" >&2; exit 2; }
done
work=${3:-$(mktemp -d)}
mkdir -p "$work/old" "$work/new"

# Probe points: a fixed grid of positions, normals and eyes in front of the paper scenes' lights.
points="$work/points.csv"
awk 'BEGIN {
  print "px,py,pz,nx,ny,nz,ex,ey,ez,m"
  for (i = 0; i < 6; ++i) for (j = 0; j < 6; ++j)
    printf "%g,%g,%g,%g,%g,%g,%g,%g,%g,%g\n", i - 2.5, 0.01 * j, j - 2.5, 0.1 * (i - 3), 1, 0.05 * j, 0.5 * i, 3, 4 - j, 2 ^ (i + j % 3)
}' >"$points"

# Each command runs with OUT replaced by the binary's own output directory.
commands=(
  "bake assets/demo/studio.glb --lights assets/demo/lights.json -o OUT/demo.glb"
  "bake assets/demo/studio.glb --lights assets/demo/lights.json --color-format float -o OUT/demo-float.glb"
  "bake assets/examples/file-lights.glb -o OUT/file-lights.glb"
  "bake assets/samples/Avocado/Avocado.gltf --lights assets/demo/lights.json -o OUT/avocado.gltf"
  "bake assets/samples/BoxInterleaved/BoxInterleaved.gltf --lights assets/demo/lights.json -o OUT/box-interleaved.glb"
  "bake assets/samples/LightsPunctualLamp/LightsPunctualLamp.gltf -o OUT/lamp.glb"
  "render assets/demo/studio.glb --lights assets/demo/lights.json -o OUT/demo.png --width 200 --height 150 --samples 4 --quiet"
  "render assets/demo/studio.glb --lights assets/demo/lights.json -o OUT/demo-wire.png --width 160 --height 120 --view wireframe --quiet"
  "render assets/demo/studio.glb -o OUT/demo-normals.png --width 160 --height 120 --view normals --quiet"
)
for scene in bowling studio; do
  for light in spot linear area; do
    commands+=(
      "bake assets/paper/$scene.glb --lights assets/paper/$scene-$light.json -o OUT/$scene-$light.glb"
      "bake assets/paper/$scene.glb --lights assets/paper/$scene-$light.json --shadows on -o OUT/$scene-$light-shadows.glb"
      "render assets/paper/$scene.glb --lights assets/paper/$scene-$light.json -o OUT/$scene-$light.png --width 160 --height 120 --samples 4 --quiet"
      "render assets/paper/$scene.glb --lights assets/paper/$scene-$light.json -o OUT/$scene-$light-shadows.png --width 120 --height 90 --shadows on --quiet"
    )
    for spec in peak neighborhood:4 exact none; do
      commands+=("probe --lights assets/paper/$scene-$light.json --points $points --specular $spec")
    done
    commands+=(
      "probe --lights assets/paper/$scene-$light.json --points $points --precision float"
      "probe --lights assets/paper/$scene-$light.json --points $points --occluders assets/paper/$scene.glb"
    )
  done
done

differ=0
count=0
for c in "${commands[@]}"; do
  count=$((count + 1))
  for side in old new; do
    bin=$old
    [[ $side == new ]] && bin=$new
    # shellcheck disable=SC2086  # the command is a list of words
    "$bin" ${c//OUT/$work/$side} >"$work/$side/stdout-$count.txt" 2>"$work/$side/stderr-$count.txt" || echo "exit $?" >>"$work/$side/stdout-$count.txt"
  done
  if ! cmp -s "$work/old/stdout-$count.txt" "$work/new/stdout-$count.txt"; then
    echo "differs: standard output of: vlit $c"
    differ=$((differ + 1))
  fi
done
for f in "$work"/old/* "$work"/new/*; do
  name=$(basename "$f")
  [[ $name == stdout-* || $name == stderr-* ]] && continue
  other="$work/new/$name"
  [[ $f == "$work"/new/* ]] && { [[ -e "$work/old/$name" ]] && continue; echo "only the new binary wrote $name"; differ=$((differ + 1)); continue; }
  if [[ ! -e $other ]]; then
    echo "only the old binary wrote $name"
    differ=$((differ + 1))
  elif ! cmp -s "$f" "$other"; then
    echo "differs: $name"
    differ=$((differ + 1))
  fi
done
files=$(find "$work/old" -type f ! -name 'stdout-*' ! -name 'stderr-*' | wc -l)
echo "compare-outputs: $count commands, $files output files, $differ differences (outputs in $work)"
[[ $differ -eq 0 ]]
