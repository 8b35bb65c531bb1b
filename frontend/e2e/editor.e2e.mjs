// The editor in headless Chromium against the real jar, as a new user would use it:
// add a sphere, drag it in the top view, change its material, render through a job and watch
// it arrive, then send a value the server refuses and see the error by its field.
// Usage: node e2e/editor.e2e.mjs path/to/studio.jar   (screenshots go to frontend/test-output/)
import { createHash } from 'node:crypto';
import { mkdirSync, readFileSync } from 'node:fs';
import { deflateSync } from 'node:zlib';
import { chromium } from 'playwright-core';
import { PerspectiveCamera, Vector3 } from 'three';
import { startServer } from './server.mjs';

const jar = process.argv[2];
if (!jar) {
  console.error('usage: node e2e/editor.e2e.mjs path/to/studio.jar');
  process.exit(2);
}
const out = new URL('../test-output/', import.meta.url).pathname;
mkdirSync(out, { recursive: true });

const results = [];
// E2E_ONLY=words runs the opening step and those whose names contain the words (while working on one)
const only = process.env.E2E_ONLY;
async function step(name, body) {
  if (only && results.length > 0 && !name.includes(only)) return;
  const started = Date.now();
  try {
    await body();
    results.push({ name, ok: true });
    console.log(`  ok    ${name} (${Date.now() - started} ms)`);
  } catch (error) {
    results.push({ name, ok: false });
    console.log(`  FAIL  ${name}: ${error.stack ?? error}`);
    throw error;
  }
}
function expect(condition, message) {
  if (!condition) throw new Error(message);
}
/** Polls an async condition until it holds (the editor re-renders after a click, not during it). */
async function until(condition, message, timeoutMs = 5000) {
  const end = Date.now() + timeoutMs;
  while (!(await condition())) {
    if (Date.now() > end) throw new Error(typeof message === 'function' ? await message() : message);
    await new Promise((resolve) => setTimeout(resolve, 25));
  }
}

/** The scene as the JSON tab shows it (the tab is left as it was found). */
async function sceneOf(page) {
  const back = await page.getByRole('tab', { selected: true }).innerText();
  await page.getByRole('tab', { name: 'JSON' }).click();
  const scene = JSON.parse(await page.getByLabel('Scene JSON').inputValue());
  await page.getByRole('tab', { name: back }).click();
  return scene;
}

/** Waits until the page has drawn two frames: whatever changed before is on the canvases then. */
async function twoFrames(page) {
  await page.evaluate(() => new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve))));
}

/** Where a world point shows in the 3D preview's camera view, in page pixels (the render camera, as three.js frames it). */
async function previewPixel(page, scene, point) {
  // opening a scene mounts a new preview: wait for its canvas, and for two frames drawn since the
  // last change (a view switched just before, on a busy machine, may not be on the canvas yet)
  await page.getByTestId('preview-3d').locator('canvas').waitFor();
  await twoFrames(page);
  const box = await page.getByTestId('preview-3d').locator('canvas').boundingBox();
  const c = scene.camera ?? {};
  const camera = new PerspectiveCamera(c.fov ?? 50, box.width / box.height, 0.01, 1e4);
  camera.position.set(...(c.position ?? [0, 2, 8]));
  camera.up.set(...(c.up ?? [0, 1, 0]));
  camera.lookAt(new Vector3(...(c.lookAt ?? [0, 0, 0])));
  camera.updateMatrixWorld();
  const ndc = new Vector3(...point).project(camera);
  return { x: box.x + ((ndc.x + 1) / 2) * box.width, y: box.y + ((1 - ndc.y) / 2) * box.height };
}

/** Opens a scene as a user opens a file. */
async function openScene(page, scene) {
  await page.getByTestId('open-scene').setInputFiles({ name: `${scene.name}.json`, mimeType: 'application/json', buffer: Buffer.from(JSON.stringify(scene)) });
}

/** The 3D preview's pixels [r, g, b] at page points, read from its canvas once a frame is drawn. */
async function previewColours(page, points) {
  await twoFrames(page);
  const canvas = page.getByTestId('preview-3d').locator('canvas');
  const box = await canvas.boundingBox();
  return canvas.evaluate((c, { points, box }) => {
    const copy = document.createElement('canvas');
    copy.width = c.width;
    copy.height = c.height;
    const g = copy.getContext('2d');
    g.drawImage(c, 0, 0);
    return points.map(({ x, y }) => {
      const px = Math.round(((x - box.x) / box.width) * c.width), py = Math.round(((y - box.y) / box.height) * c.height);
      return Array.from(g.getImageData(px, py, 1, 1).data.slice(0, 3));
    });
  }, { points, box });
}
const brightness = ([r, g, b]) => r + g + b;

/** An OBJ grid of n x n quads (2 n² triangles), as the unit tests' gridObj. */
function gridObj(n) {
  const lines = [];
  for (let i = 0; i <= n; i++) for (let j = 0; j <= n; j++) lines.push(`v ${i / n} 0 ${j / n}`);
  const at = (i, j) => i * (n + 1) + j + 1;
  for (let i = 0; i < n; i++) for (let j = 0; j < n; j++) lines.push(`f ${at(i, j)} ${at(i, j + 1)} ${at(i + 1, j + 1)} ${at(i + 1, j)}`);
  return lines.join('\n') + '\n';
}

/** A PNG of 2x2 pixels (RGB), written out: signature, IHDR, IDAT, IEND. */
function tinyPng(pixels) {
  const crcTable = Array.from({ length: 256 }, (_, n) => {
    let c = n;
    for (let k = 0; k < 8; k++) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
    return c >>> 0;
  });
  const crc = (buf) => {
    let c = 0xffffffff;
    for (const b of buf) c = crcTable[(c ^ b) & 255] ^ (c >>> 8);
    return (c ^ 0xffffffff) >>> 0;
  };
  const chunk = (type, data) => {
    const body = Buffer.concat([Buffer.from(type), data]);
    const out = Buffer.alloc(12 + data.length);
    out.writeUInt32BE(data.length, 0);
    body.copy(out, 4);
    out.writeUInt32BE(crc(body), 8 + data.length);
    return out;
  };
  const ihdr = Buffer.alloc(13);
  ihdr.writeUInt32BE(2, 0);
  ihdr.writeUInt32BE(2, 4);
  ihdr[8] = 8; // bit depth
  ihdr[9] = 2; // RGB
  const rows = Buffer.from([0, ...pixels[0], ...pixels[1], 0, ...pixels[2], ...pixels[3]]);
  return Buffer.concat([Buffer.from([137, 80, 78, 71, 13, 10, 26, 10]), chunk('IHDR', ihdr), chunk('IDAT', deflateSync(rows)), chunk('IEND', Buffer.alloc(0))]);
}

/** A glTF 2.0 JSON of one triangle, its buffer embedded. */
function triangleGltf() {
  const bytes = Buffer.alloc(44);
  [0, 0, 0, 1, 0, 0, 0, 1, 0].forEach((v, i) => bytes.writeFloatLE(v, 4 * i));
  [0, 1, 2].forEach((v, i) => bytes.writeUInt16LE(v, 36 + 2 * i));
  return JSON.stringify({
    asset: { version: '2.0' },
    scene: 0,
    scenes: [{ nodes: [0] }],
    nodes: [{ mesh: 0, translation: [0, 0.5, 0] }],
    meshes: [{ primitives: [{ attributes: { POSITION: 0 }, indices: 1, material: 0 }] }],
    materials: [{ pbrMetallicRoughness: { baseColorFactor: [0.9, 0.2, 0.1, 1] }, doubleSided: true }],
    buffers: [{ byteLength: 44, uri: `data:application/octet-stream;base64,${bytes.toString('base64')}` }],
    bufferViews: [{ buffer: 0, byteOffset: 0, byteLength: 36, target: 34962 }, { buffer: 0, byteOffset: 36, byteLength: 6, target: 34963 }],
    accessors: [
      { bufferView: 0, componentType: 5126, count: 3, type: 'VEC3', min: [0, 0, 0], max: [1, 1, 0] },
      { bufferView: 1, componentType: 5123, count: 3, type: 'SCALAR' },
    ],
  });
}

const server = await startServer(jar);
const browser = await chromium.launch({
  executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
  args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-background-networking',
    '--no-first-run', '--disable-component-update', '--disable-sync',
    '--use-angle=swiftshader', '--enable-unsafe-swiftshader'],
});
let exitCode = 0;
try {
  // one context, so that a second tab shares the clipboard (and storage) as a browser's tabs do
  const context = await browser.newContext({ viewport: { width: 1440, height: 1000 } });
  const page = await context.newPage();
  const pageErrors = [];
  page.on('pageerror', (error) => pageErrors.push(String(error)));
  const missing = [];
  page.on('response', (response) => { if (response.status() === 404) missing.push(response.url()); });
  console.log(`browser test against ${server.base}`);

  await step('the editor opens with its views, preview and inspector', async () => {
    await page.goto(server.base);
    // a loaded machine takes a while to first paint a cold page: the first wait is long
    await page.getByTestId('top-view').waitFor({ timeout: 90_000 });
    await page.getByTestId('side-view').waitFor();
    expect(await page.getByText('3D preview').count() > 0, 'no 3D preview');
  });

  await step('New, then Add sphere selects a sphere drawn in the top view', async () => {
    await page.getByRole('button', { name: 'New', exact: true }).click();
    await page.getByTestId('add-sphere').click();
    const sphere = page.getByTestId('top-view').locator('[data-kind="sphere"]').last();
    await sphere.waitFor();
    expect((await sphere.getAttribute('data-selected')) === 'true', 'the new sphere is not selected');
  });

  await step('a new sphere stands on the floor clear of the camera target: grabbed at its centre, it moves', async () => {
    expect(Number(await page.getByLabel('Center y').inputValue()) === 1, 'the new sphere (radius 1) does not rest on the floor');
    const lookAt = async () => {
      await page.getByRole('button', { name: 'Camera', exact: true }).first().click();
      const v = await Promise.all(['x', 'y', 'z'].map((a) => page.getByLabel(`Look at ${a}`).inputValue()));
      await page.getByTestId('top-view').locator('[data-kind="sphere"]').last().click();
      return v.join(',');
    };
    const targetBefore = await lookAt();
    const centerX = page.getByLabel('Center x');
    const x0 = Number(await centerX.inputValue());
    const box = await page.getByTestId('top-view').locator('[data-kind="sphere"]').last().boundingBox();
    const x = box.x + box.width / 2, y = box.y + box.height / 2;
    await page.mouse.move(x, y);
    await page.mouse.down();
    for (let i = 1; i <= 6; i++) await page.mouse.move(x + 6 * i, y);
    await page.mouse.up();
    expect(Number(await centerX.inputValue()) > x0, 'the sphere did not move when grabbed at its centre');
    expect((await lookAt()) === targetBefore, 'grabbing the sphere moved the camera target');
    await page.getByRole('button', { name: 'Undo' }).click();
    await until(async () => Number(await centerX.inputValue()) === x0, 'undo did not put the sphere back');
  });

  let xBefore;
  await step('dragging the sphere in the top view changes its x and z', async () => {
    const centerX = page.getByLabel('Center x');
    const centerZ = page.getByLabel('Center z');
    xBefore = Number(await centerX.inputValue());
    const zBefore = Number(await centerZ.inputValue());
    const sphere = page.getByTestId('top-view').locator('[data-kind="sphere"]').last();
    const box = await sphere.boundingBox();
    // grab it off-centre: the camera's target sits on the sphere's centre in this view
    const x = box.x + box.width * 0.75, y = box.y + box.height * 0.6;
    await page.mouse.move(x, y);
    await page.mouse.down();
    for (let i = 1; i <= 10; i++) await page.mouse.move(x + 8 * i, y + 5 * i);
    await page.mouse.up();
    const xAfter = Number(await centerX.inputValue());
    const zAfter = Number(await centerZ.inputValue());
    expect(xAfter > xBefore, `x did not grow: ${xBefore} -> ${xAfter}`);
    expect(zAfter > zBefore, `z did not grow (screen down is +z in the top view): ${zBefore} -> ${zAfter}`);
  });

  await step('undo puts the sphere back, redo moves it again', async () => {
    const centerX = page.getByLabel('Center x');
    await page.getByRole('button', { name: 'Undo' }).click();
    await until(async () => Number(await centerX.inputValue()) === xBefore,
      async () => `undo did not restore x: ${xBefore} expected, ${await centerX.inputValue()} shown`);
    await page.getByRole('button', { name: 'Redo' }).click();
    await until(async () => Number(await centerX.inputValue()) > xBefore, 'redo did not move it again');
  });

  await step('changing its material to mirror', async () => {
    await page.getByLabel('Material type').selectOption('mirror');
    expect((await page.getByLabel('Material type').inputValue()) === 'mirror', 'material not changed');
    await page.screenshot({ path: `${out}editor.png` });
  });

  await step('rendering through a job shows progress, tiles and then the image', async () => {
    await page.getByTestId('render-button').click();
    const progress = page.getByTestId('render-progress');
    await progress.waitFor({ timeout: 15000 });
    await page.getByTestId('render-canvas').waitFor({ timeout: 15000 });
    await page.getByTestId('render-image').waitFor({ timeout: 120000 });
    expect((await progress.getAttribute('aria-valuenow')) === '100', 'progress did not reach 100');
    const stats = await page.getByTestId('render-stats').innerText();
    expect(/800\s*[×x]\s*600/.test(stats), `no image size in "${stats}"`);
    const download = page.getByTestId('download-link');
    expect((await download.getAttribute('download')) === 'untitled.png', 'download is not named after the scene');
    await page.getByTestId('render-image').scrollIntoViewIfNeeded();
    await page.screenshot({ path: `${out}result.png` });
  });

  await step('the image is the centre: a whole render with Render in reach at 1024x768 and 1440x900; a full-size viewer at 1:1', async () => {
    for (const [width, height] of [[1024, 768], [1440, 900]]) {
      await page.setViewportSize({ width, height });
      await page.getByRole('tab', { name: 'Image' }).click();
      const image = page.getByRole('img', { name: 'The render', exact: true });
      await image.waitFor();
      await until(async () => {
        const box = await image.boundingBox();
        return box && box.x >= 0 && box.y >= 0 && box.x + box.width <= width && box.y + box.height <= height && box.width >= width * 0.45;
      }, async () => `at ${width}x${height} the image is not whole and large: ${JSON.stringify(await image.boundingBox())}`);
      const render = await page.getByTestId('render-button').boundingBox();
      expect(render && render.y >= 0 && render.y + render.height <= height, `Render is out of reach at ${width}x${height}`);
      await page.screenshot({ path: `${out}stage-${width}x${height}.png` });
    }
    // at 1024x768 with the 2D views shown, the preview's header stays inside its panel
    await page.setViewportSize({ width: 1024, height: 768 });
    const views = page.getByRole('button', { name: '2D views' });
    if ((await views.getAttribute('aria-pressed')) !== 'true') await views.click();
    await page.getByRole('tab', { name: '3D preview' }).click();
    await page.getByRole('button', { name: 'Orbit view' }).click();
    const panel = await page.getByRole('region', { name: '3D preview' }).boundingBox();
    for (const name of ['Ray traced', 'Camera view', 'Reset view', 'Camera from this view']) {
      const box = await page.getByRole('button', { name, exact: true }).boundingBox();
      expect(box && box.x >= panel.x && box.x + box.width <= panel.x + panel.width + 0.5 && box.y + box.height <= 768,
        `at 1024x768 with the 2D views "${name}" is not inside the preview (${JSON.stringify(box)} in ${JSON.stringify(panel)})`);
    }
    await page.screenshot({ path: `${out}preview-header-1024x768.png` });
    await page.getByRole('button', { name: 'Camera view' }).click();
    // the 2D views stay shown (as chosen, and as the later steps at 1440 pixels expect them)
    await page.getByRole('tab', { name: 'Image' }).click();
    // at 1920x1080 the image fills the stage: drawn larger than its own 800x600
    await page.setViewportSize({ width: 1920, height: 1080 });
    const image = page.getByRole('img', { name: 'The render', exact: true });
    await until(async () => (await image.evaluate((img) => Math.min(img.clientWidth / img.naturalWidth, img.clientHeight / img.naturalHeight))) > 1.2,
      async () => `at 1920x1080 the image is drawn at ${await image.evaluate((img) => Math.min(img.clientWidth / img.naturalWidth, img.clientHeight / img.naturalHeight))} of its size`);
    await page.screenshot({ path: `${out}stage-1920x1080.png` });
    await page.getByRole('button', { name: 'Full size' }).click();
    const viewer = page.getByRole('dialog', { name: /Full-size image/ });
    await viewer.waitFor();
    await viewer.getByRole('button', { name: '1:1' }).click();
    const scale = Number(await viewer.getByRole('img').getAttribute('data-scale'));
    expect(Math.abs(scale - 1) < 1e-9, `1:1 shows ${scale} device pixels an image pixel`);
    await page.keyboard.press('Escape');
    await viewer.waitFor({ state: 'detached' });
    await page.setViewportSize({ width: 1440, height: 1000 });
    await page.getByRole('tab', { name: '3D preview' }).click();
  });

  await step('a render of an older scene says "Out of date" and offers to render again', async () => {
    const hex = page.getByLabel('Color hex', { exact: true });
    await hex.fill('#8cf');
    await hex.press('Enter');
    await page.getByText('Out of date', { exact: true }).waitFor({ timeout: 5000 });
    await page.getByRole('button', { name: 'Render again' }).waitFor();
    expect((await hex.inputValue()) === '#88ccff', `#8cf was not read as #88ccff: ${await hex.inputValue()}`);
  });

  await step('a refused value stays with its reason beside the field until it is fixed', async () => {
    const radius = page.getByLabel('Radius');
    const before = await radius.inputValue();
    await radius.fill('-1');
    await radius.press('Enter');
    expect((await radius.inputValue()) === '-1', 'the refused value was reverted silently');
    expect((await radius.getAttribute('aria-invalid')) === 'true', 'the refused radius is not aria-invalid');
    const why = await radius.evaluate((el) => document.getElementById(el.getAttribute('aria-describedby'))?.textContent);
    expect(why === 'must be greater than 0', `the reason beside the field is "${why}"`);
    await radius.press('Escape');
    expect((await radius.inputValue()) === before, 'Escape did not revert the radius');
    expect((await radius.getAttribute('aria-invalid')) === null, 'the reverted radius is still invalid');
  });

  await step('a camera looking straight down its up vector is refused, with the error by the field', async () => {
    await page.getByRole('button', { name: 'Camera', exact: true }).first().click();
    for (const [axis, value] of [['x', '0'], ['y', '10'], ['z', '0']]) {
      const input = page.getByLabel(`Camera position ${axis}`);
      await input.fill(value);
      await input.press('Enter');
    }
    for (const [axis, value] of [['x', '0'], ['y', '0'], ['z', '0']]) {
      const input = page.getByLabel(`Look at ${axis}`);
      await input.fill(value);
      await input.press('Enter');
    }
    await page.getByTestId('render-button').click();
    const summary = page.getByTestId('error-summary');
    await summary.waitFor({ timeout: 15000 });
    expect((await summary.innerText()).includes('Camera › Up'), 'the summary does not name Camera › Up');
    const byField = page.locator('.field-error', { hasText: 'parallel' });
    await byField.first().waitFor({ timeout: 5000 });
    await byField.first().scrollIntoViewIfNeeded();
    await page.screenshot({ path: `${out}field-error.png` });
  });

  await step('the Ray traced view names the same refused field, then renders, and follows a drag in the top view', async () => {
    await page.getByRole('tab', { name: '3D preview' }).click();
    await page.getByRole('button', { name: 'Ray traced' }).click();
    const view = page.getByTestId('ray-traced-view');
    const canvas = view.getByTestId('ray-traced-canvas');
    const summary = view.getByTestId('error-summary');
    await summary.waitFor({ timeout: 15000 });
    expect((await summary.innerText()).includes('Camera › Up'), 'the live view does not name Camera › Up');

    // an up vector across the view: the scene renders, coarse to fine, and the problem goes
    for (const [axis, value] of [['y', '0'], ['z', '-1']]) {
      const input = page.getByLabel(`Up ${axis}`);
      await input.fill(value);
      await input.press('Enter');
    }
    const attribute = async (name) => canvas.getAttribute(name);
    /** True once the final frame of the newest revision sent is on the canvas. */
    const current = async () => (await attribute('data-final')) === 'true'
      && (await attribute('data-revision')) === (await attribute('data-sent-revision'));
    const where = async () => `frame of revision ${await attribute('data-revision')} (final: ${await attribute('data-final')}), `
      + `revision ${await attribute('data-sent-revision')} sent`;
    await until(current, async () => `no final frame of the valid scene: ${await where()}`, 60000);
    await summary.waitFor({ state: 'detached', timeout: 5000 });
    const status = await view.getByTestId('ray-traced-status').innerText();
    expect(/^final · \d+ spp · \d+x\d+ · /.test(status), `unexpected status line "${status}"`);
    const picture = () => canvas.evaluate((c) => {
      const data = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
      let sum = 0;
      const reds = new Set();
      for (let i = 0; i < data.length; i += 4) {
        sum = (sum * 31 + data[i] + 3 * data[i + 1] + 7 * data[i + 2]) % 1e9;
        reds.add(data[i]);
      }
      return { sum, distinct: reds.size };
    });
    const before = await picture();
    expect(before.distinct > 1, 'the ray-traced canvas is blank');

    // a drag: frames of the transient position come while the button is still down
    const revisionBefore = Number(await attribute('data-revision'));
    const sphere = page.getByTestId('top-view').locator('[data-kind="sphere"]').last();
    const box = await sphere.boundingBox();
    const x = box.x + box.width * 0.75, y = box.y + box.height * 0.6;
    await page.mouse.move(x, y);
    await page.mouse.down();
    for (let i = 1; i <= 5; i++) await page.mouse.move(x - 6 * i, y - 4 * i);
    await until(async () => Number(await attribute('data-revision')) > revisionBefore,
      async () => `no frame of a newer revision during the drag: ${await where()}`, 30000);
    for (let i = 6; i <= 10; i++) await page.mouse.move(x - 6 * i, y - 4 * i);
    await page.mouse.up();
    await until(current, async () => `no final frame of the dropped position: ${await where()}`, 60000);
    const after = await picture();
    expect(after.sum !== before.sum, 'the picture did not change with the sphere\'s position');
    await page.screenshot({ path: `${out}ray-traced.png` });
    await page.getByRole('button', { name: 'Camera view' }).click();
    await view.waitFor({ state: 'detached', timeout: 5000 });
  });

  await step('an opened file with fov 0 is flagged before Render; New clears its errors and the last render', async () => {
    const bad = { name: 'bad-fov', camera: { fov: 0 }, objects: [{ type: 'sphere', radius: 1 }] };
    await page.getByTestId('open-scene').setInputFiles({ name: 'bad-fov.json', mimeType: 'application/json', buffer: Buffer.from(JSON.stringify(bad)) });
    await page.getByRole('button', { name: 'Camera', exact: true }).first().click();
    const fov = page.getByLabel('Field of view (°)');
    await until(async () => (await fov.getAttribute('aria-invalid')) === 'true', 'fov 0 is not flagged before Render');
    const problems = page.getByTestId('problem-list');
    expect((await problems.innerText()).includes('Camera › Field of view: must be greater than 0'), `problem list: ${await problems.innerText()}`);
    await page.getByRole('button', { name: 'New', exact: true }).click();
    await page.getByRole('button', { name: 'Camera', exact: true }).first().click();
    await until(async () => (await fov.getAttribute('aria-invalid')) === null, 'the new scene still flags the old fov');
    expect(await problems.count() === 0, 'the problem list survived New');
    expect(await page.getByTestId('download-link').count() === 0, 'the old render\'s download survived New');
  });

  await step('objects have stable labels and can be renamed; the name is kept in the scene', async () => {
    await page.getByTestId('add-box').click();
    await page.getByTestId('add-sphere').click();
    const name = page.getByTestId('inspector-object').getByLabel('Name', { exact: true });
    await name.fill('ball');
    await name.press('Enter');
    const outline = page.getByRole('navigation', { name: 'Scene contents' });
    await outline.getByRole('button', { name: /Sphere "ball"/ }).waitFor();
    await outline.getByRole('button', { name: /^Box 1/ }).click();
    await page.getByRole('button', { name: 'Delete', exact: true }).click();
    await outline.getByRole('button', { name: /Sphere "ball"/ }).waitFor();
    await page.getByRole('tab', { name: 'JSON' }).click();
    const text = await page.getByLabel('Scene JSON').inputValue();
    expect(/"name": "ball"/.test(text), 'the name is not in the scene JSON');
    await page.getByRole('tab', { name: '3D preview' }).click();
  });

  await step('smaller things: arrow nudges save no float noise; mirror drops the plastic colour; long numbers fit; Escape closes Examples; the orbit view resets', async () => {
    await page.getByRole('tab', { name: '3D preview' }).click();
    await page.getByTestId('add-sphere').click();
    await page.getByLabel('Grid size in metres').selectOption('0.1');
    const sphere = page.getByTestId('top-view').locator('[data-selected="true"]');
    await sphere.focus();
    for (let i = 0; i < 7; i++) await page.keyboard.press('ArrowLeft');
    for (let i = 0; i < 3; i++) await page.keyboard.press('ArrowUp');
    await page.getByRole('tab', { name: 'JSON' }).click();
    const json = await page.getByLabel('Scene JSON').inputValue();
    expect(!/\d\.\d{12,}/.test(json), `float noise saved: ${json.match(/-?\d+\.\d{12,}/)?.[0]}`);
    // the JSON editor takes the stage's height, not nine lines
    const editor = await page.getByLabel('Scene JSON').boundingBox();
    const stage = await page.locator('#panel-json').boundingBox();
    expect(editor.height > stage.height * 0.6, `the JSON editor is ${editor.height} px of a ${stage.height} px stage`);
    await page.getByRole('tab', { name: '3D preview' }).click();

    await page.getByLabel('Material type').selectOption('plastic');
    const hex = page.getByLabel('Color hex', { exact: true });
    await hex.fill('#cc2222');
    await hex.press('Enter');
    await page.getByLabel('Material type').selectOption('mirror');
    await until(async () => (await hex.inputValue()) === '#ffffff', async () => `a mirror kept the plastic's colour ${await hex.inputValue()}`);

    await page.setViewportSize({ width: 1024, height: 768 });
    if (!(await page.getByLabel('Center x').isVisible())) await page.getByRole('button', { name: 'Inspector', exact: true }).click();
    const cx = page.getByLabel('Center x');
    await cx.fill('100000.004');
    await cx.press('Enter');
    const fit = await cx.evaluate((el) => ({ value: el.value, scroll: el.scrollWidth, client: el.clientWidth }));
    expect(fit.value === '100000.004' && fit.scroll <= fit.client, `100000.004 does not fit its field: ${JSON.stringify(fit)}`);
    await page.screenshot({ path: `${out}narrow-fields-1024.png` });
    await page.getByRole('button', { name: 'Undo' }).click();
    await page.setViewportSize({ width: 1440, height: 1000 });

    await page.getByText('Examples', { exact: true }).click();
    const list = page.getByRole('list', { name: 'Example scenes' });
    await list.waitFor();
    await page.keyboard.press('Escape');
    await list.waitFor({ state: 'hidden', timeout: 2000 });

    await page.getByRole('button', { name: 'Orbit view' }).click();
    await page.getByRole('button', { name: 'Reset view' }).click();
    await page.getByRole('button', { name: 'Camera view' }).click();
    expect(!missing.some((url) => url.includes('favicon')), `the favicon is a 404: ${missing.join(', ')}`);
  });

  await step('camera from this view: the render camera takes the orbit view\'s position and target, one undo step', async () => {
    await page.getByRole('tab', { name: '3D preview' }).click();
    await page.keyboard.press('Escape'); // nothing selected: the drag below orbits, it moves no handle
    const before = (await sceneOf(page)).camera;
    await page.getByRole('button', { name: 'Orbit view' }).click();
    const viewport = await page.getByTestId('preview-3d').boundingBox();
    const x = viewport.x + viewport.width / 2, y = viewport.y + viewport.height / 2;
    await page.mouse.move(x, y);
    await page.mouse.down();
    for (let i = 1; i <= 8; i++) await page.mouse.move(x + 20 * i, y);
    await page.mouse.up();
    await page.getByRole('button', { name: 'Camera from this view' }).click();
    let after;
    await until(async () => {
      after = (await sceneOf(page)).camera;
      return after && JSON.stringify(after.position) !== JSON.stringify(before?.position);
    }, () => `the render camera did not move: ${JSON.stringify(before)} -> ${JSON.stringify(after)}`);
    // a scene may leave its camera to the defaults (the format's: at (0, 2, 8) looking at the origin)
    const distance = (c) => Math.hypot(...(c?.position ?? [0, 2, 8]).map((p, i) => p - (c?.lookAt ?? [0, 0, 0])[i]));
    expect(Math.abs(distance(after) - distance(before)) < 0.05,
      `orbiting changed the camera's distance to its target: ${JSON.stringify(before)} -> ${JSON.stringify(after)}`);
    await page.getByRole('button', { name: 'Undo' }).click();
    await until(async () => JSON.stringify((await sceneOf(page)).camera) === JSON.stringify(before), 'one undo did not bring the camera back');
    await page.getByRole('button', { name: 'Camera view' }).click();
  });

  await step('3D: a click selects, the move handle drags it as one undo step, R scales, F frames', async () => {
    await page.getByRole('button', { name: 'New', exact: true }).click();
    await page.getByTestId('add-sphere').click();
    await page.keyboard.press('Escape');
    const scene = await sceneOf(page);
    const centre = scene.objects[0].center;
    const at = await previewPixel(page, scene, centre);
    await page.mouse.click(at.x, at.y);
    const centerX = page.getByLabel('Center x');
    await centerX.waitFor({ timeout: 10000 });
    const x0 = Number(await centerX.inputValue());
    expect(x0 === centre[0], `clicking the sphere in 3D did not select it (${x0})`);

    // the move handle's centre drags in the view's plane
    await page.mouse.move(at.x, at.y);
    await page.mouse.down();
    for (let i = 1; i <= 10; i++) await page.mouse.move(at.x + 8 * i, at.y);
    await page.mouse.up();
    await until(async () => Number(await centerX.inputValue()) > x0 + 0.3, async () => `the move handle did not move the sphere: x ${await centerX.inputValue()}`);
    const moved = await sceneOf(page);
    expect(!/\d\.\d{4,}/.test(JSON.stringify(moved.objects[0].center)), `the handles saved unrounded values ${JSON.stringify(moved.objects[0].center)}`);
    await page.screenshot({ path: `${out}handles-move.png` });
    await page.getByRole('button', { name: 'Undo' }).click();
    await until(async () => Number(await centerX.inputValue()) === x0, 'one undo did not take the whole handle drag back');

    await page.keyboard.press('r');
    expect((await page.getByRole('button', { name: 'Scale' }).getAttribute('aria-pressed')) === 'true', 'R did not choose the scale handles');
    const radius = page.getByLabel('Radius');
    await page.mouse.move(at.x + 4, at.y - 4);
    await page.mouse.down();
    for (let i = 1; i <= 10; i++) await page.mouse.move(at.x + 4 + 3 * i, at.y - 4 - 3 * i);
    await page.mouse.up();
    await until(async () => { const r = Number(await radius.inputValue()); return r > 1 && r <= 10; },
      async () => `the scale handle made the radius ${await radius.inputValue()}`);
    await page.screenshot({ path: `${out}handles-scale.png` });
    await page.keyboard.press('w');

    await page.keyboard.press('f');
    await until(async () => (await page.getByRole('button', { name: 'Orbit view' }).getAttribute('aria-pressed')) === 'true', 'F did not frame the selection in the orbit view');
    await page.screenshot({ path: `${out}frame-selection.png` });
    await page.getByRole('button', { name: 'Camera view' }).click();
  });

  await step('Ray traced: a click on the live image selects, the move handle drags it as the live image follows, arrow keys move it; an orbit drag from the floor selects nothing; Tab onto a glyph selects it', async () => {
    await page.getByRole('button', { name: 'New', exact: true }).click();
    await page.getByTestId('add-plane').click();
    await page.getByTestId('add-sphere').click();
    await page.keyboard.press('Escape');
    const scene = await sceneOf(page);
    const centre = scene.objects[1].center;
    const names = scene.objects.map((o) => o.name);
    expect(names.every((n) => typeof n === 'string' && n.length > 0) && new Set(names).size === names.length, `new objects are named ${JSON.stringify(names)}`);
    await page.getByRole('button', { name: 'Ray traced' }).click();
    const canvas = page.getByTestId('ray-traced-canvas');
    const attribute = async (name) => canvas.getAttribute(name);
    const current = async () => (await attribute('data-final')) === 'true'
      && (await attribute('data-revision')) === (await attribute('data-sent-revision'));
    await until(current, 'no final frame in the Ray traced view', 60000);
    const at = await previewPixel(page, scene, centre);
    await page.mouse.click(at.x, at.y);
    const centerX = page.getByLabel('Center x');
    await centerX.waitFor({ timeout: 10000 });
    expect(Number(await centerX.inputValue()) === centre[0], 'clicking the sphere on the live image did not select it');
    await twoFrames(page);
    // the handles are drawn over the live image: the overlay has opaque pixels where the sphere is
    const drawn = await page.getByTestId('preview-3d').locator('canvas').evaluate((c) => {
      const copy = document.createElement('canvas');
      copy.width = c.width;
      copy.height = c.height;
      const g = copy.getContext('2d');
      g.drawImage(c, 0, 0);
      const data = g.getImageData(0, 0, c.width, c.height).data;
      let opaque = 0;
      for (let i = 3; i < data.length; i += 4) if (data[i] > 0) opaque++;
      return { opaque, all: data.length / 4 };
    });
    expect(drawn.opaque > 50 && drawn.opaque < drawn.all * 0.5, `the handles over the live image: ${JSON.stringify(drawn)} opaque pixels`);
    await page.screenshot({ path: `${out}ray-traced-handles.png` });

    // the move handle over the live image: frames of the transient position come during the drag
    const revisionBefore = Number(await attribute('data-revision'));
    await page.mouse.move(at.x, at.y);
    await page.mouse.down();
    for (let i = 1; i <= 5; i++) await page.mouse.move(at.x + 8 * i, at.y);
    await until(async () => Number(await attribute('data-sent-revision')) > revisionBefore, 'the live view was sent nothing during the handle drag', 10000);
    for (let i = 6; i <= 10; i++) await page.mouse.move(at.x + 8 * i, at.y);
    await page.mouse.up();
    await until(async () => Number(await centerX.inputValue()) > centre[0] + 0.3, async () => `the move handle over the live image did not move the sphere: x ${await centerX.inputValue()}`);
    await until(current, 'no final frame of the dropped position', 60000);
    await page.getByRole('button', { name: 'Undo' }).click();
    await until(async () => Number(await centerX.inputValue()) === centre[0], 'one undo did not take the handle drag over the live image back');

    // arrow keys with the live view focused (the click focused it): one grid step along a floor axis
    const before = (await sceneOf(page)).objects[1].center;
    await page.getByRole('button', { name: 'Ray traced' }).click();
    await page.getByRole('img', { name: /The scene in 3D/ }).focus();
    await page.keyboard.press('ArrowRight');
    await until(async () => Number(await centerX.inputValue()) !== before[0], 'ArrowRight in the Ray traced view did not move the sphere');
    const grid = Number(await page.getByLabel('Grid size in metres').inputValue());
    const step = Math.round((Number(await centerX.inputValue()) - before[0]) * 1e9) / 1e9;
    expect(step === grid, `ArrowRight moved x by ${step}, not one grid step (${grid})`);

    // an orbit drag that starts on the floor does not select the floor
    await page.getByRole('button', { name: 'Orbit view' }).click();
    await page.getByRole('button', { name: 'Reset view' }).click();
    await page.keyboard.press('Escape');
    await centerX.waitFor({ state: 'detached' });
    const floor = await previewPixel(page, scene, [centre[0] + 1.5, 0, centre[2] + 1]);
    await page.mouse.move(floor.x, floor.y);
    await page.mouse.down();
    for (let i = 1; i <= 8; i++) await page.mouse.move(floor.x + 10 * i, floor.y + 3 * i);
    for (let i = 7; i >= 0; i--) await page.mouse.move(floor.x + 10 * i, floor.y + 3 * i);
    await page.mouse.up();
    await twoFrames(page);
    expect(await page.getByTestId('inspector-object').count() === 0, 'an orbit drag from the floor selected the floor');
    await page.getByRole('button', { name: 'Camera view' }).click();

    // Tab onto a glyph in a plan view selects it
    const views = page.getByRole('button', { name: '2D views' });
    if ((await views.getAttribute('aria-pressed')) !== 'true') await views.click();
    await page.getByTestId('top-view').getByTestId('object-1').focus();
    await centerX.waitFor({ timeout: 5000 });
  });

  await step('the preview shows what the render will: shadows, a mirror reflecting the scene, glass visible; extreme values leave the rest of the picture', async () => {
    const honest = {
      name: 'honest', background: '#101418',
      camera: { position: [0, 2.5, 8], lookAt: [0, 0.8, 0], fov: 45 },
      lights: [{ type: 'point', position: [4, 7, 3], intensity: 1 }],
      objects: [
        { type: 'plane', point: [0, 0, 0], normal: [0, 1, 0], material: { type: 'chalk', color: '#d04030' } },
        { type: 'sphere', center: [-2.2, 1, 0], radius: 1, material: { type: 'plastic', color: '#3070d0' } },
        { type: 'sphere', center: [0, 1, 0], radius: 1, material: { type: 'mirror' } },
        { type: 'sphere', center: [2.2, 1, 0], radius: 1, material: { type: 'glass' } },
      ],
    };
    await page.getByRole('tab', { name: '3D preview' }).click();
    await page.setViewportSize({ width: 1440, height: 900 });
    await openScene(page, honest);
    await page.keyboard.press('Escape');
    await page.waitForTimeout(300); // the lazily built shadow maps and cube maps settle within a frame or two
    // shadow: the floor where the light's ray through the blue sphere's centre lands, against the floor as far on the other side
    const L = honest.lights[0].position, C = honest.objects[1].center;
    const t = L[1] / (L[1] - C[1]);
    const shadow = [L[0] + t * (C[0] - L[0]), 0, L[2] + t * (C[2] - L[2])];
    const lit = [2 * C[0] - shadow[0] + 0.0, 0, 2 * C[2] - shadow[2] + 2.5];
    await page.screenshot({ path: `${out}preview-honest.png` });
    const [inShadow, inLight] = await previewColours(page, [await previewPixel(page, honest, shadow), await previewPixel(page, honest, lit)]);
    expect(brightness(inShadow) < 0.75 * brightness(inLight), `no shadow: ${inShadow} in the shadow, ${inLight} in the light`);
    // the mirror's lower part shows the red floor (before it showed a grey made-up room)
    const [mirrorLow] = await previewColours(page, [await previewPixel(page, honest, [0, 0.25, 0.9])]);
    expect(mirrorLow[0] > mirrorLow[1] + 30 && mirrorLow[0] > mirrorLow[2] + 30, `the mirror does not reflect the red floor: ${mirrorLow}`);
    // glass: its disc differs from the picture without it
    const glassPoints = [];
    for (let i = -3; i <= 3; i++) for (let j = -3; j <= 3; j++) glassPoints.push(await previewPixel(page, honest, [2.2 + i * 0.25, 1 + j * 0.25, 0.5]));
    const withGlass = await previewColours(page, glassPoints);
    await page.screenshot({ path: `${out}preview-honest.png` });
    await openScene(page, { ...honest, objects: honest.objects.slice(0, 3) });
    const withoutGlass = await previewColours(page, glassPoints);
    const change = withGlass.reduce((sum, p, i) => sum + Math.abs(brightness(p) - brightness(withoutGlass[i])), 0) / withGlass.length / 3;
    expect(change > 8, `the glass sphere is nearly invisible: mean change ${change.toFixed(1)} levels`);

    // a sphere at x = 1e300 and a 179.9 degree lens: the floor and the other spheres are still drawn
    const floorAt = await previewPixel(page, honest, [-1, 0, 2]);
    await openScene(page, { ...honest, objects: [...honest.objects, { type: 'sphere', center: [1e300, 1, 0], material: { type: 'chalk' } }] });
    const [floorWithFar] = await previewColours(page, [floorAt]);
    expect(floorWithFar[0] > floorWithFar[2] + 30, `a sphere at 1e300 blanked the floor: ${floorWithFar}`);
    await page.screenshot({ path: `${out}preview-extreme-1e300.png` });
    const wide = { ...honest, camera: { ...honest.camera, fov: 179.9 } };
    await openScene(page, wide);
    await page.screenshot({ path: `${out}preview-extreme-fov.png` });
    if (pageErrors.length) throw new Error(pageErrors.join('\n'));
    // at 179.9 degrees what a 45-degree lens sees is a thin band; the floor right under the camera fills the bottom
    const canvasBox = await page.getByTestId('preview-3d').locator('canvas').boundingBox();
    const bottom = { x: canvasBox.x + canvasBox.width / 2, y: canvasBox.y + canvasBox.height * 0.93 };
    const wideColours = await previewColours(page, [await previewPixel(page, wide, [0, 0, 3]), bottom]);
    for (const c of wideColours) expect(c[0] > c[2] + 30, `fov 179.9 lost the floor: ${JSON.stringify(wideColours)}`);
    await page.screenshot({ path: `${out}preview-extreme-fov.png` });
    await page.setViewportSize({ width: 1440, height: 1000 });
  });

  await step('copy in one tab, paste in another: Ctrl+C / Ctrl+V carry the selection as scene JSON', async () => {
    await page.context().grantPermissions(['clipboard-read', 'clipboard-write'], { origin: server.base });
    await page.getByRole('button', { name: 'New', exact: true }).click();
    await page.getByTestId('add-box').click();
    const name = page.getByTestId('inspector-object').getByLabel('Name', { exact: true });
    await name.fill('crate');
    await name.press('Enter');
    await name.evaluate((el) => el.blur());
    await page.keyboard.press('Control+c');
    const copied = await page.evaluate(() => navigator.clipboard.readText());
    expect(JSON.parse(copied).objects?.[0]?.name === 'crate', `the clipboard holds ${copied.slice(0, 120)}`);
    const other = await page.context().newPage();
    try {
      await other.goto(server.base);
      await other.getByTestId('top-view').waitFor();
      await other.getByRole('button', { name: 'New', exact: true }).click();
      await other.locator('body').focus();
      await other.keyboard.press('Control+v');
      // headless Chromium sends no paste event for Ctrl+V: hand the page the system clipboard's text as the browser would
      await other.evaluate(async () => {
        if (document.querySelectorAll('[data-kind="box"]').length > 0) return;
        const data = new DataTransfer();
        data.setData('text/plain', await navigator.clipboard.readText());
        document.body.dispatchEvent(new ClipboardEvent('paste', { clipboardData: data, bubbles: true, cancelable: true }));
      });
      await other.getByRole('navigation', { name: 'Scene contents' }).getByRole('button', { name: /Box "crate"/ }).waitFor({ timeout: 5000 });
      await other.screenshot({ path: `${out}pasted-in-second-tab.png` });
    } finally {
      await other.close();
    }
    // and into its own scene, beside the original, as one undo step
    await page.evaluate(async () => {
      const data = new DataTransfer();
      data.setData('text/plain', await navigator.clipboard.readText());
      document.body.dispatchEvent(new ClipboardEvent('paste', { clipboardData: data, bubbles: true, cancelable: true }));
    });
    const outline = page.getByRole('navigation', { name: 'Scene contents' });
    await until(async () => (await outline.getByRole('button', { name: /Box "crate"/ }).count()) === 2, 'pasting into the same scene did not add a second crate');
    await page.getByRole('button', { name: 'Undo' }).click();
    await until(async () => (await outline.getByRole('button', { name: /Box "crate"/ }).count()) === 1, 'one undo did not take the paste back');
  });

  await step('undo history survives a reload', async () => {
    await page.getByRole('button', { name: 'New', exact: true }).click();
    await page.getByTestId('add-sphere').click();
    await page.getByTestId('add-box').click();
    const outline = page.getByRole('navigation', { name: 'Scene contents' });
    await outline.getByRole('button', { name: /^Box 2/ }).waitFor();
    await page.reload();
    await page.getByTestId('top-view').waitFor();
    await outline.getByRole('button', { name: /^Box 2/ }).waitFor();
    const undo = page.getByRole('button', { name: 'Undo' });
    expect(!(await undo.isDisabled()), 'Undo is disabled after a reload');
    await undo.click();
    await until(async () => (await outline.getByRole('button', { name: /^Box/ }).count()) === 0, 'undo after the reload did not take the box back');
    await outline.getByRole('button', { name: /^Sphere 1/ }).waitFor();
    await page.getByRole('button', { name: 'Redo' }).click();
    await outline.getByRole('button', { name: /^Box/ }).waitFor();
  });

  await step('import: a 200,000-triangle OBJ shows its progress with no long task over 200 ms, is uploaded once by id, and survives a reload with the edits after it', async () => {
    await page.getByRole('button', { name: 'New', exact: true }).click();
    // long tasks with their start, and when the progress line first shows each phase (page clock)
    await page.evaluate(() => {
      window.longTasks = [];
      window.phaseAt = {};
      new PerformanceObserver((list) => list.getEntries().forEach((e) => window.longTasks.push({ start: e.startTime, duration: e.duration }))).observe({ type: 'longtask' });
      new MutationObserver(() => {
        const text = document.querySelector('[data-testid=import-progress]')?.textContent ?? '';
        const phase = /Importing grid\.obj: (\w+)/.exec(text)?.[1] ?? (text.includes('added as a mesh') ? 'added' : null);
        if (phase && window.phaseAt[phase] === undefined) window.phaseAt[phase] = performance.now();
      }).observe(document.body, { subtree: true, childList: true, characterData: true });
    });
    if (process.env.E2E_PREVIEW_HIDDEN) await page.getByRole('tab', { name: 'JSON' }).click();
    const obj = Buffer.from(gridObj(317)); // 200,978 triangles, 7.6 MB
    const id = `sha256-${createHash('sha256').update(obj).digest('hex')}`;
    const started = Date.now();
    await page.getByTestId('import-file').setInputFiles({ name: 'grid.obj', mimeType: 'text/plain', buffer: obj });
    const progress = page.getByTestId('import-progress');
    await until(async () => (await progress.innerText().catch(() => '')).includes('grid.obj: 200,978 triangles added as a mesh.'), async () => `the import did not finish: ${await progress.innerText().catch(() => '(none)')}`, 60_000);
    // the preview draws a large mesh part by part, saying how far it is, until all of it is in
    await twoFrames(page);
    await until(async () => (await page.getByTestId('preview-drawing').count()) === 0, 'the preview did not finish drawing the mesh', 30_000);
    await twoFrames(page);
    const drawnAt = await page.evaluate(() => performance.now());
    await page.waitForTimeout(300); // long tasks are reported after they end
    const seconds = (Date.now() - started) / 1000;
    const { phases, tasks } = await page.evaluate(() => ({ phases: window.phaseAt, tasks: window.longTasks }));
    expect(phases.hashing !== undefined && phases.reading !== undefined && phases.uploading !== undefined, `progress not shown for every phase: ${JSON.stringify(phases)}`);
    // the import's own work: from its first progress (after Playwright has handed the page the file) until the upload starts
    const longest = (from, to) => Math.round(Math.max(0, ...tasks.filter((t) => t.start >= from && t.start < to).map((t) => t.duration)));
    const reading = longest(phases.hashing, phases.uploading);
    const adding = longest(phases.uploading, drawnAt);
    const slow = tasks.filter((t) => t.start >= phases.uploading && t.start < drawnAt && t.duration > 100).map((t) => `${Math.round(t.duration)} ms at +${Math.round(t.start - phases.uploading)} ms`);
    console.log(`        200,978-triangle OBJ (${(obj.length / 1e6).toFixed(1)} MB): imported and drawn in ${seconds.toFixed(1)} s; longest task while hashing and reading ${reading} ms, while adding and drawing it ${adding} ms${slow.length ? ` (over 100 ms after the upload started: ${slow.join(', ')})` : ''}`);
    expect(reading < 200, `a long task of ${reading} ms while hashing and reading the OBJ`);
    expect(adding < 200, `a long task of ${adding} ms while adding the OBJ and drawing it in the 3D preview`);
    if (!process.env.E2E_PREVIEW_HIDDEN) {
      // all of it is drawn: its middle and points towards three corners of the grid show the mesh's
      // blue (the last part drawn is the side of u = 1; at u = v = 0, its position, are the handles)
      const scene = await sceneOf(page);
      const placed = scene.objects.at(-1);
      const at = ([u, v]) => [0, 1, 2].map((k) => placed.position[k] + placed.scale * [u, 0, v][k]);
      const corners = [[0.5, 0.5], [0.9, 0.35], [0.35, 0.9], [0.9, 0.9]];
      const colours = await previewColours(page, await Promise.all(corners.map((c) => previewPixel(page, scene, at(c)))));
      colours.forEach((c, i) => expect(c[2] > 90 && c[2] > c[0] + 40, `the preview does not show the mesh at ${corners[i]} of the grid: ${c}`));
    }
    const head = await fetch(`${server.base}/api/assets/${id}`, { method: 'HEAD' });
    expect(head.status === 200, `the server does not have the mesh (${head.status})`);
    let scene = await sceneOf(page);
    const mesh = scene.objects.at(-1);
    expect(mesh.type === 'mesh' && mesh.asset === id && mesh.obj === undefined, `the mesh is not named by its id: ${JSON.stringify(mesh).slice(0, 200)}`);
    await page.getByTestId('add-sphere').click(); // an edit after the mesh
    const outline = page.getByRole('navigation', { name: 'Scene contents' });
    await outline.getByRole('button', { name: /^Sphere/ }).waitFor();
    await page.reload();
    await page.getByTestId('top-view').waitFor();
    await outline.getByRole('button', { name: /200,978 triangles/ }).waitFor({ timeout: 30_000 });
    await outline.getByRole('button', { name: /^Sphere/ }).waitFor();
    scene = await sceneOf(page);
    expect(scene.objects.some((o) => o.asset === id), 'the mesh is gone after a reload');
    expect(!(await page.getByRole('button', { name: 'Undo' }).isDisabled()), 'Undo is disabled after a reload');
    await page.getByRole('button', { name: 'Undo' }).click();
    await until(async () => (await outline.getByRole('button', { name: /^Sphere/ }).count()) === 0, 'undo after the reload did not take the sphere back');
    expect(await page.getByTestId('autosave-notice').count() === 0, 'autosave says it failed');
    await page.screenshot({ path: `${out}import-obj.png` });
  });

  await step('import: a glTF shows in the preview, and an image dropped with an object selected becomes its texture', async () => {
    await page.getByRole('button', { name: 'New', exact: true }).click();
    await page.getByTestId('import-file').setInputFiles({ name: 'triangle.gltf', mimeType: 'model/gltf+json', buffer: Buffer.from(triangleGltf()) });
    const outline = page.getByRole('navigation', { name: 'Scene contents' });
    const alerts = async () => (await page.getByRole('alert').allInnerTexts()).join(' | ');
    await until(async () => (await outline.getByRole('button', { name: /glTF model .*\(glTF\)/ }).count()) > 0 || (await alerts()) !== '', 'the glTF model does not appear', 20_000);
    expect((await alerts()) === '', `importing the glTF: ${await alerts()}`);
    const scene = await sceneOf(page);
    const model = scene.objects.at(-1);
    expect(model.type === 'gltf' && /^sha256-/.test(model.asset), `no gltf object: ${JSON.stringify(model)}`);
    await page.screenshot({ path: `${out}import-gltf.png` });
    // the red triangle stands on the floor in front of the camera: its middle shows red in the preview
    const [red] = await previewColours(page, [await previewPixel(page, scene, [model.position[0] + 0.3, model.position[1] + 0.8, model.position[2]])]);
    expect(red[0] > 120 && red[0] > 2 * red[2], `the glTF triangle is not drawn red in the preview: ${red} at ${JSON.stringify(await previewPixel(page, scene, [model.position[0] + 0.3, model.position[1] + 0.8, model.position[2]]))}, model ${JSON.stringify(model)}, camera ${JSON.stringify(scene.camera)}`);
    await page.getByTestId('add-box').click();
    const png = tinyPng([[255, 255, 255], [0, 0, 0], [0, 0, 0], [255, 255, 255]]);
    await page.getByTestId('import-file').setInputFiles({ name: 'checks.png', mimeType: 'image/png', buffer: png });
    const thumbnail = page.getByRole('img', { name: /^Texture sha256-/ });
    await until(async () => (await thumbnail.count()) > 0 || (await alerts()) !== '', 'no texture thumbnail', 20_000);
    expect((await alerts()) === '', `importing the PNG: ${await alerts()}`);
    await until(() => thumbnail.evaluate((img) => img.complete && img.naturalWidth === 2), 'the texture thumbnail does not show');
    const box = (await sceneOf(page)).objects.at(-1);
    expect(box.material.texture?.type === 'image', `the box has no image texture: ${JSON.stringify(box.material)}`);
    await page.screenshot({ path: `${out}import-gltf-texture.png` });
  });

  await step('resolution presets with an aspect lock, and the ? panel of shortcuts', async () => {
    await page.keyboard.press('Escape');
    await page.getByLabel('Size preset').selectOption({ label: '1280 × 720 (HD)' });
    const width = page.getByLabel('Width (px)'), height = page.getByLabel('Height (px)');
    await until(async () => (await height.inputValue()) === '720', 'the HD preset did not set 1280x720');
    await page.getByLabel(/Lock aspect ratio/).check();
    await width.fill('1920');
    await width.press('Enter');
    await until(async () => (await height.inputValue()) === '1080', async () => `the locked height is ${await height.inputValue()}`);
    await page.getByLabel('Size preset').selectOption({ label: '1024 × 1024 (square)' });
    await until(async () => (await width.inputValue()) === '1024' && (await height.inputValue()) === '1024', 'the square preset did not apply');
    await page.evaluate(() => document.activeElement?.blur()); // typing ? in a field stays typing
    await page.keyboard.press('?');
    const help = page.getByRole('dialog', { name: 'Keyboard shortcuts' });
    await help.waitFor();
    expect((await help.innerText()).includes('W / E / R'), 'the panel does not list W / E / R');
    await page.screenshot({ path: `${out}shortcuts.png` });
    await page.keyboard.press('Escape');
    await help.waitFor({ state: 'detached' });
  });

  await step('multi-select: Shift-click and a Shift-drag box pick several; one drag moves them all, Delete removes them, each one undo step', async () => {
    await openScene(page, {
      name: 'multi',
      camera: { position: [0, 2, 8], lookAt: [0, 0.5, -3] },
      objects: [
        { type: 'sphere', name: 'left', center: [-2, 0.5, 0], radius: 0.5 },
        { type: 'sphere', name: 'middle', center: [0, 0.5, 0], radius: 0.5 },
        { type: 'box', name: 'right', center: [2, 0.5, 0], size: [1, 1, 1] },
        { type: 'plane' },
      ],
    });
    const top = page.getByTestId('top-view');
    const glyph = (i) => top.getByTestId(`object-${i}`);
    const centreOf = async (i) => {
      const b = await glyph(i).locator('circle, polygon').first().boundingBox();
      return [b.x + b.width / 2, b.y + b.height / 2];
    };
    await glyph(0).locator('circle').first().click();
    await glyph(1).locator('circle').first().click({ modifiers: ['Shift'] });
    await page.getByText('2 selected').waitFor();
    expect((await glyph(2).getAttribute('data-selected')) === 'false', 'the box was selected without being picked');
    // drag the middle sphere: both spheres move by the same amount, the box stays
    const [x, y] = await centreOf(1);
    await page.mouse.move(x + 4, y + 4);
    await page.mouse.down();
    for (let i = 1; i <= 8; i++) await page.mouse.move(x + 4 + 5 * i, y + 4);
    await page.mouse.up();
    let scene = await sceneOf(page);
    const dx = scene.objects[1].center[0] - 0;
    expect(dx > 0.3, `the dragged sphere did not move: ${JSON.stringify(scene.objects[1].center)}`);
    expect(Math.abs(scene.objects[0].center[0] - (-2 + dx)) < 1e-9, `the other selected sphere did not move with it: ${JSON.stringify(scene.objects[0].center)}`);
    expect(scene.objects[2].center[0] === 2, 'the box moved without being selected');
    await page.getByRole('button', { name: 'Undo' }).click();
    await until(async () => (await sceneOf(page)).objects[0].center[0] === -2 && (await sceneOf(page)).objects[1].center[0] === 0, 'one undo did not put both spheres back');
    // a Shift-drag box around the middle sphere and the box adds them; then Delete removes all three
    const [mx, my] = await centreOf(1);
    const [bx, by] = await centreOf(2);
    await page.mouse.move(mx - 30, my - 40);
    await page.keyboard.down('Shift');
    await page.mouse.down();
    await page.mouse.move((mx + bx) / 2, my, { steps: 4 });
    await top.getByTestId('marquee').waitFor();
    await page.mouse.move(bx + 30, by + 40, { steps: 4 });
    await page.mouse.up();
    await page.keyboard.up('Shift');
    await page.getByText('3 selected').waitFor();
    await page.screenshot({ path: `${out}multi-select.png` });
    await page.keyboard.press('Delete');
    await until(async () => (await sceneOf(page)).objects.length === 1, 'Delete did not remove the three selected objects');
    await page.keyboard.press('Control+z');
    await until(async () => (await sceneOf(page)).objects.length === 4, 'one undo did not bring the three back');
  });

  await step('render history: two renders compared with a slider, the first one\'s scene restored, the last render shown again after a reload', async () => {
    const red = '#d03020', blue = '#2040d0';
    const scene = {
      name: 'history', image: { width: 160, height: 120 }, camera: { position: [0, 2, 6], lookAt: [0, 1, 0] },
      objects: [{ type: 'plane', material: { type: 'chalk' } }, { type: 'sphere', center: [0, 1, 0], radius: 1, material: { type: 'plastic', color: red } }],
    };
    await openScene(page, scene);
    const stats = page.getByTestId('render-stats');
    /** Renders, and returns the number the history gave the render (its caption on the stage). */
    const renderNumber = async (before) => {
      await page.getByTestId('render-button').click();
      let number;
      await until(async () => {
        number = /Render (\d+) ·/.exec(await stats.innerText({ timeout: 100 }).catch(() => ''))?.[1];
        return number !== undefined && number !== before;
      }, 'the render did not arrive in the history', 60000);
      return number;
    };
    const first = await renderNumber();
    await page.getByRole('navigation', { name: 'Scene contents' }).getByRole('button', { name: /^Sphere/ }).click();
    const hex = page.getByLabel('Color hex', { exact: true });
    await hex.fill(blue);
    await hex.press('Enter');
    const second = await renderNumber(first);

    await page.getByRole('button', { name: /^History/ }).click();
    const strip = page.getByRole('region', { name: 'Render history' });
    for (const n of [first, second]) {
      const name = await strip.getByRole('button', { name: new RegExp(`^Render ${n} history`) }).getAttribute('title');
      expect(/ · 160 × 120 px · up to 16 spp · /.test(name), `the history names a render "${name}"`);
    }
    await strip.getByRole('button', { name: `Compare Render ${first} with Render ${second}` }).click();
    const slider = page.getByRole('slider', { name: 'Divider between the two renders' });
    expect((await slider.getAttribute('aria-valuenow')) === '50', 'the slider does not start in the middle');
    expect((await page.getByTestId('compare-left').innerText()).includes(`Render ${first} ·`), 'the left side is not labelled as the first render');
    expect((await page.getByTestId('compare-right').innerText()).includes(`Render ${second} ·`), 'the right side is not labelled as the second render');
    const [left, right] = [page.getByTestId('compare-image-left'), page.getByTestId('compare-image-right')];
    const [a, b] = [await left.boundingBox(), await right.boundingBox()];
    expect(a.width > 300 && ['x', 'y', 'width', 'height'].every((k) => Math.abs(a[k] - b[k]) < 0.5), `the two renders are not drawn alike: ${JSON.stringify([a, b])}`);
    // the left image is the red sphere's render, the right the blue one's (their centre pixels)
    const centre = (image) => image.evaluate(async (el) => {
      const bitmap = await createImageBitmap(await (await fetch(el.getAttribute('href'))).blob());
      const canvas = new OffscreenCanvas(bitmap.width, bitmap.height);
      const g = canvas.getContext('2d');
      g.drawImage(bitmap, 0, 0);
      return Array.from(g.getImageData(bitmap.width / 2, bitmap.height / 2, 1, 1).data.slice(0, 3));
    });
    const [l, r] = [await centre(left), await centre(right)];
    expect(l[0] > l[2] + 40 && r[2] > r[0] + 40, `left ${l} is not the red render or right ${r} not the blue one`);
    await slider.focus();
    for (let i = 0; i < 5; i++) await page.keyboard.press('ArrowLeft');
    await page.keyboard.press('Shift+ArrowLeft');
    expect((await slider.getAttribute('aria-valuenow')) === '35', `the keys moved the slider to ${await slider.getAttribute('aria-valuenow')}`);
    const svg = await page.locator('.compare-view__svg').boundingBox();
    const divider = await page.locator('.compare-view__divider').boundingBox();
    const at = (divider.x + divider.width / 2 - a.x) / a.width;
    expect(Math.abs(at - 0.35) < 0.01, `the divider is drawn at ${at} of the image, not 0.35`);
    await page.mouse.click(a.x + a.width * 0.8, svg.y + svg.height / 2);
    expect(Math.abs(Number(await slider.getAttribute('aria-valuenow')) - 80) < 0.5, `a click at 80% put the slider at ${await slider.getAttribute('aria-valuenow')}`);
    await page.screenshot({ path: `${out}render-history-compare.png` });

    await strip.getByRole('button', { name: `Restore scene of Render ${first}` }).click();
    const colour = async () => (await sceneOf(page)).objects[1].material.color;
    await until(async () => (await colour()) === red, 'Restore scene did not bring the red sphere back');
    await until(async () => (await stats.innerText()).includes(`Render ${first} ·`), 'the stage does not show the restored render');
    expect(await page.getByText('Out of date', { exact: true }).count() === 0, 'the restored render is out of date');
    await page.getByRole('button', { name: 'Undo' }).click();
    await until(async () => (await colour()) === blue, 'one undo did not take the restore back');
    await page.getByRole('button', { name: 'Redo' }).click();
    await until(async () => (await colour()) === red, 'redo did not restore again');

    await page.reload();
    await page.getByTestId('top-view').waitFor();
    await page.getByRole('tab', { name: 'Image' }).click();
    await page.getByTestId('render-image').waitFor({ timeout: 5000 });
    await until(async () => (await stats.innerText()).includes(`Render ${second} ·`), async () => `after a reload the stage shows "${await stats.innerText()}"`);
    await page.getByText('Out of date', { exact: true }).waitFor({ timeout: 5000 });
    await page.getByRole('button', { name: /^History/ }).click();
    await strip.getByRole('button', { name: new RegExp(`^Render ${first} `) }).waitFor();
    await page.screenshot({ path: `${out}render-history-reloaded.png` });
  });

  await step('soft lights: an area light lights the floor in the preview and glows, turns by its aim in the top view; a radius shows', async () => {
    const soft = {
      name: 'soft', background: '#101418',
      camera: { position: [0, 2, 8], lookAt: [0, 0, 0], fov: 50 },
      lights: [{ type: 'area', position: [0, 3, 0], size: [2, 1], lookAt: [0, 0, 0], color: '#ffffff', intensity: 1, falloff: false, twoSided: false }],
      objects: [{ type: 'plane', point: [0, 0, 0], normal: [0, 1, 0], material: { type: 'chalk', color: '#cccccc' } }],
    };
    await page.getByRole('tab', { name: '3D preview' }).click();
    await openScene(page, soft);
    await page.keyboard.press('Escape');
    await page.waitForTimeout(300);
    const [under, far, face] = await previewColours(page, [
      await previewPixel(page, soft, [0, 0, 1.5]), await previewPixel(page, soft, [6, 0, 1.5]), await previewPixel(page, soft, [0, 3, 0]),
    ]);
    await page.screenshot({ path: `${out}preview-area-light.png` });
    expect(brightness(under) > 1.5 * brightness(far) && brightness(under) > 150, `the area light does not light the floor below it: ${under} below, ${far} aside`);
    expect(brightness(face) > 600, `the area light's face does not glow: ${face}`);
    const top = page.getByTestId('top-view');
    expect(await top.getByTestId('light-0').locator('polygon').count() === 1, 'no rectangle for the area light in the top view');
    const aim = await top.getByTestId('light-aim-0').boundingBox();
    const x = aim.x + aim.width / 2, y = aim.y + aim.height / 2;
    await page.mouse.move(x, y);
    await page.mouse.down();
    for (let i = 1; i <= 6; i++) await page.mouse.move(x + 8 * i, y);
    await page.mouse.up();
    await until(async () => Number(await page.getByLabel('Aim (look at) x').inputValue()) > 0, 'dragging the aim did not turn the light');
    const turned = (await sceneOf(page)).lights[0];
    expect(turned.position.join(',') === '0,3,0' && turned.lookAt[0] > 0, `the drag moved the wrong thing: ${JSON.stringify(turned)}`);
    await page.getByRole('button', { name: 'Undo' }).click();
    await page.getByTestId('add-light').click();
    await page.getByLabel('Radius').fill('0.5');
    await page.getByLabel('Radius').press('Enter');
    await top.getByTestId('light-radius-1').waitFor();
    await page.getByLabel('Radius').fill('-1');
    await page.getByLabel('Radius').press('Enter');
    expect((await page.getByLabel('Radius').getAttribute('aria-invalid')) === 'true', 'a negative radius is not flagged');
    expect((await sceneOf(page)).lights[1].radius === 0.5, 'a negative radius was taken');
    await page.keyboard.press('Escape');
  });

  await step('axe-core finds no accessibility violations in the main states, at 1024x768 and 1440x900', async () => {
    const axe = readFileSync(new URL('../node_modules/axe-core/axe.min.js', import.meta.url), 'utf8');
    const violations = async (state) => {
      await twoFrames(page);
      if (!(await page.evaluate(() => 'axe' in window))) await page.addScriptTag({ content: axe });
      const result = await page.evaluate(() => window.axe.run(document, { resultTypes: ['violations'] }));
      return result.violations.map((v) => `${state}: ${v.id} (${v.impact}) at ${v.nodes.map((n) => n.target.join(' ')).slice(0, 3).join(', ')}`);
    };
    const found = [];
    for (const [width, height] of [[1024, 768], [1440, 900]]) {
      await page.setViewportSize({ width, height });
      const at = `${width}x${height}`;
      await page.getByRole('tab', { name: '3D preview' }).click();
      found.push(...await violations(`${at} 3D preview`));
      await page.getByRole('tab', { name: 'Image' }).click();
      found.push(...await violations(`${at} image with its history`));
      await page.getByRole('tab', { name: 'JSON' }).click();
      found.push(...await violations(`${at} JSON`));
      await page.getByRole('tab', { name: '3D preview' }).click();
      await page.keyboard.press('?');
      await page.getByRole('dialog', { name: 'Keyboard shortcuts' }).waitFor();
      found.push(...await violations(`${at} shortcuts`));
      await page.keyboard.press('Escape');
    }
    await page.setViewportSize({ width: 1440, height: 1000 });
    expect(found.length === 0, `axe-core:\n${found.join('\n')}`);
  });

  await step('no uncaught errors in the page', async () => {
    expect(pageErrors.length === 0, `page errors: ${pageErrors.join('\n')}`);
  });
} catch {
  exitCode = 1;
} finally {
  await browser.close();
  server.stop();
}
const passed = results.filter((r) => r.ok).length;
console.log(`browser test: ${passed} passed, ${results.length - passed} failed (screenshots in ${out})`);
if (exitCode !== 0) console.log(server.log().slice(-4000));
process.exit(exitCode);
