#!/usr/bin/env bash
# The web build and its tests (docs/web.md): the web-release preset (Emscripten) into build/web,
# the JS API's suite (node --test, with a native program to compare actions and saves with), the
# cart-pole page in headless Chromium (screenshot: build/web/web-cart-pole.png), the bundle's
# gzipped sizes and one run of the update cost in wasm against native.
# Installs nothing: ./scripts/setup.sh --test does (emscripten, nodejs, chromium, samples/web's
# playwright-core and typescript); needs the native build (./scripts/build.sh) for the comparisons.
set -euo pipefail
cd "$(dirname "$0")/.."
start=$SECONDS
native=build/src/capi
if [ ! -e "$native/libverve.so" ]; then
  echo "test_web.sh: no native $native/libverve.so to compare with; run ./scripts/build.sh first" >&2
  exit 1
fi
if [ "$(node -p 'process.versions.node.split(".")[0]')" -lt 20 ]; then
  echo "test_web.sh: Node.js $(node --version) is too old for samples/web's playwright-core; 20 or newer is needed" >&2
  exit 1
fi
if [ ! -d samples/web/node_modules/playwright-core ] || [ ! -d samples/web/node_modules/typescript ]; then
  echo "test_web.sh: samples/web lacks playwright-core or typescript; run ./scripts/setup.sh --test first" >&2
  exit 1
fi

echo "== web: the wasm module (cmake --preset web-release)"
cmake --preset web-release >/dev/null
cmake --build --preset web-release -j"$(nproc)"

echo "== web: the JavaScript API (node --test bindings/web/test), against the native library"
# The native side of test/determinism.test.js: the same seeds' actions, saves both ways.
cc -O2 -I include bindings/web/test/native/hot_plate_actions.c -L "$native" -lverve -Wl,-rpath,"$PWD/$native" \
  -o build/web/hot_plate_actions
VERVE_NATIVE_PROGRAM="$PWD/build/web/hot_plate_actions" node --expose-gc --test bindings/web/test/

echo "== web: index.d.ts against a TypeScript program (tsc --noEmit)"
samples/web/node_modules/.bin/tsc -p bindings/web/test/types

echo "== web: the cart-pole page in headless Chromium"
(cd samples/web && VERVE_NATIVE_PROGRAM="$PWD/../../build/web/hot_plate_actions" node test_page.mjs ../../build/web/web-cart-pole.png)

echo "== web: bundle sizes (bytes: raw, gzip -9)"
for f in bindings/web/dist/verve_wasm.wasm bindings/web/dist/verve_wasm.mjs; do
  echo "$f $(wc -c <"$f") $(gzip -9c "$f" | wc -c)"
done
echo "bindings/web/src/*.js $(cat bindings/web/src/*.js | wc -c) $(cat bindings/web/src/*.js | gzip -9c | wc -c)"

echo "== web: one update on the cart-pole shape, microseconds (one run each; docs/web.md)"
cc -O2 -I include bindings/web/bench/update_cost.c -L "$native" -lverve -lm -Wl,-rpath,"$PWD/$native" \
  -o build/web/update_cost_native
n=100000
native_us=$(build/web/update_cost_native $n | cut -d' ' -f1)
wasm_us=$(node build/web/bindings/web/verve_web_update_cost.cjs $n | cut -d' ' -f1)
js_us=$(node bindings/web/bench/update_cost.mjs $n | cut -d' ' -f1)
echo "native $native_us, wasm (C) $wasm_us, wasm through the JS API $js_us"
awk -v n="$native_us" -v w="$wasm_us" -v j="$js_us" 'BEGIN { printf "wasm / native: %.1fx (C), %.1fx (JS API)\n", w / n, j / n }'
echo "web: $((SECONDS - start)) s"
