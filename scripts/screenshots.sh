#!/usr/bin/env bash
# Makes the screenshots of the README and docs/guide.md with the real program under Xvfb, aiming
# the mouse through the state dump (widget rectangles, the camera).
# Needs: xvfb xdotool libgl1-mesa-dri (see README). Usage: scripts/screenshots.sh
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --quiet
bin=target/release/impulse
source scripts/xvfb.sh
dump=$(mktemp -d)/state.json
export XDG_STATE_HOME=$(mktemp -d)

# The centre of a widget of the dump, or the screen point of disc N.
widget() { python3 -c "import json,sys; r=json.load(open('$dump'))['panel_widgets']['$1']; print(round(r[0]+r[2]/2), round(r[1]+r[3]/2))"; }
disc() { python3 -c "
import json; s=json.load(open('$dump')); c=s['camera']; p=s['particles'][$1]['pos']
print(round(c['origin'][0]+c['viewport'][0]/2+(p[0]-c['center'][0])*c['scale']), round(c['origin'][1]+c['viewport'][1]/2-(p[1]-c['center'][1])*c['scale']))"; }
# English unless a picture asks for a language (the README's pictures are
# English, whatever this machine's locale).
start() {
  local lang=(--lang en); [[ " $* " == *" --lang "* ]] && lang=()
  "$bin" --dump-state "$dump" --exit-after 60 --autosave 0 --no-start "${lang[@]}" "$@" & app=$!; sleep 2.5
}
finish() { xdotool key ctrl+q; wait "$app"; }
click() { xdotool mousemove $1 $2; sleep 0.3; xdotool click 1; sleep 0.4; }

# 1. The default scene: momentum arrows, the heavy disc selected, paused.
start --paused --screenshot docs/sandbox.png
xdotool mousemove 300 300 key m
sleep 0.3; click $(disc 0); xdotool key space; sleep 1.5; xdotool key space; sleep 0.5
finish

# 2. The lesson: head-on, run to the collision (J), the Collisions tab.
start --paused --screenshot docs/lesson.png
xdotool mousemove 300 300 key 1; sleep 0.5; xdotool key m key j; sleep 1
finish

# 3. The Discs table beside the glancing hit.
start --paused --screenshot docs/panel.png
xdotool mousemove 300 300 key 4; sleep 0.5
click $(widget tab_discs)
click $(disc 0)
finish

# 4. A projector in a bright room: scale 2, light theme, the glancing hit.
start --size 1280x800 --ui-scale 2 --light --screenshot docs/projector.png
xdotool mousemove 300 300 key 4; sleep 1.2; xdotool key space; sleep 0.5
finish

# 5. Launching: dragging out a new disc in the empty box.
start assets/scenes/empty.toml --screenshot docs/launch.png
xdotool mousemove 250 450 mousedown 1
for x in 290 330 370 410 450; do xdotool mousemove "$x" $((450 - (x - 250) / 2)); sleep 0.05; done
sleep 0.5
finish
xdotool mouseup 1   # the drag was left held for the picture

# 6. The key list.
start --screenshot docs/help.png
xdotool mousemove 300 300 key h; sleep 0.5
finish

# 7. The presets, a few seconds after opening.
for preset in "1 head-on" "4 glancing" "6 cradle" "7 pi-blocks" "9 billiards" "0 pile"; do
  set -- $preset
  start --screenshot "docs/presets/$2.png"
  xdotool mousemove 300 300 key "$1"; sleep 2.5
  finish
done
# 8. The π blocks at their end: the count and π, the view following them.
start assets/scenes/preset-7-pi-blocks.toml --screenshot docs/pi-end.png
xdotool mousemove 300 300 key bracketright key bracketright; sleep 5
finish

# 9. Δp arrows at the instant of the glancing hit (J), momentum arrows on.
start --paused --screenshot docs/delta-p.png
xdotool mousemove 300 300 key 4; sleep 0.5; xdotool key m key j; sleep 1
finish

# 10. One dimension: heavy hits light on its rail, path traces on.
start --screenshot docs/track.png
xdotool mousemove 300 300 key 2; sleep 0.3; xdotool key a; sleep 4
finish

# 11. Path traces of the glancing hit: the dots' spacing is the speed.
start --screenshot docs/paths.png
xdotool mousemove 300 300 key 4; sleep 0.3; xdotool key a; sleep 4.5
finish
# 12. The start screen, as a plain start shows it.
"$bin" --dump-state "$dump" --exit-after 60 --autosave 0 --lang en --screenshot docs/start.png & app=$!; sleep 2.5
xdotool mousemove 640 300; sleep 0.5
finish

# 13. A laptop at the projector's scale: 1024×768, scale 2, the glancing hit
# at its instant (J), the ledger open and made taller by its top edge, the
# controls in their drawer.
start --size 1024x768 --ui-scale 2 --screenshot docs/projector-ledger.png
xdotool mousemove 300 200 key 4; sleep 0.5; xdotool key j; sleep 1
read -r ex ey <<< "$(widget tab_edge)"
xdotool mousemove "$ex" "$ey" mousedown 1; sleep 0.2
for dy in 30 60 90 120; do xdotool mousemove "$ex" $((ey - dy)); sleep 0.05; done
sleep 0.3; xdotool mouseup 1; xdotool mousemove 300 200; sleep 0.5
finish

# 14. Another classroom: Spanish at the projector's scale, the glancing hit at
# its instant (J), the ledger open.
start --size 1024x768 --ui-scale 2 --lang es --screenshot docs/projector-es.png
xdotool mousemove 300 200 key 4; sleep 0.5; xdotool key j; sleep 1
finish

# 15. The key list in German.
start --lang de --screenshot docs/help-de.png
xdotool mousemove 300 300 key h; sleep 0.5
finish
echo "screenshots in docs/"
