// What the native sides of the page's browser tests share (page_truth, page_render,
// page_score): the page's screenshot read beside native's picture, a difference image left
// for a failure, and main()'s report of an exception.
#pragma once

#include <cstdio>
#include <exception>
#include <optional>
#include <string>

#include "gnomon/Image.h"

namespace gnomon::web::check {

// The page's screenshot at `path`, or nothing (said on stderr, as `tool`) when its size is
// not native's.
inline std::optional<Image> pageShot(const char* tool, const std::string& path,
                                     const Image& native) {
    Image shot = readPng(path);
    if (shot.width == native.width && shot.height == native.height) return shot;
    std::fprintf(stderr, "%s: the page's picture is %dx%d, native's %dx%d\n", tool, shot.width,
                 shot.height, native.width, native.height);
    return std::nullopt;
}

// Writes where they differ beside the screenshot, says where, and fails (exit status 1).
inline int failWithDiff(const char* tool, const std::string& shotPath, const Image& native,
                        const Image& shot, const char* what) {
    const std::string diff = shotPath + ".diff.png";
    writePng(diff, compareImages(native, shot, 2).diff);
    std::fprintf(stderr, "%s: %s; see %s\n", tool, what, diff.c_str());
    return 1;
}

// main() of a check: `run`'s status, or 1 with the exception's message.
template <typename Run>
int guarded(const char* tool, const Run& run) {
    try {
        return run();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s: %s\n", tool, e.what());
        return 1;
    }
}

}  // namespace gnomon::web::check
