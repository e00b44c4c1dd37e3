#!/usr/bin/env bash
# Frame time against disc count under Xvfb (Mesa llvmpipe on the CPU): for a
# gas of 1k, 10k and 100k discs, paused without overlays, paused with every
# overlay (velocity and momentum arrows, readouts for all discs) and running
# without overlays. Prints medians (ms) of frame, physics, drawing (CPU) and
# presenting (inside next_frame: the batches rendered, the UI, the swap).
# Needs: xvfb xdotool libgl1-mesa-dri. Usage:
#   scripts/frame-times.sh [--bin PATH] [--out DIR] [--counts "1000 10000"] [--seconds S]
#                          [--modes "plain overlays running"]
set -euo pipefail
cd "$(dirname "$0")/.."
bin=target/release/impulse
out=impulse-out/frame-times
counts="1000 10000 100000"
seconds=""
modes="plain overlays running"
while [ $# -gt 0 ]; do
    case "$1" in
        --bin) bin="$2"; shift 2 ;;
        --out) out="$2"; shift 2 ;;
        --counts) counts="$2"; shift 2 ;;
        --seconds) seconds="$2"; shift 2 ;;
        --modes) modes="$2"; shift 2 ;;
        *) echo "unknown argument $1" >&2; exit 2 ;;
    esac
done
mkdir -p "$out"
source scripts/xvfb.sh

# Median of column $2 over the CSV rows of file $1 that match the overlay
# state $3 (velocity,momentum,readouts), after skipping the first 10 of them.
median() {
    awk -F, -v col="$2" -v want="$3" 'NR > 1 && ($3 "," $4 "," $5) == want { n++; if (n > 10) print $col }' "$1" |
        sort -g | awk '{ v[NR] = $1 } END { if (NR == 0) { print "-"; exit }
            m = (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2; printf "%.2f %d\n", m, NR }'
}

printf "%-8s %-9s %7s %9s %8s %8s %10s\n" discs mode frames frame_ms step_ms draw_ms present_ms
for n in $counts; do
    for mode in $modes; do
        case "$mode" in
            plain) flags=(--paused); keys=(v); want="0,0,selected" ;;
            overlays) flags=(--paused); keys=(m i); want="1,1,all" ;;
            running) flags=(); keys=(v); want="0,0,selected" ;;
        esac
        limit="${seconds:-$((12 + n / 2500))}"
        csv="$out/$n-$mode.csv"
        "$bin" --gas "$n" "${flags[@]}" --frame-stats "$csv" --exit-after "$limit" 2>/dev/null &
        app=$!
        xdotool search --sync --name "Impulse" >/dev/null
        sleep 2
        xdotool mousemove 640 400
        for k in "${keys[@]}"; do xdotool key "$k"; sleep 0.3; done
        wait $app
        read -r frame count < <(median "$csv" 7 "$want")
        read -r step _ < <(median "$csv" 8 "$want")
        read -r draw _ < <(median "$csv" 9 "$want")
        read -r present _ < <(median "$csv" 10 "$want")
        printf "%-8s %-9s %7s %9s %8s %8s %10s\n" "$n" "$mode" "$count" "$frame" "$step" "$draw" "$present"
    done
done
