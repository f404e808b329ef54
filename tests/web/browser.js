// What the browser tests and probes share: a static server for a folder on 127.0.0.1 (an
// ephemeral port), Debian's Chromium started headless with WebGL2 on SwiftShader (the CPU)
// through puppeteer-core, and a page opened until its title says it is done, with what it
// logged as errors kept for the message when it is not.
'use strict';

const fs = require('fs');
const http = require('http');
const os = require('os');
const path = require('path');

const kChromium = '/usr/bin/chromium';
const kTypes = {
    '.html': 'text/html; charset=utf-8',
    '.js': 'text/javascript; charset=utf-8',
    '.wasm': 'application/wasm',  // streaming compilation needs it
    '.data': 'application/octet-stream',
    '.png': 'image/png',
};

// A failure the caller reports as it is: the message says what to do.
class Setup extends Error {}

function puppeteer() {
    try {
        return require('puppeteer-core');
    } catch (e) {
        throw new Setup('puppeteer-core is not installed beside tests/web/package.json: ' +
                        'run scripts/web-deps.sh (npm ci) (' + e.message + ')');
    }
}

// Serves `root` (GET only, no listings) until close(); resolves to {origin, close}.
function serve(root) {
    const base = path.resolve(root);
    const server = http.createServer((request, response) => {
        const url = new URL(request.url, 'http://127.0.0.1');
        const file = path.join(base, decodeURIComponent(url.pathname));
        if (!file.startsWith(base + path.sep) || !fs.existsSync(file) ||
            !fs.statSync(file).isFile()) {
            response.writeHead(404).end();
            return;
        }
        response.writeHead(200, {
            'Content-Type': kTypes[path.extname(file)] || 'application/octet-stream',
            'Cache-Control': 'no-store',
        });
        fs.createReadStream(file).pipe(response);
    });
    return new Promise((resolve, reject) => {
        server.on('error', reject);
        server.listen(0, '127.0.0.1', () => resolve({
            origin: `http://127.0.0.1:${server.address().port}`,
            close: () => new Promise((done) => server.close(done)),
        }));
    });
}

// Chromium headless with WebGL2 on SwiftShader, in a profile of its own that goes with it.
async function launch() {
    if (!fs.existsSync(kChromium))
        throw new Setup(`${kChromium} is missing: scripts/web-deps.sh installs Debian's chromium`);
    const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'gnomon-chromium-'));
    const args = ['--use-angle=swiftshader', '--enable-unsafe-swiftshader'];
    // Chromium refuses to run as root with its sandbox (CI runs as root).
    if (process.getuid && process.getuid() === 0) args.push('--no-sandbox');
    const browser = await puppeteer().launch({
        executablePath: kChromium,
        headless: true,  // the new headless mode (--headless=new)
        args,
        userDataDir: profile,
        defaultViewport: {width: 1280, height: 1024, deviceScaleFactor: 1},
    });
    const close = browser.close.bind(browser);
    browser.close = async () => {
        await close();
        fs.rmSync(profile, {recursive: true, force: true});
    };
    return browser;
}

// Waits until the page's title begins with one of `done` (e.g. 'gnomon ready', 'gnomon
// error') or `timeoutMs` passes; resolves to the title. Throws Setup on timeout, with the
// lines in `errors`.
async function waitForTitle(page, done, timeoutMs, errors) {
    try {
        await page.waitForFunction(
            (prefixes) => prefixes.some((p) => document.title.startsWith(p)),
            {timeout: timeoutMs, polling: 100}, done);
    } catch (e) {
        const title = await page.title().catch(() => '?');
        throw new Setup(`${page.url()}: the title did not begin with '${done.join("' or '")}' ` +
                        `within ${timeoutMs / 1000} s (it is '${title}')` +
                        (errors.length ? '; the page logged:\n  ' + errors.join('\n  ') : ''));
    }
    return page.title();
}

// Opens `url` and waits for its title (waitForTitle). Resolves to {page, title, errors};
// errors: what the page logged as errors or threw, one line each, kept as it runs on.
async function open(browser, url, done, timeoutMs) {
    const page = await browser.newPage();
    const errors = [];
    page.on('console', (m) => {
        if (m.type() === 'error') errors.push('console: ' + m.text());
    });
    page.on('pageerror', (e) => errors.push('uncaught: ' + e.message));
    page.on('requestfailed', (r) => errors.push(`request failed: ${r.url()}`));
    await page.goto(url);
    return {page, title: await waitForTitle(page, done, timeoutMs, errors), errors};
}

module.exports = {Setup, serve, launch, open, waitForTitle};
