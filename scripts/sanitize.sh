#!/usr/bin/env bash
# CI's sanitizer job (issue 7 §3): builds linerlife and its tests with
# AddressSanitizer + UndefinedBehaviorSanitizer in build-asan/ (RelWithDebInfo)
# and runs the fast test suite there. Any report fails the run: ASan aborts
# on the first error, UBSan is built with -fno-sanitize-recover.
#
#   scripts/sanitize.sh            # set up, build, run the fast tests
set -euo pipefail
cd "$(dirname "$0")/.."
export LINERLIFE_BUILD_DIR=build-asan
LINERLIFE_CMAKE_ARGS="-DCMAKE_BUILD_TYPE=RelWithDebInfo -DLINERLIFE_SANITIZE=ON" scripts/setup.sh
export ASAN_OPTIONS="halt_on_error=1:abort_on_error=1:detect_leaks=1:strict_string_checks=1"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
# the 20-mill soak is the 100-mill one's CI share; under ASan (5-10x slower)
# it runs 4 mills with ten times the hang limit
export LINERLIFE_SOAK_RUNS="${LINERLIFE_SOAK_RUNS:-4}"
export LINERLIFE_TIMEOUT_SCALE="${LINERLIFE_TIMEOUT_SCALE:-10}"
ctest --test-dir build-asan -LE slow -j "$(nproc 2>/dev/null || echo 2)" --output-on-failure --timeout 1500
