#include "BenchCommand.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>
#include <sstream>

#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include "BenchSweep.h"
#include "LocalLights.h"
#include "OutputSet.h"
#include "Progress.h"
#include "SvgPlot.h"
#include "gnomon/gnomon.h"

namespace gnomon::cli {

CLI::App* addBenchCommand(CLI::App& app, BenchArgs& args) {
    CLI::App* cmd = app.add_subcommand(
        "bench",
        "time each pass of a frame (median and spread over N frames), optionally "
        "sweeping one parameter");
    cmd->add_option(
           "--scene", args.scene,
           "built-in scene name (see `gnomon scenes`), scene file (.json), glTF file (.gltf, "
           ".glb) or other model file (assimp: .obj, .ply, .fbx...)")
        ->required();
    cmd->add_option(
        "--frames", args.frames,
        "frames measured per run, 1..10000 (default " + std::to_string(args.frames) + ")");
    cmd->add_option("--warmup", args.warmup,
                    "frames rendered first and not measured, 0..1000 (default " +
                        std::to_string(args.warmup) + ")");
    cmd->add_flag("--static", args.staticMaps,
                  "keep unchanged shadow maps between frames (default: every frame redraws "
                  "every map, as when lights move)");
    cmd->add_flag("--moving-lights", args.movingLights,
                  "move every spot and point light a little each frame (a small circle), so "
                  "every map changes and --map-redraws decides how many are drawn again");
    cmd->add_option("--sweep", args.sweep,
                    "vary one parameter: lights (1..64 spot lights), local-lights (1..256 spot "
                    "and point lights of limited range in the open space the view looks into, "
                    "instead of the scene's own), map-size (256..8192), triangles (each "
                    "triangle split into 1..4096), cascades (1..4), filter, caster-detail "
                    "(stand-in casters, 1..0.01)");
    cmd->add_option("--values", args.values,
                    "comma-separated values for --sweep (default: the ranges above)");
    cmd->add_option("--write-scene", args.writeScene,
                    "with --sweep and one value in --values: write that value's scene (the "
                    "scene included, then its lights, camera and options) as a scene file, and "
                    "measure nothing")
        ->type_name("FILE");
    cmd->add_option("--out-dir", args.outDir,
                    "folder for bench.json, and for a sweep sweep.csv and sweep.svg "
                    "(default bench)");
    args.flags.add(*cmd);
    return cmd;
}

namespace {

struct Spread {
    double median = 0.0, p10 = 0.0, p90 = 0.0;
};

Spread spreadOf(std::vector<double> v) {
    Spread s;
    if (v.empty()) return s;
    std::sort(v.begin(), v.end());
    auto at = [&](double q) {
        const double i = q * double(v.size() - 1);
        const std::size_t lo = std::size_t(std::floor(i)), hi = std::size_t(std::ceil(i));
        return v[lo] + (v[hi] - v[lo]) * (i - double(lo));
    };
    s.median = at(0.5);
    s.p10 = at(0.1);
    s.p90 = at(0.9);
    return s;
}

struct PassResult {
    std::string name;
    Spread ms;
    std::uint64_t triangles = 0;
    std::int64_t fragments = -1;
};

struct Run {
    std::string value;  // the swept value ("" without a sweep)
    Spread frame;       // whole frames as an application draws them (no pass timing)
    Spread timedFrame;  // the frames whose passes were timed, a wait around each pass
    Spread shadow, main, shadowsOff, bareDepth, mainFloor;
    // Each measured frame's main pass over its floor drawn straight after it, the median of
    // those ratios: the machine's drift between the two (large on a shared machine) is
    // shared by both sides of each ratio, where two medians taken a run apart do not share it.
    double mainOverFloor = -1.0;
    std::vector<PassResult> passes;  // in frame order
    std::uint64_t shadowTriangles = 0, mainTriangles = 0;
    std::size_t shadowBytes = 0;
    int maps = 0, mapSize = 0;
    double mapsDrawn = 0.0, mapsWaiting = 0.0;  // a frame's, the median
    int momentPasses = 0;         // the moment filters' passes in the last frame measured
    int transmittancePasses = 0;  // coloured shadows' transmittance maps drawn, the same
    double rayPasses = 0.0;       // --shadow-rays uncertain: rays' own passes a frame, the median
};

// Wall time of whole frames drawn without pass timing (maps redrawn unless --static).
Spread untimedFrames(Renderer& renderer, const Scene& scene, const RenderOptions& options,
                     const BenchArgs& args) {
    std::vector<double> ms;
    Scene moved = args.movingLights ? scene : Scene{};
    for (int i = 0; i < args.warmup + args.frames; ++i) {
        if (!args.staticMaps && !args.movingLights) renderer.invalidateShadowMaps();
        if (args.movingLights) moveLights(scene, moved, i);
        const auto start = std::chrono::steady_clock::now();
        renderer.render(args.movingLights ? moved : scene, options);
        const auto stop = std::chrono::steady_clock::now();
        if (i >= args.warmup)
            ms.push_back(std::chrono::duration<double, std::milli>(stop - start).count());
    }
    return spreadOf(ms);
}

Run measure(Renderer& renderer, const Scene& scene, const RenderOptions& options,
            const BenchArgs& args, const std::string& label) {
    Run run;
    renderer.setPassTiming(true);
    std::map<std::string, std::vector<double>> perPass;
    std::vector<double> timedFrame, shadow, main, overFloor, drawn, waiting, rayPasses;
    std::atomic<int> framesDone{0};
    const int total = args.warmup + args.frames;
    const Activity activity(label, [&] { return double(framesDone.load()) / double(total); });
    Scene moved = args.movingLights ? scene : Scene{};
    for (int i = 0; i < total; ++i, ++framesDone) {
        checkInterrupt(label);
        if (!args.staticMaps && !args.movingLights) renderer.invalidateShadowMaps();
        if (args.movingLights) moveLights(scene, moved, i);
        const auto start = std::chrono::steady_clock::now();
        renderer.render(args.movingLights ? moved : scene, options);
        const double ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count();
        if (i < args.warmup) continue;
        const FrameStats stats = renderer.lastFrameStats();
        double shadowMs = 0.0, mainMs = 0.0;
        for (const PassTiming& p : stats.passes) {
            if (!perPass.count(p.name)) {
                run.passes.push_back({p.name, {}, p.triangles, p.fragments});
            }
            perPass[p.name].push_back(p.milliseconds);
            if (p.light >= 0) shadowMs += p.milliseconds;
            if (p.name == "main") mainMs += p.milliseconds;
        }
        timedFrame.push_back(ms);
        shadow.push_back(shadowMs);
        main.push_back(mainMs);
        const double floorMs = mainMs > 0.0 ? renderer.measureMainFloor() : -1.0;
        if (floorMs > 0.0) overFloor.push_back(mainMs / floorMs);
        run.shadowTriangles = stats.shadowTriangles;
        run.mainTriangles = stats.mainTriangles;
        run.shadowBytes = stats.shadowMapBytes;
        run.maps = stats.shadowMaps;
        drawn.push_back(double(stats.shadowPasses));
        waiting.push_back(double(stats.shadowMapsWaiting));
        run.momentPasses = stats.momentPasses;
        run.transmittancePasses = stats.transmittancePasses;
        rayPasses.push_back(double(stats.shadowRayPasses));
    }
    for (PassResult& p : run.passes)
        p.ms = spreadOf(perPass[p.name]);
    run.timedFrame = spreadOf(timedFrame);
    run.mapsDrawn = spreadOf(drawn).median;
    run.rayPasses = spreadOf(rayPasses).median;
    run.mapsWaiting = spreadOf(waiting).median;
    run.shadow = spreadOf(shadow);
    run.main = spreadOf(main);
    if (!overFloor.empty()) run.mainOverFloor = spreadOf(overFloor).median;
    // The reference points, in the same run: a bare depth-only draw of the casters at the
    // same map size (through the first light's camera), and the frame without shadows.
    run.mapSize = firstCasterMapSize(scene, options.shadow);
    std::vector<double> bare;
    for (int i = 0; i < args.frames; ++i) {
        const double b = renderer.measureBareDepthPass(run.mapSize);
        if (b >= 0.0) bare.push_back(b);
    }
    run.bareDepth = bare.empty() ? Spread{-1.0, -1.0, -1.0} : spreadOf(bare);
    // And the main pass's floor: the last frame's geometry and lookups, one diffuse term.
    std::vector<double> floor;
    for (int i = 0; i < args.frames; ++i) {
        const double f = renderer.measureMainFloor();
        if (f >= 0.0) floor.push_back(f);
    }
    run.mainFloor = floor.empty() ? Spread{-1.0, -1.0, -1.0} : spreadOf(floor);
    renderer.setPassTiming(false);
    // The frame itself as an application draws it: no wait between passes (each pass's
    // timing above waits before and after it, which keeps the driver from overlapping one
    // pass's setup with the last one's drawing), only the read-back's at the end.
    run.frame = untimedFrames(renderer, scene, options, args);
    RenderOptions off = options;
    off.shadow.enabled = false;
    run.shadowsOff = untimedFrames(renderer, scene, off, args);
    return run;
}

nlohmann::json spreadJson(const Spread& s) {
    return {{"median", s.median}, {"p10", s.p10}, {"p90", s.p90}};
}

nlohmann::json runJson(const Run& r) {
    nlohmann::json passes = nlohmann::json::array();
    for (const PassResult& p : r.passes) {
        passes.push_back({{"name", p.name},
                          {"ms", spreadJson(p.ms)},
                          {"triangles", p.triangles},
                          {"fragments", p.fragments}});
    }
    return {{"value", r.value},
            {"frame_ms", spreadJson(r.frame)},
            {"frame_timed_passes_ms", spreadJson(r.timedFrame)},
            {"shadow_ms", spreadJson(r.shadow)},
            {"main_ms", spreadJson(r.main)},
            {"shadows_off_ms", spreadJson(r.shadowsOff)},
            {"bare_depth_ms", spreadJson(r.bareDepth)},
            {"main_floor_ms", spreadJson(r.mainFloor)},
            {"main_over_floor", r.mainOverFloor},
            {"map_size", r.mapSize},
            {"maps", r.maps},
            {"maps_drawn", r.mapsDrawn},
            {"maps_waiting", r.mapsWaiting},
            {"shadow_map_bytes", r.shadowBytes},
            {"moment_passes", r.momentPasses},
            {"transmittance_passes", r.transmittancePasses},
            {"shadow_ray_passes", r.rayPasses},
            {"shadow_triangles", r.shadowTriangles},
            {"main_triangles", r.mainTriangles},
            {"passes", passes}};
}

void printRun(const Run& r) {
    std::printf("%-28s %10s %10s %10s %12s %12s\n", "pass", "median ms", "p10", "p90", "triangles",
                "fragments");
    for (const PassResult& p : r.passes) {
        std::printf("%-28s %10.2f %10.2f %10.2f %12llu %12s\n", p.name.c_str(), p.ms.median,
                    p.ms.p10, p.ms.p90, (unsigned long long)p.triangles,
                    p.fragments < 0 ? "-" : std::to_string(p.fragments).c_str());
    }
    std::printf("%-28s %10.2f %10.2f %10.2f\n", "frame, passes timed", r.timedFrame.median,
                r.timedFrame.p10, r.timedFrame.p90);
    std::printf("%-28s %10.2f %10.2f %10.2f\n", "frame (wall, render())", r.frame.median,
                r.frame.p10, r.frame.p90);
    std::printf("%-28s %d maps, %.0f drawn and %.0f waiting a frame (medians)\n", "  shadow maps",
                r.maps, r.mapsDrawn, r.mapsWaiting);
    std::printf("%-28s %10.2f %10.2f %10.2f\n", "  reference: shadows off", r.shadowsOff.median,
                r.shadowsOff.p10, r.shadowsOff.p90);
    if (r.bareDepth.median >= 0.0) {
        std::printf("%-28s %10.2f %10.2f %10.2f   (all casters, %d^2, no offsets)\n",
                    "  reference: bare depth", r.bareDepth.median, r.bareDepth.p10, r.bareDepth.p90,
                    r.mapSize);
    }
    if (r.mainFloor.median > 0.0) {
        std::printf("%-28s %10.2f %10.2f %10.2f   (main / floor %.2f of medians",
                    "  reference: main floor", r.mainFloor.median, r.mainFloor.p10, r.mainFloor.p90,
                    r.main.median / r.mainFloor.median);
        if (r.mainOverFloor > 0.0) std::printf(", %.2f frame by frame", r.mainOverFloor);
        std::printf(")\n");
    }
    std::printf("shadow maps: %d, %.1f MiB", r.maps, double(r.shadowBytes) / (1024.0 * 1024.0));
    if (r.momentPasses > 0) std::printf(", %d moment pass(es) a frame", r.momentPasses);
    if (r.transmittancePasses > 0) {
        std::printf(", %d transmittance pass(es) a frame", r.transmittancePasses);
    }
    if (r.rayPasses > 0.0) std::printf(", %.0f shadow-ray pass(es) a frame", r.rayPasses);
    std::printf("\n");
}

// A sweep's results: a table on stdout, and bench.json, sweep.csv and sweep.svg.
void writeSweep(const std::vector<Run>& runs, const std::string& sceneName,
                const RenderOptions& baseOptions, const BenchArgs& args, nlohmann::json& out,
                OutputSet& files) {
    out["sweep"] = args.sweep;
    out["runs"] = nlohmann::json::array();
    std::string csv =
        "value,frame_ms,frame_p10,frame_p90,shadow_ms,main_ms,shadows_off_ms,bare_depth_ms,"
        "maps,map_size,shadow_map_bytes,shadow_triangles,main_triangles\n";
    Plot plot;
    plot.title = "gnomon bench: " + sceneName + ", sweep of " + args.sweep + " (" +
                 std::to_string(baseOptions.width) + "x" + std::to_string(baseOptions.height) +
                 ", median of " + std::to_string(args.frames) + " frames)";
    const bool logAxis = args.sweep == "lights" || args.sweep == "local-lights" ||
                         args.sweep == "map-size" || args.sweep == "triangles";
    plot.xLabel = args.sweep == "triangles" ? "triangles per original triangle (totals in the CSV)"
                                            : args.sweep;
    plot.yLabel = "milliseconds";
    plot.series = {{"frame", {}},
                   {"shadow passes", {}},
                   {"main pass", {}},
                   {"shadows off (reference)", {}},
                   {"bare depth draw, 1 map (reference)", {}}};
    const int column = std::max(10, int(args.sweep.size()));
    std::printf("%-*s %10s %10s %10s %10s %12s %12s\n", column, args.sweep.c_str(), "frame ms",
                "shadow ms", "main ms", "off ms", "bare ms", "shadow MiB");
    for (std::size_t i = 0; i < runs.size(); ++i) {
        const Run& r = runs[i];
        out["runs"].push_back(runJson(r));
        char line[512];
        std::snprintf(line, sizeof line,
                      "%s,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%d,%d,%zu,%llu,%llu\n",
                      r.value.c_str(), r.frame.median, r.frame.p10, r.frame.p90, r.shadow.median,
                      r.main.median, r.shadowsOff.median, r.bareDepth.median, r.maps, r.mapSize,
                      r.shadowBytes, (unsigned long long)r.shadowTriangles,
                      (unsigned long long)r.mainTriangles);
        csv += line;
        std::printf("%-*s %10.2f %10.2f %10.2f %10.2f %12.2f %12.1f\n", column, r.value.c_str(),
                    r.frame.median, r.shadow.median, r.main.median, r.shadowsOff.median,
                    r.bareDepth.median, double(r.shadowBytes) / (1024.0 * 1024.0));
        plot.xTicks.push_back(r.value);
        plot.x.push_back(logAxis ? std::log2(std::max(1.0, std::stod(r.value))) : double(i));
        plot.series[0].y.push_back(r.frame.median);
        plot.series[1].y.push_back(r.shadow.median);
        plot.series[2].y.push_back(r.main.median);
        plot.series[3].y.push_back(r.shadowsOff.median);
        plot.series[4].y.push_back(r.bareDepth.median);
    }
    writeTextFile(files.file("bench.json"), out.dump(2) + "\n");
    writeTextFile(files.file("sweep.csv"), csv);
    writeTextFile(files.file("sweep.svg"), toSvg(plot));
    std::printf("wrote %s/bench.json, sweep.csv, sweep.svg\n", args.outDir.c_str());
}

// --write-scene: the scene of a sweep's one value as a scene file that includes the scene
// given and holds that value's lights, camera and options; nothing is measured (no GL).
int writeSweepScene(const BenchArgs& args, const Scene& base, const RenderOptions& baseOptions,
                    const std::vector<std::string>& values) {
    if (values.size() != 1) {
        throw Error(ErrorKind::InvalidInput,
                    "--write-scene needs --sweep and one value in --values, got " +
                        std::to_string(values.size()) + " values");
    }
    if (args.sweep == "triangles") {
        throw Error(ErrorKind::InvalidInput,
                    "--write-scene: a triangles sweep changes the meshes, which a scene file "
                    "takes from the scene it includes as they are");
    }
    Scene scene;
    RenderOptions options;
    applySweep(args.sweep, values[0], base, baseOptions, scene, options);
    scene.name = std::filesystem::path(args.writeScene).stem().string();
    scene.description = base.name + " with " + args.sweep + " " + values[0] +
                        " (written by gnomon bench --sweep " + args.sweep + " --values " +
                        values[0] + " --write-scene)";
    saveSceneFile(args.writeScene, args.scene, scene, options, args.flags.ground,
                  args.flags.upAxis());
    std::printf("wrote %s: %s, %zu lights\n", args.writeScene.c_str(), scene.description.c_str(),
                scene.lights.size());
    return 0;
}

}  // namespace

int runBench(const BenchArgs& args, bool verbose) {
    if (args.frames < 1 || args.frames > 10000) {
        throw Error(ErrorKind::InvalidInput,
                    "--frames must be in 1..10000, got " + std::to_string(args.frames));
    }
    if (args.warmup < 0 || args.warmup > 1000) {
        throw Error(ErrorKind::InvalidInput,
                    "--warmup must be in 0..1000, got " + std::to_string(args.warmup));
    }
    Scene base = loadWithProgress(args.scene, args.flags.upAxis());
    // Sweeps that replace the lights make a loader's added sun moot: no warning about it.
    if (args.sweep == "lights" || args.sweep == "local-lights")
        std::erase(base.warnings, std::string(kDefaultSunWarning));
    args.flags.editSceneAndWarn(base);
    const RenderOptions baseOptions = args.flags.resolve(base);
    const std::vector<std::string> values = sweepValues(args);
    if (!args.writeScene.empty()) return writeSweepScene(args, base, baseOptions, values);
    OutputSet files(args.outDir, "--out-dir");
    ContextOptions context;
    context.verbose = verbose;
    Renderer renderer(context);
    nlohmann::json out;
    out["scene"] = base.name;
    out["width"] = baseOptions.width;
    out["height"] = baseOptions.height;
    out["frames"] = args.frames;
    out["warmup"] = args.warmup;
    out["static_maps"] = args.staticMaps;
    out["moving_lights"] = args.movingLights;
    out["gl"] = renderer.glInfo();
    out["timing"] =
        "wall clock around glFinish() per pass (timer queries are unreliable on "
        "llvmpipe)";

    if (values.empty()) {
        std::fprintf(stderr, "gnomon bench: %s, %d frames after %d warm-up\n", base.name.c_str(),
                     args.frames, args.warmup);
        const Run run = measure(renderer, base, baseOptions, args, "measuring " + base.name);
        std::printf("gnomon bench: %s, %dx%d, %d frames (%s maps)\n", base.name.c_str(),
                    baseOptions.width, baseOptions.height, args.frames,
                    args.movingLights ? "moving lights'"
                    : args.staticMaps ? "kept"
                                      : "redrawn");
        printRun(run);
        out["runs"] = nlohmann::json::array({runJson(run)});
        writeTextFile(files.file("bench.json"), out.dump(2) + "\n");
        files.keep();
        std::printf("wrote %s/bench.json\n", args.outDir.c_str());
        return 0;
    }

    std::vector<Run> runs;
    try {
        for (std::size_t i = 0; i < values.size(); ++i) {
            Scene scene;
            RenderOptions options;
            applySweep(args.sweep, values[i], base, baseOptions, scene, options);
            const std::string step = "[" + std::to_string(i + 1) + "/" +
                                     std::to_string(values.size()) + "] " + args.sweep + " " +
                                     values[i];
            Run run = measure(renderer, scene, options, args, "measuring " + step);
            run.value = values[i];
            std::fprintf(stderr,
                         "gnomon bench: %s: frame %.1f ms (shadow passes %.1f, main %.1f; "
                         "maps drawn %.0f, waiting %.0f)\n",
                         step.c_str(), run.frame.median, run.shadow.median, run.main.median,
                         run.mapsDrawn, run.mapsWaiting);
            runs.push_back(std::move(run));
        }
    } catch (const Interrupted& e) {
        if (runs.empty()) throw;
        writeSweep(runs, base.name, baseOptions, args, out, files);
        files.keep();
        throw Interrupted(std::string(e.what()) + "; kept the " + std::to_string(runs.size()) +
                          " of " + std::to_string(values.size()) + " values finished");
    } catch (const Error& e) {
        // A value the renderer or the driver refuses (maps beyond a texture's size limit, more
        // lights than a uniform block holds): the values measured before it are kept too.
        if (runs.empty()) throw;
        writeSweep(runs, base.name, baseOptions, args, out, files);
        files.keep();
        throw Error(e.kind(), args.sweep + " " + values[runs.size()] + ": " + e.what() +
                                  " (kept the " + std::to_string(runs.size()) + " of " +
                                  std::to_string(values.size()) + " values finished)");
    }
    writeSweep(runs, base.name, baseOptions, args, out, files);
    files.keep();
    return 0;
}

}  // namespace gnomon::cli
