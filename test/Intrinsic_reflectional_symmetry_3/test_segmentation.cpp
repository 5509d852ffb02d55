// Symmetry-aware segmentation (paper Sec. 4.1): on two snowmen joined by a
// tube, the pure symmetry segmentation and the merging of the default
// over-segmentation give one segment per snowman, head and body together
// (the cut follows the symmetry structure, not the concavities of the necks);
// on generated shapes every face gets a segment and every segment is
// connected, also with an over-segmenter whose parts are disconnected; the
// same result on Surface_mesh and Polyhedron_3; the default over-segmenter's
// graph cut is a correct alpha expansion (CGAL 5.5.1's default
// Boykov-Kolmogorov MaxFlow cut applies only the first move); bad input
// throws Input_error.
//
// Similar pairs come from the known mirror maps of the symmetries under test
// (as in test_curves: sample i is similar to the sample nearest to its mirror
// vertex, plus 2 % random pairs), except on the bent capsule, which runs the
// package's signatures.

// The heat-method oracle first: a header it pulls in must come before
// shape_generators.h (include-order issue in internal/component_meshes.h).
#include <CGAL/Intrinsic_reflectional_symmetry_3/Heat_method_geodesic_oracle.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/irsa_curves.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/irsa_transform.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/sampling.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/segmentation.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/shape_generators.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/signatures.h>

#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Random.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/mesh_segmentation.h> // CGAL's public segmentation, default graph cut, for comparison

#include <gtest/gtest.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include "test_support.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <map>
#include <utility>
#include <vector>

namespace IRS = CGAL::Intrinsic_reflectional_symmetry_3;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef CGAL::Polyhedron_3<K> Polyhedron;
typedef std::vector<std::pair<std::size_t, std::size_t>> Pairs;

namespace {

using irs_test::expect_cancelled;
using irs_test::mirror_similar_pairs;
using irs_test::Recording_callback;

// samples to curves; similar pairs from the signatures if `which` is empty
template <typename TM>
struct Pipeline
{
  IRS::Geodesic_distance_matrix D;
  std::vector<IRS::Irsa_curve> curves;

  void run(const TM& tm, std::size_t number_of_samples, const std::vector<IRS::Known_symmetry>& symmetries,
           const std::vector<std::size_t>& which)
  {
    const IRS::Heat_method_geodesic_oracle<TM> oracle(tm);
    const std::vector<std::size_t> samples =
      IRS::farthest_point_samples(tm, IRS::parameters::number_of_samples(number_of_samples).random_seed(1u));
    D = IRS::compute_geodesic_distance_matrix(oracle, samples);
    Pairs similar;
    if(which.empty())
      IRS::similar_sample_pairs(IRS::compute_sdf_signatures(tm, D), std::back_inserter(similar));
    else
      similar = mirror_similar_pairs(symmetries, which, D, 0.02, 7);
    auto tau = get(CGAL::dynamic_vertex_property_t<double>(), tm);
    const IRS::Irsa_voting_result voting =
      IRS::compute_irsa_transform(tm, D, similar, tau,
                                  IRS::parameters::maximum_number_of_voting_pairs(std::size_t(3000)).random_seed(3u));
    curves.clear();
    IRS::extract_irsa_curves(tm, D, voting, tau, std::back_inserter(curves));
  }
};

template <typename TM>
struct Face_labels
{
  std::vector<long> values; // by face index
  explicit Face_labels(const TM& tm) : values(num_faces(tm), -7) {}
  auto map(const TM& tm) { return boost::make_iterator_property_map(values.begin(), CGAL::get_initialized_face_index_map(tm)); }
};

// every face has a label in [0, n), all n labels are used, and each label is one edge-connected set of faces
template <typename TM>
void expect_connected_cover(const TM& tm, const std::vector<long>& label, std::size_t n, const char* what)
{
  SCOPED_TRACE(what);
  ASSERT_EQ(label.size(), std::size_t(num_faces(tm)));
  ASSERT_GE(n, 1u);
  std::vector<std::size_t> size(n, 0);
  for(long l : label)
  {
    ASSERT_GE(l, 0);
    ASSERT_LT(std::size_t(l), n);
    ++size[std::size_t(l)];
  }
  for(std::size_t s : size) EXPECT_GT(s, 0u);
  const auto fim = CGAL::get_initialized_face_index_map(tm);
  std::vector<std::vector<std::size_t>> adj(label.size());
  for(auto f : faces(tm))
    for(auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm))
    {
      const auto g = face(opposite(h, tm), tm);
      if(g != boost::graph_traits<TM>::null_face()) adj[get(fim, f)].push_back(get(fim, g));
    }
  std::vector<char> seen(label.size(), 0), label_seen(n, 0);
  for(std::size_t s = 0; s < label.size(); ++s)
  {
    if(seen[s]) continue;
    EXPECT_FALSE(label_seen[std::size_t(label[s])]) << "segment " << label[s] << " is not connected";
    label_seen[std::size_t(label[s])] = 1;
    std::vector<std::size_t> stack(1, s);
    seen[s] = 1;
    while(!stack.empty())
    {
      const std::size_t f = stack.back();
      stack.pop_back();
      for(std::size_t g : adj[f])
        if(!seen[g] && label[g] == label[s]) { seen[g] = 1; stack.push_back(g); }
    }
  }
}

// an over-segmenter whose part ids are scattered (face index modulo 3): every part is disconnected
struct Scattered_over_segmenter
{
  template <class TM, class VPM, class FacePartMap>
  std::size_t operator()(const TM& tm, VPM, FacePartMap part) const
  {
    const auto fim = CGAL::get_initialized_face_index_map(tm);
    for(auto f : faces(tm)) put(part, f, std::size_t(get(fim, f)) % 3);
    return 3;
  }
};

} // namespace

// ---------------------------------------------------------------- two snowmen

TEST(Segmentation, TwoSnowmenAreCutAlongTheirSymmetryNotTheirNecks)
{
  const auto shape = IRS::generate_two_snowmen<Mesh>(3000);
  const Mesh& m = shape.mesh;
  Pipeline<Mesh> p;
  p.run(m, 600, shape.symmetries, {0, 1});
  ASSERT_GE(p.curves.size(), 2u);

  // faces of each snowman (all three vertices where its partial mirror is
  // defined), split at mid height: lower body vs. middle ball and head, which
  // a concavity-based segmentation separates at the neck
  const double scale[2] = {1., 0.7};
  std::vector<int> snowman(num_faces(m), -1);
  std::vector<char> upper(num_faces(m), 0);
  for(auto f : faces(m))
  {
    for(int k = 0; k < 2; ++k)
    {
      bool in = true;
      double z = 0.;
      for(auto v : CGAL::vertices_around_face(halfedge(f, m), m))
      {
        in = in && shape.symmetries[k].mirror[v.idx()] >= 0;
        z += m.point(v).z() / 3.;
      }
      if(in) { snowman[f.idx()] = k; upper[f.idx()] = z > 2.2 * scale[k]; }
    }
  }

  Face_labels<Mesh> pure(m), merged(m);
  const std::size_t n_pure = IRS::symmetry_segmentation(m, p.D, p.curves, pure.map(m));
  const std::size_t n_merged = IRS::symmetry_aware_segmentation(m, p.D, p.curves, merged.map(m));
  expect_connected_cover(m, pure.values, n_pure, "pure");
  expect_connected_cover(m, merged.values, n_merged, "merged");

  // CGAL's SDF segmentation (package graph cut) with as many segments, for the record
  const auto fim = CGAL::get_initialized_face_index_map(m);
  const std::vector<double> sdf =
    IRS::internal::segmentation_sdf_values(m, get(CGAL::vertex_point, m), fim, K(), 2. / 3. * CGAL_PI, 25);
  std::vector<std::size_t> sdf_seg;
  const std::size_t n_sdf = IRS::internal::sdf_graph_cut_segmentation(m, get(CGAL::vertex_point, m), fim, K(), sdf,
                                                                      n_merged, 0.26, sdf_seg);

  auto check = [&](const std::vector<long>& seg, const char* what, bool expect) {
    // the majority segment of each snowman's lower part
    std::map<long, std::size_t> count[2];
    for(std::size_t f = 0; f < seg.size(); ++f)
      if(snowman[f] >= 0 && !upper[f]) ++count[snowman[f]][seg[f]];
    long main[2];
    double own_share[2], upper_share[2];
    for(int k = 0; k < 2; ++k)
    {
      main[k] = std::max_element(count[k].begin(), count[k].end(),
                                 [](const auto& a, const auto& b) { return a.second < b.second; })->first;
      std::size_t total = 0, in = 0, up = 0, up_in = 0;
      for(std::size_t f = 0; f < seg.size(); ++f)
        if(snowman[f] == k)
        {
          ++total; in += seg[f] == main[k];
          if(upper[f]) { ++up; up_in += seg[f] == main[k]; }
        }
      own_share[k] = double(in) / double(total);
      upper_share[k] = double(up_in) / double(up);
    }
    std::cout << "[ two snowmen, " << what << " ] main segments " << main[0] << ", " << main[1]
              << "; share of each snowman in its main segment " << own_share[0] << ", " << own_share[1]
              << "; of its upper part (above the neck) " << upper_share[0] << ", " << upper_share[1] << std::endl;
    if(!expect) return;
    SCOPED_TRACE(what);
    EXPECT_NE(main[0], main[1]) << "the two snowmen must be separated";
    for(int k = 0; k < 2; ++k)
    {
      EXPECT_GE(own_share[k], 0.9);
      EXPECT_GE(upper_share[k], 0.9) << "head and body of a snowman must not be cut at the neck";
    }
  };
  check(pure.values, "pure symmetry", true);
  check(merged.values, "merged over-segmentation", true);
  std::cout << "[ two snowmen ] segments: pure " << n_pure << ", merged " << n_merged << ", CGAL SDF " << n_sdf
            << std::endl;
  check(std::vector<long>(sdf_seg.begin(), sdf_seg.end()), "CGAL SDF, same number of clusters", false);
}

// ---------------------------------------------------------------- cover, connectivity, genericity

TEST(Segmentation, EveryFaceInOneConnectedSegment)
{
  {
    const auto shape = IRS::generate_bent_capsule<Mesh>(1500);
    Pipeline<Mesh> p;
    p.run(shape.mesh, 400, shape.symmetries, {}); // the package's signatures
    ASSERT_FALSE(p.curves.empty());
    const Mesh& m = shape.mesh;
    Face_labels<Mesh> a(m), b(m), c(m), d(m);
    expect_connected_cover(m, a.values, IRS::symmetry_segmentation(m, p.D, p.curves, a.map(m)), "bent capsule, pure");
    expect_connected_cover(m, b.values, IRS::symmetry_aware_segmentation(m, p.D, p.curves, b.map(m)),
                           "bent capsule, merged");
    // a disconnected over-segmentation: parts are split into connected pieces
    expect_connected_cover(m, c.values,
                           IRS::symmetry_aware_segmentation(m, p.D, p.curves, c.map(m),
                                                            IRS::parameters::over_segmenter(Scattered_over_segmenter())
                                                              .minimum_segment_area(0.)),
                           "bent capsule, scattered parts");
    // no curve: no region; the whole (connected) mesh is one segment
    std::vector<IRS::Irsa_curve> none;
    EXPECT_EQ(IRS::symmetry_segmentation(m, p.D, none, d.map(m)), 1u);
    expect_connected_cover(m, d.values, 1, "no curve");
    // with the paper's merging, off-axis parts kept
    Face_labels<Mesh> e(m);
    expect_connected_cover(m, e.values,
                           IRS::symmetry_aware_segmentation(m, p.D, p.curves, e.map(m),
                                                            IRS::parameters::keep_off_axis_parts(true)),
                           "bent capsule, off-axis parts kept");
  }
  {
    // regions that leave faces uncovered: pieces of no region are segments or join a neighbour
    const auto shape = IRS::generate_ellipsoid<Mesh>(800);
    const Mesh& m = shape.mesh;
    Pipeline<Mesh> p;
    p.run(m, 200, shape.symmetries, {0});
    ASSERT_FALSE(p.curves.empty());
    Face_labels<Mesh> region(m), part(m), a(m), b(m);
    IRS::symmetric_regions(m, p.D, p.curves, region.map(m));
    // fake a hole in the regions: the faces of the cap x > 0.6 of no region
    for(auto f : faces(m))
      if(m.point(target(halfedge(f, m), m)).x() > 0.6) region.values[f.idx()] = -1;
    const std::size_t n_parts = IRS::Sdf_over_segmenter()(m, get(CGAL::vertex_point, m), part.map(m));
    EXPECT_GE(n_parts, 1u);
    const std::size_t na = IRS::merge_over_segmentation(m, region.map(m), part.map(m), a.map(m));
    const std::size_t nb = IRS::merge_over_segmentation(m, region.map(m), part.map(m), b.map(m),
                                                        IRS::parameters::merge_uncovered_parts(true));
    expect_connected_cover(m, a.values, na, "ellipsoid, merged");
    expect_connected_cover(m, b.values, nb, "ellipsoid, merged, uncovered joined");
    EXPECT_LE(nb, na);
  }
}

TEST(Segmentation, PartStraddlingTwoRegionsStaysApart)
{
  // Two regions (x < 0, x >= 0) and three parts: the lower half (z < 0), which
  // straddles both regions, and the two upper quarters, each in one region.
  const auto shape = IRS::generate_ellipsoid<Mesh>(800);
  const Mesh& m = shape.mesh;
  Face_labels<Mesh> region(m), part(m);
  for(auto f : faces(m))
  {
    const Point c = CGAL::centroid(m.point(target(halfedge(f, m), m)), m.point(target(next(halfedge(f, m), m), m)),
                                   m.point(source(halfedge(f, m), m)));
    region.values[f.idx()] = c.x() < 0. ? 0 : 1;
    part.values[f.idx()] = c.z() < 0. ? 0 : (c.x() < 0. ? 1 : 2);
  }
  auto segments_of = [&](double coverage, Face_labels<Mesh>& seg) {
    return IRS::merge_over_segmentation(m, region.map(m), part.map(m), seg.map(m),
                                        IRS::parameters::minimum_region_coverage(coverage));
  };
  // default (0.8): the lower half is covered about half by each region: a segment of its own
  Face_labels<Mesh> d(m), paper(m), loose(m);
  EXPECT_EQ(IRS::merge_over_segmentation(m, region.map(m), part.map(m), d.map(m)), 3u);
  std::map<long, long> of_part; // part -> its segment: one segment per part
  for(auto f : faces(m))
  {
    const auto it = of_part.emplace(part.values[f.idx()], d.values[f.idx()]).first;
    EXPECT_EQ(it->second, d.values[f.idx()]);
  }
  EXPECT_EQ(of_part.size(), 3u);
  // the paper's rule (0), and any coverage below the larger share: the lower half joins a region
  EXPECT_EQ(segments_of(0., paper), 2u);
  EXPECT_EQ(segments_of(0.4, loose), 2u);
  EXPECT_EQ(paper.values, loose.values);
  expect_connected_cover(m, paper.values, 2, "paper's rule");
}

TEST(Segmentation, SameOnSurfaceMeshAndPolyhedron)
{
  const auto shape = IRS::generate_snowman<Mesh>(1200);
  const auto poly = IRS::generate_snowman<Polyhedron>(1200);
  Pipeline<Mesh> p;
  p.run(shape.mesh, 300, shape.symmetries, {0});
  Pipeline<Polyhedron> pp;
  pp.run(poly.mesh, 300, poly.symmetries, {0});
  ASSERT_FALSE(p.curves.empty());
  ASSERT_EQ(p.curves.size(), pp.curves.size());
  Face_labels<Mesh> a(shape.mesh), b(shape.mesh);
  Face_labels<Polyhedron> pa(poly.mesh), pb(poly.mesh);
  const std::size_t na = IRS::symmetry_segmentation(shape.mesh, p.D, p.curves, a.map(shape.mesh));
  const std::size_t nb = IRS::symmetry_aware_segmentation(shape.mesh, p.D, p.curves, b.map(shape.mesh),
                                                          IRS::parameters::keep_off_axis_parts(true));
  EXPECT_EQ(IRS::symmetry_segmentation(poly.mesh, pp.D, pp.curves, pa.map(poly.mesh)), na);
  EXPECT_EQ(IRS::symmetry_aware_segmentation(poly.mesh, pp.D, pp.curves, pb.map(poly.mesh),
                                             IRS::parameters::keep_off_axis_parts(true)),
            nb);
  EXPECT_EQ(pa.values, a.values);
  EXPECT_EQ(pb.values, b.values);
  // deterministic, and the same with Sequential_tag
  Face_labels<Mesh> c(shape.mesh);
  EXPECT_EQ(IRS::symmetry_aware_segmentation<CGAL::Sequential_tag>(shape.mesh, p.D, p.curves, c.map(shape.mesh),
                                                                   IRS::parameters::keep_off_axis_parts(true)),
            nb);
  EXPECT_EQ(c.values, b.values);
}

// ---------------------------------------------------------------- the graph cut

TEST(Segmentation, GraphCutAppliesEveryExpansionMove)
{
  // On this snowman, with 4 and 6 clusters, CGAL 5.5.1's default graph cut
  // (Boykov-Kolmogorov MaxFlow, whose flow counter survives Graph::clear())
  // keeps the first expansion move only and returns a single segment; a
  // correct alpha expansion cuts the snowman at its necks.
  const auto shape = IRS::generate_snowman<Mesh>(1200);
  const Mesh& m = shape.mesh;
  const auto vpm = get(CGAL::vertex_point, m);
  const auto fim = CGAL::get_initialized_face_index_map(m);
  const std::vector<double> sdf = IRS::internal::segmentation_sdf_values(m, vpm, fim, K(), 2. / 3. * CGAL_PI, 25);
  for(std::size_t k : {4u, 6u})
  {
    std::vector<std::size_t> seg, cgal(num_faces(m));
    const std::size_t n = IRS::internal::sdf_graph_cut_segmentation(m, vpm, fim, K(), sdf, k, 0.26, seg);
    const std::size_t n_cgal =
      CGAL::segmentation_from_sdf_values(m, boost::make_iterator_property_map(sdf.begin(), fim),
                                         boost::make_iterator_property_map(cgal.begin(), fim), k);
    std::cout << "[ snowman, " << k << " clusters ] segments: package " << n << ", CGAL's default graph cut "
              << n_cgal << std::endl;
    EXPECT_GE(n, 2u) << k << " clusters";
    // head and body apart: the lowest and the highest face are in different segments
    std::size_t low = 0, high = 0;
    double zmin = std::numeric_limits<double>::infinity(), zmax = -zmin;
    for(auto f : faces(m))
    {
      const double z = m.point(target(halfedge(f, m), m)).z();
      if(z < zmin) { zmin = z; low = f.idx(); }
      if(z > zmax) { zmax = z; high = f.idx(); }
    }
    EXPECT_NE(seg[low], seg[high]) << k << " clusters";
  }
  // a constant SDF (sphere): fewer distinct values than clusters, one part, no crash in CGAL's k-means seeding
  {
    const Mesh sphere = IRS::generate_sphere<Mesh>(500).mesh;
    Face_labels<Mesh> sp(sphere);
    expect_connected_cover(sphere, sp.values, IRS::Sdf_over_segmenter()(sphere, get(CGAL::vertex_point, sphere),
                                                                         sp.map(sphere)),
                           "sphere");
  }
  // the over-segmenter goes through the same cut (one run with 4 clusters)
  Face_labels<Mesh> parts(m);
  EXPECT_GE(IRS::Sdf_over_segmenter(20, 4, 4)(m, vpm, parts.map(m)), 2u);
  expect_connected_cover(m, parts.values,
                         std::size_t(*std::max_element(parts.values.begin(), parts.values.end()) + 1),
                         "over-segmentation");
}

// ---------------------------------------------------------------- errors

TEST(Segmentation, OverSegmentationRefinesEverySdfRun)
{
  // The default over-segmentation is the common refinement of CGAL's SDF
  // segmentations with 2..K clusters: every run is a merge of its parts, up
  // to the slivers (pieces below 0.05 % of the area) merged into neighbours.
  // On the two snowmen the runs cut different places (runs nest on the stick figure).
  const auto shape = IRS::generate_two_snowmen<Mesh>(2000);
  const Mesh& m = shape.mesh;
  const auto vpm = get(CGAL::vertex_point, m);
  const auto fim = CGAL::get_initialized_face_index_map(m);
  const IRS::internal::Face_graph g = IRS::internal::make_face_graph(m, vpm, fim);
  const std::vector<double> sdf = IRS::internal::segmentation_sdf_values(m, vpm, fim, K(), 2. / 3. * CGAL_PI, 25);
  Face_labels<Mesh> parts(m);
  const std::size_t np = IRS::Sdf_over_segmenter(1000, 2, 8).from_sdf_values(m, vpm, sdf, parts.map(m));
  expect_connected_cover(m, parts.values, np, "refinement");
  std::size_t largest_run = 0;
  for(std::size_t k = 2; k <= 8; ++k)
  {
    std::vector<std::size_t> run;
    std::size_t nr = IRS::internal::sdf_graph_cut_segmentation(m, vpm, fim, K(), sdf, k, 0.26, run);
    nr = IRS::internal::merge_small_components(g, run, nr, 0., k);
    largest_run = (std::max)(largest_run, nr);
    // the area of each part in each segment of the run
    std::vector<std::map<std::size_t, double>> share(np);
    for(std::size_t f = 0; f < g.number_of_faces; ++f) share[std::size_t(parts.values[f])][run[f]] += g.area[f];
    double astray = 0.; // area outside the run segment that holds most of its part
    for(const auto& sh : share)
    {
      double total = 0., best = 0.;
      for(const auto& sa : sh) { total += sa.second; best = (std::max)(best, sa.second); }
      astray += total - best;
    }
    EXPECT_LT(astray, 0.005 * g.total_area) << k << " clusters";
    // one run asked for alone is CGAL's SDF segmentation with that many segments
    Face_labels<Mesh> single(m);
    EXPECT_EQ(IRS::Sdf_over_segmenter(k, k, k).from_sdf_values(m, vpm, sdf, single.map(m)), nr);
    EXPECT_TRUE(std::equal(run.begin(), run.end(), single.values.begin(),
                           [](std::size_t a, long b) { return long(a) == b; }))
      << k << " clusters";
  }
  std::cout << "[ two snowmen, runs with 2..8 clusters ] largest run " << largest_run << " segments, refinement "
            << np << " parts" << std::endl;
  EXPECT_GT(np, largest_run); // the runs' boundaries differ: the refinement has more parts than any run
#ifdef CGAL_LINKED_WITH_TBB
  { // the runs go in parallel: the same parts on one thread
    tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
    Face_labels<Mesh> sequential(m);
    EXPECT_EQ(IRS::Sdf_over_segmenter(1000, 2, 8).from_sdf_values(m, vpm, sdf, sequential.map(m)), np);
    EXPECT_EQ(sequential.values, parts.values);
  }
#endif
  // capped: at most the number of parts asked for
  Face_labels<Mesh> capped(m);
  const std::size_t nc = IRS::Sdf_over_segmenter(4, 2, 8).from_sdf_values(m, vpm, sdf, capped.map(m));
  EXPECT_LE(nc, 4u);
  expect_connected_cover(m, capped.values, nc, "capped refinement");
}

// The merged segmentation reports its advancement to `callback` (the regions
// up to 0.5, then after the over-segmentation), stops when it returns false
// (Operation_cancelled naming symmetry_aware_segmentation(), also when the
// stop comes during the regions), and gives the same segments with a
// callback as without.
TEST(Segmentation, CallbackReportsAndCancels)
{
  const auto shape = IRS::generate_ellipsoid<Mesh>(800);
  const Mesh& m = shape.mesh;
  Pipeline<Mesh> p;
  p.run(m, 200, shape.symmetries, {0});
  ASSERT_FALSE(p.curves.empty());
  Face_labels<Mesh> plain(m);
  const std::size_t n = IRS::symmetry_aware_segmentation(m, p.D, p.curves, plain.map(m));
  for(double stop_at : {2., 0., 0.3, 0.9, 1.})
  {
    SCOPED_TRACE("stop at " + std::to_string(stop_at));
    Recording_callback callback;
    callback.stop_at = stop_at;
    Face_labels<Mesh> labels(m);
    auto segment = [&] {
      return IRS::symmetry_aware_segmentation(m, p.D, p.curves, labels.map(m), IRS::parameters::callback(callback));
    };
    if(stop_at <= 1.)
    {
      expect_cancelled(segment, "symmetry_aware_segmentation");
      ASSERT_FALSE(callback.seen->empty());
      EXPECT_GE(callback.seen->back(), stop_at);
      EXPECT_EQ(std::count_if(callback.seen->begin(), callback.seen->end(), [&](double x) { return x >= stop_at; }), 1);
      continue;
    }
    EXPECT_EQ(segment(), n);
    callback.expect_complete();
    EXPECT_TRUE(std::any_of(callback.seen->begin(), callback.seen->end(), [](double x) { return x > 0. && x <= 0.5; }));
    EXPECT_EQ(labels.values, plain.values);
  }
}

TEST(Segmentation, BadInputThrowsInputError)
{
  const auto shape = IRS::generate_ellipsoid<Mesh>(400);
  Pipeline<Mesh> p;
  p.run(shape.mesh, 100, shape.symmetries, {0});
  ASSERT_FALSE(p.curves.empty());
  Face_labels<Mesh> seg(shape.mesh);
  // a quad mesh
  Mesh quad;
  CGAL::make_hexahedron(Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 0), Point(0, 1, 1),
                        Point(0, 0, 1), Point(1, 0, 1), Point(1, 1, 1), quad);
  Face_labels<Mesh> qseg(quad), qregion(quad), qpart(quad);
  std::fill(qregion.values.begin(), qregion.values.end(), -1);
  std::fill(qpart.values.begin(), qpart.values.end(), 0);
  auto expect_problem = [](auto&& call, IRS::Input_problem problem, const char* what) {
    try { call(); ADD_FAILURE() << "no exception: " << what; }
    catch(const IRS::Input_error& e) { EXPECT_EQ(e.problem(), problem) << what << ": " << e.what(); }
  };
  expect_problem([&] { IRS::symmetry_segmentation(quad, p.D, p.curves, qseg.map(quad)); },
                 IRS::Input_problem::not_triangle_mesh, "pure, quad mesh");
  expect_problem([&] { IRS::symmetry_aware_segmentation(quad, p.D, p.curves, qseg.map(quad)); },
                 IRS::Input_problem::not_triangle_mesh, "merged, quad mesh");
  expect_problem([&] { IRS::merge_over_segmentation(quad, qregion.map(quad), qpart.map(quad), qseg.map(quad)); },
                 IRS::Input_problem::not_triangle_mesh, "merge, quad mesh");
  expect_problem([&] { IRS::Sdf_over_segmenter()(quad, get(CGAL::vertex_point, quad), qpart.map(quad)); },
                 IRS::Input_problem::not_triangle_mesh, "over-segmenter, quad mesh");
  // curves (and matrix) of another mesh
  const auto other = IRS::generate_ellipsoid<Mesh>(600);
  Face_labels<Mesh> oseg(other.mesh);
  expect_problem([&] { IRS::symmetry_segmentation(other.mesh, p.D, p.curves, oseg.map(other.mesh)); },
                 IRS::Input_problem::invalid_parameter, "pure, other mesh");
  expect_problem([&] { IRS::symmetry_aware_segmentation(other.mesh, p.D, p.curves, oseg.map(other.mesh)); },
                 IRS::Input_problem::invalid_parameter, "merged, other mesh");
  // a curve with a vertex index out of range
  std::vector<IRS::Irsa_curve> bad = p.curves;
  bad[0].polylines[0][0] = num_vertices(shape.mesh) + 5;
  expect_problem([&] { IRS::symmetry_segmentation(shape.mesh, p.D, bad, seg.map(shape.mesh)); },
                 IRS::Input_problem::invalid_parameter, "pure, bad curve");
  expect_problem([&] { IRS::symmetry_aware_segmentation(shape.mesh, p.D, bad, seg.map(shape.mesh)); },
                 IRS::Input_problem::invalid_parameter, "merged, bad curve");
  // parameters out of range
  expect_problem([&] { IRS::symmetry_segmentation(shape.mesh, p.D, p.curves, seg.map(shape.mesh),
                                                  IRS::parameters::minimum_segment_area(-0.5)); },
                 IRS::Input_problem::invalid_parameter, "negative minimum_segment_area");
  expect_problem([&] { IRS::Sdf_over_segmenter(0); }, IRS::Input_problem::invalid_parameter, "no part");
  expect_problem([&] { IRS::Sdf_over_segmenter(20, 8, 4); }, IRS::Input_problem::invalid_parameter,
                 "fewer clusters at most than at least");
  expect_problem([&] { IRS::symmetry_aware_segmentation(shape.mesh, p.D, p.curves, seg.map(shape.mesh),
                                                        IRS::parameters::minimum_region_coverage(1.5)); },
                 IRS::Input_problem::invalid_parameter, "minimum_region_coverage above 1");
  expect_problem([&] { IRS::merge_over_segmentation(quad, qregion.map(quad), qpart.map(quad), qseg.map(quad),
                                                    IRS::parameters::minimum_region_coverage(-0.1)); },
                 IRS::Input_problem::not_triangle_mesh, "quad mesh before a negative coverage");
  // an empty mesh
  Mesh empty;
  Face_labels<Mesh> eseg(empty);
  expect_problem([&] { IRS::merge_over_segmentation(empty, eseg.map(empty), eseg.map(empty), eseg.map(empty)); },
                 IRS::Input_problem::empty_mesh, "empty mesh");
}
