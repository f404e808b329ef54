#!/usr/bin/env bash
# gnomon against glmark2 on glmark2's own shadow scene, side by side on this machine.
# Each round runs `glmark2 -b shadow` (under xvfb-run, 800x600, a window as glmark2 needs)
# and then `gnomon bench` on shadow.json (the same horse, ground quad, light and projection,
# headless), so the machine's drift hits both alike. Prints every round, each side's median
# frame time and the ratio gnomon / glmark2 (below 1: gnomon is faster).
# Usage: bench/peers/glmark2/run.sh [ROUNDS] [-- extra gnomon bench flags]
# Installs glmark2-x11 and glmark2-data (Debian) through scripts/deps.sh when missing;
# needs `make build` first.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../../.." && pwd)
rounds=${1:-5}
shift $(( $# < 1 ? $# : 1 ))
[[ ${1:-} == -- ]] && shift
gnomon=$root/build/release/apps/gnomon/gnomon
[[ -x $gnomon ]] || { echo "run.sh: $gnomon is missing: run 'make build' first" >&2; exit 1; }
"$root/scripts/deps.sh" glmark2-x11 glmark2-data
[[ $rounds =~ ^[1-9][0-9]*$ ]] || { echo "run.sh: ROUNDS must be a positive number" >&2; exit 2; }

# gnomon keeps its freed heap (gnomon::keepFreedHeap: llvmpipe allocates and frees on every
# draw, and glibc's default trimming makes the kernel fault those pages in again); glmark2 runs
# with the same thresholds, so both pay the same for memory. Without them glmark2 ran at either
# ~5 or ~12 ms a frame depending on when glibc raised its own thresholds (docs/performance.md).
heap=glibc.malloc.mmap_threshold=33554432:glibc.malloc.trim_threshold=67108864
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for ((i = 1; i <= rounds; ++i)); do
    # glmark2 prints "[shadow] ...: FPS: 147 FrameTime: 6.819 ms" (mean over its duration).
    GLIBC_TUNABLES=$heap xvfb-run -a -s "-screen 0 1024x768x24" \
        glmark2 -b shadow:duration=5 --size 800x600 >"$work/glmark2-$i.txt" 2>&1 \
        || { cat "$work/glmark2-$i.txt" >&2; exit 1; }
    sed -n 's/.*\[shadow\].*FrameTime: \([0-9.]*\) ms.*/\1/p' "$work/glmark2-$i.txt" \
        >"$work/glmark2-$i.ms"
    [[ -s $work/glmark2-$i.ms ]] || { echo "run.sh: no FrameTime in glmark2's output:" >&2
                                      cat "$work/glmark2-$i.txt" >&2; exit 1; }
    "$gnomon" bench --scene "$here/shadow.json" --frames 60 --out-dir "$work/gnomon-$i" "$@" \
        >"$work/gnomon-$i.txt" 2>&1 || { cat "$work/gnomon-$i.txt" >&2; exit 1; }
    python3 -c "import json,sys; print(f\"{json.load(open(sys.argv[1]))['runs'][0]['frame_ms']['median']:.2f}\")" \
        "$work/gnomon-$i/bench.json" >"$work/gnomon-$i.ms"
    echo "round $i: glmark2 $(cat "$work/glmark2-$i.ms") ms, gnomon $(cat "$work/gnomon-$i.ms") ms"
done
python3 - "$work" "$rounds" <<'PY'
import statistics, sys
work, rounds = sys.argv[1], int(sys.argv[2])
ms = {w: [float(open(f"{work}/{w}-{i}.ms").read()) for i in range(1, rounds + 1)]
      for w in ("glmark2", "gnomon")}
g, n = statistics.median(ms["glmark2"]), statistics.median(ms["gnomon"])
print(f"median frame: glmark2 {g:.2f} ms, gnomon {n:.2f} ms, gnomon/glmark2 {n / g:.2f}")
PY
