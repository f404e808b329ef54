#include "ScoreCommand.h"

#include <algorithm>
#include <cstdarg>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "OutputSet.h"
#include "Progress.h"

#include "gnomon/gnomon.h"

namespace gnomon::cli {

CLI::App* addScoreCommand(CLI::App& app, ScoreArgs& args) {
    CLI::App* cmd = app.add_subcommand(
        "score", "render one frame and score its shadows against a ray-traced reference");
    cmd->add_option(
           "--scene", args.scene,
           "built-in scene name (see `gnomon scenes`), scene file (.json), glTF file (.gltf, "
           ".glb) or other model file (assimp: .obj, .ply, .fbx...)")
        ->required();
    cmd->add_option("--out-dir", args.outDir,
                    "folder for render.png, errors.png (false shadow red, leaks blue, pale "
                    "inside the aliasing band), score.json, errors.csv (a row per misclassified "
                    "pixel and light) and, where the scene has coloured shadows (blended casters "
                    "with --blend-shadows coloured), tint-errors.png; with --path, path.json and "
                    "the --error-maps (default score)")
        ->type_name("DIR");
    cmd->add_option("--band", args.options.bandTexels,
                    "aliasing band: map texels either side of a reference shadow boundary "
                    "(along the surface), 0..64 (default " +
                        std::to_string(int(args.options.bandTexels)) + ")");
    cmd->add_option("--soft-samples", args.options.softSamples,
                    "rays per pixel to the light's surface for the soft reference (filter pcss), "
                    "1..4096 (default " +
                        std::to_string(args.options.softSamples) + ")");
    cmd->add_option("--contact-range", args.options.contactRange,
                    "also score the leak at contacts: over the pixels whose occluder lies "
                    "within this distance along the shadow ray, world units (default: "
                    "--contact-length when contact shadows are on, else not scored)")
        ->check(CLI::NonNegativeNumber);
    cmd->add_option("--max-error", args.maxError,
                    "exit 3 when the overall misclassified fraction exceeds this, 0..1 "
                    "(default: never)");
    cmd->add_option("--path", args.path,
                    "score every frame of a path and the flicker between frames: orbit, dolly, "
                    "sun, still, or a path file (docs/tune.md); writes path.json")
        ->type_name("NAME|FILE");
    cmd->add_option("--frames", args.frames,
                    "frames of --path, 2..10000 (default " + std::to_string(args.frames) +
                        "; a path file: its first N, 0 = all)")
        ->type_name("N");
    cmd->add_flag("--error-maps", args.errorMaps,
                  "with --path: errors-NNN.png per frame, flicker in yellow");
    args.flags.add(*cmd);
    return cmd;
}

namespace {

// What score prints fits a terminal of this many columns.
constexpr std::size_t kColumns = 80;

// `text` and a newline, broken at spaces into lines of at most kColumns, the lines after
// the first indented (a word longer than a line keeps a line of its own).
void printWrapped(const std::string& text) {
    std::string line, word;
    bool empty = true;  // no word on the line yet
    std::istringstream words(text);
    while (words >> word) {
        if (!empty && line.size() + 1 + word.size() > kColumns) {
            std::printf("%s\n", line.c_str());
            line = "  ";
            empty = true;
        }
        line += (empty ? "" : " ") + word;
        empty = false;
    }
    std::printf("%s\n", line.c_str());
}
// printf into a string (checked as printf's format is).
[[gnu::format(printf, 1, 2)]] std::string format(const char* pattern, ...) {
    std::va_list values, again;
    va_start(values, pattern);
    va_copy(again, values);
    std::string text(std::size_t(std::max(0, std::vsnprintf(nullptr, 0, pattern, values))), ' ');
    std::vsnprintf(text.data(), text.size() + 1, pattern, again);
    va_end(again);
    va_end(values);
    return text;
}

// The table: a row per light and one for all, 79 columns (the false shadow and leak columns
// under two headings, misclassified and outside the band).
void printHeader() {
    std::printf("%27s %26s  %16s %6s\n", "", "----- misclassified ------", "outside the band",
                "mean");
    std::printf("%5s  %-11s %8s %8s %8s %8s %8s %8s %6s\n", "light", "type", "pixels", "all",
                "false", "leak", "false", "leak", "|err|");
    std::printf("%5s  %-11s %8s %8s %8s %8s %8s\n", "", "", "", "", "shadow", "", "shadow");
}
void printRow(const ShadowScore& s) {
    const std::string light = s.light < 0 ? "all" : std::to_string(s.light);
    std::printf("%5s  %-11s %8ld %7.3f%% %7.3f%% %7.3f%% %7.3f%% %7.3f%% %6.4f\n", light.c_str(),
                s.type.c_str(), s.pixels, 100.0 * s.misclassified, 100.0 * s.falseShadow,
                100.0 * s.leak, 100.0 * s.falseShadowOutsideBand, 100.0 * s.leakOutsideBand,
                s.meanAbsError);
}
// The errors away from edges by cause (ErrorCauses), when there are any.
void printCauses(const ScoreResult& r) {
    const ErrorCauses& k = r.causes;
    const long falseShadow = k.falseShadowGrazing + k.falseShadowOther;
    const long leak = k.leakGrazing + k.leakContact + k.leakOther;
    if (falseShadow + leak == 0) return;
    printWrapped(format(
        "away from edges (pixel x light pairs): false shadow %ld (%ld on surfaces within 5.7 "
        "degrees of edge-on to the light, %ld other); leak %ld (%ld within 5.7 degrees of "
        "edge-on, %ld at contacts: occluder within 4 map texels of the surface, %ld other); "
        "every error in errors.csv",
        falseShadow, k.falseShadowGrazing, k.falseShadowOther, leak, k.leakGrazing, k.leakContact,
        k.leakOther));
}
// A frame's score on stdout: what was scored, the table, then the notes that apply.
void printScore(const ScoreResult& r, const Scene& scene, const RenderOptions& options,
                const std::string& outDir) {
    printWrapped(format("gnomon score: %s, %dx%d, filter %s, %s", scene.name.c_str(), options.width,
                        options.height, toString(options.shadow.filter),
                        toString(options.shadow.depthFormat)));
    printWrapped(format("reference: %s shadows, traced in %.2f s",
                        r.softReference ? "soft (pcss)" : "hard", r.traceSeconds));
    printHeader();
    for (const ShadowScore& s : r.lights)
        printRow(s);
    printRow(r.overall);
    if (!r.tintErrors.empty()) {
        printWrapped(
            format("coloured shadows: transmitted light off by %.2f/255 on average over %ld "
                   "tinted pixel x light pairs (%.2f/255 over the %ld away from edges; its colour, "
                   "where both pass light: %.2f/255 over %ld)",
                   255.0 * r.tint.meanError, r.tint.cells, 255.0 * r.tint.meanErrorOutsideBand,
                   r.tint.cellsOutsideBand, 255.0 * r.tint.meanColourError, r.tint.cellsBothLit));
    }
    if (r.contactRange > 0.0f) {
        printWrapped(
            format("at contacts (occluder within %g): %ld pixel x light pairs in shadow, %.3f%% of "
                   "them rendered lit",
                   double(r.contactRange), r.overall.contactPixels, 100.0 * r.overall.contactLeak));
    }
    printCauses(r);
    if (tracesShadowRays(options.shadow)) {
        printWrapped(format("shadow rays (%s): a ray decided %.3f%% of the pixel x light pairs",
                            toString(options.shadow.shadowRays), 100.0 * r.overall.traced));
    }
    if (r.otherSurfacePixels > 0) {
        printWrapped(
            format("not scored: %ld pixels where the render drew another surface than the "
                   "reference sees (or none)",
                   r.otherSurfacePixels));
    }
    printWrapped(format("wrote %s/render.png, errors.png, %sscore.json, errors.csv", outDir.c_str(),
                        r.tintErrors.empty() ? "" : "tint-errors.png, "));
}
// score(), with an activity line for the render and the tracing (the share of rows traced);
// Ctrl-C stops the tracing at the next row.
ScoreResult scoreWithProgress(Renderer& renderer, const Scene& scene, const RenderOptions& options,
                              const ScoreOptions& scoreOptions) {
    ScoreFrame frame = [&] {
        const Activity activity("rendering for the score");
        return renderForScore(renderer, scene, options, scoreOptions);
    }();
    checkInterrupt("rendering; nothing was written");
    ScoreProgress progress;
    try {
        const Activity activity("tracing the reference", [&progress] {
            if (interrupted()) progress.cancel = true;
            const int rows = progress.rows.load();
            return rows > 0 ? double(progress.rowsDone.load()) / rows : -1.0;
        });
        return scoreFrame(std::move(frame), scene, options, scoreOptions, &progress);
    } catch (const Error&) {
        checkInterrupt("tracing the reference; nothing was written");
        throw;
    }
}

// --path: every frame scored, a line per frame as it finishes (the progress), path.json and
// on request each frame's error map; Ctrl-C keeps the frames finished.
int runScorePath(const ScoreArgs& args, Scene& scene, const RenderOptions& options,
                 Renderer& renderer) {
    const ScenePath path = makeScenePath(args.path, scene, args.frames);
    OutputSet out(args.outDir, "--out-dir");
    ScoreProgress progress;
    std::printf("gnomon score: %s over path %s, %d frames, %dx%d, filter %s, stabilise %s\n",
                scene.name.c_str(), path.name.c_str(), path.frames(), options.width, options.height,
                toString(options.shadow.filter), options.shadow.stabilise ? "on" : "off");
    std::printf("%5s  %13s  %12s  %9s  %9s  %11s\n", "frame", "misclassified", "false shadow",
                "leak", "flicker", "compared");
    std::fflush(stdout);
    // The frame lines are the progress (a frame takes a second or a few); Ctrl-C stops after
    // the frame being scored.
    const PathScoreResult r =
        scorePath(renderer, scene, options, path, args.options, args.errorMaps, &progress,
                  [&](const PathScoreResult& soFar) {
                      const PathFrameScore& f = soFar.frames.back();
                      std::printf("%5zu  %12.3f%%  %11.3f%%  %8.3f%%  %8.4f%%  %11ld\n",
                                  soFar.frames.size() - 1, 100.0 * f.overall.misclassified,
                                  100.0 * f.overall.falseShadow, 100.0 * f.overall.leak,
                                  100.0 * f.flicker, f.compared);
                      std::fflush(stdout);
                      if (interrupted()) progress.cancel = true;
                  });
    if (r.frames.empty())
        checkInterrupt("scoring the first frame of the path; nothing was written");
    for (std::size_t i = 0; i < r.frames.size() && args.errorMaps; ++i) {
        char name[32];
        std::snprintf(name, sizeof name, "errors-%03zu.png", i);
        writePng(out.file(name), r.frames[i].errors);
    }
    writeTextFile(out.file("path.json"), toJson(r, scene.name, options));
    out.keep();
    std::printf(
        "mean over %zu frames: misclassified %.3f%%, flicker %.4f%% (max %.4f%%); "
        "traced in %.1f s\nwrote %s/path.json%s\n",
        r.frames.size(), 100.0 * r.meanMisclassified, 100.0 * r.meanFlicker, 100.0 * r.maxFlicker,
        r.traceSeconds, args.outDir.c_str(), args.errorMaps ? " and errors-NNN.png" : "");
    if (r.interrupted) {
        throw Interrupted("interrupted while scoring the path; kept the " +
                          std::to_string(r.frames.size()) + " of " + std::to_string(r.framesAsked) +
                          " frames finished");
    }
    if (args.maxError >= 0.0 && r.meanMisclassified > args.maxError) {
        std::fprintf(stderr, "gnomon: mean misclassified %.4f%% exceeds --max-error %.4f%%\n",
                     100.0 * r.meanMisclassified, 100.0 * args.maxError);
        return 3;
    }
    return 0;
}

}  // namespace

int runScore(const ScoreArgs& args, bool verbose) {
    if (args.maxError != -1.0 && !(args.maxError >= 0.0 && args.maxError <= 1.0)) {
        throw Error(ErrorKind::InvalidInput, "--max-error must be a fraction in [0, 1], got " +
                                                 std::to_string(args.maxError));
    }
    Scene scene = loadWithProgress(args.scene, args.flags.upAxis());
    args.flags.editSceneAndWarn(scene);
    const RenderOptions options = args.flags.resolve(scene);
    ContextOptions context;
    context.verbose = verbose;
    Renderer renderer(context);
    if (!args.path.empty()) return runScorePath(args, scene, options, renderer);
    if (args.errorMaps) throw Error(ErrorKind::InvalidInput, "--error-maps needs --path");
    ScoreOptions scoreOptions = args.options;
    scoreOptions.explain = true;
    const ScoreResult r = scoreWithProgress(renderer, scene, options, scoreOptions);

    OutputSet out(args.outDir, "--out-dir");
    writePng(out.file("render.png"), r.render);
    writePng(out.file("errors.png"), r.errors);
    if (!r.tintErrors.empty()) writePng(out.file("tint-errors.png"), r.tintErrors);
    writeTextFile(out.file("score.json"), toJson(r, scene.name, options));
    writeTextFile(out.file("errors.csv"), errorCellsCsv(r));
    out.keep();

    printScore(r, scene, options, args.outDir);
    if (args.maxError >= 0.0 && r.overall.misclassified > args.maxError) {
        std::fprintf(stderr, "gnomon: misclassified %.4f%% exceeds --max-error %.4f%%\n",
                     100.0 * r.overall.misclassified, 100.0 * args.maxError);
        return 3;
    }
    return 0;
}

}  // namespace gnomon::cli
