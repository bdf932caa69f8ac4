#!/usr/bin/env bash
# Builds the Linux release binaries in a Debian 11 (bullseye, glibc 2.31) root, so they load on
# glibc 2.31 or newer: Debian 11, Ubuntu 20.04, the Steam Linux Runtime 3 ("sniper"). The same
# sources built on a newer machine need that machine's glibc (docs/platforms.md).
#   ./scripts/build_old_glibc.sh [OUT]   -> OUT (default build/bullseye/install): an install tree with
#                                           libverve.so, headers, CMake package, verve.pc and the Lua
#                                           modules (LuaJIT, 5.4)
# Then, inside the root: the C sample is built against the installed tree (pkg-config) and run, the
# CMake package is consumed (tests/capi/consumer), the Lua suite runs under its luajit and lua5.4, and
# scripts/check_glibc_floor.sh checks every binary. The root is made once with debootstrap from the
# machine's own Debian mirror and kept in build/bullseye/root (about 700 MB); delete it to start over.
# Needs root (debootstrap, chroot) and the debootstrap package.
set -euo pipefail
cd "$(dirname "$0")/.."
top=$PWD
out=$(mkdir -p "${1:-build/bullseye/install}" && cd "${1:-build/bullseye/install}" && pwd)
base=$top/build/bullseye
root=$base/root
suite=bullseye
packages=build-essential,cmake,pkg-config,libeigen3-dev,luajit,libluajit-5.1-dev,lua5.4,liblua5.4-dev

if [ "$(id -u)" -ne 0 ]; then echo "build_old_glibc.sh: needs root (debootstrap and chroot)" >&2; exit 1; fi
command -v debootstrap >/dev/null || { echo "build_old_glibc.sh: debootstrap missing (apt-get install debootstrap)" >&2; exit 1; }
./scripts/fetch_source.sh pugixml third_party  # compiled into libverve; skipped when already there

if [ ! -f "$root/.verve-root-ready" ]; then
  . scripts/lib/debian_mirror.sh
  mirror=$(debian_mirror)
  if [ -z "$mirror" ]; then
    echo "build_old_glibc.sh: no Debian mirror in this machine's apt sources (a \"deb\" entry in" >&2
    echo "/etc/apt/sources.list.d/*.sources or /etc/apt/sources.list); add one and rerun." >&2
    exit 1
  fi
  IFS='|' read -r uri _ _ _ <<<"$mirror"
  # The archive keyring holds the keys of every supported release, bullseye's included.
  keyring=/usr/share/keyrings/debian-archive-keyring.gpg
  echo "== making the $suite root in $root (once; a few minutes)"
  # --one-file-system: an interrupted debootstrap may leave /proc or /sys mounted inside.
  rm -rf --one-file-system "$root"
  mkdir -p "$base"
  debootstrap --variant=minbase --keyring="$keyring" --include="$packages" "$suite" "$root" "$uri" \
    > "$base/debootstrap.log" 2>&1 || { tail -n 20 "$base/debootstrap.log" >&2; echo "build_old_glibc.sh: debootstrap failed (log: $base/debootstrap.log)" >&2; exit 1; }
  touch "$root/.verve-root-ready"
fi
in_root() { chroot "$root" /usr/bin/env -i PATH=/usr/bin:/bin HOME=/root LC_ALL=C.UTF-8 /bin/bash -euo pipefail -c "$1"; }
echo "== in the $suite root: $(in_root 'ldd --version | head -n 1'), $(in_root 'gcc --version | head -n 1'), $(in_root 'cmake --version | head -n 1')"

# The sources are copied in (not bind-mounted: nothing to unmount if a step fails).
rm -rf "$root/verve"
mkdir -p "$root/verve/src"
tar -C "$top" --exclude=./build --exclude=./.git --exclude=node_modules -cf - . | tar -C "$root/verve/src" -xf -

# Release binaries only: the suites run on the build machine (they need GoogleTest, Bullet...). The
# Godot plugin is not built here: its API header generator needs CMake 3.19 (bullseye has 3.18).
in_root "cmake -S /verve/src -B /verve/build -DCMAKE_BUILD_TYPE=Release -DVERVE_BUILD_TESTS=OFF \
  -DVERVE_BUILD_BENCH=OFF -DVERVE_BUILD_SAMPLES=OFF -DVERVE_BUILD_LUA=ON -DVERVE_BUILD_GODOT=OFF >/dev/null
  cmake --build /verve/build -j$(nproc)
  cmake --install /verve/build --prefix /verve/install >/dev/null"

echo "== in the $suite root: the C sample against the installed tree (pkg-config), the CMake package"
in_root "cd /verve && export PKG_CONFIG_PATH=/verve/install/lib/pkgconfig
  cc -std=c99 -O2 src/samples/c/hello_verve.c \$(pkg-config --cflags --libs verve) -Wl,-rpath,/verve/install/lib -o hello_verve
  ./hello_verve | tail -n 2
  cmake -S src/tests/capi/consumer -B consumer -DCMAKE_PREFIX_PATH=/verve/install -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build consumer >/dev/null && consumer/consumer_c && consumer/consumer_cpp"

echo "== in the $suite root: the Lua suite under LuaJIT and Lua 5.4, against the installed modules"
in_root "cd /verve/src && for flavour in jit:5.1 lua5.4:5.4; do
    exe=\${flavour%%:*}; [ \$exe = jit ] && exe=luajit; dir=/verve/install/lib/lua/\${flavour#*:}
    for t in bindings/lua/tests/test_*.lua; do
      \$exe -e \"package.cpath=[[\$dir/?.so]] package.path=[[bindings/lua/tests/?.lua;samples/lua/?.lua]]\" \$t >/dev/null ||
        { echo \"\$exe \$t failed\" >&2; exit 1; }
    done
    echo \"\$exe: \$(ls bindings/lua/tests/test_*.lua | wc -l) Lua test scripts passed\"
  done"

rm -rf "$out"; mkdir -p "$out"
cp -a "$root/verve/install/." "$out/"
# Every ELF file shipped from here must load on glibc 2.31.
find "$out" -type f \( -name '*.so' -o -name '*.so.*' \) -print0 | xargs -0 -n 1 scripts/check_glibc_floor.sh
echo "build_old_glibc.sh: $out"
