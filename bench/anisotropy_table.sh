#!/usr/bin/env bash
# Anisotropic truths (aligned particles, `truth --anisotropy`), each plane of the solid against that
# plane's photo (`compare --plane`): the section-area KS, the aspect-ratio KS and the orientation KS
# (Kuiper) with the 5 % critical KS of the sample sizes, and the volume W1/mean against the truth.
# "ideal" is a second truth of the same settings (seed + 1000) against the first one's photos: what
# a perfect reconstruction would score. "xy photo" is a solid made from the xy photo alone, "three
# photos" one made from all three (`particles --photo-xz --photo-yz`).
# Usage: bench/anisotropy_table.sh [SIZE]   (default 128; run from the repo root after building)
# Environment: SOLIDTEX_BIN  the solidtex binary (default ./build/cli/solidtex)
set -euo pipefail
size=${1:-128}
bin=${SOLIDTEX_BIN:-./build/cli/solidtex}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

# name|seed|truth options
truths=(
  "3 : 1.5 : 1|1|--anisotropy 3 1.5 1"
  "3 : 1.5 : 1|2|--anisotropy 3 1.5 1"
  "needles 1 : 1 : 2.5, polytopes|1|--anisotropy 1 1 2.5 --shape polytope --elongation 1"
  "plates 2 : 2 : 1, half large|3|--anisotropy 2 2 1 --large-share 0.5"
)
common="--dims 256 256 256 --small-radius 4 --large-radius 7.5"

# One row: every plane's KS triple for one solid (or truth) against the photos of truth folder $2.
row() {
  local label=$1 photos=$2 solid=$3 truth=$4
  for plane in xy xz yz; do
    local photo=$photos/photo.png
    [ "$plane" = xy ] || photo=$photos/photo_$plane.png
    "$bin" compare "$photo" "$solid" --plane "$plane" --measures none ${truth:+--truth "$truth"} \
      --report "$out/$plane.json" > /dev/null
  done
  python3 - "$out" "$label" <<'PY'
import json, sys
d, label = sys.argv[1:3]
cells = []
volume = ""
for plane in ("xy", "xz", "yz"):
    c = json.load(open(f"{d}/{plane}.json"))
    s = c["shape_and_arrangement"]
    cells.append(f"{c['ks']:.3f} / {s['aspect_ks']:.3f} / {s['orientation_ks']:.3f} ({s['shape_ks_critical_95']:.2f})")
    if "truth" in c:
        volume = f"{c['truth']['volume_wasserstein1_over_mean']:.3f}"
print(f"| {label} | " + " | ".join(cells) + f" | {volume or '-'} |")
PY
}

echo "| truth, solid | xy: area / aspect / orientation KS (critical) | xz | yz | volume W1/mean |"
echo "|---|---|---|---|---|"
for entry in "${truths[@]}"; do
  IFS='|' read -r name seed options <<< "$entry"
  # shellcheck disable=SC2086
  "$bin" truth -o "$out/t" --seed "$seed" $common $options > /dev/null
  # shellcheck disable=SC2086
  "$bin" truth -o "$out/ideal" --seed $((seed + 1000)) $common $options > /dev/null
  row "$name, seed $seed: ideal" "$out/t" "$out/ideal/truth.vdb" ""
  "$bin" particles "$out/t/photo.png" -o "$out/s.vdb" --size "$size" --seed 1 --quiet > /dev/null
  row "$name, seed $seed: xy photo" "$out/t" "$out/s.vdb" "$out/t/truth.vdb"
  "$bin" particles "$out/t/photo.png" --photo-xz "$out/t/photo_xz.png" --photo-yz "$out/t/photo_yz.png" \
    -o "$out/s.vdb" --size "$size" --seed 1 --quiet > /dev/null
  row "$name, seed $seed: three photos" "$out/t" "$out/s.vdb" "$out/t/truth.vdb"
done
