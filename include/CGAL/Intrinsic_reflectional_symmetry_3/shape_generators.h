// Copyright (c) 2026 The Intrinsic_reflectional_symmetry_3 project.
// SPDX-License-Identifier: LGPL-3.0-or-later
// Author(s)     : The Intrinsic_reflectional_symmetry_3 developers

#ifndef CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_SHAPE_GENERATORS_H
#define CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_SHAPE_GENERATORS_H

#include <CGAL/disable_warnings.h>

/// \file shape_generators.h
/// Procedural closed triangle meshes with known reflectional symmetries:
/// test shapes for the package, the demo and users.
///
/// Every generator returns a closed, connected 2-manifold made of
/// near-regular triangles (angles roughly within [30, 100] degrees), and, for
/// each known symmetry, the vertex-to-vertex mirror map. The vertex count is
/// about the target (within about -10 % / +30 %; more for tiny targets, as
/// thin parts always get at least 8 edges around). Every generator is
/// deterministic, and throws `Input_error` (`invalid_parameter`) for a target
/// below 100 vertices or a non-positive size. Vertex indices are
/// those of `CGAL::get_initialized_vertex_index_map()`, which for a freshly
/// built `Surface_mesh` or `Polyhedron_3` is the insertion order: the meshes
/// are built with `CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh()`
/// from one polygon soup, so indices agree for every mesh type.
///
/// How exact the mirror maps are:
/// - sphere, ellipsoid, capsule, torus, snowman, and the bent capsule's two
///   symmetries: exact by construction. A fundamental domain of the symmetry
///   group (e.g. the octant x, y, z >= 0) is remeshed with
///   `CGAL::Polygon_mesh_processing::isotropic_remeshing()` (vertices
///   projected onto the analytic surface), reflected across the planes, and
///   its seams are improved symmetrically (flips per orbit, relaxation then
///   re-symmetrisation), so mirror vertices have mirrored neighbourhoods,
///   mirror coordinates are exact, and vertices on a mirror plane are fixed
///   points of its map (`mirror[v] == v`). The sphere is a geodesic
///   icosphere (frequency-n subdivision of an icosahedron whose coordinate
///   planes are mirror planes), its positions made exactly symmetric.
///   Measured triangle angles: within [28, 102] degrees for 600 to 4K
///   vertices, at least 99.7 % of them within [30, 100].
/// - stick figure: its left-right (x = 0) map is exact by construction (the
///   right half, body and limbs joined by corefinement, is reflected); its
///   front-back map is by nearest vertex, as for the two snowmen below.
/// - two snowmen: the tube is joined by corefinement and the junction is
///   remeshed, so the mirror maps are computed as "nearest vertex to the
///   reflected point" (CGAL's `Orthogonal_k_neighbor_search`), kept only when
///   the relation is mutual (so the map stays an involution) and closer than
///   a tolerance: 1e-6 mean edge length for the partial snowman symmetries
///   (only vertices whose exact mirror vertex survived the junction: that is
///   what "defined away from the junction" means), half a mean edge length
///   for the global front-back plane (defined almost everywhere). Angles
///   within about [25, 120] degrees near the remeshed junctions.

#include <CGAL/Intrinsic_reflectional_symmetry_3/errors.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/shape_construction.h>

#include <CGAL/boost/graph/properties.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/boost/graph/selection.h>

#include <boost/property_map/property_map.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Intrinsic_reflectional_symmetry_3 {

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// One reflectional symmetry of a generated shape.
struct Known_symmetry
{
  /// e.g. "x=0 plane", "left snowman", "end-to-end (intrinsic)"
  std::string name;
  /// `true` if the map is the Euclidean reflection across `plane`
  /// (possibly only on a part of the shape: see `mirror`)
  bool extrinsic = false;
  /// the mirror plane `a x + b y + c z + d = 0` with a unit normal, if `extrinsic`; zeros otherwise
  std::array<double, 4> plane = {{0., 0., 0., 0.}};
  /// vertex index -> index of its mirror vertex; -1 where the symmetry is not
  /// defined (partial symmetries). An involution where defined.
  std::vector<std::ptrdiff_t> mirror;
  /// indices of the vertices within half a mean edge length of the symmetry
  /// axis curve (the curve the reflection fixes), in increasing order
  std::vector<std::size_t> axis;
};

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// A generated mesh with its known symmetries.
template <typename TriangleMesh>
struct Generated_shape
{
  TriangleMesh mesh;
  std::vector<Known_symmetry> symmetries;
  /// mean length of the mesh edges, the natural unit for tolerances
  double mean_edge_length = 0.;
};

namespace internal {
namespace shapes {

inline void check_argument(bool ok, const std::string& what)
{
  if(!ok) throw Input_error(Input_problem::invalid_parameter, what);
}

inline void check_target(std::size_t n)
{
  check_argument(n >= 100, "target_number_of_vertices must be at least 100, got " + std::to_string(n));
}

inline void check_length(double x, const std::string& name)
{
  check_argument(x > 0. && std::isfinite(x), name + " must be positive and finite, got " + std::to_string(x));
}

template <typename TriangleMesh>
void soup_to_mesh(const Soup& s, TriangleMesh& tm)
{
  typedef typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::type VPM;
  typedef typename boost::property_traits<VPM>::value_type Mesh_point;
  std::vector<Mesh_point> points;
  points.reserve(s.points.size());
  for(const Point& p : s.points)
    points.push_back(Mesh_point(p.x(), p.y(), p.z()));
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, s.triangles, tm);
}

/// vertices within `half_width` of the plane (and where the map is defined)
inline std::vector<std::size_t> plane_axis(const std::vector<Point>& points, const std::array<double, 4>& pl,
                                           const std::vector<std::ptrdiff_t>& mirror, double half_width)
{
  std::vector<std::size_t> axis;
  for(std::size_t v = 0; v < points.size(); ++v)
    if(mirror[v] >= 0 &&
       std::abs(pl[0] * points[v].x() + pl[1] * points[v].y() + pl[2] * points[v].z() + pl[3]) <= half_width)
      axis.push_back(v);
  return axis;
}

inline Known_symmetry plane_symmetry(const std::string& name, const std::array<double, 4>& pl,
                                     std::vector<std::ptrdiff_t> mirror, const std::vector<Point>& points,
                                     double mean_edge)
{
  Known_symmetry s;
  s.name = name;
  s.extrinsic = true;
  s.plane = pl;
  s.mirror = std::move(mirror);
  s.axis = plane_axis(points, pl, s.mirror, 0.5 * mean_edge);
  return s;
}

inline std::array<double, 4> coordinate_plane(int axis, double offset = 0.)
{
  std::array<double, 4> pl = {{0., 0., 0., -offset}};
  pl[axis] = 1.;
  return pl;
}

/// the symmetries of an exactly symmetric soup, one per coordinate plane of `mask`
inline std::vector<Known_symmetry> coordinate_symmetries(const Symmetric_soup& s, unsigned mask, double mean_edge)
{
  static const char* names[3] = {"x=0 plane", "y=0 plane", "z=0 plane"};
  std::vector<Known_symmetry> out;
  for(int a = 0; a < 3; ++a)
    if(mask & (1u << a))
      out.push_back(plane_symmetry(names[a], coordinate_plane(a), s.mirror[a], s.soup.points, mean_edge));
  return out;
}

template <typename TriangleMesh>
Generated_shape<TriangleMesh> make_shape(const Soup& soup, std::vector<Known_symmetry> symmetries, double mean_edge)
{
  Generated_shape<TriangleMesh> g;
  soup_to_mesh(soup, g.mesh);
  g.symmetries = std::move(symmetries);
  g.mean_edge_length = mean_edge;
  return g;
}

/// geodesic icosphere, frequency n (10 n^2 + 2 vertices), made exactly
/// symmetric for the three coordinate planes
inline Symmetric_soup icosphere(int n, double radius)
{
  const double t = (1. + std::sqrt(5.)) / 2.;
  const Point c[12] = {Point(-1, t, 0), Point(1, t, 0), Point(-1, -t, 0), Point(1, -t, 0),
                       Point(0, -1, t), Point(0, 1, t), Point(0, -1, -t), Point(0, 1, -t),
                       Point(t, 0, -1), Point(t, 0, 1), Point(-t, 0, -1), Point(-t, 0, 1)};
  const int f[20][3] = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11},
                        {1, 5, 9}, {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                        {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8}, {3, 8, 9},
                        {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
  Symmetric_soup out;
  Soup& s = out.soup;
  std::map<std::array<int, 4>, std::size_t> key_to_id; // shared corners and edge points
  auto vertex = [&](int fi, int i, int j) -> std::size_t {
    const int A = f[fi][0], B = f[fi][1], C = f[fi][2];
    std::array<int, 4> key;
    if(i == 0 && j == 0)  key = {{0, A, 0, 0}};
    else if(i == n)       key = {{0, B, 0, 0}};
    else if(j == n)       key = {{0, C, 0, 0}};
    else if(j == 0)       key = {{1, (std::min)(A, B), (std::max)(A, B), A < B ? i : n - i}};
    else if(i == 0)       key = {{1, (std::min)(A, C), (std::max)(A, C), A < C ? j : n - j}};
    else if(i + j == n)   key = {{1, (std::min)(B, C), (std::max)(B, C), B < C ? j : n - j}};
    else                  key = {{2, fi, i, j}};
    auto it = key_to_id.find(key);
    if(it != key_to_id.end()) return it->second;
    const Vector p = (c[A] - CGAL::ORIGIN) + (c[B] - c[A]) * (double(i) / n) + (c[C] - c[A]) * (double(j) / n);
    s.points.push_back(CGAL::ORIGIN + p * (radius / std::sqrt(p.squared_length())));
    key_to_id.emplace(key, s.points.size() - 1);
    return s.points.size() - 1;
  };
  for(int fi = 0; fi < 20; ++fi)
    for(int i = 0; i < n; ++i)
      for(int j = 0; i + j < n; ++j) {
        s.triangles.push_back(Triangle{{vertex(fi, i, j), vertex(fi, i + 1, j), vertex(fi, i, j + 1)}});
        if(i + j + 1 < n)
          s.triangles.push_back(Triangle{{vertex(fi, i + 1, j), vertex(fi, i + 1, j + 1), vertex(fi, i, j + 1)}});
      }

  // Mirror maps by matching reflected positions (they agree up to rounding),
  // then positions rebuilt from one representative per orbit so that the
  // reflections are exact.
  const double tol = 1e-6 * radius / double(n);
  for(int a = 0; a < 3; ++a) {
    const unsigned bit = 1u << a;
    out.mirror[a] = mirror_by_nearest_vertex(s.points, [bit](const Point& p) { return flip(p, bit); }, tol);
    for(std::ptrdiff_t m : out.mirror[a])
      if(m < 0) throw std::logic_error("shape generator: icosphere is not symmetric");
  }
  symmetrize_positions(s.points, out.mirror, 7u, [radius](const Point& p) {
    return CGAL::ORIGIN + (p - CGAL::ORIGIN) * (radius / std::sqrt((p - CGAL::ORIGIN).squared_length()));
  });
  return out;
}

inline Symmetric_soup snowman_soup(double scale, double h)
{
  Snowman_profile p;
  p.scale = scale;
  const std::vector<std::array<double, 2> > dense =
    trace_profile(p, p.bottom() - 0.1 * scale, p.top() + 0.1 * scale, 0.05 * h);
  Revolution_projector<Snowman_profile> proj{p};
  return symmetric_shape(revolution_patch(resample_profile(dense, 0.5 * std::sqrt(3.) * h), h), 3u, h, proj);
}

inline double snowman_area(double scale)
{
  Snowman_profile p;
  p.scale = scale;
  return revolution_area(trace_profile(p, p.bottom() - 0.1 * scale, p.top() + 0.1 * scale, 0.002 * scale));
}

/// capsule with axis z, radius r, cylinder |z| <= hl, symmetric for x=0, y=0, z=0
inline Symmetric_soup capsule_soup(double r, double hl, double h)
{
  Revolution_projector<Capsule_profile> proj{Capsule_profile{r, hl}};
  return symmetric_shape(revolution_patch(capsule_half_rows(r, hl, 0.5 * std::sqrt(3.) * h), h), 7u, h, proj);
}

inline double capsule_area(double r, double hl) { return 2 * pi * r * 2 * hl + 4 * pi * r * r; }

} // namespace shapes
} // namespace internal

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// A sphere of radius `radius` centred at the origin: a geodesic icosphere
/// with `10 n^2 + 2` vertices, `n` chosen to come closest to
/// `target_number_of_vertices`. Known symmetries: the planes x=0, y=0 and z=0
/// (exact; the sphere has infinitely many others).
template <typename TriangleMesh>
Generated_shape<TriangleMesh> generate_sphere(std::size_t target_number_of_vertices = 2500, double radius = 1.)
{
  using namespace internal::shapes;
  check_target(target_number_of_vertices);
  check_length(radius, "radius");
  const int n = (std::max)(1, int(std::lround(std::sqrt(double(target_number_of_vertices) / 10.))));
  Symmetric_soup s = icosphere(n, radius);
  const double e = mean_edge_length(s.soup);
  return make_shape<TriangleMesh>(s.soup, coordinate_symmetries(s, 7u, e), e);
}

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// The ellipsoid x^2/a^2 + y^2/b^2 + z^2/c^2 = 1 with about
/// `target_number_of_vertices` vertices. With three distinct radii its
/// known symmetries are exactly the planes x=0, y=0 and z=0 (exact maps).
/// Built from the octant x, y, z >= 0, isotropically remeshed on the exact
/// ellipsoid and reflected (a stretched icosphere would have stretched triangles).
template <typename TriangleMesh>
Generated_shape<TriangleMesh> generate_ellipsoid(std::size_t target_number_of_vertices = 2500,
                                                 double a = 1.5, double b = 1.0, double c = 0.7)
{
  using namespace internal::shapes;
  check_target(target_number_of_vertices);
  check_length(a, "a");
  check_length(b, "b");
  check_length(c, "c");
  const double p = 1.6075; // Knud Thomsen's approximation of the area, within about 1 %
  const double area = 4 * pi * std::pow((std::pow(a * b, p) + std::pow(a * c, p) + std::pow(b * c, p)) / 3., 1. / p);
  const double h = edge_length_for(area, target_number_of_vertices);
  const int n = (std::max)(2, int(std::lround(std::sqrt(area / 8. / (std::sqrt(3.) / 4. * h * h)))));
  Symmetric_soup s = symmetric_shape(ellipsoid_octant_patch(a, b, c, n), 7u, h, Ellipsoid_projector{a, b, c});
  const double e = mean_edge_length(s.soup);
  return make_shape<TriangleMesh>(s.soup, coordinate_symmetries(s, 7u, e), e);
}

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// A capsule (cylinder with hemispherical caps) of axis z, radius `radius`,
/// cylinder length `cylinder_length`, centred at the origin, with about
/// `target_number_of_vertices` vertices. Known symmetries: the planes x=0,
/// y=0 and z=0 (exact maps; z=0 swaps the two ends).
template <typename TriangleMesh>
Generated_shape<TriangleMesh> generate_capsule(std::size_t target_number_of_vertices = 2500,
                                               double radius = 0.5, double cylinder_length = 2.)
{
  using namespace internal::shapes;
  check_target(target_number_of_vertices);
  check_length(radius, "radius");
  check_length(cylinder_length, "cylinder_length");
  const double hl = 0.5 * cylinder_length;
  const double h = (std::min)(edge_length_for(capsule_area(radius, hl), target_number_of_vertices),
                              pi * radius / 4.); // at least 8 edges around
  Symmetric_soup s = capsule_soup(radius, hl, h);
  const double e = mean_edge_length(s.soup);
  return make_shape<TriangleMesh>(s.soup, coordinate_symmetries(s, 7u, e), e);
}

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// A torus of axis z, major radius `major_radius`, minor radius
/// `minor_radius`, with about `target_number_of_vertices` vertices. Known
/// symmetries: the planes x=0, y=0 and z=0 (exact maps).
template <typename TriangleMesh>
Generated_shape<TriangleMesh> generate_torus(std::size_t target_number_of_vertices = 2500,
                                             double major_radius = 1., double minor_radius = 0.4)
{
  using namespace internal::shapes;
  const double R = major_radius, r = minor_radius;
  check_target(target_number_of_vertices);
  check_length(r, "minor_radius");
  check_argument(R > r && std::isfinite(R), "major_radius must be finite and larger than minor_radius");
  const double h = (std::min)(edge_length_for(4 * pi * pi * R * r, target_number_of_vertices),
                              pi * r / 4.); // at least 8 edges around the tube
  Symmetric_soup s = symmetric_shape(revolution_patch(torus_half_rows(R, r, 0.5 * std::sqrt(3.) * h), h),
                                     7u, h, Torus_projector{R, r});
  const double e = mean_edge_length(s.soup);
  return make_shape<TriangleMesh>(s.soup, coordinate_symmetries(s, 7u, e), e);
}

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// A snowman: three stacked spheres of radii 1, 0.68 and 0.45 (times
/// `scale`) blended into one smooth surface of revolution about the z axis,
/// standing on z = 0 (height 3.7 `scale`), with about
/// `target_number_of_vertices` vertices. Known symmetries: the planes x=0
/// and y=0 (exact maps; every plane through the axis is a symmetry).
template <typename TriangleMesh>
Generated_shape<TriangleMesh> generate_snowman(std::size_t target_number_of_vertices = 2500, double scale = 1.)
{
  using namespace internal::shapes;
  check_target(target_number_of_vertices);
  check_length(scale, "scale");
  const double h = (std::min)(edge_length_for(snowman_area(scale), target_number_of_vertices),
                              0.35 * scale); // at least 8 edges around the head
  Symmetric_soup s = snowman_soup(scale, h);
  const double e = mean_edge_length(s.soup);
  return make_shape<TriangleMesh>(s.soup, coordinate_symmetries(s, 3u, e), e);
}

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// Two snowmen of different sizes standing on z = 0 side by side along the
/// x axis, joined by a horizontal tube along x (radius 0.25) at height 0.7:
/// the left one (`generate_snowman()` with scale 1, axis x = -1.6) and the
/// right one (scale 0.7, axis x = 1.3). About `target_number_of_vertices`
/// vertices in all. The tube is joined by corefinement
/// (`corefine_and_compute_union()`) and the junction is remeshed.
///
/// Known symmetries, in this order:
/// - "left snowman", "right snowman": each snowman's left-right mirror (the
///   plane through its axis, perpendicular to the tube). PARTIAL: defined on
///   the vertices of that snowman whose mirror vertex is exact, i.e. away
///   from the tube junction; -1 elsewhere.
/// - "y=0 plane (front-back)": the global mirror of the whole shape
///   (defined wherever a mutual nearest vertex lies within half a mean edge
///   length; near the remeshed junctions it may be -1).
/// There is no global left-right symmetry: the snowmen differ in size.
template <typename TriangleMesh>
Generated_shape<TriangleMesh> generate_two_snowmen(std::size_t target_number_of_vertices = 3000)
{
  using namespace internal::shapes;
  namespace PMP = CGAL::Polygon_mesh_processing;
  const double s_right = 0.7, x_left = -1.6, x_right = 1.3, z_tube = 0.7, r_tube = 0.25;
  check_target(target_number_of_vertices);
  const double area = snowman_area(1.) + snowman_area(s_right) + 2 * pi * r_tube * (x_right - x_left - 1.7);
  const double h = (std::min)(edge_length_for(area, target_number_of_vertices),
                              0.35 * s_right); // at least 8 edges around the small head

  // both snowmen in one (disconnected) soup, then the tube
  Soup both = snowman_soup(1., h).soup;
  for(Point& p : both.points) p = Point(p.x() + x_left, p.y(), p.z());
  {
    const Soup right = snowman_soup(s_right, h).soup;
    const std::size_t off = both.points.size();
    for(const Point& p : right.points) both.points.push_back(Point(p.x() + x_right, p.y(), p.z()));
    for(const Triangle& t : right.triangles) both.triangles.push_back(Triangle{{t[0] + off, t[1] + off, t[2] + off}});
  }
  // at least 8 edges around the tube, whatever the resolution
  const double h_tube = (std::min)(h, 2 * pi * r_tube / 8.);
  Soup tube = capsule_soup(r_tube, 0.5 * (x_right - x_left), h_tube).soup;
  const double x_mid = 0.5 * (x_left + x_right);
  for(Point& p : tube.points) p = Point(p.z() + x_mid, p.y(), -p.x() + z_tube); // a rotation: axis z -> x

  Mesh m1 = soup_to_surface_mesh(both), m2 = soup_to_surface_mesh(tube), m;
  auto crease = m.add_property_map<Mesh::Edge_index, bool>("e:irs_crease", false).first;
  if(!PMP::corefine_and_compute_union(m1, m2, m, PMP::parameters::default_values(),
                                      PMP::parameters::default_values(),
                                      PMP::parameters::edge_is_constrained_map(crease)))
    throw std::logic_error("shape generator: union of snowmen and tube failed");

  // remesh a few rings of faces around the intersection curves (the crease is kept)
  std::vector<Mesh::Face_index> junction;
  auto selected = m.add_property_map<Mesh::Face_index, bool>("f:irs_selected", false).first;
  for(Mesh::Edge_index e : edges(m))
    if(get(crease, e))
      for(Mesh::Halfedge_index hh : {halfedge(e, m), opposite(halfedge(e, m), m)})
        if(!get(selected, face(hh, m))) { put(selected, face(hh, m), true); junction.push_back(face(hh, m)); }
  CGAL::expand_face_selection(std::vector<Mesh::Face_index>(junction), m, 3, selected, std::back_inserter(junction));
  PMP::isotropic_remeshing(junction, h_tube, m,
                           PMP::parameters::number_of_iterations(10)
                             .number_of_relaxation_steps(3));
  m.collect_garbage();
  const Soup soup = surface_mesh_to_soup(m);
  const double e = mean_edge_length(soup);

  std::vector<Known_symmetry> syms;
  const double xs[2] = {x_left, x_right};
  const char* names[2] = {"left snowman", "right snowman"};
  for(int k = 0; k < 2; ++k) {
    const double x0 = xs[k];
    std::vector<std::ptrdiff_t> mirror = mirror_by_nearest_vertex(
      soup.points, [x0](const Point& p) { return Point(2 * x0 - p.x(), p.y(), p.z()); }, 1e-6 * e);
    syms.push_back(plane_symmetry(names[k], coordinate_plane(0, x0), std::move(mirror), soup.points, e));
  }
  syms.push_back(plane_symmetry("y=0 plane (front-back)", coordinate_plane(1),
                                mirror_by_nearest_vertex(soup.points, [](const Point& p) { return flip(p, 2u); }, 0.5 * e),
                                soup.points, e));
  return make_shape<TriangleMesh>(soup, std::move(syms), e);
}

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// A capsule of radius `radius` and cylinder length `cylinder_length` whose
/// axis runs along x, bent non-uniformly: the half x <= 0 stays straight, the
/// other half of the cylinder is bent along a circular arc turning by
/// `bend_angle` (radians) towards +y, in the plane z = 0, and its cap follows
/// rigidly. About `target_number_of_vertices` vertices.
///
/// Known symmetries:
/// - "end-to-end (intrinsic)": the map swapping the two ends, taken from the
///   construction (the straight capsule's x -> -x, before bending). Not a
///   Euclidean reflection (`extrinsic == false`); bending a tube is not an
///   exact isometry (lengths along the cylinder change by a factor
///   1 -+ radius * curvature on the inner and outer sides: 1 -+ 0.084 with
///   the defaults), so it is an approximately isometric intrinsic symmetry:
///   edge-graph geodesic distances between mirror pairs differ by about 2.6 %
///   on average, at most about 8 % (measured, default shape, 1500 vertices).
///   Its axis is the straight capsule's middle circle.
/// - "z=0 plane (bending plane)": an exact extrinsic mirror that maps each end to itself.
template <typename TriangleMesh>
Generated_shape<TriangleMesh> generate_bent_capsule(std::size_t target_number_of_vertices = 2500,
                                                    double radius = 0.2, double cylinder_length = 5.,
                                                    double bend_angle = CGAL_PI / 3)
{
  using namespace internal::shapes;
  check_target(target_number_of_vertices);
  check_length(radius, "radius");
  check_length(cylinder_length, "cylinder_length");
  const double hl = 0.5 * cylinder_length;
  check_argument(bend_angle >= 0. && bend_angle <= pi && radius * bend_angle / hl < 0.5,
                 "bend_angle must be in [0, pi] with radius * bend_angle / (cylinder_length / 2) < 0.5");
  const double h = (std::min)(edge_length_for(capsule_area(radius, hl), target_number_of_vertices),
                              pi * radius / 4.); // at least 8 edges around
  Symmetric_soup s = capsule_soup(radius, hl, h);
  // axis z -> x by the rotation (x, y, z) -> (z, x, y); the straight capsule's
  // end-to-end mirror is then x -> -x and its z=0 plane comes from the old y=0
  std::vector<Point> straight;
  for(const Point& p : s.soup.points) straight.push_back(Point(p.z(), p.x(), p.y()));
  const double kappa = bend_angle / hl;
  for(std::size_t v = 0; v < straight.size(); ++v) {
    const Point& p = straight[v];
    if(p.x() <= 0. || kappa == 0.) { s.soup.points[v] = p; continue; }
    const double t = (std::min)(p.x(), hl), a = kappa * t;
    const double cx = std::sin(a) / kappa, cy = (1. - std::cos(a)) / kappa; // centre line
    const double tx = std::cos(a), ty = std::sin(a);                        // its tangent
    const double nx = -std::sin(a), ny = std::cos(a);                       // normal, towards +y
    const double beyond = p.x() - t;                                        // along the rigid cap
    s.soup.points[v] = Point(cx + beyond * tx + p.y() * nx, cy + beyond * ty + p.y() * ny, p.z());
  }
  const double e = mean_edge_length(s.soup);

  std::vector<Known_symmetry> syms;
  Known_symmetry ends;
  ends.name = "end-to-end (intrinsic)";
  ends.extrinsic = false;
  ends.mirror = s.mirror[2];
  for(std::size_t v = 0; v < straight.size(); ++v)
    if(std::abs(straight[v].x()) <= 0.5 * e) ends.axis.push_back(v);
  syms.push_back(ends);
  syms.push_back(plane_symmetry("z=0 plane (bending plane)", coordinate_plane(2), s.mirror[1], s.soup.points, e));
  return make_shape<TriangleMesh>(s.soup, std::move(syms), e);
}

/// \ingroup PkgIntrinsicReflectionalSymmetry3Ref
/// A stick figure with limbs, the test shape of part repair: a body (capsule
/// of axis z, radius 0.5, cylinder |z| <= 0.9), two arms (capsules of axis x,
/// radius 0.16, cap centres at |x| = 0.3 and 1.9, height z = 0.6) and two
/// legs (capsules of axis z, radius 0.18, at x = +-0.27, cap centres at
/// z = -1.0 and -2.8), about `target_number_of_vertices` vertices. The arm
/// tips are the vertices of extreme x, the feet those of lowest z.
///
/// Known symmetries, in this order:
/// - "x=0 plane (left-right)": exact. The right half (body half, right arm
///   and right leg joined by corefinement, junctions remeshed away from the
///   plane) is reflected across x = 0, so mirror coordinates are exact and
///   the map is known combinatorially; vertices on the plane are fixed.
/// - "y=0 plane (front-back)": by mutual nearest vertex within half a mean
///   edge length (the remeshed junctions are not exactly symmetric in y).
template <typename TriangleMesh>
Generated_shape<TriangleMesh> generate_stick_figure(std::size_t target_number_of_vertices = 3000)
{
  using namespace internal::shapes;
  namespace PMP = CGAL::Polygon_mesh_processing;
  check_target(target_number_of_vertices);
  const double r_body = 0.5, hl_body = 0.9, r_arm = 0.16, r_leg = 0.18;
  const double x_arm0 = 0.3, x_arm1 = 1.9, z_arm = 0.6, x_leg = 0.27, z_leg0 = -2.8, z_leg1 = -1.0;
  const double hl_arm = 0.5 * (x_arm1 - x_arm0), hl_leg = 0.5 * (z_leg1 - z_leg0);
  const double area = capsule_area(r_body, hl_body) + 2 * capsule_area(r_arm, hl_arm) + 2 * capsule_area(r_leg, hl_leg);
  const double h = (std::min)(edge_length_for(area, target_number_of_vertices),
                              pi * r_arm / 4.); // at least 8 edges around a limb

  const Soup body = capsule_soup(r_body, hl_body, h).soup;
  Soup limbs = capsule_soup(r_arm, hl_arm, h).soup; // right arm: axis z -> x by a rotation
  for(Point& p : limbs.points) p = Point(p.z() + 0.5 * (x_arm0 + x_arm1), p.y(), -p.x() + z_arm);
  {
    const Soup leg = capsule_soup(r_leg, hl_leg, h).soup;
    const std::size_t off = limbs.points.size();
    for(const Point& p : leg.points) limbs.points.push_back(Point(p.x() + x_leg, p.y(), p.z() + 0.5 * (z_leg0 + z_leg1)));
    for(const Triangle& t : leg.triangles) limbs.triangles.push_back(Triangle{{t[0] + off, t[1] + off, t[2] + off}});
  }
  Mesh m1 = soup_to_surface_mesh(body), m2 = soup_to_surface_mesh(limbs), m;
  auto crease = m.add_property_map<Mesh::Edge_index, bool>("e:irs_crease", false).first;
  if(!PMP::corefine_and_compute_union(m1, m2, m, PMP::parameters::default_values(),
                                      PMP::parameters::default_values(),
                                      PMP::parameters::edge_is_constrained_map(crease)))
    throw std::logic_error("shape generator: union of body and limbs failed");

  // remesh a few rings around the junctions, never touching the plane x = 0
  // (its vertices must keep their exact zero coordinate)
  auto selected = m.add_property_map<Mesh::Face_index, bool>("f:irs_selected", false).first;
  std::vector<Mesh::Face_index> junction;
  for(Mesh::Edge_index e : edges(m))
    if(get(crease, e))
      for(Mesh::Halfedge_index hh : {halfedge(e, m), opposite(halfedge(e, m), m)})
        if(!get(selected, face(hh, m))) { put(selected, face(hh, m), true); junction.push_back(face(hh, m)); }
  CGAL::expand_face_selection(std::vector<Mesh::Face_index>(junction), m, 2, selected, std::back_inserter(junction));
  std::vector<Mesh::Face_index> away;
  for(Mesh::Face_index f : junction) {
    bool far = true;
    for(Mesh::Vertex_index v : vertices_around_face(halfedge(f, m), m)) far = far && m.point(v).x() > 0.5 * h;
    if(far) away.push_back(f);
  }
  PMP::isotropic_remeshing(away, h, m, PMP::parameters::number_of_iterations(10).number_of_relaxation_steps(3));
  m.collect_garbage();

  // the right half (x >= 0), its border exactly on the plane, reflected
  const Soup whole = surface_mesh_to_soup(m);
  Soup half;
  std::vector<std::size_t> id(whole.points.size(), std::size_t(-1));
  std::vector<unsigned> on_planes;
  for(const Triangle& t : whole.triangles) {
    if(whole.points[t[0]].x() < 0. || whole.points[t[1]].x() < 0. || whole.points[t[2]].x() < 0.) continue;
    Triangle u;
    for(int i = 0; i < 3; ++i) {
      if(id[t[i]] == std::size_t(-1)) {
        id[t[i]] = half.points.size();
        half.points.push_back(whole.points[t[i]]);
        on_planes.push_back(whole.points[t[i]].x() == 0. ? 1u : 0u);
      }
      u[i] = id[t[i]];
    }
    if(on_planes[u[0]] && on_planes[u[1]] && on_planes[u[2]])
      throw std::logic_error("shape generator: a triangle lies in the mirror plane");
    half.triangles.push_back(u);
  }
  Symmetric_soup s = reflect_patch(half, on_planes, 1u);
  if(!PMP::is_polygon_soup_a_polygon_mesh(s.soup.triangles))
    throw std::logic_error("shape generator: the reflected half is not a 2-manifold");
  {
    Mesh check = soup_to_surface_mesh(s.soup);
    if(!CGAL::is_closed(check) || num_vertices(check) != s.soup.points.size())
      throw std::logic_error("shape generator: the stick figure is not closed");
  }
  const double e = mean_edge_length(s.soup);
  std::vector<Known_symmetry> syms;
  syms.push_back(plane_symmetry("x=0 plane (left-right)", coordinate_plane(0), s.mirror[0], s.soup.points, e));
  syms.push_back(plane_symmetry("y=0 plane (front-back)", coordinate_plane(1),
                                mirror_by_nearest_vertex(s.soup.points, [](const Point& p) { return flip(p, 2u); }, 0.5 * e),
                                s.soup.points, e));
  return make_shape<TriangleMesh>(s.soup, std::move(syms), e);
}

} // namespace Intrinsic_reflectional_symmetry_3
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_SHAPE_GENERATORS_H
