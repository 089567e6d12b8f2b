#!/usr/bin/env bash
# DEM speed figures for docs/benchmarks.md (## DEM): medians of REPS runs.
#
#   bench/dem_bench.sh [BUILD_DIR=build] [REPS=5]
#
# 1. particle-steps/s and contacts/s against particle count (1k to 20k discs),
#    1 and 2 threads (bench_dem scaling);
# 2. real-time ratio of the whole dem model on pilot test 1 and the Qiu slice,
#    1 thread, 2 threads and threads = 0 (adaptive) (bench_dem realtime).
# The machine is shared: the repetitions go round all cases in turn, so a
# burst of other work spreads over the cases instead of spoiling one, and the
# 1-minute load average is printed with every case.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD="${1:-build}"
REPS="${2:-5}"
BIN="$BUILD/bench/bench_dem"
test -x "$BIN" || { echo "build $BIN first (cmake --build $BUILD --target bench_dem)" >&2; exit 1; }
RAW=$(mktemp)
trap 'rm -f "$RAW"' EXIT

median() { sort -g | awk '{a[NR]=$1} END {if (NR % 2) print a[(NR+1)/2]; else print (a[NR/2]+a[NR/2+1])/2}'; }
field() { awk -v k="$1" '{for (i = 1; i < NF; i++) if ($i == k) print $(i+1)}'; }
load() { cut -d' ' -f1 /proc/loadavg; }

echo "## machine"
lscpu | grep -E "Model name|^CPU\(s\)|Thread|L2|L3" || true
echo "load average at the start: $(cut -d' ' -f1-3 /proc/loadavg)"

SIZES="1000 2000 5000 10000 20000"
CONFIGS="data/mills/pilot_test_01.toml data/mills/qiu2001_sag.toml"
for rep in $(seq 1 "$REPS"); do
  for n in $SIZES; do
    for t in 1 2; do
      echo "case scaling-$n-$t load $(load) $("$BIN" scaling "$n" "$t" 1)" >> "$RAW"
    done
  done
  for cfg in $CONFIGS; do
    for t in 1 2 0; do
      echo "case realtime-$(basename "$cfg" .toml)-$t load $(load) $("$BIN" realtime "$cfg" "$t" 1)" >> "$RAW"
    done
  done
done

echo
echo "## particle-steps/s against particle count (median of $REPS; 2000 steps after 1.5 s of mill time)"
echo "| discs | threads | particle-steps/s | contacts/s | time step [s] | load average (median) |"
echo "|---|---|---|---|---|---|"
for n in $SIZES; do
  for t in 1 2; do
    rows=$(grep "case scaling-$n-$t " "$RAW")
    printf "| %s | %s | %.3g | %.3g | %.3g | %s |\n" "$(echo "$rows" | field particles | head -1)" "$t" \
      "$(echo "$rows" | field particle_steps_per_s | median)" "$(echo "$rows" | field contacts_per_s | median)" \
      "$(echo "$rows" | field dt | head -1)" "$(echo "$rows" | field load | median)"
  done
done
echo
echo "## real-time ratio of the dem model (median of $REPS; settle 1 revolution, average 1; threads 0 = adaptive)"
echo "| mill | discs | threads | simulated [s] | wall [s] | real-time ratio | particle-steps/s | load average (median) |"
echo "|---|---|---|---|---|---|---|---|"
for cfg in $CONFIGS; do
  name=$(basename "$cfg" .toml)
  for t in 1 2 0; do
    rows=$(grep "case realtime-$name-$t " "$RAW")
    printf "| %s | %s | %s | %.2f | %.2f | %.2f | %.3g | %s |\n" "$name" "$(echo "$rows" | field particles | head -1)" "$t" \
      "$(echo "$rows" | field simulated_s | head -1)" "$(echo "$rows" | field wall_s | median)" \
      "$(echo "$rows" | field realtime_ratio | median)" "$(echo "$rows" | field particle_steps_per_s | median)" \
      "$(echo "$rows" | field load | median)"
  done
done
echo
echo "load average at the end: $(cut -d' ' -f1-3 /proc/loadavg)"
echo
echo "## every run"
sed 's/^case //' "$RAW"
