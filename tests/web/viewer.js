// The viewer in the page (run.js's `drag` mode): a light dragged with the mouse moves its
// shadow, the page writes the new view into its address, and that address opened in a fresh
// page shows the same view. The pictures are the viewer's camera view (Module.viewerRect) as
// the browser shows it; gnomon_page_drag (page_drag.cpp) compares them natively.
'use strict';

const path = require('path');
const {spawnSync} = require('child_process');
const {Setup, serve, launch, open} = require('./browser.js');

const kTimeoutMs = 120000;
const kDone = ['gnomon ready', 'gnomon error'];

// Resolves once the viewer has drawn the view its state asks for and the browser has shown it.
async function drawn(page) {
    await page.waitForFunction(() => Module.viewerDrawn(), {timeout: kTimeoutMs, polling: 50});
    await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
}

async function shootView(page, file) {
    const r = await page.evaluate(() => Module.viewerRect());
    const top = await page.evaluate(() => document.getElementById('gnomon').getBoundingClientRect().top);
    if (!(r.width > 0 && r.height > 0)) throw new Setup('the viewer shows no camera view');
    await page.screenshot({path: file, clip: {x: r.x, y: top + r.y, width: r.width, height: r.height}});
    return {x: r.x, y: top + r.y, width: r.width, height: r.height};
}

function ready(what, {title, errors}) {
    if (!title.startsWith('gnomon ready')) throw new Setup(`${what}: the page says '${title}'`);
    if (errors.length) throw new Setup(`${what}: the page logged:\n  ${errors.join('\n  ')}`);
}

// Right drag (the selected light) across the middle of the view by a third of its width.
async function dragLight(page, rect) {
    const x = rect.x + rect.width / 2, y = rect.y + rect.height / 2;
    await page.mouse.move(x, y);
    await page.mouse.down({button: 'right'});
    for (let i = 1; i <= 10; ++i) {
        await page.mouse.move(x + (i * rect.width) / 30, y, {steps: 1});
        await page.evaluate(() => new Promise((r) => requestAnimationFrame(r)));
    }
    await page.mouse.up({button: 'right'});
}

async function drag(args) {
    const before = path.join(args.out, 'before.png'), after = path.join(args.out, 'after.png');
    const reopened = path.join(args.out, 'reopened.png');
    const address = args.address[0];
    const server = await serve(args.web);
    const browser = await launch();
    let moved;
    try {
        const first = await open(browser, `${server.origin}/index.html${address}`, kDone, kTimeoutMs);
        ready(address, first);
        await drawn(first.page);
        const rect = await shootView(first.page, before);
        await dragLight(first.page, rect);
        await drawn(first.page);
        await shootView(first.page, after);
        moved = await first.page.evaluate(() => location.hash);
        console.log(`${address} dragged: the address is now ${moved}`);
        if (moved === address) throw new Setup('the drag left the address as it was');
        const second = await open(browser, `${server.origin}/index.html${moved}`, kDone, kTimeoutMs);
        ready(moved, second);
        await drawn(second.page);
        await shootView(second.page, reopened);
        if (second.errors.length || first.errors.length)
            throw new Setup(`the pages logged:\n  ${first.errors.concat(second.errors).join('\n  ')}`);
    } finally {
        await browser.close();
        await server.close();
    }
    const r = spawnSync(args.check, [before, after, reopened], {encoding: 'utf8'});
    process.stdout.write(r.stdout || '');
    process.stderr.write(r.stderr || '');
    if (r.error) throw new Setup(`${args.check}: ${r.error.message}`);
    return r.status === 0 ? 0 : 1;
}

// The viewer's score (F5) of the address's view, traced in slices between frames, against
// `gnomon score` of the same address natively (gnomon_page_score, within --bound points).
async function score(args) {
    const address = args.address[0];
    const server = await serve(args.web);
    const browser = await launch();
    let title;
    try {
        const opened = await open(browser, `${server.origin}/index.html${address}`, kDone, kTimeoutMs);
        ready(address, opened);
        await drawn(opened.page);
        // Held over two frames: the viewer reads keys once a frame (Dear ImGui 1.86 keeps
        // key states, not a queue of presses), as a person's keypress lasts.
        await opened.page.keyboard.down('F5');
        await opened.page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
        await opened.page.keyboard.up('F5');
        await opened.page.waitForFunction(() => /misclassified|gnomon error/.test(document.title),
                                          {timeout: kTimeoutMs, polling: 100});
        title = await opened.page.title();
        if (opened.errors.length)
            throw new Setup(`the page logged:\n  ${opened.errors.join('\n  ')}`);
    } finally {
        await browser.close();
        await server.close();
    }
    const m = /misclassified ([0-9.]+)%/.exec(title);
    if (!m) throw new Setup(`${address}: after F5 the page says '${title}'`);
    console.log(`${address}: '${title}'`);
    const argv = [address, args.bundle, path.join(args.out, 'native.png'), `misclassified=${m[1]}`]
        .concat(args.bound ? [args.bound] : []);
    const r = spawnSync(args.check, argv, {encoding: 'utf8'});
    process.stdout.write(r.stdout || '');
    process.stderr.write(r.stderr || '');
    if (r.error) throw new Setup(`${args.check}: ${r.error.message}`);
    return r.status === 0 ? 0 : 1;
}

module.exports = {drag, score};
