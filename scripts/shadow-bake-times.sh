#!/usr/bin/env bash
# Whole `vlit bake` wall times with shadows off and on (docs/shadows.md, "Whole bakes"): the
# median of 3 runs of each, and their ratio, for the paper's bowling lane with its three panels
# and for any further ASSET LIGHTS pairs given as arguments. Prints the machine's load before
# and after (the times mean little on a busy machine).
# Usage: scripts/shadow-bake-times.sh [ASSET LIGHTS ...]      (build dir: build/release)
set -euo pipefail
cd "$(dirname "$0")/.."
vlit="${BUILD_DIR:-build/release}/vlit"
[[ -x "$vlit" ]] || { echo "shadow-bake-times: $vlit not built (cmake --workflow --preset release)" >&2; exit 2; }
pairs=(assets/paper/bowling.glb assets/paper/bowling-area.json "$@")
(( ${#pairs[@]} % 2 == 0 )) || { echo "usage: $0 [ASSET LIGHTS ...]" >&2; exit 2; }
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
# shellcheck source=scripts/median-wall-time.sh
source scripts/median-wall-time.sh
echo "load before: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "| asset | lights | shadows off (s) | shadows on (s) | on / off |"
echo "|---|---|---|---|---|"
for ((i = 0; i < ${#pairs[@]}; i += 2)); do
  asset=${pairs[i]} lights=${pairs[i + 1]}
  off=$(median_seconds 3 "$vlit" bake "$asset" --lights "$lights" -o "$out/off.glb" --quiet)
  on=$(median_seconds 3 "$vlit" bake "$asset" --lights "$lights" -o "$out/on.glb" --shadows on --quiet)
  awk -v a="$(basename "$asset")" -v l="$(basename "$lights")" -v off="$off" -v on="$on" \
    'BEGIN { printf "| %s | %s | %.3f | %.3f | %.1f |\n", a, l, off, on, on / off }'
done
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
