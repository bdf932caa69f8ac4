#!/usr/bin/env bash
# Cross-builds LuaJIT for Windows x64 with MinGW-w64 from Debian's luajit source package, for the
# Windows Lua module and its tests under Wine (bindings/lua/windows_luajit.cmake).
#   ./scripts/build_luajit_windows.sh   -> build/luajit-windows/src: luajit.exe, lua51.dll, headers
# About 1 minute on 2 cores; skipped when already built. Needs g++-mingw-w64-x86-64-posix and
# dpkg-dev (./scripts/setup.sh --test).
set -euo pipefail
cd "$(dirname "$0")/.."
out=build/luajit-windows
if [ -f "$out/src/luajit.exe" ] && [ -f "$out/src/lua51.dll" ]; then echo "$PWD/$out/src"; exit 0; fi
./scripts/fetch_source.sh luajit third_party
rm -rf "$out"; mkdir -p "$out"
cp -a third_party/luajit/. "$out/"  # LuaJIT builds in its tree: keep third_party/ as fetched
# HOST_CC builds the tools that generate the VM for the target (both 64-bit here); lua51.dll and
# luajit.exe import only KERNEL32 and msvcrt (LuaJIT links libgcc statically for MinGW).
if ! make -C "$out" -j"$(nproc)" HOST_CC=gcc CROSS=x86_64-w64-mingw32- TARGET_SYS=Windows \
    BUILDMODE=dynamic > "$out/build.log" 2>&1; then
  tail -n 20 "$out/build.log" >&2
  echo "build_luajit_windows.sh: the LuaJIT cross build failed (log: $out/build.log)" >&2
  exit 1
fi
echo "$PWD/$out/src"
