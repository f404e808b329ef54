#include "shadow/LightTiles.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace gnomon::shadow {

namespace {
// Costs on llvmpipe, 2 cores (docs/results/performance.md, "Many lights"): one light's share of
// the main pass per pixel with its 3x3 PCF lookup and without a lookup, from mixed-lights' main
// pass with shadows on and off; a triangle drawn once more, from the triangles sweep's shadow
// pass. The draw call's cost is an assumption: small next to the others.
constexpr double kShadowedNsPerPixel = 20.0;
constexpr double kUnshadowedNsPerPixel = 4.0;
constexpr double kTriangleNs = 150.0;
constexpr double kDrawMs = 0.03;
// Loops instead of lookups written out: this share more per light, from the local-lights
// sweep's 8 lights in loops and written out. The light lists' fetch of the pixel's tile, per
// pixel drawn: bounded by the main pass of a build whose every list is empty.
constexpr double kLoopShare = 0.05;
constexpr double kListNsPerPixel = 2.0;

// One pixel's lights (those `reach` marks; null: all) in ns, in loops when more than
// `maxWrittenOut` (negative: always in loops).
double pixelNs(const std::vector<LightReach>& lights, const std::uint8_t* reach,
               int maxWrittenOut) {
    int count = 0;
    double ns = 0.0;
    for (std::size_t l = 0; l < lights.size(); ++l) {
        if (reach && !reach[l]) continue;
        ++count;
        ns += lights[l].shadowed ? kShadowedNsPerPixel : kUnshadowedNsPerPixel;
    }
    return count > maxWrittenOut ? ns * (1.0 + kLoopShare) : ns;
}

struct Plane {
    glm::vec3 normal;  // outward
    float offset;      // signed distance of p: dot(normal, p) + offset
    float distance(const glm::vec3& p) const { return glm::dot(normal, p) + offset; }
};

// The frustum's 6 planes, normals pointing away from its centre.
std::array<Plane, 6> framePlanes(const std::array<glm::vec3, 8>& c) {
    // Corner i: bit 0 x (0 left, 1 right), bit 1 y (0 bottom, 1 top), bit 2 z (0 near, 1 far).
    static constexpr int kFaces[6][3] = {{0, 2, 4}, {1, 3, 5}, {0, 1, 4},
                                         {2, 3, 6}, {0, 1, 2}, {4, 5, 6}};
    glm::vec3 centre(0.0f);
    for (const glm::vec3& p : c)
        centre += p / 8.0f;
    std::array<Plane, 6> planes{};
    for (int f = 0; f < 6; ++f) {
        const glm::vec3 &a = c[kFaces[f][0]], &b = c[kFaces[f][1]], &d = c[kFaces[f][2]];
        glm::vec3 n = glm::cross(b - a, d - a);
        const float len = glm::length(n);
        n = len > 0.0f ? n / len : glm::vec3(0.0f);
        if (glm::dot(n, centre - a) > 0.0f) n = -n;
        planes[f] = {n, -glm::dot(n, a)};
    }
    return planes;
}

bool allOutside(const std::array<glm::vec3, 8>& corners, const glm::vec3& normal,
                const glm::vec3& through) {
    for (const glm::vec3& p : corners)
        if (glm::dot(p - through, normal) <= 0.0f) return false;
    return true;
}

bool coneMayReach(const LightReach& light, const std::array<glm::vec3, 8>& corners,
                  const std::array<Plane, 6>& planes) {
    if (!(light.cosOuter > 1e-4f) || glm::length(light.direction) == 0.0f) return true;
    const glm::vec3 d = glm::normalize(light.direction);
    const glm::vec3 u = glm::normalize(std::abs(d.x) < 0.9f ? glm::cross(d, glm::vec3(1, 0, 0))
                                                            : glm::cross(d, glm::vec3(0, 1, 0)));
    const glm::vec3 v = glm::cross(d, u);
    const float c = std::min(light.cosOuter, 1.0f), s = std::sqrt(1.0f - c * c), t = s / c;
    // The circumscribed square pyramid: side planes through the apex tangent to the cone.
    const glm::vec3 sides[4] = {u * c - d * s, -u * c - d * s, v * c - d * s, -v * c - d * s};
    for (const glm::vec3& n : sides)
        if (allOutside(corners, n, light.position)) return false;
    // And the other way: a tile plane with the apex and every edge of the pyramid beyond it.
    const glm::vec3 edges[4] = {d + t * (u + v), d + t * (u - v), d - t * (u + v), d - t * (u - v)};
    for (const Plane& plane : planes) {
        if (plane.distance(light.position) <= 0.0f) continue;
        bool away = true;
        for (const glm::vec3& e : edges)
            away = away && glm::dot(plane.normal, e) >= 0.0f;
        if (away) return false;
    }
    return true;
}
}  // namespace

std::array<glm::vec3, 8> tileCorners(const glm::mat4& viewFromClip, int width, int height, int x0,
                                     int y0, int x1, int y1, float nearest, float farthest) {
    std::array<glm::vec3, 8> corners{};
    for (int i = 0; i < 8; ++i) {
        const float x = float((i & 1) ? x1 : x0) / float(width) * 2.0f - 1.0f;
        const float y = float((i & 2) ? y1 : y0) / float(height) * 2.0f - 1.0f;
        const float z = 2.0f * ((i & 4) ? farthest : nearest) - 1.0f;
        const glm::vec4 p = viewFromClip * glm::vec4(x, y, z, 1.0f);
        corners[i] = glm::vec3(p) / p.w;
    }
    return corners;
}

namespace {
bool mayReachWithin(const LightReach& light, const std::array<glm::vec3, 8>& corners,
                    const std::array<Plane, 6>& planes) {
    if (light.shape == LightReach::Shape::Everywhere) return true;
    if (light.range > 0.0f) {
        for (const Plane& plane : planes)
            if (plane.distance(light.position) > light.range) return false;
    }
    return light.shape != LightReach::Shape::Cone || coneMayReach(light, corners, planes);
}
}  // namespace

bool mayReach(const LightReach& light, const std::array<glm::vec3, 8>& corners) {
    return mayReachWithin(light, corners, framePlanes(corners));
}

namespace {
// The nearest and farthest depth drawn in pixels [x0, x1) x [y0, y1): the cells overlapping
// them (a superset of the tile when cells straddle its edge, so still conservative).
glm::vec2 tileDepth(const DepthCells& depth, int x0, int y0, int x1, int y1) {
    const SampleGrid& g = depth.grid;
    glm::vec2 range(1.0f, 0.0f);
    for (int cy = y0 / g.block; cy <= (y1 - 1) / g.block && cy < g.cells.y; ++cy) {
        for (int cx = x0 / g.block; cx <= (x1 - 1) / g.block && cx < g.cells.x; ++cx) {
            const glm::vec2 cell = (*depth.ranges)[std::size_t(cy * g.cells.x + cx)];
            if (cell.x >= 1.0f) continue;  // nothing drawn there
            range = {std::min(range.x, cell.x), std::max(range.y, cell.y)};
        }
    }
    return range;
}
}  // namespace

void cullTiles(const std::vector<LightReach>& lights, const glm::mat4& viewFromClip, int width,
               int height, int size, const DepthCells* depth, TileReach& out) {
    out.size = size;
    out.columns = (width + size - 1) / size;
    out.rows = (height + size - 1) / size;
    out.reaches.assign(std::size_t(out.columns * out.rows) * lights.size(), 1);
    out.drawn.assign(std::size_t(out.columns * out.rows), 0);
    for (int r = 0; r < out.rows; ++r) {
        for (int c = 0; c < out.columns; ++c) {
            const int x0 = c * size, y0 = r * size;
            const int x1 = std::min(width, x0 + size), y1 = std::min(height, y0 + size);
            glm::vec2 range = depth ? tileDepth(*depth, x0, y0, x1, y1) : glm::vec2(0, 1);
            const bool empty = range.x > range.y;
            // Past the depths drawn by a margin: the view depth pass and the main pass may
            // round a surface's depth differently.
            range = glm::clamp(range + glm::vec2(-1e-5f, 1e-5f), 0.0f, 1.0f);
            const auto corners =
                tileCorners(viewFromClip, width, height, x0, y0, x1, y1, range.x, range.y);
            const std::array<Plane, 6> planes = framePlanes(corners);
            const std::size_t tile = std::size_t(r * out.columns + c);
            out.drawn[tile] = empty ? 0 : (x1 - x0) * (y1 - y0);
            for (std::size_t l = 0; l < lights.size(); ++l) {
                out.reaches[tile * lights.size() + l] =
                    !empty && mayReachWithin(lights[l], corners, planes) ? 1 : 0;
            }
        }
    }
}

void coarsenTiles(const TileReach& fine, int factor, int width, int height, std::size_t lights,
                  TileReach& out) {
    out.size = fine.size * factor;
    out.columns = (width + out.size - 1) / out.size;
    out.rows = (height + out.size - 1) / out.size;
    out.reaches.assign(std::size_t(out.columns * out.rows) * lights, 0);
    out.drawn.assign(std::size_t(out.columns * out.rows), 0);
    for (int r = 0; r < fine.rows; ++r) {
        for (int c = 0; c < fine.columns; ++c) {
            const std::size_t from = std::size_t(r * fine.columns + c);
            const std::size_t to = std::size_t((r / factor) * out.columns + c / factor);
            out.drawn[to] += fine.drawn[from];
            for (std::size_t l = 0; l < lights; ++l)
                out.reaches[to * lights + l] |= fine.reaches[from * lights + l];
        }
    }
}

TilingGain tilingGainMs(const TileReach& tiles, const std::vector<LightReach>& lights,
                        std::uint64_t triangles, int maxWrittenOut) {
    const std::size_t n = lights.size();
    double noneNs = 0.0, drawsNs = 0.0, listsNs = 0.0;
    int draws = 0;
    for (int r = 0; r < tiles.rows; ++r) {
        for (int c = 0; c < tiles.columns; ++c) {
            const std::size_t tile = std::size_t(r * tiles.columns + c);
            const std::uint8_t* reach = tiles.reaches.data() + tile * n;
            // Neighbours in a row with the same lights share one draw.
            if (c == 0 || n == 0 || std::memcmp(reach, reach - n, n) != 0) ++draws;
            const double pixels = double(tiles.drawn[tile]);  // where something is shaded
            noneNs += pixels * pixelNs(lights, nullptr, maxWrittenOut);
            drawsNs += pixels * pixelNs(lights, reach, maxWrittenOut);
            listsNs += pixels * (pixelNs(lights, reach, -1) + kListNsPerPixel);
        }
    }
    const double drawMs = double(triangles) * kTriangleNs * 1e-6 + kDrawMs;
    return {(noneNs - drawsNs) * 1e-6 - double(draws - 1) * drawMs, (noneNs - listsNs) * 1e-6};
}

}  // namespace gnomon::shadow
