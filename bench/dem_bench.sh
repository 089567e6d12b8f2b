#!/usr/bin/env bash
# DEM speed figures for docs/benchmarks.md (## DEM): medians of REPS runs.
#
#   bench/dem_bench.sh [BUILD_DIR=build] [REPS=5]
#
# 1. particle-steps/s and contacts/s against particle count (1k to 20k discs),
#    1 and 2 threads (bench_dem scaling);
# 2. real-time ratio of the whole dem model on pilot test 1 and the Qiu slice,
#    1 and 2 threads (bench_dem realtime).
# Prints `lscpu` and the load average first: the machine is shared, so the
# medians are what to quote.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD="${1:-build}"
REPS="${2:-5}"
BIN="$BUILD/bench/bench_dem"
test -x "$BIN" || { echo "build $BIN first (cmake --build $BUILD --target bench_dem)" >&2; exit 1; }

median() { sort -g | awk '{a[NR]=$1} END {if (NR % 2) print a[(NR+1)/2]; else print (a[NR/2]+a[NR/2+1])/2}'; }
field() { awk -v k="$1" '{for (i = 1; i < NF; i++) if ($i == k) print $(i+1)}'; }

echo "## machine"
lscpu | grep -E "Model name|^CPU\(s\)|Thread|L2|L3" || true
echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
echo
echo "## particle-steps/s against particle count (median of $REPS)"
echo "| discs | threads | particle-steps/s | contacts/s | time step [s] |"
echo "|---|---|---|---|---|"
for n in 1000 2000 5000 10000 20000; do
  for t in 1 2; do
    out=$("$BIN" scaling "$n" "$t" "$REPS")
    p=$(echo "$out" | field particles | head -1)
    ps=$(echo "$out" | field particle_steps_per_s | median)
    cs=$(echo "$out" | field contacts_per_s | median)
    dt=$(echo "$out" | field dt | head -1)
    printf "| %s | %s | %.3g | %.3g | %.3g |\n" "$p" "$t" "$ps" "$cs" "$dt"
  done
done
echo
echo "## real-time ratio of the dem model (median of $REPS; settle 1 revolution, average 1)"
echo "| mill | discs | threads | simulated [s] | wall [s] | real-time ratio | particle-steps/s |"
echo "|---|---|---|---|---|---|---|"
for cfg in data/mills/pilot_test_01.toml data/mills/qiu2001_sag.toml; do
  for t in 1 2; do
    out=$("$BIN" realtime "$cfg" "$t" "$REPS")
    p=$(echo "$out" | field particles | head -1)
    sim=$(echo "$out" | field simulated_s | head -1)
    wall=$(echo "$out" | field wall_s | median)
    rt=$(echo "$out" | field realtime_ratio | median)
    ps=$(echo "$out" | field particle_steps_per_s | median)
    printf "| %s | %s | %s | %.2f | %.2f | %.2f | %.3g |\n" "$(basename "$cfg" .toml)" "$p" "$t" "$sim" "$wall" "$rt" "$ps"
  done
done
echo
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
