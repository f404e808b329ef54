// `gnomon score`: render, ray-trace the reference, report how wrong the shadows are.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "RenderOptionsCli.h"
#include "gnomon/Score.h"

namespace gnomon::cli {

struct ScoreArgs {
    std::string scene, outDir = "score";
    double maxError = -1.0;
    std::string path;  // --path: score over a camera or light path ("" = one frame)
    int frames = 30;
    bool errorMaps = false;
    ScoreOptions options;
    RenderFlags flags;
};

CLI::App* addScoreCommand(CLI::App& app, ScoreArgs& args);
// Exit code: 0, or 3 when the overall misclassified fraction (over a path: its mean) exceeds
// --max-error.
int runScore(const ScoreArgs& args, bool verbose);

}  // namespace gnomon::cli
