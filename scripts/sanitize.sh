#!/usr/bin/env bash
# Builds with address+undefined sanitizers and runs the unit tests under them (CI runs this after
# scripts/test.sh). -O1 keeps the build quick and the reports' stacks readable. Not strict: under
# the sanitizers GCC 12 reports -Wmaybe-uninitialized inside CGAL's headers.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O1 -g1" \
  -DSOLIDTEX_TESTS=ON -DSOLIDTEX_STRICT=OFF -DSOLIDTEX_SANITIZE=address+undefined
cmake --build build-asan -j"$(nproc)"
ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
  ctest --test-dir build-asan -L unit --output-on-failure --no-tests=error -j"$(nproc)"
