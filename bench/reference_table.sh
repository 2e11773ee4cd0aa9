#!/usr/bin/env bash
# Textures and solids made from one quarter of a photo against a second photo of the material: the
# top-left SIZE x SIZE quarter of each 2*SIZE photo is the exemplar, the bottom-right quarter the
# reference. Prints a Markdown table: the result's bidirectional similarity and patch distance over
# the reference's (2D: the texture; solids: axis and oblique slices), wall time and peak memory.
# Usage: bench/reference_table.sh SIZE METHODS PHOTO.png...
#   METHODS: comma list of solid methods (chen-wang, kopf, skeletal, and grown: a GROW_FROM^3 (default 128) chen-wang solid grown
#   to GROWN_SIZE^3, default 2 x SIZE, by volume synthesis) and 2D ones (2d-kwatra, 2d-skeletal),
#   each optionally with +wavelet for --distance wavelet (e.g. 2d-skeletal+wavelet);
#   SIZE: the quarters' side, the texture's side and the solid's edge. Run from the repo root after building.
#   EXTRA_2D (environment): more options for the 2D runs, e.g. EXTRA_2D="--neighborhoods 13".
set -euo pipefail
size=$1
IFS=, read -r -a methods <<< "$2"
shift 2
bin=${SOLIDTEX_BIN:-./build/cli/solidtex}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
echo "| photo | method | reference bidirectional | bidirectional ratio | reference patch distance | patch distance ratio | seconds | peak MiB |"
echo "|---|---|---|---|---|---|---|---|"
for photo in "$@"; do
  name=$(basename "$photo" .png)
  oiiotool "$photo" --cut "${size}x${size}+0+0" -o "$out/exemplar.png"
  oiiotool "$photo" --cut "${size}x${size}+${size}+${size}" --origin +0+0 -o "$out/reference.png"
  for method in "${methods[@]}"; do
    base=${method%+wavelet}
    distance=rgb
    [ "$base" != "$method" ] && distance=wavelet
    case $base in
      2d-*)
        "$bin" synthesize2d "$out/exemplar.png" -o "$out/t.png" --size "$size" "$size" --method "${base#2d-}" \
          ${EXTRA_2D:-} --distance "$distance" --reference "$out/reference.png" --report "$out/s.json" --quiet > /dev/null
        cp "$out/s.json" "$out/c.json" ;;
      grown)
        "$bin" synthesize "$out/exemplar.png" -o "$out/v.vdb" --size "${GROWN_SIZE:-$((2 * size))}" --grow-from "${GROW_FROM:-128}" \
          --report "$out/s.json" --quiet > /dev/null
        "$bin" compare "$out/exemplar.png" "$out/v.vdb" --reference "$out/reference.png" --report "$out/c.json" > /dev/null ;;
      *)
        "$bin" synthesize "$out/exemplar.png" -o "$out/v.vdb" --size "$size" --method "$base" \
          --distance "$distance" --report "$out/s.json" --quiet > /dev/null
        "$bin" compare "$out/exemplar.png" "$out/v.vdb" --reference "$out/reference.png" --report "$out/c.json" > /dev/null ;;
    esac
    python3 - "$out/c.json" "$out/s.json" "$name" "$method" <<'PY'
import json, sys
q = json.load(open(sys.argv[1]))["quality"]
s = json.load(open(sys.argv[2]))
ref, ratio = q["reference"], q["ratio_to_reference"]
pair = lambda key: " / ".join(f"{ratio[k][key]:.3f}" for k in ("texture", "axis", "oblique") if k in ratio)
print(f"| {sys.argv[3]} | {sys.argv[4]} | {ref['bidirectional_similarity']:.4f} | {pair('bidirectional_similarity')} "
      f"| {ref['patch_distance']:.4f} | {pair('patch_distance')} | {s['seconds']:.1f} | {s['peak_memory_mib']:.0f} |")
PY
  done
done
