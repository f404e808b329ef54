// gnomon's page (apps/web): reads the address (#scene=NAME&OPTION=VALUE..., the command
// line's option names) and shows either the viewer (PageViewer.cpp: gnomon view's app on the
// canvas #gnomon, which keeps the address up to date as the user changes things) or, with
// ui=off or a picture=, only the picture (main.cpp: rendered with WebGL2, ray-traced with
// picture=truth, the error map with picture=score) drawn into the same canvas. The title says
// when it is done: "gnomon ready: ..." (what the browser tests wait for) or "gnomon error:
// ..." with the CLI's message.
'use strict';

// The picture alone, not the viewer: decided once, as the page loads (the canvas takes a 2D
// context for a picture, WebGL2 for the viewer).
const pictureOnly = (() => {
    const params = addressParams();
    return params.get('ui') === 'off' || params.has('picture');
})();

// Emscripten's module settings: gnomon.js, loaded after this file, fills in the rest.
var Module = {
    print: (text) => console.log(text),
    printErr: (text) => console.warn(text),
    canvas: pictureOnly ? element('gl') : element('gnomon'),
    onRuntimeInitialized: () => {
        fillMenu();
        element('file').addEventListener('change', (e) => loadFiles(e.target.files));
        // Files dropped anywhere on the page load as the file button's do.
        window.addEventListener('dragover', (e) => e.preventDefault());
        window.addEventListener('drop', (e) => {
            e.preventDefault();
            loadFiles(e.dataTransfer.files);
        });
        document.body.classList.toggle('viewer', !pictureOnly);
        window.addEventListener('hashchange', pictureOnly ? show : view);
        if (pictureOnly) show();
        else view();
    },
};

// The viewer, over the window below the header; a new address replaces its scene and options.
function view() {
    document.title = 'gnomon: working';
    element('scene').value = addressParams().get('scene') || 'book-triangle';
    const [width, height] = viewerSize();
    const error = Module.startViewer(location.hash, width, height);
    element('error').hidden = !error;
    element('error').textContent = error;
    element('status').textContent = error ? 'error' : '';
    if (error) document.title = 'gnomon error: ' + error.replace(/^gnomon: error: /, '');
}

// The viewer's size in CSS pixels: the window below the header, at least 640x400.
function viewerSize() {
    const top = element('gnomon').getBoundingClientRect().top;
    return [Math.max(640, window.innerWidth), Math.max(400, Math.floor(window.innerHeight - top))];
}
window.addEventListener('resize', () => {
    if (!pictureOnly && Module.resizeViewer) Module.resizeViewer(...viewerSize());
});

// Keys the viewer uses that the browser would take (F5 reloads the page).
window.addEventListener('keydown', (e) => {
    if (!pictureOnly && e.key === 'F5') e.preventDefault();
});

function element(id) {
    return document.getElementById(id);
}

// The address's keys and values, as the page was given them.
function addressParams() {
    return new URLSearchParams(location.hash.replace(/^#/, ''));
}

// The scene menu: the built-in scenes and the bundled models; choosing one keeps the
// address's options but not what belongs to the scene left (its camera, sun, ambient and
// lights), as a file loaded the same way does.
function fillMenu() {
    const menu = element('scene');
    for (const name of Module.scenes()) menu.add(new Option(name, name));
    menu.value = addressParams().get('scene') || 'book-triangle';
    menu.addEventListener('change', () => {
        location.hash = sceneAddress(menu.value).toString();
    });
}

// The address's keys for another scene: the options kept, the scene's own edits dropped.
function sceneAddress(scene) {
    const params = addressParams();
    for (const key of [...params.keys()]) {
        if (/^(camera-|light\d|sun$|ambient$)/.test(key)) params.delete(key);
    }
    params.set('scene', scene);
    return params;
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
        const params = sceneAddress('/upload/' + model);
        const address = '#' + params.toString();
        // The same files again: no hashchange, so shown here.
        if (location.hash === address) (pictureOnly ? show : view)();
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
