#!/usr/bin/env bash
# Blurred, noisy photos of known truths: the outlines drawn half-way up their edges (`--outlines
# auto`, the default, which takes half-maximum on these) against the watershed's, as the solid's
# sections score against the truth's: section-area KS against the photo, particle-volume W1/mean,
# section solidity and roundness KS against the truth's sections; and the photo's measured outline
# blur. The sweep's blur rows (truth seeds 1 and 2) and five settings the method was not tuned on.
# Usage: bench/blurred_photos_table.sh [SIZE]   (run from the repo root after building)
set -euo pipefail
size=${1:-128}
bin=${SOLIDTEX_BIN:-./build/cli/solidtex}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

# name|truth options (with the seed)
truths=(
  "sharp (sweep default)|--seed 1"
  "blur 1|--blur 1 --seed 1"
  "blur 1|--blur 1 --seed 2"
  "blur 2, noise 0.05|--blur 2 --noise 0.05 --seed 1"
  "blur 2, noise 0.05|--blur 2 --noise 0.05 --seed 2"
  "blur 1.5, noise 0.05|--blur 1.5 --noise 0.05 --seed 11"
  "blur 1.8, noise 0.08, superellipsoid|--blur 1.8 --noise 0.08 --shape superellipsoid --seed 8"
  "blur 2, noise 0.05, 10:1 volume|--blur 2 --noise 0.05 --small-radius 5 --large-radius 10.8 --seed 9"
  "blur 2.5, noise 0.03|--blur 2.5 --noise 0.03 --seed 7"
  "blur 3, prolate 1.5|--blur 3 --elongation 1.5 --seed 10"
)

cells() {
  python3 - "$1" "$2" <<'PY'
import json, sys
r, p = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))["photo"]
t = r["truth"]
print(f"{p['outlines']} | {r['ks']:.3f} | {t['volume_wasserstein1_over_mean']:.3f} | "
      f"{t['solidity_ks']:.3f} | {t['roundness_ks']:.3f}", end="")
PY
}

echo "Solids ${size}^3, seed 1. Left: default (--outlines auto); right: --outlines watershed."
echo
echo "| truth | seed | outline blur (px) | outlines | KS | volume W1/mean | solidity KS | roundness KS |" \
     "outlines | KS | volume W1/mean | solidity KS | roundness KS |"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|"
for truth in "${truths[@]}"; do
  name=${truth%%|*}
  read -r -a options <<< "${truth#*|}"
  "$bin" truth -o "$out/t" "${options[@]}" > /dev/null
  row="| $name | ${options[-1]}"
  for outlines in auto watershed; do
    "$bin" particles "$out/t/photo.png" -o "$out/$outlines.vdb" --size "$size" --outlines "$outlines" \
      --report "$out/$outlines.particles.json" --quiet > /dev/null
    "$bin" compare "$out/t/photo.png" "$out/$outlines.vdb" --truth "$out/t/truth.vdb" --outlines "$outlines" \
      --measures none --report "$out/$outlines.json" > /dev/null
    if [ "$outlines" = auto ]; then
      row+=" | $(python3 -c 'import json, sys; print("%.2f" % json.load(open(sys.argv[1]))["photo"]["outline_blur"])' \
        "$out/auto.particles.json")"
    fi
    row+=" | $(cells "$out/$outlines.json" "$out/$outlines.particles.json")"
  done
  echo "$row |"
  rm -rf "$out/t"
done
