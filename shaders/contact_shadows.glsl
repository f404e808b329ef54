// Screen-space contact shadows (CONTACT_SHADOWS; as Filament, Godot 4, Bevy and Unreal ship
// them): from the fragment, a short march towards the light through the view's depth buffer
// (ViewDepthPass, at the output's size). A step that lands behind a surface the camera sees,
// by less than the march's length (a thin occluder, not the far side of the world), is
// occluded: the contacts a shadow map misses under its tolerances and texels (a foot on the
// floor, a thin part against its base) get their shadow. Included by main.frag.glsl.
#ifdef CONTACT_SHADOWS
layout(binding = 5) uniform sampler2D uViewDepth;  // window depth, NEAREST, no comparison
layout(location = 2) uniform mat4 uClipFromView;   // the vertex stage's, shared
// View-space z from window depth d: (x·d + y) / (z·d + w). A perspective or orthographic
// projection's z and w rows do not involve x and y, so the inverse projection reduces to this.
layout(location = 8) uniform vec4 uViewZFromDepth;
layout(location = 9) uniform float uContactLength;  // world units (= view units)

const int kContactSteps = 8;

// The receiver's own plane in the depth buffer: window depth is affine in screen space (for
// perspective and orthographic views alike), so its depth at the fragment and its change
// per pixel give the depth the receiver itself has at any pixel's centre, where the buffer
// was sampled. Set by findContactPlane() before any discard (derivatives need the whole 2x2
// quad).
vec3 gContactPlane = vec3(0.0);
void findContactPlane() {
    gContactPlane = vec3(gl_FragCoord.z, dFdx(gl_FragCoord.z), dFdy(gl_FragCoord.z));
}

// Four steps of the stored depth (32-bit float: 2^-24 below 1) at the fragment, in view z:
// the two depth passes round the same surface apart by about that much, and a march shorter
// than it could tell them apart (tutorial-room, a march of 0.001: 6 % false shadow in rows).
float depthSpacing() {
    vec4 m = uViewZFromDepth;
    float denominator = m.z * gl_FragCoord.z + m.w;
    return abs(m.x * m.w - m.y * m.z) / (denominator * denominator) * exp2(-22.0);
}

float viewZFromDepth(float d) {
    return (uViewZFromDepth.x * d + uViewZFromDepth.y) / (uViewZFromDepth.z * d + uViewZFromDepth.w);
}

// `visible` (the map's visibility) when nothing in the depth buffer lies between the
// fragment and the march's length towards the light, 0 when something does; a fragment the
// map already shadows (visible 0) does not march. `lightDistance` is the light's distance
// for point and spot lights (the march stops there), or a large number for directional ones.
float contactShadow(vec3 vsP, vec3 vsN, vec3 vsToLight, float lightDistance, float visible) {
    float len = min(uContactLength, 0.95 * lightDistance);
    if (!(len > 0.0)) return visible;
    // Steps start off the surface and are staggered per pixel (interleaved gradient noise,
    // Jimenez 2014), so a short march leaves no bands.
    float jitter = fract(52.9829189 * fract(dot(gl_FragCoord.xy, vec2(0.06711056, 0.00583715))));
    vec3 start = vsP + vsN * (0.02 * len);
    vec3 end = start + vsToLight * len;
    // Clip coordinates and view z are linear along the segment, so each step interpolates
    // them instead of projecting its point: no matrix product inside the loop.
    vec4 clipStart = uClipFromView * vec4(start, 1.0);
    vec4 clipEnd = uClipFromView * vec4(end, 1.0);
    // The tolerance: a surface nearer the camera than the step, or than the receiver's own
    // plane, by less than this is the receiver (depth-buffer rounding, curvature between
    // pixels).
    float tolerance = 0.04 * len + depthSpacing();
    vec2 size = vec2(textureSize(uViewDepth, 0));
    // The march ends at its first occluder; a block of pixels leaves the loop once all of
    // its pixels have (llvmpipe skips a loop only when no pixel of the block is in it).
    for (int i = 0; i < kContactSteps && visible > 0.0; ++i) {
        float t = (float(i) + jitter) / float(kContactSteps);
        vec4 c = mix(clipStart, clipEnd, t);
        if (!(c.w > 0.0)) break;
        vec2 pixel = (c.xy / c.w * 0.5 + 0.5) * size;
        if (any(lessThan(pixel, vec2(0.0))) || any(greaterThanEqual(pixel, size))) break;
        // The buffer holds each pixel's depth at its centre, not where the step's ray meets
        // the surface: the receiver seen or lit at a grazing angle is there nearer the camera
        // than the step by up to half a pixel's depth change. It is told apart by lying on
        // its own plane at that centre. A test against the step alone took the first steps
        // of a short march, inside the fragment's own pixel, for occluders wherever the
        // light came from behind the surface as the camera sees it (LightsPunctualLamp, sun
        // at 200,20, a march of 0.01: 66 % false shadow).
        vec2 centre = floor(pixel) + 0.5;
        float sceneZ = viewZFromDepth(texelFetch(uViewDepth, ivec2(centre), 0).r);
        float ownZ = viewZFromDepth(gContactPlane.x + dot(gContactPlane.yz, centre - gl_FragCoord.xy));
        float inFront = sceneZ - mix(start.z, end.z, t);  // > 0: the scene is nearer the camera
        if (inFront > tolerance && inFront < len && sceneZ - ownZ > tolerance) visible = 0.0;
    }
    return visible;
}
#endif
