#!/usr/bin/env bash
# Volume exemplars (Su 2008): speed and quality of `solidtex synthesize EXEMPLAR.vdb` per exemplar,
# output size and seed. Per run: analysis seconds (appearance vectors and similarity sets of every
# corrected level), synthesis seconds (upsampling, jitter, correction), wall time and peak resident
# memory of the whole command (GNU time; quality measurement included unless NO_QUALITY=1), and the
# report's 3D quality: coherence and completeness of 5^3 patches over those of a voxel-shuffled copy
# (1 = no structure, lower is better; the issue's target is coherence ratio <= 0.5) and the same
# ratio on axis slices. Exemplars that are PNG photos are first made into 64^3 solids by
# `solidtex synthesize PHOTO --size 64 --seed 1` (chen-wang), the volume exemplars the issue names.
# Usage: bench/volume_table.sh SIZES SEEDS EXEMPLAR...
#   e.g. bench/volume_table.sh 64,128 1,2,3 data/volumes/ct_stent_64.vdb data/continuous/walnut.png
set -euo pipefail
sizes=$1
seeds=$2
shift 2
bin=${SOLIDTEX_BIN:-./build/cli/solidtex}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
quality=()
[ "${NO_QUALITY:-0}" = 1 ] && quality=(--no-quality)
echo "| exemplar | size | seed | analysis s | synthesis s | wall s | MiB | coherence ratio | completeness ratio | slice coherence ratio |"
echo "|---|---|---|---|---|---|---|---|---|---|"
for exemplar in "$@"; do
  name=$(basename "$exemplar")
  if [[ "$exemplar" != *.vdb ]]; then
    "$bin" synthesize "$exemplar" -o "$out/${name%.*}_64.vdb" --size 64 --seed 1 --quiet --no-quality > /dev/null
    exemplar="$out/${name%.*}_64.vdb"
    name="${name%.*} solid 64^3"
  fi
  for size in ${sizes//,/ }; do
    for seed in ${seeds//,/ }; do
      /usr/bin/time -f "%e %M" -o "$out/time" "$bin" synthesize "$exemplar" -o "$out/v.vdb" --size "$size" \
        --seed "$seed" --report "$out/r.json" --quiet "${quality[@]}" > /dev/null
      read -r wall kib < "$out/time"
      python3 - "$out/r.json" "$name" "$size" "$seed" "$wall" "$((kib / 1024))" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
q = r.get("quality")
cells = [f"{q['coherence_ratio']:.3f}", f"{q['completeness_ratio']:.3f}", f"{q['slice_coherence_ratio']:.3f}"] if q else ["", "", ""]
synthesis = r["seconds"] - r["analysis_seconds"]
print(f"| {sys.argv[2]} | {sys.argv[3]}^3 | {sys.argv[4]} | {r['analysis_seconds']:.1f} | {synthesis:.1f} "
      f"| {float(sys.argv[5]):.1f} | {sys.argv[6]} | " + " | ".join(cells) + " |")
PY
    done
  done
done
