#include "PageViewer.h"

#include <emscripten.h>

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
    std::string scene;       // the address's scene, for the title
    bool announced = false;  // the title says ready (or the error) for the current view
    std::string downloaded;  // the last file the viewer wrote, handed to the browser
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

// The browser's frame: one turn of the viewer's loop, the files it wrote, then the title
// once the view is drawn.
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
    if (p.announced) return;
    if (!p.viewer->frameError().empty()) {
        setTitle("gnomon error: " + p.viewer->frameError());
        p.announced = true;
    } else if (p.viewer->frameReady()) {
        setTitle("gnomon ready: " + p.scene + " " + std::to_string(p.viewer->drawnWidth()) + "x" +
                 std::to_string(p.viewer->drawnHeight()));
        p.announced = true;
    }
}

// The viewer's state for the page's request: its scene, options and size.
view::State stateOf(const PageRequest& request) {
    PageScene loaded = loadRequest(request, kBundle);
    view::State state;
    view::show(state, std::move(loaded.scene), request.scene, request.ground, UpAxis::Y);
    state.options = loaded.options;
    state.fitView = request.options.count("size") == 0;
    return state;
}

}  // namespace

std::string startViewer(const std::string& address, int width, int height) {
    try {
        Page& p = page();
        const PageRequest request = parseAddress(address);
        view::State state = stateOf(request);
        p.scene = state.scene.name;
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
