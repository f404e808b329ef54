#include "PageViewer.h"

#include <emscripten.h>

#include <cstdio>
#include <memory>

#include "PageRequest.h"
#include "ViewerApp.h"
#include "gnomon/Error.h"

namespace gnomon::web {
namespace {

constexpr const char* kBundle = "/scenes";  // the page's packaged models (main.cpp)

struct Page {
    cli::ViewArgs args;  // the viewer's command-line settings: defaults, F12 into /tmp
    std::unique_ptr<cli::viewer::Viewer> viewer;
    bool announced = false;  // the title says ready (or the error) for the current view
    std::string downloaded;  // the last file the viewer wrote, handed to the browser
    // What the address is written against (writeAddress): the request the shown scene was
    // loaded from, the scene as loaded, its source, and the state last written.
    PageRequest base;
    Scene loaded;
    std::string source;
    std::uint64_t written = ~std::uint64_t(0), writtenView = ~std::uint64_t(0);
    int scoresShown = 0;  // the viewer's scores the title has reported
};

Page& page() {
    static Page p;
    return p;
}

void setTitle(const std::string& title) {
    EM_ASM({ document.title = UTF8ToString($0); }, title.c_str());
}

// A file the viewer wrote into the page's memory (F12's screenshot, a saved scene file), as
// a download the browser saves where the user keeps them.
void download(const std::string& path) {
    EM_ASM(
        {
            const path = UTF8ToString($0);
            const blob = new Blob([FS.readFile(path)]);
            const link = document.createElement('a');
            link.href = URL.createObjectURL(blob);
            link.download = path.split('/').pop();
            link.click();
            setTimeout(
                function() { URL.revokeObjectURL(link.href); }, 1000);
        },
        path.c_str());
}

// The viewer loaded another scene itself (its scene menu, a preset, the ground switch):
// addresses are written against that scene from now on.
void rebase(Page& p, const view::State& state) {
    p.base = PageRequest{};
    // A bundled model by its path in the bundle ("Duck/Duck.glb"), as addresses name them.
    const std::string bundled = std::string(kBundle) + "/";
    p.base.scene =
        state.source.rfind(bundled, 0) == 0 ? state.source.substr(bundled.size()) : state.source;
    p.base.ground = state.ground;
    p.loaded = loadRequest(p.base, kBundle).scene;
    p.source = state.source;
}

// The address of what the viewer shows, in the browser's address bar (replacing the entry:
// the Back button leaves the page, not each drag). A view the address cannot hold (lights
// added or removed) keeps the last address and says why in the console.
void writeAddressBar(Page& p) {
    const view::State& state = p.viewer->state();
    if (state.revision == p.written && state.viewRevision == p.writtenView) return;
    p.written = state.revision;
    p.writtenView = state.viewRevision;
    try {
        if (state.source != p.source || state.ground != p.base.ground) rebase(p, state);
        const std::string address =
            writeAddress(p.base, p.loaded, state.scene, state.options, !state.fitView);
        EM_ASM(
            {
                const address = UTF8ToString($0);
                if (location.hash != address) history.replaceState(null, "", address);
            },
            address.c_str());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "gnomon: the address keeps the last view: %s\n", e.what());
    }
}

// The browser's frame: one turn of the viewer's loop, the files it wrote, the address, then
// the title once the view is drawn.
void frame(void*) {
    Page& p = page();
    if (!p.viewer->step()) {
        emscripten_cancel_main_loop();
        return;
    }
    if (p.viewer->lastWritten() != p.downloaded) {
        p.downloaded = p.viewer->lastWritten();
        download(p.downloaded);
    }
    writeAddressBar(p);
    if (p.viewer->scoresDone() != p.scoresShown && p.viewer->lastScore()) {
        // Each score's share in the title, after the view it scored.
        p.scoresShown = p.viewer->scoresDone();
        char share[48];
        std::snprintf(share, sizeof share, " misclassified %.4f%%",
                      100.0 * p.viewer->lastScore()->overall.misclassified);
        setTitle("gnomon ready: " + p.viewer->state().scene.name + " " +
                 std::to_string(p.viewer->drawnWidth()) + "x" +
                 std::to_string(p.viewer->drawnHeight()) + share);
    }
    if (p.announced) return;
    if (!p.viewer->frameError().empty()) {
        setTitle("gnomon error: " + p.viewer->frameError());
        p.announced = true;
    } else if (p.viewer->frameReady()) {
        setTitle("gnomon ready: " + p.viewer->state().scene.name + " " +
                 std::to_string(p.viewer->drawnWidth()) + "x" +
                 std::to_string(p.viewer->drawnHeight()));
        p.announced = true;
    }
}

// The viewer's state for the page's request (its scene, options and size), and the request
// as the base of the addresses written from now on.
view::State stateOf(Page& p, const PageRequest& request) {
    PageScene loaded = loadRequest(request, kBundle);
    p.base = request;
    p.loaded = loaded.scene;
    p.source = sceneSource(request.scene, kBundle);
    view::State state;
    view::show(state, std::move(loaded.scene), p.source, request.ground, UpAxis::Y);
    state.options = loaded.options;
    state.fitView = request.options.count("size") == 0;
    return state;
}

}  // namespace

std::string startViewer(const std::string& address, int width, int height) {
    try {
        Page& p = page();
        const PageRequest request = parseAddress(address);
        view::State state = stateOf(p, request);
        p.announced = false;
        if (p.viewer) {
            p.viewer->replaceState(std::move(state));
            return "";
        }
        p.args.screenshotDir = "/tmp";
        p.viewer = std::make_unique<cli::viewer::Viewer>(
            p.args, false, width, height, std::move(state), std::vector<view::Command>{});
        emscripten_set_main_loop_arg(frame, nullptr, 0, false);
        return "";
    } catch (const std::exception& e) {
        return std::string("gnomon: error: ") + e.what();
    }
}

bool viewerDrawn() {
    return page().viewer && page().viewer->frameReady();
}

std::array<float, 4> viewerRect() {
    return page().viewer ? page().viewer->viewRect() : std::array<float, 4>{};
}

void resizeViewer(int width, int height) {
    if (page().viewer) page().viewer->resize(width, height);
}

}  // namespace gnomon::web
