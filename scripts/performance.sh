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
for sweep in lights map-size triangles cascades filter; do
    work=$(mktemp -d)
    "$gnomon" bench --scene tutorial-room --frames 7 --warmup 2 --sweep "$sweep" --out-dir "$work"
    cp "$work/sweep.csv" "$out/$sweep.csv"
    cp "$work/sweep.svg" "$out/$sweep.svg"
    cp "$work/bench.json" "$out/$sweep.json"
    rm -rf "$work"
done
