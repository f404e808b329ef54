// Rays through the project's own BVH (src/bvh/Bvh.h), read from two RGBA32F textures with
// texelFetch so it runs on WebGL2 as on OpenGL 4.5: node i is texels 2i, 2i+1 of uBvhNodes,
// triangle j texels 3j..3j+2 of uBvhTriangles, in rows of kBvhRowTexels (bvh_layout.glsl).
// The same traversal as the C++ (front to back, a stack of deferred siblings, box exits
// widened as Ize 2013 shows) and the watertight triangle test of Woop, Benthin and
// Wald 2013, without the C++'s double-precision retry of an area of exactly 0.
#include "bvh_layout.glsl"
layout(binding = 12) uniform highp sampler2D uBvhNodes;
layout(binding = 13) uniform highp sampler2D uBvhTriangles;
// Masked and blended casters' cut-outs (render/RayMasks.h): texture coordinates and rules per
// triangle, and the textures' alphas four to a texel. Read only under BVH_CUTOUTS (some caster
// has them): a CPU driver runs the test's code for every pixel, masked off, wherever it is
// written.
layout(binding = 10) uniform highp sampler2D uBvhUvs;
layout(binding = 11) uniform mediump sampler2D uBvhAlphas;

const float kBvhWiden = 1.0 + 2.0 * (3.0 * 5.9604645e-8) / (1.0 - 3.0 * 5.9604645e-8);
const int kBvhStack = 64;

vec4 bvhTexel(highp sampler2D s, int k) {
    return texelFetch(s, ivec2(k & (kBvhRowTexels - 1), k >> kBvhRowLog2), 0);
}

// A ray in the form both tests use: the inverse direction for slabs, the shear for triangles.
struct BvhRayFrame {
    vec3 origin, inv;
    int kx, ky, kz;
    vec3 shear;  // sx, sy, sz
};

BvhRayFrame bvhFrame(vec3 origin, vec3 dir) {
    BvhRayFrame r;
    dir += vec3(0.0);  // -0 to +0, as the C++
    r.origin = origin;
    r.inv = 1.0 / dir;
    vec3 m = abs(dir);
    r.kz = m.x >= m.y && m.x >= m.z ? 0 : (m.y >= m.z ? 1 : 2);
    r.kx = (r.kz + 1) % 3;
    r.ky = (r.kx + 1) % 3;
    if (dir[r.kz] < 0.0) {
        int k = r.kx;
        r.kx = r.ky;
        r.ky = k;
    }
    r.shear = vec3(dir[r.kx] / dir[r.kz], dir[r.ky] / dir[r.kz], 1.0 / dir[r.kz]);
    return r;
}

// Where the ray enters the box lo..hi within (tnear, tfar], or -1 when it misses it.
float bvhEnter(BvhRayFrame r, vec3 lo, vec3 hi, float tnear, float tfar) {
    vec3 t0 = (lo - r.origin) * r.inv, t1 = (hi - r.origin) * r.inv;
    vec3 tn = min(t0, t1), tf = max(t0, t1) * kBvhWiden;
    float enter = max(max(tn.x, tn.y), max(tn.z, tnear));
    float leave = min(min(tf.x, tf.y), min(tf.z, tfar));
    return enter <= leave ? enter : -1.0;
}

// The distance to the triangle of corners a0, b0, c0 along the ray when it is hit within
// (tnear, tfar], else -1; `bary` the hit's barycentric weights of the corners.
float bvhHitTriangle(BvhRayFrame r, vec3 a0, vec3 b0, vec3 c0, float tnear, float tfar,
                     out vec3 bary) {
    bary = vec3(0.0);
    vec3 a = a0 - r.origin, b = b0 - r.origin, c = c0 - r.origin;
    float ax = a[r.kx] - r.shear.x * a[r.kz], ay = a[r.ky] - r.shear.y * a[r.kz];
    float bx = b[r.kx] - r.shear.x * b[r.kz], by = b[r.ky] - r.shear.y * b[r.kz];
    float cx = c[r.kx] - r.shear.x * c[r.kz], cy = c[r.ky] - r.shear.y * c[r.kz];
    float u = cx * by - cy * bx, v = ax * cy - ay * cx, w = bx * ay - by * ax;
    if ((u < 0.0 || v < 0.0 || w < 0.0) && (u > 0.0 || v > 0.0 || w > 0.0)) return -1.0;
    float det = u + v + w;
    if (det == 0.0) return -1.0;
    float t = r.shear.z * (u * a[r.kz] + v * b[r.kz] + w * c[r.kz]);
    float s = det < 0.0 ? -1.0 : 1.0;
    if (!(t * s > tnear * det * s) || !(t * s <= tfar * det * s)) return -1.0;
    bary = vec3(u, v, w) / det;
    return t / det;
}

// A texel index wrapped into 0..n-1 as the texture's sampler wraps it (mode: 0 repeat,
// 1 clamp to edge, 2 mirrored repeat). The remainder in floats, exact for indices and sizes
// under 2^24: an integer one is a division a lane on a CPU driver, paid by every pixel.
int bvhWrap(int i, int n, int mode) {
    if (mode == 1) return clamp(i, 0, n - 1);
    float period = float(mode == 2 ? 2 * n : n);
    int m = clamp(int(float(i) - period * floor(float(i) / period)), 0, int(period) - 1);
    return m < n ? m : int(period) - 1 - m;
}

// Alpha of texel `p` of a texture whose first alpha is byte `first` of uBvhAlphas.
float bvhAlphaAt(int first, ivec2 size, ivec2 p, int modes) {
    int k = first + bvhWrap(p.y, size.y, (modes / 3) % 3) * size.x + bvhWrap(p.x, size.x, modes % 3);
    vec4 four = bvhTexel(uBvhAlphas, k >> 2);
    int c = k & 3;
    return c == 0 ? four.x : c == 1 ? four.y : c == 2 ? four.z : four.w;
}

// Whether filtered triangle `tri` blocks at barycentric weights `b` (of its first, second and
// third corner): its texture's alpha there, nearest or bilinear on the full-size image as the
// reference samples it (truth/AlphaRays.cpp), reaches the triangle's threshold.
bool bvhTexelBlocks(int tri, vec3 b) {
    vec4 t0 = bvhTexel(uBvhUvs, 3 * tri), t1 = bvhTexel(uBvhUvs, 3 * tri + 1);
    vec4 t2 = bvhTexel(uBvhUvs, 3 * tri + 2);
    vec2 uv = b.x * t0.xy + b.y * t0.zw + b.z * t1.xy;
    int modes = int(t1.w);
    int first = int(t2.x) * 4096 + int(t2.y);
    ivec2 size = ivec2(t2.zw);
    vec2 x = mod(uv * vec2(size) - 0.5, 1048576.0);
    float alpha;
    if (modes >= 9) {
        alpha = bvhAlphaAt(first, size, ivec2(floor(x + 0.5)), modes);
    } else {
        ivec2 p = ivec2(floor(x));
        vec2 f = x - floor(x);
        float top = mix(bvhAlphaAt(first, size, p, modes),
                        bvhAlphaAt(first, size, p + ivec2(1, 0), modes), f.x);
        float bottom = mix(bvhAlphaAt(first, size, p + ivec2(0, 1), modes),
                           bvhAlphaAt(first, size, p + ivec2(1, 1), modes), f.x);
        alpha = mix(top, bottom, f.y);
    }
    return alpha >= t1.z;
}

// The nearest hit's distance (when `anyCaster`: the first caster's) within (tnear, tfar],
// passing through triangle `skip` (-1: none); -1 for none. `hit`: its triangle (-1: none).
float bvhTrace(vec3 origin, vec3 dir, float tnear, float tfar, bool anyCaster, int skip,
               out int hit) {
    hit = -1;
    if (textureSize(uBvhNodes, 0).x < 2) return -1.0;  // an empty hierarchy
    BvhRayFrame r = bvhFrame(origin, dir);
    float best = -1.0;
    vec4 lo = bvhTexel(uBvhNodes, 0), hi = bvhTexel(uBvhNodes, 1);
    if (bvhEnter(r, lo.xyz, hi.xyz, tnear, tfar) < 0.0) return best;
    // A node is its first child or triangle and its info (BvhNode), carried from the texels
    // its box was tested with: each step reads its two children's boxes and nothing more.
    int stackFirst[kBvhStack], stackInfo[kBvhStack];
    float stackEnter[kBvhStack];
    int top = 0;
    int first = int(lo.w), info = int(hi.w);
    // While-while (Aila and Laine, "Understanding the Efficiency of Ray Traversal on GPUs",
    // 2009): down through inner nodes until the ray reaches a leaf, then that leaf's
    // triangles, so the lanes of a vector run each loop together instead of the two branches
    // of one loop in turn. The order of nodes is the front-to-back one all the same.
    for (;;) {
        while ((info >> 1) == 0) {
            vec4 lo0 = bvhTexel(uBvhNodes, 2 * first), hi0 = bvhTexel(uBvhNodes, 2 * first + 1);
            vec4 lo1 = bvhTexel(uBvhNodes, 2 * first + 2);
            vec4 hi1 = bvhTexel(uBvhNodes, 2 * first + 3);
            float e0 = bvhEnter(r, lo0.xyz, hi0.xyz, tnear, tfar);
            float e1 = bvhEnter(r, lo1.xyz, hi1.xyz, tnear, tfar);
            if (e0 >= 0.0 && e1 >= 0.0) {
                bool secondNearer = e1 < e0;  // front to back: the farther one waits
                stackFirst[top] = int(secondNearer ? lo0.w : lo1.w);
                stackInfo[top] = int(secondNearer ? hi0.w : hi1.w);
                stackEnter[top] = max(e0, e1);
                top = min(top + 1, kBvhStack - 1);
                first = int(secondNearer ? lo1.w : lo0.w);
                info = int(secondNearer ? hi1.w : hi0.w);
            } else if (e0 >= 0.0 || e1 >= 0.0) {
                first = int(e0 >= 0.0 ? lo0.w : lo1.w);
                info = int(e0 >= 0.0 ? hi0.w : hi1.w);
            } else {
                do {  // the next deferred node the ray may still meet before its end
                    if (top == 0) return best;
                    --top;
                } while (stackEnter[top] > tfar * kBvhWiden);
                first = stackFirst[top];
                info = stackInfo[top];
            }
        }
        int count = info >> 1;
        for (int i = first; i < first + count; ++i) {
            // Its three texels read once: the flags ride in the third.
            vec4 c0 = bvhTexel(uBvhTriangles, 3 * i), c1 = bvhTexel(uBvhTriangles, 3 * i + 1);
            vec4 c2 = bvhTexel(uBvhTriangles, 3 * i + 2);
            int flags = int(c2.w);
            if ((anyCaster && (flags & 1) == 0) || i == skip) continue;
            vec3 bary;
            float t = bvhHitTriangle(r, c0.xyz, c1.xyz, c2.xyz, tnear, tfar, bary);
            if (t < 0.0) continue;
#ifdef BVH_CUTOUTS
            // (The test in a bool of its own: in one && chain with a non-constant anyCaster,
            // Mesa 22.3 built a program in which masked casters blocked everywhere.)
            bool filtered = anyCaster && (flags & 2) != 0;
            if (filtered && !bvhTexelBlocks(i, bary)) continue;
#endif
            best = t;
            tfar = t;
            hit = i;
            if (anyCaster) return best;
        }
        // The next deferred node the ray may still meet before its (shrunk) end.
        do {
            if (top == 0) return best;
            --top;
        } while (stackEnter[top] > tfar * kBvhWiden);
        first = stackFirst[top];
        info = stackInfo[top];
    }
    return best;
}
