#!/usr/bin/env bash
# Walks the commands that README.md and docs/ tell a reader to type, from the repository root, after
# ./scripts/build.sh. Each command below must appear word for word in its document (so a doc that
# changes a command fails here until this list follows it), then runs and must succeed.
# Documented ctest commands are listed (-N) and must select tests: test.sh's gating run, just before
# this, ran every one of them. Not run: ./scripts/test.sh and ./scripts/demo.sh (CI runs test.sh,
# which runs this), full-size experiments and benchmarks (minutes to hours: their programs run with
# `list` or are checked to exist), the cart-pole run to 1800 s, and LÖVE's window (the same game
# runs headless, and under Xvfb when xvfb-run is installed). About 1 minute on 2 cores after a build.
set -euo pipefail
cd "$(dirname "$0")/.."
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
# Side effects stay out of the reader's places: LÖVE's save directory, and out/ (gitignored).
export XDG_DATA_HOME="$scratch/data" XDG_RUNTIME_DIR="$scratch"
had_out=$([ -e out ] && echo yes || echo no)
failures=0

# in_doc FILE COMMAND: fails the check unless FILE contains COMMAND verbatim.
in_doc() {
  grep -qF -- "$2" "$1" && return 0
  echo "check_docs: $1 no longer contains: $2" >&2
  failures=$((failures + 1))
  return 1
}

# doc FILE COMMAND [RUN]: COMMAND is in FILE and succeeds when run from the repository root; RUN,
# if given, is what runs instead: COMMAND with a flag that keeps it short or read-only.
doc() {
  in_doc "$1" "$2" || return 0
  local run=${3:-$2}
  echo "== $1: $run"
  # A bound on every command: a documented command that hangs (an engine waiting on something
  # missing) fails the check instead of stalling CI.
  if ! timeout 900 bash -c "$run" >"$scratch/log" 2>&1; then
    tail -n 30 "$scratch/log"
    echo "check_docs: FAILED ($1): $run" >&2
    failures=$((failures + 1))
  fi
}

in_doc README.md 'cmake --preset release && cmake --build --preset release && ctest --preset release'
doc README.md 'cmake --preset release'
doc README.md 'cmake --build --preset release'
# ctest_doc FILE COMMAND: a documented ctest command selects at least one test (ctest -N).
ctest_doc() { doc "$1" "$2" "$2 -N | grep -q 'Total Tests: [1-9]'"; }

ctest_doc README.md 'ctest --preset release'
ctest_doc README.md 'ctest --preset known-gaps'
ctest_doc README.md 'ctest --test-dir build -L known_gap'

doc docs/teaching.md "build/tests/learning/verve_learning_tests --gtest_filter='DemonstrationLearning.*'"
doc docs/teaching.md "build/tests/learning/verve_learning_tests --gtest_filter='TeacherLearning.*'"
doc docs/lua.md 'cmake -S . -B build -DCMAKE_BUILD_TYPE=Release'
doc docs/lua.md 'cmake --build build -j2'
ctest_doc docs/lua.md "ctest --test-dir build -R '^lua\.'"
ctest_doc docs/lua.md "ctest --test-dir build -R '^love\.'"
doc docs/lua.md 'LUA_CPATH="build/lua/5.4/?.so" lua5.4 samples/lua/train_hot_plate.lua'
doc docs/lua.md 'LUA_CPATH="build/lua/jit/?.so" luajit samples/lua/train_hot_plate.lua --continuous'
# Shipping the LÖVE game, step by step.
doc docs/lua.md './scripts/build.sh verve_lua_5.4 verve_lua_jit'
doc docs/lua.md 'cmake --install build --prefix build/stage'
doc docs/lua.md 'mkdir -p build/love-npcs'
doc docs/lua.md 'cp build/stage/lib/lua/5.1/verve.so build/stage/lib/libverve.so.0 build/love-npcs/'
doc docs/lua.md '(cd samples/love && cmake -E tar cf ../../build/love-npcs/verve-npcs.love --format=zip main.lua conf.lua)'
doc docs/lua.md 'readelf -d build/src/capi/libverve.so.0'
in_doc docs/lua.md 'love build/love-npcs/verve-npcs.love '   # the window; the headless run below
doc docs/lua.md 'love build/love-npcs/verve-npcs.love --headless --minutes 20 --fresh'
doc docs/lua.md 'mkdir -p build/love-pet'
doc docs/lua.md 'cp build/stage/lib/lua/5.1/verve.so build/stage/lib/libverve.so.0 build/love-pet/'
doc docs/lua.md '(cd samples/love_pet && cmake -E tar cf ../../build/love-pet/verve-pet.love --format=zip main.lua conf.lua)'
doc docs/lua.md 'love build/love-pet/verve-pet.love --headless --seed 1 --shown 30'
doc docs/lua.md 'mkdir -p build/love-rays'
doc docs/lua.md 'cp build/stage/lib/lua/5.1/verve.so build/stage/lib/libverve.so.0 build/love-rays/'
doc docs/lua.md '(cd samples/love_rays && cmake -E tar cf ../../build/love-rays/verve-rays.love --format=zip *.lua)'
doc docs/lua.md 'love build/love-rays/verve-rays.love --headless --minutes 20 --seed 1'
doc docs/lua.md 'love build/love-rays/verve-rays.love --headless --minutes 20 --seed 1 --progress 2'
if command -v xvfb-run >/dev/null; then
  doc docs/lua.md 'xvfb-run -a love build/love-npcs/verve-npcs.love --minutes 20 --fresh --screenshot npcs.png'
fi

doc docs/scenes.md './scripts/build.sh verve-demo'
doc docs/scenes.md 'build/samples/runner/verve-demo list'
doc docs/scenes.md 'build/samples/runner/verve-demo run npc-arena --trials 10 --out out'
doc docs/scenes.md 'build/samples/runner/verve-demo run maze2 --runs 10 --out out'
in_doc docs/scenes.md 'build/samples/runner/verve-demo run pendulum --runs 10 --value-at 1,5,20,100 --out out'
in_doc docs/scenes.md 'build/samples/runner/verve-demo run cart-pole --seed 1 --out out'
doc docs/scenes.md 'build/samples/runner/verve-demo compare-brains --seeds 5 --out out' \
  'build/samples/runner/verve-demo compare-brains --seeds 1 --minutes 1 --out out'
doc docs/scenes.md 'build/samples/runner/verve-demo ray-npc --seeds 1-5 --minutes 20 --out out' \
  'build/samples/runner/verve-demo ray-npc --seeds 1 --minutes 1 --out out'
doc docs/scenes.md 'build/samples/runner/verve-demo ray-npc --seeds 1-5 --minutes 20 --progress-reward 2 --out out' \
  'build/samples/runner/verve-demo ray-npc --seeds 1 --minutes 1 --progress-reward 2 --out out'
doc docs/crowds.md 'build/samples/runner/verve-demo compare-brains --seeds 5 --minutes 10 --out out' \
  'build/samples/runner/verve-demo compare-brains --seeds 1 --minutes 1 --out out'

doc docs/performance.md './scripts/build.sh verve_bench'
doc docs/performance.md 'build/bench/verve_bench --benchmark_repetitions=3 --benchmark_report_aggregates_only=true' \
  'build/bench/verve_bench --benchmark_list_tests'
doc docs/performance.md './scripts/bench_crowd.sh' './scripts/bench_crowd.sh --benchmark_filter=tiny/100/'
doc docs/experiments.md 'cmake -S . -B build -DCMAKE_BUILD_TYPE=Release && cmake --build build -j2'
doc docs/experiments.md 'build/samples/tasks/verve-experiments list'
doc docs/experiments.md 'build/bench/verve_bench --benchmark_filter=Sensors' \
  'build/bench/verve_bench --benchmark_filter=Sensors --benchmark_min_time=0.01'
doc docs/experiments.md 'build/samples/tasks/verve-experiments run signaled-hot-plate-1d-14-distractors --runs 20 --trials 301 --defaults' \
  'build/samples/tasks/verve-experiments run signaled-hot-plate-1d-14-distractors --runs 2 --trials 20 --defaults'
ctest_doc docs/experiments.md 'ctest --test-dir build -L learning'
doc docs/experiments.md 'build/samples/tasks/verve-experiments run cue-change --csv cue-after.csv' \
  "build/samples/tasks/verve-experiments run cue-change --csv $scratch/cue-after.csv"
doc docs/experiments.md 'build/samples/tasks/verve-experiments run cue-change --policy-weight-bound 0 --tau-value 0.1 --policy-multiplier 5 --csv cue-before.csv' \
  "build/samples/tasks/verve-experiments run cue-change --policy-weight-bound 0 --tau-value 0.1 --policy-multiplier 5 --csv $scratch/cue-before.csv"
in_doc docs/experiments.md 'gnuplot docs/img/changing-world-cue.gp'   # rewrites the committed PNG: not run
doc docs/experiments.md 'build/samples/tasks/verve-experiments run steering-car --runs 20 --trials 301 --defaults' \
  'build/samples/tasks/verve-experiments run steering-car --runs 2 --trials 20 --defaults'
doc docs/experiments.md 'verve-classic pendulum-v1-continuous' 'build/samples/tasks/verve-classic pendulum-v1-continuous --seeds 1 --budget 2000'
doc docs/experiments.md 'build/samples/tasks/verve-classic acrobot-v1 --seeds 10'
doc docs/experiments.md 'build/samples/tasks/verve-classic cart-pole-v1 --seeds 10 --set tau_value=0.01' \
  'build/samples/tasks/verve-classic cart-pole-v1 --seeds 2 --set tau_value=0.01'
in_doc docs/experiments.md 'DEFAULTS_ONLY=1 CANDIDATE="key=value"'   # a minute or more: run by hand

# C#: the package commands run (dotnet test and the sample are what test.sh's C# step runs next).
doc docs/csharp.md 'cmake -S . -B build -DCMAKE_BUILD_TYPE=Release'
doc docs/csharp.md 'cmake --build build -j2 --target verve'
in_doc docs/csharp.md 'bindings/csharp/test.sh build/src/capi'
in_doc docs/csharp.md 'dotnet test bindings/csharp/Verve.Tests -p:VerveNativeDir=build/src/capi'
in_doc docs/csharp.md 'dotnet run --project bindings/csharp/Verve.Sample -p:VerveNativeDir=build/src/capi -- 150 1'
doc docs/csharp.md 'dotnet pack bindings/csharp/Verve -c Release -p:VerveNativeDir=build/src/capi -o out/nuget'
in_doc docs/csharp.md 'dotnet pack bindings/csharp/Verve -c Release -p:VerveNativeDir=build/src/capi -p:VerveWindowsNativeDir=build/mingw/bin -o out/nuget'
doc docs/csharp.md 'bindings/csharp/unity/make_package.sh out/unity build/src/capi'
doc docs/csharp.md 'dotnet build bindings/csharp/Verve -c Release -p:VerveStaticLink=true -o out/verve-static'

in_doc docs/web.md 'cmake --preset web-release'                  # test_web.sh, just before, ran the build and
in_doc docs/web.md 'cmake --build --preset web-release -j2'      # the suite (with the native comparisons)
in_doc docs/web.md 'node samples/web/serve.mjs'
doc docs/web.md 'node --expose-gc --test bindings/web/test/'
doc docs/web.md 'cd bindings/web && npm pack' '(cd bindings/web && npm pack --dry-run)'
# doc_code FILE SOURCE: FILE quotes SOURCE whole, as the fenced block that starts with SOURCE's first
# line (the doc's NPC scripts are the tests' own: a change to either fails here until both agree).
doc_code() {
  local first
  first=$(head -n 1 "$2")
  awk -v first="$first" '$0 == first { on = 1 } on && /^```/ { exit } on { print }' "$1" | diff -q - "$2" >/dev/null && return 0
  echo "check_docs: $1 does not quote $2 as it is" >&2
  failures=$((failures + 1))
}
doc_code docs/godot.md bindings/godot/tests/line_npc.gd
doc_code docs/godot.md bindings/godot/tests/npc.gd
in_doc docs/godot.md './scripts/setup.sh --test'
ctest_doc docs/godot.md "ctest --test-dir build -R '^godot\.'"
in_doc docs/godot.md 'cp -r build/godot/addons/verve  path/to/your/project/addons/'
doc docs/godot.md 'ls -R build/godot/addons/verve' 'cd build/godot/addons/verve && ls verve.gdnlib verve_agent.gdns verve_brain.gdns verve_batch.gdns bin/x11/libverve_godot.so bin/x11/libverve.so.0'
in_doc docs/godot.md 'godot3 --path build/godot/sample '   # the window; the headless run below
doc docs/godot.md 'godot3-server --path build/godot/sample --fixed-fps 60 --verve-test' \
  'godot3-server --path build/godot/sample --fixed-fps 60 --verve-test --verve-seeds=1'
doc docs/godot.md 'godot3-server --path build/godot/sample --fixed-fps 60 res://rays.tscn --verve-test' \
  'godot3-server --path build/godot/sample --fixed-fps 60 res://rays.tscn --verve-test --verve-seeds=1'
doc docs/godot.md 'godot3-server --path build/godot/sample --fixed-fps 60 res://rays.tscn --verve-test --verve-progress=2' \
  'godot3-server --path build/godot/sample --fixed-fps 60 res://rays.tscn --verve-test --verve-seeds=1 --verve-progress=2'
in_doc docs/godot.md 'godot3 --path build/godot/sample res://rays.tscn'
if command -v xvfb-run >/dev/null && command -v godot3 >/dev/null; then
  doc docs/godot.md 'xvfb-run -a -s "-screen 0 1024x768x24" godot3 --path build/godot/sample --fixed-fps 60 --verve-screenshot="$PWD/docs/img/godot-arena.png"' \
    'xvfb-run -a -s "-screen 0 1024x768x24" godot3 --path build/godot/sample --fixed-fps 60 --verve-screenshot="$XDG_RUNTIME_DIR/godot.png" && test -s "$XDG_RUNTIME_DIR/godot.png"'
fi

ctest_doc docs/tuning.md "ctest --test-dir build -R '^(love\.|NpcArenaLearning|HotPlateLearning|CartPoleLearning|PendulumLearning|PatrolRecipe)'"

# What the shipped library needs; the Windows cross build's commands run in test.sh right after this.
doc docs/platforms.md 'readelf -d build/src/capi/libverve.so | grep NEEDED'
doc docs/platforms.md "objdump -T build/src/capi/libverve.so | grep -o 'GLIBC_[0-9.]*' | sort -uV | tail -1"
in_doc docs/platforms.md 'cmake --preset mingw-release'
in_doc docs/platforms.md 'cmake --build --preset mingw-release'
in_doc docs/platforms.md 'ctest --preset mingw-release'
# The Windows Lua module and the release bundle: test.sh runs both (the bundle last, package.sh as
# root: a Debian 11 root and every part's tests, minutes), so here they are only found in the doc.
in_doc docs/platforms.md './scripts/build_luajit_windows.sh'
in_doc docs/platforms.md 'cmake --preset mingw-release -DVERVE_BUILD_LUA=ON -DVERVE_LUAJIT_DIR=$PWD/build/luajit-windows/src'
in_doc docs/platforms.md "ctest --preset mingw-release -R '^lua\.'"
in_doc docs/platforms.md './scripts/build_old_glibc.sh'
in_doc docs/platforms.md './scripts/package.sh'

[ "$had_out" = yes ] || rm -rf out
if [ "$failures" -gt 0 ]; then
  echo "check_docs: $failures documented command(s) failed or are no longer documented" >&2
  exit 1
fi
echo "check_docs: every walked command works"
