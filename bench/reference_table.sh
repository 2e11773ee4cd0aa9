#!/usr/bin/env bash
# A solid made from one quarter of a photo against a second photo of the material: the top-left
# SIZE x SIZE quarter of each 2*SIZE photo is the exemplar, the bottom-right quarter the reference
# (`solidtex compare --reference`). Prints a Markdown table of the solid's bidirectional similarity
# and patch distance over the reference's, on axis and oblique slices.
# Usage: bench/reference_table.sh SIZE METHODS PHOTO.png...   (METHODS: comma list; SIZE = the solid's edge
# and the quarters' side; run from the repo root after building)
set -euo pipefail
size=$1
IFS=, read -r -a methods <<< "$2"
shift 2
bin=${SOLIDTEX_BIN:-./build/cli/solidtex}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
echo "| photo | method | bidirectional: reference | axis ratio | oblique ratio | patch distance: reference | axis ratio | oblique ratio | synthesis s |"
echo "|---|---|---|---|---|---|---|---|---|"
for photo in "$@"; do
  name=$(basename "$photo" .png)
  oiiotool "$photo" --cut "${size}x${size}+0+0" -o "$out/exemplar.png"
  oiiotool "$photo" --cut "${size}x${size}+${size}+${size}" --origin +0+0 -o "$out/reference.png"
  for method in "${methods[@]}"; do
    "$bin" synthesize "$out/exemplar.png" -o "$out/v.vdb" --size "$size" --method "$method" \
      --report "$out/s.json" --quiet > /dev/null
    "$bin" compare "$out/exemplar.png" "$out/v.vdb" --reference "$out/reference.png" --report "$out/c.json" > /dev/null
    python3 - "$out/c.json" "$out/s.json" "$name" "$method" <<'PY'
import json, sys
q = json.load(open(sys.argv[1]))["quality"]
s = json.load(open(sys.argv[2]))
ref, ratio = q["reference"], q["ratio_to_reference"]
print(f"| {sys.argv[3]} | {sys.argv[4]} | {ref['bidirectional_similarity']:.4f} "
      f"| {ratio['axis']['bidirectional_similarity']:.3f} | {ratio['oblique']['bidirectional_similarity']:.3f} "
      f"| {ref['patch_distance']:.4f} | {ratio['axis']['patch_distance']:.3f} | {ratio['oblique']['patch_distance']:.3f} "
      f"| {s['seconds']:.1f} |")
PY
  done
done
