#include "truth/ErrorCauses.h"

#include <cmath>

#include "truth/Metrics.h"
#include "truth/ShadowRays.h"

namespace gnomon::truth {

namespace {

// Distance along the ray from `point` towards `dir` (starting `near` along it) to the first
// surface that stops at least half the light, no farther than `far`; -1 if none does.
// Doubling from `start` then halving the bracket: near occluders (contacts, the case that
// matters) are found to a few parts in a million of their distance, wherever the light is
// (a sun's distance is infinite).
float occluderDistance(const ShadowRays& rays, const glm::vec3& point, const glm::vec3& dir,
                       float near, float far, float start) {
    if (!(rays.transmitted(point, dir, near, far) < 0.5f)) return -1.0f;
    float lo = near, hi = std::fmin(std::fmax(start, 2.0f * near), far);
    while (!(rays.transmitted(point, dir, near, hi) < 0.5f)) {
        lo = hi;
        hi = std::fmin(2.0f * hi, far);
    }
    for (int i = 0; i < 20; ++i) {
        const float mid = 0.5f * (lo + hi);
        (rays.transmitted(point, dir, near, mid) < 0.5f ? hi : lo) = mid;
    }
    return hi;
}

void count(ErrorCauses& k, const ErrorCell& e) {
    const bool grazing = e.lightCosine < kGrazingCosine;
    if (!e.leak) {
        (grazing ? k.falseShadowGrazing : k.falseShadowOther) += 1;
    } else if (grazing) {
        k.leakGrazing += 1;
    } else if (e.occluderDistance >= 0.0f &&
               e.occluderDistance * e.lightCosine <= kContactTexels * e.texelWorld) {
        k.leakContact += 1;
    } else {
        k.leakOther += 1;
    }
}

}  // namespace

Explained explainErrors(const Reference& r, const std::vector<float>& visibility,
                        const std::vector<float>& texelWorld, const std::vector<std::uint8_t>& band,
                        bool soft) {
    Explained out;
    for (int y = 0; y < r.height; ++y) {
        for (int x = 0; x < r.width; ++x) {
            for (int l = 0; l < r.lights; ++l) {
                const std::size_t c = r.at(x, y, l);
                if (!r.applies[c]) continue;
                const bool refShadowed = occludedRef(r, c, soft);
                const bool shadowed = visibility[c] < 0.5f;
                if (shadowed == refShadowed) continue;
                ErrorCell e;
                e.x = x;
                e.y = y;
                e.light = l;
                e.leak = refShadowed;
                e.inBand = band[c] != 0;
                e.lightCosine = r.lightCosine[c];
                e.texelWorld = texelWorld[c];
                e.visibility = visibility[c];
                const std::size_t p = c / std::size_t(r.lights);
                if (e.leak && r.rays) {
                    const glm::vec3& point = r.surfacePoint[p];
                    glm::vec3 toLight(0.0f);
                    float distance = 0.0f;
                    if (r.rays->towardsLight(std::size_t(l), point, toLight, distance)) {
                        const float start = std::fmax(0.5f * e.texelWorld, 1e-30f);
                        const float near = r.rays->lead(point, r.surfaceNormal[p], toLight);
                        e.occluderDistance =
                            occluderDistance(*r.rays, point, toLight, near, distance, start);
                    }
                }
                if (!e.inBand) count(out.causes, e);
                out.cells.push_back(e);
            }
        }
    }
    return out;
}

}  // namespace gnomon::truth
