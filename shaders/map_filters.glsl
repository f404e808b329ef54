// Single maps' filters, included by shadow_lookup.glsl: where a lookup lands in its map
// (MapTap) and the receiver's plane there (TapPlane, receiver_plane.glsl) give the share of the
// footprint that is lit, under the filter the program was built for.

// Where a lookup of a single map lands: `uv` in layer `layer`, whose square [origin, origin +
// scale] is the light's map, [lo, hi] that square less half a texel (taps stay inside), one
// texel `texelUv`; `reference` is what stored depth is compared with at the point itself.
struct MapTap {
    vec2 uv;
    float layer;
    float reference;
    float texelUv;
    vec2 origin;
    float scale;
    vec2 lo;
    vec2 hi;
};

// The reference for a tap `o` (layer uv) away from the point: on the receiver's plane where
// one is followed.
float tapReference(MapTap m, TapPlane plane, vec2 o) {
#if defined(RECEIVER_PLANE)
    return m.reference + planeAlong(plane.g, plane.full, o) - plane.spread;
#else
    return m.reference;
#endif
}

#if defined(SHADOW_RAYS_UNCERTAIN)
// The reference for a tap `o` away on the receiver's full plane, with half the spread and
// without the cap that tapReference allows: a texel lit under tapReference but not under this
// one holds something nearer the light than the receiver, within the tolerance band (a caster
// under a texel above a face near edge-on, which the band hides): the map cannot tell, a ray
// can. The half spread keeps a curved surface's own texels, a little above its plane where it
// is concave, from sending every such pixel to a ray.
const float kExactSpread = 0.5;
float exactReference(MapTap m, TapPlane plane, vec2 o) {
#if defined(RECEIVER_PLANE)
    return m.reference + dot(plane.full, o) - kExactSpread * plane.spread;
#else
    return m.reference;
#endif
}
#endif

#if (defined(RECEIVER_PLANE) || defined(FLAT_GATHERS)) && !defined(HAND_COMPARE) && \
    (defined(FILTER_PCF) || defined(FILTER_HW2X2))
// PCF over whole texels: the footprint of a K x K box of bilinear taps is (K + 1)^2 texels
// with tent weights (1 - f, 1, ..., 1, f) per axis; it is read by 2x2 gathers, and every
// texel is compared against the receiver plane at its own centre. Same weights as K x K
// bilinear comparisons, fewer fetches ((K + 1)^2 / 4 gathers instead of K^2 taps: 4 instead
// of 9 for the default 3 x 3).
#if defined(FILTER_PCF)
const int kGatherRadius = PCF_SIZE / 2;
#else
const int kGatherRadius = 0;
#endif
float gatherPcf(MapTap m, TapPlane plane) {
    const int r = kGatherRadius;
    float texelUv = m.texelUv;
    vec2 s = m.uv / texelUv - 0.5;  // in texels of the layer: texel i's centre is at i
    vec2 base = floor(s);
    vec2 f = s - base;
    vec2 g = plane.g * texelUv;  // stored depth per texel along the layer's axes
    vec2 full = plane.full * texelUv;
    // The map's first texel and its last 2x2 block's start, in texels of the layer.
    vec2 first = floor(m.origin / texelUv + 0.5);
    vec2 last = first + floor(m.scale / texelUv + 0.5) - 2.0;
    float sum = 0.0, downhillShadow = 0.0, inBand = 0.0;
    for (int my = 0; my <= r; ++my) {
        float ky = clamp(base.y - float(r - 2 * my), first.y, last.y);
        vec2 wy = vec2(my == 0 ? 1.0 - f.y : 1.0, my == r ? f.y : 1.0);
        for (int mx = 0; mx <= r; ++mx) {
            float kx = clamp(base.x - float(r - 2 * mx), first.x, last.x);
            vec2 wx = vec2(mx == 0 ? 1.0 - f.x : 1.0, mx == r ? f.x : 1.0);
            // Gathered at the corner the four texels share: x (k, k+1), y (k+1, k+1),
            // z (k+1, k), w (k, k) as (column, row).
            vec4 d = GATHER_LAYER(uShadowDepths, vec2(kx, ky), texelUv, m.layer);
            vec2 o = vec2(kx, ky) - s;
            vec4 capped = dot(g, o) + vec4(g.y, g.x + g.y, g.x, 0.0);
            vec4 onPlane = dot(full, o) + vec4(full.y, full.x + full.y, full.x, 0.0);
            vec4 along = planeAlong4(capped, onPlane, kPlaneMaxApproach);
            vec4 refs = m.reference + along - plane.spread;
            vec4 w = vec4(wx.x * wy.y, wx.y * wy.y, wx.y * wy.x, wx.x * wy.x);
            vec4 lit = step(refs, d);
            sum += dot(lit, w);
            downhillShadow += dot(step(0.0, capped), 1.0 - lit);
#if defined(SHADOW_RAYS_UNCERTAIN)
            vec4 exact = m.reference + onPlane - kExactSpread * plane.spread;  // exactReference
            inBand += dot(lit, 1.0 - step(exact, d));
#endif
        }
    }
    // The silhouette rule (receiver_plane.glsl), from the texels downhill of the point: those
    // of one gather (--pcf-size 1, hw2x2) as a one-comparison lookup's tap.
#if defined(SHADOW_RAYS_UNCERTAIN)
    if (inBand > 0.0) return 0.5;
#endif
    const float cosine = r == 0 ? kSingleTapSilhouetteCosine : kSilhouetteCosine;
    if (atSilhouette(plane, cosine, downhillShadow)) return 1.0;
    return sum / float((2 * r + 1) * (2 * r + 1));
}
#endif

// The share of the lookup's footprint that is lit. `depth`: the point's own stored depth.
float mapFilter(LightRecord light, Receiver receiver, vec3 wsToLight, MapTap m, TapPlane plane,
                float depth) {
#if defined(FILTER_MOMENTS)
#if defined(MOMENTS_MSM) && defined(RECEIVER_PLANE) && !defined(HAND_COMPARE)
    // The silhouette rule (receiver_plane.glsl), judged from one depth texel diagonally
    // downhill: MSM's footprint over a plane within a degree or so of edge-on reads the
    // surface it meets across a convex edge as a caster (the Lantern's post edge-on to the
    // sun). EVSM2 and EVSM4 do not stripe there and would only leak more with it. Downhill,
    // where the plane runs away from the light, is the way its normal turned towards the light
    // points across the map.
    vec3 towards = receiver.planeNormal * dot(receiver.planeNormal, wsToLight);
    vec2 away = (light.textureFromWorld * vec4(towards, 0.0)).xy;
    float lit = compareDepth(clamp(m.uv + m.texelUv * sign(away), m.lo, m.hi), m.layer,
                             m.reference);
    if (atSilhouette(plane, kSilhouetteCosine, 1.0 - lit)) return 1.0;
#endif
    return momentVisibility(light, clamp(m.uv, m.lo, m.hi), m.layer, m.reference);
#elif (defined(RECEIVER_PLANE) || defined(FLAT_GATHERS)) && !defined(HAND_COMPARE) && \
    (defined(FILTER_PCF) || defined(FILTER_HW2X2))
    // FLAT_GATHERS without RECEIVER_PLANE: the flat plane, one reference for every texel.
    return gatherPcf(m, plane);
#elif defined(FILTER_PCF)
    float sum = 0.0;
    const int r = PCF_SIZE / 2;
    for (int y = -r; y <= r; ++y) {
        for (int x = -r; x <= r; ++x) {
            vec2 tap = clamp(m.uv + vec2(x, y) * m.texelUv, m.lo, m.hi);
            sum += compareDepth(tap, m.layer, tapReference(m, plane, tap - m.uv));
        }
    }
    return sum / float(PCF_SIZE * PCF_SIZE);
#elif defined(FILTER_POISSON)
    mat2 turn = poissonRotation();
    float radius = 0.5 * float(PCF_SIZE) * m.texelUv;
    float sum = 0.0;
    for (int i = 0; i < 16; ++i) {
        vec2 tap = clamp(m.uv + turn * kPoissonDisc[i] * radius, m.lo, m.hi);
        sum += compareDepth(tap, m.layer, tapReference(m, plane, tap - m.uv));
    }
    return sum / 16.0;
#elif defined(FILTER_PCSS)
#if defined(RECEIVER_PLANE)
    vec3 pcssPlane = vec3(plane.g, plane.spread);
#elif defined(RECEIVER_ONLY)
    vec3 pcssPlane = vec3(0.0);  // in no map: every tap compares against the point's own depth
#else
    vec3 pcssPlane = vec3(0.0, 0.0, -1.0);  // the tap-distance slope tolerance instead
#endif
    return pcssMap(light, m.uv, m.layer, depth, m.reference, m.lo, m.hi, m.texelUv,
                   light.frame == kFrameOrthographic, surfaceSlope(receiver.normal, wsToLight),
                   pcssPlane);
#else
    vec2 tap = clamp(m.uv, m.lo, m.hi);
#if defined(RECEIVER_PLANE)
    // The silhouette rule for one comparison (--filter none, colour formats' hw2x2): one tap
    // more, a texel diagonally downhill (its footprint wholly beyond the point), tells a
    // silhouette, where the point is lit, from a fold (cube_lookup.glsl's cubeSingleTap).
    vec2 downhill = clamp(m.uv + m.texelUv * sign(plane.full), m.lo, m.hi);
#if defined(MAP_NEAREST)
    // A NEAREST read is one texel: compared at its own centre on the receiver's plane, as the
    // gathers compare theirs, rather than at the point. Half a texel's capped spread instead
    // is too little where a post's side a few degrees from edge-on to a spot meets its lit
    // face, which it then reads as a caster.
    tap = (floor(tap / m.texelUv) + 0.5) * m.texelUv;
    downhill = (floor(downhill / m.texelUv) + 0.5) * m.texelUv;
#endif
    float beyond = compareDepth(downhill, m.layer, tapReference(m, plane, downhill - m.uv));
    if (atSilhouette(plane, kSingleTapSilhouetteCosine, 1.0 - beyond)) return 1.0;
#endif
#if defined(SHADOW_RAYS_UNCERTAIN)
    // One comparison is never part lit: the four texels around the point tell whether the map
    // is sure there (all alike: the comparison's answer) or not (a share between, or a texel
    // lit only within the tolerance band, which sends the lookup to a ray: shadow_rays.glsl).
    float around = 0.0, inBand = 0.0;
    for (int k = 0; k < 4; ++k) {
        vec2 o = (vec2(k & 1, k >> 1) - 0.5) * m.texelUv;
        vec2 corner = clamp(m.uv + o, m.lo, m.hi);
        float lit = compareDepth(corner, m.layer, tapReference(m, plane, corner - m.uv));
        around += lit;
        float exact = compareDepth(corner, m.layer, exactReference(m, plane, corner - m.uv));
        inBand += lit * (1.0 - exact);
    }
    if ((around > 0.0 && around < 4.0) || inBand > 0.0) return 0.5;
#endif
    return compareDepth(tap, m.layer, tapReference(m, plane, tap - m.uv));
#endif
}
