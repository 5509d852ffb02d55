// Copyright (c) 2026 The Intrinsic_reflectional_symmetry_3 project.
// SPDX-License-Identifier: LGPL-3.0-or-later
// Author(s)     : The Intrinsic_reflectional_symmetry_3 developers

#ifndef CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_SHAPE_CONSTRUCTION_H
#define CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_SHAPE_CONSTRUCTION_H

#include <CGAL/disable_warnings.h>

// Building blocks of shape_generators.h. No API promise.
//
// The main trick: a shape whose mirror planes are coordinate planes is built
// from its fundamental domain (the part with x >= 0, y >= 0, ... for the
// planes in `mask`). That patch is remeshed with CGAL's isotropic remeshing
// (vertices projected onto the exact analytic surface) and then reflected
// across the planes; the copies share the patch border vertices, which lie
// exactly on the planes. The seams are then improved without breaking the
// symmetry (edge flips decided and applied per orbit of the reflection
// group, tangential relaxation followed by re-symmetrisation). The result is
// exactly mirror-symmetric: mirror vertices have exactly reflected
// coordinates and mirrored neighbourhoods, and the mirror maps are known
// combinatorially.

// Boost's disjoint_sets.hpp calls get(T*, i) unqualified: it must be parsed
// before boost/graph/detail/adjacency_list.hpp (pulled in by CGAL headers
// below) declares boost::detail::get, which would hide boost::get from it.
#include <boost/property_map/property_map.hpp>
#include <boost/pending/disjoint_sets.hpp>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Polygon_mesh_processing/tangential_relaxation.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/boost/graph/selection.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/property_map.h>

#include <boost/math/constants/constants.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Intrinsic_reflectional_symmetry_3 {
namespace internal {
namespace shapes {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3                                          Point;
typedef K::Vector_3                                         Vector;
typedef CGAL::Surface_mesh<Point>                           Mesh;
typedef std::array<std::size_t, 3>                          Triangle;

const double pi = boost::math::constants::pi<double>();

/// a triangle soup: what polygon_soup_to_polygon_mesh() takes
struct Soup
{
  std::vector<Point> points;
  std::vector<Triangle> triangles;
};

/// a soup with the mirror maps of the coordinate planes it is symmetric for
struct Symmetric_soup
{
  Soup soup;
  /// mirror[a] for axis a (0 = x, 1 = y, 2 = z): vertex -> mirror vertex; empty if the plane is not a symmetry
  std::array<std::vector<std::ptrdiff_t>, 3> mirror;
};

inline unsigned popcount3(unsigned g) { return (g & 1u) + ((g >> 1) & 1u) + ((g >> 2) & 1u); }

/// reflects `p` across the coordinate planes whose bits are set in `g`
inline Point flip(const Point& p, unsigned g)
{
  return Point((g & 1u) ? -p.x() : p.x(), (g & 2u) ? -p.y() : p.y(), (g & 4u) ? -p.z() : p.z());
}

inline double coordinate(const Point& p, int axis) { return axis == 0 ? p.x() : (axis == 1 ? p.y() : p.z()); }

inline Mesh soup_to_surface_mesh(const Soup& s)
{
  Mesh m;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(s.points, s.triangles, m);
  return m;
}

/// vertices in index order, faces in index order; `m` must be garbage-free
inline Soup surface_mesh_to_soup(const Mesh& m)
{
  Soup s;
  s.points.reserve(num_vertices(m));
  for(Mesh::Vertex_index v : vertices(m))
    s.points.push_back(m.point(v));
  for(Mesh::Face_index f : faces(m)) {
    Triangle t;
    int i = 0;
    for(Mesh::Vertex_index v : vertices_around_face(halfedge(f, m), m))
      t[i++] = std::size_t(v);
    s.triangles.push_back(t);
  }
  return s;
}

inline double soup_area(const Soup& s)
{
  double a = 0.;
  for(const Triangle& t : s.triangles)
    a += std::sqrt(CGAL::squared_area(s.points[t[0]], s.points[t[1]], s.points[t[2]]));
  return a;
}

inline double mean_edge_length(const Soup& s)
{
  std::vector<std::pair<std::size_t, std::size_t> > edges;
  edges.reserve(3 * s.triangles.size());
  for(const Triangle& t : s.triangles)
    for(int i = 0; i < 3; ++i)
      edges.push_back(std::minmax(t[i], t[(i + 1) % 3]));
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  double sum = 0.;
  for(const auto& e : edges)
    sum += std::sqrt(CGAL::squared_distance(s.points[e.first], s.points[e.second]));
  return edges.empty() ? 0. : sum / double(edges.size());
}

/// edge length giving about `n` vertices of near-equilateral triangles on a
/// closed surface of area `area` (V ~ F/2 and F ~ area / (sqrt(3)/4 h^2))
inline double edge_length_for(double area, std::size_t n)
{
  return std::sqrt(2. * area / (std::sqrt(3.) * double((std::max)(n, std::size_t(4)))));
}

// ---------------------------------------------------------------------------
// Reflection of a fundamental-domain patch
// ---------------------------------------------------------------------------

/// Copies `patch` once per element of the reflection group generated by the
/// coordinate planes of `mask`, sharing the patch vertices that lie on a
/// plane (`on_planes[v]`: bits of the planes of `mask` vertex `v` lies on;
/// those coordinates must be exactly 0).
inline Symmetric_soup reflect_patch(const Soup& patch, const std::vector<unsigned>& on_planes, unsigned mask)
{
  Symmetric_soup out;
  const std::size_t n = patch.points.size();
  std::vector<unsigned> group;
  for(unsigned g = 0; g < 8; ++g)
    if((g & ~mask) == 0) group.push_back(g);

  // global index of (patch vertex, group element); reduced elements come first
  // (g & ~on) <= g, so they are already numbered when looked up
  std::vector<std::vector<std::size_t> > id(8, std::vector<std::size_t>(n, std::size_t(-1)));
  for(unsigned g : group)
    for(std::size_t v = 0; v < n; ++v) {
      const unsigned r = g & ~on_planes[v];
      if(r == g) {
        id[g][v] = out.soup.points.size();
        out.soup.points.push_back(flip(patch.points[v], g));
      } else {
        id[g][v] = id[r][v];
      }
    }
  for(unsigned g : group)
    for(const Triangle& t : patch.triangles) {
      Triangle u = {{id[g][t[0]], id[g][t[1]], id[g][t[2]]}};
      if(popcount3(g) % 2 == 1) std::swap(u[1], u[2]); // a reflection reverses orientation
      out.soup.triangles.push_back(u);
    }
  for(int axis = 0; axis < 3; ++axis) {
    const unsigned bit = 1u << axis;
    if(!(mask & bit)) continue;
    std::vector<std::ptrdiff_t>& m = out.mirror[axis];
    m.assign(out.soup.points.size(), -1);
    for(unsigned g : group)
      for(std::size_t v = 0; v < n; ++v)
        m[id[g][v]] = std::ptrdiff_t(id[g ^ bit][v]);
  }
  return out;
}

// ---------------------------------------------------------------------------
// Remeshing of a patch, with projection onto an analytic surface
// ---------------------------------------------------------------------------

template <typename Projector>
struct Vertex_projection
{
  const Mesh* mesh;
  Projector projector;
  Point operator()(Mesh::Vertex_index v) const { return projector(mesh->point(v)); }
};

/// Isotropic remeshing of a fundamental-domain patch. The patch border lies
/// on the planes of `mask`; border edges are split and collapsed like the
/// others, which keeps their vertices on the planes (midpoints, endpoints),
/// corners (on two planes) are fixed, and border vertices are then evened
/// out within their plane. The projector must keep a zero coordinate zero, as
/// a gradient step on an implicit surface symmetric in that coordinate does.
/// `on_planes` receives, per output vertex, the planes it lies on.
template <typename Projector>
Soup remesh_patch(const Soup& in, unsigned mask, double h, const Projector& projector,
                  std::vector<unsigned>& on_planes, unsigned iterations = 8)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  Mesh m = soup_to_surface_mesh(in);
  if(!CGAL::is_valid_polygon_mesh(m) || num_faces(m) != in.triangles.size())
    throw std::logic_error("shape generator: invalid fundamental-domain patch");

  auto plane_bits = [&](const Point& p) {
    unsigned b = 0;
    for(int a = 0; a < 3; ++a)
      if((mask & (1u << a)) && coordinate(p, a) == 0.) b |= (1u << a);
    return b;
  };
  auto corner = m.add_property_map<Mesh::Vertex_index, bool>("v:irs_corner", false).first;
  for(Mesh::Vertex_index v : vertices(m))
    if(is_border(v, m) && popcount3(plane_bits(m.point(v))) >= 2) put(corner, v, true);

  Vertex_projection<Projector> projection{&m, projector};
  // CGAL 5.5 moves user-constrained corner vertices when relax_constraints is
  // on, so the border is relaxed by hand below instead.
  PMP::isotropic_remeshing(faces(m), h, m,
                           PMP::parameters::number_of_iterations(iterations)
                             .number_of_relaxation_steps(3)
                             .vertex_is_constrained_map(corner)
                             .projection_functor(projection));
  m.collect_garbage();
  corner = m.property_map<Mesh::Vertex_index, bool>("v:irs_corner").first;

  // Even out the border: each border vertex moves towards the midpoint of its
  // two border neighbours, in its plane (they share it), then back onto the surface.
  for(int it = 0; it < 10; ++it) {
    std::vector<std::pair<Mesh::Vertex_index, Point> > moves;
    for(Mesh::Halfedge_index hb : halfedges(m)) {
      if(!is_border(hb, m)) continue;
      const Mesh::Vertex_index v = target(hb, m);
      if(get(corner, v)) continue;
      const Point& a = m.point(source(hb, m));
      const Point& b = m.point(target(next(hb, m), m));
      const Point& p = m.point(v);
      moves.emplace_back(v, projector(Point(0.5 * p.x() + 0.25 * (a.x() + b.x()),
                                            0.5 * p.y() + 0.25 * (a.y() + b.y()),
                                            0.5 * p.z() + 0.25 * (a.z() + b.z()))));
    }
    for(const auto& mv : moves) m.point(mv.first) = mv.second;
  }
  // let the interior follow (no split nor collapse with a zero target length)
  PMP::isotropic_remeshing(faces(m), 0., m,
                           PMP::parameters::number_of_iterations(3)
                             .number_of_relaxation_steps(3)
                             .vertex_is_constrained_map(corner)
                             .projection_functor(projection));

  // Border vertices should be exactly on their plane; should the remesher
  // have moved one by a rounding error, put it back onto its nearest plane.
  on_planes.assign(num_vertices(m), 0u);
  for(Mesh::Vertex_index v : vertices(m)) {
    if(!is_border(v, m)) continue;
    const Point p = m.point(v);
    double c[3] = {p.x(), p.y(), p.z()};
    int nearest = -1;
    for(int a = 0; a < 3; ++a)
      if((mask & (1u << a)) && (nearest < 0 || std::abs(c[a]) < std::abs(c[nearest]))) nearest = a;
    if(nearest < 0 || std::abs(c[nearest]) > 1e-2 * h)
      throw std::logic_error("shape generator: a patch border vertex left its mirror plane");
    if(c[nearest] != 0.) {
      c[nearest] = 0.;
      m.point(v) = projector(Point(c[0], c[1], c[2]));
    }
    on_planes[std::size_t(v)] = plane_bits(m.point(v));
  }
  // a border edge cutting a corner (its ends on different planes) would leave a hole
  for(Mesh::Halfedge_index hb : halfedges(m))
    if(is_border(hb, m) && (on_planes[std::size_t(source(hb, m))] & on_planes[std::size_t(target(hb, m))]) == 0u)
      throw std::logic_error("shape generator: a patch border edge is not in a mirror plane");
  return surface_mesh_to_soup(m);
}

/// the image of vertex `v` under the group element `g` (bits: planes)
inline std::size_t image(const std::array<std::vector<std::ptrdiff_t>, 3>& mirror, std::size_t v, unsigned g)
{
  for(int a = 0; a < 3; ++a)
    if(g & (1u << a)) v = std::size_t(mirror[a][v]);
  return v;
}

/// Makes positions exactly symmetric: per orbit of the group generated by the
/// planes of `mask`, the average of the pulled-back positions is projected
/// (`project`, which must keep a zero coordinate zero and commute with the
/// reflections) and copied, reflected, to every vertex of the orbit.
/// Coordinates of vertices fixed by a plane are set to exactly 0.
template <typename Projection>
void symmetrize_positions(std::vector<Point>& pts, const std::array<std::vector<std::ptrdiff_t>, 3>& mirror,
                          unsigned mask, const Projection& project)
{
  std::vector<unsigned> group;
  for(unsigned g = 0; g < 8; ++g)
    if((g & ~mask) == 0) group.push_back(g);
  std::vector<bool> done(pts.size(), false);
  for(std::size_t v = 0; v < pts.size(); ++v) {
    if(done[v]) continue;
    double sum[3] = {0., 0., 0.};
    for(unsigned g : group) {
      const Point q = flip(pts[image(mirror, v, g)], g);
      sum[0] += q.x(); sum[1] += q.y(); sum[2] += q.z();
    }
    for(int a = 0; a < 3; ++a) {
      sum[a] /= double(group.size());
      if((mask & (1u << a)) && mirror[a][v] == std::ptrdiff_t(v)) sum[a] = 0.;
    }
    Point rep = project(Point(sum[0], sum[1], sum[2]));
    double c[3] = {rep.x(), rep.y(), rep.z()};
    unsigned zero = 0;
    for(int a = 0; a < 3; ++a)
      if((mask & (1u << a)) && mirror[a][v] == std::ptrdiff_t(v)) { c[a] = 0.; zero |= (1u << a); }
    rep = Point(c[0], c[1], c[2]);
    for(unsigned g : group) {
      const std::size_t w = image(mirror, v, g);
      if(done[w]) continue;
      pts[w] = flip(rep, g & ~zero); // no -0.0
      done[w] = true;
    }
  }
}

inline double smallest_angle(const Point& a, const Point& b, const Point& c)
{
  return (std::min)({CGAL::approximate_angle(b, a, c), CGAL::approximate_angle(a, b, c),
                     CGAL::approximate_angle(a, c, b)});
}

/// One pass of symmetric edge flips: an edge is flipped, together with all its
/// images under the group, when that raises the smallest angle of its two
/// triangles by more than a degree. Images share the decision (their geometry
/// is exactly mirrored) and are flipped together, so the triangulation stays
/// exactly symmetric. Orbits whose edges share a triangle are skipped.
inline bool symmetric_flips(Mesh& m, const std::array<std::vector<std::ptrdiff_t>, 3>& mirror, unsigned mask)
{
  std::vector<unsigned> group;
  for(unsigned g = 0; g < 8; ++g)
    if((g & ~mask) == 0) group.push_back(g);
  bool flipped = false;
  for(Mesh::Edge_index e : edges(m)) {
    const Mesh::Halfedge_index h = halfedge(e, m), o = opposite(h, m);
    const Mesh::Vertex_index a = source(h, m), b = target(h, m);
    const Mesh::Vertex_index p = target(next(h, m), m), q = target(next(o, m), m);
    if(p == q || halfedge(p, q, m).second) continue;
    const double before = (std::min)(smallest_angle(m.point(a), m.point(b), m.point(p)),
                                     smallest_angle(m.point(b), m.point(a), m.point(q)));
    const double after = (std::min)(smallest_angle(m.point(p), m.point(q), m.point(a)),
                                    smallest_angle(m.point(q), m.point(p), m.point(b)));
    if(after <= before + 1.) continue;
    // the new triangles must keep the orientation of the old ones
    const Vector n_old = CGAL::normal(m.point(a), m.point(b), m.point(p)) + CGAL::normal(m.point(b), m.point(a), m.point(q));
    if(CGAL::normal(m.point(p), m.point(q), m.point(b)) * n_old <= 0 ||
       CGAL::normal(m.point(q), m.point(p), m.point(a)) * n_old <= 0) continue;
    std::vector<Mesh::Halfedge_index> orbit;
    std::vector<Mesh::Face_index> orbit_faces;
    bool ok = true;
    for(unsigned g : group) {
      const auto hg = halfedge(Mesh::Vertex_index(Mesh::size_type(image(mirror, std::size_t(a), g))),
                               Mesh::Vertex_index(Mesh::size_type(image(mirror, std::size_t(b), g))), m);
      if(!hg.second) { ok = false; break; }
      bool seen = false;
      for(Mesh::Halfedge_index k : orbit)
        if(edge(k, m) == edge(hg.first, m)) seen = true;
      if(seen) continue;
      orbit.push_back(hg.first);
      orbit_faces.push_back(face(hg.first, m));
      orbit_faces.push_back(face(opposite(hg.first, m), m));
    }
    if(!ok) continue;
    std::sort(orbit_faces.begin(), orbit_faces.end());
    if(std::adjacent_find(orbit_faces.begin(), orbit_faces.end()) != orbit_faces.end()) continue;
    for(Mesh::Halfedge_index k : orbit) {
      const Mesh::Vertex_index pk = target(next(k, m), m), qk = target(next(opposite(k, m), m), m);
      if(halfedge(pk, qk, m).second) { ok = false; break; }
    }
    if(!ok) continue;
    for(Mesh::Halfedge_index k : orbit) CGAL::Euler::flip_edge(k, m);
    flipped = true;
  }
  return flipped;
}

/// Improves the triangles of an exactly symmetric soup without losing its
/// symmetry: symmetric flips, then CGAL's tangential relaxation followed by
/// symmetrisation and projection, a few rounds. Vertices keep their indices.
template <typename Projection>
void improve_symmetric(Symmetric_soup& s, unsigned mask, const Projection& project, int rounds = 6)
{
  Mesh m = soup_to_surface_mesh(s.soup);
  for(int r = 0; r < rounds; ++r) {
    for(int pass = 0; pass < 4 && symmetric_flips(m, s.mirror, mask); ++pass) {}
    CGAL::Polygon_mesh_processing::tangential_relaxation(m, CGAL::parameters::number_of_iterations(2));
    std::vector<Point> pts(m.points().begin(), m.points().end());
    symmetrize_positions(pts, s.mirror, mask, project);
    for(Mesh::Vertex_index v : vertices(m)) m.point(v) = pts[std::size_t(v)];
  }
  for(int pass = 0; pass < 4 && symmetric_flips(m, s.mirror, mask); ++pass) {}
  s.soup = surface_mesh_to_soup(m); // same vertices, same order
}

/// remeshes the patch, reflects it and improves it symmetrically:
/// an exactly mirror-symmetric closed soup
template <typename Projector>
Symmetric_soup symmetric_shape(const Soup& patch, unsigned mask, double h, const Projector& projector)
{
  std::vector<unsigned> on_planes;
  Soup remeshed = remesh_patch(patch, mask, h, projector, on_planes);
  Symmetric_soup s = reflect_patch(remeshed, on_planes, mask);
  if(!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(s.soup.triangles))
    throw std::logic_error("shape generator: the reflected patch is not a 2-manifold");
  improve_symmetric(s, mask, projector);
  return s;
}

// ---------------------------------------------------------------------------
// Projectors onto analytic surfaces (all keep a zero x, y or z coordinate zero)
// ---------------------------------------------------------------------------

/// Newton steps along the gradient of x^2 + y^2 - f(z) (surface of revolution about z)
template <typename Profile>
struct Revolution_projector
{
  Profile profile; // f(z) = radius^2 at height z, and its derivative
  Point operator()(const Point& p) const
  {
    double x = p.x(), y = p.y(), z = p.z();
    for(int it = 0; it < 30; ++it) {
      const double F = x * x + y * y - profile.f(z);
      const double gx = 2 * x, gy = 2 * y, gz = -profile.df(z);
      const double gg = gx * gx + gy * gy + gz * gz;
      if(gg == 0.) break;
      const double t = F / gg;
      x -= t * gx; y -= t * gy; z -= t * gz;
      if(std::abs(F) < 1e-15) break;
    }
    return Point(x, y, z);
  }
};

/// Newton steps along the gradient of x^2/a^2 + y^2/b^2 + z^2/c^2 - 1
struct Ellipsoid_projector
{
  double a, b, c;
  Point operator()(const Point& p) const
  {
    double x = p.x(), y = p.y(), z = p.z();
    for(int it = 0; it < 30; ++it) {
      const double F = x * x / (a * a) + y * y / (b * b) + z * z / (c * c) - 1.;
      const double gx = 2 * x / (a * a), gy = 2 * y / (b * b), gz = 2 * z / (c * c);
      const double gg = gx * gx + gy * gy + gz * gz;
      if(gg == 0.) break;
      const double t = F / gg;
      x -= t * gx; y -= t * gy; z -= t * gz;
      if(std::abs(F) < 1e-15) break;
    }
    return Point(x, y, z);
  }
};

/// closest point on the torus of axis z, major radius R and minor radius r
struct Torus_projector
{
  double R, r;
  Point operator()(const Point& p) const
  {
    const double d = std::sqrt(p.x() * p.x() + p.y() * p.y());
    if(d == 0.) return p; // on the axis: no closest point; never happens on a patch
    const double cx = R * p.x() / d, cy = R * p.y() / d;
    const double vx = p.x() - cx, vy = p.y() - cy, vz = p.z();
    const double l = std::sqrt(vx * vx + vy * vy + vz * vz);
    if(l == 0.) return p;
    return Point(cx + r * vx / l, cy + r * vy / l, r * vz / l);
  }
};

// ---------------------------------------------------------------------------
// Fundamental-domain patches
// ---------------------------------------------------------------------------

/// Quarter (x >= 0, y >= 0) of a surface of revolution about z, from rows
/// (rho, z) along its profile: a row with rho == 0 is a pole. Adjacent rows
/// are joined by the shorter-diagonal strip triangulation. Outward
/// orientation if the profile turns counterclockwise (bottom to top on the
/// outside).
inline Soup revolution_patch(const std::vector<std::array<double, 2> >& rows, double h)
{
  Soup s;
  std::vector<std::vector<std::size_t> > ring(rows.size());
  for(std::size_t j = 0; j < rows.size(); ++j) {
    const double rho = rows[j][0], z = rows[j][1];
    if(rho == 0.) {
      ring[j].push_back(s.points.size());
      s.points.push_back(Point(0., 0., z));
      continue;
    }
    const int m = (std::max)(1, int(std::lround(rho * (pi / 2) / h)));
    for(int k = 0; k <= m; ++k) {
      ring[j].push_back(s.points.size());
      if(k == 0)      s.points.push_back(Point(rho, 0., z));
      else if(k == m) s.points.push_back(Point(0., rho, z));
      else {
        const double phi = (pi / 2) * double(k) / double(m);
        s.points.push_back(Point(rho * std::cos(phi), rho * std::sin(phi), z));
      }
    }
  }
  for(std::size_t j = 0; j + 1 < rows.size(); ++j) {
    const std::vector<std::size_t>& a = ring[j];
    const std::vector<std::size_t>& b = ring[j + 1];
    std::size_t i = 0, k = 0;
    while(i + 1 < a.size() || k + 1 < b.size()) {
      bool advance_a;
      if(i + 1 == a.size())      advance_a = false;
      else if(k + 1 == b.size()) advance_a = true;
      else
        advance_a = CGAL::squared_distance(s.points[a[i + 1]], s.points[b[k]]) <
                    CGAL::squared_distance(s.points[a[i]], s.points[b[k + 1]]);
      if(advance_a) { s.triangles.push_back(Triangle{{a[i], a[i + 1], b[k]}}); ++i; }
      else          { s.triangles.push_back(Triangle{{a[i], b[k + 1], b[k]}}); ++k; }
    }
  }
  return s;
}

/// Positive octant of an ellipsoid: a frequency-n grid on the octahedron face
/// with corners on the axes, pushed onto the unit sphere, then scaled.
inline Soup ellipsoid_octant_patch(double a, double b, double c, int n)
{
  Soup s;
  std::vector<std::vector<std::size_t> > id(n + 1);
  for(int i = 0; i <= n; ++i)
    for(int j = 0; i + j <= n; ++j) {
      const double u = double(n - i - j), v = double(i), w = double(j);
      const double l = std::sqrt(u * u + v * v + w * w);
      id[i].push_back(s.points.size());
      s.points.push_back(Point(a * u / l, b * v / l, c * w / l)); // zero coordinates stay exactly 0
    }
  for(int i = 0; i < n; ++i)
    for(int j = 0; i + j < n; ++j) {
      s.triangles.push_back(Triangle{{id[i][j], id[i + 1][j], id[i][j + 1]}});
      if(i + j + 1 < n)
        s.triangles.push_back(Triangle{{id[i + 1][j], id[i + 1][j + 1], id[i][j + 1]}});
    }
  return s;
}

/// rows (rho, z) at equal arc-length steps of about `step` along a dense
/// polyline; the end points are kept exactly
inline std::vector<std::array<double, 2> >
resample_profile(const std::vector<std::array<double, 2> >& dense, double step)
{
  std::vector<double> s(dense.size(), 0.);
  for(std::size_t i = 1; i < dense.size(); ++i)
    s[i] = s[i - 1] + std::hypot(dense[i][0] - dense[i - 1][0], dense[i][1] - dense[i - 1][1]);
  const double L = s.back();
  const int n = (std::max)(2, int(std::lround(L / step)));
  std::vector<std::array<double, 2> > rows;
  rows.push_back(dense.front());
  std::size_t seg = 1;
  for(int j = 1; j < n; ++j) {
    const double t = L * double(j) / double(n);
    while(seg + 1 < dense.size() && s[seg] < t) ++seg;
    const double w = (t - s[seg - 1]) / (s[seg] - s[seg - 1]);
    rows.push_back({{dense[seg - 1][0] + w * (dense[seg][0] - dense[seg - 1][0]),
                     dense[seg - 1][1] + w * (dense[seg][1] - dense[seg - 1][1])}});
  }
  rows.push_back(dense.back());
  return rows;
}

/// area of the surface of revolution of a profile polyline (Pappus)
inline double revolution_area(const std::vector<std::array<double, 2> >& dense)
{
  double a = 0.;
  for(std::size_t i = 1; i < dense.size(); ++i)
    a += 2 * pi * 0.5 * (dense[i][0] + dense[i - 1][0]) *
         std::hypot(dense[i][0] - dense[i - 1][0], dense[i][1] - dense[i - 1][1]);
  return a;
}

/// Traces the profile rho^2 = f(z) of a closed surface of revolution from its
/// bottom pole to its top pole (predictor step along the tangent, Newton
/// correction), as a dense polyline. `z_lo` < bottom pole, `z_hi` > top pole.
template <typename Profile>
std::vector<std::array<double, 2> > trace_profile(const Profile& p, double z_lo, double z_hi, double step)
{
  auto pole = [&](double outside, double inside) { // f(outside) < 0 < f(inside)
    for(int it = 0; it < 200; ++it) {
      const double mid = 0.5 * (outside + inside);
      (p.f(mid) > 0 ? inside : outside) = mid;
    }
    return 0.5 * (outside + inside);
  };
  double zin = z_lo;
  while(p.f(zin) <= 0) zin += step * 0.25;
  const double z_bottom = pole(z_lo, zin);
  zin = z_hi;
  while(p.f(zin) <= 0) zin -= step * 0.25;
  const double z_top = pole(z_hi, zin);

  std::vector<std::array<double, 2> > out;
  out.push_back({{0., z_bottom}});
  double rho = 0., z = z_bottom;
  for(int guard = 0; guard < 10000000; ++guard) {
    const double tr = p.df(z), tz = 2 * rho, tl = std::hypot(tr, tz);
    double r1 = rho + step * tr / tl, z1 = z + step * tz / tl;
    if(r1 <= 0.5 * step && tr < 0) break; // reached the top pole
    for(int it = 0; it < 20; ++it) {
      const double G = r1 * r1 - p.f(z1), gr = 2 * r1, gz = -p.df(z1), gg = gr * gr + gz * gz;
      r1 -= G * gr / gg; z1 -= G * gz / gg;
      if(std::abs(G) < 1e-14) break;
    }
    r1 = std::abs(r1);
    rho = r1; z = z1;
    out.push_back({{rho, z}});
  }
  out.push_back({{0., z_top}});
  return out;
}

/// f(z) for a capsule of radius r whose cylinder spans |z| <= hl (C^1 profile)
struct Capsule_profile
{
  double r, hl;
  double f(double z) const { const double e = (std::max)(0., std::abs(z) - hl); return r * r - e * e; }
  double df(double z) const
  {
    const double e = std::abs(z) - hl;
    return e <= 0 ? 0. : (z > 0 ? -2 * e : 2 * e);
  }
};

/// upper half (z >= 0) of a capsule profile, at arc-length steps of about `step`
inline std::vector<std::array<double, 2> > capsule_half_rows(double r, double hl, double step)
{
  const double L = hl + pi * r / 2;
  const int n = (std::max)(2, int(std::lround(L / step)));
  std::vector<std::array<double, 2> > rows;
  for(int j = 0; j <= n; ++j) {
    const double s = L * double(j) / double(n);
    if(j == 0)      rows.push_back({{r, 0.}});
    else if(j == n) rows.push_back({{0., hl + r}});
    else if(s <= hl) rows.push_back({{r, s}});
    else { const double a = (s - hl) / r; rows.push_back({{r * std::cos(a), hl + r * std::sin(a)}}); }
  }
  return rows;
}

/// upper half of the tube circle of a torus (outer equator to inner equator)
inline std::vector<std::array<double, 2> > torus_half_rows(double R, double r, double step)
{
  const int n = (std::max)(2, int(std::lround(pi * r / step)));
  std::vector<std::array<double, 2> > rows;
  for(int j = 0; j <= n; ++j) {
    const double v = pi * double(j) / double(n);
    if(j == 0)      rows.push_back({{R + r, 0.}});
    else if(j == n) rows.push_back({{R - r, 0.}});
    else            rows.push_back({{R + r * std::cos(v), r * std::sin(v)}});
  }
  return rows;
}

/// Smooth snowman profile: three stacked spheres (centre, radius) blended by a
/// log-sum-exp of r_i^2 - (z - c_i)^2 (a smooth maximum, width ~ 1/sharpness).
struct Snowman_profile
{
  std::array<double, 3> c = {{1.0, 2.3, 3.25}};
  std::array<double, 3> r = {{1.0, 0.68, 0.45}};
  double sharpness = 6.;
  double scale = 1.;

  double g(int i, double zu) const { return r[i] * r[i] - (zu - c[i]) * (zu - c[i]); }
  double f(double z) const
  {
    const double zu = z / scale;
    double m = -std::numeric_limits<double>::infinity();
    for(int i = 0; i < 3; ++i) m = (std::max)(m, g(i, zu));
    double s = 0.;
    for(int i = 0; i < 3; ++i) s += std::exp(sharpness * (g(i, zu) - m));
    return scale * scale * (m + std::log(s) / sharpness);
  }
  double df(double z) const
  {
    const double zu = z / scale;
    double m = -std::numeric_limits<double>::infinity();
    for(int i = 0; i < 3; ++i) m = (std::max)(m, g(i, zu));
    double s = 0., d = 0.;
    for(int i = 0; i < 3; ++i) {
      const double w = std::exp(sharpness * (g(i, zu) - m));
      s += w;
      d += w * (-2 * (zu - c[i]));
    }
    return scale * d / s; // d/dz [scale^2 F(z/scale)] = scale F'(z/scale)
  }
  double bottom() const { return scale * (c[0] - r[0]); }
  double top() const { return scale * (c[2] + r[2]); }
};

// ---------------------------------------------------------------------------
// Mirror maps by nearest vertex
// ---------------------------------------------------------------------------

/// For every vertex v, the vertex nearest to reflect(p_v) if it is closer than
/// `tolerance` and the relation is mutual (so the map is an involution), else -1.
template <typename Reflection>
std::vector<std::ptrdiff_t> mirror_by_nearest_vertex(const std::vector<Point>& points,
                                                     const Reflection& reflect, double tolerance)
{
  typedef CGAL::Search_traits_3<K>                                            Traits_base;
  typedef CGAL::Pointer_property_map<Point>::const_type                      Point_map;
  typedef CGAL::Search_traits_adapter<std::size_t, Point_map, Traits_base>   Traits;
  typedef CGAL::Orthogonal_k_neighbor_search<Traits>                         Search;
  typedef Search::Tree                                                        Tree;
  typedef Search::Distance                                                    Distance;

  Point_map ppmap = CGAL::make_property_map(points);
  std::vector<std::size_t> ids(points.size());
  for(std::size_t i = 0; i < ids.size(); ++i) ids[i] = i;
  Tree tree(ids.begin(), ids.end(), Tree::Splitter(), Traits(ppmap));
  tree.build();
  Distance distance(ppmap);

  std::vector<std::ptrdiff_t> nearest(points.size(), -1);
  for(std::size_t v = 0; v < points.size(); ++v) {
    Search search(tree, reflect(points[v]), 1, 0, true, distance);
    const auto it = search.begin();
    if(it != search.end() && std::sqrt(it->second) <= tolerance)
      nearest[v] = std::ptrdiff_t(it->first);
  }
  std::vector<std::ptrdiff_t> mirror(points.size(), -1);
  for(std::size_t v = 0; v < points.size(); ++v)
    if(nearest[v] >= 0 && nearest[std::size_t(nearest[v])] == std::ptrdiff_t(v))
      mirror[v] = nearest[v];
  return mirror;
}

} // namespace shapes
} // namespace internal
} // namespace Intrinsic_reflectional_symmetry_3
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_SHAPE_CONSTRUCTION_H
