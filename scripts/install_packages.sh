#!/usr/bin/env bash
# Installs the Debian 12 packages the project needs that are missing (as root,
# or a user with sudo). Does nothing when all are present.
#   bash scripts/install_packages.sh
set -euo pipefail

packages=(g++ make cmake libcgal-dev libeigen3-dev libspectra-dev libboost-dev libtbb-dev libgmp-dev libmpfr-dev
          libgtest-dev libcgal-demo f3d xvfb xauth
          python3-numpy python3-scipy # the shared evaluation tools (benchmarks only)
          python3-pil) # side-by-side figures (scripts/make_figures.sh)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "== all packages present"
  exit 0
fi
echo "== installing: ${missing[*]}"
sudo=""; [ "$(id -u)" -ne 0 ] && sudo="sudo"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
