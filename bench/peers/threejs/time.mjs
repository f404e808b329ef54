// Serves this folder (and glmark2's models under /glmark2/) on a local port, opens
// peer.html in headless Chromium (Debian's) and prints its timing as one JSON line.
// Usage: node time.mjs [SCENE] [FRAMES] [GL] [PNG]
// SCENE: book (gnomon's book-triangle) or horse (glmark2's shadow scene).
// GL: swiftshader (Chromium's CPU rasteriser, its default without a GPU) or egl (ANGLE on
// the system's OpenGL through EGL: Mesa llvmpipe here, the rasteriser gnomon runs on).
// PNG: where to write the last frame, to check what was drawn.
import {createServer} from 'node:http';
import {readFile, writeFile} from 'node:fs/promises';
import {extname, join, normalize} from 'node:path';
import {fileURLToPath} from 'node:url';
import {chromium} from 'playwright-core';

const here = fileURLToPath(new URL('.', import.meta.url));
const scene = process.argv[2] || 'book';
const frames = Number(process.argv[3] || 60);
const backend = process.argv[4] || 'swiftshader';
const png = process.argv[5];
const glmark2 = '/usr/share/glmark2/models/';
const flags = {
  swiftshader: ['--use-angle=swiftshader', '--enable-unsafe-swiftshader'],
  egl: ['--use-gl=angle', '--use-angle=gl-egl', '--ignore-gpu-blocklist'],
}[backend];
if (!flags) throw new Error(`time.mjs: unknown GL '${backend}': expected swiftshader or egl`);

const types = {'.html': 'text/html', '.js': 'text/javascript'};
const server = createServer(async (req, res) => {
  const url = decodeURIComponent(new URL(req.url, 'http://x').pathname);
  const path = url.startsWith('/glmark2/') ? normalize(join(glmark2, url.slice(9)))
                                           : normalize(join(here, url));
  if (!path.startsWith(here) && !path.startsWith(glmark2)) { res.writeHead(403).end(); return; }
  try {
    const body = await readFile(path);
    res.writeHead(200, {'Content-Type': types[extname(path)] || 'application/octet-stream'});
    res.end(body);
  } catch {
    res.writeHead(404).end();
  }
});
await new Promise((ok) => server.listen(0, '127.0.0.1', ok));
const browser = await chromium.launch({executablePath: '/usr/bin/chromium', headless: true,
                                       args: flags});
try {
  const page = await browser.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
  await page.goto(`http://127.0.0.1:${server.address().port}/peer.html?scene=${scene}&frames=${frames}`);
  await page.waitForFunction(() => window.result || null, null, {timeout: 600000, polling: 200})
      .catch((e) => { throw new Error(`peer.html: ${errors.join('; ') || e.message}`); });
  const result = await page.evaluate(() => window.result);
  if (png) await writeFile(png, Buffer.from(result.image.split(',')[1], 'base64'));
  delete result.image;
  console.log(JSON.stringify({...result, gl: backend}));
} finally {
  await browser.close();
  server.close();
}
