#!/usr/bin/env bash
# Renders the scenes of Picott 1992 (assets/paper/: the bowling lane of figures 3, 4, 7 and the
# studio of figure 9, each with its spot, linear and area lights) at 480 x 360 with 16 samples per
# pixel into docs/images/paper/, for docs/paper-scenes.md, with soft shadows (--shadows on, docs/shadows.md).
# Usage: scripts/render-paper-scenes.sh            (build dir: build/release, configured if needed)
#        BUILD_DIR=build/mine scripts/render-paper-scenes.sh
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir="${BUILD_DIR:-build/release}"
# shellcheck source=scripts/build-targets.sh
source scripts/build-targets.sh
build_targets "$build_dir" vlit
mkdir -p docs/images/paper
status=0
for scene in bowling studio; do
  for light in spot linear area; do
    out="docs/images/paper/$scene-$light.png"
    start=$(date +%s.%N)
    if "$build_dir/vlit" render "assets/paper/$scene.glb" --lights "assets/paper/$scene-$light.json" \
         -o "$out" --width 480 --height 360 --samples 16 --shadows on --quiet; then
      awk -v out="$out" -v s="$start" -v e="$(date +%s.%N)" 'BEGIN { printf "%-40s %.2f s\n", out, e - s }'
    else
      echo "render-paper-scenes: $scene with $light lights failed" >&2
      status=1
    fi
  done
done
exit $status
