#!/usr/bin/env bash
# Skeletal synthesis against the optimisation it builds on, same exemplar, size and machine, one run
# each: 2D kwatra vs skeletal at SIZE^2 and solids chen-wang vs skeletal at SIZE^3, all from the
# top-left SIZE x SIZE quarter of each photo. The synthesis seconds of the report, the wall time and peak
# resident memory of the whole command (GNU time; start-up and image I/O included), quality not measured.
# Prints a Markdown table.
# Usage: bench/skeletal_speed.sh SIZE PHOTO.png...   (run from the repo root after building)
# EXTRA_2D (environment): more options for both 2D runs, e.g. EXTRA_2D="--neighborhoods 13".
set -euo pipefail
size=$1
shift
bin=${SOLIDTEX_BIN:-./build/cli/solidtex}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
timed() {
  /usr/bin/time -f "%e %M" -o "$out/time" "$@" --report "$out/r.json" > /dev/null
  read -r wall kib < "$out/time"
  seconds=$(python3 -c "import json; print(f'{json.load(open(\"$out/r.json\"))[\"seconds\"]:.2f}')")
}
echo "| photo | kind | baseline | synthesis s | wall s | MiB | skeletal synthesis s | wall s | MiB | speed-up (synthesis) |"
echo "|---|---|---|---|---|---|---|---|---|---|"
for photo in "$@"; do
  name=$(basename "$photo" .png)
  oiiotool "$photo" --cut "${size}x${size}+0+0" -o "$out/exemplar.png"
  for kind in 2d solid; do
    if [ "$kind" = 2d ]; then
      base=kwatra
      run() { timed "$bin" synthesize2d "$out/exemplar.png" -o "$out/t.png" --size "$size" "$size" --method "$1" --quiet --no-quality ${EXTRA_2D:-}; }
    else
      base=chen-wang
      run() { timed "$bin" synthesize "$out/exemplar.png" -o "$out/v.vdb" --size "$size" --method "$1" --quiet --no-quality; }
    fi
    run "$base"
    s0=$seconds w0=$wall m0=$((kib / 1024))
    run skeletal
    echo "| $name | $kind | $base | $s0 | $w0 | $m0 | $seconds | $wall | $((kib / 1024)) | $(python3 -c "print(f'{$s0 / $seconds:.1f}x')") |"
  done
done
