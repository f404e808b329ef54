#include "shadow/ViewSamples.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>

#include "shadow/ShadowMath.h"

namespace gnomon::shadow {

namespace {

// Nearest distance from the origin to the segment a..b.
float distanceToSegment(const glm::vec3& a, const glm::vec3& b) {
    const glm::vec3 d = b - a;
    const float dd = glm::dot(d, d);
    const float t = dd > 0.0f ? std::clamp(-glm::dot(a, d) / dd, 0.0f, 1.0f) : 0.0f;
    return glm::length(a + t * d);
}

// The reach the functions below test samples against: none when `samples` already holds only
// what lies within it (samplesWithin, for this light: its apex, up to a rounding of the inverse
// its callers took it from).
float reachToTest(const ViewSamples& samples, const glm::vec3& apex, float reach) {
    const bool filtered = samples.filterReach > 0.0f && reach == samples.filterReach &&
                          glm::length(apex - samples.filterApex) <= 1e-5f * reach;
    return filtered ? 0.0f : reach;
}

// Does sample i, with the other end of its cell's segment when it has one, lie wholly farther
// than `reach` from `apex` (a spot's or point light's range: unlit there)? Never when reach <= 0.
bool beyondReach(const ViewSamples& samples, std::size_t i, const glm::vec3& apex, float reach) {
    if (!(reach > 0.0f)) return false;
    const std::size_t n = samples.points.size();
    std::size_t j = i;
    if (i + 1 < n && i < samples.farthestNext.size() && samples.farthestNext[i]) {
        j = i + 1;
    } else if (i > 0 && i - 1 < samples.farthestNext.size() && samples.farthestNext[i - 1]) {
        j = i - 1;
    }
    const glm::vec4& p = samples.points[i];
    const glm::vec4& q = samples.points[j];
    const float pad = std::max(samples.pad(p.w), samples.pad(q.w));
    return distanceToSegment(glm::vec3(p) - apex, glm::vec3(q) - apex) - pad > reach;
}

void chunkSamples(ViewSamples& s) {
    const std::size_t n = s.points.size(), count = (n + kSampleChunk - 1) / kSampleChunk;
    s.chunks.assign(count, Aabb{});
    s.chunkPads.assign(count, 0.0f);
    for (std::size_t i = 0; i < n; ++i) {
        // A pair's second point also counts in the chunk its first lies in.
        const std::size_t c = (i > 0 && s.farthestNext[i - 1] ? i - 1 : i) / kSampleChunk;
        for (std::size_t k : {c, i / kSampleChunk}) {
            s.chunks[k].extend(glm::vec3(s.points[i]));
            s.chunkPads[k] = std::max(s.chunkPads[k], s.pad(s.points[i].w));
        }
    }
}

}  // namespace

SampleGrid sampleGrid(int width, int height, int limit) {
    SampleGrid g;
    g.size = {std::max(1, width), std::max(1, height)};
    const int longer = std::max(g.size.x, g.size.y);
    g.block = std::max(1, (longer + limit - 1) / limit);
    g.cells = (g.size + g.block - 1) / g.block;
    return g;
}

void viewSamples(const std::vector<glm::vec2>& ranges, const SampleGrid& grid, const Camera& camera,
                 float aspect, ViewSamples& out) {
    static std::atomic<std::uint64_t> fillings{0};
    out.generation = ++fillings;
    out.filterReach = 0.0f;
    out.points.clear();
    out.farthestNext.clear();
    out.padConstant = out.padPerDepth = 0.0f;
    const glm::mat4 clip = clipFromView(camera, aspect);
    const glm::mat4 worldFromClip = glm::inverse(clip * viewFromWorld(camera));
    const glm::mat4 viewFromClip = glm::inverse(clip);
    // One cell's width in world units (the larger axis; cells at the far edges may be
    // partial, which only makes this generous).
    const glm::vec2 cellNdc = 2.0f * float(grid.block) / glm::vec2(grid.size);
    if (camera.projection == Projection::Orthographic) {
        out.padConstant = std::max(0.5f * (camera.right - camera.left) * cellNdc.x,
                                   0.5f * (camera.top - camera.bottom) * cellNdc.y);
    } else {
        const float tanY = std::tan(0.5f * glm::radians(camera.fovyDegrees));
        const float a = camera.aspect > 0.0f ? camera.aspect : aspect;
        out.padPerDepth = std::max(tanY * a * cellNdc.x, tanY * cellNdc.y);
    }
    out.nearest = std::numeric_limits<float>::max();
    out.farthest = 0.0f;
    out.points.reserve(2 * ranges.size());
    auto add = [&](const glm::vec2& ndcXy, float depth) {
        const glm::vec4 ndc(ndcXy, 2.0f * depth - 1.0f, 1.0f);
        const glm::vec4 world = worldFromClip * ndc;
        const glm::vec4 viewPoint = viewFromClip * ndc;
        if (!(std::abs(world.w) > 0.0f) || !(std::abs(viewPoint.w) > 0.0f)) return;
        const float viewDepth = -viewPoint.z / viewPoint.w;
        out.points.emplace_back(glm::vec3(world) / world.w, viewDepth);
        out.farthestNext.push_back(false);
        out.nearest = std::min(out.nearest, viewDepth);
        out.farthest = std::max(out.farthest, viewDepth);
    };
    for (int y = 0; y < grid.cells.y; ++y) {
        for (int x = 0; x < grid.cells.x; ++x) {
            const glm::vec2 r = ranges[std::size_t(y) * std::size_t(grid.cells.x) + std::size_t(x)];
            if (!(r.x < 1.0f) || !(r.x >= 0.0f) || !(r.y <= 1.0f)) continue;  // nothing there
            // The cell's centre: the middle of its pixels (a last cell may be partial).
            const glm::vec2 first = glm::vec2(x, y) * float(grid.block);
            const glm::vec2 end = glm::min(first + float(grid.block), glm::vec2(grid.size));
            const glm::vec2 centre = (first + end) / glm::vec2(grid.size) - 1.0f;
            const std::size_t before = out.points.size();
            add(centre, r.x);
            if (r.y > r.x) add(centre, r.y);
            if (out.points.size() == before + 2) out.farthestNext[before] = true;
        }
    }
    if (out.points.empty()) out.nearest = 0.0f;
    chunkSamples(out);
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

bool anySampleWithin(const ViewSamples& samples, const glm::vec3& apex, float reach) {
    reach = reachToTest(samples, apex, reach);
    for (std::size_t i = 0; i < samples.points.size(); ++i) {
        if (!beyondReach(samples, i, apex, reach)) return true;
    }
    return false;
}

void samplesWithin(const ViewSamples& samples, const glm::vec3& apex, float reach,
                   ViewSamples& out) {
    out.points.clear();
    out.farthestNext.clear();
    out.chunks.clear();  // walked point by point: a light's subset is small
    out.chunkPads.clear();
    out.filterApex = apex;
    out.filterReach = reach;
    out.padConstant = samples.padConstant;
    out.padPerDepth = samples.padPerDepth;
    out.generation = samples.generation;
    out.nearest = std::numeric_limits<float>::max();
    out.farthest = 0.0f;
    const std::size_t n = samples.points.size();
    const bool chunked = samples.chunks.size() == (n + kSampleChunk - 1) / kSampleChunk &&
                         samples.farthestNext.size() == n;
    std::size_t chunk = ~std::size_t(0);
    for (std::size_t i = 0; i < n;) {
        if (chunked && i / kSampleChunk != chunk) {
            chunk = i / kSampleChunk;
            // Every segment starting in the chunk lies in its box: wholly beyond, skip them all
            // (and the second point of a pair its last point starts).
            if (samples.chunks[chunk].distanceTo(apex) - samples.chunkPads[chunk] > reach) {
                i = (chunk + 1) * kSampleChunk;
                if (i < n && samples.farthestNext[i - 1]) ++i;
                continue;
            }
        }
        // A cell's pair is beyond reach or not as one (beyondReach tests their segment).
        const bool pair = i + 1 < n && i < samples.farthestNext.size() && samples.farthestNext[i];
        const std::size_t next = pair ? i + 2 : i + 1;
        if (!beyondReach(samples, i, apex, reach)) {
            for (std::size_t k = i; k < next; ++k) {
                out.points.push_back(samples.points[k]);
                out.farthestNext.push_back(pair && k == i);
                out.nearest = std::min(out.nearest, samples.points[k].w);
                out.farthest = std::max(out.farthest, samples.points[k].w);
            }
        }
        i = next;
    }
    if (out.points.empty()) out.nearest = 0.0f;
}

bool samplesDirection(const ViewSamples& samples, const glm::vec3& apex, glm::vec3& direction,
                      float reach) {
    reach = reachToTest(samples, apex, reach);
    glm::dvec3 sum(0.0);
    for (std::size_t i = 0; i < samples.points.size(); ++i) {
        const glm::vec4& p = samples.points[i];
        if (beyondReach(samples, i, apex, reach)) continue;
        const glm::vec3 d = glm::vec3(p) - apex;
        const float length = glm::length(d);
        if (!(length > samples.pad(p.w))) return false;
        sum += glm::dvec3(d / length);
    }
    if (!(glm::length(sum) > 0.0)) return false;
    direction = glm::vec3(glm::normalize(sum));
    return true;
}

bool samplesWindow(const ViewSamples& samples, const glm::mat4& lightFromWorld,
                   SampleWindow& window, const SampleWindow* limit, float reach) {
    window.lo = glm::vec2(std::numeric_limits<float>::max());
    window.hi = -window.lo;
    window.farthest = 0.0f;
    bool any = false;
    const glm::vec3 apex = reach > 0.0f ? glm::vec3(glm::inverse(lightFromWorld)[3]) : glm::vec3(0);
    reach = reachToTest(samples, apex, reach);
    for (std::size_t i = 0; i < samples.points.size(); ++i) {
        const glm::vec4& p = samples.points[i];
        if (beyondReach(samples, i, apex, reach)) continue;
        const glm::vec3 v = glm::vec3(lightFromWorld * glm::vec4(glm::vec3(p), 1.0f));
        const float depth = -v.z, pad = samples.pad(p.w);
        // Wholly behind the camera's plane: outside any limit (a cone narrower than 180°).
        if (limit && depth + pad < 0.0f) continue;
        // Wholly beside the limit's pyramid (x / -z beyond its widest tan on some side, with
        // the pad): a sample near the camera's plane but far to one side, which another of a
        // point light's faces holds (fitPointFace), does not make the window impossible.
        if (limit) {
            const float widest = std::max({std::abs(limit->lo.x), std::abs(limit->hi.x),
                                           std::abs(limit->lo.y), std::abs(limit->hi.y)});
            const float beside = std::max(std::abs(v.x), std::abs(v.y)) - pad;
            if (beside > widest * std::max(depth + pad, 0.0f)) continue;
        }
        if (!(depth > pad)) return false;
        const glm::vec2 t = glm::vec2(v) / depth;
        // A move by `pad` changes x / -z by at most pad (1 + |t|) / (depth - pad).
        const glm::vec2 reach = pad * (1.0f + glm::abs(t)) / (depth - pad);
        const glm::vec2 lo = t - reach, hi = t + reach;
        if (limit &&
            (glm::any(glm::lessThan(hi, limit->lo)) || glm::any(glm::greaterThan(lo, limit->hi)))) {
            continue;
        }
        window.lo = glm::min(window.lo, lo);
        window.hi = glm::max(window.hi, hi);
        window.farthest = std::max(window.farthest, depth + pad);
        any = true;
    }
    if (any && limit) {
        window.lo = glm::max(window.lo, limit->lo);
        window.hi = glm::min(window.hi, limit->hi);
    }
    return any;
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

namespace {

// Whether the segment a..b (light-relative) meets the pyramid of cube face `face` widened to
// [-half, half] in the face's tan units. The part in front of the face's plane projects to a
// segment of the face's plane, clipped to the square there (Liang and Barsky, 1984).
bool segmentMeetsFace(glm::vec3 a, glm::vec3 b, int face, float half) {
    const int axis = face / 2;
    const float sign = face % 2 ? -1.0f : 1.0f;
    const float eps = 1e-6f * std::max(glm::length(a), glm::length(b));
    const float fa = sign * a[axis], fb = sign * b[axis];
    if (fa < eps && fb < eps) return false;  // wholly behind the face's plane
    if (fa < eps) a += (b - a) * ((eps - fa) / (fb - fa));
    if (fb < eps) b += (a - b) * ((eps - fb) / (fa - fb));
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    const glm::vec2 p(a[u] / (sign * a[axis]), a[v] / (sign * a[axis]));
    const glm::vec2 q(b[u] / (sign * b[axis]), b[v] / (sign * b[axis]));
    const glm::vec2 d = q - p;
    float t0 = 0.0f, t1 = 1.0f;
    for (int k = 0; k < 2; ++k) {
        // half >= p[k] + t d[k] >= -half
        for (const float s : {1.0f, -1.0f}) {
            const float num = half - s * p[k], den = s * d[k];
            if (den == 0.0f) {
                if (num < 0.0f) return false;
            } else if (den > 0.0f) {
                t1 = std::min(t1, num / den);
            } else {
                t0 = std::max(t0, num / den);
            }
        }
    }
    return t0 <= t1;
}

}  // namespace

std::uint8_t cubeFacesSeen(const ViewSamples& samples, const glm::vec3& lightPosition,
                           float marginRadians, float reach) {
    // Past a tenth of a radian the widening below stops being a bound.
    constexpr float kMaxAngle = 0.1f;
    if (!(marginRadians >= 0.0f && marginRadians < kMaxAngle)) return kAllCubeFaces;
    reach = reachToTest(samples, lightPosition, reach);
    std::uint8_t faces = 0;
    const std::size_t n = samples.points.size();
    for (std::size_t i = 0; i < n; ++i) {
        if (beyondReach(samples, i, lightPosition, reach)) {
            if (i < samples.farthestNext.size() && samples.farthestNext[i]) ++i;  // its pair too
            continue;
        }
        const glm::vec3 a = glm::vec3(samples.points[i]) - lightPosition;
        glm::vec3 b = a;
        float pad = samples.pad(samples.points[i].w);
        if (i + 1 < n && i < samples.farthestNext.size() && samples.farthestNext[i]) {
            ++i;
            b = glm::vec3(samples.points[i]) - lightPosition;
            pad = std::max(pad, samples.pad(samples.points[i].w));
        }
        // Every direction within `angle` of the segment's: its pad seen from its nearest
        // point to the light, and the lookups' margin.
        const float distance = distanceToSegment(a, b);
        if (!(distance > pad)) return kAllCubeFaces;
        const float angle = std::asin(pad / distance) + marginRadians;
        if (!(angle < kMaxAngle)) return kAllCubeFaces;
        // Turning a direction by `angle` moves it at most 5 angle in a face's tan units while
        // they stay within 1.5 (the gradient of y / x over the unit sphere is at most 4.2 there).
        const float half = 1.0f + 5.0f * angle;
        for (int face = 0; face < 6; ++face) {
            if (!(faces & (1u << face)) && segmentMeetsFace(a, b, face, half))
                faces = std::uint8_t(faces | (1u << face));
        }
        if (faces == kAllCubeFaces) break;
    }
    return faces;
}

}  // namespace gnomon::shadow
