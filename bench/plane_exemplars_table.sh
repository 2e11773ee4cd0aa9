#!/usr/bin/env bash
# Continuous solids of materials that differ by direction (data/continuous/planes: three sections
# of a POV-Ray wood and of a bedded stone), each plane's slices against that plane's photo
# (bidirectional similarity of the axis slices, lower is closer). "three photos": a solid made from
# all three (`synthesize XY --photo-xz XZ --photo-yz YZ`); "one photo": a solid made from that
# plane's photo alone, every axis against it (the single-photo case); "wrong photos": the
# three-photo solid's slices of that plane against the other two planes' photos, and in brackets
# that plane's photo itself against them (what slices exactly like the photo would score).
# Usage: bench/plane_exemplars_table.sh [SIZE] [METHODS...]   (default 64, chen-wang kopf skeletal)
# Environment: SOLIDTEX_BIN  the solidtex binary (default ./build/cli/solidtex)
set -euo pipefail
size=${1:-64}
shift || true
methods=("$@")
[ ${#methods[@]} -gt 0 ] || methods=(chen-wang kopf skeletal)
bin=${SOLIDTEX_BIN:-./build/cli/solidtex}
data=$(dirname "$0")/../data/continuous/planes
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

similarity() {  # the axis slices' bidirectional similarity in a compare or synthesize report
  python3 -c 'import json, sys; q = json.load(open(sys.argv[1]))
for key in sys.argv[2:]: q = q[key]
print(q["axis"]["coherence"] + q["axis"]["completeness"])' "$@"
}

echo "| material, method, plane | three photos | one photo | ratio (target <= 1.2) | wrong photos (the photo) | wrong / three (the photo / three; target >= 1.5) |"
echo "|---|---|---|---|---|---|"
for material in wood bedded; do
  for method in "${methods[@]}"; do
    photo() { echo "$data/${material}_$1.png"; }
    "$bin" synthesize "$(photo xy)" --photo-xz "$(photo xz)" --photo-yz "$(photo yz)" --method "$method" \
      --size "$size" --seed 1 --quiet -o "$out/three.vdb" --report "$out/three.json" > /dev/null
    for plane in xy xz yz; do
      three=$(similarity "$out/three.json" planes "$plane" quality)
      "$bin" synthesize "$(photo "$plane")" --method "$method" --size "$size" --seed 1 --quiet \
        -o "$out/one.vdb" --report "$out/one.json" > /dev/null
      one=$(similarity "$out/one.json" quality)
      wrong=()
      for other in xy xz yz; do
        [ "$other" = "$plane" ] && continue
        "$bin" compare "$(photo "$other")" "$out/three.vdb" --plane "$plane" --report "$out/wrong.json" > /dev/null
        # The same for the photo itself: what slices exactly like the photo would score.
        [ -e "$out/$material-$plane-$other.json" ] ||
          "$bin" synthesize2d "$(photo "$other")" --reference "$(photo "$plane")" --size 128 128 --quiet \
            -o "$out/texture.png" --report "$out/$material-$plane-$other.json" > /dev/null
        wrong+=("$(similarity "$out/wrong.json" quality)"
          "$(python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["quality"]["reference"]["bidirectional_similarity"])' \
            "$out/$material-$plane-$other.json")")
      done
      python3 - "$material, $method, $plane" "$three" "$one" "${wrong[@]}" <<'PY'
import sys
label, three, one, *wrong = sys.argv[1:]
three, one, wrong = float(three), float(one), [float(w) for w in wrong]
pairs = list(zip(wrong[0::2], wrong[1::2]))
print(f"| {label} | {three:.3f} | {one:.3f} | {three / one:.2f} | "
      + " / ".join(f"{w:.3f} ({p:.3f})" for w, p in pairs) + " | "
      + " / ".join(f"{w / three:.2f} ({p / three:.2f})" for w, p in pairs) + " |")
PY
    done
  done
done
