#!/usr/bin/env bash
# Bakes the demo scene and the vendored sample models (assets/samples) with the release build, plus
# any Khronos sample models under $VLIT_EXTRA_ASSETS (optional: a folder laid out as the
# glTF-Sample-Assets Models/ folder, and mesh/StanfordBunny/stanford-bunny.obj), then checks
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
# Written with EXT_meshopt_compression (bake --meshopt), binary and text.
$vlit bake assets/demo/studio.glb --lights assets/demo/lights.json -o "$out/studio-meshopt.glb" --meshopt -q
$vlit bake assets/demo/studio.glb --lights assets/demo/lights.json -o "$out/studio-meshopt.gltf" --meshopt --color-format unorm8 -q
# Lights stored in the file (EXT_lights_area, VLIT_lights_linear, emissive lines and triangles),
# with and without specular folded in.
$vlit bake assets/examples/file-lights.glb -o "$out/file-lights.glb" -q
$vlit bake assets/examples/file-lights.glb -o "$out/file-lights-specular.gltf" --specular-eye 0,1.6,5.5 --specular exact -q
# The vendored samples come without their texture images (assets/samples/LICENSES.md): each is
# baked from a copy where every image it names and lacks is a 1 x 1 PNG, so that the input, and
# the .glb that embeds its images, is a valid glTF.
png_1x1='\x89PNG\r\n\x1a\n\x00\x00\x00\rIHDR\x00\x00\x00\x01\x00\x00\x00\x01\x08\x02\x00\x00\x00\x90wS\xde\x00\x00\x00\x0cIDATx\x9cc\xf8\xff\xff?\x00\x05\xfe\x02\xfe\xa75\x81\x84\x00\x00\x00\x00IEND\xaeB`\x82'
for f in assets/samples/*/*.gltf; do
  name=$(basename "${f%.*}")
  copy="$out/samples/$name"
  mkdir -p "$copy"
  cp "$(dirname "$f")"/* "$copy/"
  node -e 'for (const i of JSON.parse(require("fs").readFileSync(process.argv[1])).images || []) if (i.uri) console.log(decodeURIComponent(i.uri))' "$copy/$name.gltf" |
    while IFS= read -r image; do
      [[ -e "$copy/$image" ]] || printf "$png_1x1" > "$copy/$image"
    done
  $vlit bake "$copy/$name.gltf" --lights assets/demo/lights.json -o "$out/$name.glb" -q
  $vlit bake "$copy/$name.gltf" --lights assets/demo/lights.json -o "$out/$name-meshopt.glb" --meshopt -q
done
# A Draco-compressed input (Debian package draco), decoded by vlit and written uncompressed.
if command -v draco_transcoder >/dev/null; then
  draco_transcoder -i "$out/samples/Avocado/Avocado.gltf" -o "$out/samples/avocado-draco.glb" >/dev/null
  $vlit bake "$out/samples/avocado-draco.glb" --lights assets/demo/lights.json -o "$out/avocado-draco.glb" -q
else
  echo "validate-baked: draco_transcoder not installed (package draco): no Draco input checked" >&2
fi
extra=${VLIT_EXTRA_ASSETS:-}/gltf
if [[ -n ${VLIT_EXTRA_ASSETS:-} && -d $extra ]]; then
  for f in Box/glTF/Box.gltf BoxInterleaved/glTF-Binary/BoxInterleaved.glb SimpleSparseAccessor/glTF/SimpleSparseAccessor.gltf \
           Avocado/glTF/Avocado.gltf MetalRoughSpheresNoTextures/glTF/MetalRoughSpheresNoTextures.gltf \
           VertexColorTest/glTF/VertexColorTest.gltf LightsPunctualLamp/glTF/LightsPunctualLamp.gltf \
           Cameras/glTF/Cameras.gltf SimpleMeshes/glTF/SimpleMeshes.gltf Triangle/glTF/Triangle.gltf; do
    [[ -f $extra/$f ]] || continue
    name=$(basename "${f%.*}")
    $vlit bake "$extra/$f" --lights assets/demo/lights.json -o "$out/$name.glb" -q
  done
  $vlit bake "$extra/VertexColorTest/glTF/VertexColorTest.gltf" --lights assets/demo/lights.json --mode multiply \
    --color-format float -o "$out/VertexColorTest-multiply.gltf" -q
fi
# Mesh files baked into a new glTF document: a small tetrahedron written here, a floor under an
# emitter whose .mtl Ke (5, 4, 3) needs KHR_materials_emissive_strength (docs/mesh-files.md), and
# the Stanford bunny when VLIT_EXTRA_ASSETS has it.
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n' > "$out/tetrahedron.obj"
$vlit bake "$out/tetrahedron.obj" --lights assets/demo/lights.json -o "$out/tetrahedron.glb" -q
rm "$out/tetrahedron.obj"
printf 'newmtl floor\nKd 0.7 0.6 0.5\nNs 40\nnewmtl lamp\nKd 1 1 1\nKe 5 4 3\n' > "$out/lamp.mtl"
printf 'mtllib lamp.mtl\nv 0 0 0\nv 0 0 2\nv 2 0 2\nv 2 0 0\nv 0.5 1 0.5\nv 1.5 1 0.5\nv 1.5 1 1.5\nv 0.5 1 1.5\nusemtl floor\nf 1 2 3 4\nusemtl lamp\nf 5 6 7 8\n' > "$out/lamp.obj"
$vlit bake "$out/lamp.obj" -o "$out/lamp.glb" -q
rm "$out/lamp.obj" "$out/lamp.mtl"
bunny=${VLIT_EXTRA_ASSETS:-/nonexistent}/mesh/StanfordBunny/stanford-bunny.obj
[[ -f $bunny ]] && $vlit bake "$bunny" --lights assets/demo/lights.json -o "$out/stanford-bunny.glb" -q
node tests/validator/validate.js "$out"/*.glb "$out"/*.gltf
