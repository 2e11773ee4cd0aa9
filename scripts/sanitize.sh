#!/usr/bin/env bash
# Builds with address+undefined sanitizers and runs the unit tests under them (CI runs this after
# scripts/test.sh). -O1 keeps the build quick and the reports' stacks readable. Not strict: under
# the sanitizers GCC 12 reports -Wmaybe-uninitialized inside CGAL's headers.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
source scripts/compilerCache.sh
cmake "${compiler_cache[@]}" -S . -B build-asan -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O1 -g1" \
  -DSOLIDTEX_TESTS=ON -DSOLIDTEX_STRICT=OFF -DSOLIDTEX_SANITIZE=address+undefined
cmake --build build-asan -j"$(nproc)"
export LSAN_OPTIONS="suppressions=$PWD/scripts/lsan.supp" UBSAN_OPTIONS=print_stacktrace=1
run_unit_tests() { ctest --test-dir build-asan -L unit --output-on-failure --no-tests=error -j"$(nproc)" "$@"; }
# The image-reading tests with full stacks: the one suppression names a frame inside OpenImageIO,
# which the quick unwinder does not reach.
ASAN_OPTIONS=fast_unwind_on_malloc=0 run_unit_tests -R ImageIO
# Left to the Release run (scripts/test.sh), to keep CI within its time: whole commands run as
# processes twice or at two thread counts (ExitCodes, TwoRuns; the bad-input, signal and disk-full
# commands stay), volume synthesis and grown solids repeated at two thread counts (tsan.sh runs
# those), and the volume-synthesis quality checks at 32^3-64^3 (tsan.sh leaves them out too).
# Under the sanitizers they took 1630 of the unit tests' 3285 seconds.
repeats='^(ExitCodes\.|EveryCommand/TwoRuns\.|GrowSolid\.(Bricks|IsTheSeed)'
repeats+='|PeriodicAndSteered/RegionOfTheWholeVolume\.'
repeats+='|SynthesizeFromVolume\.(SameVolume|LayersFollow|CircleField|RepeatedTile|PeriodicVolume))'
run_unit_tests -E "ImageIO|$repeats"
