#!/usr/bin/env bash
# Command (a) of the README: install what is missing (Debian 12), build in
# Release, and run the command-line tool on a shape the project generates.
#   bash scripts/setup.sh [BUILD_DIR]        (as root, or a user with sudo)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}

packages=(g++ make cmake libcgal-dev libeigen3-dev libboost-dev libtbb-dev libgmp-dev libmpfr-dev
          libgtest-dev libcgal-demo f3d xvfb xauth
          python3-numpy python3-scipy # the shared evaluation tools (benchmarks only)
          python3-pil) # side-by-side figures (scripts/make_figures.sh)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "== installing: ${missing[*]}"
  sudo=""; [ "$(id -u)" -ne 0 ] && sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
else
  echo "== all packages present"
fi

bash scripts/build.sh "$build"

out=out/demo
echo "== running: $build/cli/irsym --shape two_snowmen --out $out"
"$build/cli/irsym" --shape two_snowmen --out "$out"
echo "== outputs in $(pwd)/$out:"
ls -1 "$out"
