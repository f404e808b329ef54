// The page's entry points, bound to JavaScript with embind (apps/web/page.js calls them): the
// scenes it can show, and `show(address)`, which reads the address, loads the scene, traces
// its picture on the project's BVH (TruthPicture.h) and hands back the pixels with a short
// report. Errors come back in the CLI's words, prefixed as the CLI prefixes them.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <algorithm>
#include <chrono>
#include <filesystem>

#include "PageRequest.h"
#include "PageViewer.h"
#include "RenderPicture.h"
#include "TruthPicture.h"
#include "gnomon/Error.h"

namespace {

using emscripten::val;

// Where the page's bundled models are (file_packager's --preload DIR@/scenes; absent when
// the build found none).
constexpr const char* kBundle = "/scenes";

val strings(const std::vector<std::string>& list) {
    val out = val::array();
    for (const std::string& s : list)
        out.call<void>("push", s);
    return out;
}

// "light 0 (directional, sun)": the light the picture shows.
std::string lightLabel(const gnomon::Scene& scene, int light) {
    if (light < 0) return "no light";
    const gnomon::Light& l = scene.lights[std::size_t(light)];
    return "light " + std::to_string(light) + " (" + gnomon::toString(l.type) +
           (l.name.empty() ? "" : ", " + l.name) + ")";
}

// `image` as RGBA, which the canvas's ImageData takes (error maps are RGB).
gnomon::Image rgba(const gnomon::Image& image) {
    if (image.channels == 4) return image;
    gnomon::Image out(image.width, image.height, 4);
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const std::uint8_t* in = image.at(x, y);
            std::uint8_t* to = out.at(x, y);
            for (int c = 0; c < 3; ++c)
                to[c] = in[std::min(c, image.channels - 1)];
            to[3] = 255;
        }
    }
    return out;
}

// Built-in scene names, then the bundled models' folders, for the page's menu.
val scenes() {
    std::vector<std::string> names;
    for (const gnomon::SceneInfo& s : gnomon::builtinScenes())
        names.push_back(s.name);
    std::vector<std::string> models;
    std::error_code ec;
    for (std::filesystem::directory_iterator it(kBundle, ec), end; !ec && it != end;
         it.increment(ec)) {
        if (it->is_directory(ec)) models.push_back(it->path().filename().string());
    }
    std::sort(models.begin(), models.end());
    names.insert(names.end(), models.begin(), models.end());
    return strings(names);
}

// {ok, width, height, pixels (RGBA, a copy), scene, light, seconds, warnings} or {ok: false,
// error}.
val show(const std::string& address) {
    val result = val::object();
    try {
        const auto start = std::chrono::steady_clock::now();
        const gnomon::web::PageRequest request = gnomon::web::parseAddress(address);
        const gnomon::web::PageScene page = gnomon::web::loadRequest(request, kBundle);
        using Picture = gnomon::web::PageRequest::Picture;
        gnomon::Image image;
        if (request.picture == Picture::Truth) {
            image =
                gnomon::web::truthPicture(page.scene, page.options, gnomon::truth::TracerKind::Bvh);
        } else if (request.picture == Picture::Score) {
            const gnomon::ScoreResult r = gnomon::web::scorePicture(page.scene, page.options);
            image = rgba(r.errors);
            result.set("misclassified", 100.0 * r.overall.misclassified);
        } else {
            image = gnomon::web::renderPicture(page.scene, page.options);
        }
        const int light = gnomon::web::pictureLight(page.scene, page.options);
        const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
        result.set("ok", true);
        result.set("width", image.width);
        result.set("height", image.height);
        result.set("pixels", val::global("Uint8ClampedArray")
                                 .new_(emscripten::typed_memory_view(image.pixels.size(),
                                                                     image.pixels.data())));
        result.set("scene", page.scene.name);
        result.set("light", lightLabel(page.scene, light));
        result.set("picture", std::string(request.picture == Picture::Truth   ? "truth"
                                          : request.picture == Picture::Score ? "score"
                                                                              : "render"));
        result.set("seconds", took.count());
        result.set("warnings", strings(page.warnings));
    } catch (const std::exception& e) {
        result.set("ok", false);
        result.set("error", std::string("gnomon: error: ") + e.what());
    }
    return result;
}

// {x, y, width, height} of the viewer's camera view on the canvas (the browser tests drag
// on it and compare it).
val viewerRect() {
    const std::array<float, 4> r = gnomon::web::viewerRect();
    val out = val::object();
    out.set("x", r[0]);
    out.set("y", r[1]);
    out.set("width", r[2]);
    out.set("height", r[3]);
    return out;
}

// {ok, ms: [each frame's wall time]} or {ok: false, error}: the address's picture rendered
// as `gnomon bench` times a frame (scripts/web-bench.js compares the two).
val bench(const std::string& address, int frames) {
    val result = val::object();
    try {
        const gnomon::web::PageScene page =
            gnomon::web::loadRequest(gnomon::web::parseAddress(address), kBundle);
        const std::vector<double> ms =
            gnomon::web::benchPicture(page.scene, page.options, 3, std::clamp(frames, 1, 10000));
        val list = val::array();
        for (double m : ms)
            list.call<void>("push", m);
        result.set("ok", true);
        result.set("ms", list);
    } catch (const std::exception& e) {
        result.set("ok", false);
        result.set("error", std::string("gnomon: error: ") + e.what());
    }
    return result;
}

}  // namespace

EMSCRIPTEN_BINDINGS(gnomon_page) {
    emscripten::function("scenes", &scenes);
    emscripten::function("show", &show);
    emscripten::function("bench", &bench);
    emscripten::function("startViewer", &gnomon::web::startViewer);
    emscripten::function("resizeViewer", &gnomon::web::resizeViewer);
    emscripten::function("viewerRect", &viewerRect);
    emscripten::function("viewerDrawn", &gnomon::web::viewerDrawn);
}
