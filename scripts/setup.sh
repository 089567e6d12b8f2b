#!/usr/bin/env bash
# Idempotent set-up: installs the Debian 12 packages linerlife needs that are
# missing (as root, or through sudo; otherwise says what to install), then
# configures and builds linerlife (Release) in build/.
#
#   scripts/setup.sh            # install what is missing, build
#   LINERLIFE_BUILD_DIR=dir     # build somewhere else
#   LINERLIFE_CMAKE_ARGS="..."  # more CMake arguments (scripts/sanitize.sh)
set -euo pipefail
cd "$(dirname "$0")/.."

PACKAGES=(
  g++ cmake make pkg-config git
  libeigen3-dev libsundials-dev libcgal-dev libhdf5-dev catch2
  libtomlplusplus-dev libcli11-dev libfmt-dev
  python3-matplotlib python3-h5py
)

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -gt 0 ]; then
  if [ "$(id -u)" -eq 0 ]; then
    SUDO=""
  elif command -v sudo >/dev/null 2>&1 && sudo -n true 2>/dev/null; then
    SUDO="sudo"
  else
    echo "linerlife setup: these Debian packages are missing and this user cannot install them:" >&2
    echo "  ${missing[*]}" >&2
    echo "Ask an administrator to run:" >&2
    echo "  apt-get update && apt-get install -y ${missing[*]}" >&2
    exit 1
  fi
  echo "linerlife setup: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

BUILD_DIR="${LINERLIFE_BUILD_DIR:-build}"
jobs=$(nproc 2>/dev/null || echo 2)
# shellcheck disable=SC2086  # LINERLIFE_CMAKE_ARGS is a list of arguments
cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release ${LINERLIFE_CMAKE_ARGS:-} >/dev/null
cmake --build "$BUILD_DIR" -j "$jobs" -- --no-print-directory 2>&1 | grep -Ev '^\[ *[0-9]+%\]|^Consolidate compiler|^Scanning dependencies' || true
test -x "$BUILD_DIR/app/linerlife" || { echo "linerlife setup: the build failed" >&2; exit 1; }
echo "linerlife setup: built $BUILD_DIR/app/linerlife"
