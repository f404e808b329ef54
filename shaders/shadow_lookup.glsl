// Shadow map lookup (SPEC S2, S9, S13, S17): world point -> light texture space, divide by
// w, compare with the stored depth plus tolerance. Single-frustum maps of all lights live in
// one texture array (one layer per light, a light's map in the layer's lower-left corner);
// point lights' cube maps in one cube-map array.
//
// Variants (injected #defines): FILTER_NONE | FILTER_HW2X2 | FILTER_PCF with PCF_SIZE,
// OUTSIDE_CLAMP (the textbooks' clamp-to-edge; default: outside the map is lit).
layout(binding = 1) uniform samplerCubeArrayShadow uShadowCubes;

// Depth-aware tolerance (SPEC S12): x steps of the stored depth's spacing; y, z that spacing
// for the 2D maps and the cubes (< 0: one float ulp of the stored depth, which grows with it).
layout(location = 7) uniform vec3 uDepthAware;

float depthTolerance(LightData light, float stored, float spacing) {
    float step = spacing >= 0.0 ? spacing : exp2(floor(log2(max(stored, 1e-30))) - 23.0);
    return light.shadowBias.x + uDepthAware.x * step;
}

#if defined(HAND_COMPARE)
// Fetch the stored depth (filtered by the sampler: --map-filter) and compare by hand: every
// lookup of colour formats (PACK_*: decode first), and --filter none on native depth (the
// course text's LINEAR lookup of a depth texture). LINEAR interpolates stored depth: fine
// for one channel, wrong for packed channels (why the book's Shadow_highp uses NEAREST).
#include "depth_packing.glsl"
layout(binding = 0) uniform sampler2DArray uShadowMaps;
float compareDepth(vec2 uv, float layer, float reference) {
    return reference > unpackDepth(texture(uShadowMaps, vec3(uv, layer))) ? 0.0 : 1.0;
}
#else
// The comparison sampler (LEQUAL): compares each texel, then filters the results; LINEAR
// gives 2x2 bilinear PCF.
layout(binding = 0) uniform sampler2DArrayShadow uShadowMaps;
float compareDepth(vec2 uv, float layer, float reference) {
    return texture(uShadowMaps, vec4(uv, layer, reference));
}
#endif

// Texels a lookup reaches from its centre, plus the bilinear footprint's one.
#if defined(FILTER_PCF)
const float kFilterReach = float(PCF_SIZE / 2) + 1.0;
#elif defined(FILTER_HW2X2)
const float kFilterReach = 1.0;
#else
const float kFilterReach = 0.5;
#endif

// Normal offset: move the lookup point off the surface along its normal. A planar receiver
// tilted by theta to the light changes stored depth by tan(theta) per texel of world size w;
// a filter reaching k texels (plus one for bilinear) needs the point (k + 1) w sin(theta) off
// the surface to stay lit everywhere it should.
vec3 normalOffset(LightData light, vec3 wsNormal, vec3 wsToLight, float texelWorld) {
    float nDotL = clamp(dot(wsNormal, wsToLight), 0.0, 1.0);
    float sinTheta = sqrt(1.0 - nDotL * nDotL);
    return wsNormal * (light.shadowBias.y * kFilterReach * texelWorld * sinTheta);
}

// Point lights (SPEC S21): the cube face of the direction light -> point holds the depth
// along that face's axis; compare against the same depth of this point. PCF taps lie in the
// face's plane (a 2-D kernel on the face, not the tutorial's 3-D grid of directions: the
// same footprint for k^2 instead of k^3 lookups).
float cubeVisibility(LightData light, vec3 wsPosition, vec3 wsNormal, vec3 wsToLight) {
    vec3 toPoint = wsPosition - light.wsPosition.xyz;
    float near = light.wsPosition.w, far = light.shadowBias.w;
    vec3 a = abs(toPoint);
    float major = max(a.x, max(a.y, a.z));
    vec3 offset = normalOffset(light, wsNormal, wsToLight, light.shadow.y * major);
    toPoint += offset;
    a = abs(toPoint);
    major = max(a.x, max(a.y, a.z));
    float ndc = (far + near) / (far - near) - 2.0 * far * near / ((far - near) * major);
    float stored = 0.5 * ndc + 0.5;
    float reference = stored - depthTolerance(light, stored, uDepthAware.z);
    float layer = light.colour.w;
#if defined(FILTER_PCF)
    // Two axes spanning the face of the major axis; one texel is 2 / size at unit distance.
    vec3 u = a.x >= a.y && a.x >= a.z ? vec3(0, 1, 0) : vec3(1, 0, 0);
    vec3 v = a.z >= a.x && a.z >= a.y ? vec3(0, 1, 0) : vec3(0, 0, 1);
    float step = light.shadowBias.z * 2.0 * major;
    float sum = 0.0;
    const int r = PCF_SIZE / 2;
    for (int y = -r; y <= r; ++y) {
        for (int x = -r; x <= r; ++x) {
            vec3 tap = toPoint + (float(x) * u + float(y) * v) * step;
            sum += texture(uShadowCubes, vec4(tap, layer), reference);
        }
    }
    return sum / float(PCF_SIZE * PCF_SIZE);
#else
    return texture(uShadowCubes, vec4(toPoint, layer), reference);
#endif
}

// Visibility of a world point for one light, 0 (shadowed) .. 1 (lit).
float shadowVisibility(LightData light, vec3 wsPosition, vec3 wsNormal, vec3 wsToLight) {
    if (light.shadow.z == kFrameCube) return cubeVisibility(light, wsPosition, wsNormal, wsToLight);
    float layer = light.colour.w;
    float uvScale = light.shadow.w;
    float texelUv = light.shadowBias.z;

    vec4 clip = light.textureFromWorld * vec4(wsPosition, 1.0);
    float texelWorld = light.shadow.y * (light.shadow.z == kFrameOrthographic ? 1.0 : clip.w);
    vec3 offset = normalOffset(light, wsNormal, wsToLight, texelWorld);
    vec4 shadowCoord = light.textureFromWorld * vec4(wsPosition + offset, 1.0);
    vec3 coord = shadowCoord.xyz / shadowCoord.w;

#ifdef OUTSIDE_CLAMP
    coord.xy = clamp(coord.xy, 0.0, 1.0);
#else
    if (shadowCoord.w <= 0.0 || any(lessThan(coord, vec3(0.0))) ||
        any(greaterThan(coord, vec3(1.0)))) {
        return 1.0;
    }
#endif
    float reference = coord.z - depthTolerance(light, coord.z, uDepthAware.y);
    // The light's map covers [0, uvScale] of the layer; keep every tap inside it.
    vec2 lo = vec2(0.5 * texelUv), hi = vec2(uvScale - 0.5 * texelUv);
    vec2 uv = coord.xy * uvScale;
#if defined(FILTER_PCF)
    float sum = 0.0;
    const int r = PCF_SIZE / 2;
    for (int y = -r; y <= r; ++y) {
        for (int x = -r; x <= r; ++x) {
            vec2 tap = clamp(uv + vec2(x, y) * texelUv, lo, hi);
            sum += compareDepth(tap, layer, reference);
        }
    }
    return sum / float(PCF_SIZE * PCF_SIZE);
#else
    return compareDepth(clamp(uv, lo, hi), layer, reference);
#endif
}
