// Vertex side of the ALPHA_TEST depth programs (alpha_test.glsl is the fragment side): the
// material's texture coordinates and alpha rule, handed on per caster.
layout(location = 3) in vec2 msUv;

out AlphaOut {
    vec2 uv;
    flat float alpha;   // base colour alpha factor
    flat float cutoff;  // masked: the cutoff; blended: -1 (dithered)
} vAlpha;

void passAlphaRule(ObjectData o) {
    vAlpha.uv = materialUv(o, msUv);
    vAlpha.alpha = o.baseColour.a;
    vAlpha.cutoff = o.flags.y == 1.0 ? o.flags.z : -1.0;
}
