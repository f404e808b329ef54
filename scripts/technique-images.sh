#!/usr/bin/env bash
# Renders the pictures of docs/techniques.md into docs/images/techniques/ (256x256, the
# Release build). Each line: an output name, then the render flags that make it.
set -euo pipefail
cd "$(dirname "$0")/.."
make build >/dev/null
gnomon=build/release/apps/gnomon/gnomon
out=docs/images/techniques
mkdir -p "$out"
while read -r name flags; do
    [[ -z "$name" || "$name" == \#* ]] && continue
    # shellcheck disable=SC2086  # the flags are words on purpose
    "$gnomon" render --size 256x256 $flags --out "$out/$name.png"
    echo "$out/$name.png"
done <<'LIST'
# Light types
directional       --scene tutorial-directional
spot              --scene tutorial-spot
area              --scene tutorial-area
point             --scene tutorial-point
mixed             --scene mixed-lights
# Light camera and what lies outside it
outside-clamp     --scene tutorial-directional --preset textbook --outside clamp
outside-lit       --scene tutorial-directional --preset textbook --outside lit
frusta            --scene mixed-lights --debug-view light-frusta
# Depth storage
r8-near           --scene book-triangle --preset textbook --depth-format r8 --bias-constant 0.005 --map-filter linear
r8-far            --scene book-triangle-far --preset textbook --depth-format r8 --bias-constant 0.005 --map-filter linear
packed-far        --scene book-triangle-far --preset textbook --depth-format rgba8-packed-256
depth16-far       --scene book-triangle-far --depth-format depth16
shadow-map        --scene tutorial-room --debug-view shadow-map
cube-map          --scene tutorial-point --debug-view shadow-map
# Acne and peter-panning
textbook-room     --scene tutorial-room --preset textbook
no-bias           --scene tutorial-room --bias-constant 0 --bias-depth-aware 0 --bias-slope 0 --bias-units 0 --normal-offset 0 --cull none
default-room      --scene tutorial-room
panning-thin      --scene tutorial-room-thin --bias-constant 0.06 --normal-offset 0
default-thin      --scene tutorial-room-thin
front-cull-thin   --scene tutorial-room-thin --cull front --bias-slope 0 --bias-units 0 --normal-offset 0 --bias-constant 0
# Filtering
map-64            --scene tutorial-room --map-size 64 --filter none
filter-none       --scene tutorial-room --map-size 256 --filter none
filter-hw2x2      --scene tutorial-room --map-size 256 --filter hw2x2
filter-pcf5       --scene tutorial-room --map-size 256 --filter pcf --pcf-size 5
filter-poisson    --scene tutorial-room --map-size 256 --filter poisson --pcf-size 5
filter-pcss       --scene tutorial-room --filter pcss --light-angle 3
pcss-spot         --scene tutorial-spot --filter pcss --light-radius 0.5
# Cascades
cascades-1        --scene tutorial-room --map-size 256
cascades-4        --scene tutorial-room --map-size 256 --cascades 4
cascades-debug    --scene tutorial-room --map-size 256 --cascades 4 --cascade-lambda 0.3 --debug-view cascades
LIST
