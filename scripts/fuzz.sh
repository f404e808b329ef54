#!/usr/bin/env bash
# Fuzzes a loader with libFuzzer under AddressSanitizer and UBSan for a bounded time.
# Usage: scripts/fuzz.sh [TARGET] [SECONDS]
#   TARGET   gltf (default): the glTF loader, from the small broken files in tests/data/gltf;
#            scene-file: the scene file reader, from examples/scenes and the broken files in
#            tests/data/scene-files, with a dictionary of the format's keys (fuzz/scene_file.dict)
#   SECONDS  default 60. A lone number is the seconds for the gltf target.
# Builds with clang into build/fuzz and keeps what it finds in build/fuzz/corpus (gltf) or
# build/fuzz/corpus-scene-file; a crash leaves its input in build/fuzz/ and exits non-zero.
set -euo pipefail
cd "$(dirname "$0")/.."
target=gltf
if [[ $# -gt 0 && ! "$1" =~ ^[0-9]+$ ]]; then target=$1; shift; fi
seconds=${1:-60}
case $target in
gltf) binary=gnomon_gltf_fuzzer; corpus=corpus; extra=() ;;
scene-file) binary=gnomon_scene_file_fuzzer; corpus=corpus-scene-file
    extra=(-dict="$PWD/fuzz/scene_file.dict") ;;
*) echo "scripts/fuzz.sh: unknown target '$target' (gltf, scene-file)" >&2; exit 2 ;;
esac
scripts/deps.sh clang
cmake -S . -B build/fuzz -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_C_COMPILER=clang \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo -DGNOMON_FUZZ=ON >/dev/null
cmake --build build/fuzz --target "$binary" -j "$(nproc)" >/dev/null
mkdir -p "build/fuzz/$corpus"
case $target in
gltf) cp tests/data/gltf/*.gltf tests/data/gltf/*.glb "build/fuzz/$corpus/" ;;
scene-file) cp examples/scenes/*.json tests/data/scene-files/*.json "build/fuzz/$corpus/" ;;
esac
cd build/fuzz
"./fuzz/$binary" -max_total_time="$seconds" -max_len=65536 -timeout=10 \
    -rss_limit_mb=4096 -print_final_stats=1 "${extra[@]}" "$corpus"
