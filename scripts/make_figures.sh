#!/usr/bin/env bash
# Regenerates the figures of the user manual (doc/.../fig/) with the project's
# own tool on generated shapes, CGAL's meshes and, where SHARED_DIR holds the
# FAUST shapes (data/faust_5k), a posed human. Needs f3d and xvfb-run
# (installed by setup.sh).
#   bash scripts/make_figures.sh [BUILD_DIR] [SHARED_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
shared=${2:-}
fig=doc/Intrinsic_reflectional_symmetry_3/fig
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$fig"

# --tries 1: the pictures of seed 1, although its map is suspect and irsym would
# otherwise keep the run of seed 2 (the samples, hence geodesics.png and transform.png, differ)
"$build/cli/irsym" --shape two_snowmen --out "$tmp/two_snowmen" --seed 1 --tries 1
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

# side-by-side pictures: each panel rendered by f3d (render PLY_OR_OFF PNG F3D_OPTIONS...),
# then put next to each other with a title under each (python3-pil)
render() {
  xvfb-run -a -s '-screen 0 1280x1024x24' f3d --quiet --no-background=0 --resolution=500,560 \
    "${@:3}" --output="$2" "$1" > /dev/null 2>&1
}
grey_ply() { # IN.off OUT.ply: the mesh in the grey of irsym's PLY files, so that both panels look alike
  /usr/bin/python3 - "$@" <<'PY'
import sys
words = [w for line in open(sys.argv[1]) for w in line.split("#")[0].split()]
nv, nf = int(words[1]), int(words[2])
with open(sys.argv[2], "w") as out:
    out.write("ply\nformat ascii 1.0\nelement vertex %d\nproperty float x\nproperty float y\nproperty float z\n"
              "property uchar red\nproperty uchar green\nproperty uchar blue\nelement face %d\n"
              "property list uchar int vertex_indices\nend_header\n" % (nv, nf))
    for i in range(nv):
        out.write(" ".join(words[4 + 3 * i:7 + 3 * i]) + " 200 200 200\n")
    k = 4 + 3 * nv
    for _ in range(nf):
        n = int(words[k]); out.write(" ".join(words[k:k + n + 1]) + "\n"); k += n + 1
PY
}
side_by_side() { # OUT.png LEFT.png "left title" RIGHT.png "right title"
  /usr/bin/python3 - "$@" <<'PY'
import sys
from PIL import Image, ImageDraw, ImageFont
out, panels = sys.argv[1], [(sys.argv[2], sys.argv[3]), (sys.argv[4], sys.argv[5])]
try:
    font = ImageFont.truetype("/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf", 24)
except OSError:
    font = ImageFont.load_default()
images = [Image.open(p).convert("RGB") for p, _ in panels]
w, h = images[0].size
canvas = Image.new("RGB", (2 * w, h + 40), images[0].getpixel((0, 0)))
draw = ImageDraw.Draw(canvas)
for k, (image, (_, title)) in enumerate(zip(images, panels)):
    canvas.paste(image, (k * w, 0))
    tw = draw.textlength(title, font=font)
    draw.text((k * w + (w - tw) / 2, h + 4), title, fill=(235, 235, 235), font=font)
canvas.quantize(colors=256, method=Image.Quantize.MEDIANCUT).save(out, optimize=True)
PY
}

# Part repair (irsym --repair): the stick figure with its right arm cut off and
# capped (before), and repaired from its left arm (after; added vertices orange).
# The same fixed camera for both, so that the two panels compare.
"$build/cli/irsym" --shape stick_figure_missing_arm --repair --samples 400 --out "$tmp/repair"
grey_ply "$tmp/repair/stick_figure_missing_arm.off" "$tmp/before.ply"
camera=(--up=+Z --camera-position=3.6,-9,0.9 --camera-focal-point=0,0,-0.75 --camera-view-up=0,0,1)
render "$tmp/before.ply" "$tmp/before.png" "${camera[@]}" --scalars=RGB --comp=-2
render "$tmp/repair/repaired.ply" "$tmp/after.png" "${camera[@]}" --scalars=RGB --comp=-2
side_by_side "$fig/repair_before_after.png" "$tmp/before.png" "right arm cut off" \
  "$tmp/after.png" "irsym --repair"

# Segmentation (segmentation_example on CGAL's camel): ours and CGAL's SDF
# segmentation with the same number of segments, one colour per face
example="$build/examples/Intrinsic_reflectional_symmetry_3/segmentation_example"
if [ -f "$tarball" ] && [ -x "$example" ]; then
  mkdir -p "$tmp/segmentation"
  "$example" "$tmp/data/meshes/camel.off" "$tmp/segmentation"
  view=(--up=+Y --camera-azimuth-angle=50 --cells --scalars=RGBA --comp=-2)
  render "$tmp/segmentation/symmetry_segmentation.ply" "$tmp/ours.png" "${view[@]}"
  render "$tmp/segmentation/sdf_segmentation.ply" "$tmp/sdf.png" "${view[@]}"
  side_by_side "$fig/camel_segmentation.png" "$tmp/ours.png" "symmetry-aware segmentation" \
    "$tmp/sdf.png" "CGAL's SDF segmentation, same count"
fi

# The symmetric map on a posed human (FAUST tr_reg_007, whose pose breaks the
# mirror plane): curves and regions, and the map (partners share a colour)
faust=${shared:+$shared/data/faust_5k/faust/tr_reg_007.off}
if [ -n "$faust" ] && [ -f "$faust" ]; then
  "$build/cli/irsym" "$faust" --samples 1250 --seed 0 --up +Y --out "$tmp/faust"
  view=(--up=+Y --camera-azimuth-angle=20 --scalars=RGB --comp=-2)
  render "$tmp/faust/curves.ply" "$tmp/faust_curves.png" "${view[@]}"
  render "$tmp/faust/symmetric_map.ply" "$tmp/faust_map.png" "${view[@]}"
  side_by_side "$fig/faust_symmetric_map.png" "$tmp/faust_curves.png" "IRSA curve and its region" \
    "$tmp/faust_map.png" "symmetric map: partners share a colour"
fi

ls -l "$fig"
