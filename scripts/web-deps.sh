#!/usr/bin/env bash
# What `make web` and the browser tests need, on a fresh Debian 12 too (CI runs them there):
#  1. Debian's Emscripten and Chromium and the header-only libraries the portable code
#     includes, through scripts/deps.sh (root, password-less sudo, or the command to run);
#  2. the source packages of Dear ImGui and meshoptimizer, which have no wasm build in Debian,
#     unpacked under build/web-src/ (imgui/ and meshoptimizer/ name them), with a deb-src
#     line for apt added under /etc/apt/sources.list.d/ when apt has none;
#  3. puppeteer-core as tests/web/package-lock.json pins it, into tests/web/node_modules.
# Each step is skipped when what it makes is already there.
set -euo pipefail
cd "$(dirname "$0")/.."

# Debian 12's versions: the page is built against these, and the source packages must match.
imgui_version=1.86+ds-1
meshopt_version=0.18+dfsg-2
src=build/web-src

as_root() {
    if [[ $(id -u) -eq 0 ]]; then
        "$@"
    elif command -v sudo >/dev/null 2>&1 && sudo -n true 2>/dev/null; then
        sudo "$@"
    else
        echo "gnomon: cannot run as root (not root, no password-less sudo): $*" >&2
        return 1
    fi
}

# 1. Packages. npm only where the machine has none (Debian's emscripten brings a Node).
packages=(emscripten chromium cmake make python3 dpkg-dev
    libglm-dev libstb-dev libtinygltf-dev nlohmann-json3-dev libcli11-dev fonts-dejavu-core)
command -v npm >/dev/null 2>&1 || packages+=(npm)
scripts/deps.sh --only "${packages[@]}"

# 2. Source packages. apt-get source needs deb-src lines: made from the deb lines of Debian's
# own sources (same mirror, suites and key) when apt has no source index at all.
if [[ ! -d $src/imgui || ! -d $src/meshoptimizer ]]; then
    if ! apt-cache showsrc imgui >/dev/null 2>&1; then
        list=/etc/apt/sources.list.d/gnomon-deb-src.sources
        if [[ -f /etc/apt/sources.list.d/debian.sources ]]; then
            sed 's/^Types: deb$/Types: deb-src/' /etc/apt/sources.list.d/debian.sources
        elif grep -qs '^deb .*debian' /etc/apt/sources.list; then
            grep '^deb .*debian' /etc/apt/sources.list | sed 's/^deb /deb-src /'
        else
            echo "gnomon: apt has no Debian sources to derive a deb-src line from" >&2
            exit 1
        fi >/tmp/gnomon-deb-src.$$ || exit 1
        echo "gnomon: adding $list (deb-src lines for apt-get source)"
        as_root cp /tmp/gnomon-deb-src.$$ "$list" || {
            echo "    then: sudo apt-get update && scripts/web-deps.sh" >&2
            rm -f /tmp/gnomon-deb-src.$$
            exit 1
        }
        rm -f /tmp/gnomon-deb-src.$$
        as_root apt-get update -qq
    fi
    mkdir -p "$src"
    rm -rf "$src/unpack"
    mkdir "$src/unpack"
    (cd "$src/unpack" &&
        apt-get source -qq "imgui=$imgui_version" "meshoptimizer=$meshopt_version" >/dev/null)
    rm -rf "$src/imgui" "$src/meshoptimizer"
    mv "$src"/unpack/imgui-*/ "$src/imgui"
    mv "$src"/unpack/meshoptimizer-*/ "$src/meshoptimizer"
    rm -rf "$src/unpack"
fi

# 3. The browser driver, exactly as locked (npm ci); again only when the lock changed.
if [[ ! -f tests/web/node_modules/.package-lock.json ||
    tests/web/package-lock.json -nt tests/web/node_modules/.package-lock.json ]]; then
    (cd tests/web && npm ci --no-audit --no-fund --loglevel=error)
fi
