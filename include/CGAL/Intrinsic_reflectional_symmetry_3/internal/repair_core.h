// Copyright (c) 2026 The Intrinsic_reflectional_symmetry_3 project.
// SPDX-License-Identifier: LGPL-3.0-or-later
// Author(s)     : The Intrinsic_reflectional_symmetry_3 developers

#ifndef CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_REPAIR_CORE_H
#define CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_REPAIR_CORE_H

#include <CGAL/disable_warnings.h>

// The steps of repair_missing_parts() (part_repair.h) on an indexed soup:
// mirror plane, missing-part detection, placement (reflection + ICP),
// overlap removal, stitching and seam fairing. No API promise.

#include <CGAL/Intrinsic_reflectional_symmetry_3/errors.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/repair_mesh.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/repair_protocol.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Polygon_mesh_processing/fair.h>
#include <CGAL/Polygon_mesh_processing/refine.h>
#include <CGAL/Polygon_mesh_processing/repair_self_intersections.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/linear_least_squares_fitting_3.h>

#include <Eigen/Dense>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <queue>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Intrinsic_reflectional_symmetry_3 {
namespace internal {

struct Repair_settings
{
  double threshold = 0.02;          // tau, as a fraction of the bounding-box diagonal
  double minimum_part_area = 0.005; // fraction of the total area
  double minimum_mirror_agreement = 0.8; // fraction of the total area (see repair_core())
  unsigned icp_iterations = 30; // not more: on FAUST, 100 iterations let the copies slide and turn
                                // further (tr_reg_009 forearm 2.07 -> 2.33 % of the diagonal)
  double maximum_collar_rms = 0.125; // of tau (see repair_core())
  double slender_part = 5.;  // length / base radius above which a part also gets the wide collar
  double wide_collar = 7.;   // of tau: the wide collar's width (see repair_core())
};

struct Repair_core_result
{
  Repair_soup mesh;
  std::array<double, 4> plane = {{0., 0., 0., 0.}};
  std::vector<std::size_t> part_sizes;
  std::vector<double> icp_rms;
  std::vector<bool> faired;
};

inline std::string repair_failure(const std::string& why) { return "part repair is not possible: " + why; }

inline Repair_point reflect_point(const Repair_point& p, const Repair_vector& n, const Repair_point& c)
{
  return p - 2. * ((p - c) * n) * n;
}

/// least-squares plane (unit normal `n`, point `c`) of points
inline void fit_plane(const std::vector<Repair_point>& pts, Repair_vector& n, Repair_point& c)
{
  Repair_plane plane;
  CGAL::linear_least_squares_fitting_3(pts.begin(), pts.end(), plane, c, CGAL::Dimension_tag<0>(),
                                       Repair_kernel(), CGAL::Default_diagonalize_traits<double, 3>());
  n = plane.orthogonal_vector();
  n = n / std::sqrt(n.squared_length());
}

/// The surface ICP fits onto, as an AABB tree of its triangles: built once,
/// queried by every fit of every part.
class Icp_target
{
public:
  /// `target`: triangles of a soup
  explicit Icp_target(const Repair_soup& target)
    : surface_(soup_to_surface(compact_soup(target))), tree_(faces(surface_).first, faces(surface_).second, surface_)
  {
    if(!tree_.empty()) tree_.accelerate_distance_queries();
  }
  Icp_target(const Icp_target&) = delete; // the tree points into the surface
  Icp_target& operator=(const Icp_target&) = delete;

  bool empty() const { return tree_.empty(); }
  Repair_point closest_point(const Repair_point& p) const { return tree_.closest_point(p); }

private:
  Repair_surface surface_;
  Repair_tree tree_;
};

/// Rigid ICP (point to closest surface point, trimmed): returns T with T(src)
/// ~ the target surface. Rigid fit by Eigen's umeyama(), closest points by a
/// CGAL AABB tree: closest points on the triangles, not nearest vertices,
/// because the two sides of a scan are meshed independently and nearest
/// vertices bias the fit by up to half an edge.
inline Eigen::Matrix4d rigid_icp(const std::vector<Repair_point>& src, const Icp_target& target,
                                 double max_pair_distance, unsigned iterations, double& rms, double& rms_start)
{
  Eigen::Matrix4d T = Eigen::Matrix4d::Identity();
  rms = rms_start = std::numeric_limits<double>::infinity();
  if(src.size() < 3 || target.empty()) return T;

  for(unsigned it = 0; it < iterations; ++it)
  {
    std::vector<std::pair<double, std::pair<Eigen::Vector3d, Eigen::Vector3d> > > pairs;
    for(const Repair_point& p0 : src)
    {
      const Eigen::Vector3d p = (T * Eigen::Vector4d(p0.x(), p0.y(), p0.z(), 1.)).head<3>();
      const Repair_point q = target.closest_point(Repair_point(p.x(), p.y(), p.z()));
      const double d = std::sqrt(CGAL::squared_distance(q, Repair_point(p.x(), p.y(), p.z())));
      if(d > max_pair_distance) continue;
      pairs.push_back(std::make_pair(d, std::make_pair(p, Eigen::Vector3d(q.x(), q.y(), q.z()))));
    }
    if(pairs.size() < 3) break;
    // trimmed ICP: the 80 % closest pairs (the ring's far side may face a cap or nothing)
    std::sort(pairs.begin(), pairs.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    const std::size_t k = (std::max)(std::size_t(3), pairs.size() * 4 / 5);
    Eigen::Matrix3Xd A(3, k), B(3, k);
    double sq = 0.;
    for(std::size_t i = 0; i < k; ++i)
    {
      A.col(Eigen::Index(i)) = pairs[i].second.first;
      B.col(Eigen::Index(i)) = pairs[i].second.second;
      sq += pairs[i].first * pairs[i].first;
    }
    rms = std::sqrt(sq / double(k));
    if(it == 0) rms_start = rms;
    const Eigen::Matrix4d step = Eigen::umeyama(A, B, false);
    T = step * T;
    if((step - Eigen::Matrix4d::Identity()).norm() < 1e-9) break;
  }
  return T;
}

inline Repair_point apply(const Eigen::Matrix4d& T, const Repair_point& p)
{
  const Eigen::Vector3d q = (T * Eigen::Vector4d(p.x(), p.y(), p.z(), 1.)).head<3>();
  return Repair_point(q.x(), q.y(), q.z());
}

/// vertices not in the largest (by area) component of the complement of `in` are added to `in`
inline void fill_enclosed(const std::vector<std::vector<std::size_t> >& nb, const std::vector<double>& area,
                          std::vector<char>& in)
{
  std::vector<char> out(in.size());
  for(std::size_t v = 0; v < in.size(); ++v) out[v] = !in[v];
  std::vector<std::ptrdiff_t> label;
  const std::size_t nc = label_components(nb, out, label);
  if(nc <= 1) return;
  std::vector<double> a(nc, 0.);
  for(std::size_t v = 0; v < in.size(); ++v) if(label[v] >= 0) a[std::size_t(label[v])] += area[v];
  const std::ptrdiff_t big = std::ptrdiff_t(std::max_element(a.begin(), a.end()) - a.begin());
  for(std::size_t v = 0; v < in.size(); ++v) if(label[v] >= 0 && label[v] != big) in[v] = 1;
}

/// The end of a limb inside the vertex set `in`: the vertices reached from
/// the one of `in` farthest from the axis (largest `g`) by a flood that
/// always takes the highest `g` on its front (the component of {g >= t}
/// around that vertex, for a falling t), stopped before more than 5 % of its
/// area lies outside `in`; returned intersected with `in`. Its border runs
/// across the limb, along a level of `g`, where the border of `in` may run up
/// the limb's side.
inline std::vector<char> limb_end_within(const std::vector<std::vector<std::size_t> >& nb,
                                         const std::vector<double>& area, const std::vector<double>& g,
                                         const std::vector<char>& in)
{
  const std::size_t n = in.size();
  std::size_t tip = n;
  for(std::size_t v = 0; v < n; ++v) if(in[v] && (tip == n || g[v] > g[tip])) tip = v;
  std::vector<char> end(n, 0);
  if(tip == n) return end;
  std::priority_queue<std::pair<double, std::size_t> > front;
  std::vector<char> seen(n, 0);
  front.push(std::make_pair(g[tip], tip));
  seen[tip] = 1;
  double inside = 0., outside = 0.;
  while(!front.empty())
  {
    const std::size_t v = front.top().second;
    front.pop();
    (in[v] ? inside : outside) += area[v];
    if(outside > 0.05 * (inside + outside)) break;
    end[v] = in[v];
    for(std::size_t w : nb[v]) if(!seen[w]) { seen[w] = 1; front.push(std::make_pair(g[w], w)); }
  }
  return end;
}

/// The triangles of a vertex set made a disk-like face region: the largest
/// edge-connected component of its triangles, its holes filled, and the
/// faces around pinched border vertices added, until its border is simple.
/// Returns the region's triangles (indices into s.triangles); empty on failure.
inline std::vector<std::size_t> clean_part_region(const Repair_soup& s, const std::vector<char>& in_vertex)
{
  const std::size_t nf = s.triangles.size();
  std::map<std::pair<std::size_t, std::size_t>, std::vector<std::size_t> > edge_faces;
  std::vector<std::vector<std::size_t> > vertex_faces(s.points.size());
  for(std::size_t f = 0; f < nf; ++f)
    for(int i = 0; i < 3; ++i)
    {
      std::size_t a = s.triangles[f][std::size_t(i)], b = s.triangles[f][std::size_t((i + 1) % 3)];
      if(a > b) std::swap(a, b);
      edge_faces[std::make_pair(a, b)].push_back(f);
      vertex_faces[s.triangles[f][std::size_t(i)]].push_back(f);
    }
  std::vector<std::vector<std::size_t> > fnb(nf);
  for(const auto& ef : edge_faces)
    if(ef.second.size() == 2) { fnb[ef.second[0]].push_back(ef.second[1]); fnb[ef.second[1]].push_back(ef.second[0]); }
  std::vector<char> in(nf, 0);
  for(std::size_t f = 0; f < nf; ++f)
    in[f] = in_vertex[s.triangles[f][0]] && in_vertex[s.triangles[f][1]] && in_vertex[s.triangles[f][2]];
  auto keep_largest = [&](std::vector<char>& set, bool complement) {
    std::vector<char> sel(nf);
    for(std::size_t f = 0; f < nf; ++f) sel[f] = complement ? !set[f] : set[f];
    std::vector<std::ptrdiff_t> lab;
    const std::size_t nc = label_components(fnb, sel, lab);
    if(nc == 0) return;
    std::vector<std::size_t> size(nc, 0);
    for(std::size_t f = 0; f < nf; ++f) if(lab[f] >= 0) ++size[std::size_t(lab[f])];
    const std::ptrdiff_t big = std::ptrdiff_t(std::max_element(size.begin(), size.end()) - size.begin());
    for(std::size_t f = 0; f < nf; ++f)
      if(lab[f] >= 0 && lab[f] != big) set[f] = complement ? 1 : 0;
  };
  for(int round = 0; round < 20; ++round)
  {
    keep_largest(in, false);
    keep_largest(in, true);
    // pinched vertices: more than one border edge pair, i.e. more than two border edges around them
    std::vector<int> border_edges(s.points.size(), 0);
    for(const auto& ef : edge_faces)
    {
      int k = 0;
      for(std::size_t f : ef.second) k += in[f] ? 1 : 0;
      if(k == 1) { ++border_edges[ef.first.first]; ++border_edges[ef.first.second]; }
    }
    bool changed = false;
    for(std::size_t v = 0; v < s.points.size(); ++v)
      if(border_edges[v] > 2)
        for(std::size_t f : vertex_faces[v]) if(!in[f]) { in[f] = 1; changed = true; }
    if(!changed) break;
  }
  std::vector<std::size_t> out;
  for(std::size_t f = 0; f < nf; ++f) if(in[f]) out.push_back(f);
  return out;
}

/// Triangles bridging two border loops facing each other (`l1`, `l2` in
/// border order; the bridge runs along l1 forwards and l2 backwards, which is
/// what consistent orientation requires), advancing on the loop whose next
/// vertex comes first by normalised arc length. Written by hand: CGAL fills a
/// single hole, not the gap between two loops.
inline void zip_loops(const std::vector<Repair_point>& pts, const std::vector<std::size_t>& l1,
                      const std::vector<std::size_t>& l2in, std::vector<Repair_triangle>& out)
{
  // l2 reversed, starting at its vertex nearest to l1[0]
  std::size_t j0 = 0;
  double best = std::numeric_limits<double>::infinity();
  for(std::size_t j = 0; j < l2in.size(); ++j)
  {
    const double d = CGAL::squared_distance(pts[l1[0]], pts[l2in[j]]);
    if(d < best) { best = d; j0 = j; }
  }
  std::vector<std::size_t> l2;
  for(std::size_t j = 0; j < l2in.size(); ++j) l2.push_back(l2in[(j0 + l2in.size() - j) % l2in.size()]);
  auto params = [&pts](const std::vector<std::size_t>& l) {
    std::vector<double> t(l.size() + 1, 0.);
    for(std::size_t i = 0; i < l.size(); ++i)
      t[i + 1] = t[i] + std::sqrt(CGAL::squared_distance(pts[l[i]], pts[l[(i + 1) % l.size()]]));
    for(double& x : t) x /= t.back();
    return t;
  };
  const std::vector<double> t1 = params(l1), t2 = params(l2);
  std::size_t i = 0, j = 0;
  const std::size_t n1 = l1.size(), n2 = l2.size();
  while(i < n1 || j < n2)
  {
    if(j == n2 || (i < n1 && t1[i + 1] <= t2[j + 1]))
    {
      out.push_back(Repair_triangle{{l1[i], l1[(i + 1) % n1], l2[j % n2]}});
      ++i;
    }
    else
    {
      out.push_back(Repair_triangle{{l2[(j + 1) % n2], l2[j], l1[i % n1]}});
      ++j;
    }
  }
}

/// the whole repair on a closed soup (see repair_core()); with `limb_ends`,
/// each part is cut to its limb's end (limb_end_within())
inline Repair_core_result repair_core_once(const Repair_soup& s, const std::vector<std::ptrdiff_t>& partner,
                                           const std::vector<std::size_t>& axis_in, const Repair_settings& rs,
                                           bool limb_ends)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  Repair_core_result result;
  const std::size_t n = s.points.size();
  if(partner.size() != n)
    throw Input_error(Input_problem::invalid_parameter, "part repair: the partner map does not match the mesh");
  const std::vector<std::vector<std::size_t> > nb = soup_neighbours(s);
  const double e = soup_mean_edge_length(s), diag = soup_bbox_diagonal(s.points);
  const std::vector<double> area = soup_vertex_areas(s);
  double total_area = 0.;
  for(double a : area) total_area += a;
  const double tau = (std::max)(rs.threshold * diag, 1.5 * e);

  // 1. The mirror plane: best fit of the IRSA curve (paper Sec. 4.2), or of
  //    the fixed points and pair midpoints of the map when no curve is given.
  std::vector<std::size_t> axis;
  for(std::size_t v : axis_in) if(v < n) axis.push_back(v);
  std::vector<Repair_point> ap;
  for(std::size_t v : axis) ap.push_back(s.points[v]);
  if(ap.size() < 3)
  {
    axis.clear();
    ap.clear();
    for(std::size_t v = 0; v < n; ++v)
      if(partner[v] >= 0 && std::size_t(partner[v]) < n)
      {
        if(std::size_t(partner[v]) == v) axis.push_back(v);
        ap.push_back(CGAL::midpoint(s.points[v], s.points[std::size_t(partner[v])]));
      }
  }
  if(ap.size() < 3) throw Input_error(Input_problem::invalid_parameter, repair_failure("no symmetry axis and no mirror pairs"));
  Repair_vector pn;
  Repair_point pc;
  fit_plane(ap, pn, pc);
  // The curve alone may be nearly a line (a pruned curve along the front of
  // a body), which leaves the plane free to turn about it: the plane is
  // refined with the map's pairs that agree with it (reflected within 3 tau
  // of their partner): normal = main direction of the pair differences,
  // through the centroid of their midpoints; twice, the second time with
  // pairs within tau.
  for(int it = 0; it < 2; ++it)
  {
    Eigen::Matrix3d M = Eigen::Matrix3d::Zero();
    Eigen::Vector3d mid = Eigen::Vector3d::Zero();
    std::size_t used = 0;
    for(std::size_t v = 0; v < n; ++v)
    {
      if(partner[v] < 0 || std::size_t(partner[v]) >= n) continue;
      const Repair_point& q = s.points[std::size_t(partner[v])];
      const Repair_vector d = s.points[v] - q;
      if(d.squared_length() < CGAL::square(2. * e)) continue; // on the axis: no direction
      if(std::sqrt(CGAL::squared_distance(reflect_point(s.points[v], pn, pc), q)) > (it == 0 ? 3. : 1.) * tau) continue;
      const Eigen::Vector3d dv(d.x(), d.y(), d.z());
      M += dv * dv.transpose();
      const Repair_point m = CGAL::midpoint(s.points[v], q);
      mid += Eigen::Vector3d(m.x(), m.y(), m.z());
      ++used;
    }
    if(used < 12) break;
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(M);
    const Eigen::Vector3d nn = es.eigenvectors().col(2);
    Repair_vector n2(nn.x(), nn.y(), nn.z());
    if(n2 * pn < 0.) n2 = -n2;
    mid /= double(used);
    pn = n2;
    pc = Repair_point(mid.x(), mid.y(), mid.z());
  }
  result.plane = {{pn.x(), pn.y(), pn.z(), -(pn * (pc - CGAL::ORIGIN))}};
  // The copies are reflected across this plane, so it must be a mirror of
  // most of the shape: where the map's partner of a vertex is not within
  // 2 tau of its reflection, the two disagree. A curve whose reflection agrees
  // with the plane on less than `minimum_mirror_agreement` of the area detects
  // nothing: on complete FAUST shapes the curves of other symmetries (most
  // found by the later rounds, once the left-right curve has detected
  // nothing) reach 0.13-0.76 and "detected" missing parts in 12 of 19 shapes;
  // where one or two limbs are cut, the curve that detects them reaches
  // 0.84-0.97 on 16 of 19 FAUST shapes (stick figure 0.94-0.97); on the
  // other three (004, 007, 008, posed: a left-right curve with a poor map, or
  // another curve) 0.16-0.75, and their copies were 8-16 % of the diagonal off.
  double agreeing = 0.;
  for(std::size_t v = 0; v < n; ++v)
    if(partner[v] >= 0 && std::size_t(partner[v]) < n &&
       CGAL::squared_distance(reflect_point(s.points[v], pn, pc), s.points[std::size_t(partner[v])]) <= CGAL::square(2. * tau))
      agreeing += area[v];
  if(!(total_area > 0. && agreeing >= rs.minimum_mirror_agreement * total_area)) { result.mesh = s; return result; }
  if(axis.empty()) // geodesic distances to the axis need sources: the vertices nearest the plane
    for(std::size_t v = 0; v < n; ++v)
      if(std::abs((s.points[v] - pc) * pn) <= 0.5 * e) axis.push_back(v);
  if(axis.empty()) throw Input_error(Input_problem::invalid_parameter, repair_failure("the mirror plane misses the mesh"));

  // 2. Detection. A reflection preserves the geodesic distance g to its
  //    axis, so g(v) - g(partner(v)) > tau means the map collapsed v onto a
  //    smaller counterpart (a limb mapped onto the cap of the missing one);
  //    a vertex without partner is also orphan. So is a vertex whose partner
  //    lies nearer to it than 2 g(v) - tau: every path from a point to its
  //    mirror image crosses the axis, so the two are 2 g(v) apart. Where a
  //    limb's counterpart is missing, the map may fold the limb's end onto
  //    itself (a capsule's end is symmetric about many planes: stick figure,
  //    leg cut 0.7 from the foot, copy 3.6 % off without this test, 0.5 %
  //    with it); searched within 3 tau of v, as such folds are local. Both
  //    tests are intrinsic, so a posed limb whose counterpart exists is not
  //    taken for a missing one.
  const std::vector<double> g = soup_dijkstra(s, nb, axis);
  std::vector<char> orphan(n, 0);
  std::vector<double> scratch(n, std::numeric_limits<double>::infinity());
  for(std::size_t v = 0; v < n; ++v)
  {
    if(partner[v] < 0 || std::size_t(partner[v]) >= n) { orphan[v] = 1; continue; }
    orphan[v] = g[v] - g[std::size_t(partner[v])] > tau;
    const double fold_radius = (std::min)(2. * g[v] - tau, 3. * tau);
    if(!orphan[v] && fold_radius > 0.)
      orphan[v] = soup_within(s, nb, v, std::size_t(partner[v]), fold_radius, scratch);
  }
  fill_enclosed(nb, area, orphan);
  std::vector<std::ptrdiff_t> label;
  const std::size_t nc = label_components(nb, orphan, label);
  std::vector<double> comp_area(nc, 0.);
  std::vector<std::vector<std::size_t> > comp(nc);
  for(std::size_t v = 0; v < n; ++v)
    if(label[v] >= 0)
    {
      const std::size_t c = std::size_t(label[v]);
      comp[c].push_back(v);
      comp_area[c] += area[v];
    }
  Repair_surface surface = soup_to_surface(s);
  Repair_tree tree(faces(surface).first, faces(surface).second, surface);
  tree.accelerate_distance_queries();
  CGAL::Side_of_triangle_mesh<Repair_surface, Repair_kernel> inside(tree);
  std::vector<std::size_t> parts;
  for(std::size_t c = 0; c < nc; ++c)
  {
    if(comp_area[c] < rs.minimum_part_area * total_area) continue;
    // An orphan part is missing on the other side when its reflection across
    // the mirror plane lands mostly off the surface, outside the shape. This
    // extrinsic check rejects what the map merely fails on (e.g. a head, whose
    // reflection is the head itself); the intrinsic orphan test above rejects
    // limbs that only have another pose on the other side.
    double off = 0.;
    for(std::size_t v : comp[c])
    {
      const Repair_point q = reflect_point(s.points[v], pn, pc);
      if(inside(q) == CGAL::ON_UNBOUNDED_SIDE && std::sqrt(tree.squared_distance(q)) > tau) off += area[v];
    }
    // ... and when it lies on one side of the plane, away from it (a region
    // straddling the plane, like a turned head, is not a missing limb): at
    // most 5 % of its area on the other side of the plane than its centroid,
    // and the centroid farther than tau. (A spread test is not used: a leg's
    // thickness is comparable to its distance to the plane.)
    double sw = 0., s1 = 0.;
    for(std::size_t v : comp[c])
    {
      sw += area[v];
      s1 += area[v] * ((s.points[v] - pc) * pn);
    }
    const double mean_d = s1 / sw;
    double across = 0.;
    for(std::size_t v : comp[c])
      if(((s.points[v] - pc) * pn) * mean_d < 0.) across += area[v];
    const bool one_sided = across <= 0.05 * sw && std::abs(mean_d) > tau;
    // ... and when it is away from the axis (a limb, not the middle of the
    // shape): at most 5 % of its area within 3 tau of the axis. (Not "no
    // vertex within 3 tau": a leg's orphan region runs up the inner thigh to
    // the crotch, where the axis passes, and was rejected for a sliver.)
    double near_axis = 0.;
    for(std::size_t v : comp[c]) if(g[v] < 3. * tau) near_axis += area[v];
    // ... and when it is the end of a limb: its vertex farthest from the axis
    // lies inside it, not on its border. An orphan patch on the side of a
    // limb, where the limb goes on farther, is not a missing part (stick
    // figure, arm cut 0.9 from the hand, 400 samples: with the plane tilted
    // 6 degrees by the damage, a patch of the stump reflected off the intact
    // arm and was copied onto it).
    double g_inside = 0., g_around = 0.;
    for(std::size_t v : comp[c])
    {
      g_inside = (std::max)(g_inside, g[v]);
      for(std::size_t w : nb[v]) if(label[w] != std::ptrdiff_t(c)) g_around = (std::max)(g_around, g[w]);
    }
    const bool limb_end = g_inside > g_around;
    const bool missing = off >= 0.5 * comp_area[c] && one_sided && near_axis <= 0.05 * comp_area[c] && limb_end;
    if(missing) parts.push_back(c);
  }
  // each part as a disk-like region of triangles
  std::vector<std::vector<std::size_t> > part_faces, part_vertices;
  for(std::size_t c : parts)
  {
    std::vector<char> in_c(n, 0);
    for(std::size_t v : comp[c]) in_c[v] = 1;
    if(limb_ends) in_c = limb_end_within(nb, area, g, in_c);
    std::vector<std::size_t> F = clean_part_region(s, in_c), O;
    std::vector<char> used(n, 0);
    for(std::size_t f : F) for(std::size_t v : s.triangles[f]) used[v] = 1;
    for(std::size_t v = 0; v < n; ++v) if(used[v]) O.push_back(v);
    if(O.empty()) continue;
    part_faces.push_back(F);
    part_vertices.push_back(O);
  }
  std::vector<char> in_part(n, 0);
  for(const auto& O : part_vertices) for(std::size_t v : O) in_part[v] = 1;
  // ICP targets: not the parts, and not where the parts' vertices collapse in
  // the map (the caps): a cap would pull a copy back along its limb's axis
  std::vector<char> hub(n, 0);
  for(const auto& O : part_vertices)
    for(std::size_t v : O)
      if(partner[v] >= 0 && std::size_t(partner[v]) < n)
        for(std::size_t w : nb[std::size_t(partner[v])]) hub[w] = hub[std::size_t(partner[v])] = 1;
  Repair_soup target_soup; // no triangles (no tree to build) when there is no part to place
  target_soup.points = s.points;
  if(!part_faces.empty())
    for(const Repair_triangle& t : s.triangles)
      if(!in_part[t[0]] && !in_part[t[1]] && !in_part[t[2]] && !hub[t[0]] && !hub[t[1]] && !hub[t[2]])
        target_soup.triangles.push_back(t);
  const Icp_target target(target_soup);

  // 3-5 with, for every part, fit number `attempt` (0, 1: the two starts
  // on the far band; 2, 3: on the near band; for a slender part the wide
  // band comes first: 0-5), tried in turn until the copies can be stitched
  // cleanly
  const Repair_core_result detected = result;
  // the fits of each part do not depend on the attempt: computed once
  // two bands, two starts each; a slender part: three bands, the wide one first
  const std::size_t number_of_fits = 6, wide_fits = 2;
  std::vector<char> slender(part_faces.size(), 0); // set with the part's fits
  std::vector<std::vector<std::pair<double, Eigen::Matrix4d> > > part_fits(part_faces.size());
  const std::size_t skip = std::size_t(-1); // attempt[k] == skip: part k is not placed
  auto build = [&](const std::vector<std::size_t>& attempt) -> Repair_core_result {
  Repair_core_result result = detected;
  // 3. Placement and overlap removal, per part.
  std::vector<char> removed(n, 0), removed_face(s.triangles.size(), 0);
  Repair_soup combined;
  combined.points = s.points;
  struct Placed { std::vector<std::size_t> zone; std::size_t first_new = 0, end_new = 0; };
  std::vector<Placed> placed;
  for(std::size_t k = 0; k < part_faces.size(); ++k)
  {
    if(attempt[k] == skip) continue;
    const std::vector<std::size_t>& O = part_vertices[k];
    Repair_soup part;
    part.points = s.points;
    for(std::size_t f : part_faces[k]) part.triangles.push_back(s.triangles[f]);
    std::vector<std::vector<std::size_t> > loops;
    if(!border_loops(part, loops) || loops.size() != 1)
      throw Input_error(Input_problem::invalid_parameter,
                        repair_failure("the base of a part to mirror is not one simple loop"), O.front());
    const std::vector<std::size_t>& base = loops.front();

    // ICP between the reflected collar (a band outside the part's base) and
    // the other side's surface
    std::vector<std::pair<double, Eigen::Matrix4d> >& fits = part_fits[k];
    auto fit_band = [&](const std::vector<double>& dO, double lo, double hi) {
      const std::size_t f0 = fits.size();
      std::vector<Repair_point> collar;
      std::vector<std::size_t> collar_vertices;
      for(std::size_t v = 0; v < n; ++v)
        if(!in_part[v] && dO[v] >= lo * tau && dO[v] <= hi * tau) collar_vertices.push_back(v);
      for(std::size_t v : collar_vertices) collar.push_back(reflect_point(s.points[v], pn, pc));
      // initial position: the rigid motion taking the reflected collar onto the
      // mirror partners of its vertices (the correspondence of the paper's
      // Fig. 13c); the reflection alone is far off when the two sides are posed
      // differently. Then ICP.
      Eigen::Matrix4d T0 = Eigen::Matrix4d::Identity();
      {
        std::vector<std::size_t> with;
        for(std::size_t i = 0; i < collar_vertices.size(); ++i)
        {
          const std::ptrdiff_t q = partner[collar_vertices[i]];
          if(q >= 0 && std::size_t(q) < n && !in_part[std::size_t(q)]) with.push_back(i);
        }
        if(with.size() >= 6)
        {
          Eigen::Matrix3Xd A(3, Eigen::Index(with.size())), B(3, Eigen::Index(with.size()));
          for(std::size_t j = 0; j < with.size(); ++j)
          {
            const Repair_point& a = collar[with[j]];
            const Repair_point& b = s.points[std::size_t(partner[collar_vertices[with[j]]])];
            A.col(Eigen::Index(j)) = Eigen::Vector3d(a.x(), a.y(), a.z());
            B.col(Eigen::Index(j)) = Eigen::Vector3d(b.x(), b.y(), b.z());
          }
          T0 = Eigen::umeyama(A, B, false);
        }
      }
      // both starts (reflection alone, and partners), each refined by ICP
      for(const Eigen::Matrix4d& start : {Eigen::Matrix4d(Eigen::Matrix4d::Identity()), T0})
      {
        std::vector<Repair_point> collar0;
        for(const Repair_point& p : collar) collar0.push_back(apply(start, p));
        double r = 0., r0 = 0.;
        const Eigen::Matrix4d Ti = rigid_icp(collar0, target, 2. * tau, rs.icp_iterations, r, r0) * start;
        // ICP slides along limbs (a tube fits itself shifted): keep the start
        // unless ICP improves the fit clearly
        if(r0 <= 1.25 * r) fits.push_back(std::make_pair(r0, start));
        else fits.push_back(std::make_pair(r, Ti));
      }
      // the plain reflection is the paper's start: kept unless the partners'
      // start fits more than twice as well
      if(fits[f0 + 1].first < 0.5 * fits[f0].first) std::swap(fits[f0], fits[f0 + 1]);
    };
    // First the band from 1.5 to 4 tau inside the base: the base is where the
    // map starts collapsing the part onto the cap, so nearer the base the
    // reflection lands on the cut, where the other side has nothing (or a
    // cap) to fit, and the wider band locks sliding and turning (stick
    // figure: 0.39 % instead of 2.59 %). Then, if no copy placed so can be
    // attached, the band from the base to 3 tau: on posed limbs (FAUST) the
    // far band fits the upper limb and leaves the copy off the stump.
    // Not wider bands: on posed limbs a band's fit turns with its width
    // (FAUST, repair_benchmark, shapes within 2 % with one limb / two limbs
    // / both: 8 / 5 / 4 with these fits; 10 / 5 / 5, 10 / 7 / 7, 9 / 5 / 5
    // and 8 / 4 / 4 with the band from the base to 5, 6, 7 or 8 tau tried
    // first; 9 / 7 / 6 with the mean placement of the 5, 6 and 7 tau fits),
    // but the mean takes the stick figure with imperfect symmetry
    // (test_repair) from within 2 % to 2.57 % (2.30 % with the far band's
    // fit in the mean). Nor the medoid of the fits: 4 / 3 / 1 on FAUST. The
    // residuals do not tell which fit is the most accurate (the far band's is
    // the smallest on nearly every FAUST part), nor does the disagreement
    // between the mean and the chosen fit (0.27-0.66 tau where the mean
    // helps on FAUST, 0.55 tau on that stick figure).
    // A slender part (longer than `slender_part` times its base radius:
    // FAUST's forearms and lower legs, 8-10; the stick figure's limbs,
    // 2-3) first gets a wide collar, from the base to `wide_collar` tau:
    // a turn of the copy moves its tip by the turn times its length, and
    // the wide collar's lever arm holds the turn (FAUST, repair_benchmark,
    // within 2 % with one limb / two limbs / both: 8 / 5 / 4 without it,
    // 9 / 5 / 5 with it; the stick figures' rows unchanged). Its fit is
    // preferred when it can be attached. The width matters: 5, 6, 7 tau
    // give 5 / 2 / 2, 10 / 7 / 7 and 9 / 5 / 5 on FAUST, but with 6 or 7
    // tau for every part the stick figure with imperfect symmetry (400
    // samples, test_repair) goes from within 2 % to 2.14 %; 7 is kept as
    // the width nearer the stick figure's own collars.
    if(fits.empty())
    {
      const std::vector<double> dO = soup_dijkstra(s, nb, base);
      double length = 0., radius = 0.;
      for(std::size_t v : O) length = (std::max)(length, dO[v]);
      std::vector<Repair_point> base_points;
      for(std::size_t v : base) base_points.push_back(s.points[v]);
      Repair_vector bn;
      Repair_point bc;
      fit_plane(base_points, bn, bc);
      for(const Repair_point& p : base_points) radius += std::sqrt(CGAL::squared_distance(p, bc));
      radius /= double(base_points.size());
      slender[k] = length > rs.slender_part * radius;
      if(slender[k]) fit_band(dO, 0., rs.wide_collar);
      fit_band(dO, 1.5, 4.);
      fit_band(dO, 0., 3.);
    }
    // a part with fewer fits takes its last one for the later attempts
    const std::size_t fit = (std::min)(attempt[k], fits.size() - 1);
    const double rms = fits[fit].first;
    const Eigen::Matrix4d T = fits[fit].second;
    result.icp_rms.push_back(rms);
    auto place = [&](std::size_t v) { return apply(T, reflect_point(s.points[v], pn, pc)); };

    // the zone the copy replaces: on the other side, beyond (a gap before)
    // the copy's base ring and within its radius, around the ring's centre
    std::vector<Repair_point> ring;
    for(std::size_t v : base) ring.push_back(place(v));
    Repair_vector rn;
    Repair_point rc;
    fit_plane(ring, rn, rc);
    Repair_vector to_part = CGAL::NULL_VECTOR;
    for(std::size_t v : O) to_part = to_part + (place(v) - rc);
    if(to_part * rn < 0.) rn = -rn;
    double rad = 0.;
    for(const Repair_point& p : ring)
    {
      const Repair_vector d = p - rc;
      rad = (std::max)(rad, std::sqrt((d - (d * rn) * rn).squared_length()));
    }
    // The zone starts a gap before the ring. Where the copy's base lies
    // beyond the end of the stump (its base on the intact side need not
    // mirror the cut), nothing is there: the gap grows until the zone reaches
    // the stump, and the seam bridges it. Each vertex's position along the
    // ring's axis and whether it lies within the cylinder around that axis
    // (not in a part, not already replaced) do not depend on the gap.
    std::vector<double> along(n, 0.), to_centre(n, 0.);
    std::vector<char> in_cylinder(n, 0);
    for(std::size_t v = 0; v < n; ++v)
    {
      if(in_part[v] || removed[v]) continue;
      const Repair_vector d = s.points[v] - rc;
      along[v] = d * rn;
      to_centre[v] = d.squared_length();
      in_cylinder[v] = std::sqrt((d - along[v] * rn).squared_length()) < 1.5 * rad;
    }
    const double first_gap = 0.5 * rad + 2. * e;
    Placed pl;
    for(double gap = first_gap; pl.zone.empty() && gap <= first_gap + 2. * rad; gap += 0.5 * rad)
    {
      std::vector<char> cand(n, 0);
      std::size_t seed = n;
      double seed_d = std::numeric_limits<double>::infinity();
      for(std::size_t v = 0; v < n; ++v)
        if(in_cylinder[v] && along[v] > -gap)
        {
          cand[v] = 1;
          if(to_centre[v] < seed_d) { seed_d = to_centre[v]; seed = v; }
        }
      if(seed == n) continue;
      std::vector<std::ptrdiff_t> cl;
      label_components(nb, cand, cl);
      std::vector<char> zone(n, 0);
      for(std::size_t v = 0; v < n; ++v) zone[v] = (cl[v] == cl[seed]);
      fill_enclosed(nb, area, zone);
      // the faces removed: a disk-like region, so that its border is one simple loop
      for(std::size_t f : clean_part_region(s, zone))
      {
        if(removed_face[f]) continue;
        for(std::size_t v : s.triangles[f])
        {
          if(in_part[v])
            throw Input_error(Input_problem::invalid_parameter,
                              repair_failure("the mirrored part overlaps the part it copies"), v);
          pl.zone.push_back(v);
          removed[v] = 1;
        }
        removed_face[f] = 1;
      }
    }
    if(pl.zone.empty())
      throw Input_error(Input_problem::invalid_parameter,
                        repair_failure("the mirrored part does not meet the surface (no place to attach it)"), O.front());
    // the copy: reflected, so its triangles are reversed
    pl.first_new = combined.points.size();
    std::vector<std::size_t> id(n, std::size_t(-1));
    for(std::size_t v : O) { id[v] = combined.points.size(); combined.points.push_back(place(v)); }
    pl.end_new = combined.points.size();
    for(const Repair_triangle& t : part.triangles)
      combined.triangles.push_back(Repair_triangle{{id[t[0]], id[t[2]], id[t[1]]}});
    placed.push_back(pl);
    result.part_sizes.push_back(O.size());
  }
  if(placed.empty()) { result.mesh = s; return result; }
  const std::size_t copy_faces = combined.triangles.size();
  for(std::size_t f = 0; f < s.triangles.size(); ++f)
    if(!removed_face[f]) combined.triangles.push_back(s.triangles[f]);

  // 4. Stitching: each placed copy's base loop to the loop its zone left.
  std::vector<std::vector<std::size_t> > loops;
  if(!border_loops(combined, loops) || loops.size() != 2 * placed.size())
    throw Input_error(Input_problem::invalid_parameter,
                      repair_failure("the cut around an attachment zone is not one simple loop"));
  const std::size_t first_bridge = combined.triangles.size();
  std::vector<std::size_t> seam;
  for(const Placed& pl : placed)
  {
    std::vector<char> near_zone(combined.points.size(), 0);
    for(std::size_t v : pl.zone) near_zone[v] = 1;
    const std::vector<std::size_t>* l1 = nullptr;
    const std::vector<std::size_t>* l2 = nullptr;
    for(const auto& l : loops)
    {
      if(l.front() >= pl.first_new && l.front() < pl.end_new) l2 = &l;
      else if(l.front() < n && near_zone[l.front()]) l1 = &l;
    }
    if(!l1 || !l2)
      throw Input_error(Input_problem::invalid_parameter, repair_failure("could not pair the loops to stitch"));
    zip_loops(combined.points, *l1, *l2, combined.triangles);
    seam.insert(seam.end(), l1->begin(), l1->end());
    seam.insert(seam.end(), l2->begin(), l2->end());
  }
  Repair_soup compacted;
  std::vector<std::ptrdiff_t> old_to_new;
  compacted = compact_soup(combined, &old_to_new);
  if(!PMP::is_polygon_soup_a_polygon_mesh(compacted.triangles))
    throw Input_error(Input_problem::invalid_parameter, repair_failure("the stitched surface is not a 2-manifold"));

  // 5. Seam: refine the bridge triangles and fair them with a ring on each side
  //    (CGAL's fairing: the harmonic-type interpolation the paper does with Poisson)
  // Variants, the first one without defect is kept: refined and faired with
  // the two loops; faired inside the strip only (the loops stay); the plain
  // strip. A faired strip can fold where the loops are close and skewed.
  Repair_surface m;
  std::string defect;
  const std::size_t kept_end = first_bridge;
  std::vector<Repair_point> input_points(s.points);
  std::sort(input_points.begin(), input_points.end());
  for(int variant = 0; variant < 3; ++variant)
  {
    m = soup_to_surface(compacted);
    bool faired = false;
    if(variant < 2)
    {
      std::vector<Repair_surface::Face_index> bridge;
      for(std::size_t f = first_bridge; f < compacted.triangles.size(); ++f)
        bridge.push_back(Repair_surface::Face_index(static_cast<Repair_surface::size_type>(f)));
      std::vector<Repair_surface::Face_index> new_faces;
      std::vector<Repair_surface::Vertex_index> fair_set;
      PMP::refine(m, bridge, std::back_inserter(new_faces), std::back_inserter(fair_set));
      std::vector<char> in_fair(num_vertices(m), 0);
      for(auto v : fair_set) in_fair[std::size_t(v)] = 1;
      if(variant == 0)
        for(std::size_t v : seam)
        {
          const std::ptrdiff_t w = old_to_new[v];
          if(w >= 0 && !in_fair[std::size_t(w)]) { in_fair[std::size_t(w)] = 1; fair_set.push_back(Repair_surface::Vertex_index(static_cast<Repair_surface::size_type>(w))); }
        }
      faired = fair_set.empty() || PMP::fair(m, fair_set);
    }
    result.faired.assign(placed.size(), faired);
    defect = mesh_defect(m);
    const auto is_new = [copy_faces, kept_end](Repair_surface::Face_index f) {
      return std::size_t(f) < copy_faces || std::size_t(f) >= kept_end; };
    if(defect.empty() && self_intersects_new(m, is_new))
    {
      // A rigid copy also copies the input's own self-intersections (FAUST:
      // toes touching): the new faces that intersect are repaired locally by
      // PMP (removed, the hole refilled), then the whole is checked again; a
      // new face is now one with a corner that is not a point of the input.
      std::vector<std::pair<Repair_surface::Face_index, Repair_surface::Face_index> > pairs;
      PMP::self_intersections(m, std::back_inserter(pairs));
      std::vector<Repair_surface::Face_index> bad;
      for(const auto& p : pairs)
        if(is_new(p.first) || is_new(p.second)) { bad.push_back(p.first); bad.push_back(p.second); }
      std::sort(bad.begin(), bad.end());
      bad.erase(std::unique(bad.begin(), bad.end()), bad.end());
      PMP::experimental::remove_self_intersections(bad, m);
      m.collect_garbage();
      defect = mesh_defect(m);
      if(defect.empty() && self_intersects_new(m, [&m, &input_points](Repair_surface::Face_index f) {
           for(auto v : vertices_around_face(halfedge(f, m), m))
             if(!std::binary_search(input_points.begin(), input_points.end(), m.point(v))) return true;
           return false; }))
        defect = "self-intersecting (a copied or stitched face crosses the surface)";
    }
    if(defect.empty()) break;
  }
  if(!defect.empty())
    throw Input_error(Input_problem::invalid_parameter, repair_failure("the repaired surface would be " + defect));
  Repair_soup r;
  r.points.assign(m.points().begin(), m.points().end());
  for(auto f : faces(m))
  {
    Repair_triangle t;
    int i = 0;
    for(auto v : vertices_around_face(halfedge(f, m), m)) t[std::size_t(i++)] = std::size_t(v);
    r.triangles.push_back(t);
  }
  result.mesh = std::move(r);
  return result;
  };
  // Each part gets its own fit: of those with which it can be attached alone,
  // the one with the smallest ICP residual (a slender part: its wide
  // collar's, if attached). The parts are separate limbs, so
  // one part that cannot be attached with a fit must not force a worse fit on
  // the others.
  const std::size_t np = part_faces.size();
  if(np == 0) return build(std::vector<std::size_t>());
  std::vector<std::size_t> chosen(np, 0); // skip: rejected for its collar fit
  bool each = true;
  for(std::size_t k = 0; k < np; ++k)
  {
    bool ok = false;
    double best = std::numeric_limits<double>::infinity();
    for(std::size_t a = 0; a < number_of_fits; ++a)
    {
      if(!part_fits[k].empty() && a >= part_fits[k].size()) break; // no such fit for this part
      std::vector<std::size_t> one(np, skip);
      one[k] = a;
      try
      {
        build(one); // the result is not kept: the choice needs every fit tried
        const double r = part_fits[k][a].first;
        // a slender part keeps its wide collar's fit once attached
        const bool keep = slender[k] && ok && chosen[k] < wide_fits;
        if(!ok || (r < best && !keep)) chosen[k] = a;
        best = (std::min)(best, r);
        ok = true;
      }
      catch(const Input_error&) // this fit cannot be attached
      {
      }
    }
    // A missing limb leaves its surroundings intact, so the reflected collar
    // fits the other side closely (part_repair.h: 0.002-0.094 tau); a part
    // whose best fit is worse than `maximum_collar_rms` tau is a failure of
    // the map (CGAL's bear.off: 0.171 tau) and is not copied, whatever fits
    // the other parts get below.
    if(ok && !(best <= rs.maximum_collar_rms * tau)) chosen[k] = skip;
    each = each && ok;
  }
  auto same_fit = [&](std::size_t a) {
    std::vector<std::size_t> attempt(np, a);
    for(std::size_t k = 0; k < np; ++k)
      if(chosen[k] == skip) attempt[k] = skip;
    return attempt;
  };
  if(each)
  {
    try
    {
      return build(chosen);
    }
    catch(const Input_error&) // the copies, each fine alone, clash: as before
    {
    }
  }
  // else the same fit for all the parts, in turn, up to the most fits a part
  // has (beyond its own, a part keeps its last fit: no attempt repeated)
  std::size_t attempts = 1;
  for(const auto& fits : part_fits) attempts = (std::max)(attempts, fits.size());
  for(std::size_t attempt = 0; attempt + 1 < attempts; ++attempt)
  {
    try
    {
      return build(same_fit(attempt));
    }
    catch(const Input_error&)
    {
    }
  }
  return build(same_fit(attempts - 1)); // if this fails too, its error is the one reported
}

/// the whole repair on a closed soup; `partner[v]` = mirror vertex or -1;
/// `axis` = the IRSA curve's vertices. A part's orphan region may run up the
/// side of its limb (the inner thigh up to the crotch); its base is then no
/// ring across the limb, and the zone its copy replaces can reach the part
/// itself (stick figure, leg cut 0.9 from the foot, 1000 samples: "the
/// mirrored part overlaps the part it copies"). When the repair fails, it is
/// tried once more with every part cut to its limb's end; if that fails too,
/// the first error is reported. Not always: the cut parts make other copies
/// worse (stick figure, leg cut 0.4 and 0.6 from the foot: 1.30 and 0.92 %
/// of the diagonal off become 2.43 and 2.36 %).
inline Repair_core_result repair_core(const Repair_soup& s, const std::vector<std::ptrdiff_t>& partner,
                                      const std::vector<std::size_t>& axis, const Repair_settings& rs)
{
  try
  {
    return repair_core_once(s, partner, axis, rs, false);
  }
  catch(const Input_error& first)
  {
    try
    {
      return repair_core_once(s, partner, axis, rs, true);
    }
    catch(const Input_error&)
    {
      throw first;
    }
  }
}

} // namespace internal
} // namespace Intrinsic_reflectional_symmetry_3
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_INTERNAL_REPAIR_CORE_H
