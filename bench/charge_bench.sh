#!/usr/bin/env bash
# Charge-model speed figures for docs/benchmarks.md (## Charge models): the
# real-time study of thesis §3.2.2 (Figs. 3-3/3-4) for the layer model V-1.2.
#
#   bench/charge_bench.sh [BUILD_DIR=build] [RUNS=5] [REVOLUTIONS=0]
#
# The 13 industrial cases (the Qiu mill and, one at a time, speed, charge
# volume, steel volume, media size, number of lifters and diameter at +/-25 %)
# and the 16 pilot tests; liner-load accumulation on (the layer model always
# accumulates loads and impacts); one thread (the model is single-threaded);
# median of RUNS runs per case, the runs going round all cases in turn so that
# a burst of other work on this shared machine spreads over the cases.
# REVOLUTIONS 0 keeps the model's default (2 averaged after 1 settling); 51
# gives the thesis' run length (§3.2.2: 300 s of the Qiu mill, 52 revolutions).
# Prints the machine, the load average before and after, and the table.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD="${1:-build}"
RUNS="${2:-5}"
REVS="${3:-0}"
BIN="$BUILD/bench/bench_charge_realtime"
test -x "$BIN" || { echo "build $BIN first (cmake --build $BUILD --target bench_charge_realtime)" >&2; exit 1; }

echo "## machine"
lscpu | grep -E "Model name|^CPU\(s\)|Thread|L2|L3" || true
echo "commit $(git rev-parse --short HEAD)$(git diff --quiet || echo ' (modified)')"
echo "uptime at the start: $(uptime)"
echo
"$BIN" "$RUNS" "$REVS"
echo
echo "uptime at the end: $(uptime)"
