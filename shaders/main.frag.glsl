#version 450 core
// Main pass shading: ambient + Blinn-Phong diffuse and specular per light in world
// space (where the maps are looked up too), attenuation 1/(c0 + c1 d + c2 d^2) (area
// lights: d from the light's plane), spot cones, and per-light shadow visibility.
// A shadowed fragment keeps ambient only (SHADOWED_FACTOR undefined) or has its colour
// multiplied by uShadowFactor per shadowing light (SHADOWED_FACTOR, the WebGL book's 0.7).
// SHADOWS_OFF skips every lookup and leaves lighting unchanged.
// VISIBILITY_PASS (gnomon score): after the main pass, the visible surfaces are drawn again
// (depth test LEQUAL, no writes) and each light's visibility and the world size of the map
// texel it came from are stored per pixel, one image layer per light, and the object drawn.
// MATERIAL_PATH (textured, masked or blended materials): the base colour texture, masked
// fragments discarded below their cutoff, blended ones written with their alpha.
// FLOOR (gnomon bench's reference): the same lights and shadow lookups with one diffuse term
// per light and nothing else, the least a main pass with these shadows can do.
// CONTACT_SHADOWS: each shadowed light's visibility also marched through the view's depth
// (contact_shadows.glsl). COLOURED_SHADOWS: light through blended casters tinted
// (transmittance_lookup.glsl). DITHER_LINEAR / DITHER_SRGB: ordered dithering of the output.
// STAND_IN_LIFT: shadow passes draw stand-in casters; their objects' lookups start off the
// surface by the stand-in's error (shadow_lookup.glsl). UNROLLED_LIGHTS: the light loops
// written out per light (below). LIGHT_LISTS: the loops run over the lights of the pixel's
// screen tile (lights.glsl). SHADOW_RAYS: each shadowed lookup is a ray through the casters'
// BVH (shadow_rays.glsl); SHADOW_RAYS_MARK: maps' answers, alpha 0 and a ray job where rays
// must decide; SHADOW_RAYS_RESOLVE: the answers of those rays (render/RayMarks.h).
// RAYS_FROM_DRAWN: as main.vert.glsl defines it.
#if defined(SHADOW_RAYS) && !defined(GNOMON_GLES)
#define RAYS_FROM_DRAWN
#endif
#include "lights.glsl"
#include "shadow_lookup.glsl"
#include "contact_shadows.glsl"

in VertexOut {
    vec3 wsPosition;
    vec3 wsNormal;
    vec3 colour;
    flat vec4 material;
    flat float receives;
#ifdef MATERIAL_PATH
    vec2 uv;
    flat vec3 alpha;
#endif
#if defined(VISIBILITY_PASS) || defined(SHADOW_RAYS)
    flat float object;  // the scene object's index
#endif
#ifdef RAYS_FROM_DRAWN
    flat int firstTriangle;
#endif
#ifdef STAND_IN_LIFT
    flat float standInError;
#endif
} vIn;

#ifdef MATERIAL_PATH
layout(binding = 4) uniform sampler2D uBaseColourTexture;  // 1x1 white when untextured
#endif

layout(location = 3) uniform vec3 uAmbient;
layout(location = 4) uniform float uShadowFactor;
layout(location = 5) uniform vec3 uEye;  // the camera's world position

// Which lookup answers (LOOKUP_OF) and what follows it (RAYS_WHERE_UNSURE): under
// --shadow-rays all the ray alone, but after the map's lookup where coloured shadows need its
// tint; under uncertain the map's, then a ray where it is unsure.
#ifdef SHADOW_RAYS
#include "shadow_rays.glsl"
#endif
#if defined(SHADOW_RAYS) && !defined(SHADOW_RAYS_UNCERTAIN) && !defined(COLOURED_SHADOWS)
#define LOOKUP_OF(mapLookup) rayVisibility
#else
#define LOOKUP_OF(mapLookup) mapLookup
#endif
#ifndef RAY_JOB_START
#define RAY_JOB_START 0u  // main()'s `rayJob`, unused without an uncertain draw's ray jobs
#endif
#if defined(SHADOW_RAYS) && !defined(SHADOW_RAYS_UNCERTAIN) && defined(COLOURED_SHADOWS)
#define RAYS_WHERE_UNSURE(sample, light, record, r, toLight) rayAfterMap(sample, light, r, toLight)
#elif !defined(SHADOW_RAYS_UNCERTAIN)
#define RAYS_WHERE_UNSURE(sample, light, record, r, toLight) sample
#endif

layout(location = 0) out vec4 fragColour;

#ifdef HAS_CASCADES
// The view depth that picks a cascade, as a row applied to the world position: the depth
// along the camera the cascades were fitted to. That is the drawing camera's (the point's
// view-space depth) except when gnomon score draws one view with another frame's maps, to see
// what only the maps' motion changes.
layout(location = 11) uniform vec4 uCascadeDepth;
#define CASCADE_DEPTH dot(uCascadeDepth, vec4(vIn.wsPosition, 1.0))
#else
#define CASCADE_DEPTH 0.0
#endif

#if defined(VISIBILITY_PASS) && defined(GNOMON_GLES)
// OpenGL ES 3.0 (WebGL2) has no image stores: one light's record a pass, uRecordLight's, into
// colour targets beside the (unused) colour: visibility, texel world size and 1 + the object
// (0: none); with coloured shadows the tint.
#define VISIBILITY_OUTPUTS
layout(location = 15) uniform int uRecordLight;
layout(location = 1) out vec4 fVisibility;
#ifdef COLOURED_SHADOWS
layout(location = 2) out vec4 fTint;
#endif
#elif defined(VISIBILITY_PASS)
layout(early_fragment_tests) in;
layout(rgba32f, binding = 0) uniform writeonly image2DArray uVisibility;
// Per pixel: 1 + the scene object whose shadows are recorded here (0: none), so that the
// score compares them with the reference's on the same surface only.
layout(r32f, binding = 2) uniform writeonly image2D uObjectRecord;
#ifdef COLOURED_SHADOWS
layout(rgba32f, binding = 1) uniform writeonly image2DArray uTintRecord;  // tint per light
#endif
#endif

// Per fragment, shared by every light's shading.
struct Surface {
    bool unlit;
    bool receives;
    bool blended;  // alpha-blended: takes no tint (its own would speckle it)
    vec3 n, base, toEye;  // world space
};

// A loop's light kind when all its records have one (cubes: point lights; cascades:
// directional ones; single maps when this frame's share one, SINGLE_MAP_KIND), passed as a
// constant so the compiler drops the other kinds' code: llvmpipe runs every side of a branch
// on the record's type. The unshadowed loop mixes kinds.
const int kAnyKind = -1;
#ifdef SINGLE_MAP_KIND
const int kSingleMapKind = SINGLE_MAP_KIND;
#else
const int kSingleMapKind = kAnyKind;
#endif

// Direction to the light (world space) and its falloff at this fragment. CONSTANT_FALLOFF:
// no light this frame has a range or distance terms (the default attenuation, 1 0 0), so the
// falloff is 1 / c0 wherever the light reaches, and the distance terms and the range window,
// which llvmpipe computes on every pixel, are compiled out.
void lightAt(LightRecord light, int kind, out vec3 toLight, out float falloff) {
    int type = kind == kAnyKind ? light.type : kind;
    falloff = 1.0;
    vec3 c = light.attenuation;
    toLight = toLightFrom(light, type, vIn.wsPosition);
    if (type == kArea) {
        // Falloff with the distance from the light's plane (Hessian normal form: n.p + d,
        // with d = -n.p0 for the plane through the light).
        vec3 n = normalize(light.direction);
#ifdef CONSTANT_FALLOFF
        falloff = 1.0 / max(c.x, 1e-6);
#else
        float dist = abs(dot(n, vIn.wsPosition - light.position));
        falloff = 1.0 / max(c.x + c.y * dist + c.z * dist * dist, 1e-6);
#endif
    } else if (type != kDirectional) {
        float dist = length(light.position - vIn.wsPosition);
#ifdef CONSTANT_FALLOFF
        falloff = 1.0 / max(c.x, 1e-6);
#else
        falloff = 1.0 / max(c.x + c.y * dist + c.z * dist * dist, 1e-6);
        // glTF's range window (1 - (d/range)^4)^2, 1 without a range (w < 0).
        float r = light.range > 0.0 ? dist / light.range : 0.0;
        float window = clamp(1.0 - r * r * r * r, 0.0, 1.0);
        falloff *= window * window;
#endif
        if (type == kSpot) {
            float cosAngle = dot(-toLight, normalize(light.direction));
            falloff *= smoothstep(light.cosOuter, light.cosInner, cosAngle);
        }
    }
}

// Adds one light's Blinn-Phong term, as visible as `visibility` says (per channel: coloured
// shadows tint it).
void shade(LightRecord light, Surface s, vec3 toLight, float falloff, vec3 visibility,
           inout vec3 lit, inout vec3 factor) {
    if (s.unlit) {
        factor *= mix(vec3(uShadowFactor), vec3(1.0), visibility);
        return;
    }
    float nDotL = max(dot(s.n, toLight), 0.0);
    vec3 h = normalize(toLight + s.toEye);
#ifdef NO_SPECULAR
    // No lit object of the scene has a highlight: its pow, an exp2 of a log2 on llvmpipe, is
    // skipped for a term that is 0.
    float spec = 0.0;
#else
    float spec = nDotL > 0.0 ? vIn.material.x * pow(max(dot(s.n, h), 0.0), vIn.material.y) : 0.0;
#endif
    vec3 contribution = light.colour * falloff * (nDotL * s.base + spec);
#ifdef SHADOWED_FACTOR
    lit += contribution;
    factor *= mix(vec3(uShadowFactor), vec3(1.0), visibility);
#else
    lit += visibility * contribution;
#endif
}

#ifdef VISIBILITY_OUTPUTS
void recordVisibility(LightRecord light, ShadowSample shadow) {
    if (light.sceneLight != uRecordLight) return;
    fVisibility.xyw = vec3(shadow.visibility, shadow.texelWorld, shadow.traced ? 1.0 : 0.0);
#ifdef COLOURED_SHADOWS
    fTint = vec4(shadow.tint, 1.0);
#endif
}
#elif defined(VISIBILITY_PASS)
void recordVisibility(LightRecord light, ShadowSample shadow) {
    imageStore(uVisibility, ivec3(ivec2(gl_FragCoord.xy), light.sceneLight),
               vec4(shadow.visibility, shadow.texelWorld, 0.0, shadow.traced ? 1.0 : 0.0));
#ifdef COLOURED_SHADOWS
    imageStore(uTintRecord, ivec3(ivec2(gl_FragCoord.xy), light.sceneLight),
               vec4(shadow.tint, 1.0));
#endif
}
#endif

#ifdef COLOURED_SHADOWS
// A blended surface lies where its own transmittance is stored: tinted by itself wherever
// rounding puts it behind that depth, so blended surfaces take no tint (as Wicked Engine's
// transparent shadow maps do).
#define LIGHT_THROUGH(shadow) \
    (s.blended ? vec3(shadow.visibility) : shadow.visibility * shadow.tint)
#else
#define LIGHT_THROUGH(shadow) vec3(shadow.visibility)
#endif

// One loop per kind of light, over its range of the light order (main()'s `range`: ends of
// the unshadowed, single-map, cube and cascaded ranges; a screen tile's ranges hold only the
// lights that reach it). llvmpipe runs both sides of every branch
// it cannot prove uniform, so a single loop would pay for every kind's lookup on every light;
// separate loops run each light's own lookup only, and lights that are off are not in any.
//
// UNROLLED_LIGHTS: the program was built for its draw's count of each kind (MainPass), and
// each kind's loop is written out once per light by the macros MainPass defines
// (UNSHADOWED_LIGHTS, MAP_LIGHTS, CUBE_LIGHTS, CASCADED_LIGHTS: NAME(BODY, first, LOOKUP,
// KIND) is BODY(first + i, LOOKUP, KIND) for each of its i). llvmpipe keeps every value a
// loop changes in memory, per pixel, behind the loop's mask, and the compiler does not
// unroll a loop whose body holds a lookup (docs/results/performance.md, "Many lights").
// Otherwise each loop tests its end after a light, inside a test for none at all: llvmpipe
// leaves a loop only when, at the loop's end, no pixel of the block is left in it, so a loop
// that tested first ran its body once more than its lights, every pixel masked off.
#ifdef UNROLLED_LIGHTS
#define EACH_LIGHT(NAME, first, last, BODY, LOOKUP, KIND) NAME(BODY, first, LOOKUP, KIND)
#else
#define EACH_LIGHT(NAME, first, last, BODY, LOOKUP, KIND) \
    {                                                     \
        int k = first, end = last;                        \
        if (k < end) do {                                 \
                BODY(k, LOOKUP, KIND)                     \
                ++k;                                      \
            } while (k < end);                            \
    }
#endif

// Declares `record` (the light order's entry k), its `light`, and `toLight` and `falloff` at
// this fragment.
#define LIGHT_AT(k, KIND)                          \
    int record = lightRecord(k);                   \
    LightRecord light = lights[record];            \
    vec3 toLight;                                  \
    float falloff;                                 \
    lightAt(light, KIND, toLight, falloff);

// Record k of the light order, shaded with what its LOOKUP found for main()'s `receiver`.
#define SHADOWED_LIGHT(k, LOOKUP, KIND)                                             \
    {                                                                               \
        LIGHT_AT(k, KIND)                                                           \
        ShadowSample shadow = kLitSample;                                           \
        if (s.receives) {                                                           \
            shadow = RAYS_WHERE_UNSURE(LOOKUP(light, receiver, toLight), light,     \
                                       record, receiver, toLight);                  \
            CONTACT(light, shadow.visibility, toLight);                             \
            RECORD(light, shadow);                                                  \
            NOTE_CASCADE(shadow);                                                   \
            NOTE_TRACED(shadow);                                                    \
        }                                                                           \
        shade(light, s, toLight, falloff, LIGHT_THROUGH(shadow), lit, factor);      \
    }
#define SHADOWED_LOOP(NAME, first, last, LOOKUP, KIND) \
    EACH_LIGHT(NAME, first, last, SHADOWED_LIGHT, LOOKUP, KIND)
// Record k of the light order, unshadowed (the arguments after it are unused).
#define UNSHADOWED_LIGHT(k, LOOKUP, KIND)                              \
    {                                                                  \
        LIGHT_AT(k, kAnyKind)                                          \
        shade(light, s, toLight, falloff, vec3(1.0), lit, factor);     \
    }

#ifdef CONTACT_SHADOWS
// Point and spot lights: the march stops short of the light. main()'s `contactPlane` is the
// receiver's plane in the depth buffer.
#define CONTACT(light, visibility, toLight)                                                  \
    {                                                                                        \
        int kind = light.type;                                                               \
        float reach = kind == kDirectional || kind == kArea                                  \
                          ? 1e30                                                             \
                          : length(light.position - vIn.wsPosition);                         \
        visibility = contactShadow(contactPlane, vIn.wsPosition, toLight, reach, visibility); \
    }
#else
#define CONTACT(light, visibility, toLight)
#endif

#ifdef VISIBILITY_PASS
#define RECORD(light, shadow) recordVisibility(light, shadow)
#else
#define RECORD(light, shadow)
#endif

#ifdef DEBUG_CASCADES
// main()'s `cascade`: the last cascade a lookup read, for the debug tint.
#define NOTE_CASCADE(shadow) if (shadow.cascade >= 0) cascade = shadow.cascade
#else
#define NOTE_CASCADE(shadow)
#endif
#if defined(DEBUG_RAYS) || defined(SHADOW_RAYS_MARK)
// main()'s `traced`: a ray decided (SHADOW_RAYS_MARK: must decide) some light's visibility.
#define NOTE_TRACED(shadow) traced = traced || shadow.traced
#else
#define NOTE_TRACED(shadow)
#endif

// The records each main() loops over: the unshadowed ones (every light when shadows are off),
// then each kind of shadowed light this frame has, through LOOP(NAME, first, last, LOOKUP,
// KIND) (NAME: the kind's macro under UNROLLED_LIGHTS).
#ifdef SHADOWS_OFF
#define UNSHADOWED_END range.ends.w
#define SHADOWED_KINDS(LOOP)
#else
#define UNSHADOWED_END range.ends.x
// (SHADOW_RAYS: each kind's lookup is the ray's, LOOKUP_OF.)
#if defined(POINT_FACES)
#define CUBE_KIND(LOOP) \
    LOOP(CUBE_LIGHTS, range.ends.y, range.ends.z, LOOKUP_OF(faceVisibility), kPoint)
#elif defined(HAS_CUBES)
#define CUBE_KIND(LOOP) \
    LOOP(CUBE_LIGHTS, range.ends.y, range.ends.z, LOOKUP_OF(cubeVisibility), kPoint)
#else
#define CUBE_KIND(LOOP)
#endif
#ifdef HAS_CASCADES
#define CASCADE_KIND(LOOP)                                                               \
    LOOP(CASCADED_LIGHTS, range.ends.z, range.ends.w, LOOKUP_OF(cascadeVisibility), \
         kDirectional)
#else
#define CASCADE_KIND(LOOP)
#endif
#define SHADOWED_KINDS(LOOP)                                                                    \
    LOOP(MAP_LIGHTS, range.ends.x, range.ends.y, LOOKUP_OF(mapVisibility), kSingleMapKind) \
    CUBE_KIND(LOOP) CASCADE_KIND(LOOP)
#endif

// The receiver's plane for the lookups (Receiver.planeNormal; the rays' geometric normal).
// Before any discard: derivatives
// need the whole 2x2 quad. Helper invocations interpolate the same triangle, so the
// differences span its plane exactly.
vec3 receiverPlaneNormal() {
#if (defined(RECEIVER_PLANE) || defined(SHADOW_RAYS)) && !defined(SHADOWS_OFF)
    vec3 dx = dFdx(vIn.wsPosition), dy = dFdy(vIn.wsPosition);
    vec3 n = cross(dx, dy);
    // Degenerate where the sine of the angle between dx and dy is under 1e-6: compared
    // squared (no roots), scaled up so that tiny scenes do not underflow.
    float len2 = dot(n, n);
    return len2 * 1e12 > dot(dx, dx) * dot(dy, dy) ? n * inversesqrt(len2)
                                                   : normalize(vIn.wsNormal);
#else
    return vec3(0.0, 1.0, 0.0);  // unused
#endif
}

// The fragment as the lookups see it, with shading normal `n`.
Receiver receiverOf(vec3 n, vec3 planeNormal) {
    Receiver r;
    r.position = vIn.wsPosition;
    r.normal = n;
    r.planeNormal = planeNormal;
    r.viewDepth = CASCADE_DEPTH;
#ifdef STAND_IN_LIFT
    r.standInError = vIn.standInError;
#else
    r.standInError = 0.0;
#endif
    r.pixel = gl_FragCoord.xy;
#ifdef SHADOW_RAYS
    r.object = vIn.object;
#else
    r.object = -1.0;
#endif
#ifdef RAYS_FROM_DRAWN
    r.drawn = vIn.firstTriangle + gl_PrimitiveID;
#else
    r.drawn = -1;
#endif
    return r;
}

#ifdef FLOOR
vec3 floorDiffuse(LightRecord light, int kind, vec3 n, out vec3 toLight) {
    int type = kind == kAnyKind ? light.type : kind;
    toLight = toLightFrom(light, type, vIn.wsPosition);
    return light.colour * max(dot(n, toLight), 0.0);
}

#define FLOOR_LIGHT(k, LOOKUP, KIND)                                                      \
    {                                                                                     \
        vec3 toLight;                                                                     \
        int record = lightRecord(k);                                                      \
        LightRecord light = lights[record];                                               \
        vec3 diffuse = floorDiffuse(light, KIND, n, toLight);                             \
        lit += diffuse * RAYS_WHERE_UNSURE(LOOKUP(light, receiver, toLight), light, record, \
                                           receiver, toLight)                             \
                             .visibility;                                                 \
    }
#define FLOOR_LOOP(NAME, first, last, LOOKUP, KIND) \
    EACH_LIGHT(NAME, first, last, FLOOR_LIGHT, LOOKUP, KIND)
#define FLOOR_UNSHADOWED(k, LOOKUP, KIND) \
    lit += floorDiffuse(lights[lightRecord(k)], kAnyKind, n, unused);

void main() {
    vec3 planeNormal = receiverPlaneNormal();
    vec3 n = normalize(vIn.wsNormal);
    Receiver receiver = receiverOf(n, planeNormal);
    vec3 lit = uAmbient;
    vec3 unused;
    uint rayJob = RAY_JOB_START;
    LightRange range = lightRange();
    EACH_LIGHT(UNSHADOWED_LIGHTS, range.first, UNSHADOWED_END, FLOOR_UNSHADOWED, _, _)
    SHADOWED_KINDS(FLOOR_LOOP)
    fragColour = vec4(lit * vIn.colour, 1.0);
}
#else
#include "dither.glsl"

void main() {
    vec3 planeNormal = receiverPlaneNormal();
#ifdef CONTACT_SHADOWS
    vec3 contactPlane = findContactPlane();
#endif
    Surface s;
    s.unlit = vIn.material.z > 0.5;
    s.receives = vIn.receives > 0.5;
    s.blended = false;
    s.n = normalize(vIn.wsNormal);
    if (vIn.material.w > 0.5 && !gl_FrontFacing) s.n = -s.n;  // double-sided: light the side we see
    s.base = vIn.colour;
    float alpha = 1.0;
#ifdef MATERIAL_PATH
    // The base colour texture (sRGB, decoded by the sampler) and the material's alpha rule.
    vec4 texel = texture(uBaseColourTexture, vIn.uv);
    s.base *= texel.rgb;
    alpha = vIn.alpha.x * texel.a;
    if (vIn.alpha.y == 1.0 && alpha < vIn.alpha.z) discard;
    if (vIn.alpha.y != 2.0) alpha = 1.0;
    s.blended = vIn.alpha.y == 2.0;
#endif
#ifdef VISIBILITY_OUTPUTS
    fVisibility = vec4(1.0, 0.0, s.receives ? vIn.object + 1.0 : 0.0, 0.0);
#ifdef COLOURED_SHADOWS
    fTint = vec4(1.0);
#endif
#elif defined(VISIBILITY_PASS)
    if (s.receives) imageStore(uObjectRecord, ivec2(gl_FragCoord.xy), vec4(vIn.object + 1.0));
#endif
    s.toEye = normalize(uEye - vIn.wsPosition);
    Receiver receiver = receiverOf(s.n, planeNormal);
    int cascade = -1;  // DEBUG_CASCADES: the last cascade a lookup read
    bool traced = false;  // DEBUG_RAYS: a ray decided some light's visibility
    uint rayJob = RAY_JOB_START;  // the pixel's ray job (shadow_rays.glsl)

    vec3 lit = s.unlit ? s.base : uAmbient * s.base;
    vec3 factor = vec3(1.0);
    LightRange range = lightRange();
    EACH_LIGHT(UNSHADOWED_LIGHTS, range.first, UNSHADOWED_END, UNSHADOWED_LIGHT, _, _)
    SHADOWED_KINDS(SHADOWED_LOOP)
    vec3 colour = lit * factor;
#ifdef DEBUG_CASCADES
    const vec3 kTints[4] = vec3[](vec3(1, 0.3, 0.3), vec3(0.3, 1, 0.3), vec3(0.3, 0.5, 1),
                                  vec3(1, 1, 0.3));
    if (cascade >= 0) colour = mix(colour, kTints[cascade], 0.35);
#endif
#ifdef SHADOW_RAYS_MARK
    if (traced) alpha = 0.0;  // drawn again with its rays (render/RayMarks.h)
    WRITE_RAY_JOB(receiver, rayJob)
#elif defined(DEBUG_RAYS)
    if (traced) colour = mix(colour, vec3(1.0, 0.0, 1.0), 0.6);
#endif
    fragColour = vec4(dither(colour), alpha);
}
#endif
