#!/usr/bin/env node
// The page's cost beside native, for docs/results/web.md: the page's download (wasm, script,
// bundled models), how long it takes to show its first view, and the whole frame (every map
// redrawn, rendered and read back, as `gnomon bench` reports "frame (wall, render())") of the
// same scenes in Chromium's WebGL2 on SwiftShader and natively on llvmpipe, the two run in
// turns so that the machine's load falls on both.
//   node scripts/web-bench.js [--rounds N] [--frames N] [--size WxH] [--out FILE]
// Needs `make` and `make web` (build/release, build/web) and scripts/web-deps.sh's browser.
'use strict';

const fs = require('fs');
const path = require('path');
const {spawnSync} = require('child_process');

const root = path.resolve(__dirname, '..');
const {serve, launch, open} = require(path.join(root, 'tests/web/browser.js'));
const gnomon = path.join(root, 'build/release/apps/gnomon/gnomon');
const web = path.join(root, 'build/web');
const bundle = path.join(root, '../shared/scenes');

function parseArgs(argv) {
    const args = {rounds: 3, frames: 20, size: '256x256', out: ''};
    for (let i = 0; i < argv.length; i += 2) args[argv[i].replace(/^--/, '')] = argv[i + 1];
    args.rounds = Number(args.rounds);
    args.frames = Number(args.frames);
    return args;
}

function median(values) {
    const s = [...values].sort((a, b) => a - b);
    return s.length % 2 ? s[(s.length - 1) / 2] : 0.5 * (s[s.length / 2 - 1] + s[s.length / 2]);
}

// Native: gnomon bench's whole-frame median for the scene (its own folder of outputs).
function nativeFrame(scene, args, tmp) {
    const out = path.join(tmp, 'native');
    const argv = ['bench', '--scene', scene.native, '--size', args.size, '--frames',
        String(args.frames), '--out-dir', out].concat(scene.flags);
    const r = spawnSync(gnomon, argv, {encoding: 'utf8'});
    if (r.status !== 0) throw new Error(`gnomon ${argv.join(' ')}: ${r.stderr}`);
    return JSON.parse(fs.readFileSync(path.join(out, 'bench.json'))).runs[0].frame_ms.median;
}

// The page: the same frames through Module.bench, in a page opened on the picture alone.
async function pageFrame(browser, origin, scene, args) {
    const address = `#ui=off&scene=${scene.page}&size=${args.size}` + scene.keys;
    const {page, title} = await open(browser, `${origin}/index.html${address}`,
        ['gnomon ready', 'gnomon error'], 300000);
    if (!title.startsWith('gnomon ready')) throw new Error(`${address}: ${title}`);
    const r = await page.evaluate((a, n) => Module.bench(a, n), address, args.frames);
    await page.close();
    if (!r.ok) throw new Error(`${address}: ${r.error}`);
    return median(r.ms);
}

// Seconds from asking for the page to its title saying the view is drawn.
async function loadSeconds(browser, origin, address) {
    const start = Date.now();
    const {page, title} = await open(browser, `${origin}/index.html${address}`,
        ['gnomon ready', 'gnomon error'], 300000);
    await page.close();
    if (!title.startsWith('gnomon ready')) throw new Error(`${address}: ${title}`);
    return (Date.now() - start) / 1000;
}

function mib(file) {
    return fs.existsSync(file) ? (fs.statSync(file).size / 1048576).toFixed(1) : '-';
}

async function main() {
    const args = parseArgs(process.argv.slice(2));
    const scenes = [
        {name: 'book-triangle', native: 'book-triangle', page: 'book-triangle', flags: [], keys: ''},
        {name: 'tutorial-room', native: 'tutorial-room', page: 'tutorial-room', flags: [], keys: ''},
        {name: 'mixed-lights', native: 'mixed-lights', page: 'mixed-lights', flags: [], keys: ''},
    ];
    if (fs.existsSync(bundle)) {
        scenes.push({name: 'Duck on ground', native: path.join(bundle, 'Duck/Duck.glb'),
            page: 'Duck', flags: ['--ground'], keys: '&ground=on'});
        scenes.push({name: 'DabrovicSponza', native: path.join(bundle, 'DabrovicSponza/dabrovic_sponza.glb'),
            page: 'DabrovicSponza', flags: [], keys: ''});
    }
    const tmp = fs.mkdtempSync('/tmp/gnomon-web-bench-');
    const server = await serve(web);
    const browser = await launch();
    const rows = [];
    const loads = {};
    try {
        for (const address of ['#scene=tutorial-room', '#ui=off&scene=tutorial-room'])
            loads[address] = [];
        for (let round = 0; round < args.rounds; ++round) {
            for (const address of Object.keys(loads))
                loads[address].push(await loadSeconds(browser, server.origin, address));
        }
        for (const scene of scenes) {
            const native = [], page = [];
            for (let round = 0; round < args.rounds; ++round) {
                native.push(nativeFrame(scene, args, tmp));
                page.push(await pageFrame(browser, server.origin, scene, args));
            }
            rows.push({scene: scene.name, native: median(native), page: median(page)});
            console.error(`${scene.name}: native ${median(native).toFixed(2)} ms, page ` +
                          `${median(page).toFixed(2)} ms`);
        }
    } finally {
        await browser.close();
        await server.close();
        fs.rmSync(tmp, {recursive: true, force: true});
    }
    const lines = [
        '# The page beside native',
        '',
        `Regenerate: \`node scripts/web-bench.js --rounds ${args.rounds} --frames ${args.frames} ` +
            `--size ${args.size} --out docs/results/web.md\` (after \`make\` and \`make web\`).`,
        '',
        'Download: gnomon.wasm ' + mib(path.join(web, 'gnomon.wasm')) + ' MiB, gnomon.js ' +
            mib(path.join(web, 'gnomon.js')) + ' MiB; the bundled models (scenes.data, only ' +
            'when ../shared/scenes was there at build time) ' + mib(path.join(web, 'scenes.data')) +
            ' MiB.',
        '',
        '| first view shown (page served from 127.0.0.1, median of ' + args.rounds + ') | seconds |',
        '|---|---|',
    ];
    for (const [address, s] of Object.entries(loads))
        lines.push(`| \`index.html${address}\` | ${median(s).toFixed(2)} |`);
    lines.push('', `Whole frame at ${args.size}, every map redrawn, rendered and read back ` +
        `(median of ${args.frames} frames, then the median of ${args.rounds} rounds, native and ` +
        'page in turns):', '',
        '| scene | native llvmpipe (ms) | page, Chromium WebGL2 on SwiftShader (ms) | page / native |',
        '|---|---|---|---|');
    for (const r of rows) {
        lines.push(`| ${r.scene} | ${r.native.toFixed(2)} | ${r.page.toFixed(2)} | ` +
                   `${(r.page / r.native).toFixed(2)} |`);
    }
    const text = lines.join('\n') + '\n';
    if (args.out) fs.writeFileSync(args.out, text);
    process.stdout.write(text);
}

main().catch((e) => {
    console.error(`web-bench: ${e.message}`);
    process.exit(1);
});
