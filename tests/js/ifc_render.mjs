// A picture of a layout.ifc as web-ifc reads it: its meshes, placed and coloured by web-ifc,
// drawn by three.js in headless Chromium. Usage: node ifc_render.mjs MODEL.ifc PICTURE.png
import { createServer } from 'node:http';
import { readFile, readFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';
import * as W from 'web-ifc';

const here = path.dirname(fileURLToPath(import.meta.url));
const [model, picture] = process.argv.slice(2);
const api = new W.IfcAPI();
await api.Init();
api.SetLogLevel(W.LogLevel.LOG_LEVEL_OFF);  // a plate's openings are in its body: nothing to cut
const id = api.OpenModel(new Uint8Array(readFileSync(model)));
const positions = [], normals = [], colors = [], indices = [];
api.StreamAllMeshes(id, (mesh) => {
  for (let g = 0; g < mesh.geometries.size(); ++g) {
    const placed = mesh.geometries.get(g);
    const geometry = api.GetGeometry(id, placed.geometryExpressID);
    const v = api.GetVertexArray(geometry.GetVertexData(), geometry.GetVertexDataSize());
    const ix = api.GetIndexArray(geometry.GetIndexData(), geometry.GetIndexDataSize());
    const T = placed.flatTransformation, first = positions.length / 3;
    for (let k = 0; k < v.length; k += 6) {
      for (let a = 0; a < 3; ++a) positions.push(T[a] * v[k] + T[4 + a] * v[k + 1] + T[8 + a] * v[k + 2] + T[12 + a]);
      for (let a = 0; a < 3; ++a) normals.push(T[a] * v[k + 3] + T[4 + a] * v[k + 4] + T[8 + a] * v[k + 5]);
      colors.push(placed.color.x, placed.color.y, placed.color.z);
    }
    for (const i of ix) indices.push(first + i);
    geometry.delete();
  }
});
const body = JSON.stringify({ positions, normals, colors, indices });
const server = createServer((req, res) => {
  const url = new URL(req.url, 'http://localhost');
  const file = url.pathname === '/' ? path.join(here, 'ifc_viewer.html')
    : url.pathname.startsWith('/three/') ? path.join(here, 'node_modules', 'three', url.pathname.slice(7)) : null;
  if (url.pathname === '/mesh.json') return res.end(body);
  if (!file) return res.writeHead(404).end();
  readFile(file, (error, data) => {
    if (error) return res.writeHead(404).end();
    res.writeHead(200, { 'content-type': file.endsWith('.js') ? 'text/javascript' : 'text/html' });
    res.end(data);
  });
});
await new Promise((ok) => server.listen(0, '127.0.0.1', ok));
const browser = await chromium.launch({
  executablePath: '/usr/bin/chromium',
  args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-background-networking',
         '--enable-unsafe-swiftshader', '--use-angle=swiftshader'],
});
const page = await browser.newPage({ viewport: { width: 1000, height: 650 } });
await page.goto(`http://127.0.0.1:${server.address().port}/`);
await page.waitForFunction(() => window.result !== undefined, null, { timeout: 60000 });
const result = await page.evaluate(() => window.result);
await page.screenshot({ path: picture });
await browser.close();
server.close();
console.log(`${model}: ${result.triangles} triangles, ${(100 * result.drawn).toFixed(1)} % drawn -> ${picture}`);
process.exit(result.drawn > 0.02 ? 0 : 1);
