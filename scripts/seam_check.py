#!/usr/bin/env python3
"""Does a solid tile without a seam? Reads DIR/particle_id.npy (solidtex ... --npy DIR) and
compares two copies side by side with the volume itself:

- section areas: on every second axis plane, the particle sections seen through a window of the
  volume's size that starts half a volume in on both in-plane axes (the copies' faces through its
  middle) against those through the volume's own window; sections cut by a window's border are
  left out, as a photo's border particles are. Two-sample KS and its 5 % critical value.
- slab fractions: the particle share of the slab of 6 planes across the faces where copies meet,
  against the least and most of the slabs inside the volume.

Usage: seam_check.py DIR [DIR ...]; prints one JSON line per volume.
"""
import json
import sys

import numpy as np
from scipy import ndimage

BAND = 3
EIGHT = np.ones((3, 3), dtype=bool)


def section_areas(ids, shift):
    areas = []
    n = ids.shape[0]
    for axis in range(3):
        for k in range(0, n, 2):
            plane = np.take(ids, k, axis=axis)
            plane = np.roll(plane, (-shift, -shift), axis=(0, 1))
            for pid in np.unique(plane[plane > 0]):
                labels, count = ndimage.label(plane == pid, structure=EIGHT)
                if count == 0:
                    continue
                sizes = np.bincount(labels.ravel())
                border = np.unique(np.concatenate([labels[0], labels[-1], labels[:, 0], labels[:, -1]]))
                for region in range(1, count + 1):
                    if region not in border and sizes[region] >= 4:
                        areas.append(sizes[region])
    return np.array(areas, dtype=float)


def ks(a, b):
    a, b = np.sort(a), np.sort(b)
    values = np.concatenate([a, b])
    return float(np.max(np.abs(np.searchsorted(a, values, side="right") / len(a)
                               - np.searchsorted(b, values, side="right") / len(b))))


def slab_fraction(occupied, axis, c):
    n = occupied.shape[axis]
    planes = [(c + d) % n for d in range(-BAND, BAND)]
    return float(np.take(occupied, planes, axis=axis).mean())


def measure(folder):
    ids = np.load(f"{folder}/particle_id.npy")  # (Z, Y, X)
    if len(set(ids.shape)) != 1:
        raise SystemExit(f"{folder}: the check takes cubic volumes, got {ids.shape}")
    n = ids.shape[0]
    inside, across = section_areas(ids, 0), section_areas(ids, n // 2)
    occupied = ids > 0
    face = np.mean([slab_fraction(occupied, a, 0) for a in range(3)])
    interior = [slab_fraction(occupied, a, c) for a in range(3) for c in range(2 * BAND, n - 2 * BAND + 1, BAND)]
    return {
        "volume": folder,
        "sections": [len(inside), len(across)],
        "area_ks": round(ks(inside, across), 4),
        "area_ks_critical95": round(1.358 * np.sqrt((len(inside) + len(across)) / (len(inside) * len(across))), 4),
        "face_slab_fraction": round(float(face), 4),
        "inside_slab_fraction_range": [round(min(interior), 4), round(max(interior), 4)],
    }


if __name__ == "__main__":
    if len(sys.argv) < 2:
        raise SystemExit(__doc__)
    for folder in sys.argv[1:]:
        print(json.dumps(measure(folder)))
