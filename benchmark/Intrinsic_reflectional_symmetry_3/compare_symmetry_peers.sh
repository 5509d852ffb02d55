#!/usr/bin/env bash
# Side by side on the FAUST shapes and the SCAPE meshes (and, with --psb, the
# PSB models that Kim et al.'s "Watertight" set gives symmetric feature points):
# our symmetric map
# (written by symmetry_map_benchmark --write) against the two peer baselines of
# the shared evaluation tools (GPS sign flips, Ovsjanikov et al. 2008; best
# extrinsic mirror plane), all scored by the same reference evaluator
# (eval_symmetry.py, protocol of Kim et al. 2010). Also a cross-check of our own
# C++ metric. On SCAPE every method runs on the mesh our benchmark writes (its
# pinched vertex split by repair_input()), with the ground truth written with it.
#   bash compare_symmetry_peers.sh BUILD_DIR [SHARED_DIR] [OUT_DIR] [BENCHMARK_OPTION...]
# SHARED_DIR defaults to ../shared next to the repository; each collection is
# skipped cleanly if absent, or when the options say --no-faust or --no-scape;
# PSB runs only with --psb (its table gives the mean per category).
# The options go to symmetry_map_benchmark (--samples, --seed, --tries, ...).
# With --noise or --holes every method runs on the perturbed mesh the benchmark
# writes, with the ground truth carried over to it (robustness side by side).
set -euo pipefail
py=${PYTHON:-/usr/bin/python3} # the tools need Debian's numpy and scipy
here=$(cd "$(dirname "$0")" && pwd)
build=$(cd "${1:?usage: compare_symmetry_peers.sh BUILD_DIR [SHARED_DIR] [OUT_DIR] [BENCHMARK_OPTION...]}" && pwd)
shared=${2:-$here/../../../shared}
out=${3:-$(mktemp -d)}
shift $(( $# < 3 ? $# : 3 ))
options=("$@")
has_option() { local a; for a in "${options[@]}"; do [ "$a" = "$1" ] && return 0; done; return 1; }
run_options=() # the options without --psb, which each collection's run sets itself
for a in "${options[@]}"; do [ "$a" = --psb ] || run_options+=("$a"); done
tools=$shared/tools
bench="$build/benchmark/Intrinsic_reflectional_symmetry_3/symmetry_map_benchmark"
if [ ! -f "$tools/eval_symmetry.py" ]; then
  echo "compare_symmetry_peers: $tools absent, skipped"; exit 0
fi

# side_by_side MESH_DIR GT_DIR MAP_DIR: one row per mesh of MESH_DIR, the CR of
# our map, of our C++ metric (MAP_DIR/ours_cpp.txt), of GPS and of the plane
side_by_side() {
  local meshes=$1 gt=$2 maps=$3
  cr() { "$py" "$tools/eval_symmetry.py" "$meshes/$1.off" "$gt/$1.vts" "$gt/$1.sym.vts" "$2" --json \
         | "$py" -c 'import json,sys; print("%.2f" % json.loads(sys.stdin.read())["CR"])'; }
  printf "%-14s %10s %10s %10s %10s\n" shape ours ours_cpp GPS extrinsic
  for off in "$meshes"/*.off; do
    local name
    name=$(basename "$off" .off)
    [ -f "$maps/$name.map" ] || continue
    [ -f "$maps/$name.gps.map" ] || "$py" "$tools/baseline_gps.py" "$off" "$maps/$name.gps.map" > /dev/null
    [ -f "$maps/$name.ext.map" ] || "$py" "$tools/baseline_extrinsic.py" "$off" "$maps/$name.ext.map" > /dev/null
    printf "%-14s %10s %10s %10s %10s\n" "$name" "$(cr "$name" "$maps/$name.map")" \
      "$(awk -v n="$name" '$1 == n { print $6 }' "$maps/ours_cpp.txt")" \
      "$(cr "$name" "$maps/$name.gps.map")" "$(cr "$name" "$maps/$name.ext.map")"
  done | tee "$maps/table.txt"
}

# means of the columns of a table, over all rows and by group: for FAUST
# ("faust"), pose 0 of each subject (tr_reg_0X0), the posed shapes
# (tr_reg_001..009, all of subject 0) and their own pose 0 (tr_reg_000); for
# PSB ("category"), the category, the name's part before "_"
means() {
  awk -v groups="$2" '
    function add(g) { for(i = 2; i <= 5; ++i) s[g, i] += $i; n[g]++ }
    function line(g, label) { if(n[g]) printf "%-14s %10.2f %10.2f %10.2f %10.2f   (mean CR %%, n=%d)\n",
                                label, s[g, 2]/n[g], s[g, 3]/n[g], s[g, 4]/n[g], s[g, 5]/n[g], n[g] }
    { add("all") }
    groups == "faust" { id = substr($1, length($1) - 2) + 0; add(id % 10 == 0 ? "rest" : "posed"); if(id == 0) add("own") }
    groups == "category" { c = $1; sub(/_.*/, "", c); if(!(c in seen)) { seen[c] = 1; order[++k] = c } add(c) }
    END { for(j = 1; j <= k; ++j) line(order[j], order[j]);
          line("all", "mean"); line("rest", "pose 0"); line("posed", "posed"); line("own", "tr_reg_000") }' "$1"
}

mkdir -p "$out"
faust=$shared/data/faust_5k/faust
if has_option --no-faust; then
  echo "FAUST: --no-faust, skipped"
elif [ -d "$faust" ]; then
  echo "FAUST ($faust)"
  "$bench" "$shared/data" --no-scape "${run_options[@]}" --write "$out" > "$out/ours_cpp.txt"
  if has_option --noise || has_option --holes; then
    side_by_side "$out" "$out" "$out" # the perturbed meshes and their ground truth
  else
    side_by_side "$faust" "$faust/corres" "$out"
  fi
  means "$out/table.txt" faust
else
  echo "FAUST: $faust absent, skipped"
fi

scape=$shared/data/kim_bim_benchmark/scape
if has_option --no-scape; then
  echo; echo "SCAPE: --no-scape, skipped"
elif [ -d "$scape/meshes" ]; then
  echo; echo "SCAPE ($scape, sparse ground truth: 44 checks per mesh)"
  mkdir -p "$out/scape"
  "$bench" "$shared/data" --no-faust "${run_options[@]}" --write "$out/scape" > "$out/scape/ours_cpp.txt"
  side_by_side "$out/scape" "$out/scape" "$out/scape"
  means "$out/scape/table.txt" ""
else
  echo "SCAPE: $scape/meshes absent, skipped"
fi

psb=$shared/data/psb
if ! has_option --psb; then
  echo; echo "PSB: run only with --psb"
elif [ -d "$psb/off" ] && [ -d "$psb/sym_gt" ]; then
  echo; echo "PSB ($psb, Kim et al.'s symmetric feature points; octopus, table and vase skipped)"
  mkdir -p "$out/psb"
  "$bench" "$shared/data" --no-faust --no-scape --psb "${run_options[@]}" --write "$out/psb" > "$out/psb/ours_cpp.txt"
  side_by_side "$out/psb" "$out/psb" "$out/psb"
  means "$out/psb/table.txt" category
else
  echo "PSB: $psb/off or $psb/sym_gt absent, skipped"
fi
