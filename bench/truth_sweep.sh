#!/usr/bin/env bash
# Section sizing against the paper's box sizing on photos cut from known 3D truths (`solidtex truth`):
# section-area KS against the photo and particle-volume W1/mean against the truth, as a Markdown table.
# Usage: bench/truth_sweep.sh [SIZE] [TRUTH SEEDS...]   (run from the repo root after building)
set -euo pipefail
size=${1:-128}
shift || true
seeds=("$@")
[ ${#seeds[@]} -eq 0 ] && seeds=(1 2)
bin=${SOLIDTEX_BIN:-./build/cli/solidtex}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
truths=("default|" "spheres|--elongation 1" "elongated|--elongation 1.5" "crowded|--fraction 0.3"
        "half large|--large-share 0.5 --spread 0.3" "wide sizes|--small-radius 5 --large-radius 16")
echo "| truth | seed | photo particles | sections KS | sections volume W1/mean | bbox KS | bbox volume W1/mean | volume fraction (sections) | photo fraction |"
echo "|---|---|---|---|---|---|---|---|---|"
for truth in "${truths[@]}"; do
  name=${truth%%|*}
  read -r -a options <<< "${truth#*|}"
  for seed in "${seeds[@]}"; do
    "$bin" truth -o "$out/t" --seed "$seed" "${options[@]}" > /dev/null
    for sizing in sections bbox; do
      "$bin" particles "$out/t/photo.png" -o "$out/$sizing.vdb" --size "$size" --sizing "$sizing" --quiet > /dev/null
      "$bin" compare "$out/t/photo.png" "$out/$sizing.vdb" --truth "$out/t/truth.vdb" --report "$out/$sizing.json" > /dev/null
    done
    python3 - "$out" "$name" "$seed" <<'PY'
import json, sys
s, b = (json.load(open(f"{sys.argv[1]}/{k}.json")) for k in ("sections", "bbox"))
w = lambda r: r["truth"]["volume_wasserstein1_over_mean"]
print(f"| {sys.argv[2]} | {sys.argv[3]} | {s['photo_particles']} | {s['ks']:.3f} | {w(s):.3f} | {b['ks']:.3f} | {w(b):.3f} "
      f"| {s['volume_fraction']:.3f} | {s['area_fraction']:.3f} |")
PY
  done
done
