// Moments of stored depth for the filterable shadow maps, shared by the moment pass that
// writes them (moments.frag.glsl) and the lookups that read them (shadow_lookup.glsl).
//
// Exponential variance shadow maps (Lauritzen and McCool, "Layered Variance Shadow Maps",
// GI 2008; Lauritzen, "Summed-Area Variance Shadow Maps", GPU Gems 3, ch. 8): depth d in
// [0, 1] is warped to exp(c (2d - 1)), whose mean and mean square a blur keeps; Chebyshev's
// inequality then bounds how much of a filtered texel lies in front of a receiver. The
// warp's exponent sets how fast light bleeding falls off with the distance between two
// casters: 40 is the largest a 32-bit float holds squared (e^80 < 3.4e38), as Lauritzen and
// MJP's "Shadows" sample use for 32-bit targets. The negative warp (EVSM4) may go as far;
// MJP's sample defaults it to 5. 20 keeps EVSM4 near PCF's error on real scenes, which 5 does
// not, and unlike 30 or 40 leaves no dots of false shadow on faces a fraction of a degree
// from edge-on to the sun (the Lantern's post).
const float kEvsmPositive = 40.0;
const float kEvsmNegative = 20.0;

// The depth moments are taken of: stored depth for orthographic maps, where it is linear
// already; for perspective ones (spot lights) the distance it stands for, mapped to [0, 1]
// over [near, far]. Stored perspective depth crowds towards 1 far from the light, where the
// warp would then see no difference between a caster and its receiver, and leak.
float momentDepth(float stored, float near, float far, bool perspective) {
    if (!perspective) return stored;
    float z = near * far / (far - stored * (far - near));
    return (z - near) / (far - near);
}

vec2 evsmWarp(float depth) {
    float d = 2.0 * clamp(depth, 0.0, 1.0) - 1.0;
    return vec2(exp(kEvsmPositive * d), -exp(-kEvsmNegative * d));
}

// The four components a texel stores: EVSM2 (e+, e+^2, 0, 0), EVSM4 (e+, e+^2, e-, e-^2),
// MSM the power moments (d, d^2, d^3, d^4) of moment shadow maps (Peters and Klein, "Moment
// Shadow Mapping", I3D 2015) as plain 32-bit floats, of depth moved to [-1, 1]: the lookup's
// 3x3 system is far better conditioned there (moment_lookup.glsl).
vec4 depthMoments(float depth) {
#if defined(MOMENTS_MSM)
    float d = 2.0 * clamp(depth, 0.0, 1.0) - 1.0, d2 = d * d;
    return vec4(d, d2, d2 * d, d2 * d2);
#else
    vec2 w = evsmWarp(depth);
#if defined(MOMENTS_EVSM4)
    return vec4(w.x, w.x * w.x, w.y, w.y * w.y);
#else
    return vec4(w.x, w.x * w.x, 0.0, 0.0);
#endif
#endif
}
