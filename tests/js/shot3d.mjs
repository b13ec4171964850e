// Screenshots of the page's 3-D view for a recipe (for the README and for looking at):
// serves RECIPE, waits for the layout in 3-D and writes the view3d figure to OUT.
// Usage: node shot3d.mjs CURDLE RECIPE OUT
import { chromium } from 'playwright-core';
import { serve } from './serve.mjs';

const [curdle, recipe, out] = process.argv.slice(2);
const { server, url } = await serve(curdle, [recipe]);
const browser = await chromium.launch({
  executablePath: '/usr/bin/chromium',
  args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-background-networking'],
});
try {
  const page = await browser.newPage({ viewport: { width: 1500, height: 1000 } });
  await page.goto(url);
  await page.waitForSelector('body[data-ready="1"]', { timeout: 30000 });
  await page.waitForFunction(() => window.view3d && window.view3d.loads > 0 &&
                             !document.querySelector('#view3d').classList.contains('stale'), null, { timeout: 90000 });
  await page.evaluate(() => document.querySelector('#view3d').scrollIntoView({ block: 'center' }));
  const target = await page.evaluate(() => window.view3d.pointOnElement());
  if (target) await page.mouse.click(target.x, target.y);
  await page.locator('#view3d-figure').screenshot({ path: out });
  console.log(`shot3d: ${out}, ${(await page.evaluate(() => window.view3d.drawn) * 100).toFixed(0)} % drawn`);
} finally {
  await browser.close();
  server.kill('SIGINT');
}
