#!/usr/bin/env bash
# Builds the sandbox for the browser into dist/: index.html, impulse.wasm,
# the JavaScript glue (macroquad's loader, quad-url's plugin and ours). Serve
# it with `python3 -m http.server -d dist` and open http://localhost:8000;
# dist/ is a static site for any web host.
#
# The toolchain route (rustup's wasm32 target, else Debian's rustc-web and
# lld-19, installed with apt when run as root) is scripts/wasm-toolchain.sh's.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/wasm-toolchain.sh
out=target/wasm/$target/release/impulse.wasm
echo "web build: $wasm_route"
wasm_cargo --release --bin impulse --no-default-features
rm -rf dist && mkdir -p dist
cp web/index.html web/impulse.js dist/
registry=$(cargo metadata --format-version 1 | python3 -c '
import json, sys, os
m = json.load(sys.stdin)
for p in m["packages"]:
    if p["name"] in ("macroquad", "quad-url"):
        print(p["name"], os.path.dirname(p["manifest_path"]))')
cp "$(echo "$registry" | awk '$1 == "macroquad" {print $2}')/js/mq_js_bundle.js" dist/
cp "$(echo "$registry" | awk '$1 == "quad-url" {print $2}')/js/quad-url.js" dist/
if command -v wasm-opt >/dev/null; then
  wasm-opt -Oz --enable-bulk-memory --enable-nontrapping-float-to-int --enable-sign-ext \
    --enable-mutable-globals "$out" -o dist/impulse.wasm
  echo "web build: wasm-opt -Oz"
else
  cp "$out" dist/impulse.wasm
  echo "web build: no wasm-opt (apt-get install binaryen to shrink the .wasm)"
fi
echo "dist/impulse.wasm: $(du -k dist/impulse.wasm | cut -f1) KiB; serve with: python3 -m http.server -d dist"
