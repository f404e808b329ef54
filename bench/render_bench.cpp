// Frame time of every built-in scene at 512x512 through the public API: wall time of
// Renderer::render (shadow passes, main pass, read-back; the read-back waits for the GPU).
// Three cases side by side in one run: maps cached (static scenes keep their maps), maps
// re-rendered every frame, and shadows off, the reference a shadowed frame is judged by.
// Then the lookup filters side by side on tutorial-room (maps cached: the filter's cost is
// in the main pass).
#include <benchmark/benchmark.h>

#include <gnomon/gnomon.h>

namespace {

gnomon::Renderer& renderer() {
    static gnomon::Renderer r;
    return r;
}

enum Mode { kCached, kRerender, kOff };

void renderScene(benchmark::State& state, const std::string& name, Mode mode) {
    const gnomon::Scene scene = gnomon::builtinScene(name);
    gnomon::RenderOptions options = scene.options;
    options.width = options.height = 512;
    options.shadow.enabled = mode != kOff;
    renderer().render(scene, options);  // warm-up: programs, uploads
    int frame = 0;
    for (auto _ : state) {
        if (mode == kRerender) {
            // A depth-pass state change invalidates every cached map: a full shadow frame.
            options.shadow.biasSlope = (frame++ % 2) ? 1.5f : 1.51f;
        }
        benchmark::DoNotOptimize(renderer().render(scene, options));
    }
    state.counters["shadow_passes"] = renderer().lastFrameStats().shadowPasses;
}

const int kRegistered = [] {
    for (const gnomon::SceneInfo& info : gnomon::builtinScenes()) {
        for (auto [mode, label] :
             {std::pair{kCached, "maps-cached"}, std::pair{kRerender, "maps-rerendered"},
              std::pair{kOff, "shadows-off"}}) {
            benchmark::RegisterBenchmark((info.name + "/512/" + label).c_str(), renderScene,
                                         info.name, mode)
                ->Unit(benchmark::kMillisecond)
                ->UseRealTime();
        }
    }
    const std::pair<const char*, gnomon::ShadowFilter> filters[] = {
        {"none", gnomon::ShadowFilter::None},
        {"hw2x2", gnomon::ShadowFilter::Hw2x2},
        {"pcf3", gnomon::ShadowFilter::Pcf},
        {"poisson", gnomon::ShadowFilter::Poisson},
        {"pcss", gnomon::ShadowFilter::Pcss}};
    for (auto [label, filter] : filters) {
        benchmark::RegisterBenchmark(
            (std::string("filter/tutorial-room/512/") + label).c_str(),
            [filter](benchmark::State& state) {
                const gnomon::Scene scene = gnomon::builtinScene("tutorial-room");
                gnomon::RenderOptions options = scene.options;
                options.width = options.height = 512;
                options.shadow.filter = filter;
                renderer().render(scene, options);
                for (auto _ : state)
                    benchmark::DoNotOptimize(renderer().render(scene, options));
            })
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
    }
    return 0;
}();

}  // namespace

int main(int argc, char** argv) {
    gnomon::keepFreedHeap();  // as the gnomon tool does, so both time the same driver work
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
