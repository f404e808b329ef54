#!/usr/bin/env bash
# Renders the pictures of docs/techniques.md into docs/images/techniques/ (256x256, the
# Release build) from examples/presets.txt: each line an output name, then the render flags;
# then the coloured-shadow pictures.
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
done < examples/presets.txt
# Coloured shadows: a scene file (the presets are the viewer's too, and name built-in scenes),
# and the error maps `gnomon score` writes beside its render.
glass=examples/stained-glass.json
"$gnomon" render --size 256x256 --scene "$glass" --blend-shadows dithered --shadow-rays off \
    --out "$out/coloured-dithered.png"  # the maps' dithering: a ray meets the glass whole
"$gnomon" render --size 256x256 --scene "$glass" --out "$out/coloured.png"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$gnomon" score --size 256x256 --scene "$glass" --out-dir "$work/glass" >/dev/null
cp "$work/glass/tint-errors.png" "$out/coloured-errors.png"
stripes=../shared/scenes/AlphaBlendModeTest/AlphaBlendModeTest.glb
if [[ -f $stripes ]]; then
    for size in 1024 4096; do
        "$gnomon" score --size 256x256 --scene "$stripes" --ground --sun 30,60 \
            --map-size "$size" --out-dir "$work/stripes-$size" >/dev/null 2>&1
        cp "$work/stripes-$size/tint-errors.png" "$out/coloured-errors-$size.png"
    done
fi
echo "$out/coloured*.png"
# Far from the origin: Suzanne on a ground 100 000 units out, and its error map.
suzanne=../shared/scenes/Suzanne/Suzanne.gltf
if [[ -f $suzanne ]]; then
    printf '{"gnomon-scene": 1, "include": [{"scene": "%s", "transform": {"translate": [100000, 0, -100000]}}], "ground": true}\n' \
        "$(realpath "$suzanne")" >"$work/far.json"
    "$gnomon" score --size 256x256 --scene "$work/far.json" --out-dir "$work/far" >/dev/null 2>&1
    cp "$work/far/render.png" "$out/far-origin.png"
    cp "$work/far/errors.png" "$out/far-origin-errors.png"
    echo "$out/far-origin*.png"
fi
# Shadow rays on Sponza's atrium (quality-real.py's view): where uncertain traces, and the error
# maps of the maps alone and with rays where they are unsure.
if python3 scripts/quality-real.py --write-scene sponza-atrium "$work/atrium.json" 2>/dev/null; then
    mapfile -t view < <(python3 scripts/quality-real.py --view-flags sponza-atrium)
    "$gnomon" render --size 256x256 --scene "$work/atrium.json" "${view[@]}" \
        --shadow-rays uncertain --debug-view rays --out "$out/rays-atrium.png"
    for rays in off uncertain; do
        "$gnomon" score --size 256x256 --scene "$work/atrium.json" "${view[@]}" \
            --shadow-rays "$rays" --out-dir "$work/atrium-$rays" >/dev/null 2>&1
        cp "$work/atrium-$rays/errors.png" "$out/rays-atrium-errors-$rays.png"
    done
    echo "$out/rays-atrium*.png"
fi
