#!/usr/bin/env bash
# Verve demo on a fresh Debian machine (run as root): installs what is missing, builds Release into
# build/, runs the Bullet cart-pole scene headless until it balances 30 simulated minutes, and
# says what it learned and where the plot is. Re-running is fast: present packages are skipped.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(build-essential cmake pkg-config libeigen3-dev libbullet-dev libpugixml-dev libgtest-dev
          libbenchmark-dev liblua5.4-dev libluajit-5.1-dev libcli11-dev gnuplot-nox)
missing=()
for p in "${packages[@]}"; do
  dpkg -s "$p" > /dev/null 2>&1 || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "== installing: ${missing[*]}"
  apt-get update -q
  DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

echo "== building (Release, build/)"
mkdir -p build
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DVERVE_BUILD_BENCH=OFF -DVERVE_BUILD_TESTS=OFF > build/configure.log 2>&1 ||
  { cat build/configure.log; exit 1; }
cmake --build build -j2 --target verve-demo

out=build/demo
echo "== cart-pole (Bullet): learning to balance for 1800 s (30 simulated minutes)"
build/samples/runner/verve-demo run cart-pole --seed 1 --trials 3000 --out "$out"
echo
echo "Plot of the learning curve: $out/cart-pole-curve.png (seconds balanced per trial, log scale)"
echo "Value-function slice (pole angle x angular velocity): $out/cart-pole-value.png"
