// Copyright (c) 2026 The Intrinsic_reflectional_symmetry_3 project.
// SPDX-License-Identifier: LGPL-3.0-or-later
// Author(s)     : The Intrinsic_reflectional_symmetry_3 developers

#ifndef CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_CHECK_INPUT_H
#define CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_CHECK_INPUT_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Intrinsic_reflectional_symmetry_3/errors.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/parameters.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/input_helpers.h>

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair.h>
#include <CGAL/Polygon_mesh_processing/repair_degeneracies.h>
#include <CGAL/Polygon_mesh_processing/shape_predicates.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Dynamic_property_map.h>

#include <boost/range/size.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <system_error>
#include <tuple>
#include <utility>
#include <vector>

/// \file check_input.h
/// Reading a mesh file, checking that a mesh is a valid input of the package,
/// and mending common defects on a copy.
///
/// The package's input is a triangle mesh whose vertices are all used by a
/// face, with finite coordinates, no non-manifold vertex or edge, and no
/// degenerate face. Boundaries (small holes) and several connected components
/// are accepted, as in Fig. 11 of the paper.

namespace CGAL {
namespace Intrinsic_reflectional_symmetry_3 {

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// Figures about a mesh that passed `check_input()`, meant for reports
/// (the command-line tool writes them into `report.json`).
struct Input_report
{
  std::size_t number_of_vertices = 0;
  std::size_t number_of_faces = 0;
  std::size_t number_of_edges = 0;
  std::size_t number_of_connected_components = 0;  ///< face-connected components
  std::size_t number_of_boundary_cycles = 0;       ///< holes and open boundaries
  std::size_t number_of_border_edges = 0;
  double longest_boundary_cycle_length = 0;        ///< length of the longest boundary cycle (0 when closed)
  double bounding_box_diagonal = 0;                ///< length of the diagonal of the axis-aligned bounding box
  double mean_edge_length = 0;
  double area = 0;                                 ///< total surface area
};

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// What `repair_input()` mended, element counts.
struct Input_repairs
{
  std::size_t duplicated_non_manifold_vertices = 0; ///< new vertices created by `PMP::duplicate_non_manifold_vertices()`
  std::size_t triangulated_faces = 0;               ///< non-triangle faces split by `PMP::triangulate_faces()`
  std::size_t removed_degenerate_faces = 0;         ///< degenerate faces (as `check_input()` says) eliminated by step 4 of `repair_input()`
  std::size_t removed_isolated_vertices = 0;        ///< isolated vertices left out
  /// for each vertex of the mended mesh, in iteration order, the index of the input vertex it comes from
  std::vector<std::size_t> output_to_input_vertex;

  /// whether anything was changed
  bool any() const
  {
    return duplicated_non_manifold_vertices + triangulated_faces +
           removed_degenerate_faces + removed_isolated_vertices > 0;
  }
};

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// A face whose area is at most this fraction of the mean face area is
/// degenerate for `check_input()`: at that ratio the area is at the level of
/// floating-point noise, and cotangent weights blow up on such faces.
constexpr double degenerate_face_relative_area = 1e-10;

/// \cond SKIP_IN_MANUAL
namespace internal {
// `where` is appended to the messages (the file name when reading a file).
template <typename PointRange, typename PolygonRange>
void input_check_polygon_soup(const PointRange& points, const PolygonRange& polygons, const std::string& where)
{
  const std::size_t np = boost::size(points), nf = boost::size(polygons);
  if(np == 0 || nf == 0) {
    std::ostringstream os;
    os << "the soup has " << np << " points and " << nf << " polygons" << where;
    throw Input_error(Input_problem::empty_mesh, os.str());
  }

  Input_offenders out_of_range, too_small, repeated;
  std::size_t pi = 0;
  for(const auto& polygon : polygons) {
    const std::size_t k = boost::size(polygon);
    std::vector<std::size_t> ids(polygon.begin(), polygon.end());
    for(std::size_t id : ids)
      if(id >= np) {
        out_of_range.add(pi, [&] {
          std::ostringstream os;
          os << "polygon " << pi << " refers to vertex " << id << ", but there are only " << np << " vertices";
          return os.str();
        });
        break;
      }
    if(k < 3)
      too_small.add(pi, [&] {
        std::ostringstream os;
        os << "polygon " << pi << " has " << k << " vertices";
        return os.str();
      });
    std::sort(ids.begin(), ids.end());
    const auto dup = std::adjacent_find(ids.begin(), ids.end());
    if(dup != ids.end())
      repeated.add(pi, [&] {
        std::ostringstream os;
        os << "polygon " << pi << " uses vertex " << *dup << " more than once";
        return os.str();
      });
    ++pi;
  }
  if(!out_of_range.empty()) out_of_range.raise(Input_problem::unreadable_file, "polygons with an invalid vertex index", where);
  if(!too_small.empty()) too_small.raise(Input_problem::not_triangle_mesh, "polygons with fewer than 3 vertices", where);
  if(!repeated.empty()) repeated.raise(Input_problem::degenerate_face, "polygons with a repeated vertex", where);

  // undirected edges, sorted, to count the polygons around each
  std::vector<std::tuple<std::size_t, std::size_t, std::size_t> > edges; // (min, max, polygon)
  pi = 0;
  for(const auto& polygon : polygons) {
    const std::vector<std::size_t> ids(polygon.begin(), polygon.end());
    for(std::size_t j = 0; j < ids.size(); ++j) {
      const std::size_t a = ids[j], b = ids[(j + 1) % ids.size()];
      edges.emplace_back((std::min)(a, b), (std::max)(a, b), pi);
    }
    ++pi;
  }
  std::sort(edges.begin(), edges.end());
  Input_offenders non_manifold;
  for(std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while(j < edges.size() && std::get<0>(edges[j]) == std::get<0>(edges[i]) &&
          std::get<1>(edges[j]) == std::get<1>(edges[i]))
      ++j;
    if(j - i > 2) {
      const std::size_t a = std::get<0>(edges[i]), b = std::get<1>(edges[i]), p = std::get<2>(edges[i]);
      const std::size_t k = j - i;
      non_manifold.add(p, [&] {
        std::ostringstream os;
        os << "edge (" << a << ", " << b << ") of polygon " << p << " is shared by " << k << " polygons";
        return os.str();
      });
    }
    i = j;
  }
  if(!non_manifold.empty()) non_manifold.raise(Input_problem::non_manifold_edge, "edges shared by more than two polygons", where);
}
} // namespace internal
/// \endcond

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// Checks the structure of a polygon soup: everything that cannot be
/// represented in a halfedge mesh, and so must be reported before one is built.
/// Checks, in this order, and throws `Input_error` for the first failing class
/// (the message names the first offending polygon, in the order of `polygons`,
/// and how many there are):
/// - `empty_mesh`: no point or no polygon;
/// - `unreadable_file`: a polygon refers to a point index that does not exist;
/// - `not_triangle_mesh`: a polygon has fewer than three vertices (larger
///   polygons are representable, `check_input()` rejects them on the mesh);
/// - `degenerate_face`: a polygon uses the same point twice;
/// - `non_manifold_edge`: an edge is shared by more than two polygons
///   (`element()` is the first polygon holding such an edge).
///
/// \tparam PointRange a random access range of points
/// \tparam PolygonRange a random access range of random access ranges of `std::size_t`
template <typename PointRange, typename PolygonRange>
void check_polygon_soup(const PointRange& points, const PolygonRange& polygons)
{
  internal::input_check_polygon_soup(points, polygons, std::string());
}

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// Reads a mesh from an OFF, OBJ, PLY or STL file (CGAL's readers), keeping
/// the file's vertex and face order: vertex `i` and face `j` of `out`
/// (in iteration order) are vertex `i` and polygon `j` of the file.
///
/// The file is read as a polygon soup, checked by `check_polygon_soup()`, its
/// polygons are oriented consistently (`PMP::orient_polygon_soup()`; only
/// the order of the vertices of some faces may change), and it is turned into
/// a mesh with `PMP::polygon_soup_to_polygon_mesh()`. Defects that a mesh can
/// represent are kept as they are, so that `check_input()` reports them and
/// `repair_input()` can mend them: non-triangle faces, isolated vertices,
/// non-finite coordinates, degenerate faces and non-manifold (pinched)
/// vertices.
///
/// `out` is cleared first.
///
/// \tparam TriangleMesh a model of `MutableFaceGraph`
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `out`}
///     \cgalParamType{a model of `WritablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, out)`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \throws Input_error `unreadable_file` (missing or unreadable file, unknown
///   extension, content that CGAL's reader cannot parse, invalid vertex
///   index), `empty_mesh` (empty file or no face), `non_finite_coordinate`
///   (a "nan" or "inf" coordinate in an ASCII OFF or OBJ file, which CGAL's
///   readers cannot parse), and the problems of `check_polygon_soup()`;
///   `non_manifold_edge` also for a surface that cannot be oriented.
template <typename TriangleMesh, typename CGAL_NP_TEMPLATE_PARAMETERS>
void read_mesh(const std::string& path, TriangleMesh& out,
               const CGAL_NP_CLASS& np = parameters::default_values())
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  typedef typename GetVertexPointMap<TriangleMesh, CGAL_NP_CLASS>::type VPM;
  typedef typename boost::property_traits<VPM>::value_type Point;
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;

  std::error_code ec;
  if(!std::filesystem::is_regular_file(path, ec))
    throw Input_error(Input_problem::unreadable_file, "cannot open '" + path + "': no such file");
  {
    std::ifstream probe(path, std::ios::binary);
    if(!probe)
      throw Input_error(Input_problem::unreadable_file, "cannot open '" + path + "'");
  }
  const std::string ext = internal::input_lowercase_extension(path);
  if(ext != "off" && ext != "obj" && ext != "ply" && ext != "stl")
    throw Input_error(Input_problem::unreadable_file,
                      "cannot read '" + path + "': unsupported extension '" + ext +
                      "' (expected .off, .obj, .ply or .stl)");
  if(std::filesystem::file_size(path, ec) == 0 && !ec)
    throw Input_error(Input_problem::empty_mesh, "file '" + path + "' is empty");

  std::vector<Point> points;
  std::vector<std::vector<std::size_t> > polygons;
  bool ok = false;
  try {
    ok = CGAL::IO::read_polygon_soup(path, points, polygons, CGAL::parameters::verbose(false));
  } catch(const std::exception&) {
    ok = false; // some CGAL readers throw on malformed content
  }
  if(!ok) {
    const std::size_t v = internal::input_find_non_finite_vertex_in_ascii_file(path, ext);
    if(v != Input_error::no_element) {
      std::ostringstream os;
      os << "vertex " << v << " of '" << path << "' has a NaN or infinite coordinate";
      throw Input_error(Input_problem::non_finite_coordinate, os.str(), v);
    }
    throw Input_error(Input_problem::unreadable_file,
                      "cannot parse '" + path + "' as a ." + ext + " mesh");
  }

  internal::input_check_polygon_soup(points, polygons, " in '" + path + "'");

  const std::size_t n = points.size();
  std::vector<std::pair<std::size_t, std::size_t> > duplicates;
  PMP::orient_polygon_soup(points, polygons,
                           CGAL::parameters::visitor(internal::Input_orientation_visitor(duplicates)));

  // A copy made for any other reason than a pinched vertex means that the
  // surface cannot be oriented: an ordered edge then still appears twice
  // once copies are mapped back to their originals.
  {
    std::vector<std::size_t> original_of(points.size());
    for(std::size_t i = 0; i < points.size(); ++i) original_of[i] = i;
    for(const auto& od : duplicates) original_of[od.second] = original_of[od.first];
    std::vector<std::tuple<std::size_t, std::size_t, std::size_t> > directed;
    for(std::size_t p = 0; p < polygons.size(); ++p)
      for(std::size_t j = 0; j < polygons[p].size(); ++j)
        directed.emplace_back(original_of[polygons[p][j]],
                              original_of[polygons[p][(j + 1) % polygons[p].size()]], p);
    std::sort(directed.begin(), directed.end());
    for(std::size_t i = 0; i + 1 < directed.size(); ++i)
      if(std::get<0>(directed[i]) == std::get<0>(directed[i + 1]) &&
         std::get<1>(directed[i]) == std::get<1>(directed[i + 1])) {
        std::ostringstream os;
        os << "the surface in '" << path << "' cannot be oriented consistently: edge ("
           << std::get<0>(directed[i]) << ", " << std::get<1>(directed[i]) << ") of polygon "
           << std::get<2>(directed[i]) << " is where the orientation flips (as on a Moebius strip)";
        throw Input_error(Input_problem::non_manifold_edge, os.str(), std::get<2>(directed[i]));
      }
  }
  if(!PMP::is_polygon_soup_a_polygon_mesh(polygons))
    throw Input_error(Input_problem::non_manifold_edge,
                      "'" + path + "' does not describe a polygon mesh, even with its pinched vertices split");

  CGAL::clear(out);
  PMP::polygon_soup_to_polygon_mesh(points, polygons, out, CGAL::parameters::default_values(), np);

  // The converter adds one vertex per point, in order (isolated ones too).
  std::vector<vertex_descriptor> vertex_of_point(vertices(out).begin(), vertices(out).end());
  if(vertex_of_point.size() != points.size())
    throw Input_error(Input_problem::unreadable_file, "'" + path + "': vertices were lost while building the mesh");
  internal::input_merge_duplicated_vertices(out, vertex_of_point, duplicates);
  CGAL_assertion(internal::input_count(vertices(out)) == n);
  CGAL_USE(n);
}

/// \cond SKIP_IN_MANUAL
namespace internal {

// Which faces check_input() calls degenerate (collinear corners, or an area at
// most degenerate_face_relative_area times the mean), in iteration order;
// repair_input() counts them the same way.
struct Input_face_degeneracy
{
  std::vector<double> areas;
  std::vector<char> collinear;
  double mean_area = 0, threshold = 0;

  template <typename TriangleMesh, typename NP>
  Input_face_degeneracy(const TriangleMesh& tm, const NP& np)
  {
    namespace PMP = CGAL::Polygon_mesh_processing;
    double total = 0;
    for(auto f : faces(tm)) {
      areas.push_back(CGAL::to_double(PMP::face_area(f, tm, np)));
      collinear.push_back(PMP::is_degenerate_triangle_face(f, tm, np));
      total += areas.back();
    }
    mean_area = areas.empty() ? 0. : total / double(areas.size());
    threshold = degenerate_face_relative_area * total / double((std::max)(std::size_t(1), areas.size()));
  }
  bool degenerate(std::size_t i) const { return collinear[i] || areas[i] <= threshold; }
  std::size_t count() const
  {
    std::size_t n = 0;
    for(std::size_t i = 0; i < areas.size(); ++i) n += degenerate(i);
    return n;
  }
};

// Every check of check_input() except the sample count.
template <typename TriangleMesh, typename VPM, typename VIM, typename FIM, typename GT>
void input_check_mesh(const TriangleMesh& tm, const VPM& vpm, const VIM& vim, const FIM& fim, const GT& gt)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  typedef boost::graph_traits<TriangleMesh> Graph_traits;
  typedef typename Graph_traits::vertex_descriptor vertex_descriptor;
  typedef typename Graph_traits::halfedge_descriptor halfedge_descriptor;
  typedef typename Graph_traits::face_descriptor face_descriptor;

  const std::size_t nv = input_count(vertices(tm)), nf = input_count(faces(tm));
  if(nv == 0 || nf == 0) {
    std::ostringstream os;
    os << "the mesh has " << nv << " vertices and " << nf << " faces";
    throw Input_error(Input_problem::empty_mesh, os.str());
  }
  input_check_index_map(vertices(tm), vim, "vertex");
  input_check_index_map(faces(tm), fim, "face");

  Input_offenders non_triangles;
  for(face_descriptor f : faces(tm)) {
    std::size_t d = 0;
    for(halfedge_descriptor h : halfedges_around_face(halfedge(f, tm), tm)) { CGAL_USE(h); ++d; }
    if(d != 3)
      non_triangles.add(std::size_t(get(fim, f)), [&] {
        std::ostringstream os;
        os << "face " << get(fim, f) << " has " << d << " vertices";
        return os.str();
      });
  }
  if(!non_triangles.empty()) non_triangles.raise(Input_problem::not_triangle_mesh, "non-triangle faces");

  Input_offenders non_finite;
  for(vertex_descriptor v : vertices(tm)) {
    const auto& p = get(vpm, v);
    if(!input_is_finite(p))
      non_finite.add(std::size_t(get(vim, v)), [&] {
        std::ostringstream os;
        os << "vertex " << get(vim, v) << " has coordinates (" << CGAL::to_double(p.x()) << ", "
           << CGAL::to_double(p.y()) << ", " << CGAL::to_double(p.z()) << ")";
        return os.str();
      });
  }
  if(!non_finite.empty()) non_finite.raise(Input_problem::non_finite_coordinate, "vertices with a non-finite coordinate");

  Input_offenders isolated;
  for(vertex_descriptor v : vertices(tm)) {
    bool has_face = false;
    if(halfedge(v, tm) != Graph_traits::null_halfedge())
      for(halfedge_descriptor h : halfedges_around_target(v, tm))
        if(!is_border(h, tm) || !is_border(opposite(h, tm), tm)) { has_face = true; break; }
    if(!has_face)
      isolated.add(std::size_t(get(vim, v)), [&] {
        std::ostringstream os;
        os << "vertex " << get(vim, v) << " belongs to no face";
        return os.str();
      });
  }
  if(!isolated.empty()) isolated.raise(Input_problem::isolated_vertex, "isolated vertices");

  // PMP::non_manifold_vertices() is linear; PMP::is_non_manifold_vertex() is linear per vertex.
  std::vector<halfedge_descriptor> cones;
  PMP::non_manifold_vertices(tm, std::back_inserter(cones));
  if(!cones.empty()) {
    std::vector<std::size_t> ids;
    for(halfedge_descriptor h : cones) ids.push_back(std::size_t(get(vim, target(h, tm))));
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    std::vector<std::size_t> fans;
    for(std::size_t id : ids)
      fans.push_back(std::size_t(std::count_if(cones.begin(), cones.end(), [&](halfedge_descriptor h) {
        return std::size_t(get(vim, target(h, tm))) == id; })));
    std::ostringstream os;
    os << "vertex " << ids.front() << " is shared by " << fans.front()
       << " fans of faces that only touch there (" << ids.size() << " non-manifold vertices in total)";
    throw Input_error(Input_problem::non_manifold_vertex, os.str(), ids.front());
  }
  // A halfedge mesh cannot hold an edge with more than two faces: that check
  // is done on the soup (check_polygon_soup(), read_mesh()).

  const Input_face_degeneracy d(tm, CGAL::parameters::vertex_point_map(vpm).geom_traits(gt));
  Input_offenders degenerate;
  std::size_t i = 0;
  for(face_descriptor f : faces(tm)) {
    if(d.degenerate(i))
      degenerate.add(std::size_t(get(fim, f)), [&] {
        std::ostringstream os;
        os << "face " << get(fim, f) << (d.collinear[i] ? " has collinear vertices" : " has a near-zero area")
           << " (area " << d.areas[i] << ", mean face area " << d.mean_area << ")";
        return os.str();
      });
    ++i;
  }
  if(!degenerate.empty()) degenerate.raise(Input_problem::degenerate_face, "degenerate faces");
}

template <typename TriangleMesh, typename VPM, typename FIM, typename GT>
Input_report input_compute_report(const TriangleMesh& tm, const VPM& vpm, const FIM& fim, const GT& gt)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  typedef boost::graph_traits<TriangleMesh> Graph_traits;
  typedef typename Graph_traits::halfedge_descriptor halfedge_descriptor;
  typedef typename Graph_traits::edge_descriptor edge_descriptor;
  typedef typename Graph_traits::face_descriptor face_descriptor;

  Input_report r;
  r.number_of_vertices = input_count(vertices(tm));
  r.number_of_faces = input_count(faces(tm));
  r.number_of_edges = input_count(edges(tm));

  const auto cgal_np = CGAL::parameters::vertex_point_map(vpm).geom_traits(gt);

  typedef CGAL::dynamic_face_property_t<std::size_t> Face_cc_tag;
  auto fcc = get(Face_cc_tag(), tm);
  r.number_of_connected_components =
    std::size_t(PMP::connected_components(tm, fcc, CGAL::parameters::face_index_map(fim)));

  // one border cycle per unvisited border halfedge (PMP::extract_boundary_cycles()
  // takes a non-const mesh in CGAL 5.5)
  typedef CGAL::dynamic_halfedge_property_t<bool> Visited_tag;
  auto visited = get(Visited_tag(), tm);
  for(halfedge_descriptor h : halfedges(tm)) put(visited, h, false);
  for(halfedge_descriptor h : halfedges(tm)) {
    if(!is_border(h, tm)) continue;
    ++r.number_of_border_edges;
    if(get(visited, h)) continue;
    ++r.number_of_boundary_cycles;
    double cycle_length = 0;
    for(halfedge_descriptor b : halfedges_around_face(h, tm)) {
      put(visited, b, true);
      cycle_length += CGAL::to_double(PMP::edge_length(b, tm, cgal_np));
    }
    r.longest_boundary_cycle_length = (std::max)(r.longest_boundary_cycle_length, cycle_length);
  }

  const CGAL::Bbox_3 box = PMP::bbox(tm, cgal_np);
  const double dx = box.xmax() - box.xmin(), dy = box.ymax() - box.ymin(), dz = box.zmax() - box.zmin();
  r.bounding_box_diagonal = std::sqrt(dx * dx + dy * dy + dz * dz);

  double length = 0;
  for(edge_descriptor e : edges(tm))
    length += CGAL::to_double(PMP::edge_length(halfedge(e, tm), tm, cgal_np));
  r.mean_edge_length = r.number_of_edges > 0 ? length / double(r.number_of_edges) : 0.;

  double area = 0;
  for(face_descriptor f : faces(tm))
    area += CGAL::to_double(PMP::face_area(f, tm, cgal_np));
  r.area = area;
  return r;
}

} // namespace internal
/// \endcond

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// Checks that `tm` is a valid input of the package and returns figures about it.
///
/// Verifies, in this order, and throws `Input_error` for the first failing
/// class, with a message naming the problem, the first offending element
/// (smallest index in the vertex or face index map, which is the file order
/// for a mesh made by `read_mesh()`) and how many there are:
/// 1. `empty_mesh`: no vertex or no face
///    (then `invalid_parameter` if the vertex or face index map does not number the elements `0..n-1`,
///    as for a `CGAL::Surface_mesh` with removed elements: call `collect_garbage()`);
/// 2. `not_triangle_mesh`: a face that is not a triangle;
/// 3. `non_finite_coordinate`: a vertex with a NaN or infinite coordinate;
/// 4. `isolated_vertex`: a vertex with no incident face;
/// 5. `non_manifold_vertex`: a vertex shared by several fans of faces (`PMP::non_manifold_vertices()`);
///    (non-manifold edges cannot exist in a halfedge mesh: `read_mesh()` and
///    `check_polygon_soup()` report them on the soup);
/// 6. `degenerate_face`: a face with collinear vertices (`PMP::is_degenerate_triangle_face()`)
///    or an area at most `degenerate_face_relative_area` times the mean face area;
/// 7. `too_many_samples`: `number_of_samples` is given and exceeds the number of vertices.
///
/// Boundaries (holes) and several connected components are accepted.
///
/// \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `%Point_3` as value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_index_map}
///     \cgalParamDescription{a property map associating to each vertex of `tm` a unique index between `0` and `num_vertices(tm) - 1`; used in messages}
///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `std::size_t` as value type}
///     \cgalParamDefault{an automatically indexed internal map}
///   \cgalParamNEnd
///   \cgalParamNBegin{face_index_map}
///     \cgalParamDescription{a property map associating to each face of `tm` a unique index between `0` and `num_faces(tm) - 1`; used in messages}
///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and `std::size_t` as value type}
///     \cgalParamDefault{an automatically indexed internal map}
///   \cgalParamNEnd
///   \cgalParamNBegin{geom_traits}
///     \cgalParamDescription{an instance of a geometric traits class}
///     \cgalParamType{a model of `Kernel`}
///     \cgalParamDefault{a \cgal kernel deduced from the point type}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_samples}
///     \cgalParamDescription{the number of samples the caller will draw; checked against the number of vertices.
///       Either the package's or CGAL's `number_of_samples` is read.}
///     \cgalParamType{an integer type}
///     \cgalParamDefault{not checked}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns an `Input_report` of `tm`
/// \throws Input_error as listed above; `invalid_parameter` for a negative `number_of_samples`
template <typename TriangleMesh, typename CGAL_NP_TEMPLATE_PARAMETERS>
Input_report check_input(const TriangleMesh& tm, const CGAL_NP_CLASS& np = parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename GetVertexPointMap<TriangleMesh, CGAL_NP_CLASS>::const_type VPM;
  typedef typename GetGeomTraits<TriangleMesh, CGAL_NP_CLASS>::type GT;

  const VPM vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                   get_const_property_map(CGAL::vertex_point, tm));
  const GT gt = choose_parameter<GT>(get_parameter(np, CGAL::internal_np::geom_traits));
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  const auto fim = CGAL::get_initialized_face_index_map(tm, np);

  internal::input_check_mesh(tm, vpm, vim, fim, gt);

  long long samples = 0;
  if(internal::input_number_of_samples(np, samples)) {
    if(samples < 0) {
      std::ostringstream os;
      os << "number_of_samples is " << samples << ", it must be positive";
      throw Input_error(Input_problem::invalid_parameter, os.str());
    }
    const std::size_t nv = internal::input_count(vertices(tm));
    if(std::size_t(samples) > nv) {
      std::ostringstream os;
      os << samples << " samples requested, but the mesh has only " << nv << " vertices";
      throw Input_error(Input_problem::too_many_samples, os.str());
    }
  }
  return internal::input_compute_report(tm, vpm, fim, gt);
}

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// Mends the common defects of `tm` on a copy, with CGAL's own tools, and
/// says what was mended. `tm` is not modified; `out` is cleared and receives
/// the mended mesh. In this order:
/// 1. the copy (`CGAL::copy_face_graph()`) leaves out isolated vertices;
/// 2. `PMP::duplicate_non_manifold_vertices()`: each extra fan at a pinched vertex gets its own vertex;
/// 3. `PMP::triangulate_faces()`: non-triangle faces are split;
/// 4. `PMP::remove_degenerate_faces()`: faces with collinear vertices are removed
///    (by edge collapses and flips); where faces that `check_input()` calls
///    degenerate remain (collinear, or of near-zero area), then
///    `PMP::experimental::remove_almost_degenerate_faces()` flips or collapses the
///    caps (an angle above 170 degrees) and needles (longest edge over shortest above
///    20) of the mesh; then new pinched vertices, if any, are duplicated;
/// 5. `PMP::remove_isolated_vertices()`.
///
/// Not mended: non-finite coordinates (step 4 is then skipped), and the
/// degenerate faces that neither function of step 4 can remove (they still fail
/// `check_input()`).
///
/// The vertex order of `out` is not the order of `tm`:
/// `Input_repairs::output_to_input_vertex` maps each vertex of `out` (in
/// iteration order, which is the index order of a `CGAL::Surface_mesh`, whose
/// garbage is collected) to the index of the vertex of `tm` it comes from.
///
/// \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
/// \tparam OutputMesh a model of `MutableFaceGraph`, for example `TriangleMesh`
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `%Point_3` as value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_index_map}
///     \cgalParamDescription{the indices of the vertices of `tm` used in `output_to_input_vertex`}
///     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `std::size_t` as value type}
///     \cgalParamDefault{an automatically indexed internal map}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the counts of what was mended, and the vertex map
template <typename TriangleMesh, typename OutputMesh, typename CGAL_NP_TEMPLATE_PARAMETERS>
Input_repairs repair_input(const TriangleMesh& tm, OutputMesh& out,
                           const CGAL_NP_CLASS& np = parameters::default_values())
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename GetVertexPointMap<TriangleMesh, CGAL_NP_CLASS>::const_type VPM;
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  typedef typename boost::graph_traits<OutputMesh>::vertex_descriptor out_vertex;
  typedef typename boost::graph_traits<OutputMesh>::face_descriptor out_face;

  const VPM vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                   get_const_property_map(CGAL::vertex_point, tm));
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);

  Input_repairs r;
  for(vertex_descriptor v : vertices(tm)) {
    bool has_face = false;
    if(halfedge(v, tm) != boost::graph_traits<TriangleMesh>::null_halfedge())
      for(halfedge_descriptor h : halfedges_around_target(v, tm))
        if(!is_border(h, tm) || !is_border(opposite(h, tm), tm)) { has_face = true; break; }
    if(!has_face) ++r.removed_isolated_vertices;
  }

  CGAL::clear(out);
  // where each vertex of `out` comes from, carried through every step
  auto origin = get(CGAL::dynamic_vertex_property_t<std::size_t>(), out);
  std::vector<std::pair<vertex_descriptor, out_vertex> > copied;
  CGAL::copy_face_graph(tm, out, CGAL::parameters::vertex_point_map(vpm)
                                   .vertex_to_vertex_output_iterator(std::back_inserter(copied)));
  for(const auto& io : copied) put(origin, io.second, std::size_t(get(vim, io.first)));

  auto duplicate = [&]() {
    std::vector<std::vector<out_vertex> > groups; // (original, its copies...)
    const std::size_t n = PMP::duplicate_non_manifold_vertices(
      out, CGAL::parameters::output_iterator(std::back_inserter(groups)));
    for(const auto& g : groups)
      for(std::size_t k = 1; k < g.size(); ++k) put(origin, g[k], get(origin, g[0]));
    return n;
  };
  r.duplicated_non_manifold_vertices = duplicate();

  {
    std::size_t non_triangles = 0;
    for(out_face f : faces(out))
      if(!CGAL::is_triangle(halfedge(f, out), out)) ++non_triangles;
    if(non_triangles > 0 && PMP::triangulate_faces(out))
      r.triangulated_faces = non_triangles;
  }

  // the predicates of remove_degenerate_faces() need finite coordinates
  bool finite = true;
  for(out_vertex v : vertices(out))
    finite = finite && internal::input_is_finite(get(CGAL::vertex_point, out, v));
  if(finite && CGAL::is_triangle_mesh(out)) {
    // degenerate as check_input() says: collinear corners, or a near-zero area
    auto count_degenerate = [&out]() {
      return internal::Input_face_degeneracy(out, CGAL::parameters::default_values()).count();
    };
    const std::size_t degenerate = count_degenerate();
    if(degenerate > 0) {
      PMP::remove_degenerate_faces(out);
      // What remove_degenerate_faces() leaves (fans of collinear faces it cannot
      // resolve, faces of near-zero area that are not exactly collinear; PSB's
      // bearing_351: 5 and 13 of them) goes by the flips and collapses of CGAL's
      // remove_almost_degenerate_faces() on the caps (an angle above 170 degrees)
      // and needles (longest over shortest edge above 20) of the mesh: on
      // bearing_351 it removes 8 of 10,380 faces and leaves none degenerate.
      if(count_degenerate() > 0) {
        PMP::experimental::remove_almost_degenerate_faces(out, std::cos(170. / 180. * CGAL_PI), 20., 0.);
      }
      const std::size_t left = count_degenerate();
      r.removed_degenerate_faces = degenerate > left ? degenerate - left : 0;
      r.duplicated_non_manifold_vertices += duplicate();
    }
  }

  r.removed_isolated_vertices += PMP::remove_isolated_vertices(out);
  internal::input_collect_garbage(out);

  r.output_to_input_vertex.clear();
  for(out_vertex v : vertices(out)) r.output_to_input_vertex.push_back(get(origin, v));
  return r;
}

} // namespace Intrinsic_reflectional_symmetry_3
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_CHECK_INPUT_H
