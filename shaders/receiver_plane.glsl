// Receiver-plane depth for the shadow lookups of shadow_lookup.glsl (included there, after
// LightRecord): the receiver's plane, its depth gradient in a map, and the per-tap depth offsets
// along it.

// The receiver's plane is Receiver.planeNormal (shadow_lookup.glsl): the triangle's own plane,
// from the screen-space derivatives of the fragment's position (the interpolated normal of a
// smooth mesh is not it). Its sign does not matter.

// Receiver-plane depth (Isidoro, "Shadow Mapping: GPU-based Tips and Techniques", GDC
// 2006; Dou et al., "Adaptive Depth Bias for Shadow Maps", I3D 2014). A plane stays a plane
// through the light's projection, so the depth it stores is affine in map coordinates:
// depth(t) = coord.z + dot(gradient, t - coord.xy). Comparing each texel against the depth
// its own centre has on the receiver's plane removes the slope from the tolerance: what is
// left covers rounding. `clip` is the lookup point in map clip space, `coord`
// after the divide; two tangent steps of about a texel give the gradient per map unit.
// The steepest receiver plane followed, as depth per distance across the light (tan of
// the angle between the surface's normal and the light): steeper planes are followed only
// this far, and the depth pass's slope-scaled offset covers the rest. Measured on Sponza's
// arches and the built-in scenes: 1-2 leak least; 4 and more let grazing planes reach past
// real occluders within the filter's footprint.
const float kPlaneMaxSlope = 2.0;
// ...except on the side where the plane comes towards the light, followed up to this many
// times further. There a surface turned almost edge-on to the light meets its neighbours
// across convex edges (a cube's lit top beside a grazing side): they lie behind the side's
// plane, so the full plane finds them lit, while the capped one, too deep there, finds
// them in front and shadows the whole side in stripes (SimpleInstancing with a side sun:
// 0.14 % of the view falsely shadowed away from edges with the cap alone, 0.04 % with 6x).
// Larger factors fix that further but leak more along real occluders' edges (Sponza's
// atrium, ToyCar); scripts/quality-real.py measures both.
const float kPlaneMaxApproach = 6.0;
// Point lights' cube faces follow the approach side less far: with 6x their taps, which
// lie on the face's plane rather than on the receiver's, reached past the stem of the Lamp's
// five point lights (LightsPunctualLamp, lamp-stem: 0.205 % misclassified against 0.174 %
// with 3x). Without any, a depth-pass offset of 0.7 left short lines along the columns of
// Sponza under a point light falsely shadowed (sponza-arcade-point: 0.039 % of the view
// away from edges, 0.003 % with 3x).
const float kCubeMaxApproach = 3.0;
// A plane within a thousandth (0.06 degrees) of edge-on to the light covers no texel of the
// map: the texels its lookups read hold the neighbours around it, and no gradient can be
// found from it (receiverPlaneGradient gives none). Whether such a plane is lit hangs on its
// last bit of tilt, and its diffuse term is nought either way, but a lookup there reads its
// neighbours as casters: acne in stripes along the map's rows (Suzanne's brow under a sun at
// azimuth 250, elevation 25: 0.08 % of the view falsely shadowed away from edges). There the
// lookup moves off the surface, towards the light along the plane's normal, by the filter's
// reach. Planes a little less edge-on, up to kGrazingCosine (0.57 degrees), are followed only
// up to kPlaneMaxSlope and stripe the same way on faceted meshes near their terminators (a
// face of Suzanne's ear, sun at 73.5, 55.9: 0.18 % of the view; the instanced cubes' sides
// under a side sun: 0.04 %): they move by a share of the reach, kGrazingShift at most,
// fading to none at kGrazingCosine. Wider or larger moves were measured and rejected: the
// whole reach from 85 degrees on let walls and posts edge-on to the sun leak beside the
// casters that touch them (Sponza's atrium 0.5 % to 1.0 % misclassified, the Lantern's lamp
// 0.23 % to 0.90 %), and a quarter of the reach up to 5.7 degrees leaked along the horse's
// and the ToyCar's terminators (0.26 % to 0.34 %, 0.64 % to 0.71 %). Lookups that apply the
// silhouette rule below take no share (`shift` 0): the rule sees those stripes for what they
// are, and the share lifted points above the surface that shadows them where a smooth mesh
// curves away from a point light (Suzanne, a random view of the broad check: 0.43 % of the
// view leaking away from edges with it, 0.005 % without; every view of quality-real.md
// within 0.05 points either way).
const float kGrazingCosine = 0.01;
const float kGrazingShift = 0.15;
vec3 grazingPlaneOffset(vec3 planeNormal, vec3 wsToLight, float texelWorld, float reach,
                        float shift) {
    float c = dot(planeNormal, wsToLight);
    float a = abs(c);
    float share = a < 1e-3 ? 1.0 : shift * (1.0 - smoothstep(0.0, kGrazingCosine, a));
    return (c < 0.0 ? -planeNormal : planeNormal) * (share * reach * texelWorld);
}

// The receiver's plane as one lookup's taps see it: stored depth per unit of tap offset,
// capped (`g`, see kPlaneMaxSlope) and full; `spread`, the capped plane's change across half a
// texel; `cosine`, |cos| of the angle between the plane's normal and the light. A lookup that
// follows no plane has the flat one: no gradient, and a cosine of 1, far from any silhouette.
struct TapPlane {
    vec2 g;
    vec2 full;
    float spread;
    float cosine;
};
const TapPlane kFlatPlane = TapPlane(vec2(0.0), vec2(0.0), 0.0, 1.0);
float planeCosine(vec3 planeNormal, vec3 wsToLight) {
#if defined(RECEIVER_PLANE)
    return abs(dot(planeNormal, wsToLight));
#else
    return 1.0;
#endif
}
// The silhouette rule. A plane within a degree or two of edge-on to the light, whose texels
// beyond the point downhill along the plane (deeper in the map) are all lit, stands at a
// silhouette: the light grazes it and meets nothing behind it. Its texels uphill then hold the
// surface it meets across a convex edge (a post's lit face beside its grazing side), which
// the capped plane finds in front, striping the grazing side with false shadow (the Lantern
// under a sun at 180.2, 10.9: 3.6 % of the view away from edges; under a point light almost
// in the plane of its post, 1.1 %). What lies uphill behind the receiver's own plane is on its
// far side from the light and cannot shadow it, so a single map takes such a point as lit
// (at these slopes, 50 depth steps a texel and more, that scored as comparing the uphill
// texels against the full plane did, which cost a fifth of mixed-lights' main pass), and a
// cube face compares its uphill taps against the full plane (taken as lit, the post under the
// point light leaked: 0.14 % of that view). Where something beyond the point is in shadow (a
// grazing face of the horse under its own neck), the capped comparison stays: the full plane
// there, or a larger kPlaneMaxApproach for every grazing plane (30x), leaked through whole
// faces (horse-glmark2: 0.003 % to 0.018 % of the view leaking away from edges; Sponza's
// atrium 0.52 % to 0.63 % misclassified). Testing only the 2x2 texels next to the point
// downhill, for one gather more instead of the footprint's arithmetic, leaked the same way.
// Single maps' kernels apply it within 1.15 degrees of edge-on (at 1.7 a few pixels of the
// Lamp's base leaked under a low sun: 0.056 % of its view away from edges); cube faces, which
// follow the plane uphill half as far (kCubeMaxApproach), within 4 (a post's side 2.9 degrees
// from edge-on to a point light, tests/gl/test_score.cpp: 2.7 % of the view striped at 1.7;
// at 4 the Lamp's views misclassify 0.005 to 0.007 points more, shadow edges on grounds far
// from a point light up to 0.045). Lookups of one comparison or one gather (--filter none,
// --pcf-size 1, hw2x2; cubes' poisson) judge from one texel downhill, or the gather's, also
// within 4 degrees (at 1.15 the post's side 1.4 to 3.8 degrees from edge-on to a spot stayed
// striped over 0.2 to 1.3 % of the view). MSM's lookups judge from one texel downhill within
// kSilhouetteCosine (shadow_lookup.glsl).
const float kSilhouetteCosine = 0.02;
const float kCubeSilhouetteCosine = 0.07;
const float kSingleTapSilhouetteCosine = 0.07;
bool atSilhouette(TapPlane plane, float cosine, float downhillShadow) {
    return plane.cosine < cosine && downhillShadow == 0.0;
}

// The depth offset of a tap `o` away on the receiver's plane, from its capped gradient `g`
// and its full one `full` (the same units): capped as above, less so towards the light.
float planeAlong(vec2 g, vec2 full, vec2 o, float approach) {
    float capped = dot(g, o);
    return min(capped, max(dot(full, o), approach * capped));
}
float planeAlong(vec2 g, vec2 full, vec2 o) {
    return planeAlong(g, full, o, kPlaneMaxApproach);
}
vec4 planeAlong4(vec4 capped, vec4 full, float approach) {
    return min(capped, max(full, approach * capped));
}
// llvmpipe divides and takes square roots exactly (a division per reciprocal, a root and a
// division per normalize), each several times the cost of a multiply-add on every pixel, so
// this runs on as few as it can: the tangents are not normalised (any two directions across
// the plane do), the two steps are not divided by their w (the solve below is homogeneous in
// each step, so their scale cancels out), and the tests compare squares. Two divisions and one
// root where it had eleven and four: mixed-lights' main pass took 0.96 of the time, and with
// mapRounding's bound and receiverPlaneNormal's test also rid of roots, glmark2's horse's 0.98
// (LP_NUM_THREADS=1, scripts/ab-bench.sh): less than the count suggests.
// The gradient per map unit, capped and full (both 0 for a plane edge-on to the light).
struct PlaneGradient {
    vec2 capped;
    vec2 full;
};
PlaneGradient receiverPlaneGradient(LightRecord light, vec3 planeNormal, vec4 clip, vec3 coord,
                                    float texelWorld, float texelCoord, vec3 wsToLight) {
    vec3 n = planeNormal;
    vec3 t1 = abs(n.x) > 0.5 ? vec3(n.y, -n.x, 0.0) : vec3(0.0, n.z, -n.y);  // 0.5 to 1 long
    vec3 t2 = cross(n, t1);
    vec4 c1 = clip + light.textureFromWorld * vec4(t1 * texelWorld, 0.0);
    vec4 c2 = clip + light.textureFromWorld * vec4(t2 * texelWorld, 0.0);
    // Each step in map coordinates and depth, times its w.
    vec3 d1 = c1.xyz - coord * c1.w, d2 = c2.xyz - coord * c2.w;
    float det = d1.x * d2.y - d2.x * d1.y;
    // A plane seen edge-on by the light has no depth gradient in the map: no texel but its
    // own line shows it, and the single-depth comparison is as good as any. (Its sine below
    // 1e-6; the products scaled up, not down, so that tiny scenes do not underflow.)
    if (!(det * det * 1e12 > dot(d1.xy, d1.xy) * dot(d2.xy, d2.xy))) {
        return PlaneGradient(vec2(0.0), vec2(0.0));
    }
    vec2 g = vec2(d1.z * d2.y - d2.z * d1.y, d1.x * d2.z - d2.x * d1.z) * (1.0 / det);
    // Clamped to kPlaneMaxSlope: the depth the surface changes over one texel when it is
    // tilted that much, from a step towards the light (times its w, as above).
    vec4 c3 = clip + light.textureFromWorld * vec4(wsToLight * texelWorld * kPlaneMaxSlope, 0.0);
    float maxPerTexelW = abs(coord.z * c3.w - c3.z);
    float perTexelW = length(g) * texelCoord * abs(c3.w);
    return PlaneGradient(perTexelW > maxPerTexelW ? g * (maxPerTexelW / perTexelW) : g, g);
}
