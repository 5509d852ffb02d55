// Copyright (c) 2026 The Intrinsic_reflectional_symmetry_3 project.
// SPDX-License-Identifier: LGPL-3.0-or-later
// Author(s)     : The Intrinsic_reflectional_symmetry_3 developers
//
// Symmetry-aware segmentation (paper Sec. 4.1) on the Princeton Segmentation
// Benchmark subset of ../shared/data/psb (76 models, all human
// segmentations). Rand-index error (Chen, Golovinskiy, Funkhouser 2009):
// 1 - Rand index against each human segmentation of a model (the fraction of
// face pairs on which the two disagree), averaged over the humans, then per
// category and overall (equal weight per model). Methods:
//   ours   symmetry_aware_segmentation(): the symmetric regions of the IRSA
//          curves merge the default over-segmentation (Sdf_over_segmenter:
//          the common refinement of CGAL's SDF segmentations with 2..12
//          clusters, at most 20 parts); a part joins the region covering at
//          least 80 % of it (--coverage), else stays a segment
//   ours+axis  the same with keep_off_axis_parts(true): only the parts the
//          curve crosses merge into its region (the symmetric core), the
//          others stay segments
//   sdf    CGAL's SDF segmentation (graph cut with Boost's max-flow, not the
//          defective default of CGAL 5.5.1) with the same number of segments
//          as ours: number_of_clusters = that number, then the smallest
//          segments merged into their neighbours down to it
//   sdf@axis   the same with the number of segments of ours+axis
//   pure   symmetry_segmentation(): the symmetric regions alone
//   sdf@h  CGAL's SDF segmentation as above with the human median number of
//          segments (to compare with the reference figure 0.193)
//   human  each human segmentation against the other humans of the model
// The pipeline: farthest-point samples, heat-method geodesics, SDF
// signatures and the similarity filter, IRSA voting, curve extraction, with
// the package's defaults (only the number of samples and the seed are set).
//
// usage: segmentation_benchmark [DATA_DIR] [--only ID] [--samples N] [--write DIR] [--threads T]
//                               [--max-curves C] [--stopping-ratio R] [--parts P] [--min-area A]
//                               [--merge-uncovered] [--nested] [--sdf-range K] [--coverage C] [--seed S]
//                               [--clusters LO,HI]
//   DATA_DIR  default ../shared/data (relative to the current directory); psb/ inside it
//   ID        only this model id (may be repeated)
//   N         samples per model (default 1000)
//   DIR       write DIR/<method>/<id>.seg (one label per face), the input of
//             ../shared/tools/rand_index.py; also the inputs of the merge:
//             DIR/regions/<id>.seg (symmetric region per face, -1 for none),
//             DIR/parts/<id>.seg (over-segmentation part per face),
//             DIR/regions/<id>.sdf (SDF value per face), DIR/regions/<id>.curves
//             (one curve per line: its vertex ids)
//   T         worker threads (default 1: the benchmark machine is shared)
//   C, R      maximum_number_of_curves and stopping_ratio of the curve extraction (package defaults otherwise)
//   P         parts of the over-segmentation (default 20); A: minimum_segment_area (default 0.01)
//   --nested  nested_symmetries(true) in the curve extraction
//   --sdf-range K  with --write DIR: only CGAL's SDF segmentation of every model with n = 1..K
//             segments, as DIR/sdf_range/<id>.<n>.seg (to compare offline studies at any n)
//   C         minimum_region_coverage of the merge (default 0.8; 0 is the paper's rule)
//   S         seed of the farthest-point samples (default 0)
//   LO,HI     range of the numbers of clusters of the over-segmentation's graph cuts
//             (Sdf_over_segmenter's second and third arguments; default 2,12)
//   --merge-uncovered  merge_uncovered_parts(true) for ours, ours+axis and pure: faces no region
//             covers join a neighbouring segment, so the number of segments is the number of curves

#include <CGAL/Intrinsic_reflectional_symmetry_3/Heat_method_geodesic_oracle.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/irsa_curves.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/irsa_transform.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/sampling.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/segmentation.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/signatures.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/symmetric_map.h>

#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace IRS = CGAL::Intrinsic_reflectional_symmetry_3;
namespace fs = std::filesystem;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef std::vector<long> Labels; // by face index

namespace {

const char* categories[] = {"Human", "Cup", "Glasses", "Airplane", "Ant", "Chair", "Octopus", "Table", "Teddy",
                            "Hand", "Plier", "Fish", "Bird", "Spring", "Armadillo", "Bust", "Mech", "Bearing",
                            "Vase", "Fourleg"};
const char* methods[] = {"ours", "ours+axis", "sdf", "pure", "sdf@h", "human", "sdf@axis"};
constexpr int number_of_methods = 7;

// a model of OverSegmenter that hands out a precomputed over-segmentation (by face index)
struct Given_parts
{
  const std::vector<long>& parts;
  template <class TriangleMesh, class VertexPointMap, class FacePartMap>
  std::size_t operator()(const TriangleMesh& tm, VertexPointMap, FacePartMap out) const
  {
    const auto fim = CGAL::get_initialized_face_index_map(tm);
    for(auto f : faces(tm)) put(out, f, typename boost::property_traits<FacePartMap>::value_type(parts[get(fim, f)]));
    return parts.empty() ? 0 : std::size_t(*std::max_element(parts.begin(), parts.end()) + 1);
  }
};

struct Options
{
  std::string data = "../shared/data", write;
  std::vector<std::string> only;
  std::size_t samples = 1000, max_curves = 0, parts = IRS::default_number_of_over_segmentation_parts;
  double stopping_ratio = -1., minimum_area = IRS::default_minimum_segment_area,
         minimum_coverage = IRS::default_minimum_region_coverage;
  int threads = 1;
  std::size_t sdf_range = 0;
  bool merge_uncovered = false;
  unsigned int seed = 0; // of the farthest-point samples
  std::size_t min_clusters = IRS::default_minimum_number_of_clusters, // Sdf_over_segmenter's range of graph cuts
              max_clusters = IRS::default_maximum_number_of_clusters;
  bool nested = false;
};

// 1 - Rand index: the share of face pairs on which a and b disagree, from the contingency table
double rand_index_error(const Labels& a, const Labels& b)
{
  std::map<std::pair<long, long>, double> n;
  std::map<long, double> na, nb;
  for(std::size_t f = 0; f < a.size(); ++f) { n[{a[f], b[f]}] += 1.; na[a[f]] += 1.; nb[b[f]] += 1.; }
  auto c2 = [](double x) { return 0.5 * x * (x - 1.); };
  double s = 0.;
  for(const auto& x : na) s += c2(x.second);
  for(const auto& x : nb) s += c2(x.second);
  for(const auto& x : n) s -= 2. * c2(x.second);
  return a.size() < 2 ? 0. : s / c2(double(a.size()));
}

double mean_error(const Labels& pred, const std::vector<Labels>& humans)
{
  double s = 0.;
  for(const Labels& h : humans) s += rand_index_error(pred, h);
  return s / double(humans.size());
}

std::size_t count_labels(const Labels& l)
{
  Labels c(l);
  std::sort(c.begin(), c.end());
  return std::size_t(std::unique(c.begin(), c.end()) - c.begin());
}

Labels read_seg(const fs::path& p)
{
  std::ifstream in(p);
  Labels out;
  long x;
  while(in >> x) out.push_back(x);
  return out;
}

void write_seg(const Options& o, const std::string& method, const std::string& id, const Labels& l)
{
  if(o.write.empty()) return;
  const fs::path dir = fs::path(o.write) / method;
  fs::create_directories(dir);
  std::ofstream out(dir / (id + ".seg"));
  for(long x : l) out << x << '\n';
}

// CGAL's post-processed SDF value of every face (its default cone and rays)
std::vector<double> sdf_values(const Mesh& m)
{
  return IRS::internal::segmentation_sdf_values(m, get(CGAL::vertex_point, m), CGAL::get_initialized_face_index_map(m),
                                                K(), 2. / 3. * CGAL_PI, 25);
}

// CGAL's SDF segmentation (package's graph cut) with exactly n segments where possible
Labels sdf_segmentation(const Mesh& m, const std::vector<double>& sdf, std::size_t n)
{
  n = (std::max)(n, std::size_t(1));
  Labels seg(num_faces(m));
  const auto fim = CGAL::get_initialized_face_index_map(m);
  IRS::Sdf_over_segmenter(n, n, n).from_sdf_values(m, get(CGAL::vertex_point, m), sdf,
                                                    boost::make_iterator_property_map(seg.begin(), fim));
  return seg;
}

struct Model_result
{
  std::string id, category;
  std::size_t vertices = 0, faces = 0, curves = 0, parts = 0, humans = 0, human_median = 0;
  std::size_t segments[number_of_methods] = {0, 0, 0, 0, 0, 0, 0};
  double error[number_of_methods] = {0., 0., 0., 0., 0., 0., 0.};
  double seconds_pipeline = 0., seconds_ours = 0., seconds_sdf = 0.;
};

bool run_model(const Options& o, const std::string& id, const std::string& category, Model_result& r)
{
  const fs::path psb = fs::path(o.data) / "psb";
  Mesh m;
  if(!CGAL::IO::read_polygon_mesh((psb / "off" / (id + ".off")).string(), m) || !CGAL::is_triangle_mesh(m))
  {
    std::cout << id << ": cannot read the mesh, skipped\n";
    return false;
  }
  std::vector<Labels> humans;
  for(int k = 0; k < 100; ++k)
  {
    const fs::path p = psb / "seg" / "Benchmark" / id / (id + "_" + std::to_string(k) + ".seg");
    if(!fs::exists(p)) continue;
    humans.push_back(read_seg(p));
    if(humans.back().size() != num_faces(m))
    {
      std::cout << id << ": " << p << " has " << humans.back().size() << " labels for " << num_faces(m)
                << " faces, skipped\n";
      return false;
    }
  }
  if(humans.empty()) { std::cout << id << ": no human segmentation, skipped\n"; return false; }
  r.id = id;
  r.category = category;
  r.vertices = num_vertices(m);
  r.faces = num_faces(m);
  r.humans = humans.size();
  std::vector<std::size_t> counts;
  for(const Labels& h : humans) counts.push_back(count_labels(h));
  std::sort(counts.begin(), counts.end());
  r.human_median = counts[counts.size() / 2];

  if(o.sdf_range > 0)
  {
    // only CGAL's SDF segmentation with 1..K segments, for offline studies
    const std::vector<double> sdf = sdf_values(m);
    for(std::size_t n = 1; n <= o.sdf_range; ++n)
      write_seg(o, "sdf_range", id + "." + std::to_string(n), sdf_segmentation(m, sdf, n));
    std::cout << id << ": SDF segmentations with 1.." << o.sdf_range << " segments written" << std::endl;
    return false;
  }

  CGAL::Real_timer t;
  t.start();
  const std::size_t ns = (std::min)(o.samples, std::size_t(num_vertices(m)));
  const std::vector<std::size_t> samples =
    IRS::farthest_point_samples(m, IRS::parameters::number_of_samples(ns).random_seed(o.seed));
  const IRS::Heat_method_geodesic_oracle<Mesh> oracle(m);
  const IRS::Geodesic_distance_matrix D = IRS::compute_geodesic_distance_matrix(oracle, samples);
  const IRS::Sdf_signatures signatures = IRS::sdf_signatures(IRS::vertex_sdf_values(m), IRS::vertex_areas(m), D);
  std::vector<std::pair<std::size_t, std::size_t>> similar;
  IRS::similar_sample_pairs(signatures, std::back_inserter(similar));
  auto tau = get(CGAL::dynamic_vertex_property_t<double>(), m);
  const IRS::Irsa_voting_result voting = IRS::compute_irsa_transform(m, D, similar, tau);
  std::vector<IRS::Irsa_curve> curves;
  const std::size_t max_curves = o.max_curves > 0 ? o.max_curves : IRS::internal::default_maximum_number_of_curves;
  const double ratio = o.stopping_ratio >= 0. ? o.stopping_ratio : IRS::internal::default_stopping_ratio;
  IRS::extract_irsa_curves(m, D, voting, tau, std::back_inserter(curves),
                           IRS::parameters::maximum_number_of_curves(max_curves).stopping_ratio(ratio)
                             .nested_symmetries(o.nested));
  r.curves = curves.size();
  r.seconds_pipeline = t.time();
  t.reset();

  // ours: regions, over-segmentation, merge (the steps of symmetry_aware_segmentation(), timed together)
  Labels region(num_faces(m), -1), part(num_faces(m), 0), ours(num_faces(m)), ours_axis(num_faces(m)),
    pure(num_faces(m));
  const auto fim = CGAL::get_initialized_face_index_map(m);
  auto fmap = [&](Labels& l) { return boost::make_iterator_property_map(l.begin(), fim); };
  // the SDF values and the over-segmentation are computed once for all methods
  CGAL::Real_timer t_sdf;
  t_sdf.start();
  const std::vector<double> sdf = sdf_values(m);
  const double seconds_sdf_values = t_sdf.time();
  IRS::symmetric_regions(m, D, curves, fmap(region));
  r.parts = IRS::Sdf_over_segmenter(o.parts, o.min_clusters, o.max_clusters).from_sdf_values(m, get(CGAL::vertex_point, m), sdf, fmap(part));
  const auto np = IRS::parameters::minimum_segment_area(o.minimum_area).merge_uncovered_parts(o.merge_uncovered)
                    .minimum_region_coverage(o.minimum_coverage);
  r.segments[0] = IRS::merge_over_segmentation(m, fmap(region), fmap(part), fmap(ours), np);
  r.seconds_ours = t.time();
  r.segments[1] = IRS::symmetry_aware_segmentation(m, D, curves, fmap(ours_axis),
                                                   np.keep_off_axis_parts(true).over_segmenter(Given_parts{part}));
  r.segments[3] = IRS::symmetry_segmentation(m, D, curves, fmap(pure), np);

  t.reset();
  const Labels sdf_same = sdf_segmentation(m, sdf, r.segments[0]);
  r.seconds_sdf = t.time() + seconds_sdf_values;
  const Labels sdf_human = sdf_segmentation(m, sdf, r.human_median);
  const Labels sdf_axis = sdf_segmentation(m, sdf, r.segments[1]);
  r.segments[2] = count_labels(sdf_same);
  r.segments[4] = count_labels(sdf_human);
  r.segments[6] = count_labels(sdf_axis);

  const Labels* preds[7] = {&ours, &ours_axis, &sdf_same, &pure, &sdf_human, nullptr, &sdf_axis};
  for(int k = 0; k < 7; ++k)
    if(preds[k] != nullptr)
    {
      r.error[k] = mean_error(*preds[k], humans);
      write_seg(o, methods[k], id, *preds[k]);
    }
  // humans, leave one out: mean over unordered pairs
  double s = 0.;
  std::size_t pairs = 0;
  for(std::size_t i = 0; i < humans.size(); ++i)
    for(std::size_t j = i + 1; j < humans.size(); ++j) { s += rand_index_error(humans[i], humans[j]); ++pairs; }
  r.error[5] = pairs ? s / double(pairs) : 0.;
  write_seg(o, "human", id, humans.front());
  // the inputs of the merge, to study other merging rules offline: the
  // symmetric region and the over-segmentation part of every face, the SDF
  // value of every face, and the curves (one per line, vertex ids)
  write_seg(o, "regions", id, region);
  write_seg(o, "parts", id, part);
  if(!o.write.empty())
  {
    std::ofstream sdf_out(fs::path(o.write) / "regions" / (id + ".sdf"));
    sdf_out << std::setprecision(9);
    for(double x : sdf) sdf_out << x << '\n';
    std::ofstream curves_out(fs::path(o.write) / "regions" / (id + ".curves"));
    for(const IRS::Irsa_curve& c : curves)
    {
      for(const auto& pl : c.polylines)
        for(std::size_t v : pl) curves_out << v << ' ';
      curves_out << '\n';
    }
  }
  r.segments[5] = r.human_median;
  return true;
}

} // namespace

int main(int argc, char** argv)
{
  Options o;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if(i + 1 >= argc) { std::cerr << a << " expects a value\n"; std::exit(1); }
      return argv[++i];
    };
    if(a == "--samples") o.samples = std::size_t(std::max(1L, std::atol(value().c_str())));
    else if(a == "--only") o.only.push_back(value());
    else if(a == "--write") o.write = value();
    else if(a == "--threads") o.threads = std::atoi(value().c_str());
    else if(a == "--sdf-range") o.sdf_range = std::size_t(std::max(1L, std::atol(value().c_str())));
    else if(a == "--max-curves") o.max_curves = std::size_t(std::max(1L, std::atol(value().c_str())));
    else if(a == "--stopping-ratio") o.stopping_ratio = std::atof(value().c_str());
    else if(a == "--parts") o.parts = std::size_t(std::max(1L, std::atol(value().c_str())));
    else if(a == "--min-area") o.minimum_area = std::atof(value().c_str());
    else if(a == "--merge-uncovered") o.merge_uncovered = true;
    else if(a == "--coverage") o.minimum_coverage = std::atof(value().c_str());
    else if(a == "--seed") o.seed = unsigned(std::atol(value().c_str()));
    else if(a == "--clusters")
    {
      const std::string v = value();
      const std::size_t comma = v.find(',');
      o.min_clusters = std::size_t(std::max(1L, std::atol(v.substr(0, comma).c_str())));
      o.max_clusters = comma == std::string::npos ? o.min_clusters
                                                  : std::size_t(std::max(1L, std::atol(v.substr(comma + 1).c_str())));
    }
    else if(a == "--nested") o.nested = true;
    else if(a == "--help" || a == "-h")
    {
      std::cout << "usage: segmentation_benchmark [DATA_DIR] [--only ID] [--samples N] [--write DIR] [--threads T]\n"
                   "                              [--max-curves C] [--stopping-ratio R] [--parts P] [--min-area A] [--merge-uncovered] [--nested] [--sdf-range K] [--coverage C] [--seed S] [--clusters LO,HI]\n";
      return 0;
    }
    else if(!a.empty() && a[0] == '-') { std::cerr << "unknown option " << a << '\n'; return 1; }
    else o.data = a;
  }
#ifdef CGAL_LINKED_WITH_TBB
  std::unique_ptr<tbb::global_control> control;
  if(o.threads > 0)
    control = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, std::size_t(o.threads));
#endif
  if(o.sdf_range > 0 && o.write.empty())
  {
    std::cerr << "--sdf-range writes its segmentations: it needs --write DIR\n";
    return 1;
  }
  const fs::path manifest = fs::path(o.data) / "psb" / "MANIFEST.tsv";
  std::cout << "segmentation benchmark: PSB subset in " << (fs::path(o.data) / "psb") << ", " << o.samples
            << " samples per model; Rand-index error (1 - RI, mean over the human segmentations); n = number of "
               "segments; times in seconds (wall clock; pipeline = samples to curves, ours = regions + "
               "over-segmentation + merge, sdf = CGAL SDF segmentation)\n";
  if(!fs::exists(manifest))
  {
    std::cout << manifest << " not found: nothing to do\n";
    return 0;
  }
  std::ifstream in(manifest);
  std::string line;
  std::getline(in, line); // header
  std::vector<Model_result> results;
  std::cout << "id\tcategory\tV\tcurves\tparts\tn_ours\tn_ours+axis\tn_pure\tn_human\tours\tours+axis\tsdf\tpure"
               "\tsdf@h\thuman\tsdf@axis\tt_pipeline\tt_ours\tt_sdf\n"
            << std::fixed;
  while(std::getline(in, line))
  {
    std::istringstream is(line);
    std::string id;
    if(!std::getline(is, id, '\t') || id.empty()) continue;
    if(!o.only.empty() && std::find(o.only.begin(), o.only.end(), id) == o.only.end()) continue;
    const std::size_t c = (std::size_t(std::atol(id.c_str())) - 1) / 20;
    Model_result r;
    if(!run_model(o, id, c < 20 ? categories[c] : "?", r)) continue;
    std::cout << r.id << '\t' << r.category << '\t' << r.vertices << '\t' << r.curves << '\t' << r.parts << '\t' << r.segments[0]
              << '\t' << r.segments[1] << '\t' << r.segments[3] << '\t' << r.human_median << std::setprecision(4);
    for(int k = 0; k < number_of_methods; ++k) std::cout << '\t' << r.error[k];
    std::cout << std::setprecision(2) << '\t' << r.seconds_pipeline << '\t' << r.seconds_ours << '\t'
              << r.seconds_sdf << std::endl;
    results.push_back(r);
  }
  if(results.empty()) return 0;

  // per category and overall
  std::cout << "\ncategory\tmodels\tmean n_ours\tmean n_ours+axis";
  for(int k = 0; k < number_of_methods; ++k) std::cout << '\t' << methods[k];
  std::cout << "\tmean t_pipeline+ours\n";
  std::vector<std::string> order;
  for(const char* c : categories)
    for(const Model_result& r : results)
      if(r.category == c) { order.push_back(c); break; }
  order.push_back("OVERALL");
  for(const std::string& c : order)
  {
    double e[number_of_methods] = {0., 0., 0., 0., 0., 0., 0.}, n = 0., seg = 0., seg_axis = 0., time = 0.;
    for(const Model_result& r : results)
    {
      if(c != "OVERALL" && r.category != c) continue;
      for(int k = 0; k < number_of_methods; ++k) e[k] += r.error[k];
      seg += double(r.segments[0]);
      seg_axis += double(r.segments[1]);
      time += r.seconds_pipeline + r.seconds_ours;
      n += 1.;
    }
    std::cout << c << '\t' << n << std::setprecision(1) << '\t' << seg / n << '\t' << seg_axis / n
              << std::setprecision(4);
    for(int k = 0; k < number_of_methods; ++k) std::cout << '\t' << e[k] / n;
    std::cout << std::setprecision(2) << '\t' << time / n << '\n';
  }
  return 0;
}
