# Sourced by check-core-wasm.sh and build-web.sh: picks how to build for
# wasm32-unknown-unknown and defines `wasm_cargo ARGS...`. Where rustup's
# wasm32 target is installed, plain cargo; otherwise Debian's rustc-web (rustc
# with the standard library's sources) and lld-19 with -Zbuild-std, which
# need nothing outside the package registries (installed with apt when run
# as root, else named as missing). Both put their output in target/wasm.
target=wasm32-unknown-unknown
if rustup target list --installed 2>/dev/null | grep -qx "$target"; then
  wasm_route="rustup's installed $target target"
  wasm_cargo() { CARGO_TARGET_DIR=target/wasm cargo build --target "$target" "$@"; }
else
  need=()
  { [ -x /usr/bin/rustc ] && [ -d /usr/lib/rustlib/src/rust/library ]; } || need+=(rustc-web cargo-web rust-web-src)
  command -v wasm-ld-19 >/dev/null || need+=(lld-19)
  if [ ${#need[@]} -gt 0 ]; then
    if [ "$(id -u)" -eq 0 ]; then
      apt-get install -y -qq --no-install-recommends "${need[@]}" >/dev/null
    else
      echo "missing: ${need[*]} (Debian packages; apt-get install them as root)" >&2
      exit 1
    fi
  fi
  wasm_route="Debian's rustc-web with -Zbuild-std"
  wasm_cargo() {
    RUSTC=/usr/bin/rustc RUSTC_BOOTSTRAP=1 \
      CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_LINKER=wasm-ld-19 \
      CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_RUSTFLAGS="-C link-arg=--allow-undefined" \
      CARGO_TARGET_DIR=target/wasm \
      /usr/bin/cargo build --target "$target" -Zbuild-std=std,panic_abort "$@"
  }
fi
