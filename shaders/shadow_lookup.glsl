// Shadow map lookup: world point -> light texture space, divide by w, compare with the stored
// depth plus tolerance. Single-frustum maps of all lights live in one texture array (one layer
// per light, a light's map in the layer's lower-left corner); point lights' cube maps in one
// cube-map array (cube_access.glsl). Each lookup (mapVisibility, cubeVisibility, faceVisibility,
// cascadeVisibility) takes a light record, the Receiver and the direction to the light and
// returns a ShadowSample; single maps' filters are in map_filters.glsl, cubes' in
// cube_lookup.glsl.
//
// Variants (injected #defines): FILTER_NONE | FILTER_HW2X2 | FILTER_PCF | FILTER_POISSON
// | FILTER_PCSS | FILTER_MOMENTS (moment_lookup.glsl), with PCF_SIZE (the kernel's width in
// texels) for PCF and POISSON,
// OUTSIDE_CLAMP (the textbooks' clamp-to-edge; default: outside the map is lit),
// COLOURED_SHADOWS (each lookup also returns its tint: transmittance_lookup.glsl).
#include "cube_access.glsl"
#include "texel_gather.glsl"
layout(binding = 1) uniform CUBE_SHADOW_MAPS uShadowCubes;

// Depth-aware tolerance: x steps of the stored depth's spacing; y, z that step for the 2D
// maps' and the cubes' formats (shadow::toleranceStep says which step, and why float
// maps take one ulp of 0.5 at every depth).
layout(location = 7) uniform vec3 uDepthAware;

float depthTolerance(LightRecord light, float step) {
    return light.biasConstant + uDepthAware.x * step;
}

#if defined(HAND_COMPARE)
// Fetch the stored depth (filtered by the sampler: --map-filter) and compare by hand: every
// lookup of colour formats (PACK_*: decode first), and --filter none on native depth (the
// course text's LINEAR lookup of a depth texture). LINEAR interpolates stored depth: fine
// for one channel, wrong for packed channels (why Shadow_highp of the WebGL Programming Guide,
// ch. 10, uses NEAREST).
#include "depth_packing.glsl"
layout(binding = 0) uniform sampler2DArray uShadowMaps;
float rawDepth(vec2 uv, float layer) {
    return unpackDepth(texture(uShadowMaps, vec3(uv, layer)));
}
float compareDepth(vec2 uv, float layer, float reference) {
    return reference > rawDepth(uv, layer) ? 0.0 : 1.0;
}
#else
// The comparison sampler (LEQUAL): compares each texel, then filters the results; LINEAR
// gives 2x2 bilinear PCF.
layout(binding = 0) uniform sampler2DArrayShadow uShadowMaps;
float compareDepth(vec2 uv, float layer, float reference) {
    return texture(uShadowMaps, vec4(uv, layer, reference));
}
#if defined(FILTER_PCSS) || defined(RECEIVER_PLANE) || defined(FLAT_GATHERS)
// PCSS's blocker search and the receiver plane's gathers read stored depth: the same maps
// through a NEAREST sampler without comparison. FLAT_GATHERS: a receiver-only object's PCF
// reads them the same way, with one reference for every texel (MainPass).
layout(binding = 2) uniform sampler2DArray uShadowDepths;
float rawDepth(vec2 uv, float layer) {
    return texture(uShadowDepths, vec3(uv, layer)).r;
}
#endif
#endif
#if defined(FILTER_PCSS)
layout(binding = 3) uniform CUBE_MAPS uShadowCubeDepths;
#endif
#if defined(FILTER_MOMENTS)
#include "moment_lookup.glsl"
#endif
#if defined(COLOURED_SHADOWS)
#include "transmittance_lookup.glsl"
#endif

// Under --shadow-rays all a ray answers every lookup (main.frag.glsl's LOOKUP_OF); with
// coloured shadows a lookup still runs for its tint, and returns it without filtering the map
// (RAYS_ONLY): the frame then draws no moments, and the main pass reads no depth map.
#if defined(SHADOW_RAYS) && !defined(SHADOW_RAYS_UNCERTAIN)
#define RAYS_ONLY
#endif

#include "shadow_sample.glsl"

// Interleaved gradient noise (Jimenez 2014): a value in [0, 1) per pixel, fixed in screen
// space, that neighbouring pixels spread evenly. Poisson taps turn by it, cascades hand over
// by it, contact shadows stagger their steps by it.
float interleavedGradientNoise() {
    return fract(52.9829189 * fract(dot(gl_FragCoord.xy, vec2(0.06711056, 0.00583715))));
}

// Texels a lookup reaches from its centre, plus the bilinear footprint's one.
#if defined(FILTER_PCF) || defined(FILTER_POISSON)
const float kFilterReach = float(PCF_SIZE / 2) + 1.0;
#elif defined(FILTER_PCSS)
const float kFilterReach = 1.5;  // the centre tap; wider taps add their own slope tolerance
#elif defined(FILTER_MOMENTS)
// The bilinear read reaches one texel, but the moments' bound takes a neighbour's depth
// as a caster over more of the footprint than a comparison would. It sizes the grazing
// planes' shift: with less, faces near edge-on to the sun (Suzanne's ear) stripe.
const float kFilterReach = 2.0;
#elif defined(FILTER_HW2X2)
const float kFilterReach = 1.0;
#else
const float kFilterReach = 0.5;
#endif
// Cubes have no moments: under the moment filters they take the default 3 x 3 PCF's reach.
#if defined(FILTER_MOMENTS)
const float kCubeReach = 2.0;
#else
const float kCubeReach = kFilterReach;
#endif

#if defined(FILTER_POISSON) || defined(FILTER_PCSS)
// 16 taps of a Poisson disc (unit radius, centred, minimum spacing 0.44 before scaling;
// generated by dart throwing for gnomon), turned per pixel by interleaved gradient noise
// (Jimenez 2014) so that the regular pattern's banding becomes fine noise.
const vec2 kPoissonDisc[16] = vec2[](
    vec2(-0.6806, -0.3015), vec2(0.2553, -0.3554), vec2(-0.9390, 0.3438), vec2(0.4399, 0.0588),
    vec2(-0.3478, 0.7287), vec2(-0.5014, 0.2749), vec2(0.0020, 0.0362), vec2(-0.2731, -0.4168),
    vec2(0.6862, -0.4297), vec2(0.2180, 0.4065), vec2(-0.5686, -0.7381), vec2(0.0612, 0.9267),
    vec2(-0.0715, -0.7930), vec2(0.7927, 0.3246), vec2(0.5396, 0.6871), vec2(0.3871, -0.7529));

mat2 poissonRotation() {
    float a = 6.2831853 * interleavedGradientNoise();
    return mat2(cos(a), sin(a), -sin(a), cos(a));
}
#endif

// Normal offset: move the lookup point off the surface along its normal. A planar receiver
// tilted by theta to the light changes stored depth by tan(theta) per texel of world size w;
// a filter reaching k texels (plus one for bilinear) needs the point (k + 1) w sin(theta) off
// the surface to stay lit everywhere it should.
// NORMAL_OFFSET: compiled in only when --normal-offset is not 0 (its default), so lookups do
// not pay for a zero shift.
vec3 normalOffset(LightRecord light, vec3 wsNormal, vec3 wsToLight, float texelWorld,
                  float reach) {
#ifdef NORMAL_OFFSET
    float nDotL = clamp(dot(wsNormal, wsToLight), 0.0, 1.0);
    float sinTheta = sqrt(1.0 - nDotL * nDotL);
    return wsNormal * (light.normalOffset * reach * texelWorld * sinTheta);
#else
    return vec3(0.0);
#endif
}

#include "receiver_plane.glsl"

#ifdef STAND_IN_LIFT
// Stand-in casters (--caster-detail) stray from the surfaces they stand for: where a concave
// stretch is simplified, a flat triangle cuts across it in front of the surface and shadows
// it. Lookups of a simplified object's own surface (Receiver.standInError: its stand-in's
// error; 0 on unsimplified receivers such as a ground) start that far towards the
// light, twice the simplifier's error: meshoptimizer measures it at the vertices it removes,
// and a triangle's centre sags further (up to 2.2 times on a sphere: see
// tests/unit/test_stand_in.cpp). At most six texels: a stand-in that strays further (a
// grid-simplified part of a model) would otherwise lift lookups past real casters.
const float kStandInLiftPerError = 2.0;
const float kStandInLiftTexels = 6.0;
float standInLift(float standInError, float texelWorld) {
    return min(kStandInLiftPerError * standInError, kStandInLiftTexels * texelWorld);
}
#endif

// The lookup point's move off the surface: the normal offset, the grazing planes' share
// `grazingShift` (receiver_plane.glsl) and the stand-in lift.
vec3 lookupOffset(LightRecord light, Receiver r, vec3 wsToLight, float texelWorld, float reach,
                  float grazingShift) {
    vec3 offset = normalOffset(light, r.normal, wsToLight, texelWorld, reach);
#if defined(RECEIVER_PLANE)
    offset += grazingPlaneOffset(r.planeNormal, wsToLight, texelWorld, reach, grazingShift);
#endif
#ifdef STAND_IN_LIFT
    offset += wsToLight * standInLift(r.standInError, texelWorld);
#endif
    return offset;
}

// The grazing planes' share of a shift (receiver_plane.glsl): none where the lookup applies the
// silhouette rule (single maps' gathered PCF and hw2x2, one-comparison lookups; cubes' every
// filter but pcss).
#if (defined(FILTER_PCF) && !defined(HAND_COMPARE)) || defined(FILTER_HW2X2) || \
    defined(FILTER_NONE)
const float kMapGrazingShift = 0.0;
#else
const float kMapGrazingShift = kGrazingShift;
#endif
#if defined(FILTER_PCSS)
const float kCubeGrazingShift = kGrazingShift;
#else
const float kCubeGrazingShift = 0.0;
#endif

#include "pcss_lookup.glsl"
#include "map_filters.glsl"
#include "cube_lookup.glsl"

// How far the rasteriser's stored depth and this code's reference for the same point may
// disagree through float rounding alone, in stored depth: each computes z / w from the map's
// matrix and the point's world coordinates, every product rounded to 2^-24 of itself, so the
// bound is 2^-24 times the sum of the products' sizes over w, twice (both sides). It passes
// one step of a float map where the terms outgrow what they leave (a spot or a cube face
// looking straight at the nearest caster, its near plane just before it: a box's top under
// a spot just above it), or where the world coordinates outgrow the map's depth range (a
// small model far from the origin).
// A perspective map also counts, as cube_lookup.glsl does, the point's own position: the
// rasteriser's and this pass's interpolated world positions each round to 2^-24 of their
// size, and the light's, folded into the matrix, as much again: four steps of the size, times
// how fast stored depth changes across the world there. Without it a face map whose near
// plane lies just before a roof far from the origin reads the roof as its own caster.
float mapRounding(LightRecord light, vec3 p, float w, float z) {
    mat4 m = light.textureFromWorld;
    vec4 a = abs(vec4(p, 1.0));
    float zTerms = dot(abs(vec4(m[0].z, m[1].z, m[2].z, m[3].z)), a);
    float wTerms = dot(abs(vec4(m[0].w, m[1].w, m[2].w, m[3].w)), a);
    float rw = 1.0 / abs(w);
    float products = exp2(-23.0) * (zTerms + abs(z) * wTerms) * rw;
    if (light.frame == kFrameOrthographic) return products;
    // |perWorld| (|p| + |light|) is at most sqrt(2 |perWorld|^2 (|p|^2 + |light|^2)): one
    // square root where three would be, which llvmpipe takes exactly and dearly.
    vec3 perWorldW = vec3(m[0].z, m[1].z, m[2].z) - z * vec3(m[0].w, m[1].w, m[2].w);
    float sizes = 2.0 * (dot(p, p) + dot(light.position, light.position));
    return products + exp2(-22.0) * sqrt(dot(perWorldW, perWorldW) * sizes) * rw;
}

// The receiver's plane in a single map, per unit of layer uv (flat without RECEIVER_PLANE).
// `clip` is the lookup point in map clip space, `coord` after the divide.
TapPlane mapPlane(LightRecord light, Receiver r, vec3 wsToLight, vec4 clip, vec3 coord,
                  float texelWorld, MapTap m) {
    TapPlane plane = kFlatPlane;
#if defined(RECEIVER_PLANE)
    plane.cosine = abs(dot(r.planeNormal, wsToLight));
    PlaneGradient gradient = receiverPlaneGradient(light, r.planeNormal, clip, coord, texelWorld,
                                                   m.texelUv / m.scale, wsToLight);
    plane.g = gradient.capped / m.scale;
    plane.full = gradient.full / m.scale;
    // `spread`: how far the plane moves between a tap's point and the centres of the texels a
    // bilinear or nearest read uses. The gathers, which compare at texel centres, keep it too:
    // without it single pixels darken along lines on tutorial-room's lit walls (why is not
    // known).
    plane.spread = 0.5 * m.texelUv * (abs(plane.g.x) + abs(plane.g.y));
#endif
    return plane;
}

#if defined(EDGE_MAPS) && defined(RECEIVER_PLANE)
// The casters' outlines beside the 2D maps (render/EdgeMaps.h): per texel the nearest line's
// point there, its 1 - depth in 24 bits above its offset from the texel's centre (0: none).
layout(binding = 17) uniform highp usampler2DArray uEdgeMaps;
// The share of a texel's step along the receiver's plane, and the depth, by which a line must
// lie nearer the light than the plane: what the plane's rounding and the offsets' eighths of
// a texel may stray.
const float kEdgeSlack = 0.1;
const float kEdgeDepthSlack = 4e-7;
// Does a caster's outline in the four texels around the receiver's own point `p` (map
// coordinates and depth, without the lookup's offsets) lie nearer the light than the
// receiver's plane at that line's point? Then something may shadow the receiver that the map,
// which holds only its texels' centres, does not show.
bool edgeAbovePlane(MapTap m, TapPlane plane, vec3 p) {
    vec2 uvP = m.origin + p.xy * m.scale;
    vec2 s = uvP / m.texelUv - 0.5;
    vec2 first = floor(m.origin / m.texelUv + 0.5);
    vec2 last = first + floor(m.scale / m.texelUv + 0.5) - 2.0;
    vec2 base = clamp(floor(s), first, last);
    // x (k, k+1), y (k+1, k+1), z (k+1, k), w (k, k) as (column, row), as GATHER_LAYER.
    uvec4 e = textureGather(uEdgeMaps, vec3((base + 1.0) * m.texelUv, m.layer));
    vec4 depth = 1.0 - vec4(e >> 8u) / 16777215.0;
    vec4 ox = vec4((e >> 4u) & 15u) / 8.0 - 1.0, oy = vec4(e & 15u) / 8.0 - 1.0;
    vec2 full = plane.full * m.texelUv;  // per texel
    vec2 o = base - s;                   // texel k's centre from the point, in texels
    vec4 along = dot(full, o) + full.x * (vec4(0.0, 1.0, 1.0, 0.0) + ox) +
                 full.y * (vec4(1.0, 1.0, 0.0, 0.0) + oy);
    float slack = kEdgeSlack * (abs(full.x) + abs(full.y)) + kEdgeDepthSlack;
    return any(lessThan(depth, p.z + along - slack));
}
#endif
// One single-frustum map: orthographic or perspective, a light's own or one cascade's.
ShadowSample mapVisibility(LightRecord light, Receiver r, vec3 wsToLight) {
    ShadowSample result = kLitSample;
    vec4 clip = light.textureFromWorld * vec4(r.position, 1.0);
    float texelWorld = light.texelWorldSize * (light.frame == kFrameOrthographic ? 1.0 : clip.w);
    result.texelWorld = texelWorld;
    vec3 offset = lookupOffset(light, r, wsToLight, texelWorld, kFilterReach, kMapGrazingShift);
    vec4 shadowCoord = clip + light.textureFromWorld * vec4(offset, 0.0);
    vec3 coord = shadowCoord.xyz / shadowCoord.w;

#ifdef OUTSIDE_CLAMP
    coord.xy = clamp(coord.xy, 0.0, 1.0);
#else
    if (shadowCoord.w <= 0.0 || any(lessThan(coord, vec3(0.0))) ||
        any(greaterThan(coord, vec3(1.0)))) {
        return result;
    }
#endif
#ifdef RECEIVER_ONLY
    float rounding = 0.0;  // the receiver is in no map: no rounding of its own to cover
#else
    float rounding = mapRounding(light, r.position + offset, shadowCoord.w, coord.z);
#endif
    MapTap m;
    m.layer = float(light.layer);
    m.reference = coord.z - depthTolerance(light, max(uDepthAware.y, rounding));
    m.texelUv = light.texelUv;
    m.origin = light.mapCorner;
    m.scale = light.uvScale;
    m.lo = m.origin + vec2(0.5 * m.texelUv);
    m.hi = m.origin + vec2(m.scale - 0.5 * m.texelUv);
    m.uv = m.origin + coord.xy * m.scale;
#if defined(COLOURED_SHADOWS)
    result.tint = mapTint(m.uv, m.layer, m.reference, m.lo, m.hi, m.texelUv);
#endif
#ifdef RAYS_ONLY
    return result;  // the tint alone: a ray gives the visibility
#endif
    TapPlane plane = mapPlane(light, r, wsToLight, shadowCoord, coord, texelWorld, m);
    result.visibility = mapFilter(light, r, wsToLight, m, plane, coord.z);
#if defined(EDGE_MAPS) && defined(RECEIVER_PLANE)
    if (result.visibility == 1.0 && clip.w > 0.0 && edgeAbovePlane(m, plane, clip.xyz / clip.w)) {
        result.visibility = 0.5;  // unsure: a ray decides (shadow_rays.glsl)
    }
#endif
    return result;
}

// Cascaded directional light: the first cascade whose far split lies beyond the
// fragment's view depth; within the last `blend` fraction of a cascade, the next one takes
// over pixel by pixel, a share t of them rising from 0 to 1 across the band (interleaved
// gradient noise against t), which hides the seam. Beyond the last cascade
// nothing is shadowed. The cascade is chosen first and looked up after: llvmpipe runs both
// sides of a branch and every pass of a loop, so a lookup in the selection loop would run
// for every cascade, and a mix of two lookups in the band would run both on every pixel.
ShadowSample cascadeVisibility(LightRecord light, Receiver r, vec3 wsToLight) {
    int first = light.firstSubRecord, count = light.cascadeCount;
    float blend = light.cascadeBlend;
    float vsDepth = r.viewDepth;
    int chosen = -1;
    float t = 0.0, previousSplit = 0.0;
    for (int k = 0; k < count; ++k) {
        float split = lights[first + k].farSplit;
        if (chosen < 0 && vsDepth <= split) {
            chosen = k;
            float bandStart = split - blend * (split - previousSplit);
            t = k + 1 < count && vsDepth > bandStart
                    ? (vsDepth - bandStart) / max(split - bandStart, 1e-6)
                    : 0.0;
        }
        previousSplit = split;
    }
    if (chosen < 0) return kLitSample;
    if (interleavedGradientNoise() < t) chosen += 1;  // t > 0 only where a next cascade is
    ShadowSample result = mapVisibility(lights[first + chosen], r, wsToLight);
    result.cascade = chosen;
    return result;
}

// A point light whose faces are maps of their own (kFrameFaces): the face the direction from
// the light leaves through, as a cube map picks it, then that face's map. A face without a map
// holds nothing the view drew: lit.
ShadowSample faceVisibility(LightRecord light, Receiver r, vec3 wsToLight) {
    vec3 d = r.position - light.position;
    vec3 a = abs(d);
    int face = a.x >= a.y && a.x >= a.z ? (d.x < 0.0 ? 1 : 0)
               : a.y >= a.z            ? (d.y < 0.0 ? 3 : 2)
                                       : (d.z < 0.0 ? 5 : 4);
    int slot = (light.faceSlots >> (3 * face)) & 7;
    ShadowSample result = mapVisibility(lights[light.firstSubRecord + min(slot, 5)], r, wsToLight);
    if (slot == 7) result.visibility = 1.0;
    return result;
}
