#!/usr/bin/env node
// What WebGL2 gives in Debian's Chromium on SwiftShader (headless, no GPU), printed as JSON:
// the limits the renderer's port must fit (uniform blocks, textures, layers, draw buffers,
// samplers), fragment precision, the extensions, and three behaviours tried for real: a
// sampler2DArrayShadow under LINEAR filtering (hardware 2x2 PCF, or one tap), gl_DrawID
// through WEBGL_multi_draw's multiDrawElementsWEBGL, and how long a large shader takes to
// compile and link. A probe, not a test: run it after scripts/web-deps.sh,
//   node scripts/webgl-limits.js > limits.json
'use strict';

const path = require('path');
const {launch} = require(path.join(__dirname, '..', 'tests', 'web', 'browser.js'));

// In the page (injected as text: page.addScriptTag), one function per question; probe()
// asks them all and returns one object.
function program(gl, vs, fs) {
    const p = gl.createProgram();
    for (const [type, text] of [[gl.VERTEX_SHADER, vs], [gl.FRAGMENT_SHADER, fs]]) {
        const s = gl.createShader(type);
        gl.shaderSource(s, text);
        gl.compileShader(s);
        if (!gl.getShaderParameter(s, gl.COMPILE_STATUS)) throw new Error(gl.getShaderInfoLog(s));
        gl.attachShader(p, s);
    }
    gl.linkProgram(p);
    if (!gl.getProgramParameter(p, gl.LINK_STATUS)) throw new Error(gl.getProgramInfoLog(p));
    return p;
}

// A colour target of w x h to draw into and read back.
function target(gl, w, h) {
    const t = gl.createTexture();
    gl.bindTexture(gl.TEXTURE_2D, t);
    gl.texStorage2D(gl.TEXTURE_2D, 1, gl.RGBA8, w, h);
    const f = gl.createFramebuffer();
    gl.bindFramebuffer(gl.FRAMEBUFFER, f);
    gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, t, 0);
    gl.viewport(0, 0, w, h);
    return () => {
        const px = new Uint8Array(w * h * 4);
        gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, px);
        return px;
    };
}

// Covers the viewport with one triangle.
const fullScreen = `#version 300 es
    void main() { vec2 p = vec2(gl_VertexID & 1, gl_VertexID >> 1) * 4.0 - 1.0;
                  gl_Position = vec4(p, 0, 1); }`;

function limits(gl) {
    const names = ['MAX_UNIFORM_BLOCK_SIZE', 'MAX_TEXTURE_SIZE', 'MAX_ARRAY_TEXTURE_LAYERS',
        'MAX_DRAW_BUFFERS', 'MAX_VERTEX_TEXTURE_IMAGE_UNITS', 'MAX_COMBINED_TEXTURE_IMAGE_UNITS',
        'MAX_TEXTURE_IMAGE_UNITS', 'MAX_3D_TEXTURE_SIZE', 'MAX_CUBE_MAP_TEXTURE_SIZE',
        'MAX_RENDERBUFFER_SIZE', 'MAX_COLOR_ATTACHMENTS', 'MAX_SAMPLES',
        'MAX_UNIFORM_BUFFER_BINDINGS', 'MAX_VERTEX_UNIFORM_BLOCKS', 'MAX_FRAGMENT_UNIFORM_BLOCKS',
        'MAX_COMBINED_UNIFORM_BLOCKS', 'UNIFORM_BUFFER_OFFSET_ALIGNMENT', 'MAX_VERTEX_ATTRIBS',
        'MAX_VARYING_VECTORS', 'MAX_VERTEX_UNIFORM_VECTORS', 'MAX_FRAGMENT_UNIFORM_VECTORS',
        'VERSION', 'SHADING_LANGUAGE_VERSION'];
    const out = {webgl2: true, limits: {}};
    for (const n of names) out.limits[n] = gl.getParameter(gl[n]);
    const info = gl.getExtension('WEBGL_debug_renderer_info');
    if (info) out.renderer = gl.getParameter(info.UNMASKED_RENDERER_WEBGL);
    const precision = (type, kind) => {
        const f = gl.getShaderPrecisionFormat(type, kind);
        return {rangeMin: f.rangeMin, rangeMax: f.rangeMax, precision: f.precision};
    };
    out.fragmentHighFloat = precision(gl.FRAGMENT_SHADER, gl.HIGH_FLOAT);
    out.fragmentHighInt = precision(gl.FRAGMENT_SHADER, gl.HIGH_INT);
    out.extensions = gl.getSupportedExtensions();
    return out;
}

// sampler2DArrayShadow: layer 1 of a 4x4 depth array holds 0.25 in its left two columns
// and 0.75 in its right two; a row of 32 pixels compares reference 0.5 across it. One tap
// gives only 0 and 1; hardware 2x2 PCF gives the steps between where taps straddle.
function arrayShadow(gl) {
    const out = {};
    for (const filter of ['NEAREST', 'LINEAR']) {
        const depth = gl.createTexture();
        gl.activeTexture(gl.TEXTURE0);
        gl.bindTexture(gl.TEXTURE_2D_ARRAY, depth);
        gl.texStorage3D(gl.TEXTURE_2D_ARRAY, 1, gl.DEPTH_COMPONENT32F, 4, 4, 2);
        const values = new Float32Array(16).map((_, i) => (i % 4 < 2 ? 0.25 : 0.75));
        gl.texSubImage3D(gl.TEXTURE_2D_ARRAY, 0, 0, 0, 1, 4, 4, 1, gl.DEPTH_COMPONENT,
                         gl.FLOAT, values);
        gl.texParameteri(gl.TEXTURE_2D_ARRAY, gl.TEXTURE_COMPARE_MODE, gl.COMPARE_REF_TO_TEXTURE);
        gl.texParameteri(gl.TEXTURE_2D_ARRAY, gl.TEXTURE_COMPARE_FUNC, gl.LEQUAL);
        gl.texParameteri(gl.TEXTURE_2D_ARRAY, gl.TEXTURE_MIN_FILTER, gl[filter]);
        gl.texParameteri(gl.TEXTURE_2D_ARRAY, gl.TEXTURE_MAG_FILTER, gl[filter]);
        gl.texParameteri(gl.TEXTURE_2D_ARRAY, gl.TEXTURE_WRAP_S, gl.CLAMP_TO_EDGE);
        const read = target(gl, 32, 1);
        const p = program(gl, fullScreen, `#version 300 es
            precision highp float; precision highp sampler2DArrayShadow;
            uniform sampler2DArrayShadow maps; out vec4 colour;
            void main() { float u = 0.375 + 0.25 * gl_FragCoord.x / 32.0;
                          colour = vec4(texture(maps, vec4(u, 0.5, 1.0, 0.5))); }`);
        gl.useProgram(p);
        gl.uniform1i(gl.getUniformLocation(p, 'maps'), 0);
        gl.drawArrays(gl.TRIANGLES, 0, 3);
        const px = read();
        const seen = [...new Set(px.filter((_, i) => i % 4 === 0))].sort((a, b) => a - b);
        out[filter.toLowerCase()] = {
            distinctValues: seen.length,
            between0And1: seen.filter((v) => v > 0 && v < 255).length,
            min: seen[0] / 255,
            max: seen[seen.length - 1] / 255,
        };
    }
    out.pcf2x2 = out.linear.between0And1 > 0 && out.nearest.between0And1 === 0;
    return out;
}

// gl_DrawID: three quads side by side drawn by one multiDrawElementsWEBGL, each coloured by
// its draw's index.
function multiDraw(gl) {
    const md = gl.getExtension('WEBGL_multi_draw');
    const out = {extension: !!md};
    if (md) {
        const read = target(gl, 48, 16);
        gl.clearColor(1, 1, 1, 1);
        gl.clear(gl.COLOR_BUFFER_BIT);
        const p = program(gl, `#version 300 es
            #extension GL_ANGLE_multi_draw : require
            in vec2 position; flat out int id;
            void main() { id = gl_DrawID; gl_Position = vec4(position, 0, 1); }`, `#version 300 es
            precision highp float; flat in int id; out vec4 colour;
            void main() { colour = vec4(float(id) / 4.0, 0, 0, 1); }`);
        gl.useProgram(p);
        const corners = [];
        for (let q = 0; q < 3; ++q) {
            const x0 = -1 + (2 / 3) * q, x1 = x0 + 2 / 3;
            corners.push(x0, -1, x1, -1, x1, 1, x0, 1);
        }
        const vb = gl.createBuffer();
        gl.bindBuffer(gl.ARRAY_BUFFER, vb);
        gl.bufferData(gl.ARRAY_BUFFER, new Float32Array(corners), gl.STATIC_DRAW);
        const position = gl.getAttribLocation(p, 'position');
        gl.enableVertexAttribArray(position);
        gl.vertexAttribPointer(position, 2, gl.FLOAT, false, 0, 0);
        const indices = [];
        for (let q = 0; q < 3; ++q) indices.push(...[0, 1, 2, 0, 2, 3].map((i) => i + 4 * q));
        const ib = gl.createBuffer();
        gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, ib);
        gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, new Uint16Array(indices), gl.STATIC_DRAW);
        md.multiDrawElementsWEBGL(gl.TRIANGLES, [6, 6, 6], 0, gl.UNSIGNED_SHORT, [0, 12, 24], 0, 3);
        const px = read();
        out.drawIds = [8, 24, 40].map((x) => Math.round(px[(8 * 48 + x) * 4] / 255 * 4));
        out.drawIdWorks = out.drawIds.join() === '0,1,2';
        out.error = gl.getError();
        gl.disableVertexAttribArray(position);
    }
    return out;
}

// A large shader: many lights' worth of PCF lookups in helper functions, about the size of
// the renderer's main pass once its includes are pasted in.
function largeShader(gl) {
    const helpers = [];
    for (let i = 0; i < 120; ++i) {
        helpers.push(`float light${i}(vec3 p, vec3 n) {
            vec4 c = records[${i % 32}].clipFromWorld * vec4(p, 1.0);
            vec3 t = c.xyz / c.w * 0.5 + 0.5; float s = 0.0;
            for (int y = -2; y <= 2; ++y) for (int x = -2; x <= 2; ++x)
                s += texture(maps, vec4(t.xy + vec2(x, y) / 2048.0, float(${i % 16}), t.z - 0.001));
            float d = max(dot(n, normalize(records[${i % 32}].position.xyz - p)), 0.0);
            return d * s / 25.0 * records[${i % 32}].colour.a;
        }`);
    }
    const big = `#version 300 es
        precision highp float; precision highp sampler2DArrayShadow;
        struct Record { mat4 clipFromWorld; vec4 position; vec4 colour; };
        layout(std140) uniform Lights { Record records[32]; };
        uniform sampler2DArrayShadow maps; in vec3 wsPosition; in vec3 wsNormal; out vec4 colour;
        ${helpers.join('\n')}
        void main() { float sum = 0.0;
            ${helpers.map((_, i) => `sum += light${i}(wsPosition, wsNormal);`).join('\n')}
            colour = vec4(vec3(sum), 1.0); }`;
    const vs = `#version 300 es
        out vec3 wsPosition; out vec3 wsNormal;
        void main() { vec2 p = vec2(gl_VertexID & 1, gl_VertexID >> 1) * 4.0 - 1.0;
                      wsPosition = vec3(p, 0); wsNormal = vec3(0, 0, 1);
                      gl_Position = vec4(p, 0, 1); }`;
    const out = {lines: big.split('\n').length, characters: big.length};
    let start = performance.now();
    let p;
    try {
        p = program(gl, vs, big);
    } catch (e) {
        out.error = String(e.message).slice(0, 300);
        return out;
    }
    out.compileAndLinkMs = Math.round(performance.now() - start);
    // SwiftShader may build the pipeline at the first draw: the first draw and a second one,
    // each up to a pixel read back (a sync point), at 64x64.
    const ubo = gl.createBuffer();
    gl.bindBuffer(gl.UNIFORM_BUFFER, ubo);
    gl.bufferData(gl.UNIFORM_BUFFER, 32 * 96, gl.STATIC_DRAW);
    gl.bindBufferBase(gl.UNIFORM_BUFFER, 0, ubo);
    gl.useProgram(p);
    gl.uniformBlockBinding(p, gl.getUniformBlockIndex(p, 'Lights'), 0);
    gl.uniform1i(gl.getUniformLocation(p, 'maps'), 0);
    const read = target(gl, 64, 64);
    for (const key of ['firstDrawMs', 'secondDrawMs']) {
        start = performance.now();
        gl.drawArrays(gl.TRIANGLES, 0, 3);
        read();
        out[key] = Math.round(performance.now() - start);
    }
    out.error = gl.getError();
    return out;
}

function probe() {
    const canvas = document.createElement('canvas');
    canvas.width = canvas.height = 64;
    const gl = canvas.getContext('webgl2', {antialias: false});
    if (!gl) return {webgl2: false};
    const out = limits(gl);
    out.arrayShadow = arrayShadow(gl);
    out.multiDraw = multiDraw(gl);
    out.largeShader = largeShader(gl);
    return out;
}

async function main() {
    const browser = await launch();
    try {
        const page = await browser.newPage();
        await page.goto('about:blank');
        const inPage = [program, target, limits, arrayShadow, multiDraw, largeShader, probe];
        await page.addScriptTag({content: `var fullScreen = ${JSON.stringify(fullScreen)};\n` +
                                          inPage.map(String).join('\n')});
        const result = await page.evaluate(() => probe());
        result.chromium = await browser.version();
        process.stdout.write(JSON.stringify(result, null, 2) + '\n');
    } finally {
        await browser.close();
    }
}

main().catch((e) => {
    console.error(`webgl-limits: ${e.message}`);
    process.exit(1);
});
