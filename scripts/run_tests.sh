#!/usr/bin/env bash
# Command (b) of the README: install what is missing, build (Release) and run
# the whole test suite.
#   bash scripts/run_tests.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
# On a fresh machine this installs what command (a) would; where packages are
# missing and cannot be installed, the build below names what it lacks.
bash scripts/install_packages.sh || echo "== could not install the missing packages; trying to build anyway"
bash scripts/build.sh "$build"
cd "$build"
ctest --output-on-failure -j "$(nproc 2>/dev/null || echo 2)" --timeout 900
