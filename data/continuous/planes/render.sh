#!/usr/bin/env bash
# Renders the plane exemplars of planes.pov: wood_{xy,xz,yz}.png and bedded_{xy,xz,yz}.png, 128 px.
# Needs povray (Debian 12: 1:3.7.0.10-2+b2). Run from this folder.
set -euo pipefail
textures=(wood bedded)
planes=(xy xz yz)
for t in 0 1; do
  for p in 0 1 2; do
    povray -D +A0.05 +AM2 +R3 +W128 +H128 +FN8 Declare=Texture=$t Declare=Plane=$p \
      +I"planes.pov" +O"${textures[t]}_${planes[p]}.png" 2>/dev/null
  done
done
