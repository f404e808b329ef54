#!/usr/bin/env node
// The pictures of the page in docs/web.md, taken in Debian's Chromium from build/web:
//   node scripts/web-shots.js        (after `make web`)
// writes docs/images/web-viewer.png (the viewer on tutorial-spot at 1280x760).
'use strict';

const path = require('path');
const root = path.resolve(__dirname, '..');
const {serve, launch, open} = require(path.join(root, 'tests/web/browser.js'));

async function main() {
    const server = await serve(path.join(root, 'build/web'));
    const browser = await launch();
    try {
        const {page, title} = await open(browser, `${server.origin}/index.html#scene=tutorial-spot`,
            ['gnomon ready', 'gnomon error'], 120000);
        if (!title.startsWith('gnomon ready')) throw new Error(title);
        await page.setViewport({width: 1280, height: 760});
        await page.waitForFunction(() => Module.viewerDrawn(), {timeout: 120000, polling: 50});
        // A few frames for the pass-time plots, then the picture.
        await page.evaluate(() => new Promise((r) => setTimeout(r, 1500)));
        const out = path.join(root, 'docs/images/web-viewer.png');
        await page.screenshot({path: out});
        console.log(`wrote ${out}`);
    } finally {
        await browser.close();
        await server.close();
    }
}

main().catch((e) => {
    console.error(`web-shots: ${e.message}`);
    process.exit(1);
});
