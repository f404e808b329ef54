#!/usr/bin/env bash
# Frame time of two gnomon binaries measured side by side: ROUNDS rounds, each running
# `gnomon bench` once with OLD then once with NEW (same scene, size and flags), so the
# machine's drift hits both alike. Prints each round, the median frame time of each binary
# and their ratio (new / old). Usage:
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
        python3 -c "import json,sys; r=json.load(open(sys.argv[1]))['runs'][0]; print(r['frame_ms']['median'])" \
            "$work/$which-$i/bench.json" >"$work/$which-$i.ms"
        echo "round $i $which $(cat "$work/$which-$i.ms") ms"
    done
done
python3 - "$work" "$rounds" <<'PY'
import statistics, sys
work, rounds = sys.argv[1], int(sys.argv[2])
ms = {w: [float(open(f"{work}/{w}-{i}.ms").read()) for i in range(1, rounds + 1)] for w in ("old", "new")}
o, n = statistics.median(ms["old"]), statistics.median(ms["new"])
print(f"median frame: old {o:.2f} ms, new {n:.2f} ms, new/old {n / o:.2f}")
PY
