// The page with a whole building (the pavilion's 23,000 bricks), in headless Chromium over
// loopback: ROUNDS changes (the next seed) with the page at rest, each timed from the click to
// the new model drawn in the 3-D view (view3d.js's "view3d-render" measure; the page asks for
// layout.glb once the controls have rested 300 ms, and that wait is counted); as many changes
// made while the 3-D view's reload is on its way, half its course in, each timed from the click
// to the curd's pixels drawn ("curd-redraw"); and clicks on the 3-D view at a grid of points
// over it (on bricks, in windows, on the sky), each timed from the click's event to the answer
// shown ("view3d-click"), with how many found an element and how many said there was none.
// Also the picks the merged drawing makes against the elements' own objects at the same points,
// and three.js's own loader's time on the same layout.glb.
// Prints one JSON line.
// Usage: node page_building.mjs CURDLE ROUNDS RECIPE
import { chromium } from 'playwright-core';
import { openModules, serve } from './serve.mjs';

const [curdle, roundsText, recipe] = process.argv.slice(2);
const rounds = Number(roundsText);
const GRID = 8;  // clicks: GRID x GRID points over the 3-D view
const quantile = (xs, q) => [...xs].sort((a, b) => a - b)[Math.min(xs.length - 1, Math.floor(q * xs.length))];
const browser = await chromium.launch({
  executablePath: '/usr/bin/chromium',
  args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-background-networking'],
});
const { server, url } = await serve(curdle, [recipe]);
try {
  const page = await browser.newPage({ viewport: { width: 1500, height: 1000 } });
  const opened = Date.now();
  await page.goto(url);
  await page.waitForSelector('body[data-ready="1"]', { timeout: 60000 });
  await openModules(page);
  const loaded = () => page.evaluate(() => window.view3d.loads);
  const shown = (n) => page.waitForFunction((n) => window.view3d.loads > n &&
    !document.getElementById('view3d').classList.contains('stale'), n, { timeout: 120000 });
  await shown(0);
  const first_model_ms = Date.now() - opened;
  await page.evaluate(() => {
    window.reloads = [];
    window.addEventListener('layout3d', () => window.reloads.push(performance.now()));
  });
  const change_ms = [], redraw_ms = [], rest_ms = [], fetch_ms = [], server_ms = [];
  let course = 300;  // ms from a reload's start to its model drawn, until measured
  for (let i = 0; i < rounds; ++i) {
    // At rest: the click to the new model drawn.
    const n = await loaded();
    const clicked = await page.evaluate(() => {
      const t = performance.now();
      document.getElementById('seed-next').click();
      return t;
    });
    await shown(n);
    const [drawn, started] = await page.evaluate(() => {
      const e = performance.getEntriesByName('view3d-render').at(-1);
      return [e.startTime + e.duration, window.reloads.at(-1)];
    });
    change_ms.push(drawn - clicked);
    const [restMs, fetchMs, serverMs] = await page.evaluate(() => [
      performance.getEntriesByName('curd-redraw').at(-1).duration,
      performance.getEntriesByName('curd-fetch').at(-1).duration, page_state.state.whole.server_ms]);
    rest_ms.push(restMs);
    fetch_ms.push(fetchMs);
    server_ms.push(serverMs);
    course = drawn - started;
    await page.waitForTimeout(200);
    // With the reload on its way: a change half its course in, to the curd's pixels drawn.
    const m = await loaded();
    const redraws = await page.evaluate(() => performance.getEntriesByName('curd-redraw').length);
    await page.evaluate((half) => new Promise((resolve) => {
      window.addEventListener('layout3d', () => scheduler.postTask(() => {
        resolve(document.getElementById('seed-next').click());
      }, { priority: 'user-blocking', delay: half }), { once: true });
      document.getElementById('seed-next').click();
    }), course / 2);
    await page.waitForFunction((r) => performance.getEntriesByName('curd-redraw').length > r + 1, redraws);
    redraw_ms.push(await page.evaluate(() => performance.getEntriesByName('curd-redraw').at(-1).duration));
    await shown(m);
    await page.waitForTimeout(200);
  }
  // Clicks over the view, the model at rest.
  await page.evaluate(() => document.querySelector('#view3d').scrollIntoView({ block: 'center' }));
  const box = await page.locator('#view3d canvas').boundingBox();
  const click_ms = [];
  let found = 0, none = 0;
  for (let i = 0; i < GRID; ++i)
    for (let j = 0; j < GRID; ++j) {
      const before = await page.evaluate(() => performance.getEntriesByName('view3d-click').length);
      await page.mouse.click(box.x + box.width * (i + 0.5) / GRID, box.y + box.height * (j + 0.5) / GRID);
      await page.waitForFunction((b) => performance.getEntriesByName('view3d-click').length > b, before);
      const [ms, id, said] = await page.evaluate(() => [performance.getEntriesByName('view3d-click').at(-1).duration,
        document.getElementById('view3d-info').dataset.id, document.getElementById('view3d-info').textContent]);
      click_ms.push(ms);
      if (id) ++found;
      else if (/^No element there/.test(said)) ++none;
    }
  // three.js's own loader on the same bytes (the page's fallback for a glb its worker does not
  // read), for comparison with the worker's course.
  const threejs_loader_ms = await page.evaluate(async () => {
    const { GLTFLoader } = await import('three/addons/loaders/GLTFLoader.js');
    const bytes = await (await fetch(window.view3d.src)).arrayBuffer();
    const t = performance.now();
    await new GLTFLoader().parseAsync(bytes, '');
    return performance.now() - t;
  });
  const picks = await page.evaluate(() => window.view3d.picksAgree(24));
  const bricks = await page.evaluate(() => window.view3d.model().getObjectsByProperty('isMesh', true).length);
  console.log(JSON.stringify({
    recipe: recipe.split('/').pop(), rounds, bricks, first_model_ms,
    change_ms_median: quantile(change_ms, 0.5), change_ms_max: Math.max(...change_ms),
    reload_course_ms: course,
    rest_redraw_ms_median: quantile(rest_ms, 0.5), rest_fetch_ms_median: quantile(fetch_ms, 0.5),
    server_ms_median: quantile(server_ms, 0.5), redraw_ms_median: quantile(redraw_ms, 0.5), redraw_ms_max: Math.max(...redraw_ms),
    clicks: click_ms.length, click_found: found, click_none: none,
    click_ms_median: quantile(click_ms, 0.5), click_ms_max: Math.max(...click_ms),
    threejs_loader_ms, picks_compared: picks.points, picks_differ: picks.differ, picks_first_differing: picks.first,
  }));
  await page.close();
} finally {
  server.kill('SIGINT');
  await browser.close();
}
