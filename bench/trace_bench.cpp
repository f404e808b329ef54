// The reference's two tracers side by side (truth/Tracer.h): Embree 3 and the project's own
// BVH (bvh/Bvh.h), on one thread, on a real scene (DabrovicSponza from the shared scenes,
// or --scene=PATH). Build time, then rays per second: coherent primary rays (a 60 degree
// view from inside the scene's box through a 640x480 grid), incoherent view rays (random
// origins in the scene's box, random directions) and incoherent shadow rays (the same, to
// a random distance). No timing is asserted anywhere; the figures are for reading.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "gnomon/Scene.h"
#include "truth/Tracer.h"

namespace {

using gnomon::truth::TracerKind;

std::string gScenePath = std::string(GNOMON_SHARED_SCENES) + "/DabrovicSponza/dabrovic_sponza.glb";

struct Ray {
    glm::vec3 origin, dir;
    float tfar;
};

// The scene as the tracers take it: world-space positions, every surface opaque.
struct Setup {
    gnomon::Scene scene;
    std::vector<std::vector<glm::vec3>> positions;
    std::vector<gnomon::truth::AlphaSurface> alpha;
    glm::vec3 lo{INFINITY}, hi{-INFINITY};
    std::vector<Ray> primary, random, shadow;

    gnomon::truth::TracerInput input() const { return {&scene, &positions, &alpha, {}}; }
};

const Setup& setup() {
    static const Setup s = [] {
        Setup s;
        s.scene = gnomon::loadScene(gScenePath);
        for (const gnomon::Object& obj : s.scene.objects) {
            const glm::mat4 m = obj.worldFromModelAt(0.0);
            std::vector<glm::vec3> p;
            for (const glm::vec3& q : s.scene.meshes[obj.mesh].positions) {
                p.push_back(glm::vec3(m * glm::vec4(q, 1.0f)));
                s.lo = glm::min(s.lo, p.back());
                s.hi = glm::max(s.hi, p.back());
            }
            s.positions.push_back(std::move(p));
        }
        s.alpha.resize(s.scene.objects.size());
        // A camera inside the scene (the atrium's floor, looking down its length): a file's
        // own camera may see it from outside, where most rays miss.
        const glm::vec3 extent = s.hi - s.lo;
        const glm::vec3 eye(s.lo.x + 0.5f * extent.x, s.lo.y + 0.2f * extent.y,
                            s.lo.z + 0.5f * extent.z);
        const glm::vec3 ahead = extent.x >= extent.z ? glm::vec3(1, 0, 0) : glm::vec3(0, 0, 1);
        const glm::vec3 right = glm::normalize(glm::cross(ahead, glm::vec3(0, 1, 0)));
        const glm::vec3 up = glm::cross(right, ahead);
        const float tanHalf = std::tan(glm::radians(30.0f));
        const int w = 640, h = 480;
        for (int y = 0; y < h; ++y) {
            for (int x = 0; x < w; ++x) {
                const float nx = (float(x) + 0.5f) / float(w) * 2.0f - 1.0f;
                const float ny = 1.0f - (float(y) + 0.5f) / float(h) * 2.0f;
                const glm::vec3 d =
                    ahead + right * (nx * tanHalf * float(w) / float(h)) + up * (ny * tanHalf);
                s.primary.push_back({eye, glm::normalize(d), INFINITY});
            }
        }
        std::mt19937 rng(1);
        std::uniform_real_distribution<float> unit(0.0f, 1.0f);
        std::normal_distribution<float> normal(0.0f, 1.0f);
        const float size = glm::length(s.hi - s.lo);
        for (int i = 0; i < 200000; ++i) {
            const glm::vec3 o = s.lo + (s.hi - s.lo) * glm::vec3(unit(rng), unit(rng), unit(rng));
            const glm::vec3 d = glm::normalize(glm::vec3(normal(rng), normal(rng), normal(rng)));
            s.random.push_back({o, d, INFINITY});
            s.shadow.push_back({o, d, unit(rng) * 0.5f * size});
        }
        std::printf("%s: %zu triangles\n", gScenePath.c_str(), gnomon::triangleCount(s.scene));
        return s;
    }();
    return s;
}

std::unique_ptr<gnomon::truth::Tracer> make(TracerKind kind) {
    const auto input = setup().input();
    return kind == TracerKind::Bvh ? gnomon::truth::makeBvhTracer(input)
                                   : gnomon::truth::makeEmbreeTracer(input);
}

void build(benchmark::State& state, TracerKind kind) {
    for (auto _ : state)
        benchmark::DoNotOptimize(make(kind));
}

enum class Rays { Primary, Random, Shadow };

void trace(benchmark::State& state, TracerKind kind, Rays which) {
    const Setup& s = setup();
    const std::vector<Ray>& rays = which == Rays::Primary  ? s.primary
                                   : which == Rays::Random ? s.random
                                                           : s.shadow;
    const auto tracer = make(kind);
    long hits = 0;
    for (auto _ : state) {
        hits = 0;
        for (const Ray& r : rays) {
            if (which == Rays::Shadow) {
                hits += tracer->transmitted(r.origin, r.dir, 0.0f, r.tfar, nullptr) < 0.5f;
            } else {
                hits += tracer->nearest(r.origin, r.dir, 0.0f, r.tfar).hit();
            }
        }
        benchmark::DoNotOptimize(hits);
    }
    state.counters["rays/s"] = benchmark::Counter(double(rays.size()) * double(state.iterations()),
                                                  benchmark::Counter::kIsRate);
    state.counters["hit share"] = double(hits) / double(rays.size());
}

void registerAll() {
    for (const TracerKind kind : {TracerKind::Embree, TracerKind::Bvh}) {
        const std::string k = gnomon::truth::toString(kind);
        benchmark::RegisterBenchmark(("build/" + k).c_str(), build, kind)
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
        for (auto [which, label] :
             {std::pair{Rays::Primary, "primary"}, std::pair{Rays::Random, "random"},
              std::pair{Rays::Shadow, "shadow"}}) {
            benchmark::RegisterBenchmark((std::string(label) + "/" + k).c_str(), trace, kind, which)
                ->Unit(benchmark::kMillisecond)
                ->UseRealTime();
        }
    }
}

}  // namespace

int main(int argc, char** argv) {
    // --scene=PATH: another scene than DabrovicSponza (taken out before benchmark's flags).
    int kept = 1;
    for (int i = 1; i < argc; ++i) {
        if (std::strncmp(argv[i], "--scene=", 8) == 0) {
            gScenePath = argv[i] + 8;
        } else {
            argv[kept++] = argv[i];
        }
    }
    argc = kept;
    if (!std::filesystem::exists(gScenePath)) {
        std::fprintf(stderr, "%s is absent: give a scene with --scene=PATH\n", gScenePath.c_str());
        return 1;
    }
    registerAll();
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
