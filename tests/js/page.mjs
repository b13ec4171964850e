// The interactive page in headless Chromium, as a designer uses it: load it, change a
// probability, drag a segment, download the segment's files, and check that they are the files
// `curdle generate` writes for the command the page shows. Bad input must show the server's
// message. Screenshots go to SCREENSHOT_DIR for a person to look at.
// Usage: node page.mjs CURDLE SCREENSHOT_DIR
import { execFileSync } from 'node:child_process';
import { mkdir, mkdtemp, readdir, readFile, rm, writeFile } from 'node:fs/promises';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { deflateSync } from 'node:zlib';
import { chromium } from 'playwright-core';
import { openModules, serve as serveOn } from './serve.mjs';

const [curdle, shots] = process.argv.slice(2);

// A greyscale PNG (8 bits, no filter) of `dark(x, y) ? 0 : 255`-style shades, rows from the top.
function greyPng(width, height, shade) {
  const rows = Buffer.alloc((width + 1) * height);
  for (let y = 0; y < height; ++y)
    for (let x = 0; x < width; ++x) rows[y * (width + 1) + 1 + x] = shade(x, y);
  const crcTable = Array.from({ length: 256 }, (_, n) => {
    let c = n;
    for (let k = 0; k < 8; ++k) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
    return c >>> 0;
  });
  const crc = (bytes) => {
    let c = 0xffffffff;
    for (const b of bytes) c = crcTable[(c ^ b) & 0xff] ^ (c >>> 8);
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
  const header = Buffer.alloc(13);
  header.writeUInt32BE(width, 0);
  header.writeUInt32BE(height, 4);
  header[8] = 8;  // bits; colour type 0 (grey)
  return Buffer.concat([Buffer.from([137, 80, 78, 71, 13, 10, 26, 10]), chunk('IHDR', header),
                        chunk('IDAT', deflateSync(rows)), chunk('IEND', Buffer.alloc(0))]);
}

// Three dark openings on a light wall, as a façade's mask draws them.
function maskDark(x, y) {
  return (x >= 20 && x < 60 && y >= 20 && y < 70) || (x >= 100 && x < 180 && y >= 40 && y < 90) ||
         (x >= 200 && x < 230 && y >= 60 && y < 120);
}
// Each field the page asks for, over its socket (a text frame: the query /api/field takes) or,
// when no socket opens, by fetch. `fieldAnswered(test)` resolves once the answer has come, with
// the request's address as /api/field has it ({url()}, as a response), for the first address
// that passes `test`. `fieldWays` counts the sockets opened, the queries sent on them and the
// fields fetched.
function watchFields(page) {
  const waiters = [];
  const ways = { sockets: 0, sent: 0, fetched: 0 };
  const answered = (address) => {
    const i = waiters.findIndex((w) => w.test(address));
    if (i >= 0) waiters.splice(i, 1)[0].resolve({ url: () => address });
  };
  page.on('websocket', (ws) => {
    if (!ws.url().includes('/api/field-socket')) return;
    ways.sockets++;
    const sent = [];
    ws.on('framesent', ({ payload }) => { ways.sent++; sent.push(`/api/field?${payload}`); });
    ws.on('framereceived', () => { const address = sent.shift(); if (address) answered(address); });
  });
  page.on('response', (r) => {
    if (!r.url().includes('/api/field?')) return;
    ways.fetched++;
    answered(r.url());
  });
  return [(test = () => true) => new Promise((resolve) => waiters.push({ test, resolve })), ways];
}

await mkdir(shots, { recursive: true });
const work = await mkdtemp(path.join(tmpdir(), 'curdle-page-'));
let failures = 0;
const check = (ok, what) => {
  console.log(`${ok ? 'ok' : 'FAIL'}: ${what}`);
  if (!ok) failures++;
};

// A server, on any free port of the loopback address.
const serve = (args) => serveOn(curdle, args);
const { server, url } = await serve([]);
const source = path.resolve(path.dirname(new URL(import.meta.url).pathname), '../..');

// The worker's merged drawing (web/glb_merge.js) of one triangle under a mirrored, turned
// and moved node, checked against the same transforms by hand: the page's models have no
// mirrored node, and a wrong turn there would draw it inside out.
{
  const merge = await import(path.join(source, 'web/glb_merge.js'));
  const buffer = new ArrayBuffer(3 * 12 * 2 + 3 * 2);
  new Float32Array(buffer, 0, 9).set([0, 0, 0, 1, 0, 0, 0, 1, 0]);  // a triangle facing +z
  new Float32Array(buffer, 36, 9).set([0, 0, 1, 0, 0, 1, 0, 0, 1]);
  new Uint16Array(buffer, 72, 3).set([0, 1, 2]);
  // The parent mirrors x and moves by (5, 0, 0); the child turns a quarter about y.
  const matrix = new Float32Array(32);
  matrix.set([-1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 5, 0, 0, 1], 0);
  matrix.set([0, 0, -1, 0, 0, 1, 0, 0, 1, 0, 0, 0, 0, 0, 0, 1], 16);
  const scene = { parent: new Int32Array([-1, 0]), mesh: new Int32Array([-1, 0]), matrix,
                  primitives: new Float64Array([0, 0, 3, 36, 72, 3, 5123, 0, 4]) };
  const [g] = (await merge.mergedDrawing(scene, buffer)).drawing;
  // By hand: the child takes (x, y, z) to (z, y, -x), the parent then to (5 - z, y, -x).
  const place = ([x, y, z]) => [5 - z, y, -x];
  const corners = [[0, 0, 0], [1, 0, 0], [0, 1, 0]].map(place);
  const drawn = [...g.index].map((i) => [...g.position.slice(i * 3, i * 3 + 3)]);
  const sameSet = corners.every((c) => drawn.some((d) => d.every((v, k) => Math.abs(v - c[k]) < 1e-6)));
  // The drawn winding's face normal against the turned normal: the same way for a face seen
  // from outside. The normal (0, 0, 1) turns to (-1, 0, 0).
  const [a, b, c] = drawn;
  const u = b.map((v, k) => v - a[k]), w = c.map((v, k) => v - a[k]);
  const face = [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]];
  const normal = [...g.normal.slice(0, 3)];
  check(sameSet && Math.abs(normal[0] + 1) < 1e-6 && Math.abs(normal[1]) < 1e-6 && Math.abs(normal[2]) < 1e-6 &&
        face[0] < 0 && g.min[0] === 5 && g.max[0] === 5,
        `the 3-D view's worker merges a mirrored node's triangle where it lies, facing out (corners ` +
        `${JSON.stringify(drawn)}, normal ${JSON.stringify(normal)}, face ${JSON.stringify(face)})`);
}

const browser = await chromium.launch({
  executablePath: '/usr/bin/chromium',
  args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-background-networking'],
});
try {
  const page = await browser.newPage({ viewport: { width: 1500, height: 1000 }, acceptDownloads: true });
  const [fieldAnswered, fieldWays] = watchFields(page);
  const pageErrors = [];
  page.on('pageerror', (e) => { pageErrors.push(e.stack || e.message); console.log('PAGEERROR', e.stack || e.message); });
  // The server's Content-Security-Policy must allow everything the page does.
  page.on('console', (m) => { if (/Content.Security.Policy/i.test(m.text())) pageErrors.push(m.text()); });
  await page.goto(url);
  await page.waitForSelector('body[data-ready="1"]', { timeout: 30000 });
  // The page's files are modules: none of the names they declare at their top level is a
  // global, as it was when they were classic scripts.
  const declared = [];
  for (const file of (await readdir(path.join(source, 'web'))).filter((f) => f.endsWith('.js')))
    for (const m of (await readFile(path.join(source, 'web', file), 'utf8')).matchAll(
      /^(?:export )?(?:async )?(?:function\*? *|const |let |var |class )([\w$]+)/gm)) declared.push(m[1]);
  const globals = await page.evaluate((names) => names.filter((n) =>  // an element's id aside
    !document.getElementById(n) && new Function(`return typeof ${n}`)() !== 'undefined'), declared);
  check(declared.length > 100 && globals.length === 0,
        `none of the page's ${declared.length} top-level names is a global (${globals.slice(0, 5)})`);
  await openModules(page);
  await page.screenshot({ path: path.join(shots, '1-loaded.png') });
  check(await page.locator('#values-table tr').count() === 3, 'the values table has a header and two values');
  check((await page.textContent('#segment-text')).includes('0,0,67,67'), 'the floor segment is preselected');

  // The canvas (WebGL, field_gl.js) shows each cell in its value's colour, y up: 500 cells
  // spread over the field, read back from the pixels at their centres. Then a colour picked in
  // the palette redraws from the cells the page holds, in the same turn of the page's event
  // loop: no new field is asked for until the picker rests.
  const refreshed = fieldAnswered((u) => u.includes('12ab34'));
  const canvasCheck = await page.evaluate(async () => {
    // The cells as /api/generate sends them (a byte a cell, base64), not as the canvas got them.
    const sent = await (await fetch('/api/generate?' + app.query({ cells: '1' }))).json();
    const cells = Uint8Array.from(atob(sent.values), (c) => c.charCodeAt(0));
    const sample = () => {
      const c = document.querySelector('#curd');
      const copy = document.createElement('canvas');
      copy.width = c.width;
      copy.height = c.height;
      const ctx = copy.getContext('2d');
      ctx.drawImage(c, 0, 0);
      const [w, h] = canvas.fieldSize();
      const wrong = [];
      for (let k = 0; k < 500; ++k) {
        const x = (k * 7919) % w, y = (k * 104729) % h;
        const px = Math.floor((x + 0.5) / w * c.width), py = Math.floor((h - 1 - y + 0.5) / h * c.height);
        const got = ctx.getImageData(px, py, 1, 1).data;
        const want = canvas.hexToRgb(page_state.state.whole.legend[cells[y * w + x]].colour);
        if (want.some((v, i) => Math.abs(v - got[i]) > 2)) wrong.push(`${x},${y}: ${[...got].slice(0, 3)} not ${want}`);
      }
      return wrong;
    };
    const first = sample();
    const asked = field_fetch.fieldIds;
    const input = document.querySelectorAll('#palette input[type=color]')[1];
    input.value = '#12ab34';
    input.dispatchEvent(new Event('input'));
    return { first, recoloured: sample(), asked: field_fetch.fieldIds - asked, colour: page_state.state.whole.legend[1].colour };
  });
  check(canvasCheck.first.length === 0, `every sampled cell is drawn in its value's colour (${canvasCheck.first.slice(0, 3).join('; ')})`);
  check(canvasCheck.asked === 0 && canvasCheck.recoloured.length === 0 && canvasCheck.colour === '#12ab34',
        `a palette colour redraws at once without a new field (${canvasCheck.asked} asked, ${canvasCheck.recoloured.length} cells wrong)`);
  await refreshed;
  await page.waitForFunction(() => page_state.state.whole.legend[1].colour === '#12ab34' && !document.querySelector('#status').textContent.includes('generating'));

  // A probability through its text field: the request carries the override, the report moves.
  const before = await page.textContent('#values-table');
  const generated = fieldAnswered();
  await page.fill('input[aria-label="Curd 0 stage 1 probability"]', '3/4');
  await page.press('input[aria-label="Curd 0 stage 1 probability"]', 'Enter');
  const response = await generated;
  check(decodeURIComponent(response.url()).includes('curds.0.probabilities=["3/4","1/2","1/3"]'),
        'the changed probability is sent as a recipe override');
  await page.waitForFunction((old) => document.querySelector('#values-table').textContent !== old, before);
  const slider = page.locator('input[aria-label="Curd 0 stage 1 probability slider"]');
  check(Math.abs(Number(await slider.inputValue()) - 0.75) < 1e-9, 'the slider follows the fraction');
  check((await page.textContent('#status')).includes('server'), 'the status shows the server time');

  check(fieldWays.sockets === 1 && fieldWays.sent >= 3 && fieldWays.fetched === 0,
        `the fields come over one open socket, none fetched (${fieldWays.sockets} socket, ` +
        `${fieldWays.sent} asked, ${fieldWays.fetched} fetched)`);

  // A slider sends its decimal.
  const slid = fieldAnswered();
  await page.locator('input[aria-label="Curd 0 stage 2 probability slider"]').fill('0.6');
  check(decodeURIComponent((await slid).url()).includes('curds.0.probabilities=["3/4","0.6","1/3"]'),
        'a slider move sends the new probability');
  check((await page.inputValue('input[aria-label="Curd 0 stage 2 probability"]')) === '0.6', 'the fraction field follows the slider');
  await page.fill('input[aria-label="Curd 0 stage 2 probability"]', '1/2');
  await page.press('input[aria-label="Curd 0 stage 2 probability"]', 'Enter');

  // A segment fixed in metres: 3 x 2.4 m of 300 mm tiles is 10 x 8 cells.
  await page.check('input[name=fix][value=metres]');
  await page.fill('#fix-w', '3');
  await page.fill('#fix-h', '2.4');
  await page.dispatchEvent('#fix-h', 'change');
  await page.waitForFunction(() => / 0,0,10,8 /.test(' ' + document.querySelector('#segment-text').textContent.split(' ')[1] + ' '));
  check((await page.textContent('#segment-text')).includes('3.00 × 2.40 m'), 'a segment fixed in metres is 10 x 8 cells, 3 x 2.4 m');

  // A window typed in, and one outside the field refused with the field's size.
  await page.fill('#window-text', '5,6,30,20');
  const typed = page.waitForResponse((r) => r.url().includes('window=5%2C6%2C30%2C20') && r.url().includes('cells=0'));
  await page.dispatchEvent('#window-text', 'change');
  await typed;
  await page.waitForFunction(() => document.querySelector('#export-what').textContent.includes('5,6,30,20'));
  check(true, 'a typed window selects that segment');
  await page.fill('#window-text', '250,0,30,20');
  await page.dispatchEvent('#window-text', 'change');
  // The message may come after the change event returns: wait for it, then check its words.
  await page.waitForFunction(() => document.querySelector('#error').textContent.includes('inside the field'),
                             null, { timeout: 10000 }).catch(() => {});
  check((await page.textContent('#error')).includes('inside the field of 256 × 256 cells'), 'a window outside the field is refused');

  // A free drag, snapped to cells.
  await page.check('input[name=fix][value=free]');
  const box = await page.locator('#curd').boundingBox();
  const at = (x, y) => [box.x + (x + 0.5) * box.width / 256, box.y + (255 - y + 0.5) * box.height / 256];
  await page.mouse.move(...at(20, 30));
  await page.mouse.down();
  await page.mouse.move(...at(40, 50), { steps: 5 });
  await page.mouse.move(...at(59, 70), { steps: 5 });
  await page.mouse.up();
  await page.waitForFunction(() => document.querySelector('#segment-text').textContent.includes('20,30,40,41'));
  check(true, 'a free drag selects cells 20,30 to 59,70 (40 x 41)');
  await page.waitForSelector('#values-table th.seg');
  check(true, 'the segment\'s counts are shown beside the whole field\'s');

  // A segment fixed to the floor's 67 x 67 cells, placed by a drag.
  await page.check('input[name=fix][value=floor]');
  await page.mouse.move(...at(120, 90));
  await page.mouse.down();
  await page.mouse.move(...at(140, 110), { steps: 5 });
  await page.mouse.up();
  await page.waitForFunction(() => / 107,77,67,67 /.test(' ' + document.querySelector('#segment-text').textContent.split(' ')[1] + ' '));
  check(true, 'a fixed segment of 67 x 67 cells follows the drag (107,77,67,67)');
  await page.waitForFunction(() => document.querySelector('#command').textContent.includes('--window 107,77,67,67'));
  await page.waitForFunction(() => document.querySelector('#export-what').textContent.includes('107,77,67,67'));
  // The layout drawing follows once the controls rest; wait for the one of this segment.
  const layoutShown = (win) => page.waitForFunction((w) => {
    const img = document.querySelector('#layout-preview');
    return img.dataset.shown === img.dataset.src && img.dataset.shown.includes(encodeURIComponent(w)) &&
           img.complete && img.naturalWidth > 0;
  }, win, { timeout: 30000 });
  await layoutShown('107,77,67,67');
  check((await page.textContent('#layout-caption')).includes('segment 107,77,67,67'), 'the segment\'s layout.png is drawn below the curd');
  await page.screenshot({ path: path.join(shots, '2-segment.png'), fullPage: true });

  // The 3-D view: the segment's layout.glb (the download's bytes) drawn by three.js, not blank,
  // and a click on an element names it.
  const shown3d = (win) => page.waitForFunction((w) => window.view3d && window.view3d.src &&
      window.view3d.src.includes(encodeURIComponent(w)) && !document.querySelector('#view3d').classList.contains('stale'),
      win, { timeout: 60000 });
  await shown3d('107,77,67,67');
  const drawn = await page.evaluate(() => window.view3d.drawn);
  check(drawn > 0.2, `the 3-D view draws the segment's layout.glb (${(drawn * 100).toFixed(0)} % of the picture)`);
  // The model is read in the page's worker, and is what three.js's own loader makes of the same
  // bytes: every element by name, with its extras, world box and material.
  const sameAsLoader = await page.evaluate(async () => {
    const THREE = await import('three');
    const { GLTFLoader } = await import('three/addons/loaders/GLTFLoader.js');
    const bytes = await (await fetch(window.view3d.src)).arrayBuffer();
    const theirs = (await new GLTFLoader().parseAsync(bytes, '')).scene;
    const describe = (root) => {
      root.updateMatrixWorld(true);
      const out = [];
      root.traverse((o) => {
        if (!o.userData || o.userData.value === undefined) return;
        const b = new THREE.Box3().setFromObject(o);
        const mats = [];
        o.traverse((m) => { if (m.isMesh) mats.push(m.material.name + '#' + m.material.color.getHexString()); });
        out.push([o.name, JSON.stringify(o.userData), ...b.min.toArray(), ...b.max.toArray()]
          .map((v) => (typeof v === 'number' ? v.toFixed(5) : v)).join(' ') + ' ' + mats.join(','));
      });
      return out.sort();
    };
    const a = describe(window.view3d.model()), b = describe(theirs);
    const differ = a.findIndex((line, i) => line !== b[i]);
    return { readIn: window.view3d.readIn, count: a.length, same: a.length === b.length && differ < 0,
             first: differ < 0 ? '' : `${a[differ]} | ${b[differ]}` };
  });
  check(sameAsLoader.readIn === 'worker' && sameAsLoader.same && sameAsLoader.count > 100,
        `the 3-D view reads layout.glb in its worker (${sameAsLoader.readIn}), into the same ${sameAsLoader.count} elements ` +
        `as three.js's loader: names, extras, boxes and materials ${sameAsLoader.first}`);
  // The camera draws the elements merged into a mesh a material: the same picture as drawn one
  // by one.
  const agrees = await page.evaluate(() => window.view3d.mergedAgrees());
  check(agrees.differ < 0.02 && agrees.merged > 0.2 && Math.abs(agrees.merged - agrees.elements) < 0.005,
        `the 3-D view's merged meshes draw what its elements would (${(agrees.differ * 100).toFixed(2)} % of pixels differ; ` +
        `${(agrees.merged * 100).toFixed(1)} % covered against ${(agrees.elements * 100).toFixed(1)} %)`);
  await page.evaluate(() => document.querySelector('#view3d').scrollIntoView({ block: 'center' }));
  const target = await page.evaluate(() => window.view3d.pointOnElement());
  check(!!target, 'an element of the 3-D view can be found under the pointer');
  if (target) {
    await page.mouse.click(target.x, target.y);
    await page.waitForFunction((id) => document.querySelector('#view3d-info').dataset.id === id, target.id, { timeout: 10000 });
    const said = await page.textContent('#view3d-info');
    // The value and material of that element in the segment's own schedule.csv.
    const rows = (await (await page.request.get(url + 'api/export?' + await page.evaluate(() =>
      app.query({ file: 'schedule.csv', window: app.windowText() })))).text()).split(/\r?\n/);
    const header = rows[0].replace(/^\ufeff/, '').split(',');
    const row = rows.find((r) => r.startsWith(target.id + ','));
    const field = (name) => row && row.split(',')[header.indexOf(name)];
    check(!!row && said === `${target.id}: value ${field('value')}` + said.slice(`${target.id}: value ${field('value')}`.length) &&
          said.endsWith(', ' + field('material')),
          `a click on ${target.id} in 3-D shows its ID, value and material as schedule.csv has them: ${said}`);
  }
  // A click finds its element in the merged drawing the camera shows, as among the elements'
  // own objects, at every point of a grid; a click on none says so.
  const picks = await page.evaluate(() => window.view3d.picksAgree(16));
  check(picks.differ === 0 && picks.hits > 20 && picks.empty,
        `a click finds the same element in the merged drawing as among the elements (${picks.points} points, ` +
        `${picks.hits} on elements, ${picks.differ} differ ${JSON.stringify(picks.first)})`);
  if (picks.empty) {
    await page.mouse.click(picks.empty.x, picks.empty.y);
    await page.waitForFunction(() => document.querySelector('#view3d-info').textContent.startsWith('No element there'),
                               null, { timeout: 10000 });
    check(await page.evaluate(() => document.querySelector('#view3d-info').dataset.id === ''),
          'a click on no element says so');
  }
  await page.locator('#view3d-figure').screenshot({ path: path.join(shots, '2b-segment-3d.png') });
  // Dragged upwards (60 pixels once put the eye under the paving) and far beyond, the eye stays
  // above ground; Reset view brings back the first view.
  const eye0 = await page.evaluate(() => window.view3d.eyeAboveGround());
  const canvas3d = await page.locator('#view3d canvas').boundingBox();
  for (const dy of [60, 400]) {
    await page.mouse.move(canvas3d.x + canvas3d.width / 2, canvas3d.y + canvas3d.height / 2);
    await page.mouse.down();
    await page.mouse.move(canvas3d.x + canvas3d.width / 2, canvas3d.y + canvas3d.height / 2 - dy, { steps: 8 });
    await page.mouse.up();
    const eye = await page.evaluate(() => window.view3d.eyeAboveGround());
    check(eye >= 0.29, `a ${dy}-pixel upward drag leaves the eye above ground (${eye.toFixed(2)} m)`);
  }
  await page.click('#view3d-reset');
  const eyeReset = await page.evaluate(() => window.view3d.eyeAboveGround());
  check(Math.abs(eyeReset - eye0) < 1e-6, `Reset view returns to the first view (eye ${eyeReset.toFixed(2)} m)`);
  const loads = await page.evaluate(() => window.view3d.loads);

  // Downloads, and the same files from the command line with the command the page shows.
  const names = ['layout.svg', 'layout.glb', 'schedule.csv', 'quantities.csv', 'report.json', 'recipe.toml'];
  const downloads = path.join(work, 'page');
  await mkdir(downloads);
  for (const name of names) {
    const [download] = await Promise.all([page.waitForEvent('download'), page.click(`#exports a[download="${name}"]`)]);
    check(download.suggestedFilename() === name, `download ${name} is named ${download.suggestedFilename()}`);
    await download.saveAs(path.join(downloads, name));
  }
  const command = (await page.textContent('#command')).trim();
  check(command.startsWith('curdle generate ') && command.includes(" --set 'curds.0.probabilities=[\"3/4\",\"1/2\",\"1/3\"]'") &&
        command.includes('--seed 8') && command.endsWith('--window 107,77,67,67'), `the command reproduces the run: ${command}`);
  const cli = path.join(work, 'cli');
  // Only the files compared: the run's other outputs (its drawing set) would only cost time.
  const compared = names.filter((n) => n !== 'recipe.toml').join(',');
  execFileSync('bash', ['-c', `${JSON.stringify(curdle)} ${command.slice('curdle '.length)} --out ${cli} --outputs ${compared} > /dev/null`]);
  for (const name of names.filter((n) => n !== 'recipe.toml')) {
    const [a, b] = await Promise.all([readFile(path.join(downloads, name)), readFile(path.join(cli, name))]);
    check(a.equals(b), `${name} from the page equals the CLI's (${a.length} bytes)`);
  }
  // The recipe download reproduces the segment with no options at all.
  const fromRecipe = path.join(work, 'from-recipe');
  execFileSync(curdle, ['generate', path.join(downloads, 'recipe.toml'), '--out', fromRecipe, '--outputs', 'schedule.csv,report.json']);
  const [s1, s2] = await Promise.all([readFile(path.join(downloads, 'schedule.csv')), readFile(path.join(fromRecipe, 'schedule.csv'))]);
  check(s1.equals(s2), 'recipe.toml alone reproduces the segment\'s schedule.csv');


  // Bad input: the page's own check, and the server's message shown as it is.
  await page.fill('input[aria-label="Curd 0 stage 2 probability"]', '1.5');
  await page.press('input[aria-label="Curd 0 stage 2 probability"]', 'Enter');
  await page.waitForSelector('#error:not([hidden])');
  check((await page.textContent('#error')).includes('not a probability'), 'an impossible probability is refused on the page');
  await page.fill('#base', '1');
  await page.dispatchEvent('#base', 'change');
  await page.waitForFunction(() => document.querySelector('#error').textContent.includes('lattice.base'));
  check((await page.textContent('#error')).includes('from 2 to 64'), 'the server\'s 400 message is shown: ' + await page.textContent('#error'));
  await page.screenshot({ path: path.join(shots, '3-error.png') });
  await page.click('#reset');
  await page.waitForFunction(() => document.querySelector('#error').hidden);

  // Search from the page: the best hit is loaded when its row is clicked.
  await page.fill('#search-seeds', '1..120');
  await page.fill('#search-targets', 'ratio:dark=0.111\ncluster:dark<=8');
  await page.click('#search-run');
  await page.waitForSelector('#search-results tr.hit', { timeout: 60000 });
  const first = page.locator('#search-results tr.hit').first();
  const seed = await first.getAttribute('data-seed');
  const win = await first.getAttribute('data-window');
  await first.click();
  await page.waitForFunction((w) => document.querySelector('#command').textContent.includes(`--window ${w}`), win);
  check((await page.inputValue('#seed')) === seed, `clicking the best hit loads seed ${seed} and segment ${win}`);
  await layoutShown(win);
  // The segment moved to the hit: the 3-D view reloads with that segment's layout.glb.
  await shown3d(win);
  check(await page.evaluate(() => window.view3d.loads) > loads, `moving the segment (to ${win}) reloads the 3-D view`);
  await page.screenshot({ path: path.join(shots, '4-search.png'), fullPage: true });

  // A picture measured and fitted with the page's lattice: the fitted recipe is the one
  // `curdle fit` writes, and loading it makes its lattice, field and curds the page's.
  await page.click('#reset');
  await page.waitForFunction(() => document.querySelector('#error').hidden);
  // A façade's mask with a dark pixel every 7 columns of row 3, so that it is not drawn in cells
  // of several pixels (the gallery's mask is: fit reads its 2 x 2 pixel cells as 120 x 60).
  const picture = path.join(work, 'mask-pixels.png');
  await writeFile(picture, greyPng(240, 120, (x, y) => (y === 3 && x % 7 === 0) || maskDark(x, y) ? 0 : 255));
  await page.setInputFiles('#measure-file', picture);
  await page.waitForSelector('#measure-result:not([hidden])');
  const measuredBody = await page.evaluate(() => measure.measured.result);
  const [base, stages] = [await page.inputValue('#base'), await page.inputValue('#stages')];
  const fitted = path.join(work, 'fitted.toml');
  execFileSync(curdle, ['fit', picture, '--base', base, '--stages', stages, '--out', fitted]);
  check(measuredBody.fit.recipe_toml === await readFile(fitted, 'utf8'),
        `the page's fitted recipe is the one curdle fit writes (base ${base}, ${stages} stages)`);
  check(await page.locator('#measure-values tr').count() === 3, 'the picture is measured as two values');
  check(await page.locator('#measure-fit tr').count() === 1 + Number(stages), 'a fitted row per stage');
  check(await page.locator('#measure-plot').evaluate((c) => c.width > 0 && c.height > 0), 'the box counts are plotted');
  const loaded = fieldAnswered();
  await page.click('#measure-load');
  const loadedUrl = decodeURIComponent((await loaded).url());
  check(loadedUrl.includes('field.cells=[240,120]'), 'loading the fit sets the field to the picture: 240 x 120 cells');
  const p1 = measuredBody.fit.curds[0].probabilities[0];
  check(loadedUrl.includes(`"${p1}"`), `loading the fit sends its probabilities (p1 = ${p1})`);
  await page.waitForFunction(() => document.querySelector('#status').textContent.includes('28,800 cells') ||
                                   document.querySelector('#status').textContent.includes('28800 cells'));
  check(await page.locator('#error').isHidden(), 'the fitted recipe generates without error');
  await page.screenshot({ path: path.join(shots, '5-measure.png'), fullPage: true });
  const notPicture = path.join(work, 'not-a-picture.png');
  await writeFile(notPicture, 'plain text');
  await page.setInputFiles('#measure-file', notPicture);
  await page.waitForFunction(() => document.querySelector('#error').textContent.includes('cannot read the picture not-a-picture.png'));
  check(true, 'a file that is no picture shows the server\'s message');
  // The three-tone paving's preview read as one Markov curd of two states: the chain with its
  // intervals, the readings compared, and the recipe shown is the one `curdle fit --states 2` writes.
  const paving = path.join(work, 'paving');
  execFileSync(curdle, ['generate', path.join(source, 'patterns/paving-three-tone-markov.toml'),
                        '--out', paving, '--outputs', 'preview.png']);
  await page.fill('#measure-states', '2');
  await page.setInputFiles('#measure-file', path.join(paving, 'preview.png'));
  await page.waitForFunction(() => measure.measured.result && measure.measured.result.fit.recipe_is_chain);
  const chainBody = await page.evaluate(() => measure.measured.result);
  const [chainBase, chainStages] = [await page.inputValue('#base'), await page.inputValue('#stages')];
  const chainFitted = path.join(work, 'chain.toml');
  execFileSync(curdle, ['fit', path.join(paving, 'preview.png'), '--base', chainBase, '--stages', chainStages,
                        '--states', '2', '--out', chainFitted]);
  check(chainBody.fit.recipe_toml === await readFile(chainFitted, 'utf8'),
        'the page\'s fitted chain is the one curdle fit --states 2 writes');
  check(await page.locator('#measure-recipe').isVisible(), 'the fitted recipe is shown');
  check(await page.locator('#measure-load').isHidden(), 'a chain is downloaded, not loaded into the plain curds');
  check((await page.textContent('#measure-readings')).includes('(supported)'), 'the supported reading is named');
  check(await page.locator('#measure-fit tr').count() >= 5, 'the start and each row of the chain are listed');
  await page.screenshot({ path: path.join(shots, '5-measure-chain.png'), fullPage: true });
  await page.fill('#measure-states', '0');

  // A floor that is not a rectangle: the L-shaped courtyard's outline and zones are drawn over
  // the curd, and zones drawn or typed in metres go to the layout and to the search.
  const yard = await serve([path.join(source, 'patterns/courtyard-l-shaped.toml')]);
  try {
    await page.goto(yard.url);
    await page.waitForSelector('body[data-ready="1"]', { timeout: 30000 });
    await openModules(page);
    const overlay = page.locator('#surface-overlay');
    check(await overlay.locator('polygon.outline').count() === 1 &&
          (await overlay.locator('polygon.outline').getAttribute('points')).split(' ').length === 6,
          'the courtyard\'s L-shaped outline (6 corners) is drawn over the curd');
    check(await overlay.locator('polygon.zone.exclude').count() === 1 && await overlay.locator('polygon.zone.value').count() === 1,
          'its planter (kept free) and entrance band (one value) are drawn');
    // A drag from beyond the floor's bottom-left to beyond its top-right is clamped to the floor.
    await page.check('#zone-draw');
    const segmentBefore = await page.inputValue('#window-text');
    const box = await page.locator('#curd').boundingBox();
    await page.mouse.move(box.x + 1, box.y + box.height - 1);
    await page.mouse.down();
    await page.mouse.move(box.x + box.width - 1, box.y + 1, { steps: 4 });
    await page.mouse.up();
    const drawn = await Promise.all(['#zone-x', '#zone-y', '#zone-w', '#zone-h'].map((id) => page.inputValue(id)));
    check(drawn.join() === '0,0,12,8', `a zone dragged over the whole floor is 0, 0, 12 x 8 m (${drawn.join(', ')})`);
    check(await page.inputValue('#window-text') === segmentBefore && await overlay.locator('polygon.zone.drawn').count() === 1,
          'the drawn zone is shown, and the segment is left as it was');
    // A zone typed in metres: a drain kept free, then a search that keeps it empty.
    for (const [id, v] of [['#zone-x', '9'], ['#zone-y', '1'], ['#zone-w', '2'], ['#zone-h', '1.5']]) await page.fill(id, v);
    await page.fill('#zone-name', 'drain');
    const zoned = fieldAnswered();
    await page.click('#zone-add');
    const zonedUrl = decodeURIComponent((await zoned).url()).replace(/\+/g, ' ');
    check(zonedUrl.includes('{name="drain",polygon=[[9000,1000],[11000,1000],[11000,2500],[9000,2500]],rule="exclude"}'),
          'the typed zone is sent as a layout zone in mm');
    await page.waitForFunction(() => document.querySelectorAll('#surface-overlay polygon.zone.exclude').length === 2);
    check(await page.locator('#error').isHidden(), 'the layout with the added zone generates without error');
    await page.locator('#canvas-wrap').screenshot({ path: path.join(shots, '6-courtyard-zones.png') });
    await page.click('#zone-target');
    check((await page.inputValue('#search-targets')).trim() === 'empty=9000,1000,2000,1500 mm', 'the zone becomes a search target in mm');
    await page.fill('#search-seeds', '1..6');
    const searched = page.waitForResponse((r) => r.url().includes('/api/search'));
    await page.click('#search-run');
    check((await searched).status() === 200, 'the search accepts the zone in mm');
    await page.click('button[aria-label="Remove zone drain"]');
    await page.waitForFunction(() => document.querySelectorAll('#surface-overlay polygon.zone.exclude').length === 1);
    check(true, 'a removed zone leaves the layout');
    await page.fill('#zone-w', '40');
    await page.click('#zone-add');
    check((await page.textContent('#error')).includes('inside the floor of 12 × 8 m'), 'a zone beyond the floor is refused, naming the floor');
    // A site from the architect's drawing: the courtyard's DXF, its layers given their roles
    // (guessed from their names), laid in place of the L, its arch sent as a bulge.
    await page.setInputFiles('#site-file', path.join(source, 'patterns/sites/courtyard.dxf'));
    await page.waitForSelector('#site-layers select');
    check(await page.locator('#site-layers select').count() === 3, 'the drawing\'s three layers are listed');
    check(await page.inputValue('select[aria-label="Role of layer A-OTLN"]') === 'outline' &&
          await page.inputValue('select[aria-label="Role of layer TREE_PIT"]') === 'zone',
          'the outline and the tree pit are guessed from their layers\' names');
    const laid = fieldAnswered();
    await page.click('#site-apply');
    const laidUrl = decodeURIComponent((await laid).url());
    check(laidUrl.includes('layout.outline=[[0,0],[14000,0],[14000,9000,-0.2'),
          'the outline is sent with its arch as a bulge');
    await page.waitForFunction(() => document.querySelector('#site-summary').textContent.includes(
        'outline 14,000 x 9,000 mm with 1 arc; 2 zones (TREE_PIT exclude, DRAIN exclude)'));
    // Laid once the command carries the outline and no error stands (the segment follows the
    // new floor after the whole field is back).
    await page.waitForFunction(() => document.querySelector('#command').textContent.includes('layout.outline=') &&
                                     document.querySelector('#error').hidden &&
                                     document.querySelectorAll('#surface-overlay polygon.zone.exclude').length === 2);
    check(await page.locator('#error').isHidden(), 'the courtyard laid from its drawing generates without error');
    await page.locator('#canvas-wrap').screenshot({ path: path.join(shots, '7-site-from-dxf.png') });
    // An office's site: its outline's top a SPLINE through 300 fit points (thousands of vertices
    // once drawn, far too long for an address: the page sends its query by POST), a frozen
    // older boundary listed as such and never guessed, the pit listed by its diameter.
    const fit = Array.from({ length: 300 }, (_, k) => {
      const t = k / 299;
      return [7000 + 7000 * Math.cos(Math.PI * t), 6000 * Math.sin(Math.PI * t) * (1 + 0.08 * Math.sin(12 * Math.PI * t))];
    });
    const groups = (pairs) => pairs.map(([c, v]) => `${c}\n${v}\n`).join('');
    const dxf = groups([[0, 'SECTION'], [2, 'HEADER'], [9, '$INSUNITS'], [70, 4], [0, 'ENDSEC'],
      [0, 'SECTION'], [2, 'TABLES'], [0, 'TABLE'], [2, 'LAYER'],
      [0, 'LAYER'], [2, 'L-SITE-BNDY'], [70, 0], [62, 7], [0, 'LAYER'], [2, 'L-SITE-BNDY-OLD'], [70, 1], [62, 7],
      [0, 'LAYER'], [2, 'L-PLNT-PITS'], [70, 0], [62, 3], [0, 'ENDTAB'], [0, 'ENDSEC'],
      [0, 'SECTION'], [2, 'ENTITIES'],
      [0, 'LINE'], [5, '10'], [8, 'L-SITE-BNDY'], [10, 0], [20, 0], [30, 0], [11, 14000], [21, 0], [31, 0],
      [0, 'SPLINE'], [5, '11'], [8, 'L-SITE-BNDY'], [70, 8], [71, 3], [74, 300],
      ...fit.flatMap(([x, y]) => [[11, x.toFixed(4)], [21, y.toFixed(4)], [31, 0]]),
      [0, 'LWPOLYLINE'], [5, '12'], [8, 'L-SITE-BNDY-OLD'], [90, 4], [70, 1],
      [10, -500], [20, -500], [10, 14500], [20, -500], [10, 14500], [20, 7000], [10, -500], [20, 7000],
      [0, 'CIRCLE'], [5, '13'], [8, 'L-PLNT-PITS'], [10, 7000], [20, 2000], [30, 0], [40, 750],
      [0, 'LWPOLYLINE'], [5, '14'], [8, 'L-SITE-BNDY'], [90, 4], [70, 1],
      [10, 16000], [20, 0], [10, 21000], [20, 0], [10, 21000], [20, 4000], [10, 16000], [20, 4000],
      [0, 'ENDSEC'], [0, 'EOF']]);
    const spline = path.join(work, 'office-spline.dxf');
    await writeFile(spline, dxf);
    await page.setInputFiles('#site-file', spline);
    await page.waitForFunction(() => document.querySelectorAll('#site-layers select').length === 3);
    check(await page.inputValue('select[aria-label="Role of layer L-SITE-BNDY"]') === 'outline' &&
          await page.inputValue('select[aria-label="Role of layer L-SITE-BNDY-OLD"]') === 'none' &&
          await page.inputValue('select[aria-label="Role of layer L-PLNT-PITS"]') === 'zone' &&
          (await page.textContent('#site-layers')).includes('L-SITE-BNDY-OLD (frozen or off in the drawing)'),
          'NCS layer names are guessed, and the frozen older boundary is shown as such and not guessed');
    const posted = [], tooLong = [];
    const onRequest = (r) => {
      if (r.method() === 'POST' && /\/api\/(field|generate|export)$/.test(r.url())) posted.push(r.postData().length);
    };
    const onResponse = (r) => { if (r.status() === 414) tooLong.push(r.url()); };
    page.on('request', onRequest);
    page.on('response', onResponse);
    // The outline's layer also holds the neighbouring plot: the page draws both and the
    // designer clicks inside the site, as CAD's BOUNDARY takes a pick point.
    check(await page.locator('#site-pick').isVisible() &&
          (await page.textContent('#site-pick-note')).includes('L-SITE-BNDY holds 2 closed regions'),
          'the outline layer\'s two regions are drawn to pick one by a click');
    await page.click('#site-apply');
    check((await page.textContent('#error')).includes('click inside the one that is the outline'),
          'laying before the click asks for it');
    await page.click('#site-pick', { position: await page.evaluate(() => site.sitePickPosition(7000, 3000)) });
    check((await page.textContent('#site-pick-note')).includes('around the point clicked'),
          'the click picks the region around it');
    await page.locator('#site-box').screenshot({ path: path.join(shots, '7c-site-pick.png') });
    await page.click('#site-apply');
    await page.waitForFunction(() => document.querySelector('#site-summary').textContent.includes('outline 14,000 x '));
    await page.waitForFunction(() => document.querySelector('#command').textContent.includes('layout.outline=') &&
                                     document.querySelector('#error').hidden &&
                                     document.querySelectorAll('#surface-overlay polygon.zone.exclude').length === 1,
                               null, { timeout: 30000 });
    page.off('request', onRequest);
    page.off('response', onResponse);
    check(posted.length > 0 && Math.max(...posted) > 20000 && !tooLong.length,
          `a site with a 300-point spline outline is laid, its long query sent by POST (${posted.length} requests, ` +
          `up to ${Math.max(0, ...posted)} bytes) and none refused as too long`);
    check((await page.textContent('#zone-list')).includes('L-PLNT-PITS: kept free, round, ⌀ 1.5 m'),
          'the round pit is listed by its diameter');
    await page.locator('#canvas-wrap').screenshot({ path: path.join(shots, '7b-site-spline.png') });
  } finally {
    yard.server.kill('SIGINT');
  }
  // A Markov curd: listed once with its states, its matrices left to the recipe; the values are
  // its states, the code no state has is not offered; a base change is still sent.
  const tones = await serve([path.join(source, 'patterns/paving-three-tone-markov.toml')]);
  try {
    await page.goto(tones.url);
    await page.waitForSelector('body[data-ready="1"]', { timeout: 30000 });
    await openModules(page);
    check(await page.locator('#curds .curd').count() === 1, 'the Markov curd is listed once, not by its bit planes');
    const note = await page.textContent('#curds .curd .note');
    check(note.includes('states dark, mid') && await page.locator('#curds .state-swatch').count() === 2,
          'it names its states with a swatch each');
    check(await page.isDisabled('#curd-count') && await page.isDisabled('#stages') &&
          await page.locator('#curds input[type=range]').count() === 0,
          'the curds\' count, the stages and probability sliders are not offered for it');
    const table = await page.textContent('#values-table');
    check(table.includes('dark') && table.includes('mid') && !table.includes('state 3'),
          'the values table lists its states and not the code no state has');
    const rebased = fieldAnswered();
    await page.selectOption('#mode', 'quota');
    const rebasedUrl = decodeURIComponent((await rebased).url());
    check(rebasedUrl.includes('lattice.mode="quota"') && !rebasedUrl.includes('curds'),
          'a mode change is sent alone, the Markov curd untouched');
    await page.waitForFunction(() => document.querySelector('#status').textContent.includes('server'));
    check(await page.locator('#error').isHidden(), 'the Markov curd generates in quota mode without error');
    await page.locator('#canvas-wrap').screenshot({ path: path.join(shots, '8-markov-paving.png') });
  } finally {
    tones.server.kill('SIGINT');
  }
  // A whole building: its façades named and its corners dashed on the unrolled strip, no floor
  // zones or site drop, a segment of a larger curd placed along the strip, the building in 3-D.
  const kiosk = await serve([path.join(source, 'patterns/kiosk-from-dxf.toml')]);
  try {
    await page.goto(kiosk.url);
    await page.waitForSelector('body[data-ready="1"]', { timeout: 30000 });
    await openModules(page);
    await page.waitForFunction(() => document.querySelectorAll('#surface-overlay line.corner').length === 4);
    const names = await page.locator('#surface-overlay text.facade-name').allTextContents();
    check(names.join() === 'S,E,N,W', `the kiosk's four façades are named on the strip (${names.join()}), its corners dashed`);
    check(await page.locator('#zone-box').isHidden() && await page.locator('#site-box').isHidden(),
          'a building offers no floor zones and no site drop: its plan and openings are the recipe\'s');
    check((await page.textContent('#fix-floor-label')).trim() === 'the strip', 'the segment is fixed to the strip');
    const cornerAt = () => page.evaluate(() => Number(document.querySelector('#surface-overlay line.corner').getAttribute('x1')));
    // Round the kiosk the field is a ring turned by its phase; a field of given cells is laid
    // from the strip's start, a cell a unit: the corners compared in that field.
    await page.fill('#field-w', '245');
    await page.dispatchEvent('#field-w', 'change');
    await page.waitForFunction(() => document.querySelector('#status').textContent.includes('9,800 cells'));
    await page.fill('#window-text', '0,0,117,40');
    await page.dispatchEvent('#window-text', 'change');
    await page.waitForFunction(() => document.querySelector('#command').textContent.includes('--window 0,0,117,40'));
    await page.waitForFunction(() => document.querySelectorAll('#surface-overlay line.corner').length === 4);
    const before = await cornerAt();
    await page.fill('#window-text', '64,0,117,40');
    await page.dispatchEvent('#window-text', 'change');
    await page.waitForFunction(() => / 64,0,117,40 /.test(' ' + document.querySelector('#segment-text').textContent.split(' ')[1] + ' '));
    await page.waitForFunction(() => document.querySelector('#command').textContent.includes('--window 64,0,117,40'));
    const after = await cornerAt();
    check(Math.abs(after - before - 64) < 1e-6 && await page.locator('#error').isHidden(),
          `a strip segment placed along a larger curd (64,0,117,40) moves the corners with it (${before} to ${after})`);
    await page.waitForFunction(() => window.view3d && window.view3d.loads > 0 &&
                               window.view3d.src.includes(encodeURIComponent('64,0,117,40')) &&
                               !document.querySelector('#view3d').classList.contains('stale'), null, { timeout: 60000 });
    await page.evaluate(() => document.querySelector('#view3d').scrollIntoView({ block: 'center' }));
    const target = await page.evaluate(() => window.view3d.pointOnElement());
    check(target && /^F-R\d+-C\d+$/.test(target.id), `the building stands in the 3-D view, a brick found by its ID (${target && target.id})`);
    const buildingPicks = await page.evaluate(() => window.view3d.picksAgree(16));
    check(buildingPicks.differ === 0 && buildingPicks.hits > 10,
          `a click on the building finds the brick the bricks' own objects find (${buildingPicks.points} points, ` +
          `${buildingPicks.hits} on bricks, ${buildingPicks.differ} differ ${JSON.stringify(buildingPicks.first)})`);
    const building = await page.evaluate(() => window.view3d.mergedAgrees());
    check(building.differ < 0.02 && building.merged > 0.05,
          `the building's merged meshes draw what its bricks would (${(building.differ * 100).toFixed(2)} % of pixels differ)`);
    await page.locator('#canvas-wrap').screenshot({ path: path.join(shots, '9-building-strip.png') });
  } finally {
    kiosk.server.kill('SIGINT');
  }
  // With every field socket the server keeps held open elsewhere, the page fetches its fields
  // instead and draws them the same.
  const holder = await browser.newPage();
  await holder.goto(url + 'style.css');
  const held = await holder.evaluate(() => Promise.all(Array.from({ length: 8 }, () => new Promise((resolve) => {
    const s = new WebSocket(`ws://${location.host}/api/field-socket`);
    s.onopen = () => resolve(1);
    s.onclose = () => resolve(0);
  }))));
  const fallback = await browser.newPage({ viewport: { width: 1500, height: 1000 } });
  const [, fallbackWays] = watchFields(fallback);
  await fallback.goto(url);
  await fallback.waitForSelector('body[data-ready="1"]', { timeout: 30000 });
  await openModules(fallback);
  const seedBefore = await fallback.evaluate(() => page_state.state.whole.seed);
  await fallback.click('#seed-next');
  await fallback.waitForFunction((s) => page_state.state.whole && page_state.state.whole.seed !== s, seedBefore);
  check(held.every(Boolean) && fallbackWays.fetched >= 2 && fallbackWays.sent === 0 &&
        await fallback.locator('#error').isHidden(),
        `with the server's ${held.length} field sockets held, the page fetches its fields and draws them ` +
        `(${fallbackWays.fetched} fetched, ${fallbackWays.sent} sent on a socket)`);
  await fallback.close();
  await holder.close();
  check(pageErrors.length === 0, `no script errors on the page ${pageErrors.join('; ')}`);
} finally {
  await browser.close();
  server.kill('SIGINT');
  const code = await new Promise((resolve) => server.on('exit', (c) => resolve(c)));
  check(code === 0, `curdle serve stops cleanly on Ctrl-C (exit ${code})`);
  await rm(work, { recursive: true, force: true });
}
console.log(`page: ${failures ? failures + ' failed' : 'all passed'}; screenshots in ${shots}`);
process.exit(failures ? 1 : 0);
