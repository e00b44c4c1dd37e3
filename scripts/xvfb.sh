# Sourced by the scripts that drive the window: starts a private Xvfb on a
# random display, points DISPLAY at it and stops it when the script exits.
display=":$((300 + RANDOM % 300))"
Xvfb "$display" -noreset -screen 0 1920x1080x24 -nolisten tcp >/dev/null 2>&1 &
xvfb=$!
trap 'kill $xvfb 2>/dev/null' EXIT
sleep 1
export DISPLAY="$display"
