#!/usr/bin/env bash
# Strong scaling of particle placement in bricks under mpirun: a photo's particle solid at SIZE^3,
# placed whole, then in bricks of EDGE as one process started alone (every core as a thread) and on
# 1 and 2 processes under mpirun (one core each); a Markdown table with the figures the 2048^3 model
# in docs/performance.md is built from (placement seconds, bytes exchanged, per-brick seconds).
# Usage: bench/mpi_particle_bricks.sh [SIZE [EDGE [PHOTO]]]   (default 256 64 leopard; from the repo root)
set -euo pipefail
size=${1:-256}
edge=${2:-64}
photo=${3:-leopard}
bin=${SOLIDTEX_BIN:-$PWD/build/cli/solidtex}
mpirun=(mpirun --allow-run-as-root --oversubscribe --quiet)
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
common=(particles "data/particles/$photo.png" --size "$size" --seed 1 --quiet)

row() {  # label, then the command
  local label=$1
  shift
  /usr/bin/time -f '%e %M' -o "$out/time" "$@" -o "$out/v.vdb" --report "$out/r.json" > /dev/null
  read -r wall kib < "$out/time"
  /usr/bin/python3 - "$out/r.json" "$label" "$wall" "$kib" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
label, wall, kib = sys.argv[2], float(sys.argv[3]), int(sys.argv[4])
t, b = r["time_seconds"], r.get("bricks")
if b:
    per_brick = sorted(p["seconds"] for p in b["per_brick"])
    bricks = (f"{b['count']} | {b['processes']} | {b['load_imbalance']:.2f} | {b['bytes_exchanged'] / 2**20:.1f} | "
              f"{per_brick[len(per_brick) // 2]:.2f} | {b['seams']['face_fraction']:.3f} / {b['seams']['other_fraction']:.3f}")
else:
    bricks = "1 | 1 | | | |"
print(f"| {label} | {wall:.1f} | {t['placement']:.1f} | {kib / 1024:.0f} | {r['volume']['volume_fraction']:.3f} | {bricks} |")
PY
}

echo "| $photo ${size}^3 | wall s | placement s | peak MiB (largest process) | volume fraction | bricks | processes | load imbalance | MiB exchanged | median brick s (all rounds) | seam fraction face / other |"
echo "|---|---|---|---|---|---|---|---|---|---|---|"
row "whole" "$bin" "${common[@]}"
row "bricks $edge, one process alone" "$bin" "${common[@]}" --bricks "$edge"
for np in 1 2; do
  row "bricks $edge, mpirun -np $np" "${mpirun[@]}" -np "$np" "$bin" "${common[@]}" --bricks "$edge"
done
