#!/usr/bin/env bash
# Frame time of two gnomon binaries measured side by side: ROUNDS rounds, each running
# `gnomon bench` once with OLD then once with NEW (same scene, size and flags), so the
# machine's drift hits both alike. Prints each round, then per binary the median over rounds
# of the frame's median and of the main pass's 10th percentile, and their ratios (new / old).
# The main pass's p10 is the steadier of the two on a shared machine: a run slowed by
# other work moves its median more than its fastest frames. Usage:
#   scripts/ab-bench.sh OLD_GNOMON NEW_GNOMON [SCENE] [ROUNDS] [-- extra bench flags]
# e.g. scripts/ab-bench.sh /tmp/base/build/apps/gnomon/gnomon build/release/apps/gnomon/gnomon tutorial-room 7
set -euo pipefail
old=$1; new=$2; scene=${3:-tutorial-room}; rounds=${4:-7}
shift $(( $# < 4 ? $# : 4 ))
[[ ${1:-} == -- ]] && shift
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for ((i = 1; i <= rounds; ++i)); do
    for which in old new; do
        bin=$old; [[ $which == new ]] && bin=$new
        "$bin" bench --scene "$scene" --frames 20 --out-dir "$work/$which-$i" "$@" >/dev/null 2>&1
        python3 - "$work/$which-$i/bench.json" >"$work/$which-$i.ms" <<'PY'
import json, sys
run = json.load(open(sys.argv[1]))["runs"][0]
main = next(p for p in run["passes"] if p["name"] == "main")
print(run["frame_ms"]["median"], main["ms"]["p10"])
PY
        echo "round $i $which: frame $(cut -d' ' -f1 "$work/$which-$i.ms") ms, main p10 $(cut -d' ' -f2 "$work/$which-$i.ms") ms"
    done
done
python3 - "$work" "$rounds" <<'PY'
import statistics, sys
work, rounds = sys.argv[1], int(sys.argv[2])
ms = {w: [[float(v) for v in open(f"{work}/{w}-{i}.ms").read().split()] for i in range(1, rounds + 1)]
      for w in ("old", "new")}
for k, name in ((0, "median frame"), (1, "main pass p10")):
    o = statistics.median(r[k] for r in ms["old"])
    n = statistics.median(r[k] for r in ms["new"])
    print(f"{name}: old {o:.2f} ms, new {n:.2f} ms, new/old {n / o:.2f}")
PY
