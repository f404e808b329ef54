// The BVH tracer (truth/BvhTracer.cpp) against Embree's on the same scenes, both behind
// truth::ShadowRays. Random view rays meet the same object and triangle at the same distance,
// or (a tie) another surface at that same distance, for all but a few rays (kAgree below);
// random shadow rays let the same light through (masked and blended casters under every
// --blend-shadows rule, with the shared scenes), for all but as few. The reference
// traced on either gives the same shadows and the same score of a visibility. The shares of
// ties and of rays that differ are printed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <random>
#include <string>
#include <type_traits>

#include "gnomon/Scene.h"
#include "truth/Metrics.h"
#include "truth/Reference.h"
#include "truth/ShadowRays.h"

namespace gnomon {
namespace {

// The share of rays (and of reference cells) on which the two tracers must agree.
constexpr double kAgree = 0.999;

using truth::TracerKind;

std::string shared(const std::string& file) {
    return std::string(GNOMON_SHARED_SCENES) + "/" + file;
}

#define NEED_SHARED(file)                                                                   \
    if (!std::filesystem::exists(shared(file))) {                                           \
        GTEST_SKIP() << shared(file) << " is absent (the shared test scenes are not here)"; \
    }

struct Agreement {
    long viewRays = 0, viewSame = 0, viewTies = 0, viewHits = 0;
    long shadowRays = 0, shadowSame = 0, shadowBlocked = 0, shadowPartial = 0;
    long differences = 0;
    std::string examples;  // the first few rays that differ, for a failure's message
};

glm::vec3 randomUnit(std::mt19937& rng) {
    std::normal_distribution<float> n(0.0f, 1.0f);
    for (;;) {
        const glm::vec3 d(n(rng), n(rng), n(rng));
        if (glm::length(d) > 1e-3f) return glm::normalize(d);
    }
}

// Same: the same triangle at the same distance. Tie: another surface at the same distance
// (coplanar overlapping faces, as where the room's boxes stand on its floor, or the edge
// between two triangles), where either answer is right and which one a tracer gives
// depends on the order it visits them.
enum class Match { Same, Tie, Differ };
Match matchOf(const truth::TraceHit& a, const truth::TraceHit& b, float scale) {
    if (a.hit() != b.hit()) return Match::Differ;
    if (!a.hit()) return Match::Same;
    const bool sameT = std::fabs(a.t - b.t) <= 1e-4f * a.t + 1e-6f * scale;
    const float nl = glm::length(a.geometricNormal) * glm::length(b.geometricNormal);
    const bool same = a.object == b.object && a.triangle == b.triangle && sameT &&
                      std::fabs(a.u - b.u) < 1e-3f && std::fabs(a.v - b.v) < 1e-3f &&
                      glm::dot(a.geometricNormal, b.geometricNormal) >= 0.9999f * nl;
    return same ? Match::Same : sameT ? Match::Tie : Match::Differ;
}

// One shadow ray on both tracers: the same light through, the same tint where any passes.
bool sameShadow(const truth::ShadowRays& e, const truth::ShadowRays& b, const glm::vec3& from,
                const glm::vec3& dir, float tnear, float tfar, Agreement& a) {
    glm::vec3 te(1.0f), tb(1.0f);
    const float se = e.transmitted(from, dir, tnear, tfar, &te);
    const float sb = b.transmitted(from, dir, tnear, tfar, &tb);
    ++a.shadowRays;
    a.shadowBlocked += se == 0.0f;
    a.shadowPartial += se > 0.0f && (se < 1.0f || te != glm::vec3(1.0f));
    const bool same =
        std::fabs(se - sb) <= 1e-3f &&
        (se == 0.0f || glm::all(glm::lessThanEqual(glm::abs(te - tb), glm::vec3(1e-3f))));
    a.shadowSame += same;
    if (!same && ++a.differences <= 5) {
        char line[200];
        std::snprintf(line, sizeof line,
                      "\n  shadow ray: Embree %.6f (%.4f %.4f %.4f), BVH %.6f "
                      "(%.4f %.4f %.4f)",
                      se, te.r, te.g, te.b, sb, tb.r, tb.g, tb.b);
        a.examples += line;
    }
    return same;
}

// `rays` view rays (half from the camera through the scene's box, half from random points
// in it in random directions) on both tracers; from each surface the camera's rays meet, a
// shadow ray to every light the reference would trace and one in a random direction.
Agreement compare(const Scene& scene, const RenderOptions& options, int rays, std::uint32_t seed) {
    const truth::ShadowRays e(scene, options, TracerKind::Embree);
    const truth::ShadowRays b(scene, options, TracerKind::Bvh);
    glm::vec3 lo(INFINITY), hi(-INFINITY);
    for (std::size_t o = 0; o < scene.objects.size(); ++o) {
        for (const glm::vec3& p : e.positions(o)) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
    }
    const glm::vec3 eye = scene.camera.eye - e.origin();
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    Agreement a;
    for (int i = 0; i < rays; ++i) {
        const glm::vec3 target = lo + (hi - lo) * glm::vec3(unit(rng), unit(rng), unit(rng));
        const bool fromCamera = i % 2 == 0;
        const glm::vec3 from =
            fromCamera ? eye : lo + (hi - lo) * glm::vec3(unit(rng), unit(rng), unit(rng));
        const glm::vec3 dir = fromCamera && glm::length(target - eye) > 0.0f
                                  ? glm::normalize(target - eye)
                                  : randomUnit(rng);
        const float tfar = 4.0f * e.scale() + glm::length(eye);
        const truth::TraceHit he = e.tracer().nearest(from, dir, 0.0f, tfar);
        const truth::TraceHit hb = b.tracer().nearest(from, dir, 0.0f, tfar);
        ++a.viewRays;
        a.viewHits += he.hit();
        const Match m = matchOf(he, hb, e.scale());
        a.viewSame += m == Match::Same;
        a.viewTies += m == Match::Tie;
        if (m == Match::Differ && ++a.differences <= 5) {
            char line[200];
            std::snprintf(line, sizeof line,
                          "\n  view ray %d: Embree %d/%u t %.9g, BVH %d/%u t %.9g", i, he.object,
                          he.triangle, he.t, hb.object, hb.triangle, hb.t);
            a.examples += line;
        }
        if (!he.hit() || m != Match::Same) continue;
        // The point as the reference takes it, from the triangle's corners, and its normal
        // on the side the ray came from.
        const Mesh& mesh = scene.meshes[scene.objects[std::size_t(he.object)].mesh];
        const std::uint32_t* t = &mesh.indices[3 * std::size_t(he.triangle)];
        const std::vector<glm::vec3>& p = e.positions(std::size_t(he.object));
        const glm::vec3 point = (1.0f - he.u - he.v) * p[t[0]] + he.u * p[t[1]] + he.v * p[t[2]];
        glm::vec3 n = glm::normalize(he.geometricNormal);
        if (glm::dot(n, dir) > 0.0f) n = -n;
        for (std::size_t l = 0; l < scene.lights.size(); ++l) {
            glm::vec3 toLight;
            float distance = 0.0f;
            if (!e.towardsLight(l, point, toLight, distance)) continue;
            if (!(glm::dot(n, toLight) > truth::ShadowRays::kEdgeOnCosine)) continue;
            sameShadow(e, b, point, toLight, e.lead(point, n, toLight), distance, a);
        }
        glm::vec3 d = randomUnit(rng);
        if (glm::dot(d, n) < 0.0f) d = -d;
        sameShadow(e, b, point, d, e.lead(point, n, d), INFINITY, a);
    }
    return a;
}

void expectAgreement(const std::string& name, const Agreement& a) {
    const double rays = double(std::max(a.viewRays, 1L));
    const double same = double(a.viewSame) / rays, ties = double(a.viewTies) / rays;
    const double differ = double(a.viewRays - a.viewSame - a.viewTies) / rays;
    const double shadow = double(a.shadowSame) / double(std::max(a.shadowRays, 1L));
    std::printf(
        "%-30s view %ld rays (%ld hits): %.3f %% same hit, %.3f %% ties, %.3f %% differ; "
        "shadow %ld rays (%ld blocked, %ld partly passed): %.3f %% agree\n",
        name.c_str(), a.viewRays, a.viewHits, 100.0 * same, 100.0 * ties, 100.0 * differ,
        a.shadowRays, a.shadowBlocked, a.shadowPartial, 100.0 * shadow);
    EXPECT_GE(same + ties, kAgree) << name << a.examples;
    EXPECT_GE(same, 0.99) << name;
    EXPECT_GE(shadow, kAgree) << name << a.examples;
    // The rays test something: surfaces met, shadows cast and not.
    EXPECT_GT(a.viewHits, a.viewRays / 4) << name;
    EXPECT_GT(a.shadowBlocked, 0) << name;
    EXPECT_LT(a.shadowBlocked, a.shadowRays) << name;
}

TEST(BvhTracer, AgreesWithEmbreeOnBuiltinScenes) {
    for (const char* name : {"tutorial-room", "mixed-lights", "book-triangle", "course-cubes"}) {
        const Scene s = builtinScene(name);
        expectAgreement(name, compare(s, s.options, 20000, 17));
    }
}

TEST(BvhTracer, AgreesWithEmbreeOnMaskedAndBlendedSurfaces) {
    NEED_SHARED("AlphaBlendModeTest/AlphaBlendModeTest.glb");
    const Scene s = loadScene(shared("AlphaBlendModeTest/AlphaBlendModeTest.glb"));
    for (const BlendShadows blend : {BlendShadows::Dithered, BlendShadows::Coloured,
                                     BlendShadows::Opaque, BlendShadows::None}) {
        RenderOptions o = s.options;
        o.shadow.blendShadows = blend;
        const Agreement a = compare(s, o, 20000, 23);
        expectAgreement(std::string("AlphaBlendModeTest ") + toString(blend), a);
        if (blend == BlendShadows::Dithered || blend == BlendShadows::Coloured) {
            EXPECT_GT(a.shadowPartial, 0) << "no shadow ray passed a blended caster";
        }
    }
}

TEST(BvhTracer, AgreesWithEmbreeOnSponza) {
    NEED_SHARED("DabrovicSponza/dabrovic_sponza.glb");
    const Scene s = loadScene(shared("DabrovicSponza/dabrovic_sponza.glb"));
    expectAgreement("DabrovicSponza", compare(s, s.options, 4000, 29));
}

// The share of `cells` where the two references' arrays agree (within 1e-3).
template <typename T>
double agreeing(const std::vector<T>& a, const std::vector<T>& b) {
    long same = 0;
    for (std::size_t c = 0; c < a.size(); ++c) {
        if constexpr (std::is_same_v<T, glm::vec3>) {
            same += glm::all(glm::lessThanEqual(glm::abs(a[c] - b[c]), glm::vec3(1e-3f)));
        } else {
            same += std::fabs(double(a[c]) - double(b[c])) <= 1e-3;
        }
    }
    return a.empty() ? 1.0 : double(same) / double(a.size());
}

// The reference on either tracer: the same surfaces, lights and shadows (hard, soft and
// tinted where asked), and the same score of a visibility that is the Embree reference's
// shadows a pixel to the right (an error of the kind a shadow map makes along every edge).
void compareReferences(const std::string& name, const Scene& s, RenderOptions o,
                       truth::ReferenceOptions ro) {
    o.width = 160;
    o.height = 120;
    ro.tracer = TracerKind::Embree;
    const truth::Reference e = truth::traceReference(s, o, ro);
    ro.tracer = TracerKind::Bvh;
    const truth::Reference b = truth::traceReference(s, o, ro);
    ASSERT_EQ(e.hard.size(), b.hard.size());
    ASSERT_EQ(e.soft.size(), b.soft.size());
    ASSERT_EQ(e.tint.size(), b.tint.size());
    const double objects = agreeing(e.object, b.object), applies = agreeing(e.applies, b.applies);
    const double hard = agreeing(e.hard, b.hard), soft = agreeing(e.soft, b.soft);
    const double tint = agreeing(e.tint, b.tint);
    const double contacts = agreeing(e.nearOccluder, b.nearOccluder);
    const bool useSoft = !e.soft.empty();
    long cells = 0;
    for (const std::uint8_t a : e.applies)
        cells += a;
    std::vector<float> shifted(e.hard.size(), 1.0f), texel(e.hard.size());
    for (int y = 0; y < o.height; ++y) {
        for (int x = 0; x < o.width; ++x) {
            for (int l = 0; l < e.lights; ++l) {
                const std::size_t c = e.at(x, y, l), left = e.at(std::max(x - 1, 0), y, l);
                shifted[c] = useSoft ? e.soft[left] : e.hard[left];
                texel[c] = e.pixelWorld[c / std::size_t(e.lights)];
            }
        }
    }
    // As gnomon score compares (lab/Score.cpp): the band, along surfaces too with hard
    // shadows (more rays, on each reference's own tracer), the pixels of the same surface.
    auto score = [&](const truth::Reference& r) {
        std::vector<std::uint8_t> band = truth::aliasingBand(r, texel, 2.0f, useSoft);
        if (!useSoft) truth::extendBandAlongSurfaces(s, r, shifted, texel, 2.0f, band);
        long excluded = 0;
        const truth::Reference same = truth::onSameSurfaces(r, e.object, excluded);
        return truth::scoreVisibility(s, same, shifted, band, useSoft);
    };
    const truth::Scores se = score(e), sb = score(b);
    std::printf(
        "%-30s reference (%ld cells lit or shadowed) agrees: objects %.3f %%, applies "
        "%.3f %%, hard %.3f %%, soft %.3f %%, tint %.3f %%, contacts %.3f %%; "
        "misclassified %.5f (Embree) %.5f (BVH)\n",
        name.c_str(), cells, 100.0 * objects, 100.0 * applies, 100.0 * hard, 100.0 * soft,
        100.0 * tint, 100.0 * contacts, se.overall.misclassified, sb.overall.misclassified);
    ASSERT_GT(cells, 1000) << name;
    if (useSoft) {
        const long penumbra = std::count_if(e.soft.begin(), e.soft.end(),
                                            [](float v) { return v > 0.0f && v < 1.0f; });
        EXPECT_GT(penumbra, 100) << name << ": no penumbra to compare";
    }
    for (const double share : {objects, applies, hard, soft, tint, contacts})
        EXPECT_GE(share, kAgree) << name;
    EXPECT_GT(se.overall.misclassified, 0.0) << name << ": the shift is an error";
    // Scores are shares of the scored cells: within a thousandth of them.
    EXPECT_NEAR(sb.overall.misclassified, se.overall.misclassified, 1e-3) << name;
    EXPECT_NEAR(sb.overall.falseShadow, se.overall.falseShadow, 1e-3) << name;
    EXPECT_NEAR(sb.overall.leak, se.overall.leak, 1e-3) << name;
    EXPECT_NEAR(sb.overall.meanAbsError, se.overall.meanAbsError, 1e-3) << name;
    EXPECT_NEAR(sb.overall.leakOutsideBand, se.overall.leakOutsideBand, 1e-3) << name;
    EXPECT_NEAR(sb.overall.falseShadowOutsideBand, se.overall.falseShadowOutsideBand, 1e-3) << name;
    EXPECT_NEAR(double(sb.overall.pixels), double(se.overall.pixels),
                1e-3 * double(se.overall.pixels))
        << name;
}

TEST(BvhTracer, ReferenceScoresAsEmbreesDoes) {
    for (const char* name : {"tutorial-room", "mixed-lights", "book-triangle"}) {
        const Scene s = builtinScene(name);
        compareReferences(name, s, s.options, {});
    }
    const Scene room = builtinScene("tutorial-room");
    RenderOptions o = room.options;
    o.shadow.lightAngle = 8.0f;
    truth::ReferenceOptions soft;
    soft.softSamples = 16;
    soft.contactRange = 0.5f;
    compareReferences("tutorial-room soft", room, o, soft);
}

TEST(BvhTracer, ReferenceScoresAsEmbreesDoesThroughBlendedCasters) {
    NEED_SHARED("AlphaBlendModeTest/AlphaBlendModeTest.glb");
    const Scene s = loadScene(shared("AlphaBlendModeTest/AlphaBlendModeTest.glb"));
    for (const BlendShadows blend : {BlendShadows::Dithered, BlendShadows::Coloured}) {
        RenderOptions o = s.options;
        o.shadow.blendShadows = blend;
        compareReferences(std::string("AlphaBlendModeTest ") + toString(blend), s, o, {});
    }
}

}  // namespace
}  // namespace gnomon
