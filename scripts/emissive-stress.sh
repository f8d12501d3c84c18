#!/usr/bin/env bash
# Emissive geometry at scale: makes every material of MetalRoughSpheresNoTextures (98 spheres,
# 1.04 M triangles, 528 k vertices) emissive and bakes it with --explain, printing the load time
# (merging 1.04 M curved triangles into lights), the light time with the kept lights, and the
# peak memory. docs/gltf-lights.md "Emissive geometry" quotes the result.
# Needs: a release build, python3, GNU time (/usr/bin/time).
set -euo pipefail
cd "$(dirname "$0")/.."
# MetalRoughSpheresNoTextures (Khronos sample, CC0, 676 KB) is not vendored: point
# VLIT_EXTRA_ASSETS at a folder holding gltf/MetalRoughSpheresNoTextures/glTF/.
src=${VLIT_EXTRA_ASSETS:-/nonexistent}/gltf/MetalRoughSpheresNoTextures/glTF
[[ -d $src ]] || { echo "emissive-stress: $src not found" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp "$src"/* "$work"/
python3 - "$work" <<'PY'
import json, sys, os
path = os.path.join(sys.argv[1], "MetalRoughSpheresNoTextures.gltf")
d = json.load(open(path))
for m in d["materials"]:
    m["emissiveFactor"] = [0.5, 0.5, 0.5]
json.dump(d, open(os.path.join(sys.argv[1], "emissive.gltf"), "w"))
PY
/usr/bin/time -f "peak memory %M kB, wall %e s" build/release/vlit bake "$work/emissive.gltf" -o "$work/out.glb" --explain "$@" 2>&1 |
  grep -E "^time|^warning|^peak|^plan: [0-9]"
