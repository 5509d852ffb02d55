// Reading, checking, mending and preparing the input mesh: one test per
// failure class on a hand-made bad file or soup, the accepted cases, every
// format on Surface_mesh and Polyhedron_3, and the preparation maps.
#include <CGAL/Intrinsic_reflectional_symmetry_3/check_input.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/prepare_mesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/polygon_mesh_to_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/subdivision_method_3.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <numeric>
#include <random>
#include <string>
#include <vector>

namespace IRS = CGAL::Intrinsic_reflectional_symmetry_3;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace fs = std::filesystem;

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef CGAL::Polyhedron_3<K> Polyhedron;

namespace {

// One directory per run, under the system's temporary directory.
const fs::path& temp_dir()
{
  static const fs::path dir = [] {
    std::random_device rd;
    fs::path d = fs::temp_directory_path() / ("irs_test_input_" + std::to_string(rd()));
    fs::create_directories(d);
    return d;
  }();
  return dir;
}

struct Remove_temp_dir : ::testing::Environment
{
  void TearDown() override { std::error_code ec; fs::remove_all(temp_dir(), ec); }
};
const auto* const remove_temp_dir = ::testing::AddGlobalTestEnvironment(new Remove_temp_dir);

std::string write_file(const std::string& name, const std::string& content)
{
  const fs::path p = temp_dir() / name;
  std::ofstream out(p, std::ios::binary);
  out << content;
  return p.string();
}

// Runs `f`, expects an Input_error of the given problem whose what() contains
// every string of `mentions`; returns the element it named.
std::size_t expect_error(const std::function<void()>& f, IRS::Input_problem problem,
                         const std::vector<std::string>& mentions)
{
  try {
    f();
  } catch(const IRS::Input_error& e) {
    EXPECT_EQ(e.problem(), problem) << e.what();
    for(const std::string& m : mentions)
      EXPECT_NE(std::string(e.what()).find(m), std::string::npos) << "'" << m << "' not in: " << e.what();
    return e.element();
  } catch(const std::exception& e) {
    ADD_FAILURE() << "unexpected exception: " << e.what();
    return IRS::Input_error::no_element;
  }
  ADD_FAILURE() << "no Input_error thrown, expected " << IRS::to_string(problem);
  return IRS::Input_error::no_element;
}

template <typename TM>
TM sphere(int subdivisions)
{
  TM tm;
  CGAL::make_icosahedron(tm, Point(0, 0, 0), 1.);
  if(subdivisions > 0)
    CGAL::Subdivision_method_3::Loop_subdivision(tm, CGAL::parameters::number_of_iterations(subdivisions));
  return tm;
}

// A flat n x n grid of unit squares in z = 0, each split in two triangles.
Mesh flat_grid(int n)
{
  Mesh m;
  std::vector<Mesh::Vertex_index> v;
  for(int j = 0; j <= n; ++j)
    for(int i = 0; i <= n; ++i)
      v.push_back(m.add_vertex(Point(i, j, 0)));
  auto at = [&](int i, int j) { return v[std::size_t(j * (n + 1) + i)]; };
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < n; ++i) {
      m.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      m.add_face(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  return m;
}

template <typename TM>
std::vector<Point> points_of(const TM& tm)
{
  std::vector<Point> p;
  for(auto v : vertices(tm)) p.push_back(get(CGAL::vertex_point, tm, v));
  return p;
}

// face lists as vertex indices, in iteration order
template <typename TM>
std::vector<std::vector<std::size_t> > faces_of(const TM& tm)
{
  auto vim = CGAL::get_initialized_vertex_index_map(tm);
  std::vector<std::vector<std::size_t> > f;
  for(auto fd : faces(tm)) {
    f.emplace_back();
    for(auto h : CGAL::halfedges_around_face(halfedge(fd, tm), tm)) f.back().push_back(get(vim, target(h, tm)));
  }
  return f;
}

bool same_cycle(std::vector<std::size_t> a, const std::vector<std::size_t>& b)
{
  if(a.size() != b.size()) return false;
  for(std::size_t r = 0; r < a.size(); ++r) {
    if(a == b) return true;
    std::rotate(a.begin(), a.begin() + 1, a.end());
  }
  return false;
}

const char* tetrahedron_off =
  "OFF\n4 4 0\n"
  "0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
  "3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n";

} // namespace

// ---------------------------------------------------------------------------
// unreadable files

TEST(ReadMesh, MissingFileIsUnreadable)
{
  const std::string path = (temp_dir() / "does_not_exist.off").string();
  Mesh m;
  expect_error([&] { IRS::read_mesh(path, m); }, IRS::Input_problem::unreadable_file, {path});
}

TEST(ReadMesh, GarbageIsUnreadable)
{
  const std::string path = write_file("garbage.off", "hello, this is not a mesh\n1 2 3\n");
  Mesh m;
  expect_error([&] { IRS::read_mesh(path, m); }, IRS::Input_problem::unreadable_file, {path});
  Polyhedron p;
  expect_error([&] { IRS::read_mesh(path, p); }, IRS::Input_problem::unreadable_file, {path});
}

TEST(ReadMesh, UnknownExtensionIsUnreadable)
{
  const std::string path = write_file("tetrahedron.xyz", tetrahedron_off);
  Mesh m;
  expect_error([&] { IRS::read_mesh(path, m); }, IRS::Input_problem::unreadable_file, {path, "xyz"});
  const std::string none = write_file("tetrahedron", tetrahedron_off);
  expect_error([&] { IRS::read_mesh(none, m); }, IRS::Input_problem::unreadable_file, {none});
}

TEST(CheckPolygonSoup, IndexOutOfRangeIsReported)
{
  // CGAL's OFF reader already refuses such files; an in-memory soup is checked here
  std::vector<Point> points{Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1)};
  std::vector<std::vector<std::size_t> > polygons{{0, 2, 1}, {0, 1, 3}, {1, 2, 7}, {0, 3, 2}};
  const std::size_t e = expect_error([&] { IRS::check_polygon_soup(points, polygons); },
                                     IRS::Input_problem::unreadable_file, {"polygon 2", "vertex 7"});
  EXPECT_EQ(e, 2u);
}

// ---------------------------------------------------------------------------
// one test per failure class

TEST(ReadMesh, EmptyFileIsEmptyMesh)
{
  Mesh m;
  const std::string empty = write_file("empty.off", "");
  expect_error([&] { IRS::read_mesh(empty, m); }, IRS::Input_problem::empty_mesh, {empty});
  const std::string no_elements = write_file("no_elements.off", "OFF\n0 0 0\n");
  expect_error([&] { IRS::read_mesh(no_elements, m); }, IRS::Input_problem::empty_mesh, {no_elements});
  const std::string no_faces = write_file("no_faces.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n");
  expect_error([&] { IRS::read_mesh(no_faces, m); }, IRS::Input_problem::empty_mesh, {"0 polygons"});
  Mesh nothing;
  expect_error([&] { IRS::check_input(nothing); }, IRS::Input_problem::empty_mesh, {"0 vertices"});
}

// a square pyramid: four triangles and a quad base (face 4)
const char* square_pyramid_off =
  "OFF\n5 5 0\n"
  "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0.5 0.5 1\n"
  "3 0 1 4\n3 1 2 4\n3 2 3 4\n3 3 0 4\n4 0 3 2 1\n";

TEST(CheckInput, QuadFaceIsNotATriangleMesh)
{
  const std::string path = write_file("pyramid.off", square_pyramid_off);
  Mesh m;
  ASSERT_NO_THROW(IRS::read_mesh(path, m));
  EXPECT_EQ(num_faces(m), 5u);
  const std::size_t e = expect_error([&] { IRS::check_input(m); }, IRS::Input_problem::not_triangle_mesh,
                                     {"face 4", "4 vertices", "1 non-triangle"});
  EXPECT_EQ(e, 4u);

  // mended by triangulation, on a copy
  Mesh mended;
  const IRS::Input_repairs r = IRS::repair_input(m, mended);
  EXPECT_EQ(r.triangulated_faces, 1u);
  EXPECT_EQ(num_faces(m), 5u);
  EXPECT_NO_THROW(IRS::check_input(mended));
}

TEST(ReadMesh, PolygonWithTwoVerticesIsNotATriangleMesh)
{
  std::vector<Point> points{Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0)};
  std::vector<std::vector<std::size_t> > polygons{{0, 1, 2}, {0, 1}};
  const std::size_t e = expect_error([&] { IRS::check_polygon_soup(points, polygons); },
                                     IRS::Input_problem::not_triangle_mesh, {"polygon 1", "2 vertices"});
  EXPECT_EQ(e, 1u);
}

TEST(ReadMesh, NanCoordinateInOffIsNonFinite)
{
  const std::string path = write_file("nan.off",
    "OFF\n4 4 0\n"
    "0 0 0\n1 0 0\nnan 1 0\n0 0 1\n"
    "3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n");
  Mesh m;
  const std::size_t e = expect_error([&] { IRS::read_mesh(path, m); }, IRS::Input_problem::non_finite_coordinate,
                                     {"vertex 2", path});
  EXPECT_EQ(e, 2u);
  const std::string obj = write_file("inf.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 inf\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n");
  EXPECT_EQ(expect_error([&] { IRS::read_mesh(obj, m); }, IRS::Input_problem::non_finite_coordinate, {"vertex 3"}), 3u);
}

TEST(CheckInput, NanCoordinateInBinaryPlyIsNonFinite)
{
  // binary formats carry NaN: the mesh is read, check_input() names the vertex
  std::vector<Point> points{Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0),
                            Point(0, 0, std::numeric_limits<double>::quiet_NaN())};
  std::vector<std::vector<std::size_t> > polygons{{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  const std::string path = (temp_dir() / "nan.ply").string();
  ASSERT_TRUE(CGAL::IO::write_polygon_soup(path, points, polygons, CGAL::parameters::use_binary_mode(true)));
  Mesh m;
  ASSERT_NO_THROW(IRS::read_mesh(path, m));
  const std::size_t e = expect_error([&] { IRS::check_input(m); }, IRS::Input_problem::non_finite_coordinate,
                                     {"vertex 3", "1 vertices"});
  EXPECT_EQ(e, 3u);
  Mesh mended;
  const IRS::Input_repairs r = IRS::repair_input(m, mended); // cannot mend it, must not crash either
  EXPECT_FALSE(r.any());
  const std::size_t em = expect_error([&] { IRS::check_input(mended); }, IRS::Input_problem::non_finite_coordinate,
                                      {"vertex"});
  ASSERT_LT(em, r.output_to_input_vertex.size());
  EXPECT_EQ(r.output_to_input_vertex[em], 3u); // the copy renumbers vertices, the map leads back
}

TEST(CheckInput, IsolatedVertexIsReported)
{
  // a tetrahedron whose vertex 2 is used by no face
  const std::string path = write_file("isolated.off",
    "OFF\n5 4 0\n"
    "0 0 0\n1 0 0\n7 7 7\n0 1 0\n0 0 1\n"
    "3 0 3 1\n3 0 1 4\n3 1 3 4\n3 0 4 3\n");
  for(int kind = 0; kind < 2; ++kind) {
    std::size_t e;
    if(kind == 0) {
      Mesh m;
      IRS::read_mesh(path, m);
      EXPECT_EQ(num_vertices(m), 5u);
      e = expect_error([&] { IRS::check_input(m); }, IRS::Input_problem::isolated_vertex, {"vertex 2"});
      Mesh mended;
      EXPECT_EQ(IRS::repair_input(m, mended).removed_isolated_vertices, 1u);
      EXPECT_EQ(num_vertices(mended), 4u);
      EXPECT_EQ(num_vertices(m), 5u);
      EXPECT_NO_THROW(IRS::check_input(mended));
    } else {
      Polyhedron p;
      IRS::read_mesh(path, p);
      e = expect_error([&] { IRS::check_input(p); }, IRS::Input_problem::isolated_vertex, {"vertex 2"});
    }
    EXPECT_EQ(e, 2u);
  }
}

// two tetrahedra (cones) touching at vertex 3 only
const char* two_cones_off =
  "OFF\n7 8 0\n"
  "0 0 0\n1 0 0\n0 1 0\n0 0 1\n0 0 2\n1 0 2\n0 1 2\n"
  "3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n"
  "3 3 4 5\n3 3 5 6\n3 3 6 4\n3 4 6 5\n";

template <typename TM>
void check_non_manifold_vertex()
{
  const std::string path = write_file("two_cones.off", two_cones_off);
  TM tm;
  ASSERT_NO_THROW(IRS::read_mesh(path, tm));
  EXPECT_EQ(num_vertices(tm), 7u); // the pinched vertex is kept, not split silently
  EXPECT_EQ(num_faces(tm), 8u);
  const std::size_t e = expect_error([&] { IRS::check_input(tm); }, IRS::Input_problem::non_manifold_vertex,
                                     {"vertex 3", "1 non-manifold"});
  EXPECT_EQ(e, 3u);

  TM mended;
  const IRS::Input_repairs r = IRS::repair_input(tm, mended);
  EXPECT_EQ(r.duplicated_non_manifold_vertices, 1u);
  EXPECT_TRUE(r.any());
  EXPECT_EQ(num_vertices(mended), 8u);
  EXPECT_EQ(num_vertices(tm), 7u);
  ASSERT_EQ(r.output_to_input_vertex.size(), 8u);
  EXPECT_EQ(std::count(r.output_to_input_vertex.begin(), r.output_to_input_vertex.end(), 3u), 2);
  for(std::size_t i = 0; i < 7; ++i)
    EXPECT_NE(std::find(r.output_to_input_vertex.begin(), r.output_to_input_vertex.end(), i),
              r.output_to_input_vertex.end());
  IRS::Input_report report;
  ASSERT_NO_THROW(report = IRS::check_input(mended));
  EXPECT_EQ(report.number_of_connected_components, 2u);
}

TEST(CheckInput, NonManifoldVertexIsReportedSurfaceMesh) { check_non_manifold_vertex<Mesh>(); }
TEST(CheckInput, NonManifoldVertexIsReportedPolyhedron) { check_non_manifold_vertex<Polyhedron>(); }

TEST(ReadMesh, NonManifoldEdgeIsReported)
{
  // three triangles on edge (0, 1), the last two polygons share it
  const std::string path = write_file("book.off",
    "OFF\n6 4 0\n"
    "0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n5 5 5\n"
    "3 2 3 5\n3 0 1 2\n3 1 0 3\n3 0 1 4\n");
  Mesh m;
  const std::size_t e = expect_error([&] { IRS::read_mesh(path, m); }, IRS::Input_problem::non_manifold_edge,
                                     {"edge (0, 1)", "3 polygons", path});
  EXPECT_EQ(e, 1u); // the first polygon holding the edge
  Polyhedron p;
  expect_error([&] { IRS::read_mesh(path, p); }, IRS::Input_problem::non_manifold_edge, {"edge (0, 1)"});
}

TEST(CheckInput, DegenerateFaceIsReported)
{
  // a flat tetrahedron: face 3 = (0, 1, 2) has collinear vertices
  const std::string path = write_file("flat.off",
    "OFF\n4 4 0\n"
    "0 0 0\n1 0 0\n2 0 0\n0 1 0\n"
    "3 0 3 1\n3 0 2 3\n3 1 3 2\n3 0 1 2\n");
  Mesh m;
  IRS::read_mesh(path, m);
  std::size_t e = expect_error([&] { IRS::check_input(m); }, IRS::Input_problem::degenerate_face,
                               {"face 3", "collinear"});
  EXPECT_EQ(e, 3u);

  // near-zero area, not exactly collinear
  const std::string sliver = write_file("sliver.off",
    "OFF\n4 4 0\n"
    "0 0 0\n1 0 0\n2 1e-14 0\n0 1 1\n"
    "3 0 3 1\n3 0 2 3\n3 0 1 2\n3 1 3 2\n");
  IRS::read_mesh(sliver, m);
  e = expect_error([&] { IRS::check_input(m); }, IRS::Input_problem::degenerate_face, {"face 2", "near-zero area"});
  EXPECT_EQ(e, 2u);

  // a polygon using a vertex twice is degenerate, found on the soup
  const std::string repeated = write_file("repeated.off",
    "OFF\n4 4 0\n"
    "0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
    "3 0 2 1\n3 0 1 3\n3 1 1 3\n3 0 3 2\n");
  e = expect_error([&] { IRS::read_mesh(repeated, m); }, IRS::Input_problem::degenerate_face,
                   {"polygon 2", "vertex 1"});
  EXPECT_EQ(e, 2u);
}

TEST(CheckInput, DegenerateFaceIsRemovedByRepair)
{
  // a closed mesh with one face flattened: a vertex moved onto the midpoint of its opposite edge
  Mesh m = sphere<Mesh>(1);
  auto f0 = *faces(m).begin();
  auto h = halfedge(f0, m);
  const Point a = m.point(source(h, m)), b = m.point(target(h, m));
  m.point(target(next(h, m), m)) = CGAL::midpoint(a, b);
  ASSERT_THROW(IRS::check_input(m), IRS::Input_error);
  Mesh mended;
  const IRS::Input_repairs r = IRS::repair_input(m, mended);
  EXPECT_GE(r.removed_degenerate_faces, 1u);
  EXPECT_NO_THROW(IRS::check_input(mended));
}

// a face of near-zero area whose corners are not exactly collinear (a vertex
// 1e-12 of an edge off its opposite edge, inside the face): PMP::degenerate_faces()
// does not see it, check_input() refuses it, and repair_input() removes it with
// CGAL's remove_almost_degenerate_faces() (a cap), touching nothing else
TEST(CheckInput, NearZeroAreaFaceIsRemovedByRepair)
{
  Mesh m = sphere<Mesh>(2);
  const std::size_t nf = num_faces(m);
  auto f0 = *faces(m).begin();
  auto h = halfedge(f0, m);
  const Point a = m.point(source(h, m)), b = m.point(target(h, m)), c = m.point(target(next(h, m), m));
  m.point(target(next(h, m), m)) = CGAL::midpoint(a, b) + 1e-12 * (c - CGAL::midpoint(a, b));
  ASSERT_FALSE(CGAL::Polygon_mesh_processing::is_degenerate_triangle_face(f0, m));
  expect_error([&] { IRS::check_input(m); }, IRS::Input_problem::degenerate_face, {"near-zero area"});
  Mesh mended;
  const IRS::Input_repairs r = IRS::repair_input(m, mended);
  EXPECT_EQ(r.removed_degenerate_faces, 1u);
  EXPECT_NO_THROW(IRS::check_input(mended));
  EXPECT_GE(num_faces(mended), nf - 2); // a flip keeps the count, a collapse removes two faces
  EXPECT_EQ(num_faces(m), nf);
}

TEST(CheckInput, TooManySamplesIsReported)
{
  const Mesh m = sphere<Mesh>(0); // 12 vertices
  EXPECT_NO_THROW(IRS::check_input(m, IRS::parameters::number_of_samples(12)));
  expect_error([&] { IRS::check_input(m, IRS::parameters::number_of_samples(13)); },
               IRS::Input_problem::too_many_samples, {"13", "12 vertices"});
  // CGAL's own number_of_samples tag is read as well
  expect_error([&] { IRS::check_input(m, CGAL::parameters::number_of_samples(100)); },
               IRS::Input_problem::too_many_samples, {"100"});
  expect_error([&] { IRS::check_input(m, IRS::parameters::number_of_samples(-1)); },
               IRS::Input_problem::invalid_parameter, {"-1"});
}

TEST(CheckInput, FirstFailingClassWinsAndCountsAreGiven)
{
  // a quad (face 1) and a NaN vertex: not_triangle_mesh comes first in the order
  std::vector<Point> points{Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 0),
                            Point(0.5, 0.5, std::numeric_limits<double>::infinity())};
  std::vector<std::vector<std::size_t> > polygons{{0, 1, 4}, {0, 3, 2, 1}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
  Mesh m;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, m);
  expect_error([&] { IRS::check_input(m); }, IRS::Input_problem::not_triangle_mesh, {"face 1"});
}

TEST(CheckInput, SurfaceMeshWithGarbageIsRefused)
{
  Mesh m = sphere<Mesh>(1);
  Mesh::Vertex_index extra = m.add_vertex(Point(5, 5, 5));
  m.add_vertex(Point(6, 6, 6));
  m.remove_vertex(extra); // indices now have a hole
  expect_error([&] { IRS::check_input(m); }, IRS::Input_problem::invalid_parameter, {"collect_garbage"});
  m.collect_garbage();
  expect_error([&] { IRS::check_input(m); }, IRS::Input_problem::isolated_vertex, {"1 isolated"});
}

// ---------------------------------------------------------------------------
// accepted inputs

TEST(CheckInput, ClosedMeshWithSmallHoleIsAccepted)
{
  Mesh closed = sphere<Mesh>(2);
  std::vector<Point> points;
  std::vector<std::vector<std::size_t> > polygons;
  PMP::polygon_mesh_to_polygon_soup(closed, points, polygons);
  const std::vector<std::size_t> hole = polygons[17];
  polygons.erase(polygons.begin() + 17); // a one-triangle hole
  double hole_perimeter = 0;
  for(std::size_t k = 0; k < 3; ++k)
    hole_perimeter += std::sqrt(CGAL::squared_distance(points[hole[k]], points[hole[(k + 1) % 3]]));
  const std::string path = (temp_dir() / "holed.off").string();
  ASSERT_TRUE(CGAL::IO::write_polygon_soup(path, points, polygons, CGAL::parameters::stream_precision(17)));
  Mesh m;
  ASSERT_NO_THROW(IRS::read_mesh(path, m));
  IRS::Input_report r;
  ASSERT_NO_THROW(r = IRS::check_input(m));
  EXPECT_EQ(r.number_of_vertices, num_vertices(closed));
  EXPECT_EQ(r.number_of_faces, num_faces(closed) - 1);
  EXPECT_EQ(r.number_of_boundary_cycles, 1u);
  EXPECT_EQ(r.number_of_border_edges, 3u);
  EXPECT_NEAR(r.longest_boundary_cycle_length, hole_perimeter, 1e-12);
  EXPECT_EQ(r.number_of_connected_components, 1u);
  EXPECT_GT(r.area, 0.);
  EXPECT_GT(r.mean_edge_length, 0.);
  EXPECT_GT(r.bounding_box_diagonal, 2.); // Loop subdivision shrinks the unit icosahedron
  EXPECT_LT(r.bounding_box_diagonal, std::sqrt(12.));
}

TEST(CheckInput, TwoComponentsAreAccepted)
{
  const std::string path = write_file("two_tetrahedra.off",
    "OFF\n8 8 0\n"
    "0 0 0\n1 0 0\n0 1 0\n0 0 1\n5 0 0\n6 0 0\n5 1 0\n5 0 1\n"
    "3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n"
    "3 4 6 5\n3 4 5 7\n3 5 6 7\n3 4 7 6\n");
  Polyhedron p;
  ASSERT_NO_THROW(IRS::read_mesh(path, p));
  IRS::Input_report r;
  ASSERT_NO_THROW(r = IRS::check_input(p));
  EXPECT_EQ(r.number_of_connected_components, 2u);
  EXPECT_EQ(r.number_of_boundary_cycles, 0u);
  EXPECT_EQ(r.longest_boundary_cycle_length, 0.);
  EXPECT_EQ(r.number_of_edges, 12u);
  EXPECT_NEAR(r.area, 2 * (1.5 + std::sqrt(3.) / 2), 1e-12);
}

TEST(ReadMesh, InconsistentOrientationIsFixedNotRejected)
{
  // face 1 of the tetrahedron listed backwards
  const std::string path = write_file("flipped.off",
    "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
    "3 0 2 1\n3 0 3 1\n3 1 2 3\n3 0 3 2\n");
  Mesh m;
  ASSERT_NO_THROW(IRS::read_mesh(path, m));
  EXPECT_TRUE(CGAL::is_closed(m));
  EXPECT_NO_THROW(IRS::check_input(m));
}

// ---------------------------------------------------------------------------
// every format, both mesh types

template <typename TM>
class ReadFormats : public ::testing::Test {};
typedef ::testing::Types<Mesh, Polyhedron> Mesh_types;
TYPED_TEST_SUITE(ReadFormats, Mesh_types);

TYPED_TEST(ReadFormats, OffObjPlyStlRoundTrip)
{
  const Mesh original = sphere<Mesh>(2); // 162 vertices, closed
  const double area = PMP::area(original);
  const std::vector<Point> pts = points_of(original);
  for(const std::string ext : {"off", "obj", "ply", "stl"}) {
    SCOPED_TRACE(ext);
    const std::string path = (temp_dir() / ("sphere." + ext)).string();
    ASSERT_TRUE(CGAL::IO::write_polygon_mesh(path, original, CGAL::parameters::stream_precision(17)));
    TypeParam tm;
    ASSERT_NO_THROW(IRS::read_mesh(path, tm));
    IRS::Input_report r;
    ASSERT_NO_THROW(r = IRS::check_input(tm));
    EXPECT_EQ(r.number_of_vertices, num_vertices(original));
    EXPECT_EQ(r.number_of_faces, num_faces(original));
    EXPECT_EQ(r.number_of_boundary_cycles, 0u);
    EXPECT_EQ(r.number_of_connected_components, 1u);
    EXPECT_NEAR(r.area, area, 1e-5 * area); // STL stores floats
    if(ext != "stl") { // STL has no shared vertices: its reader numbers them its own way
      const std::vector<Point> read = points_of(tm);
      ASSERT_EQ(read.size(), pts.size());
      for(std::size_t i = 0; i < pts.size(); ++i)
        EXPECT_LT(CGAL::squared_distance(read[i], pts[i]), 1e-20) << "vertex " << i;
    }
  }
}

// ---------------------------------------------------------------------------
// preparation

template <typename TM>
class Preparation : public ::testing::Test {};
TYPED_TEST_SUITE(Preparation, Mesh_types);

TYPED_TEST(Preparation, WithoutPreparationTheWorkingMeshIsAnExactCopy)
{
  const TypeParam tm = sphere<TypeParam>(2);
  const auto prepared = IRS::prepare_mesh(tm);
  EXPECT_TRUE(prepared.is_identity());
  EXPECT_EQ(prepared.preparation(), IRS::Mesh_preparation::none);
  const auto& w = prepared.working_mesh();
  const std::vector<Point> in_points = points_of(tm), w_points = points_of(w);
  ASSERT_EQ(w_points.size(), in_points.size());
  for(std::size_t i = 0; i < in_points.size(); ++i) EXPECT_EQ(w_points[i], in_points[i]);
  const auto in_faces = faces_of(tm), w_faces = faces_of(w);
  ASSERT_EQ(w_faces.size(), in_faces.size());
  for(std::size_t j = 0; j < in_faces.size(); ++j) EXPECT_TRUE(same_cycle(w_faces[j], in_faces[j])) << "face " << j;

  for(std::size_t i = 0; i < prepared.number_of_input_vertices(); ++i) {
    EXPECT_EQ(prepared.working_to_input_vertex(i), i);
    EXPECT_EQ(prepared.input_to_working_vertex(i), i);
  }
  for(std::size_t j = 0; j < prepared.number_of_input_faces(); ++j) EXPECT_EQ(prepared.input_to_working_face(j), j);

  std::vector<double> x;
  for(const Point& p : w_points) x.push_back(p.x());
  const std::vector<double> back = IRS::transfer_vertex_field_to_input(prepared, x);
  for(std::size_t i = 0; i < x.size(); ++i) EXPECT_EQ(back[i], in_points[i].x());
  std::vector<int> labels(num_faces(w));
  for(std::size_t j = 0; j < labels.size(); ++j) labels[j] = int(j) * 3;
  const std::vector<int> face_back = IRS::transfer_face_labels_to_input(prepared, labels);
  for(std::size_t j = 0; j < labels.size(); ++j) EXPECT_EQ(face_back[j], int(j) * 3);
}

TYPED_TEST(Preparation, RemeshingReachesTargetAndLeavesInputIntact)
{
  const TypeParam tm = sphere<TypeParam>(3); // 642 vertices
  const std::vector<Point> before = points_of(tm);
  const auto faces_before = faces_of(tm);
  for(std::size_t target : {300u, 1500u}) {
    SCOPED_TRACE(target);
    const auto prepared = IRS::prepare_mesh(
      tm, IRS::parameters::target_number_of_vertices(target).isotropic_remeshing(true));
    EXPECT_EQ(prepared.preparation(), IRS::Mesh_preparation::isotropic_remeshing);
    const double n = double(num_vertices(prepared.working_mesh()));
    EXPECT_GT(n, 0.75 * double(target));
    EXPECT_LT(n, 1.25 * double(target));
    EXPECT_GT(prepared.target_edge_length(), 0.);
    EXPECT_NO_THROW(IRS::check_input(prepared.working_mesh()));
    EXPECT_EQ(prepared.number_of_input_vertices(), num_vertices(tm));
    EXPECT_EQ(prepared.number_of_input_faces(), num_faces(tm));
  }
  // bit-identical input
  const std::vector<Point> after = points_of(tm);
  ASSERT_EQ(after.size(), before.size());
  for(std::size_t i = 0; i < before.size(); ++i) {
    EXPECT_EQ(after[i].x(), before[i].x());
    EXPECT_EQ(after[i].y(), before[i].y());
    EXPECT_EQ(after[i].z(), before[i].z());
  }
  EXPECT_EQ(faces_of(tm), faces_before);
}

TEST(Preparation, DecimationReachesTargetAndLeavesInputIntact)
{
  const Mesh tm = sphere<Mesh>(4); // 2562 vertices
  const std::vector<Point> before = points_of(tm);
  const auto faces_before = faces_of(tm);
  const auto prepared = IRS::prepare_mesh(tm, IRS::parameters::target_number_of_vertices(500));
  EXPECT_EQ(prepared.preparation(), IRS::Mesh_preparation::decimation);
  const double n = double(num_vertices(prepared.working_mesh()));
  EXPECT_GT(n, 0.75 * 500);
  EXPECT_LT(n, 1.25 * 500);
  EXPECT_NO_THROW(IRS::check_input(prepared.working_mesh()));
  EXPECT_EQ(points_of(tm), before);
  EXPECT_EQ(faces_of(tm), faces_before);

  // the input's own vertex count changes nothing
  const auto same = IRS::prepare_mesh(tm, IRS::parameters::target_number_of_vertices(num_vertices(tm)));
  EXPECT_TRUE(same.is_identity());
  EXPECT_EQ(num_vertices(same.working_mesh()), num_vertices(tm));
}

// decimation cannot add vertices: a larger target is reached by remeshing,
// unless remeshing is explicitly refused, which is an error, not a silent copy
TEST(Preparation, TargetAboveTheVertexCountRemeshes)
{
  const Mesh tm = sphere<Mesh>(3); // 642 vertices
  const std::vector<Point> before = points_of(tm);
  const auto prepared = IRS::prepare_mesh(tm, IRS::parameters::target_number_of_vertices(1500));
  EXPECT_EQ(prepared.preparation(), IRS::Mesh_preparation::isotropic_remeshing);
  const double n = double(num_vertices(prepared.working_mesh()));
  EXPECT_GT(n, 0.9 * 1500);
  EXPECT_LT(n, 1.1 * 1500);
  EXPECT_NO_THROW(IRS::check_input(prepared.working_mesh()));
  EXPECT_EQ(points_of(tm), before);
  expect_error([&] { IRS::prepare_mesh(tm, IRS::parameters::target_number_of_vertices(1500).isotropic_remeshing(false)); },
               IRS::Input_problem::invalid_parameter, {"1500", "642", "isotropic_remeshing(false)"});
}

TEST(Preparation, DecimationOfPolyhedronInput)
{
  const Polyhedron tm = sphere<Polyhedron>(3);
  const auto prepared = IRS::prepare_mesh(tm, IRS::parameters::target_number_of_vertices(200));
  const double n = double(num_vertices(prepared.working_mesh()));
  EXPECT_GT(n, 150.);
  EXPECT_LT(n, 250.);
  EXPECT_EQ(prepared.number_of_input_vertices(), 642u);
}

// f(x) = x is linear on every face: on a flat surface the input vertices lie on
// the working surface and barycentric interpolation reproduces x exactly.
TEST(Preparation, LinearFieldTransfersExactlyOnAFlatSurface)
{
  const Mesh grid = flat_grid(20); // 441 vertices
  const std::vector<Point> pts = points_of(grid);
  const double diag = std::sqrt(2.) * 20;
  for(int mode = 0; mode < 2; ++mode) {
    SCOPED_TRACE(mode == 0 ? "decimation" : "remeshing");
    const auto prepared = mode == 0
      ? IRS::prepare_mesh(grid, IRS::parameters::target_number_of_vertices(120))
      : IRS::prepare_mesh(grid, IRS::parameters::target_number_of_vertices(900).isotropic_remeshing(true));
    EXPECT_FALSE(prepared.is_identity());
    const auto& w = prepared.working_mesh();
    std::vector<double> x;
    for(auto v : vertices(w)) x.push_back(w.point(v).x());
    const std::vector<double> back = IRS::transfer_vertex_field_to_input(prepared, x);
    ASSERT_EQ(back.size(), pts.size());
    double worst = 0;
    for(std::size_t i = 0; i < pts.size(); ++i) worst = (std::max)(worst, std::abs(back[i] - pts[i].x()));
    EXPECT_LT(worst, 1e-6 * diag);
    // nearest-vertex maps land near the right place
    for(auto v : vertices(w))
      EXPECT_LT(std::sqrt(CGAL::squared_distance(w.point(v), pts[prepared.working_to_input_vertex(std::size_t(v))])),
                1.5);
  }
}

TEST(Preparation, TransfersOnACurvedClosedSurface)
{
  const Mesh tm = sphere<Mesh>(3);
  const auto prepared = IRS::prepare_mesh(tm, IRS::parameters::target_number_of_vertices(200));
  const auto& w = prepared.working_mesh();
  const std::vector<Point> pts = points_of(tm);

  // the linear field is reproduced up to the distance between the surfaces
  std::vector<double> x;
  for(auto v : vertices(w)) x.push_back(w.point(v).x());
  const std::vector<double> back = IRS::transfer_vertex_field_to_input(prepared, x);
  double worst = 0;
  for(std::size_t i = 0; i < pts.size(); ++i) worst = (std::max)(worst, std::abs(back[i] - pts[i].x()));
  EXPECT_LT(worst, 0.05); // the sphere has radius ~1, working edges ~0.25

  // face labels by side of the plane x = 0 agree away from the plane
  std::vector<int> side;
  for(auto f : faces(w)) {
    const auto h = halfedge(f, w);
    side.push_back(CGAL::centroid(w.point(source(h, w)), w.point(target(h, w)), w.point(target(next(h, w), w))).x() > 0);
  }
  const std::vector<int> in_side = IRS::transfer_face_labels_to_input(prepared, side);
  std::size_t agree = 0, counted = 0;
  std::size_t j = 0;
  for(auto f : faces(tm)) {
    const auto h = halfedge(f, tm);
    const double cx = CGAL::centroid(pts[std::size_t(source(h, tm))], pts[std::size_t(target(h, tm))],
                                     pts[std::size_t(target(next(h, tm), tm))]).x();
    if(std::abs(cx) > 0.3) { ++counted; agree += (in_side[j] == int(cx > 0)); }
    ++j;
  }
  EXPECT_EQ(agree, counted);

  // vertex labels follow the nearest working vertex
  std::vector<std::size_t> ids(num_vertices(w));
  for(std::size_t i = 0; i < ids.size(); ++i) ids[i] = i;
  const std::vector<std::size_t> vlabels = IRS::transfer_vertex_labels_to_input(prepared, ids);
  for(std::size_t i = 0; i < pts.size(); ++i)
    EXPECT_LT(std::sqrt(CGAL::squared_distance(pts[i], w.point(Mesh::Vertex_index(Mesh::size_type(vlabels[i]))))), 0.5);
}

TEST(Preparation, ParametersAreValidated)
{
  const Mesh tm = sphere<Mesh>(2);
  expect_error([&] { IRS::prepare_mesh(tm, IRS::parameters::target_number_of_vertices(3)); },
               IRS::Input_problem::invalid_parameter, {"target_number_of_vertices", "3"});
  expect_error([&] { IRS::prepare_mesh(tm, IRS::parameters::target_number_of_vertices(-10).isotropic_remeshing(true)); },
               IRS::Input_problem::invalid_parameter, {"-10"});
  expect_error([&] { IRS::prepare_mesh(tm, IRS::parameters::target_number_of_vertices(100000000).isotropic_remeshing(true)); },
               IRS::Input_problem::invalid_parameter, {"100000000"});
  // samples are counted on the working mesh
  expect_error([&] { IRS::prepare_mesh(tm, IRS::parameters::target_number_of_vertices(60).number_of_samples(100)); },
               IRS::Input_problem::too_many_samples, {"100"});
  std::vector<double> too_short(3);
  const auto prepared = IRS::prepare_mesh(tm);
  expect_error([&] { IRS::transfer_vertex_field_to_input(prepared, too_short); },
               IRS::Input_problem::invalid_parameter, {"3"});
  // a bad input is reported, not remeshed
  const std::string path = write_file("two_cones_prep.off", two_cones_off);
  Mesh pinched;
  IRS::read_mesh(path, pinched);
  expect_error([&] { IRS::prepare_mesh(pinched, IRS::parameters::isotropic_remeshing(true)); },
               IRS::Input_problem::non_manifold_vertex, {"vertex 3"});
}

// A sphere (Loop subdivision of an icosahedron, 642 vertices) with two round
// holes, the faces whose centroid lies within `north` and `south` of the poles:
// at 0.45, about the 2-ring of the pole's vertex, deep enough (sagitta ~0.1)
// that a flat patch would sit visibly inside the sphere.
template <typename TM>
TM sphere_with_two_holes(double north_radius = 0.45, double south_radius = 0.45)
{
  std::vector<Point> points;
  std::vector<std::vector<std::size_t> > polygons;
  PMP::polygon_mesh_to_polygon_soup(sphere<TM>(3), points, polygons);
  std::vector<std::vector<std::size_t> > kept;
  for(const auto& p : polygons) {
    const Point c = CGAL::centroid(points[p[0]], points[p[1]], points[p[2]]);
    const Point north(0, 0, std::sqrt((c - CGAL::ORIGIN).squared_length())), south(0, 0, -north.z());
    if(CGAL::squared_distance(c, north) > north_radius * north_radius &&
       CGAL::squared_distance(c, south) > south_radius * south_radius)
      kept.push_back(p);
  }
  PMP::remove_isolated_points_in_polygon_soup(points, kept);
  TM tm;
  PMP::polygon_soup_to_polygon_mesh(points, kept, tm);
  return tm;
}

// fill_holes(true) without remeshing: a closed working mesh whose first
// vertices and faces are the input's, the patch faired onto the sphere, the
// added vertices mapped to their nearest input vertex, the input untouched
TYPED_TEST(Preparation, FillHolesClosesTheCopyAndKeepsTheInputIds)
{
  const TypeParam tm = sphere_with_two_holes<TypeParam>();
  ASSERT_EQ(IRS::check_input(tm).number_of_boundary_cycles, 2u);
  const std::vector<Point> before = points_of(tm);
  const auto faces_before = faces_of(tm);
  double radius = 0;
  for(const Point& p : before) radius += std::sqrt((p - CGAL::ORIGIN).squared_length()) / double(before.size());

  const auto prepared = IRS::prepare_mesh(tm, IRS::parameters::fill_holes(true));
  EXPECT_EQ(prepared.number_of_filled_holes(), 2u);
  EXPECT_FALSE(prepared.is_identity());
  EXPECT_EQ(prepared.preparation(), IRS::Mesh_preparation::none);
  const auto& w = prepared.working_mesh();
  IRS::Input_report report;
  ASSERT_NO_THROW(report = IRS::check_input(w));
  EXPECT_EQ(report.number_of_boundary_cycles, 0u);
  EXPECT_EQ(report.number_of_connected_components, 1u);
  // the holes had ~30 input faces each: refinement adds interior vertices
  ASSERT_GT(num_vertices(w), before.size() + 10);

  const std::vector<Point> w_points = points_of(w);
  for(std::size_t i = 0; i < before.size(); ++i) {
    EXPECT_EQ(w_points[i], before[i]);
    EXPECT_EQ(prepared.working_to_input_vertex(i), i);
    EXPECT_EQ(prepared.input_to_working_vertex(i), i);
  }
  const auto w_faces = faces_of(w);
  for(std::size_t j = 0; j < faces_before.size(); ++j) {
    EXPECT_TRUE(same_cycle(w_faces[j], faces_before[j])) << "face " << j;
    EXPECT_EQ(prepared.input_to_working_face(j), j);
  }
  double worst_off_sphere = 0;
  for(std::size_t k = before.size(); k < w_points.size(); ++k) {
    std::size_t nearest = 0;
    for(std::size_t i = 1; i < before.size(); ++i)
      if(CGAL::squared_distance(w_points[k], before[i]) < CGAL::squared_distance(w_points[k], before[nearest]))
        nearest = i;
    EXPECT_EQ(CGAL::squared_distance(w_points[k], before[prepared.working_to_input_vertex(k)]),
              CGAL::squared_distance(w_points[k], before[nearest])) << "working vertex " << k;
    worst_off_sphere = (std::max)(worst_off_sphere,
                                  std::abs(std::sqrt((w_points[k] - CGAL::ORIGIN).squared_length()) - radius));
  }
  // faired: within 3 % of the radius, where the flat patch's centre is ~10 % inside
  EXPECT_LT(worst_off_sphere, 0.03 * radius);
  EXPECT_GT(PMP::area(w), PMP::area(tm));

  std::vector<double> x;
  for(const Point& p : w_points) x.push_back(p.x());
  const std::vector<double> back = IRS::transfer_vertex_field_to_input(prepared, x);
  for(std::size_t i = 0; i < before.size(); ++i) EXPECT_EQ(back[i], before[i].x());

  // a vertex map (each working vertex to the next, none for vertex 0) comes
  // back with partners among the added vertices sent to their nearest input vertex
  const std::size_t nw = w_points.size();
  std::vector<long> next(nw);
  for(std::size_t k = 0; k < nw; ++k) next[k] = k == 0 ? -1 : long((k + 1) % nw);
  const std::vector<std::ptrdiff_t> partner = IRS::transfer_vertex_map_to_input(prepared, next);
  ASSERT_EQ(partner.size(), before.size());
  EXPECT_EQ(partner[0], -1);
  EXPECT_EQ(partner[before.size() - 1], std::ptrdiff_t(prepared.working_to_input_vertex(before.size())));
  EXPECT_GE(partner[before.size() - 1], 0);
  for(std::size_t i = 1; i + 1 < before.size(); ++i) EXPECT_EQ(partner[i], std::ptrdiff_t(i + 1));
  next[5] = long(nw);
  expect_error([&] { IRS::transfer_vertex_map_to_input(prepared, next); }, IRS::Input_problem::invalid_parameter,
               {"partner " + std::to_string(nw), "not a working vertex"});
  next.resize(before.size());
  expect_error([&] { IRS::transfer_vertex_map_to_input(prepared, next); }, IRS::Input_problem::invalid_parameter,
               {std::to_string(before.size()), std::to_string(nw)});

  EXPECT_EQ(points_of(tm), before);
  EXPECT_EQ(faces_of(tm), faces_before);
}

// maximum_hole_boundary_length: of two holes, the shorter is filled and the
// longer left as it was; a bound that is not positive, or one given without
// fill_holes(true), is an error
TEST(Preparation, FillHolesUpToAMaximumBoundaryLength)
{
  const Mesh tm = sphere_with_two_holes<Mesh>(0.45, 0.9);
  const std::vector<Point> before = points_of(tm);
  std::vector<Mesh::Halfedge_index> cycles;
  PMP::extract_boundary_cycles(tm, std::back_inserter(cycles));
  ASSERT_EQ(cycles.size(), 2u);
  const double a = PMP::face_border_length(cycles[0], tm), b = PMP::face_border_length(cycles[1], tm);
  const double shorter = (std::min)(a, b), longer = (std::max)(a, b);
  ASSERT_LT(shorter, 0.7 * longer);

  const auto one = IRS::prepare_mesh(tm, IRS::parameters::fill_holes(true).maximum_hole_boundary_length(0.5 * (shorter + longer)));
  EXPECT_EQ(one.number_of_filled_holes(), 1u);
  EXPECT_EQ(one.number_of_holes_left_open(), 1u);
  EXPECT_FALSE(one.is_identity());
  const IRS::Input_report report = IRS::check_input(one.working_mesh());
  EXPECT_EQ(report.number_of_boundary_cycles, 1u);
  EXPECT_NEAR(report.longest_boundary_cycle_length, longer, 1e-9 * longer);
  ASSERT_GT(num_vertices(one.working_mesh()), before.size());
  const std::vector<Point> w_points = points_of(one.working_mesh());
  for(std::size_t i = 0; i < before.size(); ++i) EXPECT_EQ(w_points[i], before[i]);

  const auto both = IRS::prepare_mesh(tm, IRS::parameters::fill_holes(true).maximum_hole_boundary_length(1.01 * longer));
  EXPECT_EQ(both.number_of_filled_holes(), 2u);
  EXPECT_EQ(both.number_of_holes_left_open(), 0u);
  EXPECT_EQ(IRS::check_input(both.working_mesh()).number_of_boundary_cycles, 0u);
  const auto none = IRS::prepare_mesh(tm, IRS::parameters::fill_holes(true).maximum_hole_boundary_length(0.99 * shorter));
  EXPECT_EQ(none.number_of_filled_holes(), 0u);
  EXPECT_EQ(none.number_of_holes_left_open(), 2u);
  EXPECT_TRUE(none.is_identity());
  EXPECT_EQ(num_vertices(none.working_mesh()), before.size());

  expect_error([&] { IRS::prepare_mesh(tm, IRS::parameters::fill_holes(true).maximum_hole_boundary_length(0.)); },
               IRS::Input_problem::invalid_parameter, {"maximum_hole_boundary_length is 0", "positive"});
  expect_error([&] {
    IRS::prepare_mesh(tm, IRS::parameters::fill_holes(true).maximum_hole_boundary_length(std::nan("")));
  }, IRS::Input_problem::invalid_parameter, {"maximum_hole_boundary_length", "positive"});
  expect_error([&] { IRS::prepare_mesh(tm, IRS::parameters::maximum_hole_boundary_length(longer)); },
               IRS::Input_problem::invalid_parameter, {"without fill_holes(true)"});
  expect_error([&] { IRS::prepare_mesh(tm, IRS::parameters::fill_holes(false).maximum_hole_boundary_length(longer)); },
               IRS::Input_problem::invalid_parameter, {"without fill_holes(true)"});
  // infinity is no bound: accepted without filling (irsym passes it when no bound is given)
  EXPECT_TRUE(IRS::prepare_mesh(tm, IRS::parameters::fill_holes(false).maximum_hole_boundary_length(
                                      std::numeric_limits<double>::infinity())).is_identity());
  EXPECT_EQ(points_of(tm), before);
}

// with a target: filled first, then remeshed to the target (a hole longer than
// maximum_hole_boundary_length stays open through it); a closed input is left
// as it is (nothing to fill, still an exact copy)
TEST(Preparation, FillHolesThenRemeshAndClosedInputUnchanged)
{
  const Mesh tm = sphere_with_two_holes<Mesh>();
  const auto prepared = IRS::prepare_mesh(tm, IRS::parameters::fill_holes(true).target_number_of_vertices(1200));
  EXPECT_EQ(prepared.number_of_filled_holes(), 2u);
  EXPECT_EQ(prepared.preparation(), IRS::Mesh_preparation::isotropic_remeshing);
  const IRS::Input_report report = IRS::check_input(prepared.working_mesh());
  EXPECT_EQ(report.number_of_boundary_cycles, 0u);
  EXPECT_GT(double(report.number_of_vertices), 0.9 * 1200);
  EXPECT_LT(double(report.number_of_vertices), 1.1 * 1200);
  EXPECT_EQ(prepared.number_of_input_vertices(), num_vertices(tm));
  // the statistics of the input, not of the filled and remeshed working mesh
  EXPECT_EQ(prepared.input_report().number_of_boundary_cycles, 2u);
  EXPECT_EQ(prepared.input_report().number_of_vertices, num_vertices(tm));
  EXPECT_DOUBLE_EQ(prepared.input_report().longest_boundary_cycle_length,
                   IRS::check_input(tm).longest_boundary_cycle_length);

  // the larger hole left open by the bound stays open through the remeshing
  const Mesh uneven = sphere_with_two_holes<Mesh>(0.45, 0.9);
  const double longest = IRS::check_input(uneven).longest_boundary_cycle_length;
  const auto partly = IRS::prepare_mesh(uneven, IRS::parameters::fill_holes(true)
                                                  .maximum_hole_boundary_length(0.9 * longest)
                                                  .target_number_of_vertices(1200));
  EXPECT_EQ(partly.number_of_filled_holes(), 1u);
  EXPECT_EQ(partly.number_of_holes_left_open(), 1u);
  const IRS::Input_report partly_report = IRS::check_input(partly.working_mesh());
  EXPECT_EQ(partly_report.number_of_boundary_cycles, 1u);
  EXPECT_NEAR(partly_report.longest_boundary_cycle_length, longest, 0.05 * longest);
  EXPECT_GT(double(partly_report.number_of_vertices), 0.9 * 1200);
  EXPECT_LT(double(partly_report.number_of_vertices), 1.1 * 1200);

  const Mesh closed = sphere<Mesh>(2);
  const auto same = IRS::prepare_mesh(closed, IRS::parameters::fill_holes(true));
  EXPECT_TRUE(same.is_identity());
  EXPECT_EQ(same.number_of_filled_holes(), 0u);
  EXPECT_EQ(num_vertices(same.working_mesh()), num_vertices(closed));
}

// mend_input(true): what repair_input() mends is mended before the check, on
// a copy, and the maps lead back to the input (the duplicated copies of a
// pinched vertex both to it; a quad to one of its triangles); what it leaves
// still throws, saying so; an input without defects stays an exact copy
TEST(Preparation, MendInputThenMapBack)
{
  const std::string path = write_file("two_cones_mend.off", two_cones_off);
  Mesh tm;
  ASSERT_NO_THROW(IRS::read_mesh(path, tm));
  expect_error([&] { IRS::prepare_mesh(tm); }, IRS::Input_problem::non_manifold_vertex, {"vertex 3"});
  const auto prepared = IRS::prepare_mesh(tm, IRS::parameters::mend_input(true));
  EXPECT_FALSE(prepared.is_identity());
  EXPECT_EQ(prepared.input_repairs().duplicated_non_manifold_vertices, 1u);
  EXPECT_TRUE(prepared.input_repairs().output_to_input_vertex.empty());
  EXPECT_EQ(num_vertices(tm), 7u); // the input is not modified
  const Mesh& work = prepared.working_mesh();
  ASSERT_EQ(num_vertices(work), 8u);
  ASSERT_NO_THROW(IRS::check_input(work));
  // the statistics are the mended copy's (the input itself fails the check)
  const IRS::Input_report mended_report = IRS::check_input(work);
  EXPECT_EQ(prepared.input_report().number_of_vertices, 8u);
  EXPECT_EQ(prepared.input_report().number_of_faces, mended_report.number_of_faces);
  EXPECT_EQ(prepared.input_report().number_of_connected_components, mended_report.number_of_connected_components);
  EXPECT_DOUBLE_EQ(prepared.input_report().area, mended_report.area);
  EXPECT_DOUBLE_EQ(prepared.input_report().mean_edge_length, mended_report.mean_edge_length);
  ASSERT_EQ(prepared.number_of_input_vertices(), 7u);
  ASSERT_EQ(prepared.number_of_input_faces(), 8u);
  auto points_of = [](const Mesh& m) {
    std::vector<Point> p;
    for(auto v : vertices(m)) p.push_back(m.point(v));
    return p;
  };
  const std::vector<Point> in = points_of(tm), wp = points_of(work);
  std::vector<std::size_t> copies(7, 0);
  for(std::size_t w = 0; w < 8; ++w)
  {
    const std::size_t i = prepared.working_to_input_vertex(w);
    ASSERT_LT(i, 7u);
    EXPECT_EQ(wp[w], in[i]);
    ++copies[i];
  }
  EXPECT_EQ(copies, (std::vector<std::size_t>{1, 1, 1, 2, 1, 1, 1}));
  for(std::size_t i = 0; i < 7; ++i)
    EXPECT_EQ(wp[prepared.input_to_working_vertex(i)], in[i]) << "input vertex " << i;
  // each input face to the working face of the same corners
  std::vector<std::array<Point, 3>> in_faces, work_faces;
  for(const Mesh* m : std::vector<const Mesh*>{&tm, &work})
    for(auto f : faces(*m))
    {
      std::array<Point, 3> c;
      std::size_t k = 0;
      for(auto v : vertices_around_face(halfedge(f, *m), *m)) c[k++] = m->point(v);
      std::sort(c.begin(), c.end());
      (m == &tm ? in_faces : work_faces).push_back(c);
    }
  for(std::size_t j = 0; j < 8; ++j)
    EXPECT_EQ(in_faces[j], work_faces[prepared.input_to_working_face(j)]) << "input face " << j;
  // a map of the working mesh onto itself comes back as the same map on the input
  std::vector<std::ptrdiff_t> identity(8);
  std::iota(identity.begin(), identity.end(), std::ptrdiff_t(0));
  const std::vector<std::ptrdiff_t> back = IRS::transfer_vertex_map_to_input(prepared, identity);
  for(std::size_t i = 0; i < 7; ++i) EXPECT_EQ(back[i], std::ptrdiff_t(i));
  Polyhedron ph; // any FaceGraph
  ASSERT_NO_THROW(IRS::read_mesh(path, ph));
  const auto from_polyhedron = IRS::prepare_mesh(ph, IRS::parameters::mend_input(true));
  EXPECT_EQ(num_vertices(from_polyhedron.working_mesh()), 8u);
  EXPECT_EQ(from_polyhedron.input_repairs().duplicated_non_manifold_vertices, 1u);

  // a quad: triangulated, and the input's face 4 maps to a triangle of the base
  const std::string pyramid = write_file("pyramid_mend.off", square_pyramid_off);
  Mesh pm;
  ASSERT_NO_THROW(IRS::read_mesh(pyramid, pm));
  const auto tri = IRS::prepare_mesh(pm, IRS::parameters::mend_input(true));
  EXPECT_EQ(tri.input_repairs().triangulated_faces, 1u);
  const Mesh& tw = tri.working_mesh();
  EXPECT_EQ(num_faces(tw), 6u);
  std::size_t base_corners = 0;
  const Mesh::Face_index base(Mesh::size_type(tri.input_to_working_face(4)));
  for(auto v : vertices_around_face(halfedge(base, tw), tw)) base_corners += tw.point(v).z() == 0.;
  EXPECT_EQ(base_corners, 3u);

  // not mendable: a non-finite coordinate on a face, named on the input
  std::vector<Point> points{Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0),
                            Point(0, 0, std::numeric_limits<double>::quiet_NaN())};
  std::vector<std::vector<std::size_t>> polygons{{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  Mesh nan_mesh;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, nan_mesh);
  const std::size_t e = expect_error([&] { IRS::prepare_mesh(nan_mesh, IRS::parameters::mend_input(true)); },
                                     IRS::Input_problem::non_finite_coordinate, {"left after repair_input()"});
  EXPECT_EQ(e, 3u);

  // isolated vertices, one finite and one not: mending removes them, and they
  // lie nowhere on the working mesh (no partner, no field value, the label for
  // none), while the tetrahedron's corners keep their own vertices
  std::vector<Point> loose{Point(0, 0, 0), Point(1, 0, 0), Point(7, 7, 7), Point(0, 1, 0), Point(0, 0, 1),
                           Point(std::numeric_limits<double>::quiet_NaN(), 0, 0)};
  Mesh with_isolated;
  std::vector<Mesh::Vertex_index> lv;
  for(const Point& p : loose) lv.push_back(with_isolated.add_vertex(p));
  for(const auto& f : std::vector<std::array<std::size_t, 3>>{{0, 3, 1}, {0, 1, 4}, {1, 3, 4}, {0, 4, 3}})
    with_isolated.add_face(lv[f[0]], lv[f[1]], lv[f[2]]);
  expect_error([&] { IRS::prepare_mesh(with_isolated); }, IRS::Input_problem::non_finite_coordinate, {"vertex 5"});
  const auto tet = IRS::prepare_mesh(with_isolated, IRS::parameters::mend_input(true));
  EXPECT_EQ(tet.input_repairs().removed_isolated_vertices, 2u);
  ASSERT_EQ(tet.number_of_input_vertices(), 6u);
  ASSERT_EQ(tet.number_of_working_vertices(), 4u);
  std::vector<std::ptrdiff_t> tet_identity(4);
  std::iota(tet_identity.begin(), tet_identity.end(), std::ptrdiff_t(0));
  std::vector<double> height(4);
  std::vector<int> tet_labels(4);
  for(std::size_t w = 0; w < 4; ++w) {
    height[w] = tet.working_mesh().point(Mesh::Vertex_index(Mesh::size_type(w))).z();
    tet_labels[w] = int(w) + 10;
  }
  const std::vector<std::ptrdiff_t> tet_map = IRS::transfer_vertex_map_to_input(tet, tet_identity);
  const std::vector<double> tet_height = IRS::transfer_vertex_field_to_input(tet, height);
  const std::vector<int> tet_label = IRS::transfer_vertex_labels_to_input(tet, tet_labels, -1);
  for(std::size_t i : {std::size_t(2), std::size_t(5)}) {
    EXPECT_FALSE(tet.input_vertex_location(i).located) << "input vertex " << i;
    EXPECT_EQ(tet.input_to_working_vertex(i), tet.no_vertex) << "input vertex " << i;
    EXPECT_EQ(tet_map[i], -1) << "input vertex " << i;
    EXPECT_TRUE(std::isnan(tet_height[i])) << "input vertex " << i;
    EXPECT_EQ(tet_label[i], -1) << "input vertex " << i;
  }
  for(std::size_t i : {std::size_t(0), std::size_t(1), std::size_t(3), std::size_t(4)}) {
    EXPECT_TRUE(tet.input_vertex_location(i).located) << "input vertex " << i;
    const std::size_t w = tet.input_to_working_vertex(i);
    ASSERT_LT(w, 4u);
    EXPECT_EQ(tet.working_mesh().point(Mesh::Vertex_index(Mesh::size_type(w))), loose[i]);
    EXPECT_EQ(tet_map[i], std::ptrdiff_t(i));
    EXPECT_DOUBLE_EQ(tet_height[i], loose[i].z());
    EXPECT_EQ(tet_label[i], int(w) + 10);
  }
  EXPECT_EQ(IRS::transfer_vertex_labels_to_input(tet, tet_labels)[2], 0); // value-initialised by default

  // nothing to mend: the exact copy, as without mend_input
  const Mesh closed = sphere<Mesh>(2);
  const auto same = IRS::prepare_mesh(closed, IRS::parameters::mend_input(true));
  EXPECT_TRUE(same.is_identity());
  EXPECT_FALSE(same.input_repairs().any());
  EXPECT_EQ(num_vertices(same.working_mesh()), num_vertices(closed));
  const IRS::Input_report closed_report = IRS::check_input(closed);
  EXPECT_EQ(same.input_report().number_of_vertices, closed_report.number_of_vertices);
  EXPECT_EQ(same.input_report().number_of_edges, closed_report.number_of_edges);
  EXPECT_EQ(same.input_report().number_of_boundary_cycles, 0u);
  EXPECT_DOUBLE_EQ(same.input_report().area, closed_report.area);
  EXPECT_DOUBLE_EQ(same.input_report().bounding_box_diagonal, closed_report.bounding_box_diagonal);
}
