#!/usr/bin/env bash
# The reconstruction's default options against the paper's baseline on photos cut from a family of
# known 3D truths (`solidtex truth`: shapes, size mixes, fractions, particle counts, photo blur and
# noise): section-area KS against the photo; particle-volume W1/mean of the placed particles (solid
# seeds 1 and 2) and of the whole particles in the block, where the truth's volume CDF lies against
# the sizing's band, section solidity, roundness and aspect KS and the window spread ratio against the
# truth and its sections; as a Markdown table. An
# ideal solid per row: a second truth of the same settings and another seed, made at the solid's
# voxels per pixel and compared the same way: what a perfect reconstruction would score.
# Usage: bench/truth_sweep.sh [SIZE] [TRUTH SEEDS...]   (run from the repo root after building)
# Environment: BASELINE_FLAGS  particles options of the baseline (default: the paper's,
#                            "--sizing bbox --arrangement best-fit --smoothing 0 --body-form 0 --boundary walls")
#              JOBS            truths made and rebuilt at once (default 1)
#              ONLY            an extended regular expression: only the truths whose names match it
#              FLAGS           particles options added to both default solids (default none)
#              SOLIDTEX_BIN    the solidtex binary (default ./build/cli/solidtex)
set -euo pipefail
size=${1:-128}
shift || true
seeds=("$@")
[ ${#seeds[@]} -eq 0 ] && seeds=(1 2)
bin=${SOLIDTEX_BIN:-./build/cli/solidtex}
read -r -a flags <<< "${FLAGS:-}"
read -r -a baseline <<< "${BASELINE_FLAGS:---sizing bbox --arrangement best-fit --smoothing 0 --body-form 0 --boundary walls}"
jobs=${JOBS:-1}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

# name|truth options. The photo is the X x Y section: 320 x 320 holds about 80 particles of the
# default sizes, 800 x 800 about 500. At a depth of 72 the longest particle must fit.
truths=(
  "default|"
  "spheres|--elongation 1"
  "prolate 1.5|--elongation 1.5"
  "flattened 0.5|--flatten 0.5"
  "flattened 0.45 spheres|--elongation 1 --flatten 0.45"
  "superellipsoid p4|--shape superellipsoid"
  "superellipsoid p6 flat 0.6|--shape superellipsoid --exponent 6 --flatten 0.6 --large-radius 11"
  "polytope|--shape polytope --elongation 1"
  "polytope elongated|--shape polytope --large-radius 11"
  "polytope flat 0.6, 0.3|--shape polytope --elongation 1 --flatten 0.6 --fraction 0.3"
  "unimodal|--large-share 0"
  "unimodal spheres r9|--large-share 0 --elongation 1 --small-radius 9"
  "unimodal superellipsoid r10|--shape superellipsoid --large-share 0 --small-radius 10"
  "10:1 volume|--small-radius 5 --large-radius 10.8"
  "10:1 volume, half large|--small-radius 5 --large-radius 10.8 --large-share 0.5"
  "10:1 polytope|--shape polytope --small-radius 5 --large-radius 10.8"
  "fraction 0.1|--fraction 0.1"
  "fraction 0.3|--fraction 0.3"
  "fraction 0.4|--fraction 0.4"
  "fraction 0.4 10:1|--fraction 0.4 --small-radius 5 --large-radius 10.8"
  "few: 320x320|--dims 320 320 72"
  "few, fraction 0.1|--dims 448 448 72 --fraction 0.1"
  "many: 800x800|--dims 800 800 72"
  "many small|--dims 560 560 72 --small-radius 5 --large-radius 9"
  "noise 0.06|--noise 0.06"
  "blur 1|--blur 1"
  "blur 2, noise 0.05|--blur 2 --noise 0.05"
)

# One truth and seed: the truth, both reconstructions and their comparisons, then one table row
# (or one saying which step failed, so one refused setting does not end the sweep).
run_one() {
  local name=$1 seed=$2 dir=$3
  shift 3
  mkdir -p "$dir"
  if ! measure_one "$seed" "$dir" "$@" 2> "$dir/error"; then
    echo "| $name | $seed | failed: $(tail -n 1 "$dir/error") |"
  else
    python3 - "$dir" "$name" "$seed" <<'PY'
import json, sys
d, d2, b, i = (json.load(open(f"{sys.argv[1]}/{k}.json")) for k in ("default", "default2", "baseline", "ideal"))
def band(r):
    c = r["truth"].get("volume_cdf_band")
    return "-" if c is None else f"{c['largest_excursion']:.3f}" + ("" if c["meets_truth_band_everywhere"] else " (no)")
def cells(r):
    t = r["truth"]
    return [f"{r['ks']:.3f}", f"{t['volume_wasserstein1_over_mean']:.3f}", f"{t['solidity_ks']:.3f}",
            f"{t['roundness_ks']:.3f}", f"{t['window_spread_ratio']:.2f}", f"{r['volume_fraction']:.3f}"]
w1 = lambda r: r["truth"]["volume_wasserstein1_over_mean"]
default = [f"{d['ks']:.3f}", f"{w1(d):.3f} / {w1(d2):.3f}",
           f"{d['truth']['whole_in_block']['volume_wasserstein1_over_mean']:.3f}",
           f"{band(d)} / {band(d2)} vs {d['truth']['volume_cdf_band']['truth_dkw_bound_90']:.3f}", *cells(d)[2:]]
aspect = lambda r: f"{r['truth']['aspect_ks']:.3f}"
row = [sys.argv[2], sys.argv[3], str(d["photo_particles"]), *default, *cells(b), *cells(i)[1:5],
       f"{d['area_fraction']:.3f}", aspect(d), aspect(b), aspect(i)]
print("| " + " | ".join(row) + " |")
PY
  fi
  rm -rf "$dir"  # a truth.vdb of the default size is some 100 MB
}

# Each step ends the measure on failure: `set -e` does not reach into a function tested by `if`.
measure_one() {
  local seed=$1 dir=$2
  shift 2
  "$bin" truth -o "$dir/t" --seed "$seed" "$@" > /dev/null || return
  "$bin" particles "$dir/t/photo.png" -o "$dir/default.vdb" --size "$size" "${flags[@]}" --quiet > /dev/null || return
  "$bin" particles "$dir/t/photo.png" -o "$dir/default2.vdb" --size "$size" --seed 2 "${flags[@]}" --quiet > /dev/null || return
  "$bin" particles "$dir/t/photo.png" -o "$dir/baseline.vdb" --size "$size" "${baseline[@]}" --quiet > /dev/null || return
  for run in default default2 baseline; do
    "$bin" compare "$dir/t/photo.png" "$dir/$run.vdb" --truth "$dir/t/truth.vdb" --report "$dir/$run.json" > /dev/null || return
  done
  local scale scaled ideal
  scale=$(python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["voxels_per_pixel"])' "$dir/default.json") || return
  scaled=$(scaled_truth_options "$scale" "$@") || return
  read -r -a ideal <<< "$scaled"
  "$bin" truth -o "$dir/ideal" --seed $((seed + 1000)) "${ideal[@]}" > /dev/null || return
  "$bin" compare "$dir/t/photo.png" "$dir/ideal/truth.vdb" --scale "$scale" --truth "$dir/t/truth.vdb" \
    --report "$dir/ideal.json" > /dev/null
}

# The truth options with lengths (radii, photo dims) times SCALE: the same material at the solid's voxels.
scaled_truth_options() {
  python3 - "$@" <<'PY'
import sys
scale, options = float(sys.argv[1]), sys.argv[2:]
lengths = {"--small-radius": [7.0], "--large-radius": [13.0], "--dims": [640.0, 640.0, 72.0]}
rest, i = [], 0
while i < len(options):
    if options[i] in lengths:
        n = len(lengths[options[i]])
        lengths[options[i]] = [float(v) for v in options[i + 1:i + 1 + n]]
        i += 1 + n
    else:
        rest.append(options[i])
        i += 1
for key, values in lengths.items():
    if key == "--dims":
        # The depth only has to hold the longest particle: kept, as rounding could leave it too thin.
        rest += [key] + [str(max(8, round(v * scale))) for v in values[:2]] + [str(round(values[2]))]
    else:
        rest += [key] + [f"{v * scale:.4g}" for v in values]
print(" ".join(rest))
PY
}

echo "Default solids' options: ${flags[*]:-none}; baseline: ${baseline[*]}; solids ${size}^3; truth seeds ${seeds[*]}."
echo
echo "| truth | seed | photo particles | KS | volume W1/mean, placed, solid seeds 1 / 2 | volume W1/mean, whole in block, seed 1 | band: largest excursion, seeds 1 / 2 vs the truth's bound | solidity KS | roundness KS | window spread ratio | volume fraction |" \
     "baseline KS | baseline volume W1/mean | baseline solidity KS | baseline roundness KS | baseline window spread ratio | baseline volume fraction |" \
     "ideal volume W1/mean | ideal solidity KS | ideal roundness KS | ideal window spread ratio | photo fraction |" \
     "aspect KS | baseline aspect KS | ideal aspect KS |"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
index=0
for truth in "${truths[@]}"; do
  name=${truth%%|*}
  [[ -n ${ONLY:-} && ! $name =~ $ONLY ]] && continue
  read -r -a options <<< "${truth#*|}"
  for seed in "${seeds[@]}"; do
    index=$((index + 1))
    row="$out/$(printf %04d "$index").md"
    if [ "$jobs" -le 1 ]; then
      run_one "$name" "$seed" "$out/$index" "${options[@]}" > "$row"
      cat "$row"
    else
      run_one "$name" "$seed" "$out/$index" "${options[@]}" > "$row" &
      while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do wait -n; done
    fi
  done
done
if [ "$jobs" -gt 1 ]; then
  wait
  cat "$out"/*.md
fi
