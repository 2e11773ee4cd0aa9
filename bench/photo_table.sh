#!/usr/bin/env bash
# The bundled particle photos against solids made from them, default options beside the paper's
# configuration, as a Markdown table: section-area KS and W1/mean, solidity and roundness KS,
# window spread and nearest-neighbour ratios (solid over photo) and the fractions.
# Usage: bench/photo_table.sh [SIZE] [SEEDS...]   (run from the repo root after building)
set -euo pipefail
size=${1:-128}
shift || true
seeds=("$@")
[ ${#seeds[@]} -eq 0 ] && seeds=(1)
bin=${SOLIDTEX_BIN:-./build/cli/solidtex}
paper=(--sizing bbox --arrangement best-fit --smoothing 0 --body-form 0 --boundary walls)
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
echo "| photo | photo particles | options | seed | KS (5 % critical) | W1/mean | solidity KS | roundness KS (5 % critical) | window spread ratio | neighbour distance ratio | volume fraction (photo) |"
echo "|---|---|---|---|---|---|---|---|---|---|---|"
for photo in coins smarties gravel leopard; do
  for seed in "${seeds[@]}"; do
    for options in default paper; do
      flags=()
      [ "$options" = paper ] && flags=("${paper[@]}")
      "$bin" particles "data/particles/$photo.png" -o "$out/v.vdb" --size "$size" --seed "$seed" "${flags[@]}" \
        --quiet > /dev/null
      "$bin" compare "data/particles/$photo.png" "$out/v.vdb" --report "$out/c.json" > /dev/null
      python3 - "$out/c.json" "$photo" "$options" "$seed" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
s = r["shape_and_arrangement"]
print(f"| {sys.argv[2]} | {r['photo_particles']} | {sys.argv[3]} | {sys.argv[4]} | {r['ks']:.3f} ({r['ks_critical_95']:.3f}) "
      f"| {r['wasserstein1_over_mean']:.3f} | {s['solidity_ks']:.3f} "
      f"| {s['roundness_ks']:.3f} ({s['shape_ks_critical_95']:.3f}) | {s['window_spread_ratio']:.2f} "
      f"| {s['neighbour_distance_ratio']:.2f} | {r['volume_fraction']:.3f} ({r['area_fraction']:.3f}) |")
PY
    done
  done
done
