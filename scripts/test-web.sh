#!/usr/bin/env bash
# The browser build, tested in a real browser: builds dist/ (build-web.sh),
# serves it on a free local port, and drives it in headless Chromium through
# WebDriver (tests/web/browser_test.py). Needs Debian's chromium and
# chromium-driver (installed with apt when run as root) and selenium from
# PyPI (installed into target/web-venv). Compares the physics with the
# desktop build's (`impulse fingerprint`; IMPULSE_BIN names the binary to ask).
# Writes target/web-screenshot.png.
set -euo pipefail
cd "$(dirname "$0")/.."
if ! command -v chromium >/dev/null || [ ! -x /usr/bin/chromedriver ]; then
  if [ "$(id -u)" -eq 0 ]; then
    apt-get install -y -qq --no-install-recommends chromium chromium-driver >/dev/null
  else
    echo "missing: chromium chromium-driver (Debian packages; apt-get install them as root)" >&2
    exit 1
  fi
fi
venv=target/web-venv
if [ ! -x "$venv/bin/python" ]; then
  python3 -m venv "$venv"
fi
"$venv/bin/python" -c "import selenium" 2>/dev/null || "$venv/bin/pip" install -q selenium
scripts/build-web.sh
# The desktop's state hashes, from IMPULSE_BIN if given (CI passes the binary
# `cargo test` has just built: debug or release, the arithmetic is the same),
# else from a release build.
bin=${IMPULSE_BIN:-}
if [ -z "$bin" ]; then
  cargo build --release --quiet --bin impulse
  bin=target/release/impulse
fi
"$bin" fingerprint > target/fingerprints.json
port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
python3 -m http.server --bind 127.0.0.1 -d dist "$port" >/dev/null 2>&1 &
server=$!
trap 'kill $server 2>/dev/null || true' EXIT
for _ in $(seq 50); do
  python3 -c "import urllib.request; urllib.request.urlopen('http://127.0.0.1:$port/')" 2>/dev/null && break
  sleep 0.1
done
"$venv/bin/python" tests/web/browser_test.py "http://127.0.0.1:$port/" target/web-screenshot.png \
  target/fingerprints.json
