#!/usr/bin/env bash
# Renders the pictures of docs/techniques.md into docs/images/techniques/ (256x256, the
# Release build) from examples/presets.txt: each line an output name, then the render flags.
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
