#include "scene/MeshBuilder.h"

#include <cmath>

#include <glm/gtc/constants.hpp>

namespace gnomon::mesh {
namespace {
void addQuad(Mesh& m, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c,
             const glm::vec3& d) {
    const glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
    const auto base = std::uint32_t(m.positions.size());
    for (const glm::vec3& p : {a, b, c, d}) {
        m.positions.push_back(p);
        m.normals.push_back(n);
    }
    for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u})
        m.indices.push_back(base + i);
}
}  // namespace

Mesh box(const std::string& name, const glm::vec3& centre, const glm::vec3& size) {
    Mesh m;
    m.name = name;
    const glm::vec3 lo = centre - 0.5f * size, hi = centre + 0.5f * size;
    auto p = [&](int x, int y, int z) {
        return glm::vec3(x ? hi.x : lo.x, y ? hi.y : lo.y, z ? hi.z : lo.z);
    };
    addQuad(m, p(1, 0, 0), p(1, 1, 0), p(1, 1, 1), p(1, 0, 1));  // +x
    addQuad(m, p(0, 0, 1), p(0, 1, 1), p(0, 1, 0), p(0, 0, 0));  // -x
    addQuad(m, p(0, 1, 0), p(0, 1, 1), p(1, 1, 1), p(1, 1, 0));  // +y
    addQuad(m, p(0, 0, 0), p(1, 0, 0), p(1, 0, 1), p(0, 0, 1));  // -y
    addQuad(m, p(0, 0, 1), p(1, 0, 1), p(1, 1, 1), p(0, 1, 1));  // +z
    addQuad(m, p(1, 0, 0), p(0, 0, 0), p(0, 1, 0), p(1, 1, 0));  // -z
    return m;
}

Mesh quad(const std::string& name, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c,
          const glm::vec3& d) {
    Mesh m;
    m.name = name;
    addQuad(m, a, b, c, d);
    return m;
}

Mesh sphere(const std::string& name, const glm::vec3& centre, float radius, int columns, int rows) {
    Mesh m;
    m.name = name;
    for (int r = 0; r <= rows; ++r) {
        const float theta = glm::pi<float>() * float(r) / float(rows);
        for (int c = 0; c <= columns; ++c) {
            const float phi = glm::two_pi<float>() * float(c) / float(columns);
            const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta),
                              std::sin(theta) * std::sin(phi));
            m.positions.push_back(centre + radius * n);
            m.normals.push_back(n);
            m.uvs.emplace_back(float(c) / float(columns), float(r) / float(rows));
        }
    }
    const auto at = [&](int r, int c) { return std::uint32_t(r * (columns + 1) + c); };
    for (int r = 0; r < rows; ++r) {
        for (int c = 0; c < columns; ++c) {
            m.indices.insert(m.indices.end(), {at(r, c), at(r + 1, c + 1), at(r + 1, c)});
            m.indices.insert(m.indices.end(), {at(r, c), at(r, c + 1), at(r + 1, c + 1)});
        }
    }
    return m;
}

Mesh triangle(const std::string& name, const glm::vec3 (&p)[3], const glm::vec3 (&colour)[3]) {
    Mesh m;
    m.name = name;
    const glm::vec3 n = glm::normalize(glm::cross(p[1] - p[0], p[2] - p[0]));
    for (int i = 0; i < 3; ++i) {
        m.positions.push_back(p[i]);
        m.normals.push_back(n);
        m.colours.push_back(colour[i]);
        m.indices.push_back(std::uint32_t(i));
    }
    return m;
}

}  // namespace gnomon::mesh
