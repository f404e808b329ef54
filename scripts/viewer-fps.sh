#!/usr/bin/env bash
# Frame rate of `gnomon view` in a 1280x720 window (under xvfb-run) on every built-in scene:
# 60 frames orbiting the camera (every frame re-rendered, fitted light cameras follow the
# view) and 60 frames standing still (nothing re-rendered). Prints two lines per scene.
# MEASURE=off switches the per-pass timing (a glFinish after each pass) off.
set -euo pipefail
cd "$(dirname "$0")/.."
make build >/dev/null
gnomon=$PWD/build/release/apps/gnomon/gnomon
script=$(mktemp)
trap 'rm -f "$script"' EXIT
cat >"$script" <<SCRIPT
measure ${MEASURE:-on}
wait 5
stats
repeat 60 orbit 1 0
stats
wait 60
stats
quit
SCRIPT
for scene in $("$gnomon" scenes --names); do
    xvfb-run -a -s "-screen 0 1280x1024x24" "$gnomon" view --scene "$scene" --window 1280x720 \
        --script "$script" | sed -n '2,3p' | sed "s/^gnomon view: //; 1s/frames,/frames orbiting,/; 2s/frames,/frames still,/"
done
