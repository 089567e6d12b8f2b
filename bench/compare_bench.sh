#!/usr/bin/env bash
# Wall time of `linerlife compare` one forecast at a time (--jobs 1) against
# JOBS at once, alternating, for docs/benchmarks.md (## Forecast, "Comparing
# designs"): the bundled Qiu mill over four lifter heights by default. Each
# pair's JSON must be identical (the cases' results do not depend on --jobs);
# the script stops if they are not.
#
#   bench/compare_bench.sh [BUILD_DIR=build] [REPS=3] [JOBS=2] [VARY=liner.lifter_height_m=0.21,0.23,0.25,0.27]
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD="${1:-build}"
REPS="${2:-3}"
JOBS="${3:-2}"
VARY="${4:-liner.lifter_height_m=0.21,0.23,0.25,0.27}"
BIN="$BUILD/app/linerlife"
test -x "$BIN" || { echo "build $BIN first (scripts/setup.sh)" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "machine: $(lscpu | sed -n 's/^Model name: *//p'), $(nproc) cores; load at start: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "compare --vary $VARY"
one=()
many=()
for i in $(seq "$REPS"); do
  for j in 1 "$JOBS"; do
    t0=$(date +%s.%N)
    "$BIN" compare --vary "$VARY" --json --jobs "$j" >"$tmp/j$j.json" 2>/dev/null
    t1=$(date +%s.%N)
    w=$(awk -v a="$t0" -v b="$t1" 'BEGIN {print b - a}')
    if [ "$j" = 1 ]; then one+=("$w"); else many+=("$w"); fi
    printf 'run %d, --jobs %s: wall %.2f s; load %s\n' "$i" "$j" "$w" "$(cut -d' ' -f1 /proc/loadavg)"
  done
  cmp -s "$tmp/j1.json" "$tmp/j$JOBS.json" || { echo "run $i: --jobs 1 and --jobs $JOBS differ" >&2; exit 1; }
done
median() { printf '%s\n' "$@" | sort -g | awk '{a[NR]=$1} END {print NR % 2 ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2}'; }
m1=$(median "${one[@]}")
mj=$(median "${many[@]}")
printf 'median wall: --jobs 1 %.2f s, --jobs %s %.2f s (x %.2f); results identical in every pair\n' "$m1" "$JOBS" "$mj" \
  "$(awk -v a="$m1" -v b="$mj" 'BEGIN {print a / b}')"
