// Copyright (c) 2026 The Intrinsic_reflectional_symmetry_3 project.
// SPDX-License-Identifier: LGPL-3.0-or-later
// Author(s)     : The Intrinsic_reflectional_symmetry_3 developers

#ifndef CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_PART_REPAIR_H
#define CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_PART_REPAIR_H

#include <CGAL/disable_warnings.h>

/// \file part_repair.h
/// Symmetry-driven part repair (paper Sec. 4.2, Fig. 13-14): a part missing
/// on one side of a partial intrinsic reflectional symmetry is rebuilt from
/// its mirror part. Also the evaluation protocol the tests and the benchmark
/// share: cut limbs off a complete shape, cap the cuts, repair, and measure
/// how far the removed vertices are from the repaired surface.

#include <CGAL/Intrinsic_reflectional_symmetry_3/errors.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/geodesic_distances.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/Heat_method_geodesic_oracle.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/irsa_curves.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/irsa_transform.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/parameters.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/sampling.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/signatures.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/symmetric_map.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/repair_core.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/repair_mesh.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/repair_protocol.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Real_timer.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <exception>
#include <limits>
#include <set>
#include <string>
#include <vector>

namespace CGAL {
namespace Intrinsic_reflectional_symmetry_3 {

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// What `repair_missing_parts()` did.
struct Part_repair_report
{
  /// the number of parts added (0: no missing part was detected; the output is a copy of the input)
  std::size_t number_of_parts = 0;
  /// per part: the number of vertices of the mirror part that was copied
  std::vector<std::size_t> part_sizes;
  /// per part: root mean square distance of the ICP pairs at the end (mesh length unit)
  std::vector<double> icp_rms;
  /// the mirror plane `a x + b y + c z + d = 0` (unit normal) the copies were reflected across
  std::array<double, 4> mirror_plane = {{0., 0., 0., 0.}};
  /// the index of the curve whose region was used (overload taking all curves)
  std::size_t curve = 0;
  /// whether the fairing of the seams succeeded (if not, the seams are stitched but not smoothed)
  bool seams_faired = true;
};

namespace internal {

template <typename NamedParameters>
Repair_settings repair_settings(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  namespace inp = Intrinsic_reflectional_symmetry_3::internal_np;
  Repair_settings rs;
  rs.threshold = choose_parameter(get_parameter(np, inp::missing_part_threshold), 0.02);
  if(!(rs.threshold > 0. && rs.threshold < 1.))
    throw Input_error(Input_problem::invalid_parameter, "missing_part_threshold must be in (0, 1)");
  return rs;
}

template <typename TriangleMesh, typename NamedParameters>
void check_closed_for_repair(const TriangleMesh& tm, const NamedParameters&)
{
  if(num_faces(tm) == 0) throw Input_error(Input_problem::empty_mesh, "part repair: the mesh has no faces");
  if(!CGAL::is_triangle_mesh(tm)) throw Input_error(Input_problem::not_triangle_mesh, "part repair needs a triangle mesh");
  if(!CGAL::is_closed(tm))
    throw Input_error(Input_problem::invalid_parameter, "part repair needs a closed mesh (fill holes first)");
}

template <typename OutputMesh>
void copy_result(const Repair_core_result& r, OutputMesh& out, Part_repair_report& report)
{
  repair_soup_to_mesh(r.mesh, out, "part repair");
  report.number_of_parts = r.part_sizes.size();
  report.part_sizes = r.part_sizes;
  report.icp_rms = r.icp_rms;
  report.mirror_plane = r.plane;
  report.seams_faired = true;
  for(bool f : r.faired) report.seams_faired = report.seams_faired && f;
}

} // namespace internal

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// Symmetry-driven part repair (paper Sec. 4.2) from one IRSA curve and the
/// point-to-point reflection of its region (`symmetric_vertex_map()` called
/// with that curve alone). `out` receives the input with every detected
/// missing part rebuilt from its mirror part: one closed 2-manifold without
/// self-intersections, or an `Input_error` says why the repair is not
/// possible. The input is never modified.
///
/// **Detection.** A reflection preserves the geodesic distance g to its axis
/// (the curve). A vertex v is *orphan* when it has no partner, or when
/// g(v) - g(partner(v)) exceeds tau = `missing_part_threshold` times the
/// bounding-box diagonal (at least 1.5 mean edge lengths): the map then
/// collapses v onto a smaller counterpart, as it does for a limb present on
/// one side whose mirror is only the cap of a cut. This is intrinsic, so a
/// limb in a different pose on each side is not taken for a missing part.
/// Orphan components (plus what they enclose) of at least 0.5 % of the area
/// are parts to mirror when the reflection across the mirror plane sends at
/// least half of their area off the surface (farther than tau) and outside
/// the shape, when they lie on one side of the plane (at most 5 % of their
/// area across it) and away from the axis (at most 5 % of their area within
/// 3 tau of it): this extrinsic check rejects
/// regions where the map merely fails (a head maps onto itself), the
/// intrinsic orphan test rejects limbs that only have another pose on the
/// other side. Nothing is detected with a curve whose mirror plane (see
/// Placement) disagrees with the map: the copies are reflected across that
/// plane, so the map's partner of a vertex must lie within 2 tau of the
/// vertex's reflection on at least 80 % of the area (complete FAUST shapes:
/// curves of other symmetries reach 13-76 % and used to add parts that were
/// not missing; the curves that detect one or two cut limbs, 84-97 % on 16 of 19 shapes).
///
/// **Placement.** The part (its base, the part's border, must be one loop)
/// is reflected across the best-fitting plane of the curve (paper's
/// heuristic), refined with the map's pairs that agree with it (a pruned
/// curve can be nearly a line, which leaves the plane free to turn about
/// it), then aligned by trimmed rigid ICP (`Eigen::umeyama()`, closest
/// surface points by a CGAL AABB tree) of its reflected collar (the band from
/// 1.5 to 4 tau inside its base: nearer the base, the reflection lands on the
/// cut) onto the other side's surface, caps excluded; if no copy so placed
/// can be attached, with the band from the base to 3 tau (posed limbs).
/// Each part gets its own fit: of the four (two bands, two starts) with which
/// it can be attached alone, the one with the smallest ICP residual. A
/// slender part (longer than 5 times its base radius: a forearm, a lower
/// leg) first gets a wider collar, from the base to 7 tau, whose fit is kept
/// if it can be attached: a turn of the copy moves its tip by the turn times
/// the part's length, and the wider collar holds the turn. A part
/// whose best residual exceeds tau / 8 is not copied: a missing limb leaves
/// its surroundings intact, so their reflection fits the other side closely
/// (0.002-0.094 tau on the stick figure and FAUST), and where it does not, the
/// orphan region is a failure of the map (CGAL's complete bear.off: a patch
/// at the base of an ear, 0.171 tau).
///
/// **Stitching.** The surface the copy replaces (the cap, from a gap of half
/// the base radius before the copy's base, within 1.5 base radii of its axis)
/// is removed; the two loops are bridged by a strip of triangles, refined
/// (`CGAL::Polygon_mesh_processing::refine()`) and faired with the loops
/// (`CGAL::Polygon_mesh_processing::fair()`, in place of the paper's Poisson
/// interpolation); if that strip folds, it is faired inside only, then left
/// plain (`seams_faired` false). A copy also copies the input's own
/// self-intersections (skin touching skin in a scan): new faces that intersect
/// are repaired locally (`CGAL::Polygon_mesh_processing::experimental::remove_self_intersections()`)
/// before the result is checked.
///
/// \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
/// \tparam VertexPartnerMap a model of `ReadablePropertyMap`, vertex descriptor to a signed
///         integral vertex index (the partner), -1 where none (as written by `symmetric_vertex_map()`)
/// \tparam OutputMesh a model of `MutableFaceGraph` (may be `TriangleMesh`)
///
/// \param tm the closed triangle mesh with missing parts (read only)
/// \param curve the IRSA curve of the symmetry (its vertices give the mirror plane and the axis)
/// \param partner the vertex map of that curve's region
/// \param out receives the repaired mesh (cleared first)
/// \param np optional named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{missing_part_threshold}
///     \cgalParamDescription{tau, as a fraction of the bounding-box diagonal (see Detection)}
///     \cgalParamType{double in (0, 1)}
///     \cgalParamDefault{0.02}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
///     \cgalParamType{a model of `ReadablePropertyMap`}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_index_map}
///     \cgalParamDescription{the vertex indices (those of `partner` and of the curve)}
///     \cgalParamType{a model of `ReadablePropertyMap`}
///     \cgalParamDefault{an automatically indexed internal map}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns what was done; `number_of_parts == 0` (and `out` a copy of `tm`) when no part is missing
/// \throws Input_error if `tm` is not a closed triangle mesh, if the map does not match it, or
///         (`invalid_parameter`, message starting "part repair is not possible") if a detected part
///         cannot be attached so that the result is one closed 2-manifold without self-intersections
template <typename TriangleMesh, typename VertexPartnerMap, typename OutputMesh,
          typename CGAL_NP_TEMPLATE_PARAMETERS>
Part_repair_report repair_missing_parts(const TriangleMesh& tm, const Irsa_curve& curve, VertexPartnerMap partner,
                                        OutputMesh& out, const CGAL_NP_CLASS& np = parameters::default_values())
{
  internal::check_closed_for_repair(tm, np);
  const internal::Repair_settings rs = internal::repair_settings(np);
  const internal::Repair_soup s = internal::mesh_to_repair_soup(tm, np);
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  std::vector<std::ptrdiff_t> p(s.points.size(), -1);
  for(auto v : vertices(tm)) p[std::size_t(get(vim, v))] = std::ptrdiff_t(get(partner, v));
  const internal::Repair_core_result r = internal::repair_core(s, p, curve.vertices(), rs);
  Part_repair_report report;
  internal::copy_result(r, out, report);
  return report;
}

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// Part repair from all the IRSA curves of a shape: the curves are tried in
/// their order (at most the first four), each with its own region's map
/// (`symmetric_vertex_map()` with that curve alone, `np` passed on, without
/// the local and spectral refinements, whatever `number_of_local_rounds` and
/// `number_of_eigenfunctions` say, and with the curve
/// extraction's `symmetry_tolerance` of 1.0 unless `np` sets one); the
/// first one with which a missing part is detected repairs it (see the
/// overload taking one curve). A global symmetry that survives the damage
/// (e.g. front-back on a human missing an arm) detects nothing and is passed
/// over, as the paper's Sec. 4.2 requires.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag` for the maps
/// \param D the sample-to-vertex distance matrix of the voting
/// \param curves the curves, as from `extract_irsa_curves()`
/// \returns the report; `curve` names the curve used. `number_of_parts == 0` and `out` a copy of
///          `tm` if no curve detects a missing part.
template <typename ConcurrencyTag = CGAL::Parallel_if_available_tag, typename TriangleMesh, typename CurveRange,
          typename OutputMesh, typename CGAL_NP_TEMPLATE_PARAMETERS>
Part_repair_report repair_missing_parts(const TriangleMesh& tm, const Geodesic_distance_matrix& D,
                                        const CurveRange& curves, OutputMesh& out,
                                        const CGAL_NP_CLASS& np = parameters::default_values())
{
  internal::check_closed_for_repair(tm, np);
  std::size_t index = 0;
  std::string first_error;
  for(const Irsa_curve& c : curves)
  {
    if(index == 4) break;
    std::vector<Irsa_curve> one(1, c);
    auto partner = get(CGAL::dynamic_vertex_property_t<std::ptrdiff_t>(), tm);
    // The global match only (no local or spectral refinement): the detection
    // reads where the map collapses a limb onto the cap of its cut mirror,
    // which the locally weighted landmarks partly hide (measured: the 3 %-stretched
    // stick figure's arm 2.4 % instead of 1.5 %; FAUST one limb within 2 %
    // on 6 instead of 7 of 19 shapes).
    internal::symmetric_vertex_map<ConcurrencyTag>(tm, D, one, partner, np, true);
    try
    {
      Part_repair_report r = repair_missing_parts(tm, c, partner, out, np);
      r.curve = index;
      if(r.number_of_parts > 0) return r;
    }
    catch(const Input_error& e) // a part was found but could not be attached: try the next curve
    {
      if(first_error.empty()) first_error = e.what();
    }
    ++index;
  }
  if(!first_error.empty())
    throw Input_error(Input_problem::invalid_parameter,
                      "no curve led to a valid repair; with the first curve: " + first_error);
  const internal::Repair_soup s = internal::mesh_to_repair_soup(tm, np);
  internal::repair_soup_to_mesh(s, out, "part repair");
  return Part_repair_report();
}

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// Part repair from the IRSA transform: the curves are extracted
/// (`extract_irsa_curves()`, `np` passed on) and tried as by the overload
/// taking all curves. When none detects a missing part, tau is set to zero
/// near the curves tried (within `vicinity_radius` mean sample spacings,
/// along the mesh edges, as the extraction does near a selected boundary)
/// and the curves are extracted again, at most `maximum_number_of_rounds` times.
///
/// Why: the extraction keeps the curves of a partition of the shape and
/// drops a curve whose reflection holds mostly where a better ranked one's
/// holds. On a human missing a leg, or two limbs, the front-back symmetry
/// survives the damage, ranks first and covers the body, so the left-right
/// curve, the one whose map reveals the missing parts, is dropped as
/// dominated. Once the front-back curve is ruled out (it detects nothing),
/// its tau is removed and the left-right curve comes first.
///
/// \tparam VertexTauMap a model of `ReadablePropertyMap`, vertex descriptor to
///         the IRSA transform (as filled by `compute_irsa_transform()`)
/// \param voting the result of `compute_irsa_transform()` on `tm` and `D`
/// \param tau the IRSA transform
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{maximum_number_of_rounds}
///     \cgalParamDescription{the most extractions (the first one included)}
///     \cgalParamType{std::size_t >= 1}
///     \cgalParamDefault{3}
///   \cgalParamNEnd
///   \cgalParamNBegin{vicinity_radius}
///     \cgalParamDescription{the suppression radius, in mean sample spacings (the extraction's parameter)}
///     \cgalParamType{double >= 0}
///     \cgalParamDefault{3.0}
///   \cgalParamNEnd
///   \cgalParamNBegin{missing_part_threshold, and the parameters of `extract_irsa_curves()` and
///     `symmetric_vertex_map()`}
///     \cgalParamDescription{passed on}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the report (`curve` is the index of the curve used in its round's extraction)
/// \throws Input_error as the overload taking all curves, or if `voting` does not match `tm` and `D`
template <typename ConcurrencyTag = CGAL::Parallel_if_available_tag, typename TriangleMesh, typename VertexTauMap,
          typename OutputMesh, typename CGAL_NP_TEMPLATE_PARAMETERS>
Part_repair_report repair_missing_parts(const TriangleMesh& tm, const Geodesic_distance_matrix& D,
                                        const Irsa_voting_result& voting, const VertexTauMap& tau, OutputMesh& out,
                                        const CGAL_NP_CLASS& np = parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  namespace inp = Intrinsic_reflectional_symmetry_3::internal_np;
  internal::check_closed_for_repair(tm, np);
  const std::size_t rounds = choose_parameter(get_parameter(np, inp::maximum_number_of_rounds), std::size_t(3));
  const double radius = choose_parameter(get_parameter(np, inp::vicinity_radius), internal::default_vicinity_radius);
  if(rounds < 1) throw Input_error(Input_problem::invalid_parameter, "maximum_number_of_rounds must be >= 1");
  if(!(radius >= 0.) || !std::isfinite(radius))
    throw Input_error(Input_problem::invalid_parameter, "vicinity_radius must be finite and >= 0");
  const internal::Repair_soup s = internal::mesh_to_repair_soup(tm, np);
  const auto nb = internal::soup_neighbours(s);
  const double unit = voting.mean_sample_spacing > 0. ? voting.mean_sample_spacing : internal::soup_mean_edge_length(s);
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  std::vector<double> t(s.points.size(), 0.);
  for(auto v : vertices(tm)) t[std::size_t(get(vim, v))] = double(get(tau, v));
  auto tmap = get(CGAL::dynamic_vertex_property_t<double>(), tm);
  std::exception_ptr first_error; // rethrown as is: its message already says why
  for(std::size_t round = 0; round < rounds; ++round)
  {
    for(auto v : vertices(tm)) put(tmap, v, t[std::size_t(get(vim, v))]);
    std::vector<Irsa_curve> curves;
    extract_irsa_curves<ConcurrencyTag>(tm, D, voting, tmap, std::back_inserter(curves), np);
    if(curves.size() > 4) curves.resize(4); // the ones the overload taking all curves tries
    if(curves.empty()) break;
    try
    {
      Part_repair_report r = repair_missing_parts<ConcurrencyTag>(tm, D, curves, out, np);
      if(r.number_of_parts > 0) return r;
    }
    catch(const Input_error&) // a part was found but could not be attached: look further
    {
      if(!first_error) first_error = std::current_exception();
    }
    // these curves detect nothing: their tau goes, the next axes come first
    std::vector<std::size_t> sources;
    for(const Irsa_curve& c : curves)
      for(std::size_t v : c.vertices()) if(v < t.size()) sources.push_back(v);
    const std::vector<double> d = internal::soup_dijkstra(s, nb, sources);
    for(std::size_t v = 0; v < t.size(); ++v) if(d[v] <= radius * unit) t[v] = 0.;
  }
  if(first_error) std::rethrow_exception(first_error);
  internal::repair_soup_to_mesh(s, out, "part repair");
  return Part_repair_report();
}

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// A limb to cut off in the repair protocol (`run_part_repair_protocol()`).
struct Limb_cut
{
  /// the vertex at the limb's tip (vertex index)
  std::size_t tip = 0;
  /// the cut plane is fitted to the vertices at this edge-graph geodesic distance from the tip
  double length = 0.;
};

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// The figures of one run of the repair protocol.
struct Part_repair_protocol_result
{
  std::size_t removed_vertices = 0, damaged_vertices = 0, repaired_vertices = 0;
  Part_repair_report report;
  /// max and mean distance of the removed vertices (original positions) to
  /// the repaired surface, in % of the repaired surface's bounding-box diagonal
  double max_distance = std::numeric_limits<double>::quiet_NaN();
  double mean_distance = std::numeric_limits<double>::quiet_NaN();
  /// the max distance (same unit) per limb, in the order of the cuts
  std::vector<double> max_distance_per_cut;
  /// checks of the repaired mesh: valid triangle mesh, closed, self-intersecting at all, and
  /// self-intersecting through a face that is not a face of `tm` (a face is "of `tm`" when its
  /// three corners are points of `tm`): many scans, most FAUST meshes among them, already
  /// self-intersect where skin touches skin; the repair must not add intersections
  bool closed = false, valid = false, self_intersecting = true, new_self_intersections = true;
  /// whether `tm` itself self-intersects
  bool input_self_intersecting = false;
  /// wall-clock seconds: cut and cap, symmetry pipeline, repair
  double seconds_cut = 0., seconds_pipeline = 0., seconds_repair = 0.;
  /// empty, or the message of the `Input_error` the repair threw
  std::string error;
};

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// The part-repair evaluation protocol, shared by the tests and the benchmark
/// so that anyone can rerun it:
/// 1. each limb of `cuts` is cut off `tm` by a plane: the plane is fitted to
///    the vertices at geodesic distance `length` from `tip`, and the connected
///    set of vertices beyond it containing the tip is removed (with their triangles);
/// 2. every cut is capped (`triangulate_refine_and_fair_hole()`), so the
///    damaged mesh is closed but misses the limbs;
/// 3. the package's pipeline runs on it with its defaults
///    (`farthest_point_samples()` with `number_of_samples` and `random_seed`,
///    `Heat_method_geodesic_oracle`, `sdf_signatures()`, `similar_sample_pairs()`,
///    `compute_irsa_transform()`), then `repair_missing_parts()` from the
///    transform (it extracts the curves, `extract_irsa_curves()`);
/// 4. the repaired mesh is checked (closed, valid, self-intersections) and
///    the distance from every removed vertex to it is measured (AABB tree),
///    in % of its bounding-box diagonal.
///
/// \param tm a complete closed triangle mesh (read only)
/// \param cuts the limbs to cut (tips must be distinct limbs)
/// \param damaged receives the capped mesh
/// \param repaired receives the repaired mesh (empty if the repair threw)
/// \param np named parameters passed to the voting, the curve extraction, the maps and the repair;
///        `number_of_samples` defaults to 1000 here, `random_seed` to 0
/// \returns the figures; `error` holds the message if the repair threw (the cut and
///          the pipeline throw as usual)
template <typename TriangleMesh, typename CGAL_NP_TEMPLATE_PARAMETERS>
Part_repair_protocol_result run_part_repair_protocol(const TriangleMesh& tm, const std::vector<Limb_cut>& cuts,
                                                     TriangleMesh& damaged, TriangleMesh& repaired,
                                                     const CGAL_NP_CLASS& np = parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  namespace inp = Intrinsic_reflectional_symmetry_3::internal_np;
  typedef internal::Repair_point Point;
  Part_repair_protocol_result res;
  CGAL::Real_timer timer;
  timer.start();

  // 1-2. cut and cap
  const internal::Repair_soup s = internal::mesh_to_repair_soup(tm, parameters::default_values());
  const auto nb = internal::soup_neighbours(s);
  const double e = internal::soup_mean_edge_length(s);
  std::vector<char> removed(s.points.size(), 0);
  std::vector<Point> removed_points;
  std::vector<std::size_t> cut_of; // per removed point: its cut
  for(std::size_t k = 0; k < cuts.size(); ++k)
  {
    const Limb_cut& c = cuts[k];
    if(c.tip >= s.points.size())
      throw Input_error(Input_problem::invalid_parameter, "limb cut: the tip is not a vertex", c.tip);
    for(std::size_t v : internal::limb_vertices(s, nb, c.tip, c.length, e))
      if(!removed[v]) { removed[v] = 1; removed_points.push_back(s.points[v]); cut_of.push_back(k); }
  }
  res.removed_vertices = removed_points.size();
  internal::cut_and_cap(s, removed, damaged);
  res.damaged_vertices = num_vertices(damaged);
  res.seconds_cut = timer.time();
  timer.reset();

  // 3. pipeline and repair
  const std::size_t ns = (std::min)(std::size_t(choose_parameter(get_parameter(np, inp::number_of_samples), std::size_t(1000))),
                                    std::size_t(num_vertices(damaged)));
  const unsigned seed = choose_parameter(get_parameter(np, CGAL::internal_np::random_seed), 0u);
  const std::vector<std::size_t> samples =
    farthest_point_samples(damaged, parameters::number_of_samples(ns).random_seed(seed));
  const Heat_method_geodesic_oracle<TriangleMesh> oracle(damaged);
  const Geodesic_distance_matrix D = compute_geodesic_distance_matrix(oracle, samples);
  const Sdf_signatures sig = sdf_signatures(vertex_sdf_values(damaged), vertex_areas(damaged), D);
  std::vector<std::pair<std::size_t, std::size_t> > similar;
  similar_sample_pairs(sig, std::back_inserter(similar), parameters::random_seed(seed));
  auto tau = get(CGAL::dynamic_vertex_property_t<double>(), damaged);
  const Irsa_voting_result voting = compute_irsa_transform(damaged, D, similar, tau, np);
  res.seconds_pipeline = timer.time();
  timer.reset();
  try
  {
    res.report = repair_missing_parts(damaged, D, voting, tau, repaired, np);
  }
  catch(const Input_error& err)
  {
    res.error = err.what();
    clear(repaired);
    res.seconds_repair = timer.time();
    return res;
  }
  res.seconds_repair = timer.time();

  // 4. checks and distances
  res.repaired_vertices = num_vertices(repaired);
  res.valid = CGAL::is_valid_polygon_mesh(repaired) && CGAL::is_triangle_mesh(repaired);
  res.closed = res.valid && CGAL::is_closed(repaired);
  const internal::Repair_soup r = internal::mesh_to_repair_soup(repaired, parameters::default_values());
  const internal::Repair_surface rm = internal::soup_to_surface(r);
  {
    const internal::Repair_surface im = internal::soup_to_surface(s);
    res.input_self_intersecting = CGAL::Polygon_mesh_processing::does_self_intersect(im);
    std::set<Point> original(s.points.begin(), s.points.end());
    std::vector<std::pair<internal::Repair_surface::Face_index, internal::Repair_surface::Face_index> > pairs;
    if(res.valid) CGAL::Polygon_mesh_processing::self_intersections(rm, std::back_inserter(pairs));
    res.self_intersecting = !res.valid || !pairs.empty();
    auto is_new = [&](internal::Repair_surface::Face_index f) {
      for(auto v : vertices_around_face(halfedge(f, rm), rm))
        if(original.count(rm.point(v)) == 0) return true;
      return false;
    };
    res.new_self_intersections = !res.valid;
    for(const auto& p : pairs)
      if(is_new(p.first) || is_new(p.second)) res.new_self_intersections = true;
  }
  internal::Repair_tree tree(faces(rm).first, faces(rm).second, rm);
  tree.accelerate_distance_queries();
  const double diag = internal::soup_bbox_diagonal(r.points);
  double sum = 0.;
  std::vector<double> mx_cut(cuts.size(), 0.);
  for(std::size_t i = 0; i < removed_points.size(); ++i)
  {
    const double d = std::sqrt(tree.squared_distance(removed_points[i]));
    mx_cut[cut_of[i]] = (std::max)(mx_cut[cut_of[i]], d);
    sum += d;
  }
  if(!removed_points.empty() && diag > 0.)
  {
    res.max_distance = 100. * *std::max_element(mx_cut.begin(), mx_cut.end()) / diag;
    for(double m : mx_cut) res.max_distance_per_cut.push_back(100. * m / diag);
    res.mean_distance = 100. * sum / double(removed_points.size()) / diag;
  }
  return res;
}

} // namespace Intrinsic_reflectional_symmetry_3
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_PART_REPAIR_H
