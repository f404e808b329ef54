#!/usr/bin/env bash
# gnomon's reference against the independent caster (tests/crosscheck, CGAL) on every view of
# scripts/quality-real.py: one markdown row per view. Run after `make build`:
#   scripts/crosscheck-real.sh [WxH]      (default 256x256)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=$root/build/release/tests/crosscheck/gnomon_crosscheck
size=${1:-256x256}
[[ -x $bin ]] || { echo "crosscheck-real: $bin not found: run \`make build\` first" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "| view | pairs | disagree | pixels on another surface | light reaches differs | not compared |"
echo "|---|---|---|---|---|---|"
for view in $(python3 "$root/scripts/quality-real.py" --list); do
    if ! python3 "$root/scripts/quality-real.py" --write-scene "$view" "$work/$view.json" 2>/dev/null; then
        echo "| $view | skipped: model absent | | | | |"
        continue
    fi
    "$bin" "$work/$view.json" "$size" | python3 -c '
import re, sys
line, view = sys.stdin.read(), sys.argv[1]
n = [int(v) for v in re.findall(r"(\d+) (?:pixel x light pairs|disagree|pixels,|see another|pairs differ|not compared)", line)]
pairs, dis, pixels, other, reach, skipped = n
print(f"| {view} | {pairs} | {dis} ({100 * dis / max(pairs, 1):.3f} %) | {other} of {pixels} | {reach} | {skipped} |")
' "$view"
done
