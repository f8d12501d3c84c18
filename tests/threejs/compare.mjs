// Renders a vlit-baked glTF with three.js in headless Chromium (WebGL on SwiftShader, no GPU) and
// compares it, pixel by pixel, with a PNG from `vlit render` of the same scene and lights.
// Driven by scripts/compare-threejs.sh, which bakes and renders with vlit first; docs/gltf-output.md
// explains the measured differences.
//
// node compare.mjs --gltf BAKED.glb --vlit VLIT.png --width W --height H --out-dir DIR [--antialias]
//   writes DIR/threejs[-msaa].png and DIR/diff[-msaa].png, prints one JSON line of statistics.
// three.js setup: GLTFLoader (KHR_materials_unlit -> MeshBasicMaterial, COLOR_0 as linear vertex
// colours multiplied by baseColorFactor), the asset's first camera with the image's aspect,
// black background, pixel ratio 1, output colour space sRGB (three's default: linear -> sRGB in
// the fragment shader).
import { readFileSync, writeFileSync, existsSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';

const here = dirname(fileURLToPath(import.meta.url));
const args = process.argv.slice(2);
const option = (name, fallback) => {
  const i = args.indexOf(name);
  return i >= 0 && i + 1 < args.length ? args[i + 1] : fallback;
};
const gltfPath = option('--gltf');
const vlitPath = option('--vlit');
const outDir = option('--out-dir', '.');
const width = Number(option('--width', 640));
const height = Number(option('--height', 480));
const antialias = args.includes('--antialias');
if (!gltfPath || !vlitPath || !(width > 0) || !(height > 0)) {
  console.error('usage: node compare.mjs --gltf BAKED.glb --vlit VLIT.png --width W --height H --out-dir DIR [--antialias]');
  process.exit(2);
}
const chromiumPath = ['/usr/lib/chromium/chromium', '/usr/bin/chromium'].find(existsSync);
if (!chromiumPath) {
  console.error('compare.mjs: Debian chromium not found (apt-get install chromium)');
  process.exit(2);
}

// Everything the page loads is answered here (no server, no network): three.js from
// node_modules, the baked asset and vlit's PNG.
const origin = 'http://vlit.invalid';
const files = {
  '/asset.glb': [resolve(gltfPath), 'model/gltf-binary'],
  '/vlit.png': [resolve(vlitPath), 'image/png'],
};
const page_html = `<!doctype html><html><head><script type="importmap">
{"imports": {"three": "/three/build/three.module.js", "three/addons/": "/three/examples/jsm/"}}
</script></head><body style="margin:0"></body></html>`;

const browser = await chromium.launch({
  executablePath: chromiumPath,
  headless: true,
  args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--ignore-gpu-blocklist'],
});
try {
  const page = await browser.newPage({ viewport: { width, height }, deviceScaleFactor: 1 });
  page.on('pageerror', (e) => console.error('page error:', e.message));
  await page.route(`${origin}/**`, (route) => {
    const path = new URL(route.request().url()).pathname;
    if (path === '/' || path === '/index.html') return route.fulfill({ body: page_html, contentType: 'text/html' });
    if (files[path]) return route.fulfill({ body: readFileSync(files[path][0]), contentType: files[path][1] });
    if (path.startsWith('/three/')) {
      const file = join(here, 'node_modules', path);
      if (existsSync(file)) return route.fulfill({ body: readFileSync(file), contentType: 'text/javascript' });
    }
    return route.fulfill({ status: 404, body: 'not found' });
  });
  await page.goto(`${origin}/index.html`);
  const result = await page.evaluate(async ({ width, height, antialias }) => {
    const THREE = await import('three');
    const { GLTFLoader } = await import('three/addons/loaders/GLTFLoader.js');
    const canvas = document.createElement('canvas');
    document.body.appendChild(canvas);
    const renderer = new THREE.WebGLRenderer({ canvas, antialias, preserveDrawingBuffer: true });
    renderer.setPixelRatio(1);
    renderer.setSize(width, height, false);
    renderer.outputColorSpace = THREE.SRGBColorSpace;
    renderer.setClearColor(0x000000, 1);
    const gltf = await new GLTFLoader().loadAsync('/asset.glb');
    if (!gltf.cameras.length) throw new Error('the asset has no camera');
    const camera = gltf.cameras[0];
    camera.aspect = width / height;
    camera.updateProjectionMatrix();
    let unlit = 0, vertexColored = 0;
    gltf.scene.traverse((o) => {
      if (!o.isMesh) return;
      unlit += o.material.isMeshBasicMaterial ? 1 : 0;
      vertexColored += o.material.vertexColors ? 1 : 0;
    });
    renderer.render(gltf.scene, camera);
    const gl = renderer.getContext();
    const ours = new Uint8Array(width * height * 4);
    gl.readPixels(0, 0, width, height, gl.RGBA, gl.UNSIGNED_BYTE, ours);

    const img = new Image();
    img.src = '/vlit.png';
    await img.decode();
    const c2 = document.createElement('canvas');
    c2.width = width;
    c2.height = height;
    const ctx = c2.getContext('2d');
    ctx.drawImage(img, 0, 0);
    const ref = ctx.getImageData(0, 0, width, height).data;

    // Statistics over all pixels; "covered" = not pure black background.
    const three = new ImageData(width, height), diff = new ImageData(width, height);
    let maxDiff = 0, sumAbs = 0, sumSq = 0, over2 = 0, over8 = 0, coverage = 0, interiorOver2 = 0, interior = 0;
    const histogram = new Array(9).fill(0);  // max channel difference 0, 1, 2, 3-4, 5-8, 9-16, 17-32, 33-64, >64
    const bucket = (d) => (d <= 2 ? d : d <= 4 ? 3 : d <= 8 ? 4 : d <= 16 ? 5 : d <= 32 ? 6 : d <= 64 ? 7 : 8);
    const at = (x, y) => 4 * (y * width + x);
    for (let y = 0; y < height; ++y)
      for (let x = 0; x < width; ++x) {
        const g = at(x, height - 1 - y), r = at(x, y);
        let m = 0;
        for (let k = 0; k < 3; ++k) {
          const d = Math.abs(ours[g + k] - ref[r + k]);
          m = Math.max(m, d);
          sumAbs += d;
          sumSq += d * d;
          three.data[r + k] = ours[g + k];
        }
        three.data[r + 3] = 255;
        const coveredThree = ours[g] + ours[g + 1] + ours[g + 2] > 0, coveredVlit = ref[r] + ref[r + 1] + ref[r + 2] > 0;
        coverage += coveredThree !== coveredVlit ? 1 : 0;
        maxDiff = Math.max(maxDiff, m);
        over2 += m > 2 ? 1 : 0;
        over8 += m > 8 ? 1 : 0;
        histogram[bucket(m)] += 1;
        // Interior: the pixel and its 8 neighbours agree on coverage in vlit's image and none is an
        // edge of vlit's picture (a neighbour differing by more than 8 levels).
        let edge = x === 0 || y === 0 || x === width - 1 || y === height - 1;
        for (let dy = -1; dy <= 1 && !edge; ++dy)
          for (let dx = -1; dx <= 1 && !edge; ++dx) {
            const n = at(x + dx, y + dy);
            for (let k = 0; k < 3; ++k) edge = edge || Math.abs(ref[n + k] - ref[r + k]) > 8;
          }
        if (!edge) {
          ++interior;
          interiorOver2 += m > 2 ? 1 : 0;
        }
        const grey = (ref[r] + ref[r + 1] + ref[r + 2]) / 12;
        diff.data[r] = m > 2 ? Math.min(255, 64 + 16 * m) : grey;
        diff.data[r + 1] = m > 2 ? 0 : grey;
        diff.data[r + 2] = m > 0 && m <= 2 ? 160 : m > 2 ? 0 : grey;
        diff.data[r + 3] = 255;
      }
    const toPng = (imageData) => {
      const c = document.createElement('canvas');
      c.width = width;
      c.height = height;
      c.getContext('2d').putImageData(imageData, 0, 0);
      return c.toDataURL('image/png').split(',')[1];
    };
    const n = width * height;
    const mse = sumSq / (3 * n);
    return {
      renderer: gl.getParameter(gl.getExtension('WEBGL_debug_renderer_info')?.UNMASKED_RENDERER_WEBGL ?? gl.RENDERER),
      three_revision: THREE.REVISION,
      meshes_unlit: unlit,
      meshes_vertex_colored: vertexColored,
      antialias,
      pixels: n,
      max_abs_diff: maxDiff,
      mean_abs_diff: sumAbs / (3 * n),
      psnr_db: mse > 0 ? 10 * Math.log10((255 * 255) / mse) : Infinity,
      fraction_over_2: over2 / n,
      fraction_over_8: over8 / n,
      fraction_coverage_differs: coverage / n,
      interior_pixels: interior,
      interior_fraction_over_2: interiorOver2 / Math.max(1, interior),
      histogram_max_channel_diff: Object.fromEntries(
        ['0', '1', '2', '3-4', '5-8', '9-16', '17-32', '33-64', '>64'].map((k, i) => [k, histogram[i]])),
      three_png: toPng(three),
      diff_png: toPng(diff),
    };
  }, { width, height, antialias });
  const suffix = antialias ? '-msaa' : '';
  writeFileSync(join(outDir, `threejs${suffix}.png`), Buffer.from(result.three_png, 'base64'));
  writeFileSync(join(outDir, `diff${suffix}.png`), Buffer.from(result.diff_png, 'base64'));
  delete result.three_png;
  delete result.diff_png;
  console.log(JSON.stringify(result));
} finally {
  await browser.close();
}
