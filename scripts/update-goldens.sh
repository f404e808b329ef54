#!/usr/bin/env bash
# Regenerates tests/golden/*.png: every built-in scene at 256x256 with its own options,
# rendered by the Release build. Review the images before committing them.
set -euo pipefail
cd "$(dirname "$0")/.."
make build >/dev/null
gnomon=build/release/apps/gnomon/gnomon
for scene in $("$gnomon" scenes --names); do
    "$gnomon" render --scene "$scene" --size 256x256 --out "tests/golden/$scene.png"
    echo "tests/golden/$scene.png"
done
