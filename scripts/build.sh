#!/usr/bin/env bash
# Configure and build everything in Release; unpack CGAL's meshes (libcgal-demo)
# next to the build so that tests and benchmarks can use them.
#   bash scripts/build.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
jobs=$(nproc 2>/dev/null || echo 2)

cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release > "$build.configure.log" 2>&1 \
  || { cat "$build.configure.log"; exit 1; }
cmake --build "$build" -j "$jobs"

tarball=/usr/share/doc/libcgal-dev/data.tar.gz
if [ -f "$tarball" ] && [ ! -d "$build/cgal_data/meshes" ]; then
  mkdir -p "$build/cgal_data"
  tar -xzf "$tarball" -C "$build/cgal_data" --strip-components=1 data/meshes
fi
