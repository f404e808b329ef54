// Lookups of the filterable maps (FILTER_MOMENTS with MOMENTS_EVSM2 | MOMENTS_EVSM4 |
// MOMENTS_MSM), included by shadow_lookup.glsl: one bilinear read of a map's blurred
// moments (the moment pass's output) and a bound on how much of that texel's footprint lies
// in front of the receiver. Soft edges come from the blur and the bilinear read; the failure
// of them all is light bleeding, where two casters overlap in depth across a footprint.
#include "moments.glsl"
layout(binding = 6) uniform sampler2DArray uShadowMoments;
// Visibility below this share reads as shadow and the rest is stretched over [0, 1]:
// bleeding, whose visibility is partial, is cut (at the cost of narrower penumbrae).
layout(location = 12) uniform float uLightBleed;

float reduceBleeding(float v) {
    return clamp((v - uLightBleed) / (1.0 - uLightBleed), 0.0, 1.0);
}

// Chebyshev's one-tailed bound of the share of depths at or beyond `t` given their mean and
// mean square (`m`); the variance is kept above `minVariance`, the tolerance that keeps a
// flat receiver from shadowing itself through rounding.
float chebyshev(vec2 m, float t, float minVariance) {
    float variance = max(m.y - m.x * m.x, minVariance);
    float d = t - m.x;
    return t <= m.x ? 1.0 : variance / (variance + d * d);
}

// Depth tolerance of the EVSM bound, in [-1, 1] depth units: a warped variance of
// (c e^(c d) x this)^2 at depth d, which is what this much depth spread becomes under the warp.
const float kEvsmTolerance = 2e-4;

float evsmVisibility(vec4 m, float depth) {
    vec2 w = evsmWarp(depth);
    float pos = chebyshev(m.xy, w.x, pow(kEvsmPositive * w.x * kEvsmTolerance, 2.0));
#if defined(MOMENTS_EVSM4)
    float neg = chebyshev(m.zw, w.y, pow(kEvsmNegative * w.y * kEvsmTolerance, 2.0));
    return reduceBleeding(min(pos, neg));
#else
    return reduceBleeding(pos);
#endif
}

// Hamburger four-moment shadow intensity (Peters and Klein 2015, Algorithm 2): the biased
// moments b, the 3x3 Hankel system B c = (1, z, z^2) solved by an LDL^T factorisation, the
// two roots z2 <= z3 of c3 x^2 + c2 x + c1, and the smallest share of depths in front of z
// any distribution with these moments allows. Depth in [-1, 1] as stored; the bias pulls the
// moments towards those of the uniform distribution there (0, 1/3, 0, 1/5), which has every
// depth in its support: towards the paper's (0.5, 0.5, 0.5, 0.5) on [0, 1] instead, a
// surface near the far plane meets one of that bias's two support points and the system
// loses every digit in 32-bit floats (lit ground shadowed). How far: the value common in
// implementations, 3e-5, leaks at contacts; with 32-bit float moments 1e-5 leaks less, and
// smaller biases shadow too much.
const float kMomentBias = 1e-5;
float msmVisibility(vec4 moments, float depth) {
    float z = 2.0 * depth - 1.0;
    vec4 b = mix(moments, vec4(0.0, 1.0 / 3.0, 0.0, 0.2), kMomentBias);
    float d22 = b.y - b.x * b.x;
    float l32 = (b.z - b.x * b.y) / d22;
    float d33 = b.w - b.y * b.y - l32 * l32 * d22;
    float y2 = z - b.x;
    float y3 = z * z - b.y - l32 * y2;
    float c3 = y3 / d33;
    float c2 = y2 / d22 - l32 * c3;
    float c1 = 1.0 - b.x * c2 - b.y * c3;
    float root = sqrt(max(c2 * c2 - 4.0 * c3 * c1, 0.0));
    float r1 = (-c2 - root) / (2.0 * c3), r2 = (-c2 + root) / (2.0 * c3);
    float z2 = min(r1, r2), z3 = max(r1, r2);
    float g;
    if (z <= z2) {
        g = 0.0;
    } else if (z <= z3) {
        g = (z * z3 - b.x * (z + z3) + b.y) / ((z3 - z2) * (z - z2));
    } else {
        g = 1.0 - (z2 * z3 - b.x * (z2 + z3) + b.y) / ((z - z2) * (z - z3));
    }
    return reduceBleeding(clamp(1.0 - g, 0.0, 1.0));
}

// `uv` in the layer, `stored` the receiver's stored depth less its tolerance.
float momentVisibility(LightRecord light, vec2 uv, float layer, float stored) {
    vec4 m = texture(uShadowMoments, vec3(uv, layer));
    float depth = momentDepth(stored, light.mapNear, light.mapFar,
                              light.frame != kFrameOrthographic);
#if defined(MOMENTS_MSM)
    return msmVisibility(m, depth);
#else
    return evsmVisibility(m, depth);
#endif
}
