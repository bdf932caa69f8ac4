#!/usr/bin/env bash
# Checks that no tracked file names a package host, then sets up, builds and runs every test suite:
# C++ core, learning, tasks, scenes, C ABI, Lua and the LÖVE game (CTest), the web build
# (test_web.sh), the commands the docs give (check_docs.sh), the fuzz targets briefly, the Windows
# build's C ABI and Lua suites under Wine, then the C# binding (dotnet test) against libverve.so,
# and last the release bundle (./scripts/package.sh: the Linux library built in a Debian 11 root,
# every part tested where it will run). The bundle needs root (debootstrap, chroot); VERVE_NO_BUNDLE=1
# leaves it out, saying so.
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
# A failure's output is printed again last, where a log's tail shows it.
if ! ctest --preset release -j"$(nproc)"; then
  echo "== the failed tests again, alone"
  ctest --preset release --rerun-failed || true
  exit 1
fi

# The shipped Linux library is built in Debian 11 (./scripts/build_old_glibc.sh, on demand: a few
# minutes) to load on glibc 2.31; this machine's build needs its own, newer glibc. Cheap checks here:
# the floor check refuses a library above 2.31 (this build, when this machine's glibc is newer), and
# passes the Debian 11 build when one is there.
echo "== glibc floor 2.31 (scripts/check_glibc_floor.sh)"
host_glibc=$(getconf GNU_LIBC_VERSION | awk '{print $2}')
if [ "$(printf '%s\n2.31\n' "$host_glibc" | sort -V | tail -n 1)" != 2.31 ]; then
  if refusal=$(./scripts/check_glibc_floor.sh build/src/capi/libverve.so 2>&1); then
    echo "test.sh: check_glibc_floor.sh passed a library built on glibc $host_glibc" >&2; exit 1
  fi
  echo "refused as it should be: $refusal"
fi
if [ -f build/bullseye/install/lib/libverve.so.0 ]; then
  ./scripts/check_glibc_floor.sh build/bullseye/install/lib/libverve.so.0
fi

echo "== the web build: JS API (Node.js) and the cart-pole page (headless Chromium) (scripts/test_web.sh)"
./scripts/test_web.sh

echo "== the commands README.md and docs/ give (scripts/check_docs.sh, about 1 minute)"
./scripts/check_docs.sh

echo "== fuzz targets, 30 s each (docs/fuzzing.md; ./scripts/fuzz_campaign.sh for a real campaign)"
./scripts/fuzz.sh 30

echo "== Windows x64: verve.dll, the LuaJIT module and the Godot plugin cross-built with MinGW-w64, the C ABI and Lua suites and the plugin's load check under Wine"
# About 3-4 min on 2 cores from scratch: LuaJIT's cross build ~50 s (once), the first Wine run
# creates build/mingw/wine-prefix (~25 s), the Lua suite under luajit.exe ~15 s.
windows_start=$SECONDS
luajit_windows=$(./scripts/build_luajit_windows.sh)
cmake --preset mingw-release -DVERVE_BUILD_LUA=ON -DVERVE_LUAJIT_DIR="$luajit_windows" >/dev/null
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

echo "== the release bundle: dist/verve-<version>/, each part tested where it will run (scripts/package.sh)"
if [ "${VERVE_NO_BUNDLE:-0}" = 1 ]; then
  echo "test.sh: VERVE_NO_BUNDLE=1: the release bundle was NOT built or tested (./scripts/package.sh, as root)"
elif [ "$(id -u)" -ne 0 ]; then
  echo "test.sh: the release bundle needs root (a Debian 11 root: debootstrap, chroot); run test.sh as root," >&2
  echo "or VERVE_NO_BUNDLE=1 ./scripts/test.sh to leave it out" >&2
  exit 1
else
  ./scripts/package.sh
fi
