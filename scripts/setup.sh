#!/usr/bin/env bash
# Installs the Debian packages Verve builds and tests with (only the missing ones: fast when all
# are present), and fetches pugixml's source into third_party/ (it is compiled into libverve).
# Needs root or sudo on a fresh machine.
#   ./scripts/setup.sh         what the build and the demo need
#   ./scripts/setup.sh --test  also what every test suite needs (cross toolchain, Wine, engines, Mono,
#                              clang for fuzzing)
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libeigen3-dev libbullet-dev libcli11-dev
  googletest libgtest-dev libbenchmark-dev
  liblua5.4-dev lua5.4 luajit libluajit-5.1-dev
  gnuplot-nox
)
# Only for ./scripts/test.sh: each group names what it is for.
test_packages=(
  dpkg-dev                                     # apt-get source: third-party sources (scripts/fetch_source.sh)
  godot3-server                                # the Godot plugin's engine tests, headless (bindings/godot)
  godot3 xvfb xauth libgl1-mesa-dri            # the editor loading the plugin in a window, on a virtual display (Mesa)
  g++-mingw-w64-x86-64-posix wine64            # verve.dll cross-built for Windows x64, tested under Wine
  love                                         # LÖVE 11: the samples/love game's test (tests/love)
  mono-devel                                   # C# binding under Mono 6.8, Unity's runtime: mcs, mono, netstandard facade
  unzip jq                                     # C#: unpacking the NuGet package, checking the Unity package's JSON
  clang-14 libclang-rt-14-dev                  # libFuzzer targets (scripts/fuzz.sh)
  emscripten nodejs chromium                   # the web build, its Node.js tests and the page in headless Chromium
  debootstrap                                  # the Debian 11 root of the release build (scripts/build_old_glibc.sh)
)

if [ "${1:-}" = "--test" ]; then packages+=("${test_packages[@]}"); fi

missing=()
for p in "${packages[@]}"; do
  dpkg -s "$p" >/dev/null 2>&1 || missing+=("$p")
done
# npm is Debian's own package only where Node.js is Debian's (other builds of nodejs carry it).
if [ "${1:-}" = "--test" ] && ! command -v npm >/dev/null 2>&1; then missing+=(npm); fi

if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  sudo_cmd=()
  [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get -o DPkg::Lock::Timeout=600 update -qq
  "${sudo_cmd[@]}" apt-get -o DPkg::Lock::Timeout=600 install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# pugixml is built from source into libverve (cmake/VervePugixml.cmake), so the shipped library
# does not need libpugixml.so on a player's machine. Skipped when already there.
"$(dirname "$0")/fetch_source.sh" pugixml "$(dirname "$0")/../third_party"

if [ "${1:-}" = "--test" ]; then
  # The Godot plugin builds against Godot 3.2's GDNative headers, shipped by Debian only as source.
  "$(dirname "$0")/fetch_source.sh" godot3 "$(dirname "$0")/../third_party" \
    modules/gdnative/include modules/gdnative/gdnative_api.json
  # The web page's test drives Debian's chromium with playwright-core, and tsc checks index.d.ts
  # (samples/web/package-lock.json).
  web="$(dirname "$0")/../samples/web"
  if [ ! -d "$web/node_modules/playwright-core" ] || [ ! -d "$web/node_modules/typescript" ]; then
    (cd "$web" && npm ci --no-audit --no-fund)
  fi
fi
