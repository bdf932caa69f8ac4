#!/usr/bin/env bash
# Configures and builds Verve (Release) into build/: everything, or only the targets named.
# Options are explicit so that the demo's and the tests' runs share one build tree.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DVERVE_BUILD_TESTS=ON -DVERVE_BUILD_BENCH=ON \
  -DVERVE_BUILD_SAMPLES=ON -DVERVE_BUILD_LUA=ON >/dev/null
targets=()
for t in "$@"; do targets+=(--target "$t"); done
cmake --build build -j"$(nproc)" "${targets[@]}"
