// gnomon's page (apps/web): reads the address (#scene=NAME&OPTION=VALUE..., the command
// line's option names), asks the wasm module (main.cpp) for the scene's picture (rendered with
// WebGL2, or with picture=truth ray-traced),
// draws it into the canvas #gnomon and says in the title when it is done: "gnomon ready: ..."
// (what the browser tests wait for) or "gnomon error: ..." with the CLI's message.
'use strict';

// Emscripten's module settings: gnomon.js, loaded after this file, fills in the rest.
var Module = {
    print: (text) => console.log(text),
    printErr: (text) => console.warn(text),
    onRuntimeInitialized: () => {
        fillMenu();
        element('file').addEventListener('change', (e) => loadFiles(e.target.files));
        window.addEventListener('hashchange', show);
        show();
    },
};

function element(id) {
    return document.getElementById(id);
}

// The address's keys and values, as the page was given them.
function addressParams() {
    return new URLSearchParams(location.hash.replace(/^#/, ''));
}

// The scene menu: the built-in scenes and the bundled models; choosing one keeps the other
// keys of the address.
function fillMenu() {
    const menu = element('scene');
    for (const name of Module.scenes()) menu.add(new Option(name, name));
    menu.value = addressParams().get('scene') || 'book-triangle';
    menu.addEventListener('change', () => {
        const params = addressParams();
        params.set('scene', menu.value);
        location.hash = params.toString();
    });
}

// Files chosen with the button go into the page's memory file system under /upload (a .gltf
// with its .bin and textures: chosen together), and the address names the model; the link
// then works only in this page, while the files are in memory.
function loadFiles(files) {
    if (!files.length) return;
    if (!Module.FS.analyzePath('/upload').exists) Module.FS.mkdir('/upload');
    const written = [...files].map((file) => file.arrayBuffer().then((bytes) => {
        Module.FS.writeFile('/upload/' + file.name, new Uint8Array(bytes));
    }));
    Promise.all(written).then(() => {
        const names = [...files].map((file) => file.name);
        const model = names.find((name) => /\.(gltf|glb)$/i.test(name)) || names[0];
        const params = addressParams();
        params.set('scene', '/upload/' + model);
        const address = '#' + params.toString();
        if (location.hash === address) show();  // the same files again: no hashchange
        else location.hash = address;
    });
}

function show() {
    document.title = 'gnomon: working';
    element('status').textContent = 'working…';
    element('scene').value = addressParams().get('scene') || 'book-triangle';
    // A frame first, so the status shows before the trace holds the page.
    requestAnimationFrame(() => setTimeout(() => draw(Module.show(location.hash)), 0));
}

function draw(result) {
    const canvas = element('gnomon');
    const error = element('error');
    const warnings = element('warnings');
    warnings.replaceChildren();
    if (!result.ok) {
        error.hidden = false;
        error.textContent = result.error;
        canvas.hidden = true;
        element('caption').textContent = '';
        element('status').textContent = 'error';
        document.title = 'gnomon error: ' + result.error.replace(/^gnomon: error: /, '');
        return;
    }
    error.hidden = true;
    canvas.hidden = false;
    canvas.width = result.width;
    canvas.height = result.height;
    canvas.getContext('2d').putImageData(
        new ImageData(result.pixels, result.width, result.height), 0, 0);
    for (const text of result.warnings) {
        const item = document.createElement('li');
        item.textContent = 'warning: ' + text;
        warnings.append(item);
    }
    const ms = Math.round(result.seconds * 1000);
    const size = `${result.scene} at ${result.width}×${result.height}`;
    element('caption').textContent = result.picture === 'truth'
        ? `${size}, ${result.light}: traced on the BVH in ${ms} ms`
        : result.picture === 'score'
        ? `${size}: ${result.misclassified.toFixed(3)} % of pixels misclassified against the ` +
              `reference traced on the BVH (error map; ${ms} ms)`
        : `${size}: rendered with WebGL2 in ${ms} ms`;
    element('status').textContent = 'ready';
    document.title = `gnomon ready: ${result.scene} ${result.width}x${result.height}` +
        (result.picture === 'score' ? ` misclassified ${result.misclassified.toFixed(4)}%` : '');
}
