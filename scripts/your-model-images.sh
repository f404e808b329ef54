#!/usr/bin/env bash
# The pictures of docs/your-model.md: the Fox of ../shared/scenes (or the scene folder given)
# rendered and scored with the commands that page shows, at 320x320, into
# docs/images/your-model/. Usage: scripts/your-model-images.sh [SHARED_SCENES_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
scenes=${1:-../shared/scenes}
fox=$scenes/Fox/Fox.glb
[[ -f $fox ]] || { echo "no $fox" >&2; exit 1; }
gnomon=build/release/apps/gnomon/gnomon
[[ -x $gnomon ]] || make build
out=docs/images/your-model
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$out"
size=(--size 320x320)
"$gnomon" render --scene "$fox" "${size[@]}" --out "$out/1-as-loaded.png"
"$gnomon" render --scene "$fox" --ground "${size[@]}" --out "$out/2-ground.png"
"$gnomon" render --scene "$fox" --ground --sun 300,20 "${size[@]}" --out "$out/3-low-sun.png"
"$gnomon" score --scene "$fox" --ground --sun 300,20 "${size[@]}" --out-dir "$work/s" >/dev/null
cp "$work/s/errors.png" "$out/4-errors-defaults.png"
"$gnomon" score --scene "$fox" --ground --sun 300,20 --map-size 256 --filter none "${size[@]}" \
    --out-dir "$work/t" >/dev/null
cp "$work/t/errors.png" "$out/5-errors-small-map.png"
"$gnomon" render --scene "$fox" --ground --sun 300,20 --filter pcss --light-angle 2 "${size[@]}" \
    --out "$out/6-soft.png"
echo "wrote $out"
