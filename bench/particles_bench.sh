#!/usr/bin/env bash
# Wall time and peak memory of `solidtex particles` per exemplar and placer, as a Markdown table.
# Usage: bench/particles_bench.sh [SIZE] [PLACERS...]   (run from the repo root after building)
set -euo pipefail
size=${1:-256}
shift || true
placers=("$@")
[ ${#placers[@]} -eq 0 ] && placers=(discrete edt brute delaunay)
bin=${SOLIDTEX_BIN:-./build/cli/solidtex}
out=$(mktemp -d)
echo "| exemplar | placer | size | wall s | peak MiB | particles | volume fraction | photo fraction |"
echo "|---|---|---|---|---|---|---|---|"
for photo in gravel smarties; do
  for placer in "${placers[@]}"; do
    /usr/bin/time -f '%e %M' -o "$out/time" "$bin" particles "data/particles/$photo.png" -o "$out/v.vdb" \
      --size "$size" --placer "$placer" --seed 1 --quiet --report "$out/r.json" > /dev/null
    read -r wall kib < "$out/time"
    python3 - "$out/r.json" "$photo" "$placer" "$size" "$wall" "$kib" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
v = r["volume"]
print(f"| {sys.argv[2]} | {sys.argv[3]} | {sys.argv[4]}^3 | {float(sys.argv[5]):.1f} | {int(sys.argv[6]) / 1024:.0f} "
      f"| {v['particles']} | {v['volume_fraction']:.3f} | {v['area_fraction']:.3f} |")
PY
  done
done
rm -rf "$out"
