// The viewer in the page: `gnomon view`'s app (apps/gnomon/viewer: the four tabs, the map
// beside the view, light gizmos, presets, pass times, keyboard and mouse) on the page's
// canvas, one step of its loop per browser frame. The page's title says when the first frame
// with all its shadow maps is drawn ("gnomon ready: ...") or what went wrong ("gnomon error:
// ..."), as the picture-only page does.
#pragma once

#include <array>
#include <string>

namespace gnomon::web {

// Shows the view the address asks for (PageRequest.h) in a viewer of width x height CSS
// pixels on Module.canvas, made at the first call and kept (a later call replaces its scene
// and options). Returns "" or the error in the CLI's words.
std::string startViewer(const std::string& address, int width, int height);

// The viewer's current state is drawn (the browser tests wait for it after an input).
bool viewerDrawn();
// Where the camera's view is on the canvas (CSS pixels): x, y, width, height.
std::array<float, 4> viewerRect();
// The viewer's canvas follows the browser's window (CSS pixels).
void resizeViewer(int width, int height);

}  // namespace gnomon::web
