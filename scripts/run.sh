#!/usr/bin/env bash
# Quick start 1: set up (install what is missing, build), then run the main job
# on the bundled default mill (the Qiu 2001 SAG mill). Extra arguments go to
# the command, e.g. `scripts/run.sh --json`.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
exec "${LINERLIFE_BUILD_DIR:-build}/app/linerlife" geometry "$@"
