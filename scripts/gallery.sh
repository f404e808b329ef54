#!/usr/bin/env bash
# Renders every scene of ../shared/scenes (beside the repository) at 256x256 with gnomon's
# defaults on a --ground (so every model shows its shadow) into docs/images/gallery/, for
# the README's gallery, and prints each scene's load and first-frame times. Usage: scripts/gallery.sh [SHARED_SCENES_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
scenes=${1:-../shared/scenes}
gnomon=build/release/apps/gnomon/gnomon
[ -x "$gnomon" ] || make build
out=docs/images/gallery
mkdir -p "$out"
for dir in "$scenes"/*/; do
    name=$(basename "$dir")
    file=$(find "$dir" -maxdepth 2 \( -name '*.gltf' -o -name '*.glb' \) | sort | head -n 1)
    [ -n "$file" ] || continue
    echo "== $name"
    "$gnomon" --verbose render --scene "$file" --ground --size 256x256 --out "$out/$name.png" 2>&1 |
        grep -E "loaded|first frame" || true
done
