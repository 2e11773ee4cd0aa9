#!/usr/bin/python3
"""Particle solids placed whole and in bricks of 64 (gravel, 128^3): the fraction of the axis planes
around the bricks' inner faces (offset from the face, averaged over the three axes and the seeds),
and a figure of the z = 40 slice of each (seed 1), whose x = 64 and y = 64 lines are brick faces
(ticks on the border).
Usage: PYTHONPATH=build/python bench/brick_seams.py [FIGURE.png]   (from the repo root)"""
import sys

import numpy as np
from PIL import Image, ImageDraw

import solidtex

PHOTO, SIZE, EDGE, SEEDS = "data/particles/gravel.png", 128, 64, (1, 2, 3, 4)
OFFSETS = range(-6, 6)  # plane EDGE + offset: negative before the face, 0 the first plane after it

profiles, slices = {}, {}
for mode in ("whole", "bricks"):
    rows = []
    for seed in SEEDS:
        solid = solidtex.particles(PHOTO, size=SIZE, seed=seed, **({"bricks": EDGE} if mode == "bricks" else {}))
        taken = solid["particle_id"] > 0  # (z, y, x)
        per_axis = [taken.mean(axis=(0, 1)), taken.mean(axis=(0, 2)), taken.mean(axis=(1, 2))]
        rows.append([np.mean([p[EDGE + o] for p in per_axis]) for o in OFFSETS])
        if seed == SEEDS[0]:
            slices[mode] = solid["color"][40]
    profiles[mode] = np.mean(rows, axis=0)
    fraction = solid["report"]["photo"]["area_fraction"]

print("| placed | " + " | ".join(f"{o:+d}" for o in OFFSETS) + " |")
print("|---|" + "---|" * len(OFFSETS))
for mode, profile in profiles.items():
    print(f"| {mode} | " + " | ".join(f"{v:.3f}" for v in profile) + " |")
print(f"photo's area fraction {fraction:.3f}; plane = {EDGE} + offset, mean of x, y, z planes and seeds {SEEDS}")

if len(sys.argv) > 1:
    scale, gap = 3, 12
    panels = []
    for mode in ("whole", "bricks"):
        srgb = np.where(slices[mode] <= 0.0031308, 12.92 * slices[mode], 1.055 * np.power(slices[mode], 1 / 2.4) - 0.055)
        image = Image.fromarray((np.clip(srgb, 0, 1) * 255).astype(np.uint8)).resize((SIZE * scale, SIZE * scale), Image.NEAREST)
        framed = Image.new("RGB", (SIZE * scale + 2 * gap, SIZE * scale + 2 * gap), "white")
        framed.paste(image, (gap, gap))
        draw = ImageDraw.Draw(framed)
        at = gap + EDGE * scale
        draw.line([(at, 0), (at, gap - 2)], fill="red", width=3)
        draw.line([(0, at), (gap - 2, at)], fill="red", width=3)
        panels.append(framed)
    figure = Image.new("RGB", (sum(p.width for p in panels), panels[0].height), "white")
    figure.paste(panels[0], (0, 0))
    figure.paste(panels[1], (panels[0].width, 0))
    figure.save(sys.argv[1])
