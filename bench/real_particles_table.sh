#!/usr/bin/env bash
# Particle solids of real photos judged by looking like the photo: each photo is cut into its left
# and right halves; the left half is the exemplar, the right half the second photo. The particle
# solid (defaults, SIZE^3), the same with synthesized insides (--particle-texture
# synthesized) and a chen-wang solid (SIZE^3) are made from the left half, and each is
# rated by `compare --mode continuous --reference right` (patch distance over the right half's, on
# axis and oblique slices: 1.0 is "as close as another photo"). Prints a Markdown table; with
# PREVIEWS=DIR also leaves each photo's previews there.
# Usage: bench/real_particles_table.sh SIZE PHOTO.png... (from the repo root, after building)
set -euo pipefail
size=$1
shift
bin=${SOLIDTEX_BIN:-./build/cli/solidtex}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
echo "| photo | particles (photo / solid fraction) | particle solid: patch distance ratio axis / oblique | synthesized insides | chen-wang: axis / oblique | matrix | seconds (particles / chen-wang) |"
echo "|---|---|---|---|---|---|---|"
for photo in "$@"; do
  name=$(basename "$photo" .png)
  read -r w h < <(oiiotool "$photo" --echo "{TOP.width} {TOP.height}")
  half=$((w / 2))
  oiiotool "$photo" --cut "${half}x${h}+0+0" -o "$out/left.png"
  oiiotool "$photo" --cut "${half}x${h}+${half}+0" --origin +0+0 -o "$out/right.png"
  preview=()
  [ -n "${PREVIEWS:-}" ] && preview=(--preview "$PREVIEWS/$name")
  "$bin" particles "$out/left.png" -o "$out/p.vdb" --size "$size" --report "$out/p.json" "${preview[@]}" --quiet > /dev/null
  "$bin" compare "$out/left.png" "$out/p.vdb" --mode continuous --reference "$out/right.png" --report "$out/pc.json" > /dev/null
  "$bin" particles "$out/left.png" -o "$out/q.vdb" --size "$size" --particle-texture synthesized --quiet > /dev/null
  "$bin" compare "$out/left.png" "$out/q.vdb" --mode continuous --reference "$out/right.png" --report "$out/qc.json" > /dev/null
  "$bin" synthesize "$out/left.png" -o "$out/s.vdb" --size "$size" --report "$out/s.json" --quiet > /dev/null
  "$bin" compare "$out/left.png" "$out/s.vdb" --reference "$out/right.png" --report "$out/sc.json" > /dev/null
  python3 - "$out" "$name" <<'PY'
import json, sys
d, name = sys.argv[1], sys.argv[2]
p, s = json.load(open(f"{d}/p.json")), json.load(open(f"{d}/s.json"))
ratio = lambda f: json.load(open(f"{d}/{f}"))["quality"]["ratio_to_reference"]
pr, qr, sr = ratio("pc.json"), ratio("qc.json"), ratio("sc.json")
pair = lambda r: f"{r['axis']['patch_distance']:.2f} / {r['oblique']['patch_distance']:.2f}"
v = p["volume"]
seconds = sum(p["time_seconds"].values()) if isinstance(p["time_seconds"], dict) else p["time_seconds"]
print(f"| {name} | {p['photo']['particle_count']} ({v['area_fraction']:.2f} / {v['volume_fraction']:.2f}) "
      f"| {pair(pr)} | {pair(qr)} | {pair(sr)} | {p['matrix']['texture']} | {seconds:.0f} / {s['seconds']:.0f} |")
PY
done
