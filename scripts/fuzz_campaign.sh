#!/usr/bin/env bash
# A long, unattended fuzzing campaign on spare cores: every libFuzzer target (the fuzz preset,
# build/fuzz) for SECONDS each, JOBS targets at a time at the lowest priority, each from a corpus
# that persists between campaigns (build/fuzz/campaign/corpus/<target>/, seeded from
# tests/fuzz/corpus/). Unlike scripts/fuzz.sh (CI's short runs, which stop at the first failure),
# a finding does not end a target's run: the input is kept and the fuzzer restarts on the grown
# corpus until its time is up (at most 20 findings per target). At the end it prints, and writes
# to build/fuzz/campaign/<start time>/summary.md, the executions and findings of every target;
# docs/fuzzing.md records the campaigns run so far.
#   ./scripts/fuzz_campaign.sh [SECONDS-PER-TARGET] [JOBS] [TARGET-REGEX]
#   ./scripts/fuzz_campaign.sh 28800 2        # 8 hours per target, two at a time: overnight
#   nohup ./scripts/fuzz_campaign.sh 14400 1 crowd >/dev/null 2>&1 &   # in the background
# Replay a finding: build/fuzz/tests/fuzz/<target> build/fuzz/campaign/<time>/<target>/<file>
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-3600}
jobs=${2:-1}
filter=${3:-.}
targets=(fuzz_load_memory fuzz_load_file fuzz_calls fuzz_crowd fuzz_lua fuzz_load_recording)
seeds=(saves saves calls "" "" recordings)

./scripts/setup.sh --test
cmake --preset fuzz >/dev/null
cmake --build build/fuzz -j"$(nproc)" --target verve_fuzz
run=build/fuzz/campaign/$(date -u +%Y%m%dT%H%M%SZ)
mkdir -p "$run"

# One target for its whole time: restarts after each finding, sums the executions of every run.
fuzz_target() {
  local target=$1 seedDir=$2 out=$run/$1
  local corpus=build/fuzz/campaign/corpus/$target
  mkdir -p "$out" "$corpus"
  if [ -n "$seedDir" ] && [ -d "tests/fuzz/corpus/$seedDir" ]; then cp -n "tests/fuzz/corpus/$seedDir"/* "$corpus"/ 2>/dev/null || true; fi
  local start=$SECONDS executions=0 runs=0 left
  while :; do
    left=$((seconds - (SECONDS - start)))
    [ "$left" -ge 5 ] || break
    runs=$((runs + 1))
    # -timeout=5: at the lowest priority beside other work a 1 s limit (CI's) reports a busy
    # machine as a hang; -rss_limit_mb as CI's. The seed differs per run, so a restart explores.
    nice -n 19 "build/fuzz/tests/fuzz/$target" -max_total_time="$left" -seed="$((RANDOM * 32768 + RANDOM + 1))" \
      -timeout=5 -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$out/" "$corpus" \
      >"$out/run-$runs.log" 2>&1 || true
    local n
    n=$(grep -Eo 'stat::number_of_executed_units: +[0-9]+' "$out/run-$runs.log" | grep -Eo '[0-9]+$' || true)
    executions=$((executions + ${n:-0}))
    grep -q 'Done [0-9]* runs in' "$out/run-$runs.log" && break  # its time is up, nothing found
    # A finding (or a fuzzer that could not run): keep going on the grown corpus, up to 20.
    [ "$(find "$out" -maxdepth 1 -type f \( -name 'crash-*' -o -name 'timeout-*' -o -name 'oom-*' -o -name 'leak-*' \) | wc -l)" -lt 20 ] || break
    [ "$runs" -lt 100 ] || break  # a fuzzer that fails at once, over and over
  done
  local crashes timeouts ooms leaks elapsed
  crashes=$(find "$out" -maxdepth 1 -name 'crash-*' | wc -l)
  timeouts=$(find "$out" -maxdepth 1 -name 'timeout-*' | wc -l)
  ooms=$(find "$out" -maxdepth 1 -name 'oom-*' | wc -l)
  leaks=$(find "$out" -maxdepth 1 -name 'leak-*' | wc -l)
  elapsed=$((SECONDS - start))
  printf '| %s | %d | %d | %d | %d | %d | %d | %d | %d |\n' "$target" "$elapsed" "$executions" \
    "$((executions / (elapsed > 0 ? elapsed : 1)))" "$(find "$corpus" -type f | wc -l)" "$crashes" "$timeouts" "$ooms" "$leaks" \
    >"$out/row.md"
}

echo "== fuzzing campaign: ${seconds} s per target, ${jobs} at a time, results in $run"
running=0
for i in "${!targets[@]}"; do
  [[ ${targets[$i]} =~ $filter ]] || continue
  fuzz_target "${targets[$i]}" "${seeds[$i]}" &
  running=$((running + 1))
  if [ "$running" -ge "$jobs" ]; then wait -n || true; running=$((running - 1)); fi
done
wait

{
  echo "Fuzzing campaign $(basename "$run"): ${seconds} s per target, ${jobs} at a time, $(nproc) cores, $(git rev-parse --short HEAD)"
  echo
  echo "| target | seconds | executions | exec/s | corpus | crashes | timeouts | ooms | leaks |"
  echo "|---|---|---|---|---|---|---|---|---|"
  cat "$run"/*/row.md
} >"$run/summary.md"
cat "$run/summary.md"
found=$(find "$run" -mindepth 2 -maxdepth 2 -type f \( -name 'crash-*' -o -name 'timeout-*' -o -name 'oom-*' -o -name 'leak-*' \) | wc -l)
if [ "$found" -gt 0 ]; then
  echo "fuzz_campaign.sh: $found findings kept in $run/<target>/ (replay: build/fuzz/tests/fuzz/<target> <file>)" >&2
  exit 1
fi
