#include "shadow/ViewSamples.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "shadow/ShadowMath.h"

namespace gnomon::shadow {

glm::ivec2 sampleGridSize(int width, int height, int limit) {
    const int longer = std::max(width, height);
    const double scale = longer > limit ? double(limit) / double(longer) : 1.0;
    return {std::max(2, int(std::lround(width * scale))),
            std::max(2, int(std::lround(height * scale)))};
}

glm::mat4 sampleGridScale(glm::ivec2 grid) {
    // Pixel centres of n pixels sit at NDC (2i + 1) / n - 1; scaling clip x by (n - 1) / n
    // moves the first and last onto -1 and +1.
    glm::mat4 s(1.0f);
    s[0][0] = float(grid.x - 1) / float(grid.x);
    s[1][1] = float(grid.y - 1) / float(grid.y);
    return s;
}

void viewSamples(const std::vector<float>& depth, glm::ivec2 grid, const Camera& camera,
                 float aspect, ViewSamples& out) {
    out.points.clear();
    out.padConstant = out.padPerDepth = 0.0f;
    const glm::mat4 view = viewFromWorld(camera);
    const glm::mat4 clip = sampleGridScale(grid) * clipFromView(camera, aspect);
    const glm::mat4 worldFromClip = glm::inverse(clip * view);
    const glm::mat4 viewFromClip = glm::inverse(clip);
    // Sample spacing: the view's extent over (n - 1) gaps, the larger of the two axes.
    if (camera.projection == Projection::Orthographic) {
        out.padConstant = std::max((camera.right - camera.left) / float(grid.x - 1),
                                   (camera.top - camera.bottom) / float(grid.y - 1));
    } else {
        const float tanY = std::tan(0.5f * glm::radians(camera.fovyDegrees));
        const float a = camera.aspect > 0.0f ? camera.aspect : aspect;
        out.padPerDepth =
            std::max(2.0f * tanY * a / float(grid.x - 1), 2.0f * tanY / float(grid.y - 1));
    }
    out.nearest = std::numeric_limits<float>::max();
    out.farthest = 0.0f;
    out.points.reserve(depth.size());
    for (int y = 0; y < grid.y; ++y) {
        for (int x = 0; x < grid.x; ++x) {
            const float d = depth[std::size_t(y) * std::size_t(grid.x) + std::size_t(x)];
            if (!(d < 1.0f) || !(d >= 0.0f)) continue;  // the clear value (or garbage): empty
            const glm::vec4 ndc((2.0f * float(x) + 1.0f) / float(grid.x) - 1.0f,
                                (2.0f * float(y) + 1.0f) / float(grid.y) - 1.0f, 2.0f * d - 1.0f,
                                1.0f);
            const glm::vec4 world = worldFromClip * ndc;
            const glm::vec4 viewPoint = viewFromClip * ndc;
            if (!(std::abs(world.w) > 0.0f) || !(std::abs(viewPoint.w) > 0.0f)) continue;
            const float viewDepth = -viewPoint.z / viewPoint.w;
            out.points.emplace_back(glm::vec3(world) / world.w, viewDepth);
            out.nearest = std::min(out.nearest, viewDepth);
            out.farthest = std::max(out.farthest, viewDepth);
        }
    }
    if (out.points.empty()) out.nearest = 0.0f;
}

Aabb samplesInLight(const ViewSamples& samples, const glm::mat4& lightFromWorld, float depthFrom,
                    float depthTo) {
    Aabb box;
    const glm::mat3 turn(lightFromWorld);
    const glm::vec3 shift(lightFromWorld[3]);
    for (const glm::vec4& p : samples.points) {
        if (p.w < depthFrom || p.w > depthTo) continue;
        const glm::vec3 ls = turn * glm::vec3(p) + shift;
        const glm::vec3 pad(samples.pad(p.w));
        box.extend(ls - pad);
        box.extend(ls + pad);
    }
    return box;
}

float mapShareUsed(const ViewSamples& samples, const LightCameraFrame& frame, int mapSize,
                   float depthFrom, float depthTo, int cells) {
    const bool cube = frame.kind == FrameKind::Cube;
    const std::size_t faceCells = std::size_t(cells) * std::size_t(cells);
    std::vector<std::uint8_t> used((cube ? 6 : 1) * faceCells, 0);
    const glm::vec3 eye = glm::vec3(glm::inverse(frame.lightFromWorld)[3]);
    for (const glm::vec4& p : samples.points) {
        if (p.w < depthFrom || p.w > depthTo) continue;
        const glm::vec3 world(p);
        int face = 0;
        glm::mat4 clipFromWorld = frame.clipFromWorld();
        if (cube) {
            const glm::vec3 d = world - eye, a = glm::abs(d);
            const int axis = a.x >= a.y && a.x >= a.z ? 0 : a.y >= a.z ? 1 : 2;
            face = 2 * axis + (d[axis] < 0.0f ? 1 : 0);
            clipFromWorld = frame.faceClipFromWorld(face);
        }
        const glm::vec4 c = clipFromWorld * glm::vec4(world, 1.0f);
        if (!(c.w > 0.0f)) continue;
        const glm::vec3 ndc = glm::vec3(c) / c.w;
        if (std::abs(ndc.x) > 1.0f || std::abs(ndc.y) > 1.0f || std::abs(ndc.z) > 1.0f) continue;
        // The sample's footprint in map units: its pad over the map's world width there
        // (perspective and cube texels grow with the distance along the axis, clip w).
        const float texel =
            frame.texelWorldSize * (frame.kind == FrameKind::Orthographic ? 1.0f : c.w);
        const float padUv = texel > 0.0f ? samples.pad(p.w) / (texel * float(mapSize)) : 0.0f;
        const glm::vec2 uv = glm::vec2(ndc) * 0.5f + 0.5f;
        const glm::ivec2 lo =
            glm::clamp(glm::ivec2(glm::floor((uv - padUv) * float(cells))), 0, cells - 1);
        const glm::ivec2 hi =
            glm::clamp(glm::ivec2(glm::floor((uv + padUv) * float(cells))), 0, cells - 1);
        for (int y = lo.y; y <= hi.y; ++y) {
            for (int x = lo.x; x <= hi.x; ++x)
                used[std::size_t(face) * faceCells + std::size_t(y * cells + x)] = 1;
        }
    }
    std::size_t count = 0;
    for (std::uint8_t u : used)
        count += u;
    return float(count) / float(used.size());
}

}  // namespace gnomon::shadow
