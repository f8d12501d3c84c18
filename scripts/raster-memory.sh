#!/usr/bin/env bash
# Peak memory and time of `vlit render` on large terrain scenes (docs/rasterizer.md, memory):
# makes ~1M and ~10M triangle scenes with vlit_make_terrain_scene (bench/) in a temporary
# directory, renders each at 1920 x 1080 with 4 samples per pixel under /usr/bin/time -v, shaded
# (one directional light) and as the normals view (no lighting), and prints a table.
# Usage: scripts/raster-memory.sh [GRID...]   (default: 708 2237, i.e. 1.0M and 10.0M triangles)
#        VLIT=path/to/vlit to measure another build.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build/release}
vlit=${VLIT:-$build/vlit}
[[ -x /usr/bin/time ]] || { echo "raster-memory: /usr/bin/time is required (apt-get install time)" >&2; exit 2; }
cmake --build "$build" -j"${JOBS:-2}" --target vlit vlit_make_terrain_scene >/dev/null
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo '{"lights": [{"type": "directional", "direction": [-0.5, -1, -0.3], "intensity": 1}]}' >"$tmp/light.json"
echo "| triangles | view | peak RSS (MiB) | wall (s) | vlit --explain times |"
echo "|---|---|---|---|---|"
for grid in "${@:-708 2237}"; do
  for g in $grid; do
    "$build/bench/vlit_make_terrain_scene" "$g" "$tmp/terrain.glb"
    triangles=$(( 2 * (g - 1) * (g - 1) ))
    for view in shaded normals; do
      /usr/bin/time -v "$vlit" render "$tmp/terrain.glb" --lights "$tmp/light.json" -o "$tmp/out.png" --width 1920 \
        --height 1080 --samples 4 --view "$view" -q --explain >"$tmp/out.txt" 2>"$tmp/time.txt"
      rss=$(awk -F: '/Maximum resident/ {print int($2 / 1024)}' "$tmp/time.txt")
      wall=$(awk '/Elapsed/ {print $NF}' "$tmp/time.txt")
      times=$(grep '^time:' "$tmp/out.txt" | sed 's/^time: //')
      echo "| $triangles | $view | $rss | $wall | $times |"
    done
  done
done
