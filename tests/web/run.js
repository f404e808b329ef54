// The web page's tests in a real browser (CTest label `web`, tests/web/CMakeLists.txt), one
// case per run, the page served from build/web on 127.0.0.1 (browser.js):
//   node run.js picture --web DIR --address '#scene=...' --truth EXE --bundle DIR --out DIR
//       the canvas #gnomon, screenshot, against the picture native computes for the same
//       address (EXE: gnomon_page_truth, _render or _score, which compares and states its
//       bounds; --bound B is handed to it);
//   node run.js error --web DIR --address '#...' [--address ...] --gnomon EXE --out DIR
//       a bad address shows the very line `gnomon render` prints for the same flags;
//   node run.js upload --web DIR --address '#KEYS' --file F (--truth EXE --bundle DIR |
//           --expect-error TEXT) --out DIR
//       F chosen with the page's file button: its picture against native's for the same file
//       and keys, or an error that holds TEXT (a format this build does not read);
//   node run.js drag --web DIR --address '#scene=...' --check EXE --out DIR
//       the viewer: a light dragged moves its shadow, and the address the page then shows
//       reopens the same view (viewer.js; EXE: gnomon_page_drag);
//   node run.js score --web DIR --address '#...' --check EXE --bundle DIR --out DIR
//       the viewer's F5 score of the address's view against native's (EXE:
//       gnomon_page_score; --bound B).
// --needs-bundle: the address names a model of BUNDLE (../shared/scenes), which a clone
// without that folder lacks: skipped then (exit 77). Exit 0 pass, 1 fail, saying why.
'use strict';

const fs = require('fs');
const path = require('path');
const {spawnSync} = require('child_process');
const {Setup, serve, launch, open, waitForTitle} = require('./browser.js');
const {drag, score} = require('./viewer.js');

const kTimeoutMs = 120000;  // page load, scene load and trace under a loaded CI machine
const kSkip = 77;
const kDone = ['gnomon ready', 'gnomon error'];  // the page's titles once it has answered

function parseArgs(argv) {
    const args = {mode: argv[0], address: []};
    for (let i = 1; i < argv.length; ++i) {
        const key = argv[i].replace(/^--/, '');
        if (key === 'needs-bundle') args.needsBundle = true;
        else if (key === 'address') args.address.push(argv[++i]);
        else args[key] = argv[++i];
    }
    return args;
}

// The page in `web` must come from a `make web` that finished (the Makefile's stamp).
function checkBuilt(web) {
    if (!fs.existsSync(path.join(web, '.built'))) {
        throw new Setup(`${web} holds no page from a finished \`make web\` (the last one ` +
                        'failed, or none ran): run `make web` to see why');
    }
}

// Loads each address and hands the open page to `check`; one browser, one server.
async function withPages(web, addresses, done, check) {
    const server = await serve(web);
    const browser = await launch();
    try {
        for (const address of addresses) {
            const opened = await open(browser, `${server.origin}/index.html${address}`, done,
                                      kTimeoutMs);
            await check(address, opened);
            await opened.page.close();
        }
    } finally {
        await browser.close();
        await server.close();
    }
}

// The page's screenshot `shot` against native's picture for `address` (gnomon_page_truth,
// which prints the comparison and states its bounds); 0 when they agree.
function compareNative(args, address, shot) {
    const native = path.join(args.out, 'native.png');
    const argv = [address, args.bundle, native, shot].concat(args.bound ? [args.bound] : []);
    const r = spawnSync(args.truth, argv, {encoding: 'utf8'});
    process.stdout.write(r.stdout || '');
    process.stderr.write(r.stderr || '');
    if (r.error) throw new Setup(`${args.truth}: ${r.error.message}`);
    return r.status === 0 ? 0 : 1;
}

// The picture is drawn, the page logged no error, and its canvas is saved to `shot`.
async function screenshot(what, {page, title, errors}, shot) {
    if (!title.startsWith('gnomon ready')) throw new Setup(`${what}: the page says '${title}'`);
    if (errors.length)
        throw new Setup(`${what}: the page logged errors:\n  ${errors.join('\n  ')}`);
    await (await page.$('#gnomon')).screenshot({path: shot});
    console.log(`${what}: '${title}'`);
}

async function picture(args) {
    if (args.needsBundle && !fs.existsSync(args.bundle)) {
        console.log(`skipped: ${args.bundle} is not there, so the page bundles no models`);
        return kSkip;
    }
    fs.mkdirSync(args.out, {recursive: true});
    const shot = path.join(args.out, 'page.png');
    const address = args.address[0];
    await withPages(args.web, [address], kDone, (_, opened) => screenshot(address, opened, shot));
    return compareNative(args, address, shot);
}

async function upload(args) {
    fs.mkdirSync(args.out, {recursive: true});
    const shot = path.join(args.out, 'page.png');
    const what = `${args.file} chosen on ${args.address[0]}`;
    await withPages(args.web, [args.address[0]], kDone, async (_, opened) => {
        const {page, errors} = opened;
        await page.evaluate(() => (document.title = 'gnomon: waiting for the file'));
        await (await page.$('#file')).uploadFile(args.file);
        const title = await waitForTitle(page, kDone, kTimeoutMs, errors);
        if (args['expect-error'] === undefined) return screenshot(what, {page, title, errors}, shot);
        const shown = await page.$eval('#error', (e) => (e.hidden ? '' : e.textContent));
        if (!title.startsWith('gnomon error') || !shown.includes(args['expect-error'])) {
            throw new Setup(`${what}: the page shows '${shown}' (title '${title}'), not an ` +
                            `error holding '${args['expect-error']}'`);
        }
        console.log(`${what}: '${shown}'`);
    });
    if (args['expect-error'] !== undefined) return 0;
    // Natively the same keys, with the file where it lies.
    const params = new URLSearchParams(args.address[0].replace(/^#/, ''));
    params.set('scene', path.resolve(args.file));
    return compareNative(args, '#' + params.toString(), shot);
}

// The line `gnomon render` prints for the address's keys given as flags.
function cliError(gnomon, address, out) {
    const argv = ['render'];
    for (const [key, value] of new URLSearchParams(address.replace(/^#/, '')))
        argv.push('--' + key, value);
    argv.push('--out', path.join(out, 'cli.png'));
    const r = spawnSync(gnomon, argv, {encoding: 'utf8'});
    const line = (r.stderr || '').split('\n').find((l) => l.startsWith('gnomon: error: '));
    if (r.status !== 2 || !line) {
        throw new Setup(`gnomon ${argv.join(' ')} exited ${r.status}, not 2 (bad usage) ` +
                        `with an error line: ${r.stderr}`);
    }
    return line;
}

async function error(args) {
    fs.mkdirSync(args.out, {recursive: true});
    const expected = new Map(args.address.map((a) => [a, cliError(args.gnomon, a, args.out)]));
    await withPages(args.web, args.address, kDone, async (address, {page, title}) => {
        const shown = await page.$eval('#error', (e) => (e.hidden ? '' : e.textContent));
        if (shown !== expected.get(address) || !title.startsWith('gnomon error')) {
            throw new Setup(`${address}: the page shows '${shown}' (title '${title}'), the ` +
                            `CLI says '${expected.get(address)}'`);
        }
        console.log(`${address}: '${shown}', as the CLI`);
    });
    return 0;
}

async function main() {
    const args = parseArgs(process.argv.slice(2));
    try {
        checkBuilt(args.web);
        if (args.mode === 'picture') return await picture(args);
        if (args.mode === 'error') return await error(args);
        if (args.mode === 'upload') return await upload(args);
        if (args.mode === 'drag' || args.mode === 'score') {
            fs.mkdirSync(args.out, {recursive: true});
            return await (args.mode === 'drag' ? drag : score)(args);
        }
        throw new Setup(`unknown mode '${args.mode}' (picture, error, upload, drag or score)`);
    } catch (e) {
        console.error(`web test: ${e instanceof Setup ? e.message : e.stack}`);
        return 1;
    }
}

main().then((code) => process.exit(code));
