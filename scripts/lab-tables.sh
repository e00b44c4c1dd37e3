#!/bin/sh
# Regenerates every committed lab table and chart, the one way they are made:
#
#   scripts/lab-tables.sh          the full runs into docs/lab/ (bench, accuracy,
#                                  stress: about 5 minutes on 2 cores on a quiet
#                                  hour, 4.5 on 2026-11-26) and the
#                                  quick ones into docs/lab/quick/
#   scripts/lab-tables.sh --quick  only the quick ones (about 2 minutes)
#
# tests/lab_tables.rs checks that the deterministic columns of the quick tables
# (counts, errors, drifts; not timings) still match what the code produces, so
# after a change to the physics that moves them, run this and commit the result.
# tests/lab_figures.rs checks that every figure README.md and the lab notes
# quote is what its committed table holds; the full run rewrites those quotes.
set -eu
cd "$(dirname "$0")/.."
cargo build --release --quiet
bin=target/release/impulse
mkdir -p docs/lab/quick
"$bin" stress --quick --out docs/lab/quick
"$bin" accuracy --quick --out docs/lab/quick
rm -f docs/lab/quick/*.png docs/lab/quick/*.svg # the charts are the full runs
if [ "${1:-}" != "--quick" ]; then
    "$bin" bench --out docs/lab
    "$bin" accuracy --out docs/lab
    "$bin" stress --out docs/lab
    # The figures README.md and docs/lab/NOTES.md quote, each marked with the
    # table cell it comes from, rewritten from the new tables (the same test
    # then checks them on every `cargo test`).
    IMPULSE_UPDATE_FIGURES=1 cargo test --quiet --test lab_figures
fi
echo "lab tables written; commit docs/lab (and README.md, if its quoted figures moved)"
