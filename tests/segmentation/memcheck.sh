#!/usr/bin/env bash
# Runs a test binary under Valgrind's memcheck. Some virtual machines hide RDTSCP from CPUID while
# the CPU runs it, and libhwy (loaded by OpenImageIO through libjxl) calls it while loading: then
# Valgrind stops on its own decoder before any test code runs. That is reported as a skip (77),
# never as a pass; every other outcome is memcheck's.
set -uo pipefail
log=$(mktemp)
trap 'rm -f "$log"' EXIT
"$@" 2>&1 | tee "$log"
status=${PIPESTATUS[0]}
# RDTSCP is 0F 01 F9; a trap (ud2) from a real bug is reported alike but with other bytes.
if grep -q "unhandled instruction bytes: 0xF 0x1 0xF9 " "$log" && ! grep -q "^\[ RUN" "$log"; then
  echo "memcheck skipped: Valgrind cannot decode RDTSCP, which this CPU hides from CPUID"
  exit 77
fi
exit "$status"
