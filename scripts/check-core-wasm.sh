#!/usr/bin/env bash
# Builds the physics core for the browser (wasm32-unknown-unknown), without
# rayon: the route of Debian's rustc-web (rustc 1.96 with the standard
# library's sources) and lld-19, which needs nothing outside the package
# registries; or the rustup toolchain's wasm32 target where it is installed.
set -euo pipefail
cd "$(dirname "$0")/.."
target=wasm32-unknown-unknown
if rustup target list --installed 2>/dev/null | grep -qx "$target"; then
  echo "core for $target: rustup's installed target"
  cargo build --release -p impulse-core --no-default-features --target "$target"
  exit 0
fi
if [ ! -x /usr/bin/rustc ] || ! command -v wasm-ld-19 >/dev/null; then
  if [ "$(id -u)" -eq 0 ]; then
    apt-get install -y -qq --no-install-recommends rustc-web cargo-web rust-web-src lld-19 >/dev/null
  else
    echo "missing: Debian's rustc-web cargo-web rust-web-src lld-19 (apt-get install as root)" >&2
    exit 1
  fi
fi
echo "core for $target: Debian's rustc-web with -Zbuild-std"
RUSTC=/usr/bin/rustc RUSTC_BOOTSTRAP=1 \
  CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_LINKER=wasm-ld-19 \
  CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_RUSTFLAGS="-C link-arg=--allow-undefined" \
  CARGO_TARGET_DIR=target/wasm \
  /usr/bin/cargo build --release -p impulse-core --no-default-features \
  --target "$target" -Zbuild-std=std,panic_abort
