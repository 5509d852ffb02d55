#!/usr/bin/env bash
# Command (a) of the README: install what is missing (Debian 12), build in
# Release, and run the command-line tool on a shape the project generates.
#   bash scripts/setup.sh [BUILD_DIR]        (as root, or a user with sudo)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}

bash scripts/install_packages.sh
bash scripts/build.sh "$build"

out=out/demo
echo "== running: $build/cli/irsym --shape two_snowmen --out $out"
"$build/cli/irsym" --shape two_snowmen --out "$out"
echo "== outputs in $(pwd)/$out:"
ls -1 "$out"
