#!/usr/bin/env bash
# Builds the sandbox for the browser into dist/: index.html, impulse.wasm,
# the JavaScript glue (macroquad's loader, quad-url's plugin and ours). Serve
# it with `python3 -m http.server -d dist` and open http://localhost:8000;
# dist/ is a static site for any web host.
#
# With the rustup toolchain's wasm32 target installed it uses plain cargo;
# otherwise Debian's rustc-web (rustc with the standard library's sources)
# and lld-19, which come from the package registries alone. Run as root, it
# installs what it needs with apt; otherwise it says what is missing.
set -euo pipefail
cd "$(dirname "$0")/.."
target=wasm32-unknown-unknown
out=target/wasm/$target/release/impulse.wasm
if rustup target list --installed 2>/dev/null | grep -qx "$target"; then
  echo "web build: rustup's installed $target target"
  CARGO_TARGET_DIR=target/wasm cargo build --release --bin impulse --no-default-features \
    --target "$target"
else
  need=()
  [ -x /usr/bin/rustc ] && [ -d /usr/lib/rustlib/src/rust/library ] || need+=(rustc-web cargo-web rust-web-src)
  command -v wasm-ld-19 >/dev/null || need+=(lld-19)
  if [ ${#need[@]} -gt 0 ]; then
    if [ "$(id -u)" -eq 0 ]; then
      apt-get install -y -qq --no-install-recommends "${need[@]}" >/dev/null
    else
      echo "missing: ${need[*]} (Debian packages; apt-get install them as root)" >&2
      exit 1
    fi
  fi
  echo "web build: Debian's rustc-web with -Zbuild-std"
  RUSTC=/usr/bin/rustc RUSTC_BOOTSTRAP=1 \
    CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_LINKER=wasm-ld-19 \
    CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_RUSTFLAGS="-C link-arg=--allow-undefined" \
    CARGO_TARGET_DIR=target/wasm \
    /usr/bin/cargo build --release --bin impulse --no-default-features \
    --target "$target" -Zbuild-std=std,panic_abort
fi
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
