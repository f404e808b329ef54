#!/usr/bin/env bash
# Renders the sweeps of docs/results/performance.md: one `gnomon bench --sweep` per parameter on
# tutorial-room at 512x512, into docs/images/performance/ (CSV, SVG plot, JSON). Takes a few
# minutes; the machine should be otherwise idle.
set -euo pipefail
cd "$(dirname "$0")/.."
make build >/dev/null
gnomon=build/release/apps/gnomon/gnomon
out=docs/images/performance
mkdir -p "$out"
for sweep in lights local-lights map-size triangles cascades filter; do
    work=$(mktemp -d)
    "$gnomon" bench --scene tutorial-room --frames 7 --warmup 2 --sweep "$sweep" --out-dir "$work"
    cp "$work/sweep.csv" "$out/$sweep.csv"
    cp "$work/sweep.svg" "$out/$sweep.svg"
    cp "$work/bench.json" "$out/$sweep.json"
    rm -rf "$work"
done
# Many local lights inside Sponza's atrium (docs/results/performance.md), when the model is here.
sponza=../shared/scenes/DabrovicSponza/dabrovic_sponza.glb
if [[ -f $sponza ]]; then
    work=$(mktemp -d)
    "$gnomon" bench --scene "$sponza" --camera-eye -10.5,1.6,-1.2 --camera-target 10,4.5,0 \
        --camera-fov 65 --frames 7 --warmup 2 --sweep local-lights --values 1,8,64,256 \
        --size 512x512 --out-dir "$work"
    for f in csv svg; do cp "$work/sweep.$f" "$out/local-lights-sponza.$f"; done
    cp "$work/bench.json" "$out/local-lights-sponza.json"
    rm -rf "$work"
fi
