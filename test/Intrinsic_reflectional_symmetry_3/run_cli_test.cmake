# End-to-end test of the irsym tool: a generated shape gives every output file
# and a well-formed report; bad input and bad usage give clear errors and the
# documented exit codes, never a crash.
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})

function(run expected_rc)
  execute_process(COMMAND ${IRSYM} ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT "${rc}" STREQUAL "${expected_rc}")
    message(FATAL_ERROR "irsym ${ARGN}: exit ${rc}, expected ${expected_rc}\n${out}\n${err}")
  endif()
  set(last_err "${err}" PARENT_SCOPE)
endfunction()

# the lines of the snowman's OFF file (after test 1 wrote it) as the list `off`,
# and its vertex and face counts as `nv` and `nf`
macro(read_snowman_off)
  file(STRINGS ${WORK_DIR}/snowman/snowman.off off)
  list(GET off 1 counts)
  string(REGEX MATCHALL "[0-9]+" counts "${counts}")
  list(GET counts 0 nv)
  list(GET counts 1 nf)
endmacro()

# 1. the main job on a generated shape
run(0 --shape snowman --samples 200 --seed 3 --threads 2 --out ${WORK_DIR}/snowman)
foreach(f report.json samples.txt tau.txt transform.ply sdf.ply geodesics.ply snowman.off
        curves.txt curves.polylines.txt regions.txt symmetric_map.txt curves.ply symmetric_map.ply segmentation.txt
        segmentation.ply)
  if(NOT EXISTS ${WORK_DIR}/snowman/${f})
    message(FATAL_ERROR "missing output ${f}")
  endif()
endforeach()
file(READ ${WORK_DIR}/snowman/report.json report)
set(report_main "${report}")
foreach(key stages input parameters results similar_sample_pairs curves peak_memory_mib)
  string(JSON ignored ERROR_VARIABLE jerr GET "${report}" ${key})
  if(key STREQUAL "similar_sample_pairs" OR key STREQUAL "curves")
    string(JSON ignored ERROR_VARIABLE jerr GET "${report}" results ${key})
  endif()
  if(jerr)
    message(FATAL_ERROR "report.json lacks '${key}': ${jerr}\n${report}")
  endif()
endforeach()
# the default number of --tries is the one the README and --help give
string(JSON default_tries ERROR_VARIABLE jerr GET "${report}" parameters tries)
if(jerr OR NOT default_tries EQUAL 5)
  message(FATAL_ERROR "report.json: parameters.tries '${default_tries}' without --tries, expected 5 ${jerr}")
endif()
# the snowman's map is right: it holds no part in place far from the curve,
# and preserves distances
string(JSON fixed ERROR_VARIABLE jerr GET "${report}" results fixed_point_share)
string(JSON suspect ERROR_VARIABLE jerr2 GET "${report}" results map_suspect)
string(JSON distortion ERROR_VARIABLE jerr3 GET "${report}" results isometric_distortion)
string(JSON tried_distortion ERROR_VARIABLE jerr4 GET "${report}" results tries 0 isometric_distortion)
if(jerr OR jerr2 OR jerr3 OR jerr4 OR NOT suspect STREQUAL "OFF" OR fixed GREATER 0.02 OR fixed LESS 0
   OR distortion GREATER 0.02 OR distortion LESS 0 OR NOT tried_distortion STREQUAL distortion)
  message(FATAL_ERROR "report.json: fixed_point_share '${fixed}', isometric_distortion '${distortion}' (in tries: "
                      "'${tried_distortion}'), map_suspect '${suspect}', expected at most 0.02, at most 0.02 "
                      "and false ${jerr} ${jerr2} ${jerr3} ${jerr4}")
endif()
# every curve says whether it is nested (the run is without --nested-symmetries)
string(JSON ncurves ERROR_VARIABLE jerr LENGTH "${report}" results curve_details)
if(jerr OR ncurves LESS 1)
  message(FATAL_ERROR "report.json: no curve_details (${jerr})\n${report}")
endif()
math(EXPR last "${ncurves} - 1")
foreach(c RANGE ${last})
  string(JSON nested ERROR_VARIABLE jerr GET "${report}" results curve_details ${c} nested)
  if(jerr OR NOT nested STREQUAL "OFF")
    message(FATAL_ERROR "report.json: curve ${c} has nested '${nested}', expected false ${jerr}")
  endif()
endforeach()
file(STRINGS ${WORK_DIR}/snowman/samples.txt samples)
list(LENGTH samples n)
if(NOT n EQUAL 200)
  message(FATAL_ERROR "samples.txt has ${n} lines, expected 200")
endif()

# per-input outputs: one line per input face / vertex, ids within range, at
# least one curve; also when the tool decimated the mesh first
function(check_symmetry_outputs dir vertices faces)
  file(STRINGS ${dir}/regions.txt regions)
  list(LENGTH regions n)
  if(NOT n EQUAL ${faces})
    message(FATAL_ERROR "${dir}/regions.txt has ${n} lines, expected ${faces} (input faces)")
  endif()
  file(STRINGS ${dir}/symmetric_map.txt partners)
  list(LENGTH partners n)
  if(NOT n EQUAL ${vertices})
    message(FATAL_ERROR "${dir}/symmetric_map.txt has ${n} lines, expected ${vertices} (input vertices)")
  endif()
  set(mapped 0)
  foreach(p IN LISTS partners)
    if(p GREATER_EQUAL ${vertices} OR p LESS -1)
      message(FATAL_ERROR "${dir}/symmetric_map.txt: partner ${p} out of range")
    endif()
    if(p GREATER_EQUAL 0)
      math(EXPR mapped "${mapped} + 1")
    endif()
  endforeach()
  if(mapped EQUAL 0)
    message(FATAL_ERROR "${dir}/symmetric_map.txt maps no vertex")
  endif()
  file(STRINGS ${dir}/curves.txt curves)
  list(LENGTH curves n)
  if(n EQUAL 0)
    message(FATAL_ERROR "${dir}/curves.txt has no curve")
  endif()
  foreach(c IN LISTS curves)
    string(REPLACE " " ";" ids "${c}")
    foreach(i IN LISTS ids)
      if(i GREATER_EQUAL ${vertices} OR i LESS 0)
        message(FATAL_ERROR "${dir}/curves.txt: vertex ${i} out of range")
      endif()
    endforeach()
  endforeach()
endfunction()
file(STRINGS ${WORK_DIR}/snowman/snowman.off off_lines LIMIT_COUNT 2)
list(GET off_lines 1 counts)
string(REGEX MATCHALL "[0-9]+" counts "${counts}")
list(GET counts 0 nv)
list(GET counts 1 nf)
check_symmetry_outputs(${WORK_DIR}/snowman ${nv} ${nf})
run(0 ${WORK_DIR}/snowman/snowman.off --target-vertices 1200 --samples 200 --out ${WORK_DIR}/decimated)
check_symmetry_outputs(${WORK_DIR}/decimated ${nv} ${nf})
# a target above the vertex count is reached by remeshing, without --remesh
math(EXPR refined_target "${nv} * 3 / 2")
run(0 ${WORK_DIR}/snowman/snowman.off --target-vertices ${refined_target} --samples 200 --out ${WORK_DIR}/refined)
check_symmetry_outputs(${WORK_DIR}/refined ${nv} ${nf})
file(READ ${WORK_DIR}/refined/report.json refined_report)
string(JSON working ERROR_VARIABLE jerr GET "${refined_report}" results working_vertices)
if(jerr OR working LESS_EQUAL nv)
  message(FATAL_ERROR "--target-vertices ${refined_target} on ${nv} vertices: ${working} working vertices ${jerr}")
endif()

# without --repair: no repair output
string(JSON ignored ERROR_VARIABLE jerr GET "${report}" repair)
if(NOT jerr OR EXISTS ${WORK_DIR}/snowman/repaired.ply)
  message(FATAL_ERROR "a repair output without --repair")
endif()

# 1b. --repair on the stick figure whose right arm was cut off and capped:
# the arm is found missing and rebuilt; the repaired mesh is closed and valid
run(0 --shape stick_figure_missing_arm --repair --samples 400 --threads 2 --out ${WORK_DIR}/repair)
if(NOT EXISTS ${WORK_DIR}/repair/repaired.ply)
  message(FATAL_ERROR "--repair wrote no repaired.ply")
endif()
file(READ ${WORK_DIR}/repair/report.json report)
string(JSON parts ERROR_VARIABLE jerr GET "${report}" repair parts_added)
if(jerr OR parts LESS 1)
  message(FATAL_ERROR "report.json: no part added (${parts}) ${jerr}\n${report}")
endif()
foreach(key possible missing_part_found valid closed manifold)
  string(JSON value ERROR_VARIABLE jerr GET "${report}" repair ${key})
  if(jerr OR NOT value STREQUAL "ON")
    message(FATAL_ERROR "report.json: repair ${key} is '${value}', expected true ${jerr}\n${report}")
  endif()
endforeach()
string(JSON value ERROR_VARIABLE jerr GET "${report}" repair self_intersecting)
if(jerr OR NOT value STREQUAL "OFF")
  message(FATAL_ERROR "report.json: the repaired mesh self-intersects ${jerr}\n${report}")
endif()
# the PLY's header agrees with the report
file(STRINGS ${WORK_DIR}/repair/repaired.ply header LIMIT_COUNT 12)
string(JSON nv GET "${report}" repair vertices)
if(NOT header MATCHES "element vertex ${nv};")
  message(FATAL_ERROR "repaired.ply does not have the ${nv} vertices of the report: ${header}")
endif()

# 1c. a repair that is not possible (a mesh with a hole: repair needs a closed
# mesh) is reported, exit 0, and no repaired.ply is written
read_snowman_off()
math(EXPR nf1 "${nf} - 1")
list(REMOVE_AT off -1)
list(REMOVE_AT off 1)
list(INSERT off 1 "${nv} ${nf1} 0")
string(REPLACE ";" "\n" off "${off}")
file(WRITE ${WORK_DIR}/holed.off "${off}\n")
run(0 ${WORK_DIR}/holed.off --repair --samples 100 --out ${WORK_DIR}/holed)
file(READ ${WORK_DIR}/holed/report.json report)
string(JSON possible ERROR_VARIABLE jerr GET "${report}" repair possible)
string(JSON error ERROR_VARIABLE jerr2 GET "${report}" repair error)
if(jerr OR jerr2 OR NOT possible STREQUAL "OFF" OR NOT error MATCHES "closed")
  message(FATAL_ERROR "report.json: an impossible repair is not reported (${possible}, '${error}')\n${report}")
endif()
if(EXISTS ${WORK_DIR}/holed/repaired.ply)
  message(FATAL_ERROR "repaired.ply written although the repair was not possible")
endif()
# --fill-holes: the hole is filled on the working mesh (one triangle again),
# and every output still refers to the holed input
run(0 ${WORK_DIR}/holed.off --fill-holes --samples 100 --out ${WORK_DIR}/filled)
check_symmetry_outputs(${WORK_DIR}/filled ${nv} ${nf1})
file(READ ${WORK_DIR}/filled/report.json report)
string(JSON filled ERROR_VARIABLE jerr GET "${report}" results filled_holes)
string(JSON preparation ERROR_VARIABLE jerr2 GET "${report}" results preparation)
string(JSON working_faces ERROR_VARIABLE jerr3 GET "${report}" results working_faces)
string(JSON fill_parameter ERROR_VARIABLE jerr4 GET "${report}" parameters fill_holes)
if(jerr OR jerr2 OR jerr3 OR jerr4 OR NOT filled EQUAL 1 OR NOT preparation STREQUAL "holes filled"
   OR NOT working_faces EQUAL nf OR NOT fill_parameter STREQUAL "ON")
  message(FATAL_ERROR "--fill-holes: filled_holes '${filled}', preparation '${preparation}', working_faces "
                      "'${working_faces}' (expected 1, 'holes filled', ${nf}), parameters.fill_holes '${fill_parameter}' "
                      "${jerr} ${jerr2} ${jerr3} ${jerr4}")
endif()
# --max-hole-length below the hole's rim: nothing filled, the hole left open
run(0 ${WORK_DIR}/holed.off --fill-holes --max-hole-length 1e-6 --samples 100 --out ${WORK_DIR}/bounded)
check_symmetry_outputs(${WORK_DIR}/bounded ${nv} ${nf1})
file(READ ${WORK_DIR}/bounded/report.json report)
string(JSON filled ERROR_VARIABLE jerr GET "${report}" results filled_holes)
string(JSON left_open ERROR_VARIABLE jerr2 GET "${report}" results holes_left_open)
string(JSON working_faces ERROR_VARIABLE jerr3 GET "${report}" results working_faces)
string(JSON bound ERROR_VARIABLE jerr4 GET "${report}" parameters max_hole_length)
if(jerr OR jerr2 OR jerr3 OR jerr4 OR NOT filled EQUAL 0 OR NOT left_open EQUAL 1
   OR NOT working_faces EQUAL nf1 OR NOT bound EQUAL 1e-6)
  message(FATAL_ERROR "--max-hole-length 1e-6: filled_holes '${filled}', holes_left_open '${left_open}', "
                      "working_faces '${working_faces}' (expected 0, 1, ${nf1}), parameters.max_hole_length "
                      "'${bound}' ${jerr} ${jerr2} ${jerr3} ${jerr4}")
endif()
# a one-face hole is small: no warning; a closed mesh: none either
foreach(dir holed snowman)
  file(READ ${WORK_DIR}/${dir}/report.json report)
  string(JSON nwarnings ERROR_VARIABLE jerr LENGTH "${report}" warnings)
  if(jerr OR NOT nwarnings EQUAL 0)
    message(FATAL_ERROR "${dir}: expected an empty list of warnings (${jerr})\n${report}")
  endif()
endforeach()
# an open surface (a lone triangle) runs, with a warning about its boundary
file(WRITE ${WORK_DIR}/triangle.off "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
run(0 ${WORK_DIR}/triangle.off --samples 3 --out ${WORK_DIR}/triangle)
if(NOT last_err MATCHES "warning: the mesh has a boundary")
  message(FATAL_ERROR "no warning for an open surface: ${last_err}")
endif()
file(READ ${WORK_DIR}/triangle/report.json report)
string(JSON warning ERROR_VARIABLE jerr GET "${report}" warnings 0)
if(jerr OR NOT warning MATCHES "boundary")
  message(FATAL_ERROR "report.json: no warning for an open surface (${jerr})\n${report}")
endif()
# filled, the warning names the invented patch and the bound that would keep
# the boundary open; with a shorter bound, the boundary stays open
run(0 ${WORK_DIR}/triangle.off --samples 3 --fill-holes --out ${WORK_DIR}/triangle_filled)
if(NOT last_err MATCHES "invented patch.*--max-hole-length")
  message(FATAL_ERROR "--fill-holes on an open surface: no warning about the patch: ${last_err}")
endif()
run(0 ${WORK_DIR}/triangle.off --samples 3 --fill-holes --max-hole-length 0.1 --out ${WORK_DIR}/triangle_open)
file(READ ${WORK_DIR}/triangle_open/report.json report)
string(JSON left_open ERROR_VARIABLE jerr GET "${report}" results holes_left_open)
if(jerr OR NOT left_open EQUAL 1 OR NOT last_err MATCHES "distort the geodesics")
  message(FATAL_ERROR "--max-hole-length 0.1 on a lone triangle: holes_left_open '${left_open}' (expected 1), "
                      "warning: ${last_err} ${jerr}")
endif()

# 2. the same seed gives the same samples at another thread count
run(0 ${WORK_DIR}/snowman/snowman.off --samples 200 --seed 3 --threads 1 --geodesics dijkstra --out ${WORK_DIR}/again)
file(READ ${WORK_DIR}/snowman/samples.txt a)
file(READ ${WORK_DIR}/again/samples.txt b)
if(NOT a STREQUAL b)
  message(FATAL_ERROR "samples differ between runs with the same seed")
endif()

# 2b. --max-voting-pairs: only that many similar pairs vote, and the report says so
string(JSON similar GET "${report_main}" results similar_sample_pairs)
run(0 ${WORK_DIR}/snowman/snowman.off --samples 200 --seed 3 --max-voting-pairs 40 --out ${WORK_DIR}/capped)
file(READ ${WORK_DIR}/capped/report.json capped)
string(JSON voting GET "${capped}" results voting_pairs)
string(JSON cap GET "${capped}" parameters max_voting_pairs)
if(similar LESS_EQUAL 40 OR NOT voting EQUAL 40 OR NOT cap EQUAL 40)
  message(FATAL_ERROR "--max-voting-pairs 40: ${voting} voting pairs of ${similar} similar, reported cap '${cap}'")
endif()

# 2b'. --max-similar-pairs-per-sample: the most similar 0.5 x 200 pairs are kept
run(0 ${WORK_DIR}/snowman/snowman.off --samples 200 --seed 3 --max-similar-pairs-per-sample 0.5 --out ${WORK_DIR}/fewer)
file(READ ${WORK_DIR}/fewer/report.json fewer)
string(JSON kept GET "${fewer}" results similar_sample_pairs)
string(JSON per_sample GET "${fewer}" parameters max_similar_pairs_per_sample)
if(similar LESS_EQUAL 100 OR NOT kept EQUAL 100 OR NOT per_sample EQUAL 0.5)
  message(FATAL_ERROR "--max-similar-pairs-per-sample 0.5: ${kept} similar pairs kept of ${similar}, "
                      "reported '${per_sample}'")
endif()

# 2c. --tries: at 300 samples the two snowmen's map with seed 0 holds the small
# snowman in place (fixed_point_share about 0.48); the map with seed 1 holds
# nothing in place (about 0; it mirrors each snowman across the plane through
# its axis perpendicular to the tube, another symmetry of a body of revolution
# away from the tube). The tool runs seed 1 after seed 0, stops there and keeps
# it, and its outputs are those of a run with --seed 1 alone
run(0 --shape two_snowmen --samples 300 --tries 3 --threads 2 --out ${WORK_DIR}/tries)
file(READ ${WORK_DIR}/tries/report.json tries_report)
string(JSON ntries ERROR_VARIABLE jerr LENGTH "${tries_report}" results tries)
string(JSON first_seed ERROR_VARIABLE jerr1 GET "${tries_report}" results tries 0 seed)
string(JSON first_share ERROR_VARIABLE jerr2 GET "${tries_report}" results tries 0 fixed_point_share)
string(JSON second_share ERROR_VARIABLE jerr3 GET "${tries_report}" results tries 1 fixed_point_share)
string(JSON kept_seed ERROR_VARIABLE jerr4 GET "${tries_report}" results seed_kept)
string(JSON kept_share ERROR_VARIABLE jerr5 GET "${tries_report}" results fixed_point_share)
string(JSON suspect ERROR_VARIABLE jerr6 GET "${tries_report}" results map_suspect)
if(jerr OR jerr1 OR jerr2 OR jerr3 OR jerr4 OR jerr5 OR jerr6 OR NOT ntries EQUAL 2 OR NOT first_seed EQUAL 0
   OR first_share LESS_EQUAL 0.1 OR second_share GREATER 0.1 OR NOT kept_seed EQUAL 1
   OR NOT kept_share STREQUAL second_share OR NOT suspect STREQUAL "OFF")
  message(FATAL_ERROR "--tries 3 on the two snowmen at 300 samples: ${ntries} runs, first seed '${first_seed}' "
                      "with share ${first_share}, then ${second_share}; kept seed '${kept_seed}' with share "
                      "${kept_share}, map_suspect '${suspect}'; expected 2 runs, seed 0 above 0.1, seed 1 at most "
                      "0.1 and kept, not suspect ${jerr}${jerr1}${jerr2}${jerr3}${jerr4}${jerr5}${jerr6}")
endif()
run(0 --shape two_snowmen --samples 300 --seed 1 --tries 1 --threads 2 --out ${WORK_DIR}/seed1)
foreach(f symmetric_map.txt curves.txt regions.txt samples.txt)
  file(READ ${WORK_DIR}/tries/${f} a)
  file(READ ${WORK_DIR}/seed1/${f} b)
  if(NOT a STREQUAL b)
    message(FATAL_ERROR "--tries kept seed 1, but its ${f} differs from that of a run with --seed 1")
  endif()
endforeach()

# 2d. the guided run: with --tries 1 the suspect map of seed 0 (above) is the
# only try, so the tool runs once more on its samples, voting with the pairs
# that the global reflection (global_reflection_map()) swaps and mapping from
# it; that map (the two snowmen swapped end to end) holds nothing in place
# and is kept
run(0 --shape two_snowmen --samples 300 --tries 1 --threads 2 --out ${WORK_DIR}/guided)
file(READ ${WORK_DIR}/guided/report.json guided_report)
string(JSON gtries ERROR_VARIABLE gerr LENGTH "${guided_report}" results tries)
string(JSON gflag ERROR_VARIABLE gerr1 GET "${guided_report}" results tries 1 guided)
string(JSON gshare ERROR_VARIABLE gerr2 GET "${guided_report}" results tries 1 fixed_point_share)
string(JSON gkept ERROR_VARIABLE gerr3 GET "${guided_report}" results guided)
string(JSON gsuspect ERROR_VARIABLE gerr4 GET "${guided_report}" results map_suspect)
# the global reflection turns the surface over (orientation_reversing_share(); measured 0.95)
string(JSON greversing ERROR_VARIABLE gerr5 GET "${guided_report}" results tries 1 global_reflection_reversing_share)
if(gerr OR gerr1 OR gerr2 OR gerr3 OR gerr4 OR gerr5 OR NOT gtries EQUAL 2 OR NOT gflag STREQUAL "ON"
   OR gshare GREATER 0.1 OR NOT gkept STREQUAL "ON" OR NOT gsuspect STREQUAL "OFF" OR greversing LESS 0.5)
  message(FATAL_ERROR "--tries 1 on the two snowmen at 300 samples: ${gtries} runs, the second guided '${gflag}' "
                      "with share '${gshare}', guided kept '${gkept}', map_suspect '${gsuspect}', global "
                      "reflection reversing '${greversing}'; expected a guided second run holding nothing in "
                      "place, kept, after a reflection ${gerr}${gerr1}${gerr2}${gerr3}${gerr4}${gerr5}")
endif()
if(NOT last_err MATCHES "voting again on the samples of seed 0")
  message(FATAL_ERROR "--tries 1 on the two snowmen: no message for the guided run: ${last_err}")
endif()

# 2e. the guided run that takes the global reflection itself (measured at 400
# samples, seed 3; takes_whole_shape_reflection()): its map covers the whole
# shape as the region of its first curve, as report.json says
run(0 --shape two_snowmen --samples 400 --seed 3 --tries 1 --threads 2 --out ${WORK_DIR}/whole)
file(READ ${WORK_DIR}/whole/report.json whole_report)
string(JSON wkept ERROR_VARIABLE werr GET "${whole_report}" results whole_shape_reflection)
string(JSON wtry ERROR_VARIABLE werr1 GET "${whole_report}" results tries 1 whole_shape_reflection)
string(JSON wfaces ERROR_VARIABLE werr2 GET "${whole_report}" results faces_in_regions)
string(JSON wmapped ERROR_VARIABLE werr3 GET "${whole_report}" results vertices_with_partner)
string(JSON wfirst ERROR_VARIABLE werr4 GET "${guided_report}" results whole_shape_reflection)
# the reflection refined over the whole mesh is the less defective (refine_symmetric_map(); measured)
string(JSON wrefined ERROR_VARIABLE werr5 GET "${whole_report}" results tries 1 global_reflection_refined)
if(werr OR werr1 OR werr2 OR werr3 OR werr4 OR werr5 OR NOT wkept STREQUAL "ON" OR NOT wtry STREQUAL "ON"
   OR NOT wfirst STREQUAL "OFF" OR NOT wrefined STREQUAL "ON")
  message(FATAL_ERROR "--tries 1 on the two snowmen at 400 samples, seed 3: whole_shape_reflection '${wkept}' "
                      "(in tries: '${wtry}'), expected true, refined '${wrefined}', expected true; at 300 "
                      "samples, seed 0: '${wfirst}', expected false ${werr}${werr1}${werr2}${werr3}${werr4}${werr5}")
endif()
file(STRINGS ${WORK_DIR}/whole/regions.txt wregions)
list(LENGTH wregions wn)
list(REMOVE_DUPLICATES wregions)
file(STRINGS ${WORK_DIR}/whole/symmetric_map.txt wpartners)
list(LENGTH wpartners wv)
list(FIND wpartners -1 wunmapped)
if(NOT wregions STREQUAL "0" OR NOT wn EQUAL wfaces OR NOT wunmapped EQUAL -1 OR NOT wv EQUAL wmapped)
  message(FATAL_ERROR "the whole-shape map: region ids '${wregions}' over ${wn} faces (report: ${wfaces}), "
                      "${wv} vertices (report: ${wmapped} mapped), first unmapped at ${wunmapped}; expected "
                      "region 0 everywhere and every vertex mapped")
endif()

# 3. bad input: exit 2 and a message naming the problem
file(WRITE ${WORK_DIR}/quad.off "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n")
run(2 ${WORK_DIR}/quad.off --out ${WORK_DIR}/bad)
if(NOT last_err MATCHES "not a triangle mesh")
  message(FATAL_ERROR "unclear message for a quad mesh: ${last_err}")
endif()
run(2 ${WORK_DIR}/does_not_exist.off --out ${WORK_DIR}/bad)
if(NOT last_err MATCHES "unreadable file")
  message(FATAL_ERROR "unclear message for a missing file: ${last_err}")
endif()
run(2 ${WORK_DIR}/snowman/snowman.off --samples 100000 --out ${WORK_DIR}/bad)
if(NOT last_err MATCHES "too many samples")
  message(FATAL_ERROR "unclear message for too many samples: ${last_err}")
endif()

# 3a. --mend-input: a defect repair_input() mends (here an isolated vertex, after
# the snowman's vertices) is bad input without it, with a hint, and mended with
# it; the outputs still have a line per input vertex and face
read_snowman_off()
math(EXPR nv1 "${nv} + 1")
math(EXPR after_vertices "${nv} + 2")
list(INSERT off ${after_vertices} "7 7 7")
list(REMOVE_AT off 1)
list(INSERT off 1 "${nv1} ${nf} 0")
string(REPLACE ";" "\n" off "${off}")
file(WRITE ${WORK_DIR}/isolated.off "${off}\n")
run(2 ${WORK_DIR}/isolated.off --samples 100 --out ${WORK_DIR}/bad)
if(NOT last_err MATCHES "isolated vertex: vertex ${nv}" OR NOT last_err MATCHES "--mend-input")
  message(FATAL_ERROR "unclear message for an isolated vertex: ${last_err}")
endif()
run(0 ${WORK_DIR}/isolated.off --mend-input --samples 100 --tries 1 --out ${WORK_DIR}/mended)
file(READ ${WORK_DIR}/mended/report.json report)
string(JSON removed ERROR_VARIABLE jerr GET "${report}" results mended removed_isolated_vertices)
string(JSON preparation ERROR_VARIABLE jerr2 GET "${report}" results preparation)
string(JSON wv ERROR_VARIABLE jerr3 GET "${report}" results working_vertices)
if(jerr OR jerr2 OR jerr3 OR NOT removed EQUAL 1 OR NOT preparation STREQUAL "mended" OR NOT wv EQUAL nv)
  message(FATAL_ERROR "report.json: --mend-input on an isolated vertex: removed '${removed}', preparation "
                      "'${preparation}', working vertices '${wv}' (expected 1, mended, ${nv})")
endif()
file(STRINGS ${WORK_DIR}/mended/symmetric_map.txt mapped)
file(STRINGS ${WORK_DIR}/mended/regions.txt regions)
list(LENGTH mapped n_mapped)
list(LENGTH regions n_regions)
if(NOT n_mapped EQUAL nv1 OR NOT n_regions EQUAL nf)
  message(FATAL_ERROR "--mend-input: ${n_mapped} map lines for ${nv1} input vertices, ${n_regions} region lines "
                      "for ${nf} input faces")
endif()
# the removed vertex lies nowhere on the working mesh: no partner, no transform value
file(STRINGS ${WORK_DIR}/mended/tau.txt tau)
list(GET mapped ${nv} isolated_partner)
list(GET tau ${nv} isolated_tau)
list(GET mapped 0 first_partner)
if(NOT isolated_partner STREQUAL "-1" OR NOT isolated_tau STREQUAL "nan" OR first_partner STREQUAL "-1")
  message(FATAL_ERROR "--mend-input: the removed isolated vertex ${nv} has partner '${isolated_partner}' and "
                      "transform '${isolated_tau}' (expected -1 and nan); vertex 0 has partner '${first_partner}'")
endif()

# 3b. a time limit that has already passed stops the run (exit 4) once the first stage ends, with a message
run(4 --shape snowman --samples 200 --time-limit 0.000001 --out ${WORK_DIR}/limited)
if(NOT last_err MATCHES "time limit of 1e-06 s was reached" OR NOT last_err MATCHES "preparation ended after it")
  message(FATAL_ERROR "unclear message for a time limit: ${last_err}")
endif()

# 4. bad usage: exit 1
run(1 --shape snowman)
run(1 --shape snowman --out ${WORK_DIR}/x --time-limit 0)
run(1 --shape snowman --out ${WORK_DIR}/x --time-limit soon)
run(1 --shape snowman --out ${WORK_DIR}/x --geodesics magic)
run(1 --shape snowman --out ${WORK_DIR}/x --samples many)
run(1 --shape snowman --out ${WORK_DIR}/x --max-voting-pairs 0)
run(1 --shape snowman --out ${WORK_DIR}/x --max-similar-pairs-per-sample -1)
run(1 --shape snowman --out ${WORK_DIR}/x --max-similar-pairs-per-sample all)
run(1 --shape snowman --out ${WORK_DIR}/x --tries 0)
run(1 --shape snowman --out ${WORK_DIR}/x --tries 101)
run(1 --shape snowman --out ${WORK_DIR}/x --seed 99999999999)
run(1 --shape snowman --out ${WORK_DIR}/x --max-hole-length 0.5)
run(1 --shape snowman --out ${WORK_DIR}/x --fill-holes --max-hole-length -1)
run(0 --help)
message(STATUS "irsym end-to-end test passed")
