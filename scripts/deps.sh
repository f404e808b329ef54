#!/usr/bin/env bash
# Installs the Debian 12 packages gnomon builds and runs with, only those that are missing,
# plus any named as arguments (scripts/fuzz.sh adds clang); `--only P...` checks only the
# packages named (scripts/web-deps.sh: the web build needs none of the native libraries). As
# root it calls apt-get; otherwise sudo (non-interactive); when neither is possible it prints
# the exact command to run and fails.
set -euo pipefail

if [[ "${1:-}" == "--only" ]]; then
    shift
    packages=("$@")
else
    packages=(
        build-essential cmake pkg-config clang-format
        libepoxy-dev libegl-dev libegl1 libegl-mesa0 libgl1 libopengl0 libgl1-mesa-dri
        libglfw3-dev libimgui-dev libglm-dev libpng-dev libstb-dev libcli11-dev
        libtinygltf-dev nlohmann-json3-dev libembree-dev libassimp-dev
        libgtest-dev libgmock-dev libbenchmark-dev libmeshoptimizer-dev
        # the independent ray caster that checks the reference (tests/crosscheck)
        libcgal-dev
        xvfb xauth python3
        # the viewer's font (DejaVu Sans)
        fonts-dejavu-core
        # glmark2's horse (/usr/share/glmark2/models/horse.3ds), a view of scripts/quality-real.py
        glmark2-data
        "$@"
    )
fi

missing=()
for p in "${packages[@]}"; do
    status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
    [[ "$status" == "install ok installed" ]] || missing+=("$p")
done
[[ ${#missing[@]} -eq 0 ]] && exit 0

echo "gnomon: installing missing packages: ${missing[*]}"
if [[ $(id -u) -eq 0 ]]; then
    run=()
elif command -v sudo >/dev/null 2>&1 && sudo -n true 2>/dev/null; then
    run=(sudo)
else
    echo "gnomon: cannot install packages (not root, no password-less sudo). Run:" >&2
    echo "    sudo apt-get update && sudo apt-get install -y ${missing[*]}" >&2
    exit 1
fi
export DEBIAN_FRONTEND=noninteractive
"${run[@]}" apt-get update -qq
"${run[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
