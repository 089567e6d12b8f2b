#!/usr/bin/env bash
# Wall time of the default forecast (bundled Qiu mill, layer model, whole life
# to a criterion, one core) for docs/benchmarks.md (## Forecast): median of
# REPS runs, with the share spent in charge drives and the 1-minute load.
#
#   bench/forecast_bench.sh [BUILD_DIR=build] [REPS=5] [CONFIG]
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD="${1:-build}"
REPS="${2:-5}"
CONFIG="${3:-}"
BIN="$BUILD/app/linerlife"
test -x "$BIN" || { echo "build $BIN first (scripts/setup.sh)" >&2; exit 1; }
echo "machine: $(lscpu | sed -n 's/^Model name: *//p'), $(nproc) cores; load at start: $(cut -d' ' -f1-3 /proc/loadavg)"
walls=()
for i in $(seq "$REPS"); do
  out=$(OMP_NUM_THREADS=1 "$BIN" forecast $CONFIG --json --quiet)
  line=$(printf '%s' "$out" | /usr/bin/python3 -c '
import json, sys
d = json.load(sys.stdin)
print("%.2f %.0f %s %d %d %d" % (d["wall_s"], d["operating_hours"], d["criterion"], d["charge_redrives"],
                                 d["cvode_steps"], d["rhs_evals"]))')
  set -- $line
  walls+=("$1")
  echo "run $i: wall $1 s, life $2 h ($3), $4 drives, $5 CVODE steps, $6 rhs; load $(cut -d' ' -f1 /proc/loadavg)"
done
printf '%s\n' "${walls[@]}" | sort -g | awk '{a[NR]=$1} END {m = NR % 2 ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2; printf "median wall %.2f s over %d runs\n", m, NR}'
