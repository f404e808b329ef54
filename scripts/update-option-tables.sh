#!/usr/bin/env bash
# Rewrites the option tables of README.md and docs/scene-file.md (between their
# <!-- options:KIND --> and <!-- options:end --> markers) from the option schema, as
# `gnomon options --markdown KIND` prints it. The cli.option_tables test fails until this is
# run after a change to an option's name, doc, range or default.
# Usage: scripts/update-option-tables.sh [GNOMON_BINARY]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
gnomon=${1:-$root/build/release/apps/gnomon/gnomon}
[[ -x $gnomon ]] || { echo "no gnomon binary at $gnomon (make build first)" >&2; exit 1; }
for pair in "flags:README.md" "scene-file:docs/scene-file.md"; do
    kind=${pair%%:*}; doc=$root/${pair#*:}
    table=$(mktemp)
    "$gnomon" options --markdown "$kind" >"$table"
    python3 - "$doc" "$kind" "$table" <<'PY'
import sys, re
doc, kind, table = sys.argv[1], sys.argv[2], open(sys.argv[3]).read()
text = open(doc).read()
start, end = f"<!-- options:{kind} -->\n", "<!-- options:end -->"
i = text.index(start) + len(start)
j = text.index(end, i)
open(doc + ".tmp", "w").write(text[:i] + table + text[j:])
PY
    mv "$doc.tmp" "$doc"
    rm -f "$table"
    echo "updated $doc"
done
