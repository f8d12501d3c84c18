#!/usr/bin/env bash
# Bakes the demo scene and real assets from ../shared/assets with the release build, then checks
# every output with the Khronos glTF-Validator (npm package gltf-validator, installed from the npm
# registry into tests/validator/node_modules). Exit status 1 if any output has a validation error.
# Needs: a release build (scripts/test.sh or scripts/demo.sh), node and npm.
set -euo pipefail
cd "$(dirname "$0")/.."
command -v node >/dev/null && command -v npm >/dev/null || { echo "validate-baked: node and npm are required" >&2; exit 2; }
(cd tests/validator && npm ci --no-audit --no-fund --silent)
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
vlit=build/release/vlit
$vlit bake assets/demo/studio.glb --lights assets/demo/lights.json -o "$out/studio.glb" -q
$vlit bake assets/demo/studio.glb --lights assets/demo/lights.json -o "$out/studio.gltf" --color-format unorm8 -q
# Lights stored in the file (EXT_lights_area, VLIT_lights_linear, emissive lines and triangles),
# with and without specular folded in.
$vlit bake assets/examples/file-lights.glb -o "$out/file-lights.glb" -q
$vlit bake assets/examples/file-lights.glb -o "$out/file-lights-specular.gltf" --specular-eye 0,1.6,5.5 --specular exact -q
shared=../shared/assets/gltf
if [[ -d $shared ]]; then
  for f in Box/glTF/Box.gltf BoxInterleaved/glTF-Binary/BoxInterleaved.glb SimpleSparseAccessor/glTF/SimpleSparseAccessor.gltf \
           Avocado/glTF/Avocado.gltf MetalRoughSpheresNoTextures/glTF/MetalRoughSpheresNoTextures.gltf \
           VertexColorTest/glTF/VertexColorTest.gltf LightsPunctualLamp/glTF/LightsPunctualLamp.gltf \
           Cameras/glTF/Cameras.gltf SimpleMeshes/glTF/SimpleMeshes.gltf Triangle/glTF/Triangle.gltf; do
    [[ -f $shared/$f ]] || continue
    name=$(basename "${f%.*}")
    $vlit bake "$shared/$f" --lights assets/demo/lights.json -o "$out/$name.glb" -q
  done
  $vlit bake "$shared/VertexColorTest/glTF/VertexColorTest.gltf" --lights assets/demo/lights.json --mode multiply \
    --color-format float -o "$out/VertexColorTest-multiply.gltf" -q
fi
# A mesh file (OBJ through OpenMesh) baked into a new glTF document.
bunny=../shared/assets/mesh/StanfordBunny/stanford-bunny.obj
[[ -f $bunny ]] && $vlit bake "$bunny" --lights assets/demo/lights.json -o "$out/stanford-bunny.glb" -q
node tests/validator/validate.js "$out"/*.glb "$out"/*.gltf
