"""The materials descriptors against PoreSpy's on the same arrays (docs/validation.md).

usage: PYTHONPATH=build/python:PORESPY/stubs:PORESPY/src python3 bench/descriptors_vs_porespy.py [N]
with PORESPY = ../shared/peers/porespy (its run.sh lists the Debian packages it needs). Fields: a
random two-phase field of N^3 (smoothed noise) and the particle phase of a gravel solid of N^3.
Prints one JSON object per field and measure: the largest differences and what they are of.
"""
import json
import sys
import time

import numpy as np
import porespy as ps
from scipy import ndimage

import solidtex

ps.settings.tqdm["disable"] = True

N = int(sys.argv[1]) if len(sys.argv) > 1 else 96


def fields():
    rng = np.random.default_rng(1)
    yield "blobs", ndimage.gaussian_filter(rng.normal(size=(N, N, N)), 2.5, mode="wrap") > 0.05
    solid = solidtex.particles("data/particles/gravel.png", size=N, seed=1)
    yield "gravel", solid["particle_id"] > 0


def timed(f):
    start = time.perf_counter()
    value = f()
    return value, time.perf_counter() - start


def two_point(name, im):
    ours, t_ours = timed(lambda: solidtex.two_point_correlation(im, periodic=True, max_distance=N // 2 - 1))
    theirs, t_theirs = timed(lambda: ps.metrics.two_point_correlation(im, bins=np.arange(0, N // 2 + 1)))
    # PoreSpy's bin at edge r holds separations in (r - 1, r]; ours rounds them to r. Compare at
    # whole r on the axes, where both hold the same separations, through PoreSpy's own
    # autocorrelation image, and radially where the bins differ.
    radial_ps = np.asarray(theirs.probability_scaled)
    edges = np.asarray(theirs.bin_edges)[:-1]
    mid = [r for r in range(2, N // 2 - 2)]
    ours_mid = np.array([0.5 * (ours["radial"][r - 1] + ours["radial"][r]) for r in mid])
    ps_at = np.interp(mid, edges, radial_ps)
    return {"field": name, "measure": "two_point_correlation (periodic, radial)",
            "largest_difference": float(np.max(np.abs(ours_mid - ps_at))),
            "phase_fraction": float(im.mean()), "seconds": {"solidtex": t_ours, "porespy": t_theirs}}


def chords(name, im):
    ours, t_ours = timed(lambda: solidtex.chord_lengths(im))
    out = {"field": name, "measure": "chord lengths along numpy axis 0 (z)"}
    theirs, t_theirs = timed(lambda: ps.filters.apply_chords(im, spacing=0, axis=0, trim_edges=True))
    sizes = ndimage.sum(theirs > 0, theirs, index=np.arange(1, theirs.max() + 1)).astype(int)
    sizes = np.bincount(sizes[sizes > 0])  # clear_border leaves the labels of the chords it removed empty
    counts = ours["z"]
    # PoreSpy's clear_border also drops every chord on a line in the field's faces: ours on the
    # lines inside them counts the same chords.
    inner = solidtex.chord_lengths(np.ascontiguousarray(im[:, 1:-1, 1:-1]))["z"]
    out["same_as_porespy_on_inner_lines"] = bool(np.array_equal(np.trim_zeros(inner, "b"), np.trim_zeros(sizes, "b")))
    out["mean_chord"] = {"solidtex": float((np.arange(len(counts)) * counts).sum() / counts.sum()),
                         "porespy": float((np.arange(len(sizes)) * sizes).sum() / sizes.sum())}
    out["chords"] = {"solidtex": int(counts.sum()), "porespy": int(sizes.sum())}
    out["seconds"] = {"solidtex": t_ours, "porespy": t_theirs}
    return out


def lineal(name, im):
    R = 20
    ours, t_ours = timed(lambda: solidtex.lineal_path(im, R))
    # L(r) from PoreSpy's forward linear distance: a voxel starts a segment of r voxels' length
    # in the phase when its distance to the next voxel outside, along the axis, exceeds r.
    dist, t_theirs = timed(lambda: ps.filters.distance_transform_lin(im, axis=2, mode="forward"))
    theirs, definition = [], []
    for r in range(R + 1):
        fits = dist[:, :, : N - r]  # segments that fit in the field, as ours counts them
        theirs.append(float((fits > r).mean()))
        inside = np.ones(im[:, :, : N - r].shape, bool)
        for step in range(r + 1):
            inside &= im[:, :, step : N - r + step]
        definition.append(float(inside.mean()))
    return {"field": name, "measure": "lineal path along x, r = 0..20",
            "largest_difference": float(np.max(np.abs(np.array(theirs) - ours["x"]))),
            "largest_difference_from_definition": float(np.max(np.abs(np.array(definition) - ours["x"]))),
            "seconds": {"solidtex": t_ours, "porespy": t_theirs}}


def thickness(name, im):
    ours, t_ours = timed(lambda: solidtex.local_thickness(im, sizes=25))
    # The same radii: PoreSpy's own, 10**log10 of its float32 distances, can round the largest
    # above the deepest voxel's distance and so lose the largest sphere.
    theirs, t_theirs = timed(lambda: ps.filters.local_thickness(im, sizes=ours["radii"], mode="hybrid"))
    differ = np.abs(ours["thickness"] - theirs) > 1e-4
    return {"field": name, "measure": "local thickness, 25 sizes",
            "voxels_that_differ": int(differ.sum()), "voxels": int(im.sum()),
            "mean_radius": {"solidtex": float(ours["thickness"][im].mean()), "porespy": float(theirs[im].mean())},
            "seconds": {"solidtex": t_ours, "porespy": t_theirs}}


for name, im in fields():
    for measure in (two_point, chords, lineal, thickness):
        print(json.dumps(measure(name, im)), flush=True)
