// One channel of the four texels around a texel corner, in textureGather's order: (i, j + 1),
// (i + 1, j + 1), (i + 1, j), (i, j). GATHER_2D(s, i, j, texelSize): texels (i, j) to
// (i + 1, j + 1) of a 2D texture (red; i and j ints, texelSize one texel in uv);
// GATHER_LAYER(s, ij, texelUv, layer): the same in a 2D array's layer (ij a vec2 of whole
// texel numbers); GATHER_LAYER_AT(s, uv, layer, component): the texels a bilinear read at
// `uv` blends. OpenGL 4.5 gathers them; GLSL ES 3.00 (WebGL2) has no textureGather, so there
// they are four texel fetches, clamped to the edge as the gather's sampler clamps them.
// A call of these macros stays on one line (cube_access.glsl says why).
#ifdef GNOMON_GLES
#define GATHER_2D(s, i, j, texelSize) gatherTexels(s, ivec2(i, j), 0)
#define GATHER_LAYER(s, ij, texelUv, layer) gatherTexels(s, ivec3(ivec2(ij), int(layer)), 0)
#define GATHER_LAYER_AT(s, uv, layer, c) gatherTexels(s, bilinearCorner(s, uv, layer), c)

// The lower-left texel of the 2x2 a bilinear read at `uv` of layer `layer` blends.
ivec3 bilinearCorner(sampler2DArray s, vec2 uv, float layer) {
    return ivec3(ivec2(floor(uv * vec2(textureSize(s, 0).xy) - 0.5)), int(layer));
}
vec4 gatherTexels(sampler2D s, ivec2 ij, int component) {
    ivec2 last = textureSize(s, 0) - 1;
    ivec2 lo = clamp(ij, ivec2(0), last), hi = clamp(ij + 1, ivec2(0), last);
    return vec4(texelFetch(s, ivec2(lo.x, hi.y), 0)[component], texelFetch(s, hi, 0)[component],
                texelFetch(s, ivec2(hi.x, lo.y), 0)[component], texelFetch(s, lo, 0)[component]);
}
vec4 gatherTexels(sampler2DArray s, ivec3 ij, int component) {
    ivec2 last = textureSize(s, 0).xy - 1;
    ivec2 lo = clamp(ij.xy, ivec2(0), last), hi = clamp(ij.xy + 1, ivec2(0), last);
    return vec4(texelFetch(s, ivec3(lo.x, hi.y, ij.z), 0)[component],
                texelFetch(s, ivec3(hi, ij.z), 0)[component],
                texelFetch(s, ivec3(hi.x, lo.y, ij.z), 0)[component],
                texelFetch(s, ivec3(lo, ij.z), 0)[component]);
}
#else
#define GATHER_2D(s, i, j, texelSize) textureGather(s, vec2(i + 1, j + 1) * texelSize)
#define GATHER_LAYER(s, ij, texelUv, layer) textureGather(s, vec3((ij + 1.0) * texelUv, layer))
#define GATHER_LAYER_AT(s, uv, layer, component) textureGather(s, vec3(uv, layer), component)
#endif
