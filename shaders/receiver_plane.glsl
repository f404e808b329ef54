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
// left covers rounding.

// The steepest plane followed, as depth per distance across the light (tan of the angle
// between the surface's normal and the light). Steeper planes are followed only this far and
// the depth pass's slope-scaled offset covers the rest: followed all the way, a grazing plane
// reaches past real occluders within the filter's footprint.
const float kPlaneMaxSlope = 2.0;
// ...except on the side where the plane comes towards the light, followed this many times
// further. There a surface almost edge-on to the light meets its neighbours across convex
// edges (a cube's lit top beside a grazing side): they lie behind the side's plane, so the
// full plane finds them lit, where the capped one, too deep there, stripes the side with
// shadow. Larger factors leak more along real occluders' edges.
const float kPlaneMaxApproach = 6.0;
// Cube faces follow the approach side less far: their taps lie on the face's plane rather than
// on the receiver's and reach past thin casters sooner (the stem of LightsPunctualLamp's lamp);
// with no approach at all, columns under a point light get short lines of false shadow.
const float kCubeMaxApproach = 3.0;
// Planes edge-on to the light. Within a thousandth (0.06 degrees) a plane covers no texel of
// the map: its lookups read its neighbours, which shadow it in stripes along the map's rows,
// and no gradient can be found from it (receiverPlaneGradient gives none); its diffuse term is
// nought either way. There the lookup moves off the surface, towards the light along the
// plane's normal, by the filter's reach. Planes a little less edge-on, up to kGrazingCosine
// (0.57 degrees), are followed only up to kPlaneMaxSlope and stripe the same way on faceted
// meshes near their terminators: they move by a share of the reach, kGrazingShift at most,
// fading to none at kGrazingCosine. Larger moves let walls edge-on to the sun leak beside the
// casters that touch them. Lookups that apply the silhouette rule below take no share (`shift`
// 0): the rule tells those stripes apart, and the share would lift points of a smooth mesh
// that curves away from a point light above the surface that shadows them.
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

// The silhouette rule. A plane near edge-on to the light whose texels downhill of the point
// (deeper in the map) are all lit stands at a silhouette: the light grazes it and meets nothing
// behind it. Its texels uphill then hold the surface it meets across a convex edge (a post's lit
// face beside its grazing side), which the capped plane finds in front: false shadow in stripes.
// What lies uphill behind the receiver's plane is on its far side from the light and cannot
// shadow it, so a single map takes such a point as lit and a cube face compares its uphill taps
// against the full plane. Where something downhill is in shadow (glmark2's horse under its own
// neck) the capped comparison stays: the full plane would leak through whole faces there.
// It applies within 1.15 degrees of edge-on for single maps' kernels; within 4 for cube faces
// (they follow the plane uphill half as far, kCubeMaxApproach) and for lookups that judge from
// one texel or one gather downhill (--filter none, --pcf-size 1, hw2x2; cubes' poisson). MSM
// judges from one texel downhill within the kernels' angle (map_filters.glsl).
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
// The receiver plane's gradient per map unit, capped and full (both 0 for a plane edge-on to the
// light). `clip` is the lookup point in map clip space, `coord` after the divide; two tangent
// steps of about a texel give the gradient. llvmpipe divides and takes square roots exactly,
// each several times the cost of a multiply-add on every pixel, so this uses as few as it can:
// the tangents are not normalised (any two directions across the plane do), the steps are not
// divided by their w (the solve is homogeneous in each step, so their scale cancels out), and
// the tests compare squares.
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
