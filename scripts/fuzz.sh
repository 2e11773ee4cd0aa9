#!/usr/bin/env bash
# Builds the libFuzzer harnesses (clang, address+undefined) in build-fuzz and fuzzes one of them:
#   bash scripts/fuzz.sh HARNESS [SECONDS] [extra libFuzzer flags...]
# HARNESS is photo, mask, vdb or options; SECONDS defaults to 600. New inputs that add coverage go
# to build-fuzz/corpus/HARNESS (seeded from tests/fuzz/corpus/HARNESS, which stays untouched);
# crashes, leaks, out-of-memory and timeouts go to build-fuzz/findings/HARNESS/.
set -euo pipefail
cd "$(dirname "$0")/.."
harness=${1:?usage: scripts/fuzz.sh photo|mask|vdb|options [seconds] [libFuzzer flags]}
seconds=${2:-600}
shift $(($# < 2 ? $# : 2))
case $harness in photo | mask | vdb | options) ;; *) echo "unknown harness: $harness" >&2; exit 2 ;; esac

# -O1 -g1 as in scripts/sanitize.sh: quick to build, readable stacks.
cmake -S . -B build-fuzz -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_CXX_FLAGS_RELEASE="-O1 -g1" -DSOLIDTEX_TESTS=ON \
  -DSOLIDTEX_SANITIZE=address+undefined -DSOLIDTEX_FUZZ=ON >/dev/null
cmake --build build-fuzz -j"${FUZZ_BUILD_JOBS:-2}" --target "fuzz_$harness"

corpus=build-fuzz/corpus/$harness
findings=$PWD/build-fuzz/findings/$harness
mkdir -p "$corpus" "$findings"
# The full unwinder lets the suppressions name frames inside OpenImageIO; malloc of an impossible
# size returns null, as it would without the sanitizer (operator new still aborts: docs/fuzzing.md).
export ASAN_OPTIONS=fast_unwind_on_malloc=0:allocator_may_return_null=1
export LSAN_OPTIONS="suppressions=$PWD/tests/fuzz/lsan.supp" UBSAN_OPTIONS=print_stacktrace=1
# One worker (-fork=1) that keeps going past findings, so that a run reports all it found.
# The options corpus names files in data/ by relative path: run from the repository root.
status=0
build-fuzz/tests/fuzz/fuzz_"$harness" -fork=1 -ignore_crashes=1 -ignore_ooms=1 -ignore_timeouts=1 \
  -max_total_time="$seconds" -timeout=60 -artifact_prefix="$findings/" "$@" \
  "$corpus" tests/fuzz/corpus/"$harness" 2>&1 | tee build-fuzz/findings/"$harness".log || status=$?
# A crashed job leaves its input file behind (tests/fuzz/inputFile.h): remove those of dead processes.
for file in /dev/shm/solidtex_fuzz_*; do
  pid=${file#/dev/shm/solidtex_fuzz_}
  [[ -e $file ]] && ! kill -0 "${pid%%_*}" 2>/dev/null && rm -f "$file"
done
echo "findings in $findings: $(find "$findings" -type f | wc -l)"
exit "$status"
