// Gallery browser test (issue 20). Opens paper_figures/out/index.html from
// file:// (as a reader would, no server) in headless Chromium and asserts:
// no console error, no failed request, every image loaded, every viewer
// loaded its model with the expected mesh count, the part toggles and the
// orbit work, and the demo body is about 1.7 m tall. Then it loads
// demo.glb with three.js's own GLTFLoader (npm three@0.170.0, served to the
// page through Playwright's request routing, no server) and asserts the
// same height and mesh count there. Saves out/gallery-screenshot.png.
//
// Usage: GALLERY_NODE_MODULES=<dir>/node_modules node verify/gallery/test.mjs [OUT_DIR]
// (verify/gallery/run.sh installs Chromium and the npm packages first).
import { createRequire } from 'module';
import { pathToFileURL } from 'url';
import fs from 'fs';
import path from 'path';

const nm = process.env.GALLERY_NODE_MODULES;
const require = createRequire(nm ? nm + '/' : import.meta.url);
const { chromium } = require('playwright-core');
// three's package.json is not an export: locate it from its main entry
const threeDir = path.resolve(path.dirname(require.resolve('three')), '..');

const out = path.resolve(process.argv[2] || 'paper_figures/out');
// "about 1.7 m": the MakeHuman base body is 1.67 m; a unit slip is 10x.
const BODY_HEIGHT_M = [1.6, 1.8];
// demo.glb: skin, skirt, teddy (issue 20: three.js loads 3 meshes).
const DEMO_MESHES = 3;
// Every gallery model is a character or a part of one, in metres: a model
// left in decimetres (10x) or millimetres falls outside this range.
const ANY_MODEL_HEIGHT_M = [0.1, 3.0];
const TIMEOUT_MS = 180000;

const failures = [];
const fail = (m) => { failures.push(m); console.log('FAIL ' + m); };
const ok = (m) => console.log('ok   ' + m);

const browser = await chromium.launch({
  executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
  args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
    '--disable-background-networking', '--disable-component-update', '--disable-sync',
    '--use-angle=swiftshader', '--enable-unsafe-swiftshader'],
});
try {
  const page = await browser.newPage({ viewport: { width: 1500, height: 1000 } });
  const errors = [];
  page.on('console', (m) => { if (m.type() === 'error') errors.push('console: ' + m.text()); });
  page.on('pageerror', (e) => errors.push('page error: ' + e));
  page.on('requestfailed', (r) => errors.push('request failed: ' + r.url()));
  const t0 = Date.now();
  await page.goto(pathToFileURL(path.join(out, 'index.html')).href, { waitUntil: 'load' });
  await page.waitForFunction(
    () => [...document.querySelectorAll('.viewer')].every((v) => v.dataset.status !== 'loading'),
    null, { timeout: TIMEOUT_MS });
  const s = await page.evaluate(() => ({
    viewers: [...document.querySelectorAll('.viewer')].map((v) => ({ ...v.dataset })),
    images: [...document.images].map((i) => ({ src: i.getAttribute('src'), ok: i.complete && i.naturalWidth > 0 })),
    figures: document.querySelectorAll('article.figure').length,
    pass: document.querySelectorAll('tr.pass').length,
    failRows: document.querySelectorAll('tr.fail').length,
  }));
  ok(`page loaded in ${((Date.now() - t0) / 1000).toFixed(1)} s: ${s.figures} figures, ${s.images.length} images, ${s.viewers.length} viewers, ${s.pass} passing check rows`);
  if (s.figures === 0) fail('no figure on the page');
  if (s.images.length === 0) fail('no image on the page');
  for (const i of s.images) if (!i.ok) fail(`image did not load: ${i.src}`);
  if (s.failRows > 0) fail(`${s.failRows} failing check rows on the page`);
  if (!s.viewers.some((v) => v.model === 'demo.glb')) fail('no viewer for demo.glb');
  for (const v of s.viewers) {
    if (v.status !== 'loaded') { fail(`viewer ${v.model}: status ${v.status}`); continue; }
    if (v.meshes !== v.expectedMeshes) fail(`viewer ${v.model}: ${v.meshes} meshes, expected ${v.expectedMeshes}`);
    else ok(`viewer ${v.model}: ${v.meshes} meshes, ${v.triangles} triangles, height ${Number(v.height).toFixed(3)} m`);
    const vh = Number(v.height);
    if (!(vh >= ANY_MODEL_HEIGHT_M[0] && vh <= ANY_MODEL_HEIGHT_M[1])) fail(`viewer ${v.model}: height ${vh} is not a character's height in metres`);
    if (v.model === 'demo.glb') {
      if (Number(v.meshes) !== DEMO_MESHES) fail(`demo.glb: ${v.meshes} meshes, expected ${DEMO_MESHES}`);
      const h = Number(v.height);
      if (!(h >= BODY_HEIGHT_M[0] && h <= BODY_HEIGHT_M[1])) fail(`demo.glb body height ${h} m, expected about 1.7 m`);
    }
  }
  // per-part toggle and orbit on the demo viewer
  const demo = page.locator('.viewer[data-model="demo.glb"]');
  if (await demo.count()) {
    const visible = () => page.evaluate(() => window.pdesculptGallery.viewers['demo.glb'].parts.filter((p) => p.visible).length);
    const before = await visible();
    await demo.locator('.toggles input').last().uncheck();
    const after = await visible();
    if (after !== before - 1) fail(`toggle: ${before} -> ${after} visible parts`); else ok(`toggle: ${before} -> ${after} visible parts`);
    await demo.locator('.toggles input').last().check();
    const yaw = () => page.evaluate(() => window.pdesculptGallery.viewers['demo.glb'].view.yaw);
    const y0 = await yaw();
    const box = await demo.locator('canvas').boundingBox();
    await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
    await page.mouse.down();
    await page.mouse.move(box.x + box.width / 2 + 120, box.y + box.height / 2, { steps: 5 });
    await page.mouse.up();
    if ((await yaw()) === y0) fail('orbit: dragging did not turn the view'); else ok('orbit: dragging turns the view');
    await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
    await page.mouse.down();
    await page.mouse.move(box.x + box.width / 2 - 120, box.y + box.height / 2, { steps: 5 });
    await page.mouse.up();
  }
  await page.evaluate(() => window.scrollTo(0, 0));
  await page.waitForTimeout(300);
  const shot = path.join(out, 'gallery-screenshot.png');
  await page.screenshot({ path: shot });
  ok(`screenshot ${shot}`);
  for (const e of errors) fail(e);

  // demo.glb in three.js itself
  const glb = path.join(out, 'demo.glb');
  if (fs.existsSync(glb)) {
    const p2 = await browser.newPage();
    p2.on('console', (m) => { if (m.type() === 'error') fail('three.js page console: ' + m.text()); });
    p2.on('pageerror', (e) => fail('three.js page error: ' + e));
    const html = `<!DOCTYPE html><script type="importmap">{"imports":{"three":"/three/build/three.module.js","three/addons/":"/three/examples/jsm/"}}</script>
<script type="module">
import * as THREE from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
const buf = await (await fetch('/out/demo.glb')).arrayBuffer();
new GLTFLoader().parse(buf, '', (g) => {
  let meshes = 0, triangles = 0;
  g.scene.traverse((o) => { if (o.isMesh) { meshes++; triangles += o.geometry.index.count / 3; } });
  const b = new THREE.Box3().setFromObject(g.scene);
  window.result = { meshes, triangles, height: b.max.y - b.min.y, revision: THREE.REVISION };
}, (e) => { window.result = { error: String(e) }; });
</script>`;
    await p2.route('http://gallery.test/**', async (route) => {
      const u = new URL(route.request().url());
      if (u.pathname === '/check.html') return route.fulfill({ contentType: 'text/html', body: html });
      const [root, rel] = u.pathname.startsWith('/three/') ? [threeDir, u.pathname.slice(7)]
        : u.pathname.startsWith('/out/') ? [out, u.pathname.slice(5)] : [null, null];
      const f = root && path.join(root, rel);
      if (!f || !f.startsWith(root) || !fs.existsSync(f)) return route.fulfill({ status: 404, body: '' });
      return route.fulfill({ contentType: f.endsWith('.js') ? 'text/javascript' : 'application/octet-stream', body: fs.readFileSync(f) });
    });
    await p2.goto('http://gallery.test/check.html');
    await p2.waitForFunction(() => window.result !== undefined, null, { timeout: TIMEOUT_MS });
    const r = await p2.evaluate(() => window.result);
    if (r.error) fail('three.js GLTFLoader: ' + r.error);
    else {
      ok(`three.js r${r.revision}: demo.glb ${r.meshes} meshes, ${r.triangles} triangles, height ${r.height.toFixed(3)} m`);
      if (r.meshes !== DEMO_MESHES) fail(`three.js: ${r.meshes} meshes, expected ${DEMO_MESHES}`);
      if (!(r.height >= BODY_HEIGHT_M[0] && r.height <= BODY_HEIGHT_M[1])) fail(`three.js: body height ${r.height} m, expected about 1.7 m`);
    }
  } else {
    fail(`${glb} missing`);
  }
} finally {
  await browser.close();
}
if (failures.length) {
  console.log(`gallery browser test: ${failures.length} failure(s)`);
  process.exit(1);
}
console.log('gallery browser test: all assertions passed');
