// Copyright (c) 2026 The Intrinsic_reflectional_symmetry_3 project.
// SPDX-License-Identifier: LGPL-3.0-or-later
// Author(s)     : The Intrinsic_reflectional_symmetry_3 developers

#ifndef CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_REPAIR_MESH_H
#define CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_REPAIR_MESH_H

#include <CGAL/disable_warnings.h>

// Building blocks of part_repair.h: an indexed triangle soup copy of the
// input (the input is never modified), its conversion back to any
// TriangleMesh, connectivity helpers and the final validity checks. No API promise.

#include <CGAL/Intrinsic_reflectional_symmetry_3/errors.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <map>
#include <queue>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Intrinsic_reflectional_symmetry_3 {
namespace internal {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Repair_kernel;
typedef Repair_kernel::Point_3                              Repair_point;
typedef Repair_kernel::Vector_3                             Repair_vector;
typedef Repair_kernel::Plane_3                              Repair_plane;
typedef CGAL::Surface_mesh<Repair_point>                    Repair_surface;
typedef std::array<std::size_t, 3>                          Repair_triangle;
/// AABB tree of a Repair_surface's triangles (closest points, inside tests)
typedef CGAL::AABB_tree<CGAL::AABB_traits<Repair_kernel, CGAL::AABB_face_graph_triangle_primitive<Repair_surface> > >
  Repair_tree;

struct Repair_soup
{
  std::vector<Repair_point> points;
  std::vector<Repair_triangle> triangles;
};

/// the mesh as a soup, vertices in the order of the vertex index map
template <typename TriangleMesh, typename NamedParameters>
Repair_soup mesh_to_repair_soup(const TriangleMesh& tm, const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm));
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  Repair_soup s;
  s.points.resize(num_vertices(tm));
  for(auto v : vertices(tm))
  {
    const auto& p = get(vpm, v);
    s.points[std::size_t(get(vim, v))] = Repair_point(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  }
  for(auto f : faces(tm))
  {
    Repair_triangle t;
    int i = 0;
    for(auto v : vertices_around_face(halfedge(f, tm), tm))
    {
      if(i == 3) throw Input_error(Input_problem::not_triangle_mesh, "part repair needs a triangle mesh");
      t[std::size_t(i++)] = std::size_t(get(vim, v));
    }
    if(i != 3) throw Input_error(Input_problem::not_triangle_mesh, "part repair needs a triangle mesh");
    s.triangles.push_back(t);
  }
  return s;
}

/// drops the vertices no triangle uses, keeping the order of the others;
/// `old_to_new` receives the new index of every old vertex (or -1)
inline Repair_soup compact_soup(const Repair_soup& in, std::vector<std::ptrdiff_t>* old_to_new = nullptr)
{
  std::vector<std::ptrdiff_t> id(in.points.size(), -1);
  for(const Repair_triangle& t : in.triangles)
    for(std::size_t v : t) id[v] = 0;
  Repair_soup out;
  for(std::size_t v = 0; v < in.points.size(); ++v)
    if(id[v] == 0) { id[v] = std::ptrdiff_t(out.points.size()); out.points.push_back(in.points[v]); }
  for(const Repair_triangle& t : in.triangles)
    out.triangles.push_back(Repair_triangle{{std::size_t(id[t[0]]), std::size_t(id[t[1]]), std::size_t(id[t[2]])}});
  if(old_to_new) *old_to_new = std::move(id);
  return out;
}

/// `tm` (cleared first) built from a soup; throws if the soup is not a 2-manifold polygon mesh
template <typename TriangleMesh>
void repair_soup_to_mesh(const Repair_soup& s, TriangleMesh& tm, const std::string& what)
{
  if(!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(s.triangles))
    throw Input_error(Input_problem::non_manifold_vertex, what + ": the result would not be a 2-manifold");
  typedef typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::type VPM;
  typedef typename boost::property_traits<VPM>::value_type Mesh_point;
  std::vector<Mesh_point> points;
  points.reserve(s.points.size());
  for(const Repair_point& p : s.points) points.push_back(Mesh_point(p.x(), p.y(), p.z()));
  clear(tm);
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, s.triangles, tm);
}

inline Repair_surface soup_to_surface(const Repair_soup& s)
{
  Repair_surface m;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(s.points, s.triangles, m);
  return m;
}

/// vertex -> neighbour vertices (through the edges of the triangles)
inline std::vector<std::vector<std::size_t> > soup_neighbours(const Repair_soup& s)
{
  std::vector<std::vector<std::size_t> > nb(s.points.size());
  for(const Repair_triangle& t : s.triangles)
    for(int i = 0; i < 3; ++i)
    {
      nb[t[std::size_t(i)]].push_back(t[std::size_t((i + 1) % 3)]);
      nb[t[std::size_t((i + 1) % 3)]].push_back(t[std::size_t(i)]);
    }
  for(auto& n : nb) { std::sort(n.begin(), n.end()); n.erase(std::unique(n.begin(), n.end()), n.end()); }
  return nb;
}

/// Edge-graph Dijkstra from `sources` into `d` (+infinity where not reached),
/// relaxing only up to `radius` and stopping once `target` is settled; every
/// vertex given a distance is appended to `touched`. Returns whether `target`
/// was settled.
inline bool soup_dijkstra_bounded(const Repair_soup& s, const std::vector<std::vector<std::size_t> >& nb,
                                  const std::vector<std::size_t>& sources, double radius, std::size_t target,
                                  std::vector<double>& d, std::vector<std::size_t>& touched)
{
  typedef std::pair<double, std::size_t> Item;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item> > q;
  for(std::size_t v : sources) { d[v] = 0.; touched.push_back(v); q.push(Item(0., v)); }
  while(!q.empty())
  {
    const Item it = q.top();
    q.pop();
    if(it.first > d[it.second]) continue;
    if(it.second == target) return true;
    for(std::size_t w : nb[it.second])
    {
      const double dw = it.first + std::sqrt(CGAL::squared_distance(s.points[it.second], s.points[w]));
      if(dw <= radius && dw < d[w])
      {
        if(d[w] == std::numeric_limits<double>::infinity()) touched.push_back(w);
        d[w] = dw;
        q.push(Item(dw, w));
      }
    }
  }
  return false;
}

/// edge-graph Dijkstra distances from a set of vertices of a soup
inline std::vector<double> soup_dijkstra(const Repair_soup& s, const std::vector<std::vector<std::size_t> >& nb,
                                         const std::vector<std::size_t>& sources)
{
  std::vector<double> d(s.points.size(), std::numeric_limits<double>::infinity());
  std::vector<std::size_t> touched;
  soup_dijkstra_bounded(s, nb, sources, std::numeric_limits<double>::infinity(), std::size_t(-1), d, touched);
  return d;
}

/// Whether `target` is within edge-graph distance `radius` of `source`. `d`
/// is scratch, of the soup's size and all +infinity on entry; it is so again
/// on return, so that many calls cost only the vertices within `radius`.
inline bool soup_within(const Repair_soup& s, const std::vector<std::vector<std::size_t> >& nb, std::size_t source,
                        std::size_t target, double radius, std::vector<double>& d)
{
  std::vector<std::size_t> touched;
  const bool found = soup_dijkstra_bounded(s, nb, {source}, radius, target, d, touched);
  for(std::size_t v : touched) d[v] = std::numeric_limits<double>::infinity();
  return found;
}

inline double soup_mean_edge_length(const Repair_soup& s)
{
  double sum = 0.;
  std::size_t n = 0;
  for(const Repair_triangle& t : s.triangles)
    for(int i = 0; i < 3; ++i, ++n)
      sum += std::sqrt(CGAL::squared_distance(s.points[t[std::size_t(i)]], s.points[t[std::size_t((i + 1) % 3)]]));
  return n ? sum / double(n) : 0.;
}

inline double soup_bbox_diagonal(const std::vector<Repair_point>& pts)
{
  if(pts.empty()) return 0.;
  const CGAL::Bbox_3 b = CGAL::bbox_3(pts.begin(), pts.end());
  return std::sqrt(CGAL::square(b.xmax() - b.xmin()) + CGAL::square(b.ymax() - b.ymin()) + CGAL::square(b.zmax() - b.zmin()));
}

/// one third of the incident triangle areas
inline std::vector<double> soup_vertex_areas(const Repair_soup& s)
{
  std::vector<double> a(s.points.size(), 0.);
  for(const Repair_triangle& t : s.triangles)
  {
    const double fa = std::sqrt(CGAL::squared_area(s.points[t[0]], s.points[t[1]], s.points[t[2]])) / 3.;
    for(std::size_t v : t) a[v] += fa;
  }
  return a;
}

/// connected components (through `nb`) of the vertices with `in[v]`; labels -1 elsewhere
inline std::size_t label_components(const std::vector<std::vector<std::size_t> >& nb, const std::vector<char>& in,
                                    std::vector<std::ptrdiff_t>& label)
{
  label.assign(nb.size(), -1);
  std::size_t n = 0;
  std::vector<std::size_t> stack;
  for(std::size_t s = 0; s < nb.size(); ++s)
  {
    if(!in[s] || label[s] >= 0) continue;
    label[s] = std::ptrdiff_t(n);
    stack.assign(1, s);
    while(!stack.empty())
    {
      const std::size_t v = stack.back();
      stack.pop_back();
      for(std::size_t w : nb[v])
        if(in[w] && label[w] < 0) { label[w] = std::ptrdiff_t(n); stack.push_back(w); }
    }
    ++n;
  }
  return n;
}

/// The border loops of the triangles of `s` (each as the vertex sequence along
/// the border halfedges, i.e. with the missing faces on the left); empty if
/// an edge has more than two triangles or a border vertex is pinched.
inline bool border_loops(const Repair_soup& s, std::vector<std::vector<std::size_t> >& loops)
{
  loops.clear();
  std::map<std::pair<std::size_t, std::size_t>, int> directed;
  for(const Repair_triangle& t : s.triangles)
    for(int i = 0; i < 3; ++i)
      if(++directed[std::make_pair(t[std::size_t(i)], t[std::size_t((i + 1) % 3)])] > 1) return false;
  // a border halfedge (a, b) has no (b, a); it runs against the triangle's (b, a) order, so the
  // border loop goes b -> a
  std::map<std::size_t, std::size_t> next;
  for(const auto& d : directed)
    if(directed.find(std::make_pair(d.first.second, d.first.first)) == directed.end())
      if(!next.emplace(d.first.second, d.first.first).second) return false; // pinched border vertex
  std::map<std::size_t, bool> used;
  for(const auto& st : next)
  {
    if(used[st.first]) continue;
    std::vector<std::size_t> loop;
    std::size_t v = st.first;
    while(!used[v])
    {
      used[v] = true;
      loop.push_back(v);
      const auto it = next.find(v);
      if(it == next.end()) return false;
      v = it->second;
    }
    if(v != st.first) return false;
    loops.push_back(loop);
  }
  return true;
}

/// Why a result is not one closed 2-manifold, or empty.
template <typename TriangleMesh>
std::string mesh_defect(const TriangleMesh& tm)
{
  if(!CGAL::is_valid_polygon_mesh(tm)) return "not a valid polygon mesh";
  if(!CGAL::is_triangle_mesh(tm)) return "not a triangle mesh";
  if(!CGAL::is_closed(tm)) return "not closed";
  return std::string();
}

/// Whether a pair of intersecting faces involves a face with `is_new(f)`.
/// Real scans often self-intersect already (most FAUST meshes do, where
/// skin touches skin); what the repair must not do is add intersections.
template <typename IsNew>
bool self_intersects_new(const Repair_surface& m, const IsNew& is_new)
{
  std::vector<std::pair<Repair_surface::Face_index, Repair_surface::Face_index> > pairs;
  CGAL::Polygon_mesh_processing::self_intersections(m, std::back_inserter(pairs));
  for(const auto& p : pairs)
    if(is_new(p.first) || is_new(p.second)) return true;
  return false;
}

} // namespace internal
} // namespace Intrinsic_reflectional_symmetry_3
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_REPAIR_MESH_H
