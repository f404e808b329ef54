// Alpha-tested shadow casters (ALPHA_TEST variants of the depth passes): masked materials
// cut away below their cutoff; blended ones (--blend-shadows dithered) keep a share alpha of
// the map's texels, chosen by a hash of the texel so that filtered lookups see partial shadow.
layout(binding = 4) uniform sampler2D uBaseColourTexture;  // 1x1 white when untextured

in AlphaOut {
    vec2 uv;
    flat float alpha;   // base colour alpha factor
    flat float cutoff;  // masked: the cutoff; blended: -1 (dithered)
#ifdef BLEND_OPAQUE_PARTS
    // Blended casters under coloured shadows: which texels are fully opaque is read at full
    // resolution, as the transmittance pass and the reference read them (mip levels blur
    // opaque stripes below the threshold where the light sees them at a slant, and the map
    // then lets through light the reference blocks).
    flat float fullResolution;
#endif
} vAlpha;

// Uniform in [0, 1) per texel, no visible pattern (integer hash, PCG-style).
float texelHash(uvec2 p) {
    uint h = p.x * 747796405u + p.y * 2891336453u + 277803737u;
    h = ((h >> ((h >> 28u) + 4u)) ^ h) * 277803737u;
    h = (h >> 22u) ^ h;
    return float(h >> 8) * (1.0 / 16777216.0);
}

// Masked: cut below the cutoff, as the main pass and the reference do. Dithered: kept where
// alpha > a hash in [0, 1), so alpha 0 never casts and alpha 1 always does.
void alphaTest() {
#ifdef BLEND_OPAQUE_PARTS
    float alpha = vAlpha.alpha * (vAlpha.fullResolution > 0.5
                                      ? textureLod(uBaseColourTexture, vAlpha.uv, 0.0).a
                                      : texture(uBaseColourTexture, vAlpha.uv).a);
#else
    float alpha = vAlpha.alpha * texture(uBaseColourTexture, vAlpha.uv).a;
#endif
    bool cut = vAlpha.cutoff >= 0.0 ? alpha < vAlpha.cutoff
                                    : alpha <= texelHash(uvec2(gl_FragCoord.xy));
    if (cut) discard;
}
