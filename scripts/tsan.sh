#!/usr/bin/env bash
# Builds libverve and the suites where threads meet (hardening stress tests and hooks, C ABI, core,
# io) with ThreadSanitizer (the tsan preset, into build/tsan) and runs them: any data race fails the
# run. Left out: the single-threaded learning and scene suites, the single-threaded allocation-failure
# sweeps (AllocationFailure.*; the batch sweep, whose workers meet, runs) and the kill-mid-save tests
# (no threads meet there; ASan runs them). Measured on 2 shared cores: ~6 min to
# build from scratch, ~20 s to run. CI runs it after sanitize.sh; each suite has a 10-minute timeout.
set -euo pipefail
cd "$(dirname "$0")/.."

./scripts/setup.sh
cmake --preset tsan -DVERVE_BUILD_SAMPLES=OFF -DVERVE_BUILD_LUA=OFF >/dev/null
# suite path and the gtest filter it runs with
suites=(
  "tests/hardening/verve_hardening_tests:*"
  "tests/hardening/verve_memory_tests:-AllocationFailure.*"
  "tests/capi/verve_capi_tests:*"
  "tests/capi/verve_crowd_tests:*"        # the batch on its own pool and a host scheduler, shared brains
  "tests/core/verve_core_tests:*"
  "tests/io/verve_io_tests:-*Kill*"
)
targets=()
for s in "${suites[@]}"; do targets+=(--target "$(basename "${s%%:*}")"); done
cmake --build build/tsan -j"$(nproc)" "${targets[@]}"
export TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1"
for s in "${suites[@]}"; do
  echo "== $(basename "${s%%:*}") under ThreadSanitizer"
  timeout 600 "build/tsan/${s%%:*}" --gtest_brief=1 "--gtest_filter=${s#*:}"
done
