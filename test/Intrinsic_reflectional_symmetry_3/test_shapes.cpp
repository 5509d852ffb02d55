// Generated test shapes: closed, 2-manifold, connected, no self-intersection,
// near-regular triangles, and mirror maps that are involutions agreeing with
// the Euclidean reflections (extrinsic symmetries) or with the intrinsic
// metric (the bent capsule). Run on Surface_mesh and Polyhedron_3.

#include <CGAL/Intrinsic_reflectional_symmetry_3/shape_generators.h>

#include "irsym_output.h" // the command-line tool's pictures

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/repair.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <iostream>
#include <iterator>
#include <limits>
#include <numeric>
#include <queue>
#include <string>
#include <vector>

namespace IRS = CGAL::Intrinsic_reflectional_symmetry_3;
namespace PMP = CGAL::Polygon_mesh_processing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;

namespace {

template <typename Mesh>
std::vector<Point> vertex_points(const Mesh& m)
{
  std::vector<Point> pts(num_vertices(m));
  auto vim = CGAL::get_initialized_vertex_index_map(m);
  for(auto v : vertices(m)) pts[get(vim, v)] = get(CGAL::vertex_point, m, v);
  return pts;
}

Point reflect(const Point& p, const std::array<double, 4>& pl)
{
  const double d = pl[0] * p.x() + pl[1] * p.y() + pl[2] * p.z() + pl[3];
  return Point(p.x() - 2 * d * pl[0], p.y() - 2 * d * pl[1], p.z() - 2 * d * pl[2]);
}

/// edge-graph shortest paths, written out so as not to depend on the package's oracles
template <typename Mesh>
std::vector<double> dijkstra(const Mesh& m, std::size_t from)
{
  auto vim = CGAL::get_initialized_vertex_index_map(m);
  const std::vector<Point> pts = vertex_points(m);
  std::vector<std::vector<std::size_t> > adj(pts.size());
  for(auto e : edges(m)) {
    const std::size_t a = get(vim, source(e, m)), b = get(vim, target(e, m));
    adj[a].push_back(b);
    adj[b].push_back(a);
  }
  std::vector<double> d(pts.size(), std::numeric_limits<double>::infinity());
  typedef std::pair<double, std::size_t> Item;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item> > queue;
  d[from] = 0.;
  queue.push(Item(0., from));
  while(!queue.empty()) {
    const Item it = queue.top();
    queue.pop();
    if(it.first > d[it.second]) continue;
    for(std::size_t w : adj[it.second]) {
      const double nd = it.first + std::sqrt(CGAL::squared_distance(pts[it.second], pts[w]));
      if(nd < d[w]) { d[w] = nd; queue.push(Item(nd, w)); }
    }
  }
  return d;
}

/// largest distance from a reflected vertex to its nearest mesh vertex:
/// about 0 for a mirror plane of the shape
double plane_symmetry_error(const std::vector<Point>& pts, const std::array<double, 4>& pl)
{
  typedef CGAL::Search_traits_3<K> Traits;
  typedef CGAL::Orthogonal_k_neighbor_search<Traits> Search;
  Search::Tree tree(pts.begin(), pts.end());
  double worst = 0.;
  for(const Point& p : pts) {
    Search search(tree, reflect(p, pl), 1);
    worst = (std::max)(worst, search.begin()->second);
  }
  return std::sqrt(worst);
}

/// the plane a x + b y + c z + d = 0 whose reflection best maps p_v to p_mirror(v):
/// normal along the dominant direction of the displacements, through their midpoints
std::array<double, 4> best_plane_for_map(const std::vector<Point>& pts, const std::vector<std::ptrdiff_t>& mirror)
{
  Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
  for(std::size_t v = 0; v < pts.size(); ++v) {
    if(mirror[v] < 0) continue;
    const K::Vector_3 d = pts[std::size_t(mirror[v])] - pts[v];
    const Eigen::Vector3d e(d.x(), d.y(), d.z());
    C += e * e.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(C);
  const Eigen::Vector3d n = es.eigenvectors().col(2);
  double off = 0.;
  std::size_t count = 0;
  for(std::size_t v = 0; v < pts.size(); ++v) {
    if(mirror[v] < 0) continue;
    const Point mid = CGAL::midpoint(pts[v], pts[std::size_t(mirror[v])]);
    off += n[0] * mid.x() + n[1] * mid.y() + n[2] * mid.z();
    ++count;
  }
  return {{n[0], n[1], n[2], -off / double(count)}};
}

template <typename Mesh>
struct Angle_stats
{
  double min = 180., max = 0., share_in_30_100 = 0.;
};

template <typename Mesh>
Angle_stats<Mesh> angle_stats(const Mesh& m)
{
  Angle_stats<Mesh> s;
  std::size_t good = 0, n = 0;
  for(auto f : faces(m)) {
    Point p[3];
    int i = 0;
    for(auto v : vertices_around_face(halfedge(f, m), m)) p[i++] = get(CGAL::vertex_point, m, v);
    bool ok = true;
    for(int k = 0; k < 3; ++k) {
      const double a = CGAL::approximate_angle(p[(k + 1) % 3], p[k], p[(k + 2) % 3]);
      s.min = (std::min)(s.min, a);
      s.max = (std::max)(s.max, a);
      if(a < 30. || a > 100.) ok = false;
    }
    good += ok ? 1 : 0;
    ++n;
  }
  s.share_in_30_100 = double(good) / double(n);
  return s;
}

/// the checks every generated shape must pass
template <typename Mesh>
void check_shape(const IRS::Generated_shape<Mesh>& g, const std::string& name, std::size_t target,
                 bool exact_maps)
{
  SCOPED_TRACE(name);
  const Mesh& m = g.mesh;
  const std::size_t n = num_vertices(m);
  EXPECT_GT(n, target * 6 / 10);
  EXPECT_LT(n, target * 16 / 10);
  ASSERT_TRUE(CGAL::is_triangle_mesh(m));
  ASSERT_TRUE(CGAL::is_valid_polygon_mesh(m));
  EXPECT_TRUE(CGAL::is_closed(m));
  std::vector<typename boost::graph_traits<Mesh>::halfedge_descriptor> pinched;
  PMP::non_manifold_vertices(m, std::back_inserter(pinched));
  EXPECT_TRUE(pinched.empty());
  auto fcc = get(CGAL::dynamic_face_property_t<std::size_t>(), m);
  EXPECT_EQ(PMP::connected_components(m, fcc), 1u);
  EXPECT_FALSE(PMP::does_self_intersect(m));
  EXPECT_TRUE(PMP::is_outward_oriented(m)); // SDF rays go inwards

  const Angle_stats<Mesh> a = angle_stats(m);
  std::cout << "[shape] " << name << ": " << n << " vertices, mean edge " << g.mean_edge_length
            << ", angles in [" << a.min << ", " << a.max << "] deg, "
            << 100. * a.share_in_30_100 << " % of triangles within [30, 100]" << std::endl;
  EXPECT_GT(a.min, 20.);
  EXPECT_LT(a.max, 125.);
  EXPECT_GT(a.share_in_30_100, 0.99);

  const std::vector<Point> pts = vertex_points(m);
  for(const IRS::Known_symmetry& s : g.symmetries) {
    SCOPED_TRACE(s.name);
    ASSERT_EQ(s.mirror.size(), n);
    std::size_t defined = 0, fixed = 0;
    double worst = 0.;
    for(std::size_t v = 0; v < n; ++v) {
      const std::ptrdiff_t w = s.mirror[v];
      if(w < 0) { ASSERT_EQ(w, -1); continue; }
      ASSERT_LT(std::size_t(w), n);
      ASSERT_EQ(s.mirror[std::size_t(w)], std::ptrdiff_t(v)) << "not an involution at " << v;
      ++defined;
      if(w == std::ptrdiff_t(v)) ++fixed;
      if(s.extrinsic)
        worst = (std::max)(worst, std::sqrt(CGAL::squared_distance(reflect(pts[v], s.plane), pts[std::size_t(w)])));
    }
    EXPECT_GT(defined, n / 10);
    ASSERT_FALSE(s.axis.empty());
    EXPECT_TRUE(std::is_sorted(s.axis.begin(), s.axis.end()));
    for(std::size_t v : s.axis) {
      ASSERT_LT(v, n);
      EXPECT_GE(s.mirror[v], 0);
      if(s.extrinsic) {
        const double d = std::abs(s.plane[0] * pts[v].x() + s.plane[1] * pts[v].y() + s.plane[2] * pts[v].z() + s.plane[3]);
        EXPECT_LE(d, 0.5 * g.mean_edge_length + 1e-12);
      }
    }
    if(s.extrinsic) {
      EXPECT_NEAR(s.plane[0] * s.plane[0] + s.plane[1] * s.plane[1] + s.plane[2] * s.plane[2], 1., 1e-12);
      EXPECT_LE(worst, g.mean_edge_length);
      if(exact_maps) {
        EXPECT_LE(worst, 1e-9);
      }
      // exact maps fix exactly the vertices lying on the plane
      for(std::size_t v = 0; v < n && exact_maps; ++v) {
        if(s.mirror[v] < 0) continue;
        const double d = s.plane[0] * pts[v].x() + s.plane[1] * pts[v].y() + s.plane[2] * pts[v].z() + s.plane[3];
        EXPECT_EQ(std::abs(d) < 1e-12, s.mirror[v] == std::ptrdiff_t(v)) << v;
      }
    }
    if(exact_maps) {
      EXPECT_GT(fixed, 0u);
    }
    std::cout << "[shape]   " << s.name << ": defined on " << defined << " vertices, " << fixed
              << " fixed, axis " << s.axis.size() << " vertices, max |reflection - mirror| "
              << worst << std::endl;
  }
}

std::vector<std::string> names(const std::vector<IRS::Known_symmetry>& s)
{
  std::vector<std::string> out;
  for(const auto& k : s) out.push_back(k.name);
  return out;
}

template <typename Mesh>
class Shapes : public ::testing::Test {};

typedef ::testing::Types<CGAL::Surface_mesh<Point>, CGAL::Polyhedron_3<K> > Mesh_types;
TYPED_TEST_SUITE(Shapes, Mesh_types);

} // namespace

TYPED_TEST(Shapes, Sphere)
{
  const auto g = IRS::generate_sphere<TypeParam>(1500, 2.);
  check_shape(g, "sphere", 1500, true);
  EXPECT_EQ(names(g.symmetries), (std::vector<std::string>{"x=0 plane", "y=0 plane", "z=0 plane"}));
  for(const Point& p : vertex_points(g.mesh)) EXPECT_NEAR(std::sqrt((p - CGAL::ORIGIN).squared_length()), 2., 1e-12);
}

TYPED_TEST(Shapes, Ellipsoid)
{
  const auto g = IRS::generate_ellipsoid<TypeParam>(1500);
  check_shape(g, "ellipsoid", 1500, true);
  ASSERT_EQ(g.symmetries.size(), 3u);
  for(const Point& p : vertex_points(g.mesh))
    EXPECT_NEAR(p.x() * p.x() / 2.25 + p.y() * p.y() + p.z() * p.z() / 0.49, 1., 1e-9);
}

TYPED_TEST(Shapes, Capsule)
{
  const auto g = IRS::generate_capsule<TypeParam>(1500);
  check_shape(g, "capsule", 1500, true);
  ASSERT_EQ(g.symmetries.size(), 3u);
}

TYPED_TEST(Shapes, Torus)
{
  const auto g = IRS::generate_torus<TypeParam>(1500);
  check_shape(g, "torus", 1500, true);
  ASSERT_EQ(g.symmetries.size(), 3u);
  EXPECT_EQ(long(num_vertices(g.mesh)) - long(num_edges(g.mesh)) + long(num_faces(g.mesh)), 0L);
}

TYPED_TEST(Shapes, Snowman)
{
  const auto g = IRS::generate_snowman<TypeParam>(1500);
  check_shape(g, "snowman", 1500, true);
  EXPECT_EQ(names(g.symmetries), (std::vector<std::string>{"x=0 plane", "y=0 plane"}));
  // a snowman: its horizontal radius has two necks between three bulges
  double zmin = 1e9, zmax = -1e9;
  for(const Point& p : vertex_points(g.mesh)) { zmin = (std::min)(zmin, p.z()); zmax = (std::max)(zmax, p.z()); }
  EXPECT_NEAR(zmin, 0., 0.05);
  EXPECT_NEAR(zmax, 3.7, 0.05);
}

TYPED_TEST(Shapes, TwoSnowmen)
{
  const auto g = IRS::generate_two_snowmen<TypeParam>(2500);
  check_shape(g, "two snowmen", 2500, false);
  ASSERT_EQ(names(g.symmetries),
            (std::vector<std::string>{"left snowman", "right snowman", "y=0 plane (front-back)"}));
  const std::vector<Point> pts = vertex_points(g.mesh);
  const std::size_t n = pts.size();
  // partial maps: defined only on their own snowman, on most of it, not near the tube
  const double axis_x[2] = {-1.6, 1.3}, body_radius[2] = {1.0, 0.7}, junction_x[2] = {-1.6 + 0.95, 1.3 - 0.7};
  for(int k = 0; k < 2; ++k) {
    const IRS::Known_symmetry& s = g.symmetries[std::size_t(k)];
    EXPECT_TRUE(s.extrinsic);
    std::size_t on_snowman = 0, defined = 0;
    for(std::size_t v = 0; v < n; ++v) {
      const bool mine = std::abs(pts[v].x() - axis_x[k]) <= body_radius[k] + 1e-3 &&
                        std::hypot(pts[v].x() - junction_x[k], pts[v].z() - 0.7) > 0.5; // away from the tube
      on_snowman += mine ? 1 : 0;
      if(s.mirror[v] >= 0) {
        ++defined;
        EXPECT_LE(std::abs(pts[v].x() - axis_x[k]), body_radius[k] + 1e-3);
      }
    }
    // undefined at the junction and at its mirror image
    for(std::size_t v = 0; v < n; ++v) {
      if(std::hypot(std::abs(pts[v].x() - axis_x[k]) - std::abs(junction_x[k] - axis_x[k]), pts[v].z() - 0.7) < 0.15 &&
         std::abs(pts[v].y()) < 0.15) {
        EXPECT_EQ(s.mirror[v], -1) << s.name << " vertex " << v;
      }
    }
    EXPECT_GT(defined, on_snowman * 8 / 10);
    std::cout << "[shape]   " << s.name << ": defined on " << defined << " of about " << on_snowman
              << " snowman vertices away from the tube" << std::endl;
  }
  // no global left-right mirror: reflecting across the middle plane between the axes misses the shape
  const std::array<double, 4> middle = {{1., 0., 0., 0.15}};
  EXPECT_GT(plane_symmetry_error(pts, middle), 2 * g.mean_edge_length);
  EXPECT_LT(plane_symmetry_error(pts, g.symmetries[2].plane), g.mean_edge_length);
  // the front-back plane is global (almost everywhere)
  std::size_t defined = 0;
  for(std::ptrdiff_t w : g.symmetries[2].mirror) defined += w >= 0 ? 1 : 0;
  EXPECT_GT(defined, n * 95 / 100);
}

TYPED_TEST(Shapes, BentCapsule)
{
  const auto g = IRS::generate_bent_capsule<TypeParam>(1500);
  check_shape(g, "bent capsule", 1500, true);
  ASSERT_EQ(names(g.symmetries),
            (std::vector<std::string>{"end-to-end (intrinsic)", "z=0 plane (bending plane)"}));
  const IRS::Known_symmetry& ends = g.symmetries[0];
  EXPECT_FALSE(ends.extrinsic);
  const std::vector<Point> pts = vertex_points(g.mesh);
  const std::size_t n = pts.size();
  for(std::ptrdiff_t w : ends.mirror) ASSERT_GE(w, 0); // global

  // The end-to-end map roughly preserves edge-graph geodesic distances.
  // Tolerance: 15 % of the distance plus one mean edge length for every pair,
  // 5 % on average (the inner and outer sides of the bent half are
  // compressed / stretched by 1 -+ radius * curvature = 1 -+ 0.084).
  std::size_t tip = 0;
  for(std::size_t v = 0; v < n; ++v) if(pts[v].x() < pts[tip].x()) tip = v;
  std::vector<std::size_t> sources = {tip};
  for(std::size_t k = 1; k < 8; ++k) sources.push_back((k * 7919) % n);
  double worst = 0., mean = 0.;
  std::size_t count = 0;
  for(std::size_t a : sources) {
    const std::vector<double> da = dijkstra(g.mesh, a);
    const std::vector<double> db = dijkstra(g.mesh, std::size_t(ends.mirror[a]));
    for(std::size_t v = 0; v < n; v += 7) {
      const double ref = da[v], img = db[std::size_t(ends.mirror[v])];
      const double err = std::abs(ref - img) / (ref + g.mean_edge_length);
      worst = (std::max)(worst, err);
      mean += err;
      ++count;
      EXPECT_LE(std::abs(ref - img), 0.15 * ref + g.mean_edge_length) << a << " -> " << v;
    }
  }
  EXPECT_LT(mean / double(count), 0.05);
  std::cout << "[shape]   end-to-end map: geodesic distance distortion mean " << 100. * mean / double(count)
            << " %, max " << 100. * worst << " % (relative to distance + 1 edge)" << std::endl;

  // ...while no Euclidean mirror maps the ends onto each other:
  const std::size_t other_tip = std::size_t(ends.mirror[tip]);
  EXPECT_GT(std::sqrt(CGAL::squared_distance(pts[tip], pts[other_tip])), 1.);
  // the shape's Euclidean mirror (the bending plane) maps each end to itself,
  const std::array<double, 4> bending = g.symmetries[1].plane;
  EXPECT_LT(plane_symmetry_error(pts, bending), 1e-9);
  EXPECT_LT(std::sqrt(CGAL::squared_distance(reflect(pts[tip], bending), pts[tip])), g.mean_edge_length);
  // the only plane sending one tip onto the other (their bisector) is no symmetry,
  const K::Vector_3 d = pts[other_tip] - pts[tip];
  const double l = std::sqrt(d.squared_length());
  const Point mid = CGAL::midpoint(pts[tip], pts[other_tip]);
  const std::array<double, 4> bisector = {{d.x() / l, d.y() / l, d.z() / l,
                                           -(d.x() * mid.x() + d.y() * mid.y() + d.z() * mid.z()) / l}};
  const double bisector_error = plane_symmetry_error(pts, bisector);
  EXPECT_GT(bisector_error, 4 * g.mean_edge_length);
  // and the plane best fitting the end-to-end map leaves large residuals.
  const std::array<double, 4> fit = best_plane_for_map(pts, ends.mirror);
  double rms = 0., worst_residual = 0.;
  for(std::size_t v = 0; v < n; ++v) {
    const double r2 = CGAL::squared_distance(reflect(pts[v], fit), pts[std::size_t(ends.mirror[v])]);
    rms += r2;
    worst_residual = (std::max)(worst_residual, std::sqrt(r2));
  }
  rms = std::sqrt(rms / double(n));
  EXPECT_GT(worst_residual, 4 * g.mean_edge_length);
  std::cout << "[shape]   tip-bisector plane: largest reflected-vertex distance to the mesh " << bisector_error
            << "; best-fit plane of the map: residual RMS " << rms << ", max " << worst_residual
            << " (mean edge " << g.mean_edge_length << ")" << std::endl;

  // for comparison, the straight capsule's end-to-end map is the Euclidean z=0 plane
  const auto straight = IRS::generate_capsule<TypeParam>(1500, 0.2, 5.);
  const std::vector<Point> sp = vertex_points(straight.mesh);
  const std::array<double, 4> sfit = best_plane_for_map(sp, straight.symmetries[2].mirror);
  double srms = 0.;
  for(std::size_t v = 0; v < sp.size(); ++v)
    srms += CGAL::squared_distance(reflect(sp[v], sfit), sp[std::size_t(straight.symmetries[2].mirror[v])]);
  EXPECT_LT(std::sqrt(srms / double(sp.size())), 1e-9);
}

TEST(ShapesAcrossMeshTypes, SameIndicesAndDeterministic)
{
  typedef CGAL::Surface_mesh<Point> SM;
  typedef CGAL::Polyhedron_3<K> P;
  const auto a = IRS::generate_two_snowmen<SM>(1500);
  const auto b = IRS::generate_two_snowmen<P>(1500);
  const auto c = IRS::generate_two_snowmen<SM>(1500);
  const std::vector<Point> pa = vertex_points(a.mesh), pb = vertex_points(b.mesh), pc = vertex_points(c.mesh);
  ASSERT_EQ(pa.size(), pb.size());
  ASSERT_EQ(pa.size(), pc.size());
  for(std::size_t v = 0; v < pa.size(); ++v) {
    EXPECT_EQ(pa[v], pb[v]);
    EXPECT_EQ(pa[v], pc[v]);
  }
  ASSERT_EQ(a.symmetries.size(), c.symmetries.size());
  for(std::size_t k = 0; k < a.symmetries.size(); ++k) {
    EXPECT_EQ(a.symmetries[k].mirror, b.symmetries[k].mirror);
    EXPECT_EQ(a.symmetries[k].mirror, c.symmetries[k].mirror);
    EXPECT_EQ(a.symmetries[k].axis, c.symmetries[k].axis);
  }
  EXPECT_EQ(num_faces(a.mesh), num_faces(b.mesh));
}

TEST(ShapesResolutions, SmallAndDefault)
{
  typedef CGAL::Surface_mesh<Point> SM;
  for(std::size_t n : {600u, 2500u}) {
    check_shape(IRS::generate_ellipsoid<SM>(n), "ellipsoid " + std::to_string(n), n, true);
    check_shape(IRS::generate_snowman<SM>(n), "snowman " + std::to_string(n), n, true);
    check_shape(IRS::generate_torus<SM>(n), "torus " + std::to_string(n), n, true);
    check_shape(IRS::generate_two_snowmen<SM>(n), "two snowmen " + std::to_string(n), n, false);
    check_shape(IRS::generate_bent_capsule<SM>(n), "bent capsule " + std::to_string(n), n, true);
  }
}

TEST(ShapesArguments, BadArgumentsThrow)
{
  typedef CGAL::Surface_mesh<Point> SM;
  auto invalid = [](auto&& f) {
    try { f(); ADD_FAILURE() << "no exception"; }
    catch(const IRS::Input_error& e) { EXPECT_EQ(e.problem(), IRS::Input_problem::invalid_parameter) << e.what(); }
  };
  invalid([] { IRS::generate_sphere<SM>(50); });
  invalid([] { IRS::generate_sphere<SM>(500, -1.); });
  invalid([] { IRS::generate_ellipsoid<SM>(500, 1., 0., 1.); });
  invalid([] { IRS::generate_capsule<SM>(500, 0.5, 0.); });
  invalid([] { IRS::generate_torus<SM>(500, 0.3, 0.4); });
  invalid([] { IRS::generate_snowman<SM>(500, std::numeric_limits<double>::infinity()); });
  invalid([] { IRS::generate_two_snowmen<SM>(10); });
  invalid([] { IRS::generate_bent_capsule<SM>(500, 0.2, 5., 4.); });
  invalid([] { IRS::generate_bent_capsule<SM>(500, 1.5, 5., 2.); });
  // tiny targets still give closed shapes: thin parts keep at least 8 edges around
  const auto g = IRS::generate_bent_capsule<SM>(100);
  EXPECT_TRUE(CGAL::is_closed(g.mesh));
  EXPECT_FALSE(PMP::does_self_intersect(g.mesh));
}

// irsym's picture of a symmetric map (symmetric_map.ply, cli/irsym_output.h):
// on the ellipsoid, its x=0 mirror map gives partners one colour and a
// colour field that still varies; the identity, no mirror map, colours the
// two sides differently; vertices without a partner are dark grey
TEST(MapPicture, PartnersShareAColour)
{
  typedef CGAL::Surface_mesh<Point> SM;
  const auto shape = IRS::generate_ellipsoid<SM>(1000);
  const IRS::Known_symmetry& s = shape.symmetries[0];
  ASSERT_EQ(s.name, "x=0 plane");
  const std::vector<Point> pts = vertex_points(shape.mesh);
  std::vector<std::ptrdiff_t> partner = s.mirror;
  const std::size_t unmapped = 0;
  const std::size_t mirror_of_unmapped = std::size_t(partner[unmapped]);
  partner[unmapped] = -1;
  const std::vector<CGAL::IO::Color> colours = irsym::partner_colours(partner, irsym::coordinate_fields(shape.mesh));
  ASSERT_EQ(colours.size(), pts.size());
  EXPECT_EQ(colours[unmapped], CGAL::IO::Color(70, 70, 70));
  std::size_t pairs = 0, same = 0;
  std::vector<std::array<unsigned char, 3>> distinct;
  for(std::size_t v = 0; v < pts.size(); ++v) {
    if(partner[v] < 0 || v == mirror_of_unmapped) continue; // that one's partner is unmapped: no involution
    ++pairs;
    same += colours[v] == colours[std::size_t(partner[v])];
    distinct.push_back({{colours[v].red(), colours[v].green(), colours[v].blue()}});
  }
  std::sort(distinct.begin(), distinct.end());
  distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
  EXPECT_EQ(same, pairs);
  EXPECT_GE(distinct.size(), 100u) << "the colour field varies";

  std::vector<std::ptrdiff_t> identity(pts.size());
  std::iota(identity.begin(), identity.end(), std::ptrdiff_t(0));
  const std::vector<CGAL::IO::Color> own = irsym::partner_colours(identity, irsym::coordinate_fields(shape.mesh));
  std::size_t off_plane = 0, differ = 0;
  for(std::size_t v = 0; v < pts.size(); ++v)
    if(std::abs(pts[v].x()) > 0.5) {
      ++off_plane;
      differ += own[v] != own[std::size_t(s.mirror[v])];
    }
  EXPECT_GE(double(differ), 0.95 * double(off_plane));

  // irsym's intrinsic fields (distances from points of the axis) are mirror
  // symmetric themselves: the sides look alike even under the identity, and
  // a field infinite somewhere (another component) takes the end of the scale
  std::vector<std::vector<double>> from_axis(2, std::vector<double>(pts.size()));
  for(std::size_t v = 0; v < pts.size(); ++v) {
    from_axis[0][v] = std::sqrt(CGAL::to_double(CGAL::squared_distance(pts[v], Point(0, 0, 1))));
    from_axis[1][v] = std::sqrt(CGAL::to_double(CGAL::squared_distance(pts[v], Point(0, 1, 0))));
  }
  from_axis[0][0] = std::numeric_limits<double>::infinity();
  const std::vector<CGAL::IO::Color> symmetric = irsym::partner_colours(identity, from_axis);
  std::size_t alike = 0;
  for(std::size_t v = 1; v < pts.size(); ++v) alike += symmetric[v] == symmetric[std::size_t(s.mirror[v])] || s.mirror[v] == 0;
  EXPECT_GE(double(alike), 0.9 * double(pts.size() - 1));
  EXPECT_NE(symmetric[0], CGAL::IO::Color(70, 70, 70));
}
