#!/usr/bin/env bash
# Sets up, builds and runs the main job on a bundled exemplar: README's first command.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
source scripts/compilerCache.sh
cmake "${compiler_cache[@]}" -S . -B build -DCMAKE_BUILD_TYPE=Release -DSOLIDTEX_TESTS=OFF
cmake --build build -j"$(nproc)" --target solidtex
mkdir -p out
./build/cli/solidtex particles data/particles/smarties.png -o out/smarties.vdb --size 128 \
  --report out/smarties.json --preview out/smarties_preview
echo "wrote out/smarties.vdb, out/smarties.json and out/smarties_preview/preview.png"
