#!/usr/bin/env bash
# Sets up, builds and runs every test suite: C++ core, learning, tasks, scenes, C ABI and Lua
# (CTest), the Windows build's C ABI suites under Wine, then the C# binding (dotnet test) against
# the freshly built libverve.so.
set -euo pipefail
cd "$(dirname "$0")/.."

./scripts/setup.sh --test
./scripts/build.sh

# Learning bars we do not meet yet (thresholds unchanged; docs/experiments.md): run and reported
# in every run so a regression or a fix is seen, but not gating.
echo "== known gaps (reported, not gating)"
ctest --test-dir build -R '^KnownGap' -j"$(nproc)" || echo "known gaps: some bars are still missed (see above)"

echo "== C++, C ABI and Lua suites (ctest)"
ctest --test-dir build --output-on-failure -j"$(nproc)" -E '^KnownGap'

echo "== fuzz targets, 30 s each (docs/fuzzing.md; ./scripts/fuzz.sh 3600 for a real campaign)"
./scripts/fuzz.sh 30

echo "== Windows x64: verve.dll cross-built with MinGW-w64, the C ABI suites run under Wine"
# About 2-3 min on 2 cores from scratch (the first Wine run creates build/mingw/wine-prefix: ~25 s).
windows_start=$SECONDS
cmake --preset mingw-release >/dev/null
cmake --build build/mingw -j"$(nproc)"
ctest --test-dir build/mingw --output-on-failure -j"$(nproc)"
echo "Windows build and Wine run: $((SECONDS - windows_start)) s"

echo "== C# binding (dotnet test)"
if ! command -v dotnet >/dev/null 2>&1; then
  echo "test.sh: the .NET SDK (dotnet) is not installed; the C# suite cannot run." >&2
  echo "Install the .NET SDK (https://learn.microsoft.com/dotnet/core/install/linux-debian) and rerun." >&2
  exit 1
fi
bindings/csharp/test.sh "$PWD/build/src/capi"
