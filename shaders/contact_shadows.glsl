// Screen-space contact shadows (CONTACT_SHADOWS; as Filament, Godot 4, Bevy and Unreal ship
// them): from the fragment, a short march towards the light through the view's depth buffer
// (ViewDepthPass, at the output's size). A step that lands behind a surface the camera sees,
// by less than the march's length (a thin occluder, not the far side of the world), is
// occluded: the contacts a shadow map misses under its tolerances and texels (a foot on the
// floor, a thin part against its base) get their shadow. Included by main.frag.glsl.
#ifdef CONTACT_SHADOWS
layout(binding = 5) uniform sampler2D uViewDepth;  // window depth, NEAREST, no comparison
layout(location = 2) uniform mat4 uClipFromView;   // the vertex stage's, shared
layout(location = 8) uniform mat4 uViewFromClip;
layout(location = 9) uniform float uContactLength;  // world units (= view units)

const int kContactSteps = 8;

// View-space z of what the camera sees at window position `uv` (negative: in front).
float contactSceneZ(vec2 uv) {
    float d = texture(uViewDepth, uv).r;
    vec4 v = uViewFromClip * vec4(uv * 2.0 - 1.0, d * 2.0 - 1.0, 1.0);
    return v.z / v.w;
}

// 1 when nothing in the depth buffer lies between the fragment and `length` towards the
// light, 0 when something does. `lightDistance` is the light's distance for point and spot
// lights (the march stops there), or a large number for directional ones.
float contactShadow(vec3 vsP, vec3 vsN, vec3 vsToLight, float lightDistance) {
    float len = min(uContactLength, 0.95 * lightDistance);
    if (!(len > 0.0)) return 1.0;
    // Steps start off the surface and are staggered per pixel (interleaved gradient noise,
    // Jimenez 2014), so a short march leaves no bands.
    float jitter = fract(52.9829189 * fract(dot(gl_FragCoord.xy, vec2(0.06711056, 0.00583715))));
    vec3 start = vsP + vsN * (0.02 * len);
    // The tolerance: a surface nearer the camera than the step by less than this is the
    // receiver itself (depth-buffer rounding, curvature between pixels).
    float tolerance = 0.04 * len;
    for (int i = 0; i < kContactSteps; ++i) {
        vec3 p = start + vsToLight * (len * (float(i) + jitter) / float(kContactSteps));
        vec4 c = uClipFromView * vec4(p, 1.0);
        if (!(c.w > 0.0)) break;
        vec2 uv = c.xy / c.w * 0.5 + 0.5;
        if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) break;
        float inFront = contactSceneZ(uv) - p.z;  // > 0: the scene is nearer the camera
        if (inFront > tolerance && inFront < len) return 0.0;
    }
    return 1.0;
}
#endif
