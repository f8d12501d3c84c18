#!/usr/bin/env bash
# The client check of docs/gltf-output.md: bakes a paper scene with vlit, renders the baked glTF
# with three.js (unlit vertex colours, the asset's camera) in headless Debian Chromium, renders
# the same scene and lights with `vlit render`, and compares the two images pixel by pixel,
# without antialiasing (vlit --samples 1 against WebGL without MSAA) and with (vlit --samples 16
# against WebGL MSAA); then the preview of the baked asset (`vlit render baked.glb`, no lights:
# COLOR_0 x base colour unlit, docs/rasterizer.md) against three.js without antialiasing. Prints one JSON line of statistics per comparison; exits 1 if a comparison
# exceeds the tolerances below (unlit vertex-coloured materials in three.js; at most 0.1% of the
# interior pixels off by more than 2/255; at most 0.1% (no AA) / 1% (AA) of all pixels off by more
# than 8/255; PSNR at least 44 / 40 dB), 2 if node, npm or chromium is missing.
# Needs: a release build (scripts/test.sh), node and npm (three and playwright-core are installed
# from the npm registry into tests/threejs/node_modules, pinned by its package-lock.json), and
# Debian's chromium (apt-get install chromium). OUT_DIR=DIR keeps the images (default: a
# temporary directory, removed at exit).
set -euo pipefail
cd "$(dirname "$0")/.."
command -v node >/dev/null && command -v npm >/dev/null || { echo "compare-threejs: node and npm are required" >&2; exit 2; }
[[ -x /usr/lib/chromium/chromium || -x /usr/bin/chromium ]] || { echo "compare-threejs: chromium is required (apt-get install chromium)" >&2; exit 2; }
(cd tests/threejs && npm ci --no-audit --no-fund --silent)
if [[ -n "${OUT_DIR:-}" ]]; then out=$OUT_DIR; mkdir -p "$out"; else out=$(mktemp -d); trap 'rm -rf "$out"' EXIT; fi
vlit=build/release/vlit
scene=assets/paper/studio.glb
lights=assets/paper/studio-area.json
width=640 height=480
# The bake holds no specular (as by default); back faces are culled as glTF viewers do for
# single-sided materials. COLOR_0 as float by default: the normalized formats clip the light
# multiplier at 1 (this scene has vertices lit above 1), which vlit render does not
# (BAKE_FORMAT=unorm16 shows that difference; docs/gltf-output.md).
$vlit bake "$scene" --lights "$lights" --color-format "${BAKE_FORMAT:-float}" -o "$out/baked.glb" -q
common=(--lights "$lights" --specular none --cull-back-faces --width $width --height $height -q)
$vlit render "$scene" "${common[@]}" --samples 1 -o "$out/vlit.png"
$vlit render "$scene" "${common[@]}" --samples 16 -o "$out/vlit-16.png"
mkdir -p "$out/preview"
$vlit render "$out/baked.glb" --cull-back-faces --width $width --height $height -q --samples 1 -o "$out/preview/vlit.png"
status=0
check() {  # check JSON: the tolerances of docs/gltf-output.md
  node -e '
    const r = JSON.parse(process.argv[1]);
    const ok = r.meshes_unlit > 0 && r.meshes_unlit === r.meshes_vertex_colored &&
               r.interior_fraction_over_2 <= 0.001 && r.fraction_over_8 <= (r.antialias ? 0.01 : 0.001) &&
               r.psnr_db >= (r.antialias ? 40 : 44);
    console.log(JSON.stringify(r));
    if (!ok) { console.error("compare-threejs: over tolerance"); process.exit(1); }' "$1" || status=1
}
check "$(node tests/threejs/compare.mjs --gltf "$out/baked.glb" --vlit "$out/vlit.png" --width $width --height $height --out-dir "$out")"
check "$(node tests/threejs/compare.mjs --gltf "$out/baked.glb" --vlit "$out/vlit-16.png" --width $width --height $height --out-dir "$out" --antialias)"
check "$(node tests/threejs/compare.mjs --gltf "$out/baked.glb" --vlit "$out/preview/vlit.png" --width $width --height $height --out-dir "$out/preview")"
exit $status
