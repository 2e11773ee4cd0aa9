#!/usr/bin/env bash
# The materials descriptors of particle solids against their photos (docs/validation.md): for each
# bundled photo, and for a truth (`solidtex truth`) with the truth's own volume as a second solid,
# `compare --measures all` at SIZE^3, seed 1. One Markdown row per photo, solid and phase.
# Usage: bench/materials_table.sh [SIZE]   (default 128; run from the repo root after building)
#   PHOTOS="gravel smarties leopard coins"   SHAPES="ellipsoid superellipsoid polytope"
set -euo pipefail
size=${1:-128}
bin=${SOLIDTEX_BIN:-$PWD/build/cli/solidtex}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
echo "| photo | solid | phase | fraction photo / solid | S2 rms sections / solid | correlation length ratio (solid) | mean chord ratio sections / solid | local thickness ratio (sections) | perimeter ratio (sections) | S_V / (4/pi L_A) | tortuosity x / y / z |"
echo "|---|---|---|---|---|---|---|---|---|---|---|"
row() {  # photo-label solid-label photo vdb [compare options]
  local label=$1 solid=$2 photo=$3 vdb=$4
  shift 4
  local start end
  start=$(date +%s.%N)
  "$bin" compare "$photo" "$vdb" --measures all --report "$out/c.json" "$@" > /dev/null
  end=$(date +%s.%N)
  /usr/bin/python3 - "$out/c.json" "$label" "$solid" "$start" "$end" <<'PY'
import json, sys
report, label, solid, start, end = sys.argv[1], sys.argv[2], sys.argv[3], float(sys.argv[4]), float(sys.argv[5])
phases = json.load(open(report))["materials"]["phases"]
for name, p in phases.items():
    s, v = p["sections_vs_photo"], p["solid_vs_photo"]
    tau = p["solid"]["tortuosity"]
    taus = " / ".join(f"{tau[a]['factor']:.2f}" if "factor" in tau[a] else "none" for a in "xyz")
    print(f"| {label} | {solid} | {name} | {p['photo']['fraction']:.3f} / {p['solid']['fraction']:.3f} "
          f"| {s['s2_rms']:.4f} / {v['s2_rms']:.4f} | {v['s2_correlation_length_ratio']:.2f} "
          f"| {s['chord_mean_ratio']:.2f} / {v['chord_mean_ratio']:.2f} | {s['local_thickness_mean_ratio']:.2f} "
          f"| {s['perimeter_density_ratio']:.2f} | {v['surface_density_ratio']:.2f} | {taus} |")
PY
}
for photo in ${PHOTOS:-gravel smarties leopard coins}; do
  "$bin" particles "data/particles/$photo.png" -o "$out/v.vdb" --size "$size" --seed 1 --quiet > /dev/null
  row "$photo" "solidtex $size^3" "data/particles/$photo.png" "$out/v.vdb"
done
# A truth's middle section is the photo: its own volume is the reference level for the solid's.
for shape in ${SHAPES:-ellipsoid superellipsoid polytope}; do
  "$bin" truth -o "$out/t" --shape "$shape" --dims 256 256 128 --seed 1 > /dev/null
  "$bin" particles "$out/t/photo.png" -o "$out/v.vdb" --size "$size" --seed 1 --quiet > /dev/null
  row "$shape truth 256x256x128" "solidtex $size^3" "$out/t/photo.png" "$out/v.vdb"
  row "$shape truth 256x256x128" "the truth" "$out/t/photo.png" "$out/t/truth.vdb" --scale 1
done
