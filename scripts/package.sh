#!/usr/bin/env bash
# Lays out the release bundle, dist/verve-<version>/ (version: project() in CMakeLists.txt), what a
# studio drops into a project, each part tested where it will run:
#   c-sdk/linux-x86_64     built in a Debian 11 root (glibc 2.31 floor): build_old_glibc.sh runs the C
#                          sample, the CMake package and the Lua suite inside that root
#   c-sdk/windows-x86_64   the mingw-release preset; its suites, and a consumer of this folder, under Wine
#   lua/, love/            the LuaJIT/5.4 modules (Linux) and the LuaJIT module (Windows, suite under
#                          Wine with luajit.exe); the LÖVE game's folders, the Linux one played by LÖVE
#   godot/addons/verve     the GDNative addon (Linux and Windows) with its editor plugin and
#                          VerveAgentNode node, run by godot3-server from this folder (the Windows
#                          plugin: loaded under Wine as Godot loads it; no Godot for Windows here)
#   godot/sample           the sample game with that addon inside: opens and learns as it is
#   csharp/                the NuGet and Unity packages, checked by bindings/csharp/test.sh
# plus README.md (what is where) and SHA256SUMS. About 7 minutes on 2 cores from a fresh clone (2 of
# them making the Debian 11 root, kept for reruns), about 2 minutes when rerun. Needs root
# (debootstrap, chroot) and what ./scripts/setup.sh --test installs (it runs that first).
#   ./scripts/package.sh
set -euo pipefail
cd "$(dirname "$0")/.."
top=$PWD
version=$(sed -n 's/^project(verve VERSION \([0-9.]*\).*/\1/p' CMakeLists.txt)
[ -n "$version" ] || { echo "package.sh: no version in CMakeLists.txt's project()" >&2; exit 1; }
dist=$top/dist/verve-$version
work=$top/build/package
wine=$(command -v wine64 || command -v wine || echo /usr/lib/wine/wine64)
export WINEPREFIX=$top/build/mingw/wine-prefix WINEDEBUG=-all WINEDLLOVERRIDES=mscoree,mshtml=
step() { echo "== package.sh ($((SECONDS / 60))m$((SECONDS % 60))s): $*"; }

if [ "$(id -u)" -ne 0 ]; then echo "package.sh: needs root (the Debian 11 root: debootstrap, chroot)" >&2; exit 1; fi
./scripts/setup.sh --test
rm -rf "$dist" "$work"
mkdir -p "$dist" "$work"

step "Linux: the Debian 11 build (scripts/build_old_glibc.sh)"
./scripts/build_old_glibc.sh
linux=$top/build/bullseye/install
mkdir -p "$dist/c-sdk/linux-x86_64"
cp -a "$linux/include" "$dist/c-sdk/linux-x86_64/"
mkdir -p "$dist/c-sdk/linux-x86_64/lib"
(cd "$linux/lib" && cp -a libverve.so* *.a cmake pkgconfig "$dist/c-sdk/linux-x86_64/lib/")
# The C sample against the bundle itself, moved away from where it was installed (verve.pc and the
# CMake package are relocatable), on this machine.
cc -std=c99 -O2 samples/c/hello_verve.c $(PKG_CONFIG_PATH=$dist/c-sdk/linux-x86_64/lib/pkgconfig pkg-config --cflags --libs verve) \
  -Wl,-rpath,"$dist/c-sdk/linux-x86_64/lib" -o "$work/hello_verve"
(cd "$work" && ./hello_verve | grep -E 'trial 60: +[0-9]+ steps')

step "Windows: verve.dll and the LuaJIT module (mingw-release preset), their suites under Wine"
luajit_dir=$(./scripts/build_luajit_windows.sh)
cmake --preset mingw-release -DVERVE_BUILD_LUA=ON -DVERVE_LUAJIT_DIR="$luajit_dir" >/dev/null
cmake --build --preset mingw-release -j"$(nproc)"
ctest --preset mingw-release -j"$(nproc)"
cmake --install build/mingw --prefix "$work/windows" >/dev/null
windows=$work/windows
mkdir -p "$dist/c-sdk/windows-x86_64/lib"
cp -a "$windows/include" "$windows/bin" "$dist/c-sdk/windows-x86_64/"
(cd "$windows/lib" && cp -a *.a cmake pkgconfig "$dist/c-sdk/windows-x86_64/lib/")
# A consumer of the bundle's Windows folder (find_package(verve), C and C++), run under Wine. verve_DIR:
# the toolchain confines CMAKE_PREFIX_PATH to the MinGW root.
cmake -S tests/capi/consumer -B "$work/consumer-windows" --toolchain "$top/cmake/mingw-w64-x86_64.cmake" \
  -DCMAKE_BUILD_TYPE=Release -Dverve_DIR="$dist/c-sdk/windows-x86_64/lib/cmake/verve" >/dev/null
cmake --build "$work/consumer-windows" >/dev/null
cp "$dist/c-sdk/windows-x86_64/bin/verve.dll" "$work/consumer-windows/"
(cd "$work/consumer-windows" && "$wine" consumer_c.exe && "$wine" consumer_cpp.exe) | tr -d '\r'

step "Lua and LÖVE"
for flavour in 5.1:luajit 5.4:lua5.4; do
  d=$dist/lua/linux-x86_64/${flavour#*:}
  mkdir -p "$d"
  # The module finds libverve.so.0 beside itself (RPATH $ORIGIN); cp -L: the library, not a link.
  cp "$linux/lib/lua/${flavour%%:*}/verve.so" "$d/"
  cp -L "$linux/lib/libverve.so.0" "$d/"
done
mkdir -p "$dist/lua/windows-x86_64/luajit"
cp "$windows/lib/lua/5.1/verve.dll" "$dist/lua/windows-x86_64/luajit/"  # carries the library inside
for os in linux windows; do
  mkdir -p "$dist/love/$os-x86_64"
  (cd samples/love && cmake -E tar cf "$dist/love/$os-x86_64/verve-npcs.love" --format=zip main.lua conf.lua)
done
cp "$dist/lua/linux-x86_64/luajit/verve.so" "$dist/lua/linux-x86_64/luajit/libverve.so.0" "$dist/love/linux-x86_64/"
cp "$dist/lua/windows-x86_64/luajit/verve.dll" "$dist/love/windows-x86_64/"
# The Linux game as shipped, played headless by LÖVE (tests/love/check_npcs.lua: learning bars, then a
# restart from the saves; about 15 s).
mkdir -p "$work/love-save"
luajit tests/love/check_npcs.lua "$(command -v love)" "$dist/love/linux-x86_64/verve-npcs.love" "$work/love-save"

step "Godot addon (Linux): libverve_godot.so built here, with the Debian 11 libverve.so.0"
./scripts/build.sh verve_godot verve_godot_projects >/dev/null
mkdir -p "$dist/godot/addons"
cp -a build/godot/addons/verve "$dist/godot/addons/"
cp -L "$linux/lib/libverve.so.0" "$dist/godot/addons/verve/bin/x11/libverve.so.0"
# Windows: the mingw-release build's plugin and verve.dll (the .gdnlib names both platforms). No
# Godot for Windows here: the bundle's copy is loaded as Godot loads it, under Wine.
cp -a build/mingw/godot/addons/verve/bin/win64 "$dist/godot/addons/verve/bin/"
"$wine" build/mingw/bindings/godot/load_check/verve_godot_windows_load.exe \
  "$dist/godot/addons/verve/bin/win64/libverve_godot.dll" | tr -d '\r'
# The binding's checks in the engine, headless, with the bundle's addon in the test project.
rm -rf "$work/godot-tests"
cp -a build/godot/tests "$work/godot-tests"
rm -rf "$work/godot-tests/addons/verve"
cp -a "$dist/godot/addons/verve" "$work/godot-tests/addons/"
cp "$dist/godot/addons/verve/bin/x11/libverve_godot.so" "$work/godot-tests/addons/verve/bin/x11/libverve_godot_other.so"
# test_node.gd: the VerveAgentNode node and its overlay, and the doc's NPC learning. -e --quit: the
# editor loads the addon's plugin (the test project enables it); any ERROR there fails. Godot keeps
# its settings under HOME: a private one, so an unset or read-only home fails nothing (as in CTest).
godot_run() {  # <project> <pattern that fails the run> <godot3-server arguments...>
  local project=$1 fail=$2 home=$work/godot-home; shift 2
  mkdir -p "$home"
  if ! LANG=en HOME=$home XDG_CONFIG_HOME=$home/.config XDG_DATA_HOME=$home/.local/share XDG_CACHE_HOME=$home/.cache \
      timeout 300 godot3-server --path "$project" "$@" > "$work/godot.log" 2>&1 \
      || grep -qE "$fail" "$work/godot.log"; then
    cat "$work/godot.log" >&2; echo "package.sh: the Godot addon failed in godot3-server ($*)" >&2; exit 1
  fi
  tail -n 1 "$work/godot.log"
}
godot_run "$work/godot-tests" "SCRIPT ERROR|Parse Error" --fixed-fps 60 --script res://test_agent.gd
godot_run "$work/godot-tests" "SCRIPT ERROR|Parse Error" --fixed-fps 60 --script res://test_node.gd
godot_run "$work/godot-tests" "ERROR|Unable to load addon" -e --quit
# The sample game with the bundle's addon, learning where it will be opened (about 6 s).
rm -rf "$dist/godot/sample"
cp -a samples/godot "$dist/godot/sample"
cp -a "$dist/godot/addons" "$dist/godot/sample/"
godot_run "$dist/godot/sample" "SCRIPT ERROR|Parse Error" --fixed-fps 60 --verve-test

step "C#: NuGet and Unity packages with the bundle's libraries (bindings/csharp/test.sh)"
mkdir -p "$work/csharp-linux"
cp -L "$linux/lib/libverve.so" "$work/csharp-linux/libverve.so"
bindings/csharp/test.sh "$work/csharp-linux" "$dist/c-sdk/windows-x86_64/bin"
mkdir -p "$dist/csharp"
cp bindings/csharp/bin/package/Verve.*.nupkg "$dist/csharp/"
bindings/csharp/unity/make_package.sh "$work/unity" "$work/csharp-linux" "$dist/c-sdk/windows-x86_64/bin" >/dev/null
cp "$work"/unity/com.verve.agent-*.tgz "$dist/csharp/"

step "glibc floor of every Linux binary in the bundle"
find "$dist" -type f -name '*.so*' -print0 | sort -z | xargs -0 -n 1 ./scripts/check_glibc_floor.sh

cp LICENSE THIRD_PARTY_NOTICES.md "$dist/"
sed "s/@VERSION@/$version/g" scripts/package_readme.md > "$dist/README.md"
(cd "$dist" && find . -type f ! -name SHA256SUMS | sort | sed 's#^\./##' | xargs sha256sum > SHA256SUMS)
step "done: $dist ($(du -sh "$dist" | cut -f1), $(wc -l < "$dist/SHA256SUMS") files)"
