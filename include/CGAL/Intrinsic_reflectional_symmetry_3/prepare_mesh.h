// Copyright (c) 2026 The Intrinsic_reflectional_symmetry_3 project.
// SPDX-License-Identifier: LGPL-3.0-or-later
// Author(s)     : The Intrinsic_reflectional_symmetry_3 developers

#ifndef CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_PREPARE_MESH_H
#define CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_PREPARE_MESH_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Intrinsic_reflectional_symmetry_3/check_input.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/errors.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/parameters.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/prepare_helpers.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <boost/iterator/counting_iterator.hpp>
#include <boost/range/size.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numeric>
#include <string>
#include <sstream>
#include <type_traits>
#include <utility>
#include <vector>

/// \file prepare_mesh.h
/// Optional isotropic remeshing or decimation of the input to a target vertex
/// count, on a `CGAL::Surface_mesh` copy, with maps back to the input so that
/// every result can be expressed on the input's vertices and faces.

namespace CGAL {
namespace Intrinsic_reflectional_symmetry_3 {

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// What `prepare_mesh()` did to make the working mesh.
enum class Mesh_preparation
{
  none,                 ///< the working mesh is an exact copy of the input
  isotropic_remeshing,  ///< `PMP::isotropic_remeshing()`
  decimation            ///< `Surface_mesh_simplification::edge_collapse()`
};

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// Where an input vertex lies on the working mesh: the nearest point of the
/// working surface, as a face and barycentric coordinates. An input vertex on
/// no face (isolated), which `mend_input(true)` removes, lies nowhere: it is
/// no point of the surface, so it takes no place on it (`located` false).
struct Input_vertex_location
{
  std::size_t face = 0;                      ///< working face index
  std::array<std::size_t, 3> vertices{};     ///< working vertex indices of the face's corners
  std::array<double, 3> weights{};           ///< barycentric coordinates, one per entry of `vertices`
  bool located = true;                       ///< false for a removed isolated vertex: the other members are meaningless
};

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// The mesh the package works on, and its correspondence with the input.
///
/// Input vertices and faces are designated by their index in the input's
/// vertex and face index maps (the file order for a mesh made by
/// `read_mesh()`); working vertices and faces by their index in the working
/// `Surface_mesh` (which has no garbage: indices are `0..n-1`).
/// Made by `prepare_mesh()`.
///
/// \tparam GeomTraits a model of `Kernel`
template <typename GeomTraits>
class Prepared_mesh
{
public:
  typedef GeomTraits Geom_traits;
  typedef typename GeomTraits::Point_3 Point_3;
  /// the working mesh type
  typedef CGAL::Surface_mesh<Point_3> Working_mesh;

  /// the working mesh
  const Working_mesh& working_mesh() const { return working_; }
  /// what was done to the input to get the working mesh
  Mesh_preparation preparation() const { return preparation_; }
  /// whether the working mesh is an exact copy of the input and all maps are identities
  bool is_identity() const
  {
    return preparation_ == Mesh_preparation::none && number_of_filled_holes_ == 0 && !input_repairs_.any();
  }
  /// what `mend_input(true)` mended (`repair_input()`; nothing otherwise); its
  /// `output_to_input_vertex` is left empty, `working_to_input_vertices()` takes its place
  const Input_repairs& input_repairs() const { return input_repairs_; }
  /// what `check_input()` returns for the input, or with `mend_input(true)` for
  /// its mended copy where something was mended: the statistics of the mesh
  /// the preparation starts from, so that a caller need not check it again
  const Input_report& input_report() const { return input_report_; }
  /// the number of boundary cycles filled before any remeshing (`fill_holes(true)`)
  std::size_t number_of_filled_holes() const { return number_of_filled_holes_; }
  /// the number of boundary cycles `fill_holes(true)` left open: longer than
  /// `maximum_hole_boundary_length`, or without a triangulation (0 without `fill_holes(true)`)
  std::size_t number_of_holes_left_open() const { return number_of_holes_left_open_; }
  /// the target edge length given to isotropic remeshing (0 when not remeshed)
  double target_edge_length() const { return target_edge_length_; }

  std::size_t number_of_input_vertices() const { return input_vertex_locations_.size(); }
  std::size_t number_of_input_faces() const { return input_face_to_working_.size(); }
  std::size_t number_of_working_vertices() const { return working_to_input_vertex_.size(); }
  std::size_t number_of_working_faces() const { return std::size_t(working_.number_of_faces()); }

  /// the input vertex nearest to working vertex `w` (identity without preparation)
  std::size_t working_to_input_vertex(std::size_t w) const { return working_to_input_vertex_.at(w); }
  /// returned by `input_to_working_vertex()` for an input vertex that lies nowhere
  static constexpr std::size_t no_vertex = std::size_t(-1);

  /// the working vertex of largest barycentric weight in the location of input
  /// vertex `i`, or `no_vertex` for an isolated vertex that `mend_input(true)` removed
  std::size_t input_to_working_vertex(std::size_t i) const
  {
    const Input_vertex_location& l = input_vertex_locations_.at(i);
    if(!l.located) return no_vertex;
    std::size_t best = 0;
    for(std::size_t k = 1; k < 3; ++k)
      if(l.weights[k] > l.weights[best]) best = k;
    return l.vertices[best];
  }
  /// where input vertex `i` lies on the working mesh
  const Input_vertex_location& input_vertex_location(std::size_t i) const { return input_vertex_locations_.at(i); }
  /// the working face nearest to the centroid of input face `f` (identity without preparation)
  std::size_t input_to_working_face(std::size_t f) const { return input_face_to_working_.at(f); }

  /// for each working vertex, its nearest input vertex
  const std::vector<std::size_t>& working_to_input_vertices() const { return working_to_input_vertex_; }
  /// for each input vertex, its location on the working mesh
  const std::vector<Input_vertex_location>& input_vertex_locations() const { return input_vertex_locations_; }
  /// for each input face, the working face nearest to its centroid
  const std::vector<std::size_t>& input_to_working_faces() const { return input_face_to_working_; }

  /// \cond SKIP_IN_MANUAL
  Prepared_mesh() = default;
  Prepared_mesh(Working_mesh&& working, Mesh_preparation preparation, double target_edge_length,
                std::vector<std::size_t>&& working_to_input_vertex,
                std::vector<Input_vertex_location>&& input_vertex_locations,
                std::vector<std::size_t>&& input_face_to_working, std::size_t number_of_filled_holes = 0,
                std::size_t number_of_holes_left_open = 0, Input_repairs input_repairs = Input_repairs(),
                Input_report input_report = Input_report())
    : working_(std::move(working)), preparation_(preparation), target_edge_length_(target_edge_length),
      number_of_filled_holes_(number_of_filled_holes), number_of_holes_left_open_(number_of_holes_left_open),
      input_repairs_(std::move(input_repairs)), input_report_(input_report),
      working_to_input_vertex_(std::move(working_to_input_vertex)),
      input_vertex_locations_(std::move(input_vertex_locations)),
      input_face_to_working_(std::move(input_face_to_working))
  {}
  /// \endcond

private:
  Working_mesh working_;
  Mesh_preparation preparation_ = Mesh_preparation::none;
  double target_edge_length_ = 0;
  std::size_t number_of_filled_holes_ = 0, number_of_holes_left_open_ = 0;
  Input_repairs input_repairs_;
  Input_report input_report_;
  std::vector<std::size_t> working_to_input_vertex_;
  std::vector<Input_vertex_location> input_vertex_locations_;
  std::vector<std::size_t> input_face_to_working_;
};

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// Largest `target_number_of_vertices` accepted by `prepare_mesh()`: beyond
/// it, a samples-by-vertices geodesic matrix no longer fits in memory for any
/// useful number of samples, whatever the remeshing can do.
constexpr std::size_t maximum_target_number_of_vertices = 5000000;

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// The edge length `L` for which isotropic remeshing of a surface of area
/// `area` gives about `number_of_vertices` vertices.
///
/// Derivation: an equilateral triangle of side `L` has area `sqrt(3)/4 L^2`;
/// a closed triangle mesh of small genus has `F ~ 2V` faces (Euler: `V - E + F = 2 - 2g`, `2E = 3F`), so
/// `area ~ 2V sqrt(3)/4 L^2 = sqrt(3)/2 V L^2`, that is `V ~ 2 area / (sqrt(3) L^2)` and
/// `L = sqrt(2 area / (sqrt(3) V))`. (Writing `V ~ 2 area / (sqrt(3)/2 L^2)` would count
/// each triangle for a vertex, `F ~ V`, and double `V`.) Boundaries make `V` slightly larger.
inline double isotropic_edge_length_for_vertex_count(double area, double number_of_vertices)
{
  return std::sqrt(2. * area / (std::sqrt(3.) * number_of_vertices));
}

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// Makes the mesh the package works on: a `CGAL::Surface_mesh` copy of `tm`,
/// optionally with its holes filled, optionally remeshed or decimated to a
/// target vertex count, with the maps between its elements and those of `tm`.
/// `tm` is never modified.
///
/// - `mend_input(true)`: before anything else, the common defects that
///   `check_input()` refuses and `repair_input()` mends (pinched vertices,
///   polygons, faces with collinear vertices, isolated vertices; SCAPE's meshes
///   have a pinched vertex) are mended on a copy, which is then checked; what is
///   left (a face of tiny but non-zero area, a non-manifold edge, a non-finite
///   coordinate on a face) throws as `check_input()` does, the message saying
///   that it remains after `repair_input()`. Where something was mended, the maps
///   to the input are those of a remeshed input (below): by nearness, the
///   duplicated copies of a pinched vertex both leading back to it, and an input
///   vertex on no face located at its nearest working point (weights 0 where its
///   coordinates are not finite). `Prepared_mesh::input_repairs()` says what was
///   mended. Without it, such an input throws.
/// - `fill_holes(true)`: first, every boundary cycle of the copy is filled by
///   `PMP::triangulate_refine_and_fair_hole()` (a patch refined to the density of
///   its rim and faired for tangent continuity), so that geodesics and the
///   signatures see a closed surface. Without remeshing or decimation, input vertex `i`
///   and face `j` are still working vertex `i` and face `j`, and the added vertices and
///   faces come after them; the added vertices map to their nearest input vertex.
///   Every boundary is filled, whatever its size, unless `maximum_hole_boundary_length`
///   bounds the length of the cycles to fill: give it where the surface has an opening by
///   design (the base of a scanned bust) besides its holes. A boundary CGAL finds no
///   triangulation for stays open too; `Prepared_mesh::number_of_filled_holes()` and
///   `Prepared_mesh::number_of_holes_left_open()` count both kinds.
/// - Neither `target_number_of_vertices` nor `isotropic_remeshing` given, or a
///   target equal to the vertex count of `tm` without `isotropic_remeshing(true)`: the
///   working mesh is an exact copy (vertex `i` and face `j` of the working mesh are
///   vertex `i` and face `j` of the index maps of `tm`), and all maps are identities
///   (with `fill_holes(true)`, for the input's elements; the patches come after them).
/// - `isotropic_remeshing(true)`, or a target above the vertex count of `tm` (only
///   remeshing adds vertices; an explicit `isotropic_remeshing(false)` with such a target
///   throws): `PMP::isotropic_remeshing()` with the edge length
///   `isotropic_edge_length_for_vertex_count(area, target)` (target: `target_number_of_vertices`,
///   or the vertex count of `tm`). Remeshing keeps edges within [4/5, 4/3] of that length,
///   so the vertex count can miss the target by up to ~50 %: while the count is below the
///   target by more than 10 %, the input is remeshed again with a shorter length (at most six
///   runs); if it is then above the target by more than 10 %, edges are collapsed
///   (`Surface_mesh_simplification::edge_collapse()`) down to the target and the mesh is
///   evened out by remeshing without splits and collapses (flips and tangential relaxation).
/// - `target_number_of_vertices(n)` alone, `n` below the vertex count of `tm`:
///   `Surface_mesh_simplification::edge_collapse()` (Lindstrom-Turk cost and placement)
///   until `n` vertices remain.
///
/// The maps: each working vertex gets its nearest input vertex (kd-tree,
/// `CGAL::Orthogonal_k_neighbor_search`); each input vertex gets its nearest
/// point on the working mesh (`PMP::locate_with_AABB_tree()`, face and
/// barycentric coordinates), so that per-vertex scalar fields transfer to the
/// input by barycentric interpolation (`transfer_vertex_field_to_input()`);
/// each input face gets the working face nearest to its centroid
/// (`transfer_face_labels_to_input()`).
///
/// \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{target_number_of_vertices}
///     \cgalParamDescription{the number of vertices wanted for the working mesh}
///     \cgalParamType{an integer type}
///     \cgalParamDefault{no target: the input's vertex count}
///     \cgalParamExtra{must be at least 4 and at most `maximum_target_number_of_vertices`}
///   \cgalParamNEnd
///   \cgalParamNBegin{isotropic_remeshing}
///     \cgalParamDescription{whether to remesh isotropically (rather than decimate)}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`, `true` for a target above the vertex count of `tm`}
///   \cgalParamNEnd
///   \cgalParamNBegin{mend_input}
///     \cgalParamDescription{whether to mend the defects `repair_input()` mends before checking the input}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{fill_holes}
///     \cgalParamDescription{whether to fill every boundary cycle before remeshing or decimation}
///     \cgalParamType{`bool`}
///     \cgalParamDefault{`false`}
///   \cgalParamNEnd
///   \cgalParamNBegin{maximum_hole_boundary_length}
///     \cgalParamDescription{with `fill_holes(true)`, only the boundary cycles at most this long
///       (the sum of their edge lengths, as `PMP::face_border_length()` measures it) are filled}
///     \cgalParamType{`double`}
///     \cgalParamDefault{no bound: every cycle is filled}
///     \cgalParamExtra{must be positive; a finite bound needs `fill_holes(true)` (infinity: no bound)}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_iterations}
///     \cgalParamDescription{iterations of isotropic remeshing}
///     \cgalParamType{`unsigned int`}
///     \cgalParamDefault{`3`}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_samples}
///     \cgalParamDescription{the number of samples the caller will draw on the working mesh; checked against its vertex count}
///     \cgalParamType{an integer type}
///     \cgalParamDefault{not checked}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `%Point_3` as value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_index_map}
///     \cgalParamDescription{the indices by which input vertices are designated}
///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `std::size_t` as value type}
///     \cgalParamDefault{an automatically indexed internal map}
///   \cgalParamNEnd
///   \cgalParamNBegin{face_index_map}
///     \cgalParamDescription{the indices by which input faces are designated}
///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and `std::size_t` as value type}
///     \cgalParamDefault{an automatically indexed internal map}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{an instance of a geometric traits class}
///     \cgalParamType{a model of `Kernel`}
///     \cgalParamDefault{a \cgal kernel deduced from the point type}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \throws Input_error any problem of `check_input()` on `tm`, or with `mend_input(true)` on
///   the mended copy (the element index, if any, then refers to the input for a vertex and is
///   `no_element` for a face or an edge) (`too_many_samples` against
///   the working mesh); `invalid_parameter` for a target below 4 or above
///   `maximum_target_number_of_vertices`, or for a target above the vertex count of `tm`
///   with `isotropic_remeshing(false)`; `invalid_parameter` for a `maximum_hole_boundary_length`
///   that is not a positive number, or a finite one without `fill_holes(true)`.
template <typename TriangleMesh, typename CGAL_NP_TEMPLATE_PARAMETERS>
Prepared_mesh<typename GetGeomTraits<TriangleMesh, CGAL_NP_CLASS>::type>
prepare_mesh(const TriangleMesh& tm, const CGAL_NP_CLASS& np = parameters::default_values())
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  namespace SMS = CGAL::Surface_mesh_simplification;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::is_default_parameter;

  typedef typename GetGeomTraits<TriangleMesh, CGAL_NP_CLASS>::type GT;
  typedef typename GetVertexPointMap<TriangleMesh, CGAL_NP_CLASS>::const_type VPM;
  typedef Prepared_mesh<GT> Result;
  typedef typename Result::Working_mesh Working_mesh;
  typedef typename Result::Point_3 Point_3;
  typedef boost::graph_traits<TriangleMesh> Graph_traits;
  typedef typename Graph_traits::vertex_descriptor vertex_descriptor;
  typedef typename Graph_traits::halfedge_descriptor halfedge_descriptor;
  typedef typename Graph_traits::face_descriptor face_descriptor;
  typedef typename boost::graph_traits<Working_mesh>::face_descriptor working_face;
  typedef typename boost::graph_traits<Working_mesh>::vertex_descriptor working_vertex;

  const VPM vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                   get_const_property_map(CGAL::vertex_point, tm));
  const GT gt = choose_parameter<GT>(get_parameter(np, CGAL::internal_np::geom_traits));
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  const auto fim = CGAL::get_initialized_face_index_map(tm, np);

  // the maps below are only meaningful on a valid input: the input itself, or
  // with mend_input(true) its mended copy
  Input_repairs repairs;
  Working_mesh mended;
  const bool mend = choose_parameter(get_parameter(np, internal_np::mend_input), false);
  if(mend) {
    repairs = repair_input(tm, mended, np);
    try {
      internal::input_check_mesh(mended, get(CGAL::vertex_point, mended), get(boost::vertex_index, mended),
                                 get(boost::face_index, mended), gt);
    } catch(const Input_error& e) {
      const std::string what = e.what(), prefix = std::string(to_string(e.problem())) + ": ";
      const bool of_vertex = e.problem() == Input_problem::non_manifold_vertex ||
                             e.problem() == Input_problem::non_finite_coordinate ||
                             e.problem() == Input_problem::isolated_vertex;
      const std::size_t element = of_vertex && e.element() < repairs.output_to_input_vertex.size()
                                    ? repairs.output_to_input_vertex[e.element()] : Input_error::no_element;
      throw Input_error(e.problem(),
                        "left after repair_input(), on the mended copy: " +
                          (what.compare(0, prefix.size(), prefix) == 0 ? what.substr(prefix.size()) : what) +
                          (element != Input_error::no_element ? " (input vertex " + std::to_string(element) + ")" : ""),
                        element);
    }
    if(!repairs.any()) CGAL::clear(mended);
  }
  const bool mends = repairs.any();
  if(!mend) // with mend_input(true) the copy was checked: where nothing was mended, the same mesh
    internal::input_check_mesh(tm, vpm, vim, fim, gt);
  const Input_report input_report =
    mends ? internal::input_compute_report(mended, get(CGAL::vertex_point, mended), get(boost::face_index, mended), gt)
          : internal::input_compute_report(tm, vpm, fim, gt);
  repairs.output_to_input_vertex.clear(); // the working mesh's own map takes its place

  const std::size_t nv = internal::input_count(vertices(tm)), nf = internal::input_count(faces(tm));
  const bool remesh_given = !is_default_parameter<CGAL_NP_CLASS, internal_np::isotropic_remeshing_t>::value;
  bool remesh = choose_parameter(get_parameter(np, internal_np::isotropic_remeshing), false);
  const bool has_target = !is_default_parameter<CGAL_NP_CLASS, internal_np::target_number_of_vertices_t>::value;
  long long target_count = (long long)nv;
  if(has_target) {
    target_count = (long long)choose_parameter(get_parameter(np, internal_np::target_number_of_vertices), 0);
    if(target_count < 4 || target_count > (long long)maximum_target_number_of_vertices) {
      std::ostringstream os;
      os << "target_number_of_vertices is " << target_count << ", it must be between 4 and "
         << maximum_target_number_of_vertices;
      throw Input_error(Input_problem::invalid_parameter, os.str());
    }
    // decimation only removes vertices: a larger count needs remeshing
    if(std::size_t(target_count) > nv) {
      if(remesh_given && !remesh) {
        std::ostringstream os;
        os << "target_number_of_vertices is " << target_count << ", above the " << nv
           << " vertices of the input, but isotropic_remeshing(false) forbids adding vertices";
        throw Input_error(Input_problem::invalid_parameter, os.str());
      }
      remesh = true;
    }
  }
  const unsigned int iterations = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations), 3u);
  const bool fill_holes = choose_parameter(get_parameter(np, internal_np::fill_holes), false);
  const double maximum_hole_boundary_length = choose_parameter(
    get_parameter(np, internal_np::maximum_hole_boundary_length), std::numeric_limits<double>::infinity());
  if(!(maximum_hole_boundary_length > 0)) {
    std::ostringstream os;
    os << "maximum_hole_boundary_length is " << maximum_hole_boundary_length << ", it must be positive";
    throw Input_error(Input_problem::invalid_parameter, os.str());
  }
  // a bound on the holes to fill means nothing without filling: say so rather than ignore it
  if(std::isfinite(maximum_hole_boundary_length) && !fill_holes)
    throw Input_error(Input_problem::invalid_parameter,
                      "maximum_hole_boundary_length is given without fill_holes(true): no hole would be filled");

  // the exact copy: vertices in vertex-index order, faces in face-index order
  // (or the mended copy); the input's points, also for the maps
  std::vector<Point_3> points(nv);
  for(vertex_descriptor v : vertices(tm))
    points[std::size_t(get(vim, v))] = get(vpm, v);
  Working_mesh working;
  if(mends) {
    working = std::move(mended);
  } else {
    std::vector<std::array<std::size_t, 3> > triangles(nf);
    for(face_descriptor f : faces(tm)) {
      const halfedge_descriptor h = halfedge(f, tm);
      triangles[std::size_t(get(fim, f))] = {{std::size_t(get(vim, target(h, tm))),
                                              std::size_t(get(vim, target(next(h, tm), tm))),
                                              std::size_t(get(vim, target(next(next(h, tm), tm), tm)))}};
    }
    PMP::polygon_soup_to_polygon_mesh(points, triangles, working);
  }
  const internal::Prepare_fill_outcome holes = fill_holes
    ? internal::prepare_fill_holes(working, maximum_hole_boundary_length) : internal::Prepare_fill_outcome();

  Mesh_preparation preparation = Mesh_preparation::none;
  double edge_length = 0;
  if(remesh) {
    const double area = CGAL::to_double(PMP::area(working));
    edge_length = isotropic_edge_length_for_vertex_count(area, double(target_count));
    // Isotropic remeshing keeps edges in [4/5 L, 4/3 L], so its vertex count can
    // stay up to ~1.5x off the target (a regular input sits in that band). Shorten
    // L until the count reaches the target, then, if it overshoots by more than
    // 10 %, collapse edges down to the target and even the mesh out with flips and
    // tangential relaxation (remeshing without splits and collapses).
    // Sharp turns of the border are features: remeshing would cut such corners.
    auto corner = working.template add_property_map<working_vertex, bool>("v:irs_border_corner", false).first;
    for(auto h : halfedges(working)) {
      if(!is_border(h, working)) continue;
      const auto d1 = working.point(target(h, working)) - working.point(source(h, working));
      const auto d2 = working.point(target(next(h, working), working)) - working.point(target(h, working));
      const double cosine = CGAL::to_double(d1 * d2) /
                            std::sqrt(CGAL::to_double(d1.squared_length() * d2.squared_length()));
      if(cosine < std::cos(CGAL_PI / 6)) put(corner, target(h, working), true);
    }
    double length = edge_length;
    Working_mesh trial;
    bool close_enough = false;
    for(int attempt = 0; attempt < 6; ++attempt) {
      trial = working;
      PMP::isotropic_remeshing(faces(trial), length, trial,
                               CGAL::parameters::number_of_iterations(iterations)
                                 .vertex_is_constrained_map(trial.template property_map<working_vertex, bool>(
                                   "v:irs_border_corner").first));
      trial.collect_garbage();
      const double ratio = double(trial.number_of_vertices()) / double(target_count);
      if(std::abs(ratio - 1.) <= 0.1) { close_enough = true; break; }
      if(ratio > 1.) break;
      length *= (std::min)(0.9, std::sqrt(ratio));
    }
    if(!close_enough && trial.number_of_vertices() > std::size_t(target_count)) {
      SMS::edge_collapse(trial, internal::Prepare_vertex_count_stop_predicate(std::size_t(target_count)));
      trial.collect_garbage();
      PMP::isotropic_remeshing(faces(trial), edge_length, trial,
                               CGAL::parameters::number_of_iterations(iterations).do_split(false).do_collapse(false)
                                 .vertex_is_constrained_map(trial.template property_map<working_vertex, bool>(
                                   "v:irs_border_corner").first));
      trial.collect_garbage();
    }
    working = std::move(trial);
    auto left = working.template property_map<working_vertex, bool>("v:irs_border_corner");
    if(left.second) working.remove_property_map(left.first);
    preparation = Mesh_preparation::isotropic_remeshing;
  } else if(has_target && std::size_t(target_count) < nv) {
    SMS::edge_collapse(working, internal::Prepare_vertex_count_stop_predicate(std::size_t(target_count)));
    working.collect_garbage();
    preparation = Mesh_preparation::decimation;
  }

  long long samples = 0;
  if(internal::input_number_of_samples(np, samples)) {
    if(samples < 0) {
      std::ostringstream os;
      os << "number_of_samples is " << samples << ", it must be positive";
      throw Input_error(Input_problem::invalid_parameter, os.str());
    }
    if(std::size_t(samples) > working.number_of_vertices()) {
      std::ostringstream os;
      os << samples << " samples requested, but the working mesh has only " << working.number_of_vertices()
         << " vertices";
      throw Input_error(Input_problem::too_many_samples, os.str());
    }
  }

  const std::size_t nw = working.number_of_vertices();
  std::vector<std::size_t> working_to_input(nw);
  std::vector<Input_vertex_location> locations(nv);
  std::vector<std::size_t> face_map(nf);

  // identity maps: the working mesh is the input's copy (with its holes' patches after it)
  const bool copy = preparation == Mesh_preparation::none && !mends;
  if(copy) {
    for(std::size_t i = 0; i < nv; ++i) {
      working_to_input[i] = i;
      Input_vertex_location& l = locations[i];
      // a corner of the first face around the vertex, with weight 1
      const working_vertex wv(static_cast<typename Working_mesh::size_type>(i));
      const auto h = halfedge(wv, working);
      const working_face f = is_border(h, working) ? face(opposite(h, working), working) : face(h, working);
      const auto hf = halfedge(f, working);
      l.face = std::size_t(f);
      l.vertices = {{std::size_t(source(hf, working)), std::size_t(target(hf, working)),
                     std::size_t(target(next(hf, working), working))}};
      for(std::size_t k = 0; k < 3; ++k) l.weights[k] = l.vertices[k] == i ? 1. : 0.;
    }
    for(std::size_t j = 0; j < nf; ++j) face_map[j] = j;
  }

  // the input vertices on a face: after mending (which removes the others,
  // isolated), those alone have a place on the working surface; a vertex of a
  // face is finite, or mending would have failed above
  std::vector<char> on_face;
  if(mends) {
    on_face.assign(nv, 0);
    for(face_descriptor f : faces(tm))
      for(halfedge_descriptor h : halfedges_around_face(halfedge(f, tm), tm))
        on_face[std::size_t(get(vim, target(h, tm)))] = 1;
  }

  // working vertex -> nearest input vertex, for the vertices that are not
  // copies of input vertices (all of them after mending, remeshing or
  // decimation; then the input vertices on no face, or not finite, are left
  // out: the mending removed them)
  const std::size_t first_new_vertex = copy ? nv : 0;
  if(first_new_vertex < nw) {
    std::vector<std::size_t> candidates;
    if(mends) {
      for(std::size_t i = 0; i < nv; ++i)
        if(on_face[i]) candidates.push_back(i);
    } else {
      candidates.resize(nv);
      std::iota(candidates.begin(), candidates.end(), std::size_t(0));
    }
    typedef CGAL::Search_traits_3<GT> Base_traits;
    typedef typename CGAL::Pointer_property_map<Point_3>::const_type Point_pmap;
    typedef CGAL::Search_traits_adapter<std::size_t, Point_pmap, Base_traits> Traits;
    typedef CGAL::Orthogonal_k_neighbor_search<Traits> Neighbor_search;
    typedef typename Neighbor_search::Tree Tree;
    typedef typename Neighbor_search::Distance Distance;
    const Point_pmap ppmap = CGAL::make_property_map(std::as_const(points));
    Tree tree(candidates.begin(), candidates.end(), typename Tree::Splitter(), Traits(ppmap));
    const Distance distance(ppmap);
    for(std::size_t w = first_new_vertex; w < nw; ++w) {
      Neighbor_search search(tree, working.point(working_vertex(static_cast<typename Working_mesh::size_type>(w))),
                             1, 0, true, distance);
      working_to_input[w] = search.begin()->first;
    }
  }

  // input vertex -> location on the working mesh; input face -> nearest working face
  if(!copy) {
    typedef CGAL::AABB_face_graph_triangle_primitive<Working_mesh> Primitive;
    typedef CGAL::AABB_traits<GT, Primitive> AABB_traits;
    typedef CGAL::AABB_tree<AABB_traits> Tree;
    Tree tree;
    PMP::build_AABB_tree(working, tree);
    tree.accelerate_distance_queries();
    for(std::size_t i = 0; i < nv; ++i) {
      if(!on_face.empty() && !on_face[i]) { // an isolated vertex that mending removed: no point of the surface
        locations[i].located = false;
        continue;
      }
      const auto loc = PMP::locate_with_AABB_tree(points[i], tree, working);
      const auto hf = halfedge(loc.first, working);
      Input_vertex_location& l = locations[i];
      l.face = std::size_t(loc.first);
      l.vertices = {{std::size_t(source(hf, working)), std::size_t(target(hf, working)),
                     std::size_t(target(next(hf, working), working))}};
      for(std::size_t k = 0; k < 3; ++k) l.weights[k] = CGAL::to_double(loc.second[k]);
    }
    for(face_descriptor f : faces(tm)) { // the centroid of the corners (polygons too, when mended)
      double c[3] = {0, 0, 0}, k = 0;
      for(halfedge_descriptor h : halfedges_around_face(halfedge(f, tm), tm)) {
        const Point_3& p = points[std::size_t(get(vim, target(h, tm)))];
        c[0] += CGAL::to_double(p.x()); c[1] += CGAL::to_double(p.y()); c[2] += CGAL::to_double(p.z());
        k += 1;
      }
      face_map[std::size_t(get(fim, f))] =
        std::size_t(tree.closest_point_and_primitive(Point_3(c[0] / k, c[1] / k, c[2] / k)).second);
    }
  }

  return Result(std::move(working), preparation, edge_length, std::move(working_to_input),
                std::move(locations), std::move(face_map), holes.filled, holes.left_open, std::move(repairs),
                input_report);
}

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// Transfers a per-vertex scalar field of the working mesh to the input's
/// vertices by barycentric interpolation at their locations on the working
/// mesh. Exact for fields that are linear on the working faces; a copy
/// without preparation. Infinite values propagate (a zero weight does not
/// turn an infinite value into NaN). An input vertex that lies nowhere (an
/// isolated vertex that `mend_input(true)` removed) gets NaN.
///
/// \tparam WorkingValues a random access range of numbers, indexed by working vertex index
/// \returns the field on the input vertices, in input vertex index order
/// \throws Input_error `invalid_parameter` if `working_values` has fewer entries than working vertices
template <typename GeomTraits, typename WorkingValues>
std::vector<double> transfer_vertex_field_to_input(const Prepared_mesh<GeomTraits>& prepared,
                                                   const WorkingValues& working_values)
{
  internal::prepare_check_size(std::size_t(boost::size(working_values)), prepared.number_of_working_vertices(),
                               "working vertex values");
  std::vector<double> out(prepared.number_of_input_vertices());
  for(std::size_t i = 0; i < out.size(); ++i) {
    const Input_vertex_location& l = prepared.input_vertex_location(i);
    if(!l.located) {
      out[i] = std::numeric_limits<double>::quiet_NaN();
      continue;
    }
    double value = 0;
    for(std::size_t k = 0; k < 3; ++k)
      if(l.weights[k] != 0)
        value += l.weights[k] * double(working_values[l.vertices[k]]);
    out[i] = value;
  }
  return out;
}

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// Transfers per-vertex labels (any copyable type) of the working mesh to the
/// input's vertices: each input vertex takes the label of
/// `prepared.input_to_working_vertex(i)`, and an input vertex that lies nowhere
/// (an isolated vertex that `mend_input(true)` removed) takes `no_label`.
///
/// \tparam WorkingLabels a random access range, indexed by working vertex index
/// \returns the labels of the input vertices, in input vertex index order
/// \throws Input_error `invalid_parameter` if `working_labels` has fewer entries than working vertices
template <typename GeomTraits, typename WorkingLabels>
std::vector<typename boost::range_value<WorkingLabels>::type>
transfer_vertex_labels_to_input(const Prepared_mesh<GeomTraits>& prepared, const WorkingLabels& working_labels,
                                const typename boost::range_value<WorkingLabels>::type& no_label =
                                  typename boost::range_value<WorkingLabels>::type())
{
  internal::prepare_check_size(std::size_t(boost::size(working_labels)), prepared.number_of_working_vertices(),
                               "working vertex labels");
  std::vector<typename boost::range_value<WorkingLabels>::type> out;
  out.reserve(prepared.number_of_input_vertices());
  for(std::size_t i = 0; i < prepared.number_of_input_vertices(); ++i) {
    const std::size_t w = prepared.input_to_working_vertex(i);
    out.push_back(w == Prepared_mesh<GeomTraits>::no_vertex ? no_label : working_labels[w]);
  }
  return out;
}

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// Transfers a map from working vertices to working vertices (for example the
/// partners of `symmetric_vertex_map()`, negative for none) to the input: input
/// vertex `i` takes the partner of `prepared.input_to_working_vertex(i)`, as the
/// input vertex nearest to it (`prepared.working_to_input_vertex()`), or -1
/// (also for an input vertex that lies nowhere: an isolated vertex that
/// `mend_input(true)` removed).
///
/// \tparam WorkingPartners a random access range of signed integers, indexed by working vertex index
/// \returns the partner of each input vertex, in input vertex index order
/// \throws Input_error `invalid_parameter` if `working_partners` has fewer entries than working
///   vertices, or if a partner is not a working vertex
template <typename GeomTraits, typename WorkingPartners>
std::vector<std::ptrdiff_t> transfer_vertex_map_to_input(const Prepared_mesh<GeomTraits>& prepared,
                                                         const WorkingPartners& working_partners)
{
  internal::prepare_check_size(std::size_t(boost::size(working_partners)), prepared.number_of_working_vertices(),
                               "working vertex partners");
  std::vector<std::ptrdiff_t> out(prepared.number_of_input_vertices(), -1);
  for(std::size_t i = 0; i < out.size(); ++i) {
    const std::size_t at = prepared.input_to_working_vertex(i);
    if(at == Prepared_mesh<GeomTraits>::no_vertex) continue;
    const long long w = (long long)working_partners[at];
    if(w < 0) continue;
    if(std::size_t(w) >= prepared.number_of_working_vertices()) {
      std::ostringstream os;
      os << "partner " << w << " is not a working vertex (" << prepared.number_of_working_vertices() << " of them)";
      throw Input_error(Input_problem::invalid_parameter, os.str());
    }
    out[i] = std::ptrdiff_t(prepared.working_to_input_vertex(std::size_t(w)));
  }
  return out;
}

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// Transfers per-face labels (any copyable type, for example segment ids) of
/// the working mesh to the input's faces: each input face takes the label of
/// the working face nearest to its centroid.
///
/// \tparam WorkingLabels a random access range, indexed by working face index
/// \returns the labels of the input faces, in input face index order
/// \throws Input_error `invalid_parameter` if `working_labels` has fewer entries than working faces
template <typename GeomTraits, typename WorkingLabels>
std::vector<typename boost::range_value<WorkingLabels>::type>
transfer_face_labels_to_input(const Prepared_mesh<GeomTraits>& prepared, const WorkingLabels& working_labels)
{
  internal::prepare_check_size(std::size_t(boost::size(working_labels)), prepared.number_of_working_faces(),
                               "working face labels");
  std::vector<typename boost::range_value<WorkingLabels>::type> out;
  out.reserve(prepared.number_of_input_faces());
  for(std::size_t j = 0; j < prepared.number_of_input_faces(); ++j)
    out.push_back(working_labels[prepared.input_to_working_face(j)]);
  return out;
}

} // namespace Intrinsic_reflectional_symmetry_3
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_PREPARE_MESH_H
