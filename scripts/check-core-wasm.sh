#!/usr/bin/env bash
# Builds the physics core alone for the browser (wasm32-unknown-unknown),
# without rayon; the toolchain route is scripts/wasm-toolchain.sh's.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/wasm-toolchain.sh
echo "core for $target: $wasm_route"
wasm_cargo --release -p impulse-core --no-default-features
