// `curdle serve` on any free port of the loopback address, for the page's checks: the server
// and the address it prints.
import { spawn } from 'node:child_process';

export async function serve(curdle, args) {
  const server = spawn(curdle, ['serve', '--port', '0', ...args], { stdio: ['ignore', 'pipe', 'inherit'] });
  const url = await new Promise((resolve, reject) => {
    let text = '';
    server.stdout.on('data', (d) => {
      text += d;
      const m = /open (http:\/\/127\.0\.0\.1:\d+\/)/.exec(text);
      if (m) resolve(m[1]);
    });
    server.on('exit', (code) => reject(new Error(`curdle serve exited ${code}: ${text}`)));
    setTimeout(() => reject(new Error(`curdle serve printed no address: ${text}`)), 20000);
  });
  return { server, url };
}

// The page keeps no globals (its files are ES modules): the checks reach its state and
// functions through the modules themselves, put on `window` under their file names
// (`page_state.state`, `canvas.fieldSize()`, …), the same instances the page runs.
export const openModules = (page) => page.evaluate(async () => {
  for (const name of ['page_state', 'app', 'canvas', 'field_fetch', 'measure', 'site'])
    window[name] = await import(`./${name}.js`);
});
