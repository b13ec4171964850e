// Opens each model the way a user would: three.js's GLTFLoader in headless Chromium, over a
// server on the loopback address. Each must load, show a picture (not a blank canvas) and
// keep its extent; a screenshot of each is written for a person to look at.
// Usage: node render.mjs SCREENSHOT_DIR MODEL.glb ... (CURDLE_LOOK=x,y,z,dx,dy,dz for a close look
// at a point, metres in glTF axes)
import { createServer } from 'node:http';
import { readFile, mkdir } from 'node:fs/promises';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';

const here = path.dirname(fileURLToPath(import.meta.url));
const [shots, ...models] = process.argv.slice(2);
await mkdir(shots, { recursive: true });
const byName = new Map(models.map((m, i) => [`${i}.glb`, m]));
const types = { '.js': 'text/javascript', '.html': 'text/html', '.glb': 'model/gltf-binary' };

const server = createServer(async (req, res) => {
  const url = new URL(req.url, 'http://localhost');
  let file;
  if (url.pathname === '/') file = path.join(here, 'viewer.html');
  else if (url.pathname.startsWith('/three/')) file = path.join(here, 'node_modules', 'three', url.pathname.slice(7));
  else if (url.pathname.startsWith('/model/')) file = byName.get(url.pathname.slice(7));
  try {
    if (!file) throw new Error('not found');
    const body = await readFile(file);
    res.writeHead(200, { 'content-type': types[path.extname(file)] ?? 'application/octet-stream' });
    res.end(body);
  } catch {
    res.writeHead(404);
    res.end();
  }
});
await new Promise((ok) => server.listen(0, '127.0.0.1', ok));
const port = server.address().port;

const browser = await chromium.launch({
  executablePath: '/usr/bin/chromium',
  args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-background-networking',
         '--disable-component-update', '--disable-sync', '--no-first-run', '--enable-unsafe-swiftshader',
         '--use-angle=swiftshader'],
});
let failed = 0;
try {
  const page = await browser.newPage({ viewport: { width: 800, height: 600 } });
  for (const [name, model] of byName) {
    await page.goto(`http://127.0.0.1:${port}/?model=${name}` +
                    (process.env.CURDLE_LOOK ? `&look=${process.env.CURDLE_LOOK}` : ''));
    await page.waitForFunction(() => window.result !== undefined, null, { timeout: 60000, polling: 50 });
    const result = await page.evaluate(() => window.result);
    const shot = path.join(shots, path.basename(path.dirname(model)) + '.png');
    await page.screenshot({ path: shot });
    const ok = !result.error && result.meshes > 0 && result.drawn > 0.01 && result.size.every((s) => s > 0);
    if (!ok) failed++;
    console.log(`${ok ? 'ok  ' : 'FAIL'} ${model}: ${result.error ?? `${result.meshes} meshes, ` +
      `${result.named} named nodes, ${(100 * result.drawn).toFixed(1)} % of the picture drawn, ` +
      `extent ${result.size.map((s) => s.toFixed(2)).join(' x ')} m`} -> ${shot}`);
  }
} finally {
  await browser.close();
  server.close();
}
process.exit(failed ? 1 : 0);
