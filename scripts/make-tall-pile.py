#!/usr/bin/env python3
"""Writes assets/scenes/stress-pile-tall.toml: 360 discs (18 columns, 20
rows) with random velocities up to 1 m/s, restitution 0.8, under gravity.
The seed is fixed, so running this again writes the same file."""
import math
import random
from pathlib import Path

COLUMNS, ROWS, SEED = 18, 20, 18
RADIUS, SPACING = 0.2, 0.5
PALETTE = ["#0072b2", "#e69f00", "#009e73", "#cc79a7", "#56b4e9", "#d55e00"]

rng = random.Random(SEED)
out = [
    'name = "Stress: tall pile (e = 0.8)"',
    'description = "360 discs in 18 columns and 20 rows, thrown about at up to 1 m/s, fall into a pile with restitution 0.8: an event-driven method must come through inelastic collapse and resting contact."',
    "",
    "# Written by scripts/make-tall-pile.py (seed 18); run it again to get the",
    "# same file.",
    "[world]",
    f"size = [{COLUMNS * SPACING}, {ROWS * SPACING + 2.0}]",
    "gravity = [0.0, -9.81]",
    "restitution = 0.8",
    "wall_restitution = 0.8",
    'boundary = "box"',
]
for row in range(ROWS):
    for col in range(COLUMNS):
        speed = rng.uniform(0.0, 1.0)
        angle = rng.uniform(0.0, 2.0 * math.pi)
        x = (col + 0.5) * SPACING
        y = (row + 0.5) * SPACING + 1.0
        mass = math.pi * RADIUS * RADIUS
        out += [
            "",
            "[[particles]]",
            f"pos = [{x!r}, {y!r}]",
            f"vel = [{speed * math.cos(angle)!r}, {speed * math.sin(angle)!r}]",
            f"mass = {mass!r}",
            f"radius = {RADIUS!r}",
            f'color = "{PALETTE[col % len(PALETTE)]}"',
        ]
path = Path(__file__).resolve().parent.parent / "assets/scenes/stress-pile-tall.toml"
path.write_text("\n".join(out) + "\n")
print(f"wrote {path}")
