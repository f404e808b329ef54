#!/usr/bin/env bash
# viewer.screenshot.SCENE: `gnomon view` starts on SCENE in a window (run under xvfb-run),
# draws frames, takes a screenshot and saves its settings through a --script, and exits 0;
# the screenshot must equal `gnomon render` of the saved scene file within the golden
# tolerance. Exit 77 (skipped) when no window can be opened.
set -uo pipefail
source "$(dirname "$0")/run_view.sh"
gnomon=$1 compare=$2 scene=$3 work=$4
rm -rf "$work" && mkdir -p "$work"
cat >"$work/script.txt" <<SCRIPT
wait 2
set --size 256x256
orbit 20 -5
wait 3
screenshot $work/view.png
save $work/saved.json
quit
SCRIPT
run_view --scene "$scene" --script "$work/script.txt"
"$gnomon" render --scene "$work/saved.json" --out "$work/render.png" || exit 1
"$compare" "$work/view.png" "$work/render.png"
