// `gnomon view`: the interactive shadow lab (W. Brown, Learn Computer Graphics using WebGL,
// 12.6: an interactive shadow program). A GLFW window with Dear ImGui:
// the camera's view beside the selected light's shadow map, a control for every render
// option, live pass times, one-click ground-truth scores with an error overlay, presets,
// save/load as scene files, and screenshots equal to `gnomon render`'s. docs/viewer.md.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "RenderOptionsCli.h"

namespace gnomon::cli {

struct ViewArgs {
    std::string scene = "tutorial-room";
    std::string script;  // --script FILE: timed commands (docs/viewer.md)
    std::string window = "1280x720";
    std::string screenshotDir = ".";  // where F12 writes its PNGs
    RenderFlags flags;
};

CLI::App* addViewCommand(CLI::App& app, ViewArgs& args);
// Exit code: 0; 1 when a script's expectation fails or the window cannot open.
int runView(const ViewArgs& args, bool verbose);

}  // namespace gnomon::cli
