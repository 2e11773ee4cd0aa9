#!/usr/bin/env bash
# Skeletal synthesis against the optimisation it builds on, same exemplar, size and machine, one run
# each: 2D kwatra vs skeletal at SIZE^2 and solids chen-wang vs skeletal at SIZE^3, all from the
# top-left SIZE x SIZE quarter of each photo. Wall time and peak resident memory of the whole command
# (GNU time), quality not measured. Prints a Markdown table.
# Usage: bench/skeletal_speed.sh SIZE PHOTO.png...   (run from the repo root after building)
set -euo pipefail
size=$1
shift
bin=${SOLIDTEX_BIN:-./build/cli/solidtex}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
timed() { /usr/bin/time -f "%e %M" -o "$out/time" "$@" > /dev/null; read -r seconds kib < "$out/time"; }
echo "| photo | kind | baseline | s | MiB | skeletal s | MiB | speed-up |"
echo "|---|---|---|---|---|---|---|---|"
for photo in "$@"; do
  name=$(basename "$photo" .png)
  oiiotool "$photo" --cut "${size}x${size}+0+0" -o "$out/exemplar.png"
  for kind in 2d solid; do
    if [ "$kind" = 2d ]; then
      base=kwatra
      run() { timed "$bin" synthesize2d "$out/exemplar.png" -o "$out/t.png" --size "$size" "$size" --method "$1" --quiet --no-quality; }
    else
      base=chen-wang
      run() { timed "$bin" synthesize "$out/exemplar.png" -o "$out/v.vdb" --size "$size" --method "$1" --quiet --no-quality; }
    fi
    run "$base"
    s0=$seconds m0=$((kib / 1024))
    run skeletal
    echo "| $name | $kind | $base | $s0 | $m0 | $seconds | $((kib / 1024)) | $(python3 -c "print(f'{$s0 / $seconds:.1f}x')") |"
  done
done
