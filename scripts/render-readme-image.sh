#!/usr/bin/env bash
# Re-renders docs/images/demo.png, the picture in the README, from the bundled demo scene.
# Needs a release build (scripts/demo.sh or scripts/test.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
build/release/vlit render assets/demo/studio.glb --lights assets/demo/lights.json \
  -o docs/images/demo.png --width 640 --height 480 --samples 16 -q
