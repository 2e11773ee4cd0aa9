#!/usr/bin/env bash
# Time and peak memory of the materials descriptors (docs/performance.md): a gravel solid of SIZE^3
# (seed 1), then `compare` with no measures, with the default ones, and the tortuosity of each
# phase along z alone (Python, the same library call `compare --measures tortuosity` makes).
# Usage: bench/materials_speed.sh [SIZE]   (default 256; run from the repo root after building)
set -euo pipefail
size=${1:-256}
bin=${SOLIDTEX_BIN:-$PWD/build/cli/solidtex}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
"$bin" particles data/particles/gravel.png -o "$out/g.vdb" --size "$size" --seed 1 --quiet > /dev/null
for measures in none s2,lineal,chord,psd,minkowski; do
  /usr/bin/time -f "compare --measures $measures: %e s, peak %M KiB" \
    "$bin" compare data/particles/gravel.png "$out/g.vdb" --measures "$measures" > /dev/null
done
PYTHONPATH=$PWD/build/python /usr/bin/python3 - "$size" <<'PY'
import resource, sys, time
import solidtex
size = int(sys.argv[1])
ids = solidtex.particles("data/particles/gravel.png", size=size, seed=1)["particle_id"]
for name, phase in (("particles", ids > 0), ("matrix", ids == 0)):
    start = time.perf_counter()
    t = solidtex.tortuosity(phase, axis=0)  # numpy axis 0: z
    print(f"tortuosity of the {name} along z: {time.perf_counter() - start:.1f} s, tau {t['factor']:.3f}, "
          f"{t['iterations']} iterations, residual {t['relative_residual']:.1e}, flux mismatch {t['flux_mismatch']:.1e}")
print(f"peak {resource.getrusage(resource.RUSAGE_SELF).ru_maxrss} KiB")
PY
