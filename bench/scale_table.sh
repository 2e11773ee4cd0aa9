#!/usr/bin/env bash
# Wall time, peak memory and bytes per voxel of `solidtex particles` at several sizes, for gravel and
# for the spheres photo of the scale issue, then PoreSpy's random sequential addition beside the
# spheres at PEER_SIZE (../shared/peers/porespy/run.sh); a Markdown table.
# Usage: bench/scale_table.sh [SIZES]   (default 128,256,512; run from the repo root after building)
#   PEER_SIZE=256   the size PoreSpy runs at (empty: no peer row)
#   PHOTOS="gravel spheres"
set -euo pipefail
sizes=${1:-128,256,512}
peerSize=${PEER_SIZE-256}
photos=${PHOTOS:-gravel spheres}
bin=${SOLIDTEX_BIN:-./build/cli/solidtex}
peer=${PEER:-../shared/peers/porespy/run.sh}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

# The spheres photo: two radii, no stretch, fraction 0.3; made at 1 voxel per pixel.
"$bin" truth -o "$out/spheres" --dims 512 512 64 --fraction 0.3 --small-radius 6 --large-radius 9 \
  --large-share 0.5 --spread 0.15 --elongation 1 --seed 1 > /dev/null

photoOf() { [ "$1" = spheres ] && echo "$out/spheres/photo.png" || echo "data/particles/$1.png"; }
extraOf() { [ "$1" = spheres ] && echo "--scale 1" || true; }

echo "| photo | size | wall s | placement s | peak MiB | bytes per voxel | particles | volume fraction | photo fraction |"
echo "|---|---|---|---|---|---|---|---|---|"
declare -A spheresWall
for photo in $photos; do
  for size in ${sizes//,/ }; do
    # shellcheck disable=SC2046
    /usr/bin/time -f '%e %M' -o "$out/time" "$bin" particles "$(photoOf "$photo")" -o "$out/v.vdb" \
      --size "$size" --seed 1 --quiet --report "$out/r.json" $(extraOf "$photo") > /dev/null
    read -r wall kib < "$out/time"
    [ "$photo" = spheres ] && spheresWall[$size]=$wall
    python3 - "$out/r.json" "$photo" "$size" "$wall" "$kib" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
v, size, kib = r["volume"], int(sys.argv[3]), int(sys.argv[5])
print(f"| {sys.argv[2]} | {size}^3 | {float(sys.argv[4]):.1f} | {r['time_seconds']['placement']:.1f} "
      f"| {kib / 1024:.0f} | {kib * 1024 / size ** 3:.1f} | {v['particles']} | {v['volume_fraction']:.3f} "
      f"| {v['area_fraction']:.3f} |")
PY
    rm -f "$out/v.vdb"
  done
done

if [ -n "$peerSize" ] && [ -x "$peer" ]; then
  /usr/bin/time -f '%e %M' -o "$out/time" "$peer" "$peerSize" > "$out/peer.json"
  read -r wall kib < "$out/time"
  python3 - "$out/peer.json" "$peerSize" "$wall" "$kib" "${spheresWall[$peerSize]:-}" <<'PY'
import json, sys
r, size, kib = json.load(open(sys.argv[1])), int(sys.argv[2]), int(sys.argv[4])
print(f"| PoreSpy rsa, radii 10..5 | {size}^3 | {float(sys.argv[3]):.1f} | {r['poly_s']:.1f} (packing) "
      f"| {kib / 1024:.0f} | {kib * 1024 / size ** 3:.1f} | - | {r['poly_vf']:.3f} | 0.300 |")
if sys.argv[5]:
    print(f"\nspheres at {size}^3: {float(sys.argv[5]):.1f} s, {float(sys.argv[5]) / r['poly_s']:.2f}x PoreSpy's packing")
PY
fi
