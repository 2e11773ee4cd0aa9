#!/usr/bin/env bash
# Particle solids placed in bricks against the same solids placed whole: for each photo and seed,
# the section statistics `compare` gives (area KS, solidity KS, window spread ratio, neighbour
# distance ratio, volume fraction) and the seam measure (window spread of the axis planes within 4
# voxels of a brick face against the rest, measured on the unbricked solids too, as the reference
# level). A Markdown table, one row per photo, mode and seed.
# Usage: bench/particle_bricks.sh [SIZE [EDGE]]   (default 128 64; run from the repo root after building)
#   PHOTOS="gravel smarties:72"   photos in data/particles, each with its own edge after a colon
#   (at least twice its particles' reach)     SEEDS="1 2 3 4"
set -euo pipefail
size=${1:-128}
default_edge=${2:-64}
bin=${SOLIDTEX_BIN:-$PWD/build/cli/solidtex}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
echo "| photo | placed | seed | seconds | volume fraction | area KS | solidity KS | window spread ratio | neighbour distance ratio | seam: face / other window spread | face / other fraction |"
echo "|---|---|---|---|---|---|---|---|---|---|---|"
for entry in ${PHOTOS:-gravel smarties:72}; do
  photo=${entry%%:*}
  edge=$default_edge
  [ "$entry" != "$photo" ] && edge=${entry#*:}
  for seed in ${SEEDS:-1 2 3 4}; do
    for mode in whole bricks; do
      extra=()
      [ "$mode" = bricks ] && extra=(--bricks "$edge")
      start=$(date +%s.%N)
      "$bin" particles "data/particles/$photo.png" -o "$out/v.vdb" --size "$size" --seed "$seed" --quiet "${extra[@]}" > /dev/null
      end=$(date +%s.%N)
      "$bin" compare "data/particles/$photo.png" "$out/v.vdb" --bricks "$edge" --report "$out/c.json" > /dev/null
      /usr/bin/python3 - "$out/c.json" "$photo" "$mode" "$seed" "$start" "$end" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
photo, mode, seed, start, end = sys.argv[2], sys.argv[3], sys.argv[4], float(sys.argv[5]), float(sys.argv[6])
s, a = r["brick_seams"], r["shape_and_arrangement"]
print(f"| {photo} | {mode} | {seed} | {end - start:.1f} | {r['volume_fraction']:.3f} (photo {r['area_fraction']:.3f}) | "
      f"{r['ks']:.3f} | {a['solidity_ks']:.3f} | {a['window_spread_ratio']:.2f} | {a['neighbour_distance_ratio']:.2f} | "
      f"{s['face_window_spread']:.3f} / {s['other_window_spread']:.3f} | {s['face_fraction']:.3f} / {s['other_fraction']:.3f} |")
PY
    done
  done
done
