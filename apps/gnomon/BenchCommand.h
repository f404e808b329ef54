// `gnomon bench`: what each pass of a frame costs, and how that grows with one parameter.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "RenderOptionsCli.h"

namespace gnomon::cli {

struct BenchArgs {
    std::string scene, outDir = "bench", sweep, values;
    std::string writeScene;  // --write-scene: the scene file of the sweep's one value
    int frames = 20, warmup = 3;
    bool staticMaps = false;
    bool movingLights = false;  // --moving-lights: spot and point lights move every frame
    RenderFlags flags;
};

CLI::App* addBenchCommand(CLI::App& app, BenchArgs& args);
int runBench(const BenchArgs& args, bool verbose);

}  // namespace gnomon::cli
