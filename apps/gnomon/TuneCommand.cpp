#include "TuneCommand.h"

#include <algorithm>
#include <cstdio>

#include "OutputSet.h"
#include "Progress.h"
#include "SvgPlot.h"
#include "gnomon/gnomon.h"

namespace gnomon::cli {

CLI::App* addTuneCommand(CLI::App& app, TuneArgs& args) {
    CLI::App* cmd = app.add_subcommand(
        "tune",
        "search shadow settings for the least error against ray-traced truth in a time budget");
    cmd->add_option(
           "--scene", args.scene,
           "built-in scene name (see `gnomon scenes`), scene file (.json), glTF file (.gltf, "
           ".glb) or other model file (assimp: .obj, .ply, .fbx...)")
        ->required();
    cmd->add_option("--views", args.views,
                    "more views to score besides the scene's camera: a path file "
                    "(docs/tune.md), one view per camera")
        ->type_name("FILE");
    cmd->add_option("--budget-ms", args.options.budgetMs,
                    "frame-time budget, measured as bench measures (default: the starting "
                    "settings' own frame time)")
        ->type_name("MS");
    cmd->add_option("--sweeps", args.options.maxSweeps,
                    "most passes over the settings, 1..10 (default " +
                        std::to_string(args.options.maxSweeps) + ")")
        ->type_name("N");
    cmd->add_option("--time-limit", args.options.timeLimitSeconds,
                    "seconds the search may take, tracing included; at the limit it keeps the "
                    "best found so far (0: none; default " +
                        std::to_string(int(args.options.timeLimitSeconds)) + ")")
        ->type_name("S");
    cmd->add_option("--shift-check", args.options.checkShifted,
                    "score the best and the starting settings again with the view moved half "
                    "a pixel four ways, and choose the best only if it wins on every one "
                    "(default on)")
        ->type_name("on|off")
        ->check(CLI::IsMember({"on", "off"}).description(""));
    cmd->add_option("--out-dir", args.outDir,
                    "folder for tune.json (every trial), front.svg and tuned.json (default tune)")
        ->type_name("DIR");
    cmd->add_option("--out", args.out,
                    "the scene file with the chosen settings (default OUT-DIR/tuned.json)")
        ->type_name("FILE");
    args.flags.add(*cmd);
    return cmd;
}

namespace {

double pct(double f) {
    return 100.0 * f;
}

void printTrial(std::size_t i, const TuneTrial& t, double budget, const char* mark = "") {
    if (!t.failure.empty()) {
        std::printf("%5zu  failed (never chosen): %s: %s\n", i, t.flags.c_str(), t.failure.c_str());
        std::fflush(stdout);
        return;
    }
    std::printf("%5zu  %13.3f%%  %13.3f%%  %9.1f%s  %s%s\n", i, pct(t.misclassified),
                pct(t.awayFromEdges), t.frameMs, t.frameMs > budget ? "*" : " ",
                t.flags.empty() ? "(starting settings)" : t.flags.c_str(), mark);
    std::fflush(stdout);
}

// Error against frame time: every trial as a point, the front joined. Trials above 4x the
// starting error (acne everywhere) would flatten the rest: left out and counted in the title.
// The error axis turns logarithmic where the rest still spans more than a decade.
std::string frontSvg(const TuneResult& r, const std::string& scene) {
    const double cap = 4.0 * std::max(r.trials.front().error, 1e-4);
    std::vector<int> order;
    for (std::size_t i = 0; i < r.trials.size(); ++i)
        if (r.trials[i].error <= cap) order.push_back(int(i));
    std::sort(order.begin(), order.end(),
              [&](int a, int b) { return r.trials[a].frameMs < r.trials[b].frameMs; });
    Plot plot;
    char title[160];
    std::snprintf(title, sizeof title, "gnomon tune: %s (budget %.0f ms; %zu of %zu trials shown)",
                  scene.c_str(), r.budgetMs, order.size(), r.trials.size());
    plot.title = title;
    plot.xLabel = "frame ms";
    plot.yLabel = "misclassified + away from edges, %";
    plot.logYWhenWide = true;
    PlotSeries all{"every trial", {}, true}, front{"front", {}, false};
    for (int i : order) {
        const TuneTrial& t = r.trials[std::size_t(i)];
        const bool onFront = std::find(r.front.begin(), r.front.end(), i) != r.front.end();
        plot.x.push_back(t.frameMs);
        all.y.push_back(pct(t.error));
        front.y.push_back(onFront ? pct(t.error) : -1.0);
    }
    plot.series = {all, front};
    return toSvg(plot);
}

void printSummary(const TuneResult& r, double timeLimit) {
    const TuneTrial& start = r.trials.front();
    if (r.timedOut) {
        std::printf(
            "\nstopped at the time limit (%.0f s) after %zu trials and %d sweep(s): the "
            "best found so far is kept (--time-limit 0 searches to the end)\n",
            timeLimit, r.trials.size(), r.sweeps);
    }
    // The front, fastest first, with the starting settings in their place among it.
    std::printf("\nfront (nothing tried is both faster and better; <- marks the start):\n");
    bool startShown = false;
    for (int i : r.front) {
        if (!startShown && i != 0 && start.frameMs < r.trials[std::size_t(i)].frameMs) {
            printTrial(0, start, r.budgetMs, "  <- start, not on the front");
            startShown = true;
        }
        printTrial(std::size_t(i), r.trials[std::size_t(i)], r.budgetMs,
                   i == 0 ? "  <- start" : "");
        startShown = startShown || i == 0;
    }
    if (!startShown) printTrial(0, start, r.budgetMs, "  <- start, not on the front");
    if (r.beatsStart < 0) {
        std::printf("nothing tried beats the starting settings\n");
    } else {
        std::printf("trial %d beats the starting settings (%s)\n", r.beatsStart,
                    r.trials[std::size_t(r.beatsStart)].error < start.error ? "better, no slower"
                                                                            : "as good, faster");
    }
    if (r.best < 0) {
        std::printf("no setting tried fits the budget of %.1f ms\n", r.budgetMs);
        return;
    }
    const TuneTrial& best = r.trials[std::size_t(r.best)];
    if (r.chosen > 0 && r.sameQuality) {
        const TuneTrial& c = r.trials[std::size_t(r.chosen)];
        std::printf("same quality, %.0f %% cheaper: `%s` (%.1f ms from %.1f)\n",
                    100.0 * (1.0 - c.frameMs / start.frameMs), c.flags.c_str(), c.frameMs,
                    start.frameMs);
    }
    if (r.best == 0) {
        std::printf(
            "the starting settings are already the best within %.1f ms: %.3f%% "
            "misclassified, %.3f%% away from edges\n",
            r.budgetMs, pct(start.misclassified), pct(start.awayFromEdges));
        return;
    }
    std::printf(
        "best within %.1f ms: %s\n  misclassified %.3f%% (from %.3f%%, %.2fx), away "
        "from edges %.3f%% (from %.3f%%), %.1f ms (from %.1f)\n",
        r.budgetMs, best.flags.c_str(), pct(best.misclassified), pct(start.misclassified),
        start.misclassified > 0 ? best.misclassified / start.misclassified : 1.0,
        pct(best.awayFromEdges), pct(start.awayFromEdges), best.frameMs, start.frameMs);
    if (!r.shifted.done) return;
    std::printf(
        "on the views moved half a pixel right, left, up and down (error %%, best against "
        "starting settings):");
    for (std::size_t i = 0; i < r.shifted.bestErrors.size(); ++i)
        std::printf(" %.3f/%.3f", pct(r.shifted.bestErrors[i]), pct(r.shifted.startErrors[i]));
    if (r.shifted.holds) {
        std::printf("\n  the gain holds on every one: the best is chosen\n");
    } else {
        std::printf(
            "\n  the gain does not hold on every one, so it is the pixel grid's, not the "
            "setting's: the starting settings are kept, on the front within what half a pixel "
            "changes\n");
    }
}

}  // namespace

int runTune(const TuneArgs& args, bool verbose) {
    if (args.options.maxSweeps < 1 || args.options.maxSweeps > 10)
        throw Error(ErrorKind::InvalidInput, "--sweeps must be in 1..10");
    if (!(args.options.budgetMs >= 0.0 && args.options.budgetMs < 1e6))
        throw Error(ErrorKind::InvalidInput, "--budget-ms must be in [0, 1e6)");
    if (!(args.options.timeLimitSeconds >= 0.0 && args.options.timeLimitSeconds < 1e7))
        throw Error(ErrorKind::InvalidInput, "--time-limit must be in [0, 1e7) seconds");
    Scene scene = loadWithProgress(args.scene, args.flags.upAxis());
    args.flags.editSceneAndWarn(scene);
    const RenderOptions start = args.flags.resolve(scene);
    TuneOptions options = args.options;
    if (!args.views.empty()) options.extraViews = makeScenePath(args.views, scene, 0).cameras;
    OutputSet out(args.outDir, "--out-dir");
    ContextOptions context;
    context.verbose = verbose;
    Renderer renderer(context);
    std::printf("gnomon tune: %s, %d view(s), %dx%d; a trial per line (* over the budget)\n",
                scene.name.c_str(), 1 + int(options.extraViews.size()), start.width, start.height);
    std::printf("%5s  %14s  %14s  %10s  %s\n", "trial", "misclassified", "away from edges",
                "frame ms", "settings changed");
    TuneProgress progress;
    std::size_t shown = 0;
    double budget = options.budgetMs;
    const TuneResult r = tune(renderer, scene, start, options, &progress, [&](const TuneTrial& t) {
        if (shown == 0 && budget <= 0.0) budget = t.frameMs;
        printTrial(shown++, t, budget);
        if (interrupted()) progress.cancel = true;
    });
    printSummary(r, options.timeLimitSeconds);
    const std::string tuned = args.out.empty() ? out.file("tuned.json") : out.add(args.out);
    // Each light with the map size the chosen trial gave it (its own unless searched).
    if (r.chosen >= 0) applyMapSizes(r.trials[std::size_t(r.chosen)].mapSizes, scene);
    saveSceneFile(tuned, args.scene, scene,
                  r.chosen >= 0 ? r.trials[std::size_t(r.chosen)].options : start,
                  args.flags.ground);
    writeTextFile(out.file("tune.json"), toJson(r, scene.name));
    writeTextFile(out.file("front.svg"), frontSvg(r, scene.name));
    out.keep();
    std::printf(
        "wrote %s, %s/tune.json and front.svg (searched %.0f s, %.1f s of it tracing the "
        "references)\n",
        tuned.c_str(), args.outDir.c_str(), r.seconds, r.traceSeconds);
    if (r.interrupted) {
        throw Interrupted("interrupted while tuning; kept the best of the " +
                          std::to_string(r.trials.size()) + " trials finished");
    }
    return 0;
}

}  // namespace gnomon::cli
