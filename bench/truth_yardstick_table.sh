#!/usr/bin/env bash
# The split-half yardstick of bench/real_particles_table.sh on known truths, with the truth's own
# volume as a third solid: each truth's photo (256x256, its middle section) is cut into halves; the
# truth volume (256x256x128), the particle solid and a chen-wang solid (both SIZE^3, from the left
# half) are rated by `compare --mode continuous --reference right`. Prints a Markdown table.
# Usage: bench/truth_yardstick_table.sh SIZE NAME "TRUTH OPTIONS" [NAME "OPTIONS"]... (from the
# repo root, after building)
set -euo pipefail
size=$1
shift
bin=${SOLIDTEX_BIN:-./build/cli/solidtex}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
echo "| truth | truth volume: patch distance ratio axis / oblique | particle solid | chen-wang |"
echo "|---|---|---|---|"
while [ $# -gt 0 ]; do
  name=$1
  read -r -a options <<< "$2"
  shift 2
  "$bin" truth -o "$out/t" --dims 256 256 128 "${options[@]}" > /dev/null
  oiiotool "$out/t/photo.png" --cut "128x256+0+0" -o "$out/left.png"
  oiiotool "$out/t/photo.png" --cut "128x256+128+0" --origin +0+0 -o "$out/right.png"
  rate() { "$bin" compare "$out/left.png" "$1" --mode continuous --reference "$out/right.png" --report "$2" > /dev/null; }
  rate "$out/t/truth.vdb" "$out/tc.json"
  "$bin" particles "$out/left.png" -o "$out/p.vdb" --size "$size" --quiet > /dev/null
  rate "$out/p.vdb" "$out/pc.json"
  "$bin" synthesize "$out/left.png" -o "$out/s.vdb" --size "$size" --quiet --no-quality > /dev/null
  rate "$out/s.vdb" "$out/sc.json"
  python3 - "$out" "$name" <<'PY'
import json, sys
d, name = sys.argv[1], sys.argv[2]
ratio = lambda f: json.load(open(f"{d}/{f}"))["quality"]["ratio_to_reference"]
pair = lambda r: f"{r['axis']['patch_distance']:.2f} / {r['oblique']['patch_distance']:.2f}"
print(f"| {name} | {pair(ratio('tc.json'))} | {pair(ratio('pc.json'))} | {pair(ratio('sc.json'))} |")
PY
  rm -rf "$out/t"
done
