// gnomon: the command-line tool. Subcommands: `scenes` lists the built-in scenes, `render`
// draws one frame to a PNG (and optionally each light's shadow map), `score` measures its
// shadows against a ray-traced reference (over a camera or light path too), `tune` searches
// shadow settings against that reference within a frame-time budget, `bench` times each pass
// (and sweeps a parameter), `view` opens the interactive viewer (a window; docs/viewer.md). Exit
// codes: 0 success, 1 failure (writing output, OpenGL), 2 bad usage or input (a missing or broken
// input file too), 3 score above --max-error.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "BenchCommand.h"
#include "HelpFormatter.h"
#include "OutputSet.h"
#include "Progress.h"
#include "RenderOptionsCli.h"
#include "ScoreCommand.h"
#include "TuneCommand.h"
#include "Viewer.h"
#include "gnomon/gnomon.h"

namespace {

int runScenes(bool namesOnly) {
    for (const gnomon::SceneInfo& s : gnomon::builtinScenes()) {
        if (namesOnly) {
            std::printf("%s\n", s.name.c_str());
        } else {
            std::printf("%-20s %s\n", s.name.c_str(), s.description.c_str());
        }
    }
    return 0;
}

// Every render option with its range and default (from the schema); --markdown: the docs'
// tables as README.md and docs/scene-file.md hold them.
int runOptions(const std::string& markdown) {
    if (markdown == "flags" || markdown == "scene-file") {
        std::fputs(gnomon::optionTableMarkdown(markdown == "flags" ? gnomon::OptionTable::Flags
                                                                   : gnomon::OptionTable::SceneFile)
                       .c_str(),
                   stdout);
        return 0;
    }
    if (!markdown.empty()) {
        throw gnomon::Error(gnomon::ErrorKind::InvalidInput,
                            "--markdown: expected flags or scene-file, got '" + markdown + "'");
    }
    const gnomon::RenderOptions defaults;
    const gnomon::OptionSpec* previous = nullptr;
    for (const gnomon::OptionSpec& spec : gnomon::optionSchema()) {
        if (!previous || previous->group != spec.group)
            std::printf("%s%s:\n", previous ? "\n" : "", gnomon::toString(spec.group));
        previous = &spec;
        std::printf(
            "  %-18s %-28s default %s\n", spec.name, gnomon::optionRange(spec).c_str(),
            *spec.defaultNote ? spec.defaultNote : gnomon::formatOption(spec, defaults).c_str());
    }
    return 0;
}

struct RenderArgs {
    std::string scene, out, shadowMaps;
    gnomon::cli::RenderFlags flags;
};

// The image, then each light's map: all of them, or (on any failure) none of them.
void writeOutputs(const RenderArgs& args, gnomon::Renderer& renderer, const gnomon::Image& image,
                  bool verbose) {
    const bool maps = !args.shadowMaps.empty();
    gnomon::cli::OutputSet files =
        maps ? gnomon::cli::OutputSet(args.shadowMaps, "--shadow-maps") : gnomon::cli::OutputSet();
    gnomon::writeImage(files.add(args.out), image);
    for (const gnomon::ShadowMapImage& map :
         maps ? renderer.shadowMaps() : std::vector<gnomon::ShadowMapImage>{}) {
        const std::string path =
            files.file("light-" + std::to_string(map.light) +
                       (map.cascade >= 0 ? "-cascade-" + std::to_string(map.cascade) : "") +
                       (map.face >= 0 ? "-face-" + std::to_string(map.face) : "") + ".png");
        gnomon::writePng(path, map.depth);
        if (verbose) std::fprintf(stderr, "gnomon: wrote %s\n", path.c_str());
    }
    files.keep();
}

int runRender(const RenderArgs& args, bool verbose) {
    if (!gnomon::imageFormatKnown(args.out)) {
        throw gnomon::Error(
            gnomon::ErrorKind::InvalidInput,
            "--out: '" + args.out + "': the format follows the extension: .png, .jpg or .jpeg");
    }
    const auto loadStart = std::chrono::steady_clock::now();
    gnomon::Scene scene = gnomon::cli::loadWithProgress(args.scene, args.flags.upAxis());
    const double loadMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - loadStart)
            .count();
    args.flags.editSceneAndWarn(scene);
    if (verbose) {
        const std::size_t triangles = gnomon::triangleCount(scene);
        std::fprintf(
            stderr, "gnomon: loaded '%s' in %.0f ms: %zu triangles, %zu objects, %zu lights\n",
            scene.name.c_str(), loadMs, triangles, scene.objects.size(), scene.lights.size());
        // Where the model lies, in the world units lights and cameras are placed in (a model
        // in millimetres or far from the origin is otherwise found by trial).
        if (!scene.objects.empty()) {
            glm::vec3 lo, hi;
            gnomon::sceneBounds(scene, lo, hi);
            std::fprintf(stderr, "gnomon: scene bounds %.6g,%.6g,%.6g to %.6g,%.6g,%.6g\n", lo.x,
                         lo.y, lo.z, hi.x, hi.y, hi.z);
        }
    }
    const gnomon::RenderOptions options = args.flags.resolve(scene);
    if (options.lightOnly >= int(scene.lights.size())) {
        throw gnomon::Error(gnomon::ErrorKind::InvalidInput,
                            "--light-only " + std::to_string(options.lightOnly) + ": scene '" +
                                scene.name + "' has " + std::to_string(scene.lights.size()) +
                                " light(s)");
    }
    gnomon::ContextOptions context;
    context.verbose = verbose;
    gnomon::Renderer renderer(context);
    const auto renderStart = std::chrono::steady_clock::now();
    const gnomon::Image image = [&] {
        const gnomon::cli::Activity activity("rendering " + std::to_string(options.width) + "x" +
                                             std::to_string(options.height));
        return renderer.render(scene, options);
    }();
    gnomon::cli::checkInterrupt("rendering; nothing was written");
    if (const std::string& note = renderer.lastFrameStats().mapBudgetNote; !note.empty())
        std::fprintf(stderr, "gnomon: warning: %s\n", note.c_str());
    if (verbose) {
        std::fprintf(stderr, "gnomon: first frame (uploads, shadow maps, main pass) in %.0f ms\n",
                     std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() -
                                                               renderStart)
                         .count());
    }
    {
        const gnomon::cli::Activity activity("writing " + args.out);
        writeOutputs(args, renderer, image, verbose);
    }
    if (verbose) {
        const gnomon::FrameStats stats = renderer.lastFrameStats();
        std::fprintf(stderr,
                     "gnomon: %d shadow map(s), %d shadow pass(es) drawing %llu triangles "
                     "(%d caster draws culled), main pass %llu triangles in %d light tile(s)%s%s, "
                     "%.1f MiB of shadow maps\n",
                     stats.shadowMaps, stats.shadowPasses,
                     (unsigned long long)stats.shadowTriangles, stats.castersCulled,
                     (unsigned long long)stats.mainTriangles,
                     std::max({1, stats.lightTiles, stats.lightLists}),
                     stats.lightLists > 0 ? " of light lists in one draw" : "",
                     stats.mainFromViewDepth ? " from the view's depth" : "",
                     double(stats.shadowMapBytes) / (1024.0 * 1024.0));
        if (stats.momentPasses > 0) {
            std::fprintf(stderr, "gnomon: %d moment pass(es) for the filterable maps\n",
                         stats.momentPasses);
        }
        if (stats.shadowRayPasses > 0) {
            std::fprintf(stderr,
                         "gnomon: shadow rays traced in %d pass(es) of their own, between the "
                         "main pass's two draws\n",
                         stats.shadowRayPasses);
        }
        if (stats.transmittancePasses > 0) {
            std::fprintf(stderr, "gnomon: %d transmittance pass(es) for the coloured shadows\n",
                         stats.transmittancePasses);
        }
        static const char* const kFaceNames[6] = {"+X", "-X", "+Y", "-Y", "+Z", "-Z"};
        for (const gnomon::MapUsage& u : renderer.mapUsage()) {
            const std::string faces =
                u.cube ? " (" + std::to_string(u.faces) + " of 6 faces drawn)" : "";
            const std::string part =
                u.cascade >= 0 ? " cascade " + std::to_string(u.cascade)
                : u.face >= 0  ? " face " + std::to_string(u.face) + " (" + kFaceNames[u.face] + ")"
                               : "";
            std::fprintf(stderr, "gnomon: light %d%s: %d² %s%s, the view uses %.0f %% of it%s\n",
                         u.light, part.c_str(), u.mapSize, u.cube ? "cube" : "map", faces.c_str(),
                         100.0 * double(u.share),
                         u.waiting ? " (kept as drawn earlier: waits for --map-redraws)" : "");
        }
    }
    return 0;
}

// The first word that is not a flag must be a command: when it is not, one line naming the
// nearest command if one is a few typing slips away (global flags take no values, so the
// first word is the command).
bool unknownCommand(int argc, char** argv, const CLI::App& app) {
    std::vector<std::string> names;
    for (const CLI::App* sub : app.get_subcommands({}))
        names.push_back(sub->get_name());
    for (int i = 1; i < argc; ++i) {
        const std::string word = argv[i];
        if (word.empty() || word[0] == '-') continue;
        if (std::find(names.begin(), names.end(), word) != names.end()) return false;
        std::string list;
        for (const std::string& n : names)
            list += (list.empty() ? "" : ", ") + n;
        const std::string nearest = gnomon::nearestName(word, names);
        std::fprintf(stderr, "gnomon: error: unknown command '%s'%s (commands: %s)\n", word.c_str(),
                     nearest.empty() ? "" : ("; did you mean '" + nearest + "'?").c_str(),
                     list.c_str());
        return true;
    }
    return false;
}

// For a word nobody took that looks like a flag ("--map-sise"), the nearest flag of `app` a
// few typing slips away ("; did you mean --map-size?"), else "".
std::string nearestFlag(const std::string& word, const CLI::App& app) {
    if (word.rfind("--", 0) != 0) return "";
    std::vector<std::string> flags;
    for (const CLI::Option* o : app.get_options()) {
        const std::vector<std::string>& names = o->get_lnames();
        flags.insert(flags.end(), names.begin(), names.end());
    }
    const std::string nearest = gnomon::nearestName(word.substr(2, word.find('=') - 2), flags);
    return nearest.empty() ? "" : "; did you mean --" + nearest + "?";
}

}  // namespace

int main(int argc, char** argv) {
    // llvmpipe's per-draw buffers would otherwise make the kernel fault pages in on every draw
    // (gnomon.h; docs/results/performance.md, "The heap kept between draws").
    gnomon::keepFreedHeap();
    CLI::App app{"gnomon: real-time shadows you can measure (OpenGL 4.5 core, headless)"};
    app.require_subcommand(1);
    // Global flags are accepted after the command too (`gnomon render --verbose ...`): a
    // command passes what it does not know to gnomon itself.
    app.fallthrough();
    app.formatter(std::make_shared<gnomon::cli::HelpFormatter>());
    bool verbose = false;
    app.add_flag("-v,--verbose", verbose,
                 "print OpenGL vendor/renderer/version and what was written");
    app.set_version_flag("--version", gnomon::version());

    bool namesOnly = false;
    CLI::App* scenes = app.add_subcommand("scenes", "list the built-in scenes");
    scenes->add_flag("--names", namesOnly, "names only, one per line");

    std::string markdown;
    CLI::App* optionsCmd = app.add_subcommand(
        "options", "list every render option with its range and default (flags, scene-file keys)");
    optionsCmd->add_option("--markdown", markdown,
                           "print the docs' table instead: flags (README.md) or scene-file "
                           "(docs/scene-file.md)");

    RenderArgs render;
    CLI::App* renderCmd = app.add_subcommand("render", "render one frame to a PNG file");
    renderCmd
        ->add_option(
            "--scene", render.scene,
            "built-in scene name (see `gnomon scenes`), scene file (.json), glTF file (.gltf, "
            ".glb) or other model file (assimp: .obj, .ply, .fbx...)")
        ->required();
    renderCmd->add_option("--out", render.out, "output PNG path (written atomically)")->required();
    renderCmd->add_option(
        "--shadow-maps", render.shadowMaps,
        "also write each light's shadow map as DIR/light-N.png (cascades: light-N-cascade-K.png; "
        "cubes: six faces side by side, white where the view looks none up; 16-bit grey, darker "
        "= nearer)");
    render.flags.add(*renderCmd);

    gnomon::cli::ScoreArgs scoreArgs;
    CLI::App* scoreCmd = gnomon::cli::addScoreCommand(app, scoreArgs);

    gnomon::cli::TuneArgs tuneArgs;
    CLI::App* tuneCmd = gnomon::cli::addTuneCommand(app, tuneArgs);

    gnomon::cli::BenchArgs benchArgs;
    CLI::App* benchCmd = gnomon::cli::addBenchCommand(app, benchArgs);

    gnomon::cli::ViewArgs viewArgs;
    CLI::App* viewCmd = gnomon::cli::addViewCommand(app, viewArgs);

    if (unknownCommand(argc, argv, app)) return 2;
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        // One line, prefixed as every other error, and where help is; words nobody took are
        // named in the order given (CLI11 lists them reversed).
        std::string what = e.what();
        if (dynamic_cast<const CLI::ExtrasError*>(&e) != nullptr) {
            what = "unknown flag or stray value:";
            const CLI::App& command =
                app.get_subcommands().empty() ? app : *app.get_subcommands().front();
            std::string hint;
            for (const std::string& word : app.remaining()) {
                what += " " + word;
                if (hint.empty()) hint = nearestFlag(word, command);
            }
            what += hint;
        }
        std::fprintf(stderr, "gnomon: error: %s (see gnomon%s --help)\n", what.c_str(),
                     app.get_subcommands().empty()
                         ? ""
                         : (" " + app.get_subcommands().front()->get_name()).c_str());
        return 2;
    }
    gnomon::cli::catchInterrupts();
    try {
        if (*scenes) return runScenes(namesOnly);
        if (*optionsCmd) return runOptions(markdown);
        if (*renderCmd) return runRender(render, verbose);
        if (*scoreCmd) return gnomon::cli::runScore(scoreArgs, verbose);
        if (*tuneCmd) return gnomon::cli::runTune(tuneArgs, verbose);
        if (*benchCmd) return gnomon::cli::runBench(benchArgs, verbose);
        if (*viewCmd) return gnomon::cli::runView(viewArgs, verbose);
    } catch (const gnomon::cli::Interrupted& e) {
        std::fprintf(stderr, "gnomon: %s\n", e.what());
        return gnomon::cli::kInterruptedExitCode;
    } catch (const gnomon::Error& e) {
        std::fprintf(stderr, "gnomon: error: %s\n", e.what());
        return e.kind() == gnomon::ErrorKind::InvalidInput ? 2 : 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "gnomon: error: %s\n", e.what());
        return 1;
    }
    return 0;
}
