#!/usr/bin/env bash
# Quick start 1: set up (install what is missing, build), then run the main job
# on the bundled default mill (the Qiu 2001 SAG mill). Extra arguments go to
# the command, e.g. `scripts/run.sh --json`. The forecast of the bundled mill
# (layer charge model, whole liner life) takes about 10 s on a 2-core machine
# once built (docs/benchmarks.md, "Forecast") and writes results/forecast.h5
# and its charts.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
exec "${LINERLIFE_BUILD_DIR:-build}/app/linerlife" forecast --out results "$@"
