#!/usr/bin/env bash
# Whole-command wall times with the exact specular against --specular none (issue 21's bars,
# docs/performance.md "Specular end to end"): the median of 5 runs of each, and their ratio, for
# the demo render (assets/demo, 960 x 720) and for any further ASSET LIGHTS EYE triples given as
# arguments, baked with --specular-eye EYE. Prints the machine's load before and after (the times
# mean little on a busy machine).
# Usage: scripts/specular-times.sh [ASSET LIGHTS EYE ...]      (build dir: build/release)
set -euo pipefail
cd "$(dirname "$0")/.."
vlit="${BUILD_DIR:-build/release}/vlit"
[[ -x "$vlit" ]] || { echo "specular-times: $vlit not built (cmake --workflow --preset release)" >&2; exit 2; }
(( $# % 3 == 0 )) || { echo "usage: $0 [ASSET LIGHTS EYE ...]" >&2; exit 2; }
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
# shellcheck source=scripts/median-wall-time.sh
source scripts/median-wall-time.sh
row() {  # row NAME COMMAND... : the command with --specular none and exact appended
  local name=$1 none exact
  shift
  none=$(median_seconds 5 "$@" --specular none)
  exact=$(median_seconds 5 "$@" --specular exact)
  awk -v n="$name" -v a="$none" -v b="$exact" 'BEGIN { printf "| %s | %.3f | %.3f | %.2f |\n", n, a, b, b / a }'
}
echo "load before: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "| command | --specular none (s) | --specular exact (s) | exact / none |"
echo "|---|---|---|---|"
row "render assets/demo/studio.glb 960 x 720" "$vlit" render assets/demo/studio.glb \
  --lights assets/demo/lights.json -o "$out/demo.png" --width 960 --height 720 --quiet
args=("$@")
for ((i = 0; i < ${#args[@]}; i += 3)); do
  asset=${args[i]} lights=${args[i + 1]} eye=${args[i + 2]}
  row "bake $(basename "$asset") --lights $(basename "$lights") --specular-eye $eye" "$vlit" bake "$asset" \
    --lights "$lights" --specular-eye "$eye" -o "$out/bake.glb" --quiet
done
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
