#!/usr/bin/env python3
"""Two copies side by side, both ways: the middle z-slice of each volume's colour tiled 2x2, the
volumes in a row. Reads DIR/color.npy (solidtex ... --npy DIR).

Usage: tile_slices.py OUT.png DIR [DIR ...]
"""
import sys

import numpy as np
from PIL import Image

GAP = 8
SCALE = 2  # pixels per voxel


def srgb(linear):
    x = np.clip(linear, 0, 1)
    return np.where(x <= 0.0031308, 12.92 * x, 1.055 * x ** (1 / 2.4) - 0.055)


def tiled(folder):
    color = np.load(f"{folder}/color.npy")  # (Z, Y, X, 3) linear
    middle = color[color.shape[0] // 2][::-1]  # y up, as the previews show it
    image = (srgb(np.tile(middle, (2, 2, 1))) * 255 + 0.5).astype(np.uint8)
    return image.repeat(SCALE, axis=0).repeat(SCALE, axis=1)


if __name__ == "__main__":
    if len(sys.argv) < 3:
        raise SystemExit(__doc__)
    tiles = [tiled(folder) for folder in sys.argv[2:]]
    height = max(t.shape[0] for t in tiles)
    out = np.full((height, sum(t.shape[1] for t in tiles) + GAP * (len(tiles) - 1), 3), 255, np.uint8)
    x = 0
    for t in tiles:
        out[: t.shape[0], x : x + t.shape[1]] = t
        x += t.shape[1] + GAP
    Image.fromarray(out).save(sys.argv[1])
