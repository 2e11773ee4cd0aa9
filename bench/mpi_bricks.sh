#!/usr/bin/env bash
# Strong scaling of volume-exemplar synthesis in bricks under mpirun: the stent CT exemplar at
# SIZE^3, unbricked, then in bricks of each EDGES as one process started alone (every core as a
# thread) and on 1 and 2 processes under mpirun (which binds each to one core by default); a
# Markdown table with the per-brick figures the 2048^3 model in docs/performance.md is built from.
# Usage: bench/mpi_bricks.sh [SIZE]   (default 256; run from the repo root after building)
#   EDGES="128"            brick edges
#   OPTIONS="--corrections 1"  synthesis options of every run (each brick is widened by 16 voxels per
#                          correction pass: with the default 4, bricks of 128 repeat 8 times the work)
set -euo pipefail
size=${1:-256}
edges=${EDGES:-128}
# shellcheck disable=SC2206
options=(${OPTIONS---corrections 1})
bin=${SOLIDTEX_BIN:-$PWD/build/cli/solidtex}
mpirun=(mpirun --allow-run-as-root --oversubscribe --quiet)
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
common=(synthesize data/volumes/ct_stent_64.vdb --size "$size" --seed 1 --quiet --no-quality "${options[@]}")

row() {  # label, then the command
  local label=$1
  shift
  /usr/bin/time -f '%e %M' -o "$out/time" "$@" -o "$out/v.vdb" --report "$out/r.json" > /dev/null
  read -r wall kib < "$out/time"
  python3 - "$out/r.json" "$label" "$wall" "$kib" "$size" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
label, wall, kib, size = sys.argv[2], float(sys.argv[3]), int(sys.argv[4]), int(sys.argv[5])
b = r.get("bricks")
if not b:
    print(f"| {label} | 1 | 1 | {wall:.1f} | {r['analysis_seconds']:.1f} | - | - | - | - | {kib / 1024:.0f} |")
    sys.exit()
analysis = max(p["analysis_seconds"] for p in b["per_process"])
per_brick = max((p["seconds"] - p["analysis_seconds"]) / p["bricks"] for p in b["per_process"] if p["bricks"])
print(f"| {label} | {b['count']} | {b['processes']} | {wall:.1f} | {analysis:.1f} | {per_brick:.1f} "
      f"| {b['bytes_exchanged'] / 2**20:.1f} | {b['load_imbalance']:.2f} "
      f"| {b['gather_seconds']:.1f} / {b['join_seconds']:.1f} / {b['write_seconds']:.1f} "
      f"| {kib / 1024:.0f} |")
PY
}

echo "| run | bricks | processes | wall s | analysis s | s per brick | MiB sent | imbalance | rank 0: gather / join / write s | peak MiB |"
echo "|---|---|---|---|---|---|---|---|---|---|"
row "unbricked" "$bin" "${common[@]}"
for edge in $edges; do
  row "--bricks $edge, no mpirun" "$bin" "${common[@]}" --bricks "$edge"
  for np in 1 2; do
    row "--bricks $edge, -np $np" "${mpirun[@]}" -np "$np" "$bin" "${common[@]}" --bricks "$edge"
  done
done
