#!/usr/bin/env bash
# Volume exemplars (Su 2008) with and without --periodic: the seam where two copies of the output meet.
# Per run: wall time and the report's synthesis seconds, and per plane between neighbouring layers the
# mean squared difference of neighbouring voxels' values (colour channels summed, linear; density for
# a density exemplar): the interior planes' mean and sd over all three axes, and the wrap plane of
# each axis (layer N-1 against layer 0, where copies meet). Photos are first made into 64^3 chen-wang
# solids, as bench/volume_table.sh does.
# Usage: bench/periodic_seams.sh SIZE SEED EXEMPLAR...
#   e.g. bench/periodic_seams.sh 64 1 data/volumes/ct_stent_64.vdb data/continuous/burlap.png
set -euo pipefail
size=$1
seed=$2
shift 2
bin=${SOLIDTEX_BIN:-./build/cli/solidtex}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
echo "| exemplar | periodic | wall s | synthesis s | interior planes: mean (sd) | wrap planes x, y, z | wrap / interior mean |"
echo "|---|---|---|---|---|---|---|"
for exemplar in "$@"; do
  name=$(basename "$exemplar")
  if [[ "$exemplar" != *.vdb ]]; then
    "$bin" synthesize "$exemplar" -o "$out/${name%.*}_64.vdb" --size 64 --seed 1 --quiet --no-quality > /dev/null
    exemplar="$out/${name%.*}_64.vdb"
    name="${name%.*} solid 64^3"
  fi
  for periodic in no yes; do
    flag=()
    [ "$periodic" = yes ] && flag=(--periodic)
    rm -rf "$out/npy"
    /usr/bin/time -f "%e" -o "$out/time" "$bin" synthesize "$exemplar" -o "$out/v.vdb" --size "$size" \
      --seed "$seed" --report "$out/r.json" --npy "$out/npy" --quiet --no-quality "${flag[@]}" > /dev/null
    /usr/bin/python3 - "$out" "$name" "$periodic" "$(cat "$out/time")" <<'PY'
import json, os, sys
import numpy as np
folder, name, periodic, wall = sys.argv[1:5]
path = os.path.join(folder, "npy", "color.npy")
if not os.path.exists(path):
    path = os.path.join(folder, "npy", "density.npy")
v = np.load(path).astype(np.float64)  # (Z, Y, X[, C])
if v.ndim == 3:
    v = v[..., None]
interior, wrap = [], []
for axis in (2, 1, 0):  # x, y, z
    # plane between layer l and l + 1 (the last: layer N-1 against layer 0, where copies meet)
    step = (np.roll(v, -1, axis=axis) - v) ** 2
    planes = step.sum(axis=3).mean(axis=tuple(a for a in range(3) if a != axis))
    interior.extend(planes[:-1])
    wrap.append(planes[-1])
m, sd = float(np.mean(interior)), float(np.std(interior, ddof=1))
r = json.load(open(os.path.join(folder, "r.json")))
synthesis = r["seconds"] - r["analysis_seconds"]
print(f"| {name} | {periodic} | {float(wall):.1f} | {synthesis:.1f} | {m:.5f} ({sd:.5f}) | "
      + ", ".join(f"{w:.5f}" for w in wrap) + " | " + ", ".join(f"{w / m:.2f}" for w in wrap) + " |")
PY
  done
done
