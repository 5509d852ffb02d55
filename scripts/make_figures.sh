#!/usr/bin/env bash
# Regenerates the figures of the user manual (doc/.../fig/) with the project's
# own tool on generated shapes. Needs f3d and xvfb-run (installed by setup.sh).
#   bash scripts/make_figures.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
fig=doc/Intrinsic_reflectional_symmetry_3/fig
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$fig"

"$build/cli/irsym" --shape two_snowmen --out "$tmp/two_snowmen" --seed 1
for f in sdf geodesics transform; do
  [ -f "$tmp/two_snowmen/$f.png" ] && cp "$tmp/two_snowmen/$f.png" "$fig/two_snowmen_$f.png"
done
"$build/cli/irsym" --shape bent_capsule --out "$tmp/bent_capsule" --seed 1
[ -f "$tmp/bent_capsule/transform.png" ] && cp "$tmp/bent_capsule/transform.png" "$fig/bent_capsule_transform.png"
# CGAL's camel (libcgal-demo, installed by setup.sh)
tarball=/usr/share/doc/libcgal-dev/data.tar.gz
if [ -f "$tarball" ]; then
  tar -xzf "$tarball" -C "$tmp" data/meshes/camel.off
  "$build/cli/irsym" "$tmp/data/meshes/camel.off" --samples 1500 --up +Y --out "$tmp/camel"
  [ -f "$tmp/camel/curves.png" ] && cp "$tmp/camel/curves.png" "$fig/camel_curves.png"
fi
ls -l "$fig"
