#!/usr/bin/env bash
# Quick start 2: set up (install what is missing, build), then run the whole
# default test suite. Tests tagged [slow] are excluded here; run them with
# `ctest --test-dir build -L slow` (README.md, "Layout").
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
ctest --test-dir "${LINERLIFE_BUILD_DIR:-build}" -LE slow -j "$(nproc 2>/dev/null || echo 2)" --output-on-failure
