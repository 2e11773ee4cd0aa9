#!/usr/bin/env bash
# Continuous solids against their exemplars, as a Markdown table: coherence, completeness, their sum
# (bidirectional similarity) and the patch distance on axis and oblique slices, per method.
# Usage: bench/continuous_table.sh SIZE METHODS EXEMPLAR.png...   (METHODS: comma list, e.g. chen-wang,kopf;
# run from the repo root after building)
set -euo pipefail
size=$1
IFS=, read -r -a methods <<< "$2"
shift 2
bin=${SOLIDTEX_BIN:-./build/cli/solidtex}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
echo "| exemplar | method | coherence axis / oblique | completeness axis / oblique | bidirectional axis / oblique | patch distance axis / oblique | colour histogram distance | synthesis s |"
echo "|---|---|---|---|---|---|---|---|"
for exemplar in "$@"; do
  for method in "${methods[@]}"; do
    "$bin" synthesize "$exemplar" -o "$out/v.vdb" --size "$size" --method "$method" --report "$out/r.json" \
      --quiet > /dev/null
    python3 - "$out/r.json" "$(basename "$exemplar" .png)" "$method" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
q = r["quality"]
a, o = q["axis"], q["oblique"]
pair = lambda key: f"{a[key]:.4f} / {o[key]:.4f}"
print(f"| {sys.argv[2]} | {sys.argv[3]} | {pair('coherence')} | {pair('completeness')} "
      f"| {pair('bidirectional_similarity')} | {pair('patch_distance')} | {q['color_histogram_distance']:.3f} "
      f"| {r['seconds']:.1f} |")
PY
  done
done
