// Rays a second through the project's BVH in a fragment shader (shaders/bvh_trace.glsl, one
// ray per pixel, on the OpenGL driver at hand: llvmpipe here) beside Embree and the C++ BVH
// on the CPU's cores, on the same rays of a real scene (DabrovicSponza from the shared
// scenes, or --scene=PATH): shadow rays from the surfaces a view inside the scene sees toward
// a sun (coherent), shadow rays between random points (incoherent), and the view's own rays
// (nearest hit). Prints medians of --runs runs and how often the GPU's answer (hit or not)
// agrees with the CPU BVH's. No timing is asserted anywhere; the figures are for reading.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "bvh/Bvh.h"
#include "gl/Caps.h"
#include "gl/Context.h"
#include "gl/Objects.h"
#include "gl/Program.h"
#include "gnomon/Error.h"
#include "gnomon/Scene.h"
#include "truth/Tracer.h"

namespace bvh_layout {
#include "bvh_layout.glsl"  // NOLINT(bugprone-suspicious-include): shared with GLSL
}  // namespace bvh_layout

namespace {

using Clock = std::chrono::steady_clock;
namespace truth = gnomon::truth;
namespace bvh = gnomon::bvh;

struct Rays {
    std::string name;
    std::vector<glm::vec4> origins;     // xyz, tfar
    std::vector<glm::vec4> directions;  // xyz, 1: stop at any caster (shadow ray)
};

struct World {
    gnomon::Scene scene;
    std::vector<std::vector<glm::vec3>> positions;
    std::vector<truth::AlphaSurface> alpha;
    glm::vec3 lo{INFINITY}, hi{-INFINITY};
    truth::TracerInput input() const { return {&scene, &positions, &alpha, {}}; }
};

World load(const std::string& path) {
    World w;
    w.scene = gnomon::loadScene(path);
    for (const gnomon::Object& obj : w.scene.objects) {
        const glm::mat4 m = obj.worldFromModelAt(0.0);
        std::vector<glm::vec3> p;
        for (const glm::vec3& q : w.scene.meshes[obj.mesh].positions) {
            p.push_back(glm::vec3(m * glm::vec4(q, 1.0f)));
            w.lo = glm::min(w.lo, p.back());
            w.hi = glm::max(w.hi, p.back());
        }
        w.positions.push_back(std::move(p));
    }
    w.alpha.resize(w.scene.objects.size());
    return w;
}

bvh::Bvh buildBvh(const World& w) {
    std::vector<bvh::BvhTriangle> tris;
    for (std::size_t o = 0; o < w.scene.objects.size(); ++o) {
        const std::vector<std::uint32_t>& idx = w.scene.meshes[w.scene.objects[o].mesh].indices;
        const std::vector<glm::vec3>& p = w.positions[o];
        // Shadow rays pass through an object that casts no shadow (gnomon's ground under a
        // model), as the C++ BVH's (truth::BvhTracer) and the main pass's do.
        const float flags =
            w.scene.objects[o].castsShadows ? float(bvh::BvhTriangle::kCaster) : 0.0f;
        for (std::size_t t = 0; t + 2 < idx.size(); t += 3) {
            tris.push_back(
                {p[idx[t]], float(o), p[idx[t + 1]], float(t / 3), p[idx[t + 2]], flags});
        }
    }
    return bvh::Bvh(std::move(tris));
}

// A view from inside the scene's box (as bench/trace_bench.cpp), width x height rays.
Rays viewRays(const World& w, int width, int height) {
    Rays r{"view (nearest)", {}, {}};
    const glm::vec3 extent = w.hi - w.lo;
    const glm::vec3 eye(w.lo.x + 0.5f * extent.x, w.lo.y + 0.2f * extent.y,
                        w.lo.z + 0.5f * extent.z);
    const glm::vec3 ahead = extent.x >= extent.z ? glm::vec3(1, 0, 0) : glm::vec3(0, 0, 1);
    const glm::vec3 right = glm::normalize(glm::cross(ahead, glm::vec3(0, 1, 0)));
    const glm::vec3 up = glm::cross(right, ahead);
    const float tanHalf = std::tan(glm::radians(30.0f));
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const float nx = (float(x) + 0.5f) / float(width) * 2.0f - 1.0f;
            const float ny = 1.0f - (float(y) + 0.5f) / float(height) * 2.0f;
            const glm::vec3 d =
                glm::normalize(ahead + right * (nx * tanHalf * float(width) / float(height)) +
                               up * (ny * tanHalf));
            r.origins.emplace_back(eye, 1e30f);
            r.directions.emplace_back(d, 0.0f);
        }
    }
    return r;
}

// From where each view ray lands toward a sun high in the sky; misses keep the view ray.
Rays sunRays(const Rays& view, const truth::Tracer& cpu, float size) {
    Rays r{"shadow, coherent", {}, {}};
    const glm::vec3 sun = glm::normalize(glm::vec3(0.3f, 1.0f, 0.2f));
    for (std::size_t i = 0; i < view.origins.size(); ++i) {
        const glm::vec3 o(view.origins[i]), d(view.directions[i]);
        const truth::TraceHit h = cpu.nearest(o, d, 0.0f, 1e30f);
        const glm::vec3 p = h.hit() ? o + d * (h.t * (1.0f - 1e-4f)) : o;
        r.origins.emplace_back(p, size);
        r.directions.emplace_back(sun, 1.0f);
    }
    return r;
}

Rays randomRays(const World& w, std::size_t n) {
    Rays r{"shadow, incoherent", {}, {}};
    std::mt19937 rng(1);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    std::normal_distribution<float> normal(0.0f, 1.0f);
    const float size = glm::length(w.hi - w.lo);
    for (std::size_t i = 0; i < n; ++i) {
        const glm::vec3 o = w.lo + (w.hi - w.lo) * glm::vec3(unit(rng), unit(rng), unit(rng));
        const glm::vec3 d = glm::normalize(glm::vec3(normal(rng), normal(rng), normal(rng)));
        r.origins.emplace_back(o, unit(rng) * 0.5f * size);
        r.directions.emplace_back(d, 1.0f);
    }
    return r;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

// Each ray's answer on the CPU (hit or not), over `threads` threads; seconds taken.
double cpuTrace(const truth::Tracer& t, const Rays& rays, int threads, std::vector<char>& hit) {
    hit.assign(rays.origins.size(), 0);
    const auto start = Clock::now();
    std::vector<std::thread> pool;
    for (int k = 0; k < threads; ++k) {
        pool.emplace_back([&, k] {
            for (std::size_t i = std::size_t(k); i < rays.origins.size();
                 i += std::size_t(threads)) {
                const glm::vec3 o(rays.origins[i]), d(rays.directions[i]);
                const float tfar = rays.origins[i].w;
                hit[i] = rays.directions[i].w > 0.5f
                             ? t.transmitted(o, d, 0.0f, tfar, nullptr) < 0.5f
                             : t.nearest(o, d, 0.0f, tfar).hit();
            }
        });
    }
    for (std::thread& th : pool)
        th.join();
    return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv) {
    std::string path = std::string(GNOMON_SHARED_SCENES) + "/DabrovicSponza/dabrovic_sponza.glb";
    int runs = 5, width = 320, height = 240;
    for (int i = 1; i < argc; ++i) {
        if (std::strncmp(argv[i], "--scene=", 8) == 0) path = argv[i] + 8;
        if (std::strncmp(argv[i], "--runs=", 7) == 0) runs = std::max(1, std::atoi(argv[i] + 7));
    }
    if (!std::filesystem::exists(path)) {
        std::fprintf(stderr, "%s is absent: give a scene with --scene=PATH\n", path.c_str());
        return 1;
    }
    try {
        gnomon::gl::HeadlessContext context(false, false);
        gnomon::gl::ContextCaps caps;
        const World world = load(path);
        auto t0 = Clock::now();
        const bvh::Bvh tree = buildBvh(world);
        const double buildSeconds = std::chrono::duration<double>(Clock::now() - t0).count();
        const auto embree = truth::makeEmbreeTracer(world.input());
        const auto own = truth::makeBvhTracer(world.input());
        const Rays view = viewRays(world, width, height);
        const std::vector<Rays> sets = {sunRays(view, *embree, glm::length(world.hi - world.lo)),
                                        randomRays(world, view.origins.size()), view};
        std::printf("%s: %zu triangles, %zu nodes (built in %.2f s); %d x %d rays a set\n",
                    path.c_str(), tree.triangles().size(), tree.nodes().size(), buildSeconds, width,
                    height);
        namespace gl = gnomon::gl;
        const int rowTexels = bvh_layout::kBvhRowTexels;
        gl::Texture nodes = gl::Texture::texelRows("bvh nodes", &tree.nodes()[0].lo.x,
                                                   tree.nodes().size() * 2, rowTexels);
        gl::Texture triangles = gl::Texture::texelRows("bvh triangles", &tree.triangles()[0].p0.x,
                                                       tree.triangles().size() * 3, rowTexels);
        gl::Program program =
            gl::buildProgram("bvh rays", {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"},
                                          {GL_FRAGMENT_SHADER, "bvh_rays.frag.glsl"}});
        gl::Texture target = gl::Texture::plain2D("hits", GL_RGBA32F, width, height);
        gl::Framebuffer fb("hits");
        fb.attach(GL_COLOR_ATTACHMENT0, target);
        fb.checkComplete();
        gl::VertexArray empty("no attributes");
        const int threads = int(std::max(1u, std::thread::hardware_concurrency()));
        std::printf("%-20s %14s %14s %14s %9s\n", "rays", "GPU shader/s", "Embree/s", "C++ BVH/s",
                    "agree");
        for (const Rays& rays : sets) {
            gl::Texture origins = gl::Texture::texelRows("ray origins", &rays.origins[0].x,
                                                         rays.origins.size(), width);
            gl::Texture directions = gl::Texture::texelRows("ray directions", &rays.directions[0].x,
                                                            rays.directions.size(), width);
            glBindFramebuffer(GL_FRAMEBUFFER, fb.id());
            glViewport(0, 0, width, height);
            glDisable(GL_DEPTH_TEST);
            gl::use(program);
            gl::bindTexture(12, nodes);
            gl::bindTexture(13, triangles);
            gl::bindTexture(14, origins);
            gl::bindTexture(15, directions);
            glBindVertexArray(empty.id());
            std::vector<double> gpu, em, cpu;
            std::vector<char> cpuHit, embreeHit;
            for (int run = 0; run < runs; ++run) {
                glFinish();
                t0 = Clock::now();
                glDrawArrays(GL_TRIANGLES, 0, 3);
                glFinish();
                gpu.push_back(std::chrono::duration<double>(Clock::now() - t0).count());
                em.push_back(cpuTrace(*embree, rays, threads, embreeHit));
                cpu.push_back(cpuTrace(*own, rays, threads, cpuHit));
            }
            std::vector<glm::vec4> out(rays.origins.size());
            target.read(0, 0, 0, width, height, GL_RGBA, GL_FLOAT, out.size() * sizeof(glm::vec4),
                        out.data());
            std::size_t agree = 0;
            for (std::size_t i = 0; i < out.size(); ++i)
                agree += (out[i].x >= 0.0f) == (cpuHit[i] != 0);
            const double n = double(rays.origins.size());
            std::printf("%-20s %14.3g %14.3g %14.3g %8.4f%%\n", rays.name.c_str(), n / median(gpu),
                        n / median(em), n / median(cpu), 100.0 * double(agree) / n);
        }
        std::printf("CPU tracers on %d threads; llvmpipe on its own threads (LP_NUM_THREADS)\n",
                    threads);
    } catch (const gnomon::Error& e) {
        std::fprintf(stderr, "gpu_trace_bench: %s\n", e.what());
        return 1;
    }
    return 0;
}
