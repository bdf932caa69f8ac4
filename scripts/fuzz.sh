#!/usr/bin/env bash
# Builds the libFuzzer targets (the fuzz preset: clang, ASan + UBSan, into build/fuzz) and fuzzes
# each one for SECONDS (default 30, as CI runs them; give 3600 or more for a real campaign).
#   ./scripts/fuzz.sh [SECONDS] [TARGET-REGEX]
# Each run starts from a scratch copy of tests/fuzz/corpus/<target>/ and stops at the first crash,
# sanitizer report, leak, > 2 GB of memory or input slower than 1 s; the reproducer is kept in
# build/fuzz/tests/fuzz/work/<target>/ (replay: build/fuzz/tests/fuzz/<target> <file>).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-30}
filter=${2:-.}

./scripts/setup.sh --test
cmake --preset fuzz >/dev/null
cmake --build build/fuzz -j"$(nproc)" --target verve_fuzz
echo "== fuzzing each target for ${seconds} s"
log=build/fuzz/fuzz-run.log
status=0
VERVE_FUZZ_SECONDS=$seconds ctest --test-dir build/fuzz -L fuzz -R "$filter" --no-tests=error -V --timeout $((seconds + 600)) >"$log" 2>&1 \
  || status=$?
# libFuzzer's closing line (executions, coverage) and statistics per target, then ctest's verdict.
grep -E '^[0-9]+: (#[0-9]+|  stat::)|Test +#[0-9]+:|tests passed' "$log" || true
if [ "$status" -ne 0 ]; then
  echo "fuzz.sh: a target failed; full output in $log" >&2
  grep -E -A40 'FATAL_ERROR|ERROR: (libFuzzer|AddressSanitizer|LeakSanitizer)|runtime error' "$log" | head -80 >&2 || true
fi
exit "$status"
