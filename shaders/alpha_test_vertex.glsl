// Vertex side of the ALPHA_TEST depth programs (alpha_test.glsl is the fragment side): the
// material's texture coordinates and alpha rule, handed on per caster.
layout(location = 3) in vec2 msUv;

out AlphaOut {
    vec2 uv;
    flat float alpha;   // base colour alpha factor
    flat float cutoff;  // masked: the cutoff; blended: -1 (dithered)
#ifdef BLEND_OPAQUE_PARTS
    flat float fullResolution;  // 1: read the texture's level 0 (blended casters)
#endif
} vAlpha;

void passAlphaRule(ObjectData o) {
    vAlpha.uv = materialUv(o, msUv);
    vAlpha.alpha = o.baseColour.a;
#ifdef BLEND_OPAQUE_PARTS
    // Coloured shadows: a blended caster's fully opaque texels (alpha 255) are opaque casters,
    // its others tint the light (truth/AlphaRays.h: kOpaqueBlendAlpha, the same threshold).
    vAlpha.cutoff = o.flags.y == 1.0 ? o.flags.z : 254.5 / 255.0;
    vAlpha.fullResolution = o.flags.y == 1.0 ? 0.0 : 1.0;
#else
    vAlpha.cutoff = o.flags.y == 1.0 ? o.flags.z : -1.0;
#endif
}
