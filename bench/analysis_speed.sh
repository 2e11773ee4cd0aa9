#!/usr/bin/env bash
# Analysis of large exemplars: exact against approximate similarity sets, same exemplar, size, seeds
# and machine. Per run: the analysis seconds of all levels (neighbourhoods, PCA, similarity sets) and
# of the finest level, the synthesis seconds, wall time and peak resident memory of the whole command
# (GNU time; quality measurement included), and the report's quality (bidirectional similarity and
# patch distance, axis / oblique; lower is better). Prints a Markdown table; with SEARCHES=approximate
# only the approximate search runs (the exact one takes minutes per 512^2 exemplar).
# Usage: bench/analysis_speed.sh SIZE SEEDS EXEMPLAR...   e.g. bench/analysis_speed.sh 64 1,2,3 data/continuous/brick.png
set -euo pipefail
size=$1
seeds=$2
shift 2
bin=${SOLIDTEX_BIN:-./build/cli/solidtex}
searches=${SEARCHES:-exact,approximate}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
echo "| exemplar | search | seed | analysis s | finest level s | sets | synthesis s | wall s | MiB | bidirectional axis / oblique | patch distance axis / oblique |"
echo "|---|---|---|---|---|---|---|---|---|---|---|"
for exemplar in "$@"; do
  name=$(basename "$exemplar")
  for search in ${searches//,/ }; do
    for seed in ${seeds//,/ }; do
      /usr/bin/time -f "%e %M" -o "$out/time" "$bin" synthesize "$exemplar" -o "$out/v.vdb" --size "$size" \
        --seed "$seed" --similarity-search "$search" --report "$out/r.json" --quiet > /dev/null
      read -r wall kib < "$out/time"
      python3 - "$out/r.json" "$name" "$search" "$seed" "$wall" "$((kib / 1024))" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
levels = r["level_reports"]
sets = levels[-1].get("similarity_sets", {})
kind = sets.get("search", "-") + (f" {sets['lists']} cells, {sets['probes']} probes" if "lists" in sets else "")
q = r["quality"]
pair = lambda m: f"{q['axis'][m]:.4f} / {q['oblique'][m]:.4f}"
print(f"| {sys.argv[2]} | {sys.argv[3]} | {sys.argv[4]} | {sum(l['analysis_seconds'] for l in levels):.1f} | "
      f"{levels[-1]['analysis_seconds']:.1f} | {kind} | {r['seconds']:.1f} | {sys.argv[5]} | {sys.argv[6]} | "
      f"{pair('bidirectional_similarity')} | {pair('patch_distance')} |")
PY
    done
  done
done
