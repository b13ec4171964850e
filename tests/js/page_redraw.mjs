// How long the page takes from a change to the curd's pixels drawn, in headless Chromium over
// loopback with the browser's own Accept-Encoding: for each recipe given, the next seed is
// clicked 2 x ROUNDS times, and the page's "curd-redraw" measures (app.js: from the change to
// the pixels drawn, gl.finish() included) are read back. The changes alternate between two
// kinds, so that load on the machine falls on both alike: one comes while the 3-D view's
// reload of the last change (layout.glb, asked for 300 ms after a change, fetched, read and
// drawn) is under way, at a point spread over its course from the first round to the last; the
// other once that reload is done and the page is idle. redraw_ms is the first kind,
// idle_ms the second; reload_in_flight how many changes of the first kind found the reload
// still on its way (the rest came as it finished). Also a palette colour's redraw, which takes
// no new data. fetch_ms is the part until the field is in the page (asked for on the page's
// WebSocket, web/field_worker.js), server_ms the server's own part of that; view3d_render_ms the
// 3-D view's drawing of each new model on the page's thread; reload_ms the reload's course,
// from its start to its model drawn, with the page idle; floor_ms what the browser alone costs:
// the smallest field the pattern takes (67 x 67 cells, 4 KB of head and 0.5 KB of values) asked
// for the same way, off the page's thread, with no change drawn and nothing else on its way.
// Prints one JSON line per recipe.
// Usage: [WEB_ROOT=DIR] node page_redraw.mjs CURDLE ROUNDS RECIPE...
import { chromium } from 'playwright-core';
import { openModules, serve } from './serve.mjs';

const [curdle, roundsText, ...recipes] = process.argv.slice(2);
const rounds = Number(roundsText);
const browser = await chromium.launch({
  executablePath: '/usr/bin/chromium',
  args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-background-networking'],
});
const quantile = (xs, q) => [...xs].sort((a, b) => a - b)[Math.min(xs.length - 1, Math.floor(q * xs.length))];
try {
  for (const recipe of recipes) {
    // WEB_ROOT: the page from another copy of its files, to compare two versions of it (both
    // ES modules, as the page is since 098bef6: the checks import its modules).
    const { server, url } = await serve(curdle, process.env.WEB_ROOT ? ['--web-root', process.env.WEB_ROOT, recipe] : [recipe]);
    try {
      const page = await browser.newPage({ viewport: { width: 1500, height: 1000 } });
      const encodings = new Set();
      page.on('request', async (r) => {
        if (r.url().includes('/api/field?')) encodings.add((await r.allHeaders())['accept-encoding'] || '');
      });
      await page.goto(url);
      await page.waitForSelector('body[data-ready="1"]', { timeout: 60000 });
      await openModules(page);
      // The 3-D view's reloads, as the page starts them (report.js's "layout3d" event) and
      // finishes them (view3d.js's "view3d-render" measure).
      await page.evaluate(() => {
        window.reloads = { started: [] };
        window.addEventListener('layout3d', () => window.reloads.started.push(performance.now()));
      });
      const redraws = { reload: [], idle: [] };
      const server_ms = [];
      const fetch_ms = [];
      const reload_ms = [];
      let inFlight = 0;
      let reloadCourse = 150;  // ms, until measured on an idle round
      let startedBefore = 0;  // the reloads started before the last change
      for (let i = 0; i < 2 * rounds; ++i) {
        const kind = i % 2 ? 'reload' : 'idle';
        if (i > 0 && kind === 'idle') {
          // The last change's reload done and drawn, then a moment's rest.
          reload_ms.push(await page.evaluate(async (n) => {
            const done = () => window.reloads.started.length > n && window.view3d.src !== null &&
              !document.getElementById('view3d').classList.contains('stale');
            for (const t = performance.now(); !done();) {
              if (performance.now() - t > 20000 || window.view3d.error) throw new Error(`no 3-D model: ${window.view3d.error}`);
              await new Promise((r) => setTimeout(r, 5));
            }
            const drawn = performance.getEntriesByName('view3d-render').at(-1);
            return drawn.startTime + drawn.duration - window.reloads.started.at(-1);
          }, startedBefore));
          reloadCourse = quantile(reload_ms, 0.5);
          await page.waitForTimeout(100);
        }
        // The change: the next seed's button clicked in the page, at once on an idle round; on
        // the other, a part of the reload's course after it started. Timed by the page's
        // scheduler at the priority of input, as a person's click comes: a plain timer waited
        // behind the page's other tasks (the 3-D view's continuations of scheduler.yield).
        const offset = kind === 'reload' ? reloadCourse * (Math.floor(i / 2) + 0.5) / rounds : 0;
        const before = await page.evaluate(() => [performance.getEntriesByName('curd-redraw').length,
                                                  window.reloads.started.length]);
        const last = startedBefore;
        startedBefore = before[1];
        const foundOnItsWay = await page.evaluate(([kind, n, offset]) => new Promise((resolve) => {
          const change = () => scheduler.postTask(() => {
            const stale = document.getElementById('view3d').classList.contains('stale');
            document.getElementById('seed-next').click();
            resolve(stale ? 1 : 0);
          }, { priority: 'user-blocking',
               delay: kind === 'idle' ? 0 : Math.max(0, offset - (performance.now() - window.reloads.started.at(-1))) });
          if (kind === 'idle' || window.reloads.started.length > n) change();
          else window.addEventListener('layout3d', change, { once: true });
        }), [kind, last, offset]);
        if (kind === 'reload') inFlight += foundOnItsWay;
        await page.waitForFunction((n) => performance.getEntriesByName('curd-redraw').length > n, before[0],
                                   { timeout: 60000 });
        const [ms, fetched, server] = await page.evaluate(() => {
          const all = performance.getEntriesByName('curd-redraw');
          const fetches = performance.getEntriesByName('curd-fetch');
          return [all[all.length - 1].duration, fetches[fetches.length - 1].duration, page_state.state.whole.server_ms];
        });
        redraws[kind].push(ms);
        fetch_ms.push(fetched);
        server_ms.push(server);
      }
      const recolour = await page.evaluate(() => {
        const times = [];
        for (let i = 0; i < 20; ++i) {
          const t = performance.now();
          page_state.state.whole.legend[0].colour = i % 2 ? '#ffffff' : '#eeeeee';
          canvas.recolour();
          times.push(performance.now() - t);
        }
        return times;
      });
      await page.waitForTimeout(1500);  // the last change's 3-D model in and drawn
      const floor = await page.evaluate(async () => {
        const times = [];
        for (let i = 0; i < 15; ++i) {
          await new Promise((r) => setTimeout(r, 50));
          const t = performance.now();
          await field_fetch.fetchField(`/api/field?seed=${i}&set=${encodeURIComponent('field.cells=[67,67]')}`);
          times.push(performance.now() - t);
        }
        return times;
      });
      // The 3-D view's own pictures of each new model, on the page's thread.
      const view3d = await page.evaluate(() => performance.getEntriesByName('view3d-render').map((e) => e.duration));
      const [w, h] = await page.evaluate(() => canvas.fieldSize());
      console.log(JSON.stringify({
        recipe: recipe.split('/').pop(), cells: `${w}x${h}`, rounds,
        redraw_ms_median: quantile(redraws.reload, 0.5), redraw_ms_p90: quantile(redraws.reload, 0.9),
        idle_ms_median: quantile(redraws.idle, 0.5), idle_ms_p90: quantile(redraws.idle, 0.9),
        reload_in_flight: inFlight, reload_ms_median: reload_ms.length ? quantile(reload_ms, 0.5) : null,
        fetch_ms_median: quantile(fetch_ms, 0.5), server_ms_median: quantile(server_ms, 0.5), recolour_ms_median: quantile(recolour, 0.5),
        floor_ms_median: quantile(floor, 0.5),
        view3d_render_ms_median: view3d.length ? quantile(view3d, 0.5) : null, view3d_models: view3d.length,
        accept_encoding: [...encodings].join(' | '),
      }));
      await page.close();
    } finally {
      server.kill('SIGINT');
    }
  }
} finally {
  await browser.close();
}
