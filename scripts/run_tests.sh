#!/usr/bin/env bash
# Command (b) of the README: build (Release) and run the whole test suite.
#   bash scripts/run_tests.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
bash scripts/build.sh "$build"
cd "$build"
ctest --output-on-failure -j "$(nproc 2>/dev/null || echo 2)" --timeout 900
