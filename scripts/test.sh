#!/usr/bin/env bash
# Sets up, builds (Release, warnings as errors) and runs the whole test suite: README's second command.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
source scripts/compilerCache.sh
cmake "${compiler_cache[@]}" -S . -B build -DCMAKE_BUILD_TYPE=Release -DSOLIDTEX_TESTS=ON -DSOLIDTEX_STRICT=ON
cmake --build build -j"$(nproc)"
ctest --test-dir build --output-on-failure --no-tests=error -j"$(nproc)"
