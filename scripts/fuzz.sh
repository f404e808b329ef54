#!/usr/bin/env bash
# Fuzzes the glTF loader with libFuzzer under AddressSanitizer and UBSan for a bounded time.
# Usage: scripts/fuzz.sh [SECONDS]  (default 60). Builds with clang into build/fuzz, starts
# from the committed corpus of small broken files (tests/data/gltf) and keeps what it finds
# in build/fuzz/corpus; a crash leaves its input in build/fuzz/ and exits non-zero.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
scripts/deps.sh clang
cmake -S . -B build/fuzz -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_C_COMPILER=clang \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo -DGNOMON_FUZZ=ON >/dev/null
cmake --build build/fuzz --target gnomon_gltf_fuzzer -j "$(nproc)" >/dev/null
mkdir -p build/fuzz/corpus
cp tests/data/gltf/*.gltf tests/data/gltf/*.glb build/fuzz/corpus/
cd build/fuzz
./fuzz/gnomon_gltf_fuzzer -max_total_time="$seconds" -max_len=65536 -timeout=10 \
    -rss_limit_mb=4096 -print_final_stats=1 corpus
