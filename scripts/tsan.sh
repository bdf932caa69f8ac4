#!/usr/bin/env bash
# Builds libverve and the suites where threads meet (C ABI, hardening stress tests, core, io) with
# ThreadSanitizer (the tsan preset, into build/tsan) and runs them: any data race fails the run.
# The single-threaded learning and scene suites are left out: TSan sees races only between threads.
# CI runs it after sanitize.sh; each suite is bounded by a 10-minute timeout.
set -euo pipefail
cd "$(dirname "$0")/.."

./scripts/setup.sh
cmake --preset tsan -DVERVE_BUILD_SAMPLES=OFF -DVERVE_BUILD_LUA=OFF >/dev/null
suites=(tests/hardening/verve_hardening_tests tests/capi/verve_capi_tests tests/core/verve_core_tests
        tests/io/verve_io_tests)
targets=()
for s in "${suites[@]}"; do targets+=(--target "$(basename "$s")"); done
cmake --build build/tsan -j"$(nproc)" "${targets[@]}"
export TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1"
for s in "${suites[@]}"; do
  echo "== $(basename "$s") under ThreadSanitizer"
  timeout 600 "build/tsan/$s" --gtest_brief=1
done
