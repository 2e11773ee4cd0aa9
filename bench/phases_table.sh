#!/usr/bin/env bash
# Truths of two and three kinds of particle (`truth`: small orange, large blue, with --medium-share a
# green class between, or an orange one told apart by its grain alone), each solid made with `particles --phases auto`: the phases found, and per
# phase the photo's area fraction, the truth's volume fraction of that class, the solid's volume
# fraction, and the section-area KS against the photo's particles of the phase (`compare`) with its
# 5 % critical value.
# Usage: bench/phases_table.sh [SIZE]   (default 128; run from the repo root after building)
# Environment: SOLIDTEX_BIN  the solidtex binary (default ./build/cli/solidtex)
set -euo pipefail
size=${1:-128}
bin=${SOLIDTEX_BIN:-./build/cli/solidtex}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

# name|seed|truth options
truths=(
  "two classes|1|"
  "two classes|2|"
  "two classes, half large|3|--large-share 0.5"
  "three classes|1|--medium-share 0.3 --medium-radius 7.5"
  "three classes|2|--medium-share 0.3 --medium-radius 7.5"
  "three classes, polytopes|3|--medium-share 0.3 --medium-radius 7.5 --shape polytope"
  "grainy orange|4|--medium-share 0.3 --medium-radius 7.5 --medium-srgb 0.92 0.55 0.16 --medium-grain 0.1"
  "grainy orange, same size|5|--medium-share 0.4 --medium-radius 5 --medium-srgb 0.92 0.55 0.16 --medium-grain 0.08"
)
echo "| truth | seed | phases found | phase (L* a* b*, grain) | photo area fraction | truth volume fraction | solid volume fraction | section KS (critical) |"
echo "|---|---|---|---|---|---|---|---|"
for entry in "${truths[@]}"; do
  IFS='|' read -r name seed options <<<"$entry"
  dir=$out/$seed-${name// /_}
  # shellcheck disable=SC2086
  "$bin" truth -o "$dir" --dims 512 512 128 --small-radius 5 --large-radius 10 --seed "$seed" $options >/dev/null
  "$bin" particles "$dir/photo.png" -o "$dir/solid.vdb" --size "$size" --phases auto --seed "$seed" \
    --report "$dir/solid.json" >/dev/null 2>&1
  "$bin" compare "$dir/photo.png" "$dir/solid.vdb" --measures none --report "$dir/compare.json" >/dev/null
  /usr/bin/python3 - "$dir" "$name" "$seed" <<'PY'
import json, sys
d, name, seed = sys.argv[1:]
truth = json.load(open(f"{d}/truth.json"))
compare = json.load(open(f"{d}/compare.json"))
solid = json.load(open(f"{d}/solid.json"))
# Each phase is matched to the truth class of the nearest colour (b* tells orange from blue, a* green);
# classes of one colour are told apart by their grain, in the order of the phases' grain.
def lab_of(rgb):
    import colorsys
    def lin(c): return c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4
    r, g, b = (lin(c) for c in rgb)
    x = (0.4124 * r + 0.3576 * g + 0.1805 * b) / 0.95047
    y = 0.2126 * r + 0.7152 * g + 0.0722 * b
    z = (0.0193 * r + 0.1192 * g + 0.9505 * b) / 1.08883
    f = lambda t: t ** (1 / 3) if t > 0.008856 else 7.787 * t + 16 / 116
    return (116 * f(y) - 16, 500 * (f(x) - f(y)), 200 * (f(y) - f(z)))
classes = truth["options"]["classes"]
class_lab = [lab_of(c["srgb"]) for c in classes]
phases = compare.get("phases", [])
found = len(phases)
solid_classes = solid["phases"]["classes"]
def colour_distance(lab, i): return sum((a - b) ** 2 for a, b in zip(lab, class_lab[i])) ** 0.5
def same_colour(lab):
    best = min(colour_distance(lab, i) for i in range(len(classes)))
    return [i for i in range(len(classes)) if colour_distance(lab, i) < best + 3]
def match(p):
    group = same_colour(solid_classes[p["phase"] - 1]["lab"])
    mates = sorted((q for q in phases if same_colour(solid_classes[q["phase"] - 1]["lab"]) == group),
                   key=lambda q: solid_classes[q["phase"] - 1]["grain"])
    by_grain = sorted(group, key=lambda i: classes[i].get("grain", 0))
    return by_grain[min(mates.index(p), len(by_grain) - 1)]
for p in phases:
    lab, grain = solid_classes[p["phase"] - 1]["lab"], solid_classes[p["phase"] - 1]["grain"]
    k = match(p)
    print(f"| {name} | {seed} | {found} of {len(classes)} | {lab[0]:.0f} {lab[1]:.0f} {lab[2]:.0f}, {grain:.1f} | "
          f"{p['area_fraction']:.3f} | {truth['volume_fraction_per_class'][k]:.3f} | {p['volume_fraction']:.3f} | "
          f"{p.get('ks', 1):.3f} ({p.get('ks_critical_95', 0):.3f}) |")
PY
done
