#!/usr/bin/env bash
# Builds Verve with AddressSanitizer and UndefinedBehaviorSanitizer (the asan-ubsan preset, into
# build/asan-ubsan) and runs the C++, C ABI and Lua suites there: any memory error or undefined
# behaviour fails the run. CI runs it after ./scripts/test.sh.
set -euo pipefail
cd "$(dirname "$0")/.."

./scripts/setup.sh
cmake --preset asan-ubsan >/dev/null
cmake --build build/asan-ubsan -j"$(nproc)"
echo "== C++, C ABI and Lua suites under ASan + UBSan (ctest)"
ctest --test-dir build/asan-ubsan --output-on-failure -j"$(nproc)" -LE known_gap --timeout 1200
