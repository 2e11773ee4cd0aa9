#!/usr/bin/env bash
# 3D particle sizes against known truths (docs/validation.md, "3D sizes"): for each truth of the
# family, two solids (seeds 1, 2) of SIZE^3 and their `compare --truth`: the volume W1/mean of the
# placed particles (whole, centre in the block) and of the whole particles in the block
# (Miles-Lantuejoul), and where the truth's volume CDF lies against the sizing's band (share of the
# band's 32 volumes it is inside, largest excursion outside, and "yes" where that excursion is
# within the truth's own 90 % DKW bound). One Markdown row per truth.
# Usage: bench/size_band_table.sh [SIZE]   (default 128; run from the repo root after building)
set -euo pipefail
size=${1:-128}
bin=${SOLIDTEX_BIN:-$PWD/build/cli/solidtex}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

row() {
  local name=$1 seed=$2 dir="$out/row"
  shift 2
  rm -rf "$dir"
  "$bin" truth -o "$dir/t" --seed "$seed" "$@" > /dev/null
  for s in 1 2; do
    "$bin" particles "$dir/t/photo.png" -o "$dir/s$s.vdb" --size "$size" --seed "$s" --quiet > /dev/null
    "$bin" compare "$dir/t/photo.png" "$dir/s$s.vdb" --truth "$dir/t/truth.vdb" --measures none \
      --report "$dir/c$s.json" > /dev/null
  done
  python3 - "$dir" "$name" "$seed" <<'PY'
import json, sys
d, name, seed = sys.argv[1:4]
cells = []
for s in (1, 2):
    c = json.load(open(f"{d}/c{s}.json"))
    t, band = c["truth"], c["truth"]["volume_cdf_band"]
    cells += [f"{t['volume_wasserstein1_over_mean']:.3f} / {t['whole_in_block']['volume_wasserstein1_over_mean']:.3f}",
              f"{band['truth_inside_share']:.2f} ({band['largest_excursion']:.3f} vs {band['truth_dkw_bound_90']:.3f}: "
              + ("yes" if band["meets_truth_band_everywhere"] else "no") + ")"]
print(f"| {name} | {seed} | {c['photo_particles']} | " + " | ".join(cells) + " |")
PY
}

echo "| truth | truth seed | photo particles | W1/mean placed / in block, solid seed 1 | band: inside share (largest excursion vs the truth's bound: met), seed 1 | W1/mean placed / in block, seed 2 | band, seed 2 |"
echo "|---|---|---|---|---|---|---|"
row "default" 1
row "default" 2
row "spheres" 1 --elongation 1
row "flattened 0.45 spheres" 2 --elongation 1 --flatten 0.45
row "superellipsoid p4" 1 --shape superellipsoid
row "polytope" 1 --shape polytope --elongation 1
row "unimodal" 1 --large-share 0
row "10:1 volume" 1 --small-radius 5 --large-radius 10.8
row "10:1 polytope" 1 --shape polytope --small-radius 5 --large-radius 10.8
row "fraction 0.1" 2 --fraction 0.1
row "fraction 0.3" 2 --fraction 0.3
row "few: 320x320" 2 --dims 320 320 72
row "many small" 1 --dims 560 560 72 --small-radius 5 --large-radius 9
row "noise 0.06" 1 --noise 0.06
row "blur 1" 1 --blur 1
row "blur 2, noise 0.05" 1 --blur 2 --noise 0.05
