#!/usr/bin/env bash
# Runs the libFuzzer targets (tests/fuzz/) for a bounded time each and reports
# executions and findings (issue 7 §2; results in docs/reliability.md).
#
#   bench/fuzz.sh [seconds_per_target=120] [targets...]
#
# FUZZ_TIMEOUT (seconds, default 10) is libFuzzer's limit for one input: an
# input slower than that is reported as a timeout and ends the target's run.
# The sanitizers make the build-fuzz binaries 20-50 x slower than Release, so
# on a loaded machine give fuzz_remesh more (FUZZ_TIMEOUT=60) and replay any
# timeout with the Release build (build/tests/fuzz/fuzz_remesh FILE) before
# calling it a hang (docs/reliability.md, Fuzzing).
#
# Builds with clang (Debian's clang + libclang-rt-14-dev) in build-fuzz/ with
# ASan+UBSan and libFuzzer coverage on every library. Seeds come from
# tests/fuzz/corpus/<target>/ (read only); the growing corpus goes to
# build-fuzz/corpus/<target>/; crashes and hangs to build-fuzz/artifacts/.
# Every crash or hang found must be copied into tests/fuzz/corpus/<target>/ as
# a regression input (CI replays that folder) and fixed.
set -euo pipefail
cd "$(dirname "$0")/.."
secs="${1:-120}"
limit="${FUZZ_TIMEOUT:-10}"
shift || true
targets=("${@:-config profile_csv remesh}")
read -r -a targets <<< "${targets[*]}"

for p in clang libclang-rt-14-dev; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || {
    echo "fuzz.sh: install $p (apt-get install -y $p)" >&2; exit 1; }
done

cmake -S . -B build-fuzz -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DLINERLIFE_FUZZ=ON -DCMAKE_CXX_FLAGS="-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize=vptr" >/dev/null
cmake --build build-fuzz -j "$(nproc)" --target $(printf 'fuzz_%s ' "${targets[@]}") >/dev/null

mkdir -p build-fuzz/artifacts
for t in "${targets[@]}"; do
  mkdir -p "build-fuzz/corpus/$t"
  log="build-fuzz/fuzz_$t.log"
  t0=$(date +%s)
  ASAN_OPTIONS=detect_leaks=1 ./build-fuzz/tests/fuzz/fuzz_$t -max_total_time="$secs" -timeout="$limit" -rss_limit_mb=4096 \
    -artifact_prefix="build-fuzz/artifacts/${t}-" -print_final_stats=1 \
    "build-fuzz/corpus/$t" "tests/fuzz/corpus/$t" >"$log" 2>&1 || true
  ran=$(( $(date +%s) - t0 ))
  execs=$(grep -E '^stat::number_of_executed_units' "$log" | awk '{print $2}')
  found=$(ls build-fuzz/artifacts/ 2>/dev/null | grep -c "^${t}-" || true)
  # libFuzzer stops at its first finding, so the run may be shorter than asked
  echo "$t: ${execs:-?} executions in ${ran} s (asked ${secs} s), corpus $(ls build-fuzz/corpus/$t | wc -l) inputs, findings: $found (log $log)"
done
