#!/usr/bin/env bash
# gnomon against three.js in headless Chromium, side by side on this machine, on gnomon's book
# scene (book-triangle) or glmark2's shadow scene (horse: bench/peers/glmark2/shadow.json).
# Each round runs `gnomon bench` on the scene (headless EGL, Mesa llvmpipe), then peer.html
# (the same scene in three.js) in Debian's Chromium twice: on SwiftShader (Chromium's own CPU
# rasteriser, its default without a GPU) and on ANGLE over the system's OpenGL (llvmpipe, the
# rasteriser gnomon runs on). Every frame of each redraws its shadow map and view and waits
# for them. Prints every round, the medians and gnomon / three.js (below 1: gnomon is faster).
# Usage: bench/peers/threejs/run.sh [book|horse] [ROUNDS] [-- extra gnomon bench flags]
# Installs Debian's chromium (and glmark2-data for the horse) through scripts/deps.sh and
# three.js and playwright-core from npm (package-lock.json) when missing; needs Node.js with
# npm, and `make build` first.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../../.." && pwd)
scene=${1:-book}
shift $(( $# < 1 ? $# : 1 ))
rounds=${1:-5}
shift $(( $# < 1 ? $# : 1 ))
case $scene in
    book) gnomonScene=book-triangle ;;
    horse) gnomonScene=$here/../glmark2/shadow.json ;;
    *) echo "run.sh: unknown scene '$scene': expected book or horse" >&2; exit 2 ;;
esac
[[ ${1:-} == -- ]] && shift
[[ $rounds =~ ^[1-9][0-9]*$ ]] || { echo "run.sh: ROUNDS must be a positive number" >&2; exit 2; }
gnomon=$root/build/release/apps/gnomon/gnomon
[[ -x $gnomon ]] || { echo "run.sh: $gnomon is missing: run 'make build' first" >&2; exit 1; }
command -v npm >/dev/null || { echo "run.sh: needs Node.js and npm (not found)" >&2; exit 1; }
"$root/scripts/deps.sh" chromium glmark2-data
[[ -d $here/node_modules/three && -d $here/node_modules/playwright-core ]] ||
    (cd "$here" && npm ci --no-audit --no-fund --loglevel=error)

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
median() { python3 -c "import json,sys; print(f\"{json.load(open(sys.argv[1]))$2:.2f}\")" "$1"; }
for ((i = 1; i <= rounds; ++i)); do
    "$gnomon" bench --scene "$gnomonScene" --frames 60 --out-dir "$work/gnomon-$i" "$@" \
        >"$work/gnomon-$i.txt" 2>&1 || { cat "$work/gnomon-$i.txt" >&2; exit 1; }
    median "$work/gnomon-$i/bench.json" "['runs'][0]['frame_ms']['median']" >"$work/gnomon-$i.ms"
    line="round $i: gnomon $(cat "$work/gnomon-$i.ms") ms"
    for gl in swiftshader egl; do
        node "$here/time.mjs" "$scene" 60 "$gl" >"$work/$gl-$i.json" 2>"$work/$gl-$i.err" ||
            { cat "$work/$gl-$i.err" >&2; exit 1; }
        median "$work/$gl-$i.json" "['median']" >"$work/$gl-$i.ms"
        line+=", three.js on $gl $(cat "$work/$gl-$i.ms") ms"
    done
    echo "$line"
done
python3 - "$work" "$rounds" <<'PY'
import json, statistics, sys
work, rounds = sys.argv[1], int(sys.argv[2])
ms = {w: [float(open(f"{work}/{w}-{i}.ms").read()) for i in range(1, rounds + 1)]
      for w in ("gnomon", "swiftshader", "egl")}
g = statistics.median(ms["gnomon"])
for gl in ("swiftshader", "egl"):
    info = json.load(open(f"{work}/{gl}-1.json"))
    t = statistics.median(ms[gl])
    print(f"median frame: gnomon {g:.2f} ms, three.js r{info['three']} on {info['renderer']} "
          f"{t:.2f} ms, gnomon/three.js {g / t:.2f}")
PY
