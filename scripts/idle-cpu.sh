#!/usr/bin/env bash
# What an idle window costs: starts the sandbox paused on the two-disc
# head-on preset under a private Xvfb (Mesa llvmpipe on the CPU), lets it
# settle, then reads the CPU time (user + system, from /proc) that the app
# and Xvfb use over the next SECONDS, as a percentage of one core.
# Needs: xvfb libgl1-mesa-dri. Usage:
#   scripts/idle-cpu.sh [--bin PATH] [--seconds S] [--running]
set -euo pipefail
cd "$(dirname "$0")/.."
bin=target/release/impulse
seconds=60
paused=--paused
while [ $# -gt 0 ]; do
    case "$1" in
        --bin) bin="$2"; shift 2 ;;
        --seconds) seconds="$2"; shift 2 ;;
        --running) paused=""; shift ;;
        *) echo "unknown argument $1" >&2; exit 2 ;;
    esac
done
source scripts/xvfb.sh
dir=$(mktemp -d)
# shellcheck disable=SC2086
"$bin" assets/scenes/preset-1-head-on.toml $paused --autosave 0 --out "$dir" >/dev/null 2>&1 &
app=$!
trap 'kill $app $xvfb 2>/dev/null; rm -rf "$dir"' EXIT
sleep 5
ticks() { awk '{print $14 + $15}' "/proc/$1/stat"; }
hz=$(getconf CLK_TCK)
a0=$(ticks $app); x0=$(ticks $xvfb)
sleep "$seconds"
a1=$(ticks $app); x1=$(ticks $xvfb)
share() { awk -v t="$1" -v hz="$hz" -v s="$seconds" 'BEGIN { printf "%.1f", 100 * t / hz / s }'; }
echo "app:  $(share $((a1 - a0))) % of a core over $seconds s"
echo "Xvfb: $(share $((x1 - x0))) % of a core over $seconds s"
