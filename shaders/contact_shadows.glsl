// Screen-space contact shadows (CONTACT_SHADOWS; as Filament, Godot 4, Bevy and Unreal ship
// them): from the fragment, a short march towards the light through the view's depth buffer
// (ViewDepthPass, at the output's size). A step that lands behind a surface the camera sees,
// by less than half the march's length (a thin occluder, not the far side of the world), is
// occluded: the contacts a shadow map misses under its tolerances and texels (a foot on the
// floor, a thin part against its base) get their shadow. Included by main.frag.glsl.
#ifdef CONTACT_SHADOWS
layout(binding = 5) uniform sampler2D uViewDepth;  // window depth, NEAREST, no comparison
// The view's clip from world, one product on the CPU where each fragment would make two.
layout(location = 13) uniform mat4 uClipFromWorld;
// View-space z from window depth d: (x·d + y) / (z·d + w). A perspective or orthographic
// projection's z and w rows do not involve x and y, so the inverse projection reduces to this.
layout(location = 8) uniform vec4 uViewZFromDepth;
layout(location = 9) uniform float uContactLength;  // world units (= view units)

// At most this many steps, written out (the compiler unrolls a constant count): llvmpipe
// keeps what a loop changes in memory behind its mask, and each step costs a depth read on
// every pixel. Four steps, from the fragment itself, close the contacts as well as more would
// (docs/results/performance.md, "Contact shadows").
const int kContactSteps = 4;

// The receiver's own plane in the depth buffer: window depth is affine in screen space (for
// perspective and orthographic views alike), so its depth at the fragment and its change
// per pixel give the depth the receiver itself has at any pixel's centre, where the buffer
// was sampled. Taken before any discard (derivatives need the whole 2x2 quad).
vec3 findContactPlane() {
    return vec3(gl_FragCoord.z, dFdx(gl_FragCoord.z), dFdy(gl_FragCoord.z));
}

// dz/dd, view z per unit of window depth at window depth d: the march converts its
// tolerances into depth once, at the fragment, and compares depths without a division.
float viewZPerDepth(float d) {
    vec4 m = uViewZFromDepth;
    float denominator = m.z * d + m.w;
    return abs(m.x * m.w - m.y * m.z) / (denominator * denominator);
}

// `visible` (the map's visibility) when nothing in the depth buffer lies between the
// fragment and the march's length towards the light, 0 when something does. `plane` is
// findContactPlane()'s. The point `p` and the direction `toLight` are in world space (the
// view's rotation keeps lengths). `lightDistance` is the light's distance for point and spot
// lights (the march stops there), or a large number for directional ones.
float contactShadow(vec3 plane, vec3 p, vec3 toLight, float lightDistance, float visible) {
    float len = min(uContactLength, 0.95 * lightDistance);
    if (!(len > 0.0)) return visible;
    // Steps are staggered per pixel (shadow_lookup.glsl's interleaved gradient noise), so a
    // short march leaves no bands.
    float jitter = interleavedGradientNoise();
    // The march starts at the fragment, whose clip coordinates its window position and
    // 1 / w give without a matrix product, and ends `len` towards the light.
    vec2 size = vec2(textureSize(uViewDepth, 0));
    vec2 invSize = 1.0 / size;
    float w0 = 1.0 / gl_FragCoord.w;
    vec4 clipStart = vec4((vec3(gl_FragCoord.xy / size, gl_FragCoord.z) * 2.0 - 1.0) * w0, w0);
    vec4 clipEnd = uClipFromWorld * vec4(p + toLight * len, 1.0);
    // A march towards the camera stops before the camera's plane, where it would not project.
    float wMin = 0.1 * clipStart.w;
    if (clipEnd.w < wMin) {
        float keep = (clipStart.w - wMin) / (clipStart.w - clipEnd.w);
        clipEnd = mix(clipStart, clipEnd, keep);
        len *= keep;
    }
    // A segment stays a segment on screen, with window depth linear along it: the march
    // steps evenly in pixels and window depth, with no division per step.
    vec3 from = gl_FragCoord.xyz;
    float toW = 1.0 / clipEnd.w;
    vec3 to = vec3((clipEnd.xy * toW * 0.5 + 0.5) * size, clipEnd.z * toW * 0.5 + 0.5);
    // One step per pixel crossed, up to kContactSteps: more would read the same pixels again,
    // so a short march (a contact is a few pixels wide) reads a pixel or two.
    int steps = int(clamp(ceil(max(abs(to.x - from.x), abs(to.y - from.y))), 1.0,
                          float(kContactSteps)));
    // The tolerances in window depth at the fragment. A surface nearer the camera than the
    // step, or than the receiver's own plane, by less than `tolerance` is the receiver
    // (curvature between pixels: a share of the march; the two depth passes' rounding of one
    // surface: four steps of 32-bit float depth below 1, 2^-24 each, else a march shorter
    // than that rounding shadows rows of a floor). Nearer than the step by more than half the
    // march's length, it is taken for a surface in front of the ray rather than an occluder
    // across it (the whole length takes thin walls' far sides for occluders).
    float perDepth = viewZPerDepth(gl_FragCoord.z);
    float tolerance = 0.04 * len / perDepth + exp2(-22.0);
    float thickness = 0.5 * len / perDepth;
    float stepShare = 1.0 / float(steps);
    for (int i = 0; i < kContactSteps; ++i) {
        vec3 q = mix(from, to, (float(i) + jitter) * stepShare);
        // A step past the march's own count or off the screen reads a clamped pixel and
        // counts for nothing (a segment that leaves the screen does not come back).
        bool counts = i < steps && all(greaterThanEqual(q.xy, vec2(0.0))) &&
                      all(lessThan(q.xy, size));
        // The buffer holds each pixel's depth at its centre, not where the step's ray meets
        // the surface: the receiver seen or lit at a grazing angle is there nearer the camera
        // than the step by up to half a pixel's depth change. It is told apart by lying on
        // its own plane at that centre. A test against the step alone would take the first
        // steps of a short march, inside the fragment's own pixel, for occluders wherever the
        // light comes from behind the surface as the camera sees it.
        vec2 centre = floor(clamp(q.xy, vec2(0.0), size - 1.0)) + 0.5;
        // Read at the pixel's centre through the NEAREST sampler: the same texel as a
        // texelFetch, which llvmpipe runs slower.
        float scene = texture(uViewDepth, centre * invSize).r;
        float own = plane.x + dot(plane.yz, centre - gl_FragCoord.xy);
        float inFront = q.z - scene;  // > 0: the scene is nearer the camera than the step
        if (counts && inFront > tolerance && inFront < thickness && own - scene > tolerance) {
            visible = 0.0;
        }
    }
    return visible;
}
#endif
