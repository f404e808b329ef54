// The main pass's output dithering (DITHER_LINEAR, DITHER_SRGB); dither() passes the colour
// through unchanged without either. Included by main.frag.glsl.
#if defined(DITHER_LINEAR) || defined(DITHER_SRGB)
// Ordered dithering (Bayer, 1973; a 4x4 threshold matrix) of the 8-bit output by less than
// half a step either way: a smooth gradient, which plain rounding turns into flat bands one
// step apart, becomes a fine fixed pattern whose local average is the true colour. The same
// pixel always gets the same offset, so images stay deterministic. For sRGB output the step is
// one of the encoded values the target stores: the offset, meant in that encoding, is carried
// back to linear by the curve's slope at c, dc/de = 2.4 c / (e + 0.055) = (2.4 / 1.055)
// c^(7/12) (1 / 12.92 on the linear toe). To first order that is the encoded offset (off by
// under 1.5 % of it, at the darkest end of the power segment). c^(7/12) is read off c's float
// bits: scaling them by 7/12 scales its exponent and, near enough, its logarithm (the constant
// chosen for the least error over the power segment: within 4.6 %, so the largest offset,
// 15/32 of a step, stays under half a step), where pow, an exp2 of a log2 on llvmpipe, would
// cost a large share of the main pass.
// The matrix's entry from the bits of x ^ y and y, interleaved and reversed (its recursive
// construction), in integer operations: llvmpipe reads a table indexed per pixel one lane at
// a time.
vec3 dither(vec3 c) {
    ivec2 p = ivec2(gl_FragCoord.xy) & 3;
    int q = p.x ^ p.y;
    int bayer = ((q & 1) << 3) | ((p.y & 1) << 2) | (q & 2) | ((p.y >> 1) & 1);
    float offset = ((float(bayer) + 0.5) / 16.0 - 0.5) / 255.0;
#ifdef DITHER_SRGB
    c = clamp(c, 0.0, 1.0);
    vec3 power = max(c, 0.0031308);  // the power segment's slope, kept finite on the toe
    vec3 root = intBitsToFloat(ivec3(vec3(floatBitsToInt(power)) * (7.0 / 12.0)) + 443722423);
    vec3 slope = mix(vec3(1.0 / 12.92), (2.4 / 1.055) * root, step(0.0031308, c));
    return c + offset * slope;
#else
    return c + offset;
#endif
}
#else
vec3 dither(vec3 c) {
    return c;
}
#endif
