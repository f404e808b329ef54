// Depth in 8-bit colour channels, the GPU side of src/shadow/DepthPacking.cpp:
// PACK_R8 (red only), PACK_256 (the base of the WebGL Programming Guide's Shadow_highp),
// PACK_255 (the online WebGL tutorial's base); none of them: a native depth texture, whose
// red channel is the depth.
#if defined(PACK_256)
const float kPackBase = 256.0;
#else
const float kPackBase = 255.0;
#endif

vec4 packDepth(float depth) {
#if defined(PACK_R8)
    return vec4(depth, 0.0, 0.0, 1.0);
#else
    vec4 shift = vec4(1.0, kPackBase, kPackBase * kPackBase, kPackBase * kPackBase * kPackBase);
    vec4 c = fract(depth * shift);
    // Remove from each channel what the next, finer channel already holds.
    c -= c.yzww * vec4(1.0 / kPackBase, 1.0 / kPackBase, 1.0 / kPackBase, 0.0);
    return c;
#endif
}

float unpackDepth(vec4 c) {
#if defined(PACK_R8) || !(defined(PACK_256) || defined(PACK_255))
    return c.r;
#else
    return dot(c, vec4(1.0, 1.0 / kPackBase, 1.0 / (kPackBase * kPackBase),
                       1.0 / (kPackBase * kPackBase * kPackBase)));
#endif
}
