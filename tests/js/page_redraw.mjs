// How long the page takes from a change to the curd's pixels drawn, in headless Chromium over
// loopback with the browser's own Accept-Encoding: for each recipe given, the next seed is
// clicked ROUNDS times, 400 ms apart (so that the 3-D view's reload, 300 ms after a change, is
// under way when the next change comes), and the page's "curd-redraw" measures (app.js: from
// the change to the pixels drawn, gl.finish() included) are read back. Also a palette colour's
// redraw, which takes no new data. fetch_ms is the part until the field is in the page (asked
// for on the page's WebSocket, web/field_worker.js), server_ms the server's own part of that;
// view3d_render_ms the 3-D view's drawing of each new model on the page's thread (models a
// change dropped on their way are not drawn); floor_ms what the browser alone costs: the
// smallest field the pattern takes (67 x 67 cells, 4 KB of head and 0.5 KB of values) asked for
// the same way, off the page's thread, with no change drawn and nothing else on its way. Prints
// one JSON line per recipe.
// Usage: [GAP_MS=400] [WEB_ROOT=DIR] node page_redraw.mjs CURDLE ROUNDS RECIPE...
import { chromium } from 'playwright-core';
import { serve } from './serve.mjs';

const [curdle, roundsText, ...recipes] = process.argv.slice(2);
const rounds = Number(roundsText);
const browser = await chromium.launch({
  executablePath: '/usr/bin/chromium',
  args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-background-networking'],
});
const quantile = (xs, q) => [...xs].sort((a, b) => a - b)[Math.min(xs.length - 1, Math.floor(q * xs.length))];
try {
  for (const recipe of recipes) {
    // WEB_ROOT: the page from another copy of its files, to compare two versions of it.
    const { server, url } = await serve(curdle, process.env.WEB_ROOT ? ['--web-root', process.env.WEB_ROOT, recipe] : [recipe]);
    try {
      const page = await browser.newPage({ viewport: { width: 1500, height: 1000 } });
      const encodings = new Set();
      page.on('request', async (r) => {
        if (r.url().includes('/api/field?')) encodings.add((await r.allHeaders())['accept-encoding'] || '');
      });
      await page.goto(url);
      await page.waitForSelector('body[data-ready="1"]', { timeout: 60000 });
      const redraws = [];
      const server_ms = [];
      const fetch_ms = [];
      for (let i = 0; i < rounds; ++i) {
        const before = await page.evaluate(() => performance.getEntriesByName('curd-redraw').length);
        await page.click('#seed-next');
        await page.waitForFunction((n) => performance.getEntriesByName('curd-redraw').length > n, before,
                                   { timeout: 60000 });
        const [ms, fetched, server] = await page.evaluate(() => {
          const all = performance.getEntriesByName('curd-redraw');
          const fetches = performance.getEntriesByName('curd-fetch');
          return [all[all.length - 1].duration, fetches[fetches.length - 1].duration, state.whole.server_ms];
        });
        redraws.push(ms);
        fetch_ms.push(fetched);
        server_ms.push(server);
        await page.waitForTimeout(Number(process.env.GAP_MS || 400));
      }
      const recolour = await page.evaluate(() => {
        const times = [];
        for (let i = 0; i < 20; ++i) {
          const t = performance.now();
          state.whole.legend[0].colour = i % 2 ? '#ffffff' : '#eeeeee';
          recolour();
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
          await fetchField(`/api/field?seed=${i}&set=${encodeURIComponent('field.cells=[67,67]')}`);
          times.push(performance.now() - t);
        }
        return times;
      });
      // The 3-D view's own pictures of each new model, on the page's thread.
      const view3d = await page.evaluate(() => performance.getEntriesByName('view3d-render').map((e) => e.duration));
      const [w, h] = await page.evaluate(() => fieldSize());
      console.log(JSON.stringify({
        recipe: recipe.split('/').pop(), cells: `${w}x${h}`, rounds,
        redraw_ms_median: quantile(redraws, 0.5), redraw_ms_p90: quantile(redraws, 0.9),
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
