#!/usr/bin/env bash
# Makes the README's screenshots with the real program under Xvfb.
# Needs: xvfb xdotool libgl1-mesa-dri (see README). Usage: scripts/screenshots.sh
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --quiet
bin=target/release/impulse
source scripts/xvfb.sh

# 1. The default scene with momentum arrows and the heavy disc selected
#    (it starts at world (3, 5), which is pixel (270, 400) in the fitted view).
$bin --paused --screenshot docs/sandbox.png --exit-after 30 &
app=$!
sleep 2
xdotool mousemove 640 400 key m
xdotool mousemove 270 400 click 1
xdotool mousemove 640 760 key space
sleep 2.2
xdotool key space
sleep 0.3
xdotool key ctrl+q
wait $app

# 2. Launching: dragging out a new disc in the empty box, with the help open.
$bin assets/scenes/empty.toml --screenshot docs/launch.png --exit-after 30 &
app=$!
sleep 2
xdotool mousemove 300 500 mousedown 1
for x in 340 380 420 460 500; do xdotool mousemove "$x" $((500 - (x - 300) / 2)); sleep 0.05; done
sleep 0.5
xdotool key ctrl+q
wait $app

$bin --screenshot docs/help.png --exit-after 30 &
app=$!
sleep 2
xdotool mousemove 640 400 key h
sleep 0.5
xdotool key ctrl+q
wait $app
echo "screenshots in docs/"
