// Copyright (c) 2026 The Intrinsic_reflectional_symmetry_3 project.
// SPDX-License-Identifier: LGPL-3.0-or-later
// Author(s)     : The Intrinsic_reflectional_symmetry_3 developers
//
// The three geodesic oracles, the distance matrix and farthest-point sampling,
// on generated spheres (great-circle distances are known) with Surface_mesh and
// Polyhedron_3.

#include <CGAL/Intrinsic_reflectional_symmetry_3/geodesic_distances.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/sampling.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/polygon_mesh_to_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/generators.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/task_arena.h>
#endif

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <iomanip>
#include <iostream>
#include <limits>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace IRS = CGAL::Intrinsic_reflectional_symmetry_3;
namespace PMP = CGAL::Polygon_mesh_processing;

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3                                          Point;
typedef CGAL::Surface_mesh<Point>                           Surface_mesh;
typedef CGAL::Polyhedron_3<K>                               Polyhedron;
typedef std::vector<std::array<std::size_t, 3> >            Triangles;

namespace {

const double pi = 3.14159265358979323846;
const float inf = std::numeric_limits<float>::infinity();

// ---------------------------------------------------------------------------
// Generated meshes. Both mesh types are built from the same soup, so vertex
// index i is the same point in a Surface_mesh and in a Polyhedron_3.

struct Soup
{
  std::vector<Point> points;
  Triangles triangles;
};

// unit sphere around `center`: icosahedron, `levels` Loop subdivisions
// (levels 3: 642 vertices, 4: 2562), vertices projected onto the sphere
Soup sphere_soup(int levels, const Point& center = Point(0, 0, 0))
{
  Surface_mesh sm;
  CGAL::make_icosahedron(sm, center, 1.);
  CGAL::Subdivision_method_3::Loop_subdivision(sm, CGAL::parameters::number_of_iterations(levels));
  for(auto v : vertices(sm)) {
    const K::Vector_3 d = sm.point(v) - center;
    sm.point(v) = center + d / std::sqrt(d.squared_length());
  }
  Soup soup;
  PMP::polygon_mesh_to_polygon_soup(sm, soup.points, soup.triangles);
  return soup;
}

// two disjoint unit spheres; the second one's vertices come after the first's
Soup two_spheres_soup(int levels)
{
  Soup a = sphere_soup(levels), b = sphere_soup(levels, Point(3, 0, 0));
  const std::size_t offset = a.points.size();
  a.points.insert(a.points.end(), b.points.begin(), b.points.end());
  for(auto t : b.triangles)
    a.triangles.push_back({{ t[0] + offset, t[1] + offset, t[2] + offset }});
  return a;
}

template <typename Mesh>
Mesh mesh_from_soup(const Soup& soup)
{
  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(soup.points, soup.triangles, mesh);
  return mesh;
}

// built once: Loop subdivision and Polyhedron_3 construction are not free
const Soup& sphere3() { static const Soup s = sphere_soup(3); return s; }
const Soup& sphere4() { static const Soup s = sphere_soup(4); return s; }
const Soup& two_spheres3() { static const Soup s = two_spheres_soup(3); return s; }

// ---------------------------------------------------------------------------
// The three models behind one switch, so every check runs on each of them.

enum class Model { heat, exact, dijkstra };
const Model all_models[] = { Model::heat, Model::exact, Model::dijkstra };

const char* name(Model m)
{
  switch(m) {
    case Model::heat: return "heat";
    case Model::exact: return "exact";
    case Model::dijkstra: return "dijkstra";
  }
  return "?";
}

template <typename Mesh>
IRS::Geodesic_distance_matrix matrix_of(Model m, const Mesh& mesh, const std::vector<std::size_t>& sources)
{
  switch(m) {
    case Model::heat: {
      IRS::Heat_method_geodesic_oracle<Mesh> oracle(mesh);
      return IRS::compute_geodesic_distance_matrix(oracle, sources);
    }
    case Model::exact: {
      IRS::Exact_geodesic_oracle<Mesh> oracle(mesh);
      return IRS::compute_geodesic_distance_matrix(oracle, sources);
    }
    case Model::dijkstra: {
      IRS::Dijkstra_geodesic_oracle<Mesh> oracle(mesh);
      return IRS::compute_geodesic_distance_matrix(oracle, sources);
    }
  }
  return IRS::Geodesic_distance_matrix();
}

bool bit_identical(const IRS::Geodesic_distance_matrix& a, const IRS::Geodesic_distance_matrix& b)
{
  if(a.sources() != b.sources() || a.number_of_vertices() != b.number_of_vertices())
    return false;
  for(std::size_t i = 0; i < a.number_of_sources(); ++i)
    if(std::memcmp(a.row(i), b.row(i), a.number_of_vertices() * sizeof(float)) != 0)
      return false;
  return true;
}

// largest |a - b| over all entries (infinite entries must match exactly)
double max_difference(const IRS::Geodesic_distance_matrix& a, const IRS::Geodesic_distance_matrix& b)
{
  double m = 0;
  for(std::size_t i = 0; i < a.number_of_sources(); ++i)
    for(std::size_t v = 0; v < a.number_of_vertices(); ++v) {
      if(std::isinf(a(i, v)) || std::isinf(b(i, v))) {
        if(a(i, v) != b(i, v)) return std::numeric_limits<double>::infinity();
        continue;
      }
      m = (std::max)(m, double(std::abs(a(i, v) - b(i, v))));
    }
  return m;
}

std::string percent(double x)
{
  std::ostringstream s;
  s << std::setprecision(3) << 100 * x << " %";
  return s.str();
}

} // namespace

// ---------------------------------------------------------------------------
// Typed tests: the same checks on Surface_mesh and Polyhedron_3.

template <typename Mesh>
class Geodesics : public ::testing::Test {};
typedef ::testing::Types<Surface_mesh, Polyhedron> Mesh_types;
TYPED_TEST_SUITE(Geodesics, Mesh_types);

// Against great-circle distances acos(p.q) on a unit sphere of 2562 vertices.
// Errors are relative to the diameter pi. The polyhedral surface is slightly
// inside the sphere, so even exact polyhedral geodesics are a little short.
TYPED_TEST(Geodesics, MatchGreatCircleDistances)
{
  typedef TypeParam Mesh;
  const Soup& soup = sphere4();
  const Mesh mesh = mesh_from_soup<Mesh>(soup);

  // sources spread over the sphere; few for the exact model, which is slow
  const std::vector<std::size_t> many = IRS::farthest_point_samples(
    mesh, IRS::parameters::number_of_samples(16).random_seed(1u));
  const std::vector<std::size_t> few(many.begin(), many.begin() + 8);

  // mean and max allowed error (fraction of the diameter), set from measurement
  // (measured mean / max: heat 0.43 % / 1.06 %, exact 0.03 % / 0.07 %, Dijkstra 3.1 % / 6.5 %)
  struct Bound { Model model; double mean, max; };
  const Bound bounds[] = { { Model::heat, 0.0075, 0.015 },
                           { Model::exact, 0.001, 0.002 },
                           { Model::dijkstra, 0.04, 0.08 } };
  for(const Bound& b : bounds) {
    const std::vector<std::size_t>& sources = (b.model == Model::exact) ? few : many;
    const IRS::Geodesic_distance_matrix d = matrix_of(b.model, mesh, sources);
    double sum = 0, worst = 0;
    for(std::size_t i = 0; i < sources.size(); ++i)
      for(std::size_t v = 0; v < d.number_of_vertices(); ++v) {
        const Point& p = soup.points[sources[i]];
        const Point& q = soup.points[v];
        const double dot = (std::max)(-1., (std::min)(1., p.x() * q.x() + p.y() * q.y() + p.z() * q.z()));
        const double error = std::abs(double(d(i, v)) - std::acos(dot)) / pi;
        sum += error;
        worst = (std::max)(worst, error);
      }
    const double mean = sum / double(sources.size() * d.number_of_vertices());
    std::cout << "[ sphere ] " << name(b.model) << ": mean error " << percent(mean)
              << ", max error " << percent(worst) << " of the diameter (" << sources.size()
              << " sources x " << d.number_of_vertices() << " vertices)" << std::endl;
    this->RecordProperty(std::string(name(b.model)) + "_mean_error", percent(mean));
    this->RecordProperty(std::string(name(b.model)) + "_max_error", percent(worst));
    EXPECT_LT(mean, b.mean) << name(b.model);
    EXPECT_LT(worst, b.max) << name(b.model);
  }
}

// d(a,b) against d(b,a) over pairs of samples, relative to the diameter pi.
// Dijkstra and exact are symmetric up to float rounding; the heat method is not
// symmetric by construction, only approximately.
TYPED_TEST(Geodesics, SymmetricOnSamplePairs)
{
  typedef TypeParam Mesh;
  const Mesh mesh = mesh_from_soup<Mesh>(sphere3());
  const std::vector<std::size_t> samples = IRS::farthest_point_samples(
    mesh, IRS::parameters::number_of_samples(12).random_seed(3u));

  // (measured: heat 0.30 %, exact and Dijkstra below float resolution)
  struct Tolerance { Model model; double relative; };
  const Tolerance tolerances[] = { { Model::heat, 0.005 }, { Model::exact, 1e-6 }, { Model::dijkstra, 1e-6 } };
  for(const Tolerance& t : tolerances) {
    const IRS::Geodesic_distance_matrix d = matrix_of(t.model, mesh, samples);
    double worst = 0;
    for(std::size_t i = 0; i < samples.size(); ++i)
      for(std::size_t j = 0; j < samples.size(); ++j)
        worst = (std::max)(worst, std::abs(double(d(i, samples[j])) - double(d(j, samples[i]))) / pi);
    std::cout << "[ symmetry ] " << name(t.model) << ": max |d(a,b) - d(b,a)| = " << percent(worst)
              << " of the diameter" << std::endl;
    this->RecordProperty(std::string(name(t.model)) + "_asymmetry", percent(worst));
    EXPECT_LE(worst, t.relative) << name(t.model);
  }
}

// Two disjoint spheres: +infinity across, finite within, and within a sphere
// the same distances as for that sphere alone.
TYPED_TEST(Geodesics, TwoComponentsGiveInfinityAcross)
{
  typedef TypeParam Mesh;
  const Mesh both = mesh_from_soup<Mesh>(two_spheres3());
  const Mesh one = mesh_from_soup<Mesh>(sphere3());
  const std::size_t n = sphere3().points.size();
  ASSERT_EQ(num_vertices(both), 2 * n);

  const std::vector<std::size_t> sources = { 0, 5, n + 0, n + 5 };
  const std::vector<std::size_t> sources_alone = { 0, 5, 0, 5 };
  for(Model m : all_models) {
    const IRS::Geodesic_distance_matrix d = matrix_of(m, both, sources);
    const IRS::Geodesic_distance_matrix alone = matrix_of(m, one, sources_alone);
    for(std::size_t i = 0; i < sources.size(); ++i) {
      const std::size_t own = sources[i] < n ? 0 : n, other = sources[i] < n ? n : 0;
      std::size_t finite = 0, infinite = 0;
      double worst = 0;
      for(std::size_t v = 0; v < n; ++v) {
        finite += std::isfinite(d(i, own + v)) ? 1 : 0;
        infinite += (d(i, other + v) == inf) ? 1 : 0;
        worst = (std::max)(worst, double(std::abs(d(i, own + v) - alone(i, v))));
      }
      EXPECT_EQ(finite, n) << name(m);
      EXPECT_EQ(infinite, n) << name(m);
      EXPECT_EQ(d(i, sources[i]), 0.f) << name(m);
      EXPECT_LE(worst, 1e-6) << name(m) << ": a component differs from the same sphere alone";
    }
  }
}

// An isolated vertex is a component of its own: 0 to itself, +infinity elsewhere.
TYPED_TEST(Geodesics, IsolatedVertex)
{
  typedef TypeParam Mesh;
  Mesh mesh = mesh_from_soup<Mesh>(sphere3());
  const std::size_t n = num_vertices(mesh);
  auto v = add_vertex(mesh);
  put(get(CGAL::vertex_point, mesh), v, Point(5, 5, 5));
  const std::vector<std::size_t> sources = { n, 0 };
  for(Model m : all_models) {
    const IRS::Geodesic_distance_matrix d = matrix_of(m, mesh, sources);
    ASSERT_EQ(d.number_of_vertices(), n + 1) << name(m);
    EXPECT_EQ(d(0, n), 0.f) << name(m);
    EXPECT_EQ(d(0, 0), inf) << name(m);
    EXPECT_EQ(d(1, n), inf) << name(m);
    EXPECT_TRUE(std::isfinite(d(1, n - 1))) << name(m);
  }
}

TYPED_TEST(Geodesics, FarthestPointSamples)
{
  typedef TypeParam Mesh;
  const Mesh mesh = mesh_from_soup<Mesh>(sphere3());
  const std::size_t n = num_vertices(mesh);

  const auto a = IRS::farthest_point_samples(mesh, IRS::parameters::number_of_samples(50).random_seed(7u));
  const auto b = IRS::farthest_point_samples(mesh, IRS::parameters::number_of_samples(50).random_seed(7u));
  const auto c = IRS::farthest_point_samples(mesh, IRS::parameters::number_of_samples(50).random_seed(8u));
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
  ASSERT_EQ(a.size(), 50u);
  EXPECT_EQ(std::set<std::size_t>(a.begin(), a.end()).size(), 50u);
  for(std::size_t s : a)
    EXPECT_LT(s, n);

  // CGAL's own number_of_samples is honoured too
  EXPECT_EQ(IRS::farthest_point_samples(mesh, CGAL::parameters::number_of_samples(9)).size(), 9u);

  // default: min(3000, ceil(n / 4)) distinct samples
  const auto all = IRS::farthest_point_samples(mesh);
  EXPECT_EQ(all.size(), (std::min)(std::size_t(3000), (n + 3) / 4));
  EXPECT_EQ(std::set<std::size_t>(all.begin(), all.end()).size(), all.size());

  // the farthest-point property, checked with the Dijkstra oracle (same edge metric):
  // sample k is at maximal distance from samples 0 .. k-1 (float tolerance)
  IRS::Dijkstra_geodesic_oracle<Mesh> oracle(mesh);
  const IRS::Geodesic_distance_matrix d = IRS::compute_geodesic_distance_matrix(oracle, a);
  std::vector<float> nearest(n, inf);
  for(std::size_t k = 0; k + 1 < a.size(); ++k) {
    for(std::size_t v = 0; v < n; ++v)
      nearest[v] = (std::min)(nearest[v], d(k, v));
    const float farthest = *std::max_element(nearest.begin(), nearest.end());
    EXPECT_NEAR(nearest[a[k + 1]], farthest, 1e-5f) << "sample " << k + 1;
  }
}

TYPED_TEST(Geodesics, FarthestPointSamplesCoverEveryComponent)
{
  typedef TypeParam Mesh;
  const Mesh mesh = mesh_from_soup<Mesh>(two_spheres3());
  const std::size_t n = sphere3().points.size();
  for(unsigned seed : { 0u, 1u, 2u, 3u }) {
    const auto s = IRS::farthest_point_samples(mesh, IRS::parameters::number_of_samples(10).random_seed(seed));
    ASSERT_EQ(s.size(), 10u);
    // the second sample is at infinite distance from the first: in the other sphere
    EXPECT_NE(s[0] < n, s[1] < n) << "seed " << seed;
    const std::size_t in_first = std::count_if(s.begin(), s.end(), [n](std::size_t v) { return v < n; });
    EXPECT_GE(in_first, 1u);
    EXPECT_LE(in_first, 9u);
  }
}

TYPED_TEST(Geodesics, FarthestPointSamplesRejectBadCounts)
{
  typedef TypeParam Mesh;
  const Mesh mesh = mesh_from_soup<Mesh>(sphere3());
  const int n = static_cast<int>(num_vertices(mesh));
  try {
    IRS::farthest_point_samples(mesh, IRS::parameters::number_of_samples(n + 1));
    ADD_FAILURE() << "no exception for too many samples";
  } catch(const IRS::Input_error& e) {
    EXPECT_EQ(e.problem(), IRS::Input_problem::too_many_samples);
  }
  try {
    IRS::farthest_point_samples(mesh, IRS::parameters::number_of_samples(0));
    ADD_FAILURE() << "no exception for 0 samples";
  } catch(const IRS::Input_error& e) {
    EXPECT_EQ(e.problem(), IRS::Input_problem::invalid_parameter);
  }
  EXPECT_EQ(IRS::farthest_point_samples(mesh, IRS::parameters::number_of_samples(n)).size(), std::size_t(n));
}

TYPED_TEST(Geodesics, RejectNonTriangleAndEmptyMeshes)
{
  typedef TypeParam Mesh;
  Mesh cube; // six quadrilaterals
  CGAL::make_hexahedron(Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 0),
                        Point(0, 1, 1), Point(0, 0, 1), Point(1, 0, 1), Point(1, 1, 1), cube);
  const Mesh empty;
  auto expect_problem = [](IRS::Input_problem expected, auto&& build) {
    try {
      build();
      ADD_FAILURE() << "no exception";
    } catch(const IRS::Input_error& e) {
      EXPECT_EQ(e.problem(), expected) << e.what();
    }
  };
  expect_problem(IRS::Input_problem::not_triangle_mesh, [&] { IRS::Heat_method_geodesic_oracle<Mesh> o(cube); });
  expect_problem(IRS::Input_problem::not_triangle_mesh, [&] { IRS::Exact_geodesic_oracle<Mesh> o(cube); });
  expect_problem(IRS::Input_problem::not_triangle_mesh, [&] { IRS::Dijkstra_geodesic_oracle<Mesh> o(cube); });
  expect_problem(IRS::Input_problem::empty_mesh, [&] { IRS::Heat_method_geodesic_oracle<Mesh> o(empty); });
  expect_problem(IRS::Input_problem::empty_mesh, [&] { IRS::Exact_geodesic_oracle<Mesh> o(empty); });
  expect_problem(IRS::Input_problem::empty_mesh, [&] { IRS::Dijkstra_geodesic_oracle<Mesh> o(empty); });
  expect_problem(IRS::Input_problem::empty_mesh, [&] { IRS::farthest_point_samples(empty); });

  const Mesh mesh = mesh_from_soup<Mesh>(sphere3());
  const std::size_t n = num_vertices(mesh);
  std::vector<float> row(n);
  IRS::Heat_method_geodesic_oracle<Mesh> heat(mesh, IRS::parameters::number_of_threads(1));
  IRS::Exact_geodesic_oracle<Mesh> exact(mesh);
  IRS::Dijkstra_geodesic_oracle<Mesh> dijkstra(mesh);
  expect_problem(IRS::Input_problem::invalid_parameter, [&] { heat.distances_from(n, row.data()); });
  expect_problem(IRS::Input_problem::invalid_parameter, [&] { exact.distances_from(n, row.data()); });
  expect_problem(IRS::Input_problem::invalid_parameter, [&] { dijkstra.distances_from(n, row.data()); });
  expect_problem(IRS::Input_problem::invalid_parameter,
                 [&] { IRS::compute_geodesic_distance_matrix(dijkstra, std::vector<std::size_t>{ 0, n }); });
  expect_problem(IRS::Input_problem::invalid_parameter, [&] {
    IRS::Heat_method_geodesic_oracle<Mesh> o(mesh, IRS::parameters::number_of_threads(0));
  });
}

// ---------------------------------------------------------------------------
// Surface_mesh and Polyhedron_3 with the same indexed geometry give the same
// distances: the oracles build their internal meshes and graphs canonically.

TEST(GeodesicsAcrossMeshTypes, SameDistances)
{
  const Surface_mesh sm = mesh_from_soup<Surface_mesh>(sphere3());
  const Polyhedron poly = mesh_from_soup<Polyhedron>(sphere3());
  const std::vector<std::size_t> sources = IRS::farthest_point_samples(
    sm, IRS::parameters::number_of_samples(6).random_seed(11u));
  EXPECT_EQ(sources, IRS::farthest_point_samples(poly, IRS::parameters::number_of_samples(6).random_seed(11u)));

  for(Model m : all_models) {
    const IRS::Geodesic_distance_matrix a = matrix_of(m, sm, sources), b = matrix_of(m, poly, sources);
    const double difference = max_difference(a, b);
    std::cout << "[ mesh types ] " << name(m) << ": max |Surface_mesh - Polyhedron_3| = " << difference
              << (bit_identical(a, b) ? " (bit-identical)" : "") << std::endl;
    if(m == Model::heat)
      EXPECT_LE(difference, 1e-5 * pi) << name(m); // near-identical is what is promised
    else
      EXPECT_TRUE(bit_identical(a, b)) << name(m);
  }
}

// Vertex index maps given by the user are honoured: a reversed numbering
// permutes the columns.
TEST(GeodesicsAcrossMeshTypes, UserVertexIndexMap)
{
  const Surface_mesh sm = mesh_from_soup<Surface_mesh>(sphere3());
  const std::size_t n = num_vertices(sm);
  Surface_mesh copy = sm;
  auto rev = copy.add_property_map<Surface_mesh::Vertex_index, std::size_t>("v:reversed", 0).first;
  for(auto v : vertices(copy))
    rev[v] = n - 1 - std::size_t(v);
  IRS::Dijkstra_geodesic_oracle<Surface_mesh> plain(copy);
  IRS::Dijkstra_geodesic_oracle<Surface_mesh> permuted(copy, IRS::parameters::vertex_index_map(rev));
  IRS::Heat_method_geodesic_oracle<Surface_mesh> heat_plain(copy, IRS::parameters::number_of_threads(1));
  IRS::Heat_method_geodesic_oracle<Surface_mesh> heat_permuted(
    copy, IRS::parameters::vertex_index_map(rev).number_of_threads(1));
  std::vector<float> a(n), b(n), c(n), d(n);
  plain.distances_from(3, a.data());
  permuted.distances_from(n - 1 - 3, b.data());
  heat_plain.distances_from(3, c.data());
  heat_permuted.distances_from(n - 1 - 3, d.data());
  for(std::size_t v = 0; v < n; ++v) {
    EXPECT_EQ(a[v], b[n - 1 - v]);
    EXPECT_NEAR(c[v], d[n - 1 - v], 1e-5f);
  }
}

// ---------------------------------------------------------------------------
// Determinism at any thread count.

TEST(GeodesicsThreads, HeatWorkersAnswerIdentically)
{
  const Surface_mesh mesh = mesh_from_soup<Surface_mesh>(sphere3());
  const std::size_t n = num_vertices(mesh);
  IRS::Heat_method_geodesic_oracle<Surface_mesh> oracle(mesh, IRS::parameters::number_of_threads(3));
  ASSERT_EQ(oracle.number_of_workers(), 3u);
  std::vector<float> first(n), other(n), scratch(n);
  for(std::size_t source : { std::size_t(0), std::size_t(17), n - 1 }) {
    oracle.distances_from_worker(0, source, first.data());
    // worker 1 fresh, worker 2 after an unrelated query: same bits
    oracle.distances_from_worker(1, source, other.data());
    EXPECT_EQ(0, std::memcmp(first.data(), other.data(), n * sizeof(float))) << "source " << source;
    oracle.distances_from_worker(2, (source + 101) % n, scratch.data());
    oracle.distances_from_worker(2, source, other.data());
    EXPECT_EQ(0, std::memcmp(first.data(), other.data(), n * sizeof(float))) << "source " << source;
    oracle.distances_from(source, other.data());
    EXPECT_EQ(0, std::memcmp(first.data(), other.data(), n * sizeof(float))) << "source " << source;
  }
}

TEST(GeodesicsThreads, MatrixIsBitIdenticalWithOneAndTwoThreads)
{
#ifndef CGAL_LINKED_WITH_TBB
  GTEST_SKIP() << "TBB is not linked";
#else
  const Surface_mesh mesh = mesh_from_soup<Surface_mesh>(sphere4());
  const std::vector<std::size_t> sources = IRS::farthest_point_samples(
    mesh, IRS::parameters::number_of_samples(64).random_seed(5u));
  IRS::Heat_method_geodesic_oracle<Surface_mesh> heat(mesh, IRS::parameters::number_of_threads(2));
  IRS::Dijkstra_geodesic_oracle<Surface_mesh> dijkstra(mesh);

  auto with_threads = [&](int threads, const auto& oracle) {
    IRS::Geodesic_distance_matrix m;
    tbb::task_arena arena(threads);
    arena.execute([&] { m = IRS::compute_geodesic_distance_matrix<CGAL::Parallel_tag>(oracle, sources); });
    return m;
  };
  EXPECT_TRUE(bit_identical(with_threads(1, heat), with_threads(2, heat)));
  EXPECT_TRUE(bit_identical(with_threads(1, dijkstra), with_threads(2, dijkstra)));
  EXPECT_TRUE(bit_identical(with_threads(2, heat),
                            IRS::compute_geodesic_distance_matrix<CGAL::Sequential_tag>(heat, sources)));
#endif
}
