#!/usr/bin/env bash
# Renders every built-in scene into OUT (default out/) and prints the paths written.
set -euo pipefail
gnomon=${1:?usage: demo.sh GNOMON_BINARY [OUT_DIR]}
out=${2:-out}
mkdir -p "$out"
for scene in $("$gnomon" scenes --names); do
    "$gnomon" render --scene "$scene" --out "$out/$scene.png" --shadow-maps "$out/maps-$scene"
    echo "wrote $out/$scene.png (shadow maps in $out/maps-$scene/)"
done
