#!/usr/bin/env bash
# Checks that no tracked file names a package host, then sets up, builds and runs every test suite:
# C++ core, learning, tasks, scenes, C ABI, Lua and the LÖVE game (CTest), the web build
# (test_web.sh), the commands the docs give (check_docs.sh), the fuzz targets briefly, the Windows
# build's C ABI suites under Wine, then the C# binding (dotnet test) against libverve.so.
set -euo pipefail
cd "$(dirname "$0")/.."

echo "== no package host named in the repository (scripts/check_no_hosts.sh)"
./scripts/check_no_hosts.sh
./scripts/check_fetch_source_mirror.sh

./scripts/setup.sh --test
./scripts/build.sh

# Learning bars we do not meet yet (thresholds unchanged; docs/experiments.md): run and reported
# in every run so a regression or a fix is seen, but not gating.
echo "== known gaps (reported, not gating)"
ctest --preset known-gaps -j"$(nproc)" || echo "known gaps: some bars are still missed (see above)"

# The README's `ctest --preset release`: the release preset's tree is build/, labelled known gaps left out.
echo "== C++, C ABI, Lua and LÖVE suites (ctest)"
ctest --preset release -j"$(nproc)"

echo "== the web build: JS API (Node.js) and the cart-pole page (headless Chromium) (scripts/test_web.sh)"
./scripts/test_web.sh

echo "== the commands README.md and docs/ give (scripts/check_docs.sh, about 1 minute)"
./scripts/check_docs.sh

echo "== fuzz targets, 30 s each (docs/fuzzing.md; ./scripts/fuzz_campaign.sh for a real campaign)"
./scripts/fuzz.sh 30

echo "== Windows x64: verve.dll cross-built with MinGW-w64, the C ABI suites run under Wine"
# About 2-3 min on 2 cores from scratch (the first Wine run creates build/mingw/wine-prefix: ~25 s).
windows_start=$SECONDS
cmake --preset mingw-release >/dev/null
cmake --build --preset mingw-release -j"$(nproc)"
ctest --preset mingw-release -j"$(nproc)"
echo "Windows build and Wine run: $((SECONDS - windows_start)) s"

echo "== C# binding: xunit, sample, NuGet package, Mono 6.8 (Unity's runtime), Unity package"
if ! command -v dotnet >/dev/null 2>&1; then
  echo "test.sh: the .NET SDK (dotnet) is not installed; the C# suite cannot run." >&2
  echo "Install the .NET SDK (https://learn.microsoft.com/dotnet/core/install/linux-debian) and rerun." >&2
  exit 1
fi
bindings/csharp/test.sh "$PWD/build/src/capi" "$PWD/build/mingw/bin"  # both runtimes in the packages
