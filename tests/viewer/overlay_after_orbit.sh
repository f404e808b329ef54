#!/usr/bin/env bash
# viewer.overlay_after_orbit: a score's error overlay shows over the frame it scored and is
# gone once the camera moves. In a 640x480 window with no side view the camera's view is the
# 384x336 area at (256, 0) (Viewer::frame's layout); that area of a window shot, below the
# band where the sun's icon is drawn, is compared with a screenshot of the same settings:
# different while the overlay is on (the error map is dark where the frame is right), equal
# after an orbit (no stale map blended over the new frame).
# Exit 77 (skipped) when no window can be opened.
set -uo pipefail
source "$(dirname "$0")/run_view.sh"
gnomon=$1 compare=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
cat >"$work/script.txt" <<SCRIPT
side none
wait 3
score
wait-score
wait 2
window-shot $work/scored-window.png
screenshot $work/scored.png
orbit 25 -5
wait 3
window-shot $work/orbited-window.png
screenshot $work/orbited.png
quit
SCRIPT
run_view --window 640x480 --scene tutorial-room --script "$work/script.txt"
area="256,60,384,276 0,60"
if "$compare" "$work/scored-window.png" "$work/scored.png" $area; then
    echo "the error overlay was not drawn over the scored frame"
    exit 1
fi
"$compare" "$work/orbited-window.png" "$work/orbited.png" $area || {
    echo "after the orbit the view is not the frame alone (a stale overlay?)"
    exit 1
}
