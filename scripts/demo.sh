#!/usr/bin/env bash
# Verve demo on a fresh Debian machine: installs what is missing, builds Release into build/,
# runs the Bullet cart-pole scene headless until it balances 30 simulated minutes, and says what
# it learned and where the plot is. Re-running is fast: present packages are skipped.
set -euo pipefail
cd "$(dirname "$0")/.."

./scripts/setup.sh
echo "== building verve-demo (Release, build/)"
./scripts/build.sh verve-demo >/dev/null

out=build/demo
echo "== cart-pole (Bullet): learning to balance for 1800 s (30 simulated minutes)"
build/samples/runner/verve-demo run cart-pole --seed 1 --trials 3000 --out "$out"
echo
echo "Plot of the learning curve: $out/cart-pole-curve.png (seconds balanced per trial, log scale)"
echo "Value-function slice (pole angle x angular velocity): $out/cart-pole-value.png"
