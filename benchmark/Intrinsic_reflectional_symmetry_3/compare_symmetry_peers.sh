#!/usr/bin/env bash
# Side by side on the FAUST shapes: our symmetric map (written by
# symmetry_map_benchmark --write) against the two peer baselines of the shared
# evaluation tools (GPS sign flips, Ovsjanikov et al. 2008; best extrinsic
# mirror plane), all scored by the same reference evaluator (eval_symmetry.py,
# protocol of Kim et al. 2010). Also a cross-check of our own C++ metric.
#   bash compare_symmetry_peers.sh BUILD_DIR [SHARED_DIR] [OUT_DIR]
# SHARED_DIR defaults to ../shared next to the repository; skips cleanly if absent.
set -euo pipefail
py=${PYTHON:-/usr/bin/python3} # the tools need Debian's numpy and scipy
here=$(cd "$(dirname "$0")" && pwd)
build=$(cd "${1:?usage: compare_symmetry_peers.sh BUILD_DIR [SHARED_DIR] [OUT_DIR]}" && pwd)
shared=${2:-$here/../../../shared}
out=${3:-$(mktemp -d)}
faust=$shared/data/faust_5k/faust
tools=$shared/tools
if [ ! -d "$faust" ] || [ ! -f "$tools/eval_symmetry.py" ]; then
  echo "compare_symmetry_peers: $faust or $tools absent, skipped"; exit 0
fi
mkdir -p "$out"
"$build/benchmark/Intrinsic_reflectional_symmetry_3/symmetry_map_benchmark" "$shared/data" --no-scape \
  --write "$out" > "$out/ours_cpp.txt"
cr() { "$py" "$tools/eval_symmetry.py" "$faust/$1.off" "$faust/corres/$1.vts" "$faust/corres/$1.sym.vts" "$2" --json \
       | "$py" -c 'import json,sys; print("%.2f" % json.loads(sys.stdin.read())["CR"])'; }
printf "%-12s %10s %10s %10s %10s\n" shape ours ours_cpp GPS extrinsic
for off in "$faust"/*.off; do
  name=$(basename "$off" .off)
  [ -f "$out/$name.gps.map" ] || "$py" "$tools/baseline_gps.py" "$off" "$out/$name.gps.map" > /dev/null
  [ -f "$out/$name.ext.map" ] || "$py" "$tools/baseline_extrinsic.py" "$off" "$out/$name.ext.map" > /dev/null
  cpp=$(awk -v n="$name" '$1 == n { print $6 }' "$out/ours_cpp.txt")
  printf "%-12s %10s %10s %10s %10s\n" "$name" "$(cr "$name" "$out/$name.map")" "$cpp" \
    "$(cr "$name" "$out/$name.gps.map")" "$(cr "$name" "$out/$name.ext.map")"
done | tee "$out/table.txt"
awk '{ for(i = 2; i <= 5; ++i) s[i] += $i; n++ }
     END { printf "%-12s %10.2f %10.2f %10.2f %10.2f   (mean CR %%, n=%d)\n", "mean", s[2]/n, s[3]/n, s[4]/n, s[5]/n, n }' \
  "$out/table.txt"
