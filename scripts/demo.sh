#!/usr/bin/env bash
# Installs what is missing (Debian packages), builds the release preset, then lights the bundled
# demo scene: out/demo.png (rasterized) and out/demo.glb (light baked into COLOR_0).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release
mkdir -p out
build/release/vlit render assets/demo/studio.glb --lights assets/demo/lights.json -o out/demo.png --width 960 --height 720
build/release/vlit bake assets/demo/studio.glb --lights assets/demo/lights.json -o out/demo.glb
echo "demo: wrote out/demo.png and out/demo.glb"
