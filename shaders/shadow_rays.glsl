// Shadow rays: a shadowed light's visibility from one ray through a BVH of the scene's casters
// (bvh_trace.glsl, built by render::RayScene) instead of its map. The hard answer of the
// light's centre, as the reference traces it (truth::ShadowRays); masked and blended casters
// block it where their texels do (bvhTexelBlocks, render/RayMasks.h). --shadow-rays all:
// every lookup is a ray (LOOKUP_OF in main.frag.glsl), soft filters get the hard answer too.
// SHADOW_RAYS_UNCERTAIN (--shadow-rays uncertain): the map's answer where it is sure, a ray's
// where it is not (raysWhereUnsure). Included by main.frag.glsl after uEye.
#include "bvh_trace.glsl"

// Below this cosine between the surface's plane and the way to the light, the surface faces
// away from the light: in its own shadow (the reference's edge-on bound).
const float kRayEdgeOn = 1e-3;
// Shading and plane normals closer than this (sine of their angle): a flat face.
const float kFlatFaceSine = 3e-4;
// The margin of rayLead, as shares of the scene's radius (every object's, as the reference
// measures it: uRayScale) and of the position's size: the reference's (truth::ShadowRays::lead)
// where the ray leaves its own triangle (rayStartBegin), twice it elsewhere, for an interpolated
// position rounds more than one taken from its triangle's corners. Longer, a lead skips the
// caster a few millimetres above a face all but edge-on to the light (glmark2's cat); shorter,
// it meets its own surface's neighbours where the reference does not (the cat on a ground ten
// times its size, whose radius sets the reference's margin).
layout(location = 16) uniform float uRayScale;
const float kRayMarginOfScale = 2e-6;
const float kRayMarginOfPosition = 1e-6;
// Within this cosine of edge-on, the ray leaves from the surface's own triangle, as the
// reference's does (truth::Reference): its normal from the corners, which puts a face all but
// edge-on to the light on the reference's side of kRayEdgeOn (interpolated and derived normals
// round by 1e-5..1e-4: a wall 0.06 degrees from the sun's plane in Sponza's atrium fell either
// side), the point moved onto its plane, and the reference's margin.
const float kOwnTriangleCosine = 0.03;

// Where a shadow ray leaves: the point, its normal on the side the camera sees, the margin
// its lead follows, the triangle it leaves (-1: not known) and whether that is the one the
// main pass drew.
struct RayStart {
    vec3 point, normal;
    float margin;
    int triangle;
    bool drawn;
};

// The reference's margin at `p`.
float rayMargin(vec3 p) {
    return kRayMarginOfScale * uRayScale + kRayMarginOfPosition * length(p);
}

// The camera as the reference casts each pixel's ray (render::PixelRayCamera): its eye and
// axes, its lens (perspective: tan(fovy / 2), aspect; orthographic: right - left, right +
// left, top - bottom, top + bottom), and the frame's width, height, a pixel's size at depth 1
// and whether orthographic. The reference's own operations in its order (truth::Reference),
// for a pixel's centre can lie 1e-5 pixels from an edge.
layout(location = 18) uniform vec3 uCameraEye;
layout(location = 19) uniform vec3 uCameraRight;
layout(location = 20) uniform vec3 uCameraUp;
layout(location = 21) uniform vec3 uCameraAhead;
layout(location = 22) uniform vec4 uCameraLens;
layout(location = 23) uniform vec4 uCameraFrame;

// The ray through the centre of window pixel `pixel` (GL's rows, bottom first).
void pixelRay(vec2 pixel, out vec3 from, out vec3 dir) {
    float nx = pixel.x / uCameraFrame.x * 2.0 - 1.0;
    float ny = 1.0 - (uCameraFrame.y - pixel.y) / uCameraFrame.y * 2.0;
    vec4 l = uCameraLens;
    if (uCameraFrame.w > 0.5) {
        from = uCameraEye + uCameraRight * (0.5 * (nx * l.x + l.y)) +
               uCameraUp * (0.5 * (ny * l.z + l.w));
        dir = uCameraAhead;
    } else {
        vec3 d = uCameraAhead + uCameraRight * (nx * l.x * l.y) + uCameraUp * (ny * l.x);
        from = uCameraEye;
        dir = d / length(d);
    }
}

// The hierarchy's triangle the main pass drew as triangle `drawn` (render/DrawnTriangles.h),
// from render::RayScene's start table (four to a texel, as floats); -1 where it is none (no
// caster, not known: WebGL2's draws name none, main.frag.glsl's RAYS_FROM_DRAWN).
#ifndef GNOMON_GLES
layout(binding = 16) uniform highp sampler2D uRayStarts;
#endif
int rayStartTriangle(int drawn) {
#ifdef GNOMON_GLES
    return -1;
#else
    if (drawn < 0 || textureSize(uRayStarts, 0).x < 2) return -1;
    vec4 four = bvhTexel(uRayStarts, drawn >> 2);
    int c = drawn & 3;
    return int(c == 0 ? four.x : c == 1 ? four.y : c == 2 ? four.z : four.w);
#endif
}

// The world size of a pixel at `p`.
float pixelWorld(vec3 p) {
    return uCameraFrame.z *
           (uCameraFrame.w > 0.5 ? 1.0 : max(dot(p - uCameraEye, uCameraAhead), 0.0));
}

// The start on triangle `tri` where the pixel's own ray meets it, as the reference's start
// (its point from the corners, its plane's normal); false where the ray passes beside it.
bool rayStartOn(inout RayStart s, vec2 pixel, int tri) {
    vec3 from, view, bary;
    pixelRay(pixel, from, view);
    vec3 a = bvhTexel(uBvhTriangles, 3 * tri).xyz, b = bvhTexel(uBvhTriangles, 3 * tri + 1).xyz;
    vec3 c = bvhTexel(uBvhTriangles, 3 * tri + 2).xyz;
    vec3 g = cross(b - a, c - a);
    if (bvhHitTriangle(bvhFrame(from, view), a, b, c, 0.0, 3.4e38, bary) < 0.0 ||
        !(length(g) > 0.0))
        return false;
    s.point = bary.x * a + bary.y * b + bary.z * c;
    s.normal = normalize(g);
    s.margin = rayMargin(s.point);
    s.triangle = tri;
    s.drawn = true;
    return true;
}

// The normal a ray leaves by. The plane's normal from the position's derivatives rounds by
// about 1e-4 radians; a flat face's shading normal is its own exactly, which keeps a face all
// but edge-on to the light (a wall under a sun at a right angle to it) on one side of
// kRayEdgeOn throughout.
vec3 rayNormal(Receiver r) {
    return length(cross(r.planeNormal, r.normal)) < kFlatFaceSine ? r.normal : r.planeNormal;
}

// One light's rays at a receiver, as steps each tracing at most once: the search for the
// start's triangle (kRayFindStart), the shadow ray (kRayShadow) and, where rayAgain asks, the
// start on the pixel's own ray (kRayFindOwn) and a shadow ray from there (kRayShadowOwn). The
// caller's one loop traces every lane's next ray together. llvmpipe runs a shader as vectors of
// pixels and a branch as a mask: each traversal written out runs its first steps for every
// pixel whether it traces or not, so one trace in a loop costs less than four in a row.
const int kRayBegin = 0;
const int kRayFindStart = 1;
const int kRayShadow = 2;
const int kRayFindOwn = 3;
const int kRayShadowOwn = 4;
const int kRayDone = 5;

struct RayTrip {
    int step;  // the step whose trace runs next (kRayBegin: none yet; kRayDone: no more)
    RayStart start;
    float object;  // the object the start lies on (the drawn triangle's, where known)
    bool pixel;    // the start's search follows the pixel's own ray
    float t;       // the shadow ray's first caster (0: the start faces away; -1: none)
    vec3 from, dir;  // the next trace: its origin and direction, its stretch (t0, t1], whether
    float t0, t1;    // any caster ends it (a shadow ray) and the triangle it passes by
    bool anyCaster;
    int skip;
};

// The start's search (the start at `r` with normal `n`): false where it needs no trace. On the
// triangle of the hierarchy that the pixel's ray meets, where there is one (not under a receiver
// that casts no shadow). Where the main pass says which it drew (RAYS_FROM_DRAWN), there, unless
// the pixel's ray passes beside it: the raster rounds a triangle's corners to 1/256 pixel, so a
// pixel whose centre lies that close to an edge can show the triangle beyond it, whatever lies
// behind; then the ray's first triangle on the object the raster drew. With `ofPixel`
// (rayAgain), the first triangle of that object a short stretch of the pixel's own ray meets
// around the point: the depth test rounds too, and where two surfaces cross it may draw the
// farther. Where the drawn one is not known and near edge-on to `wsToLight`, the one the
// camera's ray through the point meets.
bool rayStartBegin(inout RayTrip q, Receiver r, vec3 wsToLight, bool ofPixel) {
    vec3 n = rayNormal(r);
    q.start = RayStart(r.position, n, 2.0 * rayMargin(r.position), -1, false);
    int own = rayStartTriangle(r.drawn);
    q.object = own >= 0 ? bvhTexel(uBvhTriangles, 3 * own).w : r.object;
    bool onOwn = !ofPixel && own >= 0 && rayStartOn(q.start, r.pixel, own);
    bool whole = !ofPixel && own >= 0 && !onOwn;  // the pixel's ray passes beside it
    q.pixel = ofPixel || whole;
    q.anyCaster = false;
    q.skip = -1;
    if (onOwn || !(q.pixel || abs(dot(n, wsToLight)) < kOwnTriangleCosine)) return false;
    float h = 64.0 * q.start.margin;
    q.t0 = 0.0;
    q.t1 = 2.0 * h;
    if (q.pixel) {
        pixelRay(r.pixel, q.from, q.dir);
        float along = dot(r.position - q.from, q.dir);
        q.t0 = whole ? 0.0 : max(along - h, 0.0);
        q.t1 = whole ? 3.4e38 : along + h;
    } else {
        q.dir = normalize(r.position - uEye);
        q.from = q.start.point - h * q.dir;
    }
    return true;
}

// The start once its search found `t` on triangle `tri` (t < 0: none, or no search): on that
// triangle's plane with its normal, turned to the side the camera sees.
void rayStartEnd(inout RayTrip q, vec3 position, float t, int tri) {
    if (t >= 0.0 && (!q.pixel || int(bvhTexel(uBvhTriangles, 3 * tri).w) == int(q.object))) {
        vec3 a = bvhTexel(uBvhTriangles, 3 * tri).xyz;
        vec3 g = cross(bvhTexel(uBvhTriangles, 3 * tri + 1).xyz - a,
                       bvhTexel(uBvhTriangles, 3 * tri + 2).xyz - a);
        if (length(g) > 0.0) {
            q.start.normal = normalize(g);
            if (q.pixel) q.start.point = q.from + t * q.dir;
            q.start.point -= dot(q.start.point - a, q.start.normal) * q.start.normal;
            q.start.triangle = tri;
            q.start.margin = rayMargin(q.start.point);
        }
    }
    if (dot(q.start.normal, uEye - position) < 0.0) q.start.normal = -q.start.normal;
}

// How far along the ray its start is skipped: the stretch within the margin of the surface's
// plane, for the rounding of the position. The ray keeps to the line through the point, as the
// reference's does: a start pushed off along the normal would move the whole ray sideways, past
// the edges of the casters near it (leaks along every shadow's edge under a low light).
float rayLead(RayStart s, vec3 dir) {
    return s.margin / max(dot(s.normal, dir), kRayEdgeOn);
}

// The shadow ray from q.start towards `light`: false where it needs no trace, q.t then its
// answer (0: the start faces away; -1: the light lies within the margin). Directional lights
// reach from infinitely far; area lights, parallel as they light, from their plane; spot and
// point lights from their position. The ray passes its own start's triangle: not a caster of
// its own point.
bool rayShadowBegin(inout RayTrip q, LightRecord light, vec3 wsToLight) {
    q.dir = wsToLight;
    q.t = 0.0;
    if (dot(q.start.normal, wsToLight) <= kRayEdgeOn) return false;
    float reach = 1e30;
    if (light.type == kArea) {
        reach = dot(q.start.point - light.position, normalize(light.direction));
    } else if (light.type != kDirectional) {
        vec3 d = light.position - q.start.point;
        reach = length(d);
        q.dir = d / reach;
    }
    q.from = q.start.point;
    q.t0 = rayLead(q.start, q.dir);
    q.t1 = reach;
    q.anyCaster = true;
    q.skip = q.start.triangle;
    q.t = -1.0;
    return reach > q.t0;
}

// After the first shadow ray: where the start faces away from the light, or a caster lies
// within 1/64 pixel of its plane, the raster's point may not lie on the triangle the pixel's
// own ray meets: its centre within the raster's rounding of an edge (the face beyond it
// drawn), past the edge behind a neighbour (a concave crease), or behind a surface crossing it
// that the depth test rounded away. The pixel's own ray's triangle decides.
bool rayAgain(RayTrip q) {
    return (q.start.triangle < 0 || q.start.drawn) && q.t >= 0.0 &&
           (q.t == 0.0 || q.t * dot(q.start.normal, q.dir) < pixelWorld(q.start.point) / 64.0);
}

// The steps after the one whose trace found `t` (on triangle `hit`) that need no trace, up to
// the next that does (q.step) or the end (kRayDone, q.t the answer). kRayBegin: the first.
void rayTripStep(inout RayTrip q, Receiver r, LightRecord light, vec3 wsToLight, float t,
                 int hit) {
    if (q.step == kRayBegin) {
        q.t = -1.0;
        q.step = kRayFindStart;
        if (rayStartBegin(q, r, wsToLight, false)) return;
        t = -1.0;
    }
    if (q.step == kRayFindStart) {
        rayStartEnd(q, r.position, t, hit);
        q.step = kRayShadow;
        if (rayShadowBegin(q, light, wsToLight)) return;
        t = q.t;
    }
    if (q.step == kRayShadow) {
        q.t = t;
        q.step = kRayDone;
        if (!rayAgain(q)) return;
        q.step = kRayFindOwn;
        if (rayStartBegin(q, r, wsToLight, true)) return;
        t = -1.0;
    }
    if (q.step == kRayFindOwn) {
        rayStartEnd(q, r.position, t, hit);
        q.step = kRayDone;
        if (q.start.triangle < 0) return;  // none found: the first ray's answer stands
        q.step = kRayShadowOwn;
        if (rayShadowBegin(q, light, wsToLight)) return;
        t = q.t;
    }
    if (q.step == kRayShadowOwn) {
        q.t = t;
        q.step = kRayDone;
    }
}

// A trip before its first step, every field set.
RayTrip rayTrip() {
    return RayTrip(kRayBegin, RayStart(vec3(0.0), vec3(0.0), 0.0, -1, false), 0.0, false, -1.0,
                   vec3(0.0), vec3(0.0, 0.0, 1.0), 0.0, 0.0, false, -1);
}

// The light's visibility at `r` along `wsToLight` (lightAt's direction): 0 when a caster lies
// between.
ShadowSample rayVisibility(LightRecord light, Receiver r, vec3 wsToLight) {
    RayTrip q = rayTrip();
    rayTripStep(q, r, light, wsToLight, -1.0, -1);
    while (q.step != kRayDone) {
        int hit;
        float t = bvhTrace(q.from, q.dir, q.t0, q.t1, q.anyCaster, q.skip, hit);
        rayTripStep(q, r, light, wsToLight, t, hit);
    }
    ShadowSample result = kLitSample;
    result.traced = true;
    result.visibility = q.t >= 0.0 ? 0.0 : 1.0;
    return result;
}

// The map's sample with the ray's visibility: its tint (COLOURED_SHADOWS) and texel kept.
ShadowSample rayAfterMap(ShadowSample s, LightRecord light, Receiver r, vec3 wsToLight) {
    s.visibility = rayVisibility(light, r, wsToLight).visibility;
    s.traced = true;
    return s;
}

// A pixel's ray job (render/RayMarks.h): the records of up to two lights to trace, 15 bits
// each (kNoRayRecord: none), in the low and high halves of a word; the rays' pass sets the top
// bit of a half when its light is visible.
const uint kRayRecordBits = 0x7fffu;
const uint kNoRayRecord = 0x7fffu;
const uint kRayLitBit = 0x8000u;
const uint kNoRayRecords = 0x7fff7fffu;

// A ray job in one texel: the point as its distance along the pixel's own ray, the lights'
// records, rayNormal in octahedral form at 16 bits a coordinate (Cigolle et al., "A Survey of
// Efficient Representations for Independent Unit Vectors", JCGT 2014) and the surface
// (rayJobSurface).
vec2 rayOctahedral(vec3 n) {
    vec2 p = n.xy / (abs(n.x) + abs(n.y) + abs(n.z));
    vec2 s = vec2(p.x >= 0.0 ? 1.0 : -1.0, p.y >= 0.0 ? 1.0 : -1.0);
    return n.z >= 0.0 ? p : (1.0 - abs(p.yx)) * s;
}
vec3 rayFromOctahedral(vec2 e) {
    vec3 n = vec3(e, 1.0 - abs(e.x) - abs(e.y));
    vec2 s = vec2(n.x >= 0.0 ? 1.0 : -1.0, n.y >= 0.0 ? 1.0 : -1.0);
    if (n.z < 0.0) n.xy = (1.0 - abs(n.yx)) * s;
    return normalize(n);
}
// The job's point from its distance along the pixel's ray (pixelRay).
vec3 rayJobPoint(vec2 pixel, float along) {
    vec3 from, dir;
    pixelRay(pixel, from, dir);
    return from + along * dir;
}

#ifdef SHADOW_RAYS_UNCERTAIN
// Hybrid shadows (J. Story, "Hybrid Ray-Traced Shadows", GDC 2015): the map is unsure where its
// filter's footprint holds both lit and shadowed texels (a shadow's edge, a caster thinner than
// the footprint) and where it finds lit a receiver whose plane lies within kUnsureCosine of
// edge-on to the light, where a caster under a fraction of a texel above the receiver (the
// tolerance band) hides in the receiver's own depth and the silhouette rule guesses. There one
// ray decides. (Found shadowed there, the map is as sure as elsewhere: its grazing misses are
// leaks.) The lookups report a footprint with a texel lit only within the tolerance band as
// part lit too (map_filters.glsl's exactReference).
// SHADOW_RAYS_MARK (the first of render/RayMarks.h's draws): the map's answer, `traced` where
// a ray must decide, and the pixel's ray job for the rays' pass (ray_trace.frag.glsl).
// SHADOW_RAYS_RESOLVE (the second): that pass's answers for the lights of the pixel's job, a
// ray here for any other (RAY_JOB_OVERFLOW: the draw has more than two shadowed lights).
const float kUnsureCosine = 0.12;
// main()'s `rayJob`: under SHADOW_RAYS_MARK the records of the lights to trace
// (kNoRayRecords: none yet), under SHADOW_RAYS_RESOLVE their answers once read (kRayJobUnread:
// not yet; no answer has the lit bit of an empty half).
const uint kRayJobUnread = 0xffffffffu;
#ifdef SHADOW_RAYS_MARK
#define RAY_JOB_START kNoRayRecords
layout(location = 1) out uvec4 fRayJob;  // rayJobAlong's bits, the records, the normal, surface
void noteRayJob(inout uint job, int record) {
    if ((job & kRayRecordBits) == kNoRayRecord) {
        job = (job & ~kRayRecordBits) | uint(record);
    } else if ((job >> 16) == kNoRayRecord) {
        job = (job & kRayRecordBits) | (uint(record) << 16);
    }
}
// The job's surface: the triangle drawn where known, else the object with the top bit set.
uint rayJobSurface(Receiver r) {
    return r.drawn >= 0 ? uint(r.drawn) : (0x80000000u | uint(r.object));
}
// How far along the pixel's own ray its point lies.
float rayJobAlong(Receiver r) {
    vec3 from, dir;
    pixelRay(r.pixel, from, dir);
    return dot(r.position - from, dir);
}
#define WRITE_RAY_JOB(r, job)                                                      \
    fRayJob = uvec4(floatBitsToUint(rayJobAlong(r)), job,                          \
                    packSnorm2x16(rayOctahedral(rayNormal(r))), rayJobSurface(r));
#elif defined(SHADOW_RAYS_RESOLVE)
#define RAY_JOB_START kRayJobUnread
#ifdef GNOMON_GLES
#include "ray_pyramid.glsl"
#define RAY_ANSWER_OF(p) texelFetch(uRayPyramid, rayAnswerTexel(rayJobOf(p)), 0).r
#else
layout(binding = 14) uniform highp usampler2D uRayAnswers;  // per pixel (ray_trace.frag.glsl)
#define RAY_ANSWER_OF(p) texelFetch(uRayAnswers, p, 0).r
#endif
// 1 or 0 when this pixel's job traced `record`'s light (visible or not); -1 when it did not.
int rayJobAnswer(inout uint job, int record) {
    if (job == kRayJobUnread) job = RAY_ANSWER_OF(ivec2(gl_FragCoord.xy));
    if ((job & kRayRecordBits) == uint(record)) return int((job & kRayLitBit) != 0u);
    uint high = job >> 16;
    if ((high & kRayRecordBits) == uint(record)) return int((high & kRayLitBit) != 0u);
    return -1;
}
#endif
ShadowSample raysWhereUnsure(ShadowSample s, LightRecord light, int record, Receiver r,
                             vec3 wsToLight, inout uint job) {
    bool partial = s.visibility > 0.0 && s.visibility < 1.0;
    bool grazing = abs(dot(r.planeNormal, wsToLight)) < kUnsureCosine && s.visibility == 1.0;
#ifdef SHADOW_RAYS_MARK
    s.traced = partial || grazing;
    if (s.traced) noteRayJob(job, record);
#elif defined(SHADOW_RAYS_RESOLVE)
    if (partial || grazing) {
        int answer = rayJobAnswer(job, record);
        if (answer >= 0) {
            s.visibility = float(answer);
            s.traced = true;
        }
#ifdef RAY_JOB_OVERFLOW
        if (answer < 0) s = rayAfterMap(s, light, r, wsToLight);
#endif
    }
#else
    if (partial || grazing) s = rayAfterMap(s, light, r, wsToLight);  // WebGL: no ?: on structs
#endif
    return s;
}
// (main()'s `rayJob` carries the pixel's ray job from light to light.)
#define RAYS_WHERE_UNSURE(sample, light, record, r, toLight) \
    raysWhereUnsure(sample, light, record, r, toLight, rayJob)
#endif
