// A box whose every side is a grid of squares at whole coordinates, so its corners weld
// exactly by position: a solid of many triangles, wound outwards (counter-clockwise seen
// from outside). For tests of what may be culled on solids with a few faces wound wrongly.
#pragma once

#include <cstdint>

#include "gnomon/Scene.h"

namespace gnomon::test {

// Spans [0, cells] on each axis, scaled by `scale` and moved by `offset`; two triangles per
// square, the sides in the order -x, +x, -y, +y, -z, +z, each square's two in a row.
inline Mesh gridSolid(int cells, float scale = 1.0f, glm::vec3 offset = glm::vec3(0.0f)) {
    Mesh m;
    m.name = "grid solid";
    for (int axis = 0; axis < 3; ++axis) {
        for (int side : {0, cells}) {
            const int u = (axis + 1) % 3, v = (axis + 2) % 3;
            glm::vec3 normal(0.0f);
            normal[axis] = side ? 1.0f : -1.0f;
            auto corner = [&](int i, int j) {
                glm::vec3 p;
                p[axis] = float(side);
                p[u] = float(i);
                p[v] = float(j);
                m.positions.push_back(offset + scale * p);
                m.normals.push_back(normal);
                return std::uint32_t(m.positions.size() - 1);
            };
            for (int i = 0; i < cells; ++i) {
                for (int j = 0; j < cells; ++j) {
                    const std::uint32_t a = corner(i, j), b = corner(i + 1, j),
                                        c = corner(i + 1, j + 1), d = corner(i, j + 1);
                    // u x v is the axis: counter-clockwise seen from outside on the far side.
                    if (side)
                        m.indices.insert(m.indices.end(), {a, b, c, a, c, d});
                    else
                        m.indices.insert(m.indices.end(), {a, c, b, a, d, c});
                }
            }
        }
    }
    return m;
}

// Turns triangle `t` over (swaps two corners): wound the wrong way, its normals kept.
inline void turnTriangle(Mesh& m, std::size_t t) {
    std::swap(m.indices[3 * t + 1], m.indices[3 * t + 2]);
}

}  // namespace gnomon::test
