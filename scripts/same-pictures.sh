#!/usr/bin/env bash
# Are two gnomon builds' pictures the same, byte for byte? Renders every built-in scene, the
# shared glTF scenes (../shared/scenes, when present) and the built-ins under each shadow
# technique (filters, depth formats, cascades, point maps, receiver plane, contact and
# coloured shadows, output encodings, debug views) at 256x256 with both binaries and compares
# the PNGs. For refactors that must not change a pixel. Prints each differing render and a
# count; exits 1 when any differs or fails. Usage:
#   scripts/same-pictures.sh OLD_GNOMON NEW_GNOMON [OUT_DIR]
# e.g. scripts/same-pictures.sh ../base/build/release/apps/gnomon/gnomon build/release/apps/gnomon/gnomon
set -euo pipefail
old=${1:?usage: same-pictures.sh OLD_GNOMON NEW_GNOMON [OUT_DIR]}
new=${2:?usage: same-pictures.sh OLD_GNOMON NEW_GNOMON [OUT_DIR]}
out=${3:-$(mktemp -d)}
mkdir -p "$out"
shared="$(cd "$(dirname "$0")/.." && pwd)/../shared/scenes"
same=0 differ=0 failed=0

# compare NAME FLAGS...: one render with each binary.
compare() {
    local name=$1
    shift
    for which in old new; do
        local bin=$old
        [[ $which == new ]] && bin=$new
        if ! "$bin" render "$@" --size 256x256 --out "$out/$name-$which.png" 2>"$out/$name-$which.err"; then
            echo "FAILED ($which): $name: $* ($(tail -1 "$out/$name-$which.err"))"
            failed=$((failed + 1))
            return
        fi
    done
    if cmp -s "$out/$name-old.png" "$out/$name-new.png"; then
        same=$((same + 1))
    else
        echo "DIFFERS: $name: $*"
        differ=$((differ + 1))
    fi
}

for scene in $("$new" scenes --names); do
    compare "$scene" --scene "$scene"
done
if [[ -d $shared ]]; then
    for dir in "$shared"/*/; do
        model=$(ls "$dir"*.gltf "$dir"*.glb 2>/dev/null | head -1 || true)
        [[ -n $model ]] && compare "shared-$(basename "$dir")" --scene "$model"
    done
fi
# The techniques, each on the scene that exercises it.
for filter in none pcf poisson pcss evsm2 evsm4 msm; do
    compare "room-$filter" --scene tutorial-room --filter "$filter"
    compare "point-$filter" --scene tutorial-point --filter "$filter"
done
for format in depth16 depth24 r8 rgba8-packed-256 rgba8-packed-255; do
    compare "room-$format" --scene tutorial-room --depth-format "$format"
done
compare room-cascades --scene tutorial-room --cascades 3
compare room-cascade-tint --scene mixed-lights --debug-view cascades
compare point-cube --scene tutorial-point --point-maps cube
compare spot-receiver-plane-off --scene tutorial-spot --receiver-plane off
compare room-contact --scene tutorial-room --contact-length 0.2
compare mixed-srgb --scene mixed-lights --output-encoding srgb
compare mixed-boxes --scene mixed-lights --fit-to boxes
compare spot-map --scene tutorial-spot --debug-view shadow-map
compare point-map --scene tutorial-point --debug-view shadow-map
compare mixed-frusta --scene mixed-lights --debug-view light-frusta
if [[ -f examples/stained-glass.json ]]; then
    compare glass-coloured --scene examples/stained-glass.json
    compare glass-dithered --scene examples/stained-glass.json --blend-shadows dithered
fi
echo "same=$same differs=$differ failed=$failed (renders in $out)"
[[ $differ == 0 && $failed == 0 ]]
