#!/usr/bin/env bash
# Angular and flattened particles (the sweep's polytope, superellipsoid and flattened truths, truth
# seeds 1 and 2; default and spheres as controls): how the photo's particles read against the
# truth's sections (mean solidity and roundness, both at the solid's resolution), the smoothing the
# fit chose, and the solid's section solidity and roundness KS against the truth's sections.
# Usage: bench/hard_shapes_table.sh [SIZE]   (run from the repo root after building)
# Environment: SOLIDTEX_BIN  the solidtex binary (default ./build/cli/solidtex)
set -euo pipefail
size=${1:-128}
bin=${SOLIDTEX_BIN:-./build/cli/solidtex}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

# name|truth options, as bench/truth_sweep.sh spells them
truths=(
  "default|"
  "spheres|--elongation 1"
  "flattened 0.5|--flatten 0.5"
  "flattened 0.45 spheres|--elongation 1 --flatten 0.45"
  "superellipsoid p4|--shape superellipsoid"
  "superellipsoid p6 flat 0.6|--shape superellipsoid --exponent 6 --flatten 0.6 --large-radius 11"
  "unimodal superellipsoid r10|--shape superellipsoid --large-share 0 --small-radius 10"
  "polytope|--shape polytope --elongation 1"
  "polytope elongated|--shape polytope --large-radius 11"
  "polytope flat 0.6, 0.3|--shape polytope --elongation 1 --flatten 0.6 --fraction 0.3"
  "10:1 polytope|--shape polytope --small-radius 5 --large-radius 10.8"
)

cells() {
  python3 - "$1" "$2" <<'PY'
import json, sys
r, p = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
s, t = r["shape_and_arrangement"]["photo"], r["truth"]
print(f"{s['solidity_mean']:.3f} / {s['roundness_mean']:.3f} | "
      f"{t['truth_sections']['solidity_mean']:.3f} / {t['truth_sections']['roundness_mean']:.3f} | "
      f"{p['smoothing']['radius']:.2f} | {t['solidity_ks']:.3f} | {t['roundness_ks']:.3f}", end="")
PY
}

echo "Solids ${size}^3, solid seed 1, default options."
echo
echo "| truth | seed | photo solidity / roundness | truth sections' | smoothing | solidity KS | roundness KS |"
echo "|---|---|---|---|---|---|---|"
for truth in "${truths[@]}"; do
  name=${truth%%|*}
  read -r -a options <<< "${truth#*|}"
  for seed in 1 2; do
    "$bin" truth -o "$out/t" --seed "$seed" "${options[@]}" > /dev/null
    "$bin" particles "$out/t/photo.png" -o "$out/solid.vdb" --size "$size" --report "$out/particles.json" \
      --quiet > /dev/null
    "$bin" compare "$out/t/photo.png" "$out/solid.vdb" --truth "$out/t/truth.vdb" --measures none \
      --report "$out/compare.json" > /dev/null
    echo "| $name | $seed | $(cells "$out/compare.json" "$out/particles.json") |"
    rm -rf "$out/t"
  done
done
