#!/usr/bin/env bash
# Renders the sweeps of docs/results/performance.md: one `gnomon bench --sweep` per parameter on
# tutorial-room at 512x512, into docs/images/performance/ (CSV, SVG plot, JSON), and the
# local-lights sweeps in Sponza's atrium with every map redrawn and with moving lights under a
# redraw budget of 8. Takes a few minutes (the Sponza runs about ten more); the machine should be
# otherwise idle. Usage: scripts/performance.sh [SWEEP...] (default: all of them; local-lights
# includes Sponza's).
set -euo pipefail
cd "$(dirname "$0")/.."
make build >/dev/null
gnomon=build/release/apps/gnomon/gnomon
out=docs/images/performance
mkdir -p "$out"
sweeps=("$@")
[[ ${#sweeps[@]} -gt 0 ]] || sweeps=(lights local-lights map-size triangles cascades filter)
wanted() { [[ " ${sweeps[*]} " == *" $1 "* ]]; }
for sweep in "${sweeps[@]}"; do
    work=$(mktemp -d)
    "$gnomon" bench --scene tutorial-room --frames 7 --warmup 2 --sweep "$sweep" --out-dir "$work"
    cp "$work/sweep.csv" "$out/$sweep.csv"
    cp "$work/sweep.svg" "$out/$sweep.svg"
    cp "$work/bench.json" "$out/$sweep.json"
    rm -rf "$work"
done
# Many local lights (docs/results/performance.md): tutorial-room's lights moving under a redraw
# budget of 8, and Sponza's atrium both ways, when the model is here.
# local_sweep NAME BENCH_FLAGS...: one local-lights sweep at 512x512 into $out/NAME.*
local_sweep() {
    local name=$1 work
    shift
    work=$(mktemp -d)
    "$gnomon" bench "$@" --frames 7 --warmup 2 --sweep local-lights --size 512x512 \
        --out-dir "$work"
    for f in csv svg; do cp "$work/sweep.$f" "$out/$name.$f"; done
    cp "$work/bench.json" "$out/$name.json"
    rm -rf "$work"
}
sponza=../shared/scenes/DabrovicSponza/dabrovic_sponza.glb
atrium=(--scene "$sponza" --camera-eye -10.5,1.6,-1.2 --camera-target 10,4.5,0 --camera-fov 65)
if wanted local-lights; then
    local_sweep local-lights-moving --scene tutorial-room --values 1,8,64,256 --moving-lights \
        --map-redraws 8
    if [[ -f $sponza ]]; then
        local_sweep local-lights-sponza "${atrium[@]}" --values 1,8,64,256
        local_sweep local-lights-sponza-moving "${atrium[@]}" --values 1,8,64,256 \
            --moving-lights --map-redraws 8
    fi
fi
