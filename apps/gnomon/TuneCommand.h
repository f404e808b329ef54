// `gnomon tune`: search shadow settings for the lowest error against the ray-traced
// reference within a frame-time budget; writes the front and a scene file to render with.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "RenderOptionsCli.h"
#include "gnomon/Tune.h"

namespace gnomon::cli {

struct TuneArgs {
    std::string scene, views, outDir = "tune", out;
    TuneOptions options;
    RenderFlags flags;
};

CLI::App* addTuneCommand(CLI::App& app, TuneArgs& args);
// Exit code 0; Ctrl-C keeps what was found (exit 130 after writing it).
int runTune(const TuneArgs& args, bool verbose);

}  // namespace gnomon::cli
