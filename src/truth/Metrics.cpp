#include "truth/Metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "truth/ShadowRays.h"

namespace gnomon::truth {

namespace {

constexpr float kFar = 1e20f;

// One row or column: d[i] = min_j (i - j)^2 + f[j] (the lower envelope of parabolas).
void distance1D(const float* f, float* d, int n, std::vector<int>& v, std::vector<float>& z) {
    v.resize(std::size_t(n));
    z.resize(std::size_t(n) + 1);
    int k = 0;
    v[0] = 0;
    z[0] = -std::numeric_limits<float>::infinity();
    z[1] = std::numeric_limits<float>::infinity();
    for (int q = 1; q < n; ++q) {
        float s = 0.0f;
        for (;;) {
            const int p = v[std::size_t(k)];
            s = ((f[q] + float(q) * float(q)) - (f[p] + float(p) * float(p))) /
                (2.0f * float(q) - 2.0f * float(p));
            if (s <= z[std::size_t(k)] && k > 0) {
                --k;
                continue;
            }
            break;
        }
        if (s <= z[std::size_t(k)]) {  // k == 0: replace the only parabola
            v[0] = q;
            z[1] = std::numeric_limits<float>::infinity();
            continue;
        }
        ++k;
        v[std::size_t(k)] = q;
        z[std::size_t(k)] = s;
        z[std::size_t(k) + 1] = std::numeric_limits<float>::infinity();
    }
    k = 0;
    for (int q = 0; q < n; ++q) {
        while (z[std::size_t(k) + 1] < float(q))
            ++k;
        const float dq = float(q - v[std::size_t(k)]);
        d[q] = dq * dq + f[v[std::size_t(k)]];
    }
}

// Which side of a shadow edge a cell lies on: 1 lit, 0 occluded or facing away from the
// light (the terminator, where a surface turns into its own attached shadow, is a shadow
// edge as much as a cast shadow's outline is), -1 neither (no surface, no light there).
int edgeSide(const Reference& r, std::size_t cell, bool soft) {
    if (r.applies[cell]) return occludedRef(r, cell, soft) ? 0 : 1;
    const bool facesAway = !r.lightCosine.empty() && r.lightCosine[cell] <= 0.0f;
    return facesAway ? 0 : -1;
}

// The band's reach at cell c (pixel p), in world units along the surface: bandTexels map
// texels, and never less than the pixel. The map samples the light's image plane: an edge it
// places within k texels there lies within k / cos(theta) texels along a receiver tilted by
// theta (a wall under a high sun, the ground under a low one), wherever the error came from
// (sampling, or a tolerance that grows with the receiver's slope).
float bandReach(const Reference& r, const std::vector<float>& texelWorld, float bandTexels,
                std::size_t p, std::size_t c) {
    const float cosine = r.lightCosine.empty() ? 1.0f : r.lightCosine[c];
    const float stretch = 1.0f / std::max(cosine, 1.0f / kBandMaxStretch);
    return std::max(r.pixelWorld[p], bandTexels * texelWorld[c] * stretch);
}

}  // namespace

bool occludedRef(const Reference& r, std::size_t cell, bool soft) {
    return soft ? r.soft[cell] < 0.5f : r.hard[cell] < 0.5f;
}

void extendBandAlongSurfaces(const Scene& scene, const Reference& r,
                             const std::vector<float>& visibility,
                             const std::vector<float>& texelWorld, float bandTexels,
                             std::vector<std::uint8_t>& band) {
    if (!r.rays || r.surfacePoint.empty()) return;
    const std::size_t pixels = std::size_t(r.width) * std::size_t(r.height);
    for (std::size_t p = 0; p < pixels; ++p) {
        const int o = r.object[p];
        if (o < 0 || scene.materials[scene.objects[std::size_t(o)].material].unlit) continue;
        for (int l = 0; l < r.lights; ++l) {
            const std::size_t c = p * std::size_t(r.lights) + std::size_t(l);
            if (!r.applies[c] || band[c]) continue;
            const bool refLit = r.hard[c] >= 0.5f;
            if (refLit == (visibility[c] >= 0.5f)) continue;  // right: nothing to excuse
            const float reach = bandReach(r, texelWorld, bandTexels, p, c);
            if (r.rays->otherSideWithin(std::size_t(l), r.surfacePoint[p], r.surfaceNormal[p],
                                        reach, refLit ? 1 : 0)) {
                band[c] = 1;
            }
        }
    }
}

std::vector<std::uint8_t> aliasingBand(const Reference& r, const std::vector<float>& texelWorld,
                                       float bandTexels, bool soft) {
    const std::size_t pixels = std::size_t(r.width) * std::size_t(r.height);
    std::vector<std::uint8_t> band(pixels * std::size_t(r.lights), 0);
    std::vector<std::uint8_t> seeds(pixels);
    for (int l = 0; l < r.lights; ++l) {
        std::fill(seeds.begin(), seeds.end(), 0);
        bool any = false;
        for (int y = 0; y < r.height; ++y) {
            for (int x = 0; x < r.width; ++x) {
                const int here = edgeSide(r, r.at(x, y, l), soft);
                if (here < 0) continue;
                const int nx[2] = {x + 1, x}, ny[2] = {y, y + 1};
                for (int k = 0; k < 2; ++k) {
                    if (nx[k] >= r.width || ny[k] >= r.height) continue;
                    const int there = edgeSide(r, r.at(nx[k], ny[k], l), soft);
                    if (there >= 0 && there != here) {
                        seeds[std::size_t(y) * std::size_t(r.width) + std::size_t(x)] = 1;
                        seeds[std::size_t(ny[k]) * std::size_t(r.width) + std::size_t(nx[k])] = 1;
                        any = true;
                    }
                }
            }
        }
        if (!any) continue;
        const std::vector<float> d2 = squaredDistance(seeds, r.width, r.height);
        for (std::size_t p = 0; p < pixels; ++p) {
            const std::size_t c = p * std::size_t(r.lights) + std::size_t(l);
            if (!r.applies[c]) continue;
            const float radius = r.pixelWorld[p] > 0.0f
                                     ? bandReach(r, texelWorld, bandTexels, p, c) / r.pixelWorld[p]
                                     : 1.0f;
            band[c] = d2[p] <= radius * radius;
        }
    }
    return band;
}

std::vector<float> squaredDistance(const std::vector<std::uint8_t>& seeds, int width, int height) {
    std::vector<float> grid(seeds.size());
    for (std::size_t i = 0; i < seeds.size(); ++i)
        grid[i] = seeds[i] ? 0.0f : kFar;
    const int longest = std::max(width, height);
    std::vector<float> f(static_cast<std::size_t>(longest));
    std::vector<float> d(static_cast<std::size_t>(longest));
    std::vector<int> v;
    std::vector<float> z;
    for (int x = 0; x < width; ++x) {  // columns
        for (int y = 0; y < height; ++y)
            f[std::size_t(y)] = grid[std::size_t(y) * std::size_t(width) + std::size_t(x)];
        distance1D(f.data(), d.data(), height, v, z);
        for (int y = 0; y < height; ++y)
            grid[std::size_t(y) * std::size_t(width) + std::size_t(x)] = d[std::size_t(y)];
    }
    for (int y = 0; y < height; ++y) {  // then rows
        float* row = &grid[std::size_t(y) * std::size_t(width)];
        std::copy(row, row + width, f.begin());
        distance1D(f.data(), row, width, v, z);
    }
    return grid;
}

Reference onSameSurfaces(const Reference& r, const std::vector<int>& object, long& excluded) {
    excluded = 0;
    Reference same = r;
    const std::size_t pixels = std::size_t(r.width) * std::size_t(r.height);
    if (object.size() != pixels || r.object.size() != pixels) return same;
    const std::size_t lights = std::size_t(r.lights);
    for (std::size_t p = 0; p < pixels; ++p) {
        if (object[p] == r.object[p]) continue;
        bool applied = false;
        for (std::size_t l = 0; l < lights; ++l) {
            applied = applied || r.applies[p * lights + l];
            same.applies[p * lights + l] = 0;
        }
        excluded += applied;
    }
    return same;
}

Scores scoreVisibility(const Scene& scene, const Reference& r, const std::vector<float>& visibility,
                       const std::vector<std::uint8_t>& band, bool soft) {
    struct Counts {
        long pixels = 0, band = 0, falseShadow = 0, leak = 0, falseOut = 0, leakOut = 0;
        long contact = 0, contactLeak = 0;
        double absError = 0.0;
    };
    const bool contacts = !r.nearOccluder.empty();
    std::vector<Counts> perLight(std::size_t(r.lights));
    const std::size_t pixels = std::size_t(r.width) * std::size_t(r.height);
    for (std::size_t p = 0; p < pixels; ++p) {
        for (int l = 0; l < r.lights; ++l) {
            const std::size_t c = p * std::size_t(r.lights) + std::size_t(l);
            if (!r.applies[c]) continue;
            Counts& k = perLight[std::size_t(l)];
            const bool refShadowed = occludedRef(r, c, soft);
            const bool shadowed = visibility[c] < 0.5f;
            ++k.pixels;
            k.band += band[c];
            if (shadowed && !refShadowed) {
                ++k.falseShadow;
                k.falseOut += !band[c];
            } else if (!shadowed && refShadowed) {
                ++k.leak;
                k.leakOut += !band[c];
            }
            k.absError += std::fabs(double(visibility[c]) - (soft ? r.soft[c] : r.hard[c]));
            if (contacts && r.nearOccluder[c]) {
                ++k.contact;
                k.contactLeak += !shadowed;
            }
        }
    }
    auto finish = [](const Counts& k, ShadowScore& s) {
        s.pixels = k.pixels;
        s.bandPixels = k.band;
        const double n = k.pixels > 0 ? double(k.pixels) : 1.0;
        s.falseShadow = double(k.falseShadow) / n;
        s.leak = double(k.leak) / n;
        s.misclassified = s.falseShadow + s.leak;
        s.falseShadowOutsideBand = double(k.falseOut) / n;
        s.leakOutsideBand = double(k.leakOut) / n;
        s.meanAbsError = k.absError / n;
        s.contactPixels = k.contact;
        s.contactLeak = k.contact > 0 ? double(k.contactLeak) / double(k.contact) : 0.0;
    };
    Scores out;
    out.overall.type = "all";
    Counts total;
    for (std::size_t l = 0; l < perLight.size(); ++l) {
        const Counts& k = perLight[l];
        if (k.pixels == 0) continue;
        ShadowScore s;
        s.light = int(l);
        s.type = toString(scene.lights[l].type);
        finish(k, s);
        out.lights.push_back(s);
        total.pixels += k.pixels;
        total.band += k.band;
        total.falseShadow += k.falseShadow;
        total.leak += k.leak;
        total.falseOut += k.falseOut;
        total.leakOut += k.leakOut;
        total.absError += k.absError;
        total.contact += k.contact;
        total.contactLeak += k.contactLeak;
    }
    finish(total, out.overall);
    return out;
}

Image errorMap(const Reference& r, const std::vector<float>& visibility,
               const std::vector<std::uint8_t>& band, bool soft, const Image& render) {
    Image out(r.width, r.height, 3);
    for (int y = 0; y < r.height; ++y) {
        for (int x = 0; x < r.width; ++x) {
            const std::uint8_t* c = render.at(x, y);
            const std::uint8_t grey = std::uint8_t((int(c[0]) + int(c[1]) + int(c[2])) / 3 * 2 / 5);
            int kind = 0;  // 1 false shadow in band, 2 leak in band, 3 false, 4 leak
            for (int l = 0; l < r.lights; ++l) {
                const std::size_t cell = r.at(x, y, l);
                if (!r.applies[cell]) continue;
                const bool refShadowed = occludedRef(r, cell, soft);
                const bool shadowed = visibility[cell] < 0.5f;
                if (shadowed == refShadowed) continue;
                const int k = (shadowed ? 1 : 2) + (band[cell] ? 0 : 2);
                kind = std::max(kind, k);
            }
            static const std::uint8_t kColours[5][3] = {
                {0, 0, 0}, {255, 170, 170}, {170, 200, 255}, {255, 40, 40}, {40, 120, 255}};
            std::uint8_t* o = out.at(x, y);
            for (int i = 0; i < 3; ++i)
                o[i] = kind == 0 ? grey : kColours[kind][i];
        }
    }
    return out;
}

namespace {
// A cell's transmitted-light error (mean over channels, 0..1) under coloured shadows, or < 0
// where neither the renderer nor the reference tinted the light (no channel below 1 by more
// than half an 8-bit step).
float tintError(const Reference& r, const std::vector<float>& visibility,
                const std::vector<float>& tint, bool soft, std::size_t c) {
    constexpr float kTinted = 1.0f - 0.5f / 255.0f;
    if (!r.applies[c]) return -1.0f;
    const glm::vec3 mine(tint[3 * c], tint[3 * c + 1], tint[3 * c + 2]);
    const glm::vec3& theirs = r.tint[c];
    const float least = std::min({mine.x, mine.y, mine.z, theirs.x, theirs.y, theirs.z});
    if (!(least < kTinted)) return -1.0f;
    const glm::vec3 d = glm::abs(mine * visibility[c] - theirs * (soft ? r.soft[c] : r.hard[c]));
    return (d.x + d.y + d.z) / 3.0f;
}

bool tintScored(const Reference& r, const std::vector<float>& visibility,
                const std::vector<float>& tint) {
    const std::size_t cells = r.applies.size();
    return r.tint.size() == cells && tint.size() == 3 * cells && visibility.size() == cells;
}
}  // namespace

TintScore scoreTint(const Reference& r, const std::vector<float>& visibility,
                    const std::vector<float>& tint, const std::vector<std::uint8_t>& band,
                    bool soft) {
    TintScore score;
    if (!tintScored(r, visibility, tint)) return score;
    double sum = 0.0, sumOutside = 0.0, sumColour = 0.0;
    for (std::size_t c = 0; c < r.applies.size(); ++c) {
        const float error = tintError(r, visibility, tint, soft, c);
        if (error < 0.0f) continue;
        ++score.cells;
        sum += error;
        if (!band[c]) {
            ++score.cellsOutsideBand;
            sumOutside += error;
        }
        if (visibility[c] >= 0.5f && (soft ? r.soft[c] : r.hard[c]) >= 0.5f) {
            const glm::vec3 d =
                glm::abs(glm::vec3(tint[3 * c], tint[3 * c + 1], tint[3 * c + 2]) - r.tint[c]);
            ++score.cellsBothLit;
            sumColour += (d.x + d.y + d.z) / 3.0f;
        }
    }
    if (score.cells > 0) score.meanError = sum / double(score.cells);
    if (score.cellsBothLit > 0) score.meanColourError = sumColour / double(score.cellsBothLit);
    if (score.cellsOutsideBand > 0) {
        score.meanErrorOutsideBand = sumOutside / double(score.cellsOutsideBand);
    }
    return score;
}

Image tintErrorMap(const Reference& r, const std::vector<float>& visibility,
                   const std::vector<float>& tint, bool soft, const Image& render) {
    Image out(r.width, r.height, 3);
    const bool scored = tintScored(r, visibility, tint);
    for (int y = 0; y < r.height; ++y) {
        for (int x = 0; x < r.width; ++x) {
            const std::uint8_t* c = render.at(x, y);
            const std::uint8_t grey = std::uint8_t((int(c[0]) + int(c[1]) + int(c[2])) / 3 * 2 / 5);
            float worst = -1.0f;
            for (int l = 0; scored && l < r.lights; ++l)
                worst = std::max(worst, tintError(r, visibility, tint, soft, r.at(x, y, l)));
            std::uint8_t* o = out.at(x, y);
            if (worst < 0.0f) {
                o[0] = o[1] = o[2] = grey;
                continue;
            }
            // Tinted: dark green when right, through yellow (4/255) to red (16/255 and more).
            const float t = std::clamp(worst * 255.0f / 16.0f, 0.0f, 1.0f);
            const float green = t < 0.25f ? 0.45f + 2.2f * t : 1.0f - (t - 0.25f) / 0.75f;
            o[0] = std::uint8_t(255.0f * std::min(1.0f, 4.0f * t));
            o[1] = std::uint8_t(255.0f * std::clamp(green, 0.0f, 1.0f));
            o[2] = 0;
        }
    }
    return out;
}

}  // namespace gnomon::truth
