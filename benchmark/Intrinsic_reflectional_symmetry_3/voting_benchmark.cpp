// IRSA transform benchmark: time per stage and peak memory of the whole
// transform (heat-method geodesics, SDF signatures, voting) for growing
// sample counts on CGAL's camel.off and man.off; fast voting vs the literal
// reference of Alg. 1-2 side by side on the same input, for several
// similarity thresholds; with --robustness, the relative L2 change of tau
// under vertex noise and small holes (paper Fig. 10-11); and, with
// --floor-study, the measurements behind the default of
// `distance_tolerance_floor`. Prints tables; asserts nothing.
//
// usage: voting_benchmark [options] DIR...
//   DIR...                directories searched for camel.off and man.off
//                         (e.g. data/meshes of libcgal-demo's data.tar.gz)
//   --samples a,b,...     sample counts (default 500,1000,2000,3000,5000)
//   --meshes x,y,...      mesh file names (default camel.off,man.off)
//   --threads N           threads of the parallel stages (default: all)
//   --reference-samples N samples of the fast-vs-reference run (default 300; 0: skip)
//   --reference-eps a,b   similarity thresholds of that run (default 0.025,0.05,0.1,0.2);
//                         then the same comparison with the defaults on the meshes, FAUST's
//                         tr_reg_000 (with --faust) and three generated shapes
//   --cap-samples N       samples of the voting-pair cap study on each mesh (default 1000; 0: skip):
//                         tau with 1/2 .. 1/16 of the similar pairs voting, against all of them
//   --no-scaling          skip the scaling study (e.g. to run only fast vs reference)
//   --robustness          also run the noise and holes study (camel, and FAUST with --faust),
//                         the holes also filled first (prepare_mesh's fill_holes)
//   --robustness-samples N  samples of that study (default 1000)
//   --floor-study         also run the distance-floor measurements
//   --faust DIR           FAUST folder with X.off and corres/X.{vts,sym.vts}
//                         (for --floor-study and --robustness)

#include <CGAL/Intrinsic_reflectional_symmetry_3/Heat_method_geodesic_oracle.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/Dijkstra_geodesic_oracle.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/check_input.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/irsa_transform.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/prepare_mesh.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/perturbed_copies.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/reference_voting.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/sampling.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/shape_generators.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/signatures.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Random.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Surface_mesh.h>

#include <Eigen/Dense>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace IRS = CGAL::Intrinsic_reflectional_symmetry_3;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef std::vector<std::pair<std::size_t, std::size_t>> Pairs;

namespace {

// peak resident memory (Linux; -1 elsewhere), and its reset (Linux >= 4.0)
double peak_mb()
{
  std::ifstream in("/proc/self/status");
  std::string line;
  while(std::getline(in, line))
    if(line.rfind("VmHWM:", 0) == 0)
      return std::stod(line.substr(6)) / 1024.;
  return -1.;
}
void reset_peak()
{
  std::ofstream out("/proc/self/clear_refs");
  if(out) out << "5";
}

std::vector<std::string> split(const std::string& s)
{
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string item;
  while(std::getline(ss, item, ',')) out.push_back(item);
  return out;
}

bool find_file(const std::vector<std::string>& dirs, const std::string& name, std::string& path)
{
  for(const std::string& d : dirs)
  {
    std::ifstream f(d + "/" + name);
    if(f) { path = d + "/" + name; return true; }
  }
  return false;
}

Pairs similar_pairs(const Mesh& m, const IRS::Geodesic_distance_matrix& D, const std::vector<double>& sdf,
                    const std::vector<double>& areas, double similarity_threshold = IRS::default_similarity_threshold)
{
  (void)m;
  const IRS::Sdf_signatures sig = IRS::sdf_signatures(sdf, areas, D);
  Pairs pairs;
  // the paper's filter without the cap on similar pairs: the studies here
  // measure the voting (and its own cap) on every pair that passes
  IRS::similar_sample_pairs(sig, std::back_inserter(pairs),
                            IRS::parameters::similarity_threshold(similarity_threshold)
                              .maximum_similar_pairs_per_sample(std::numeric_limits<double>::infinity()));
  return pairs;
}

// ---------------------------------------------------------------- scaling

void scaling(const std::string& path, const std::vector<std::size_t>& sample_counts)
{
  Mesh m;
  CGAL::Real_timer t;
  t.start();
  if(!CGAL::IO::read_polygon_mesh(path, m) || is_empty(m)) { std::cout << "cannot read " << path << "\n"; return; }
  const double t_read = t.time();
  t.reset();
  IRS::Heat_method_geodesic_oracle<Mesh> oracle(m);
  const double t_oracle = t.time();
  t.reset();
  const std::vector<double> sdf = IRS::vertex_sdf_values(m);
  const std::vector<double> areas = IRS::vertex_areas(m);
  const double t_sdf = t.time();
  std::cout << "\n## " << path << ": " << num_vertices(m) << " vertices; read " << t_read << " s, heat-method oracle "
            << t_oracle << " s, per-vertex SDF " << t_sdf << " s (once per mesh)\n\n"
            << "| samples | FPS s | geodesic matrix s | signatures+pairs s | similar pairs | voting set-up s | voting s |"
               " boundary | distance | locality | axial | support (CPU s) | voted | total s | peak MB |\n"
            << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for(std::size_t n : sample_counts)
  {
    if(n > num_vertices(m)) continue;
    reset_peak();
    CGAL::Real_timer total;
    total.start();
    t.reset();
    const std::vector<std::size_t> samples =
      IRS::farthest_point_samples(m, IRS::parameters::number_of_samples(n).random_seed(1u));
    const double t_fps = t.time();
    t.reset();
    const IRS::Geodesic_distance_matrix D = IRS::compute_geodesic_distance_matrix(oracle, samples);
    const double t_matrix = t.time();
    t.reset();
    const Pairs pairs = similar_pairs(m, D, sdf, areas);
    const double t_sig = t.time();
    auto tau = m.add_property_map<Mesh::Vertex_index, double>("v:tau", 0.).first;
    const IRS::Irsa_voting_result r = IRS::compute_irsa_transform(m, D, pairs, tau);
    const double t_total = total.time() + t_oracle + t_sdf; // the oracle and SDF are per mesh
    std::cout << "| " << n << " | " << std::fixed << std::setprecision(2) << t_fps << " | " << t_matrix << " | "
              << t_sig << " | " << pairs.size() << " | " << r.setup_seconds << " | " << r.voting_seconds;
    for(double s : r.stage_seconds) std::cout << " | " << s;
    std::cout << " | " << r.voting_pairs.size() << " | " << t_total << " | " << std::setprecision(0)
              << peak_mb() << " |" << std::endl;
    m.remove_property_map(tau);
  }
}

// ---------------------------------------------------------------- fast vs reference

// Heat-method geodesics from n farthest-point samples (seed 1): the input of
// every study below
IRS::Geodesic_distance_matrix sample_geodesics(const Mesh& m, std::size_t n)
{
  const IRS::Heat_method_geodesic_oracle<Mesh> oracle(m);
  const std::vector<std::size_t> samples =
    IRS::farthest_point_samples(m, IRS::parameters::number_of_samples(n).random_seed(1u));
  return IRS::compute_geodesic_distance_matrix(oracle, samples);
}

// The reference and the fast voting (one thread, then in parallel) on the same
// set-up, each timed alone
struct Reference_comparison
{
  IRS::Irsa_voting_result ref, seq, par;
  std::vector<double> tau_ref, tau_seq, tau_par;
  double t_ref = 0., t_seq = 0., t_par = 0.;
};

Reference_comparison compare_with_reference(const IRS::internal::Voting_setup& setup)
{
  Reference_comparison c;
  CGAL::Real_timer t;
  t.start();
  c.ref = IRS::internal::Reference_voting(setup).run(c.tau_ref);
  c.t_ref = t.time();
  t.reset();
  c.seq = IRS::internal::run_fast_voting<CGAL::Sequential_tag>(setup, c.tau_seq, 0);
  c.t_seq = t.time();
  t.reset();
  c.par = IRS::internal::run_fast_voting<CGAL::Parallel_if_available_tag>(setup, c.tau_par, 0);
  c.t_par = t.time();
  return c;
}

// One row per similarity threshold. The set-up shared by both implementations
// (input checks, vertex adjacency, sample matrix, sigma: make_voting_setup())
// is timed apart; "voting" is what follows it, "end to end" includes it. The
// fast voting builds an index that depends only on (mesh, D) (vertex blocks,
// bounds, D in block order, sample order): "fast voting" includes it (that is
// what compute_irsa_transform() costs); "shared index" is the fast voting
// given an index built once for all thresholds (timed apart), i.e. the cost
// of one more transform on the same (mesh, D).
void versus_reference(const std::string& path, std::size_t n, const std::vector<double>& thresholds)
{
  Mesh m;
  if(!CGAL::IO::read_polygon_mesh(path, m) || is_empty(m)) return;
  const IRS::Geodesic_distance_matrix D = sample_geodesics(m, n);
  const std::vector<double> sdf = IRS::vertex_sdf_values(m), areas = IRS::vertex_areas(m);
  std::cout << "\n## Fast voting vs the literal reference (Alg. 1-2): " << path << ", " << n
            << " samples, default voting parameters\n\n"
            << "| eps_SIM | similar pairs | voted | shared set-up s | reference voting s | fast voting, 1 thread s |"
               " fast voting, parallel s | fast, shared (mesh, D) index, 1 thread s | speed-up voting (1 thread) |"
               " speed-up voting (parallel) | speed-up with shared index (1 thread) |"
               " speed-up end to end (1 thread) | same voted and eligible pairs | tau: max rel. difference |"
               " bit-different tau |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  std::unique_ptr<IRS::internal::Voting_index> index;
  double t_index = 0.;
  std::ostringstream stages; // where the 1-thread fast voting spends its time
  stages << "\nFast voting, 1 thread, by stage (s; 'index' is the rest: the (mesh, D) index and the"
            " neighbourhoods, built per transform; 'candidates' includes the test at m):\n\n"
            "| eps_SIM | total | index | boundary | candidates | locality | axial | support |"
            " candidates | after locality | after axial |\n|---|---|---|---|---|---|---|---|---|---|---|\n";
  for(double eps_sim : thresholds)
  {
    const Pairs pairs = similar_pairs(m, D, sdf, areas, eps_sim);
    CGAL::Real_timer t;
    t.start();
    const IRS::internal::Voting_setup setup =
      IRS::internal::make_voting_setup(m, D, pairs, IRS::parameters::default_values());
    const double t_setup = t.time();
    const Reference_comparison c = compare_with_reference(setup);
    const IRS::Irsa_voting_result &ref = c.ref, &seq = c.seq, &par = c.par;
    const std::vector<double> &tau_ref = c.tau_ref, &tau_seq = c.tau_seq, &tau_par = c.tau_par;
    const double t_ref = c.t_ref, t_seq = c.t_seq, t_par = c.t_par;
    if(!index)
    {
      t.reset();
      index.reset(new IRS::internal::Voting_index(setup, false));
      t_index = t.time();
    }
    std::vector<double> tau_shared;
    t.reset();
    const IRS::Irsa_voting_result shr =
      IRS::internal::run_fast_voting<CGAL::Sequential_tag>(setup, tau_shared, 0, index.get());
    const double t_shared = t.time();
    double max_rel = 0.;
    std::size_t bit_different = 0;
    for(std::size_t v = 0; v < tau_ref.size(); ++v)
    {
      const double a = tau_ref[v], b = tau_par[v], c = tau_seq[v];
      if(a != b || a != c || a != tau_shared[v]) ++bit_different;
      const double scale = (std::max)(std::abs(a), 1e-300);
      max_rel = (std::max)({max_rel, std::abs(a - b) / scale, std::abs(a - c) / scale});
    }
    bool same_pairs = ref.voting_pairs.size() == par.voting_pairs.size() &&
                      ref.voting_pairs.size() == seq.voting_pairs.size() &&
                    ref.voting_pairs.size() == shr.voting_pairs.size();
    for(std::size_t k = 0; same_pairs && k < ref.voting_pairs.size(); ++k)
      same_pairs = ref.voting_pairs[k].eligible_pairs == par.voting_pairs[k].eligible_pairs &&
                   ref.voting_pairs[k].boundary == par.voting_pairs[k].boundary &&
                   ref.voting_pairs[k].eligible_pairs == seq.voting_pairs[k].eligible_pairs &&
                   ref.voting_pairs[k].eligible_pairs == shr.voting_pairs[k].eligible_pairs;
    std::cout << "| " << eps_sim << " | " << pairs.size() << " | " << ref.voting_pairs.size() << " | "
              << std::fixed << std::setprecision(4) << t_setup << " | " << t_ref << " | " << t_seq << " | "
              << t_par << " | " << t_shared << " | " << std::setprecision(0) << t_ref / t_seq << "x | "
              << t_ref / t_par << "x | " << t_ref / t_shared << "x | "
              << (t_setup + t_ref) / (t_setup + t_seq) << "x | " << (same_pairs ? "yes" : "NO") << " | "
              << std::scientific << std::setprecision(1) << max_rel << std::defaultfloat << " | "
              << bit_different << " |" << std::endl;
    double staged = 0.;
    for(double x : seq.stage_seconds) staged += x;
    stages << "| " << eps_sim << std::fixed << std::setprecision(4) << " | " << t_seq << " | " << t_seq - staged;
    for(double x : seq.stage_seconds) stages << " | " << x;
    stages << " | " << seq.number_of_candidate_pairs << " | " << seq.number_of_pairs_after_locality << " | "
           << seq.number_of_pairs_after_axial << " |\n" << std::defaultfloat;
  }
  std::cout << stages.str();
  std::cout << "\n(mesh, D) index built once for the shared-index column: " << std::fixed << std::setprecision(4)
            << t_index << " s\n";
}

// The same comparison with the default parameters on several shapes: the
// reference costs about voting pairs x |beta| x similar pairs, so its ratio to
// the fast voting grows with the number of pairs the similarity filter keeps
// (few on CGAL's meshes and FAUST, many on the smooth generated shapes).
void versus_reference_by_shape(const std::vector<std::pair<std::string, Mesh>>& shapes, std::size_t n)
{
  std::cout << "\n## Fast voting vs the literal reference by shape, default parameters, " << n << " samples\n\n"
            << "| shape | vertices | similar pairs | voted | reference s | fast, 1 thread s | fast, parallel s |"
               " speed-up (1 thread) | speed-up (parallel) | bit-different tau |\n|---|---|---|---|---|---|---|---|---|---|\n";
  for(const auto& named : shapes)
  {
    const Mesh& m = named.second;
    const IRS::Geodesic_distance_matrix D = sample_geodesics(m, (std::min)(n, std::size_t(num_vertices(m))));
    const Pairs pairs = similar_pairs(m, D, IRS::vertex_sdf_values(m), IRS::vertex_areas(m));
    const IRS::internal::Voting_setup setup =
      IRS::internal::make_voting_setup(m, D, pairs, IRS::parameters::default_values());
    const Reference_comparison c = compare_with_reference(setup);
    std::size_t bit_different = 0;
    for(std::size_t v = 0; v < c.tau_ref.size(); ++v)
      bit_different += (c.tau_ref[v] != c.tau_seq[v] || c.tau_ref[v] != c.tau_par[v]);
    std::cout << "| " << named.first << " | " << num_vertices(m) << " | " << pairs.size() << " | "
              << c.ref.voting_pairs.size() << " | " << std::fixed << std::setprecision(4) << c.t_ref << " | "
              << c.t_seq << " | " << c.t_par << " | " << std::setprecision(0) << c.t_ref / c.t_seq << "x | "
              << c.t_ref / c.t_par << "x | " << bit_different << " |" << std::endl << std::defaultfloat;
  }
}

// ---------------------------------------------------------------- robustness

// tau by vertex index for the given sample vertices: heat-method geodesics,
// SDF signatures and similar pairs, voting, default parameters
std::vector<double> irsa_tau(const Mesh& m, const std::vector<std::size_t>& samples, std::size_t& similar)
{
  IRS::Heat_method_geodesic_oracle<Mesh> oracle(m);
  const IRS::Geodesic_distance_matrix D = IRS::compute_geodesic_distance_matrix(oracle, samples);
  const Pairs pairs = similar_pairs(m, D, IRS::vertex_sdf_values(m), IRS::vertex_areas(m));
  similar = pairs.size();
  auto tau = get(CGAL::dynamic_vertex_property_t<double>(), m);
  IRS::compute_irsa_transform(m, D, pairs, tau);
  std::vector<double> out(num_vertices(m));
  for(auto v : m.vertices()) out[v.idx()] = get(tau, v);
  return out;
}

// ||tau' - tau|| / ||tau|| over the vertices kept (map[v] >= 0: index in tau')
double relative_l2(const std::vector<double>& tau, const std::vector<double>& tau2, const std::vector<std::ptrdiff_t>& map)
{
  double num = 0., den = 0.;
  for(std::size_t v = 0; v < tau.size(); ++v)
  {
    if(map[v] < 0) continue;
    const double d = tau2[std::size_t(map[v])] - tau[v];
    num += d * d;
    den += tau[v] * tau[v];
  }
  return den > 0. ? std::sqrt(num / den) : 0.;
}

// Same sample vertices on the perturbed meshes (the vertex set is the same
// under noise; with holes, the samples whose vertex survives), so the error
// measures the transform, not a new sampling. Fig. 10-11 of the paper.
void robustness(const std::string& name, const Mesh& m, std::size_t n)
{
  const double e = IRS::check_input(m).mean_edge_length;
  const std::vector<std::size_t> samples =
    IRS::farthest_point_samples(m, IRS::parameters::number_of_samples(n).random_seed(1u));
  std::size_t similar = 0;
  CGAL::Real_timer t;
  t.start();
  const std::vector<double> tau = irsa_tau(m, samples, similar);
  std::cout << "| " << name << " | original | " << num_vertices(m) << " / " << samples.size() << " | " << similar
            << " | 0 | " << std::fixed << std::setprecision(1) << t.time() << " |" << std::endl;
  std::vector<std::ptrdiff_t> identity(num_vertices(m));
  for(std::size_t v = 0; v < identity.size(); ++v) identity[v] = std::ptrdiff_t(v);
  for(double level : {0.1, 0.2, 0.42})
  {
    t.reset();
    const Mesh noisy = IRS::internal::noisy_copy(m, level, e, 7u);
    const std::vector<double> tau2 = irsa_tau(noisy, samples, similar);
    std::cout << "| " << name << " | noise " << std::setprecision(2) << level << " | " << num_vertices(noisy) << " / "
              << samples.size() << " | " << similar << " | " << std::setprecision(3)
              << relative_l2(tau, tau2, identity) << " | " << std::setprecision(1) << t.time() << " |" << std::endl;
  }
  for(std::size_t holes : {std::size_t(8), std::size_t(16)})
  {
    t.reset();
    Mesh holed;
    std::vector<std::ptrdiff_t> map;
    unsigned seed = IRS::internal::first_hole_seed;
    if(!IRS::internal::holed_copy_from_seed(m, 0.03, holes, seed, IRS::internal::number_of_hole_seeds, holed, map))
    {
      std::cout << "| " << name << " | " << holes << " holes | (seeds " << IRS::internal::first_hole_seed << "-"
                << IRS::internal::first_hole_seed + IRS::internal::number_of_hole_seeds - 1
                << " pinch a vertex or cut off a part) | | | |" << std::endl;
      continue;
    }
    std::vector<std::size_t> kept;
    for(std::size_t s : samples)
      if(map[s] >= 0) kept.push_back(std::size_t(map[s]));
    const std::vector<double> tau2 = irsa_tau(holed, kept, similar);
    std::cout << "| " << name << " | " << holes << " holes, " << std::setprecision(2)
              << 100. * double(num_faces(m) - num_faces(holed)) / double(num_faces(m)) << " % faces removed"
              << (seed != IRS::internal::first_hole_seed ? ", seed " + std::to_string(seed) : std::string()) << " | "
              << num_vertices(holed) << " / " << kept.size() << " | " << similar << " | " << std::setprecision(3)
              << relative_l2(tau, tau2, map) << " | " << std::setprecision(1) << t.time() << " |" << std::endl;

    // the same holes filled first (prepare_mesh's fill_holes): the holed mesh's
    // vertices keep their ids, so the samples and the error stay the same vertices
    t.reset();
    const auto filled = IRS::prepare_mesh(holed, IRS::parameters::fill_holes(true));
    const std::vector<double> tau3 = irsa_tau(filled.working_mesh(), kept, similar);
    std::cout << "| " << name << " | " << holes << " holes, filled first (" << filled.number_of_filled_holes()
              << " patches) | " << num_vertices(filled.working_mesh()) << " / " << kept.size() << " | " << similar
              << " | " << std::setprecision(3) << relative_l2(tau, tau3, map) << " | " << std::setprecision(1)
              << t.time() << " |" << std::endl;
  }
}

void robustness_study(const std::vector<std::string>& dirs, const std::string& faust, std::size_t n)
{
  std::cout << "\n## Robustness (paper Fig. 10-11): ||tau' - tau|| / ||tau|| (L2 over the vertices kept)\n"
               "Same sample vertices (farthest-point, seed 1) on the perturbed copies; heat-method geodesics, SDF\n"
               "similarity and voting recomputed on each copy with the default parameters. Noise: isotropic\n"
               "Gaussian, mean displacement = level x mean edge length, seed 7. Holes: 3 % of the faces, as\n"
               "balls of faces around random vertices, seed " << IRS::internal::first_hole_seed
            << " (or the next that pinches no vertex and cuts off no part);\n"
               "then filled first by prepare_mesh(fill_holes(true)), the error over the holed mesh's vertices.\n\n"
               "| shape | perturbation | vertices / samples | similar pairs | relative L2 error | time s |\n"
               "|---|---|---|---|---|---|\n";
  std::string camel;
  if(find_file(dirs, "camel.off", camel))
  {
    Mesh m;
    if(CGAL::IO::read_polygon_mesh(camel, m) && !is_empty(m))
      robustness("camel", m, n);
  }
  if(!faust.empty())
  {
    Mesh m;
    if(CGAL::IO::read_polygon_mesh(faust + "/tr_reg_000.off", m) && !is_empty(m))
      robustness("FAUST tr_reg_000", m, (std::min)(n, std::size_t(num_vertices(m)) / 4));
  }
}

// ---------------------------------------------------------------- voting-pair cap

// What `maximum_number_of_voting_pairs` does to tau: only that many of the
// similar pairs, drawn with the seed, vote for boundaries (all of them still
// support); measured against the uncapped transform on the same samples.
// tau sums the votes, so a cap scales it down by about the share of pairs
// that vote: the difference is taken after scaling the capped tau by
// (similar pairs / voting pairs), the estimate of the uncapped sum. Columns:
// that relative L2 difference, and the share of the 5 % of vertices with the
// largest tau that stay among the 5 % largest (the ridges).
void cap_study(const std::string& path, std::size_t n)
{
  Mesh m;
  if(!CGAL::IO::read_polygon_mesh(path, m) || is_empty(m)) { std::cout << "cannot read " << path << "\n"; return; }
  n = (std::min)(n, std::size_t(num_vertices(m)));
  const IRS::Geodesic_distance_matrix D = sample_geodesics(m, n);
  const Pairs pairs = similar_pairs(m, D, IRS::vertex_sdf_values(m), IRS::vertex_areas(m));
  auto run = [&](std::size_t cap, unsigned seed, double& seconds) {
    auto tau = get(CGAL::dynamic_vertex_property_t<double>(), m);
    CGAL::Real_timer t;
    t.start();
    IRS::compute_irsa_transform(m, D, pairs, tau, IRS::parameters::maximum_number_of_voting_pairs(cap).random_seed(seed));
    seconds = t.time();
    std::vector<double> out(num_vertices(m));
    for(auto v : m.vertices()) out[v.idx()] = get(tau, v);
    return out;
  };
  auto top = [](const std::vector<double>& tau) {
    std::vector<std::size_t> order(tau.size());
    for(std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    const std::size_t k = (std::max)(std::size_t(1), tau.size() / 20);
    std::partial_sort(order.begin(), order.begin() + std::ptrdiff_t(k), order.end(),
                      [&](std::size_t a, std::size_t b) { return tau[a] > tau[b] || (tau[a] == tau[b] && a < b); });
    std::vector<char> in(tau.size(), 0);
    for(std::size_t i = 0; i < k; ++i) in[order[i]] = 1;
    return in;
  };
  double t_full = 0.;
  const std::vector<double> full = run(std::numeric_limits<std::size_t>::max(), 0u, t_full); // no cap: the default
  const std::vector<char> full_top = top(full);
  std::vector<std::ptrdiff_t> identity(full.size());
  for(std::size_t v = 0; v < identity.size(); ++v) identity[v] = std::ptrdiff_t(v);
  std::cout << "\n## Voting-pair cap (`maximum_number_of_voting_pairs`): " << path << ", " << n << " samples, "
            << pairs.size() << " similar pairs, uncapped voting " << t_full << " s\n\n"
            << "| voting pairs | share | seed | voting s | speed-up | scaled tau: rel. L2 difference | top 5 % kept |\n"
               "|---|---|---|---|---|---|---|\n";
  for(std::size_t divisor : {2u, 4u, 8u, 16u})
    for(unsigned seed : {1u, 2u})
    {
      const std::size_t cap = (std::max)(std::size_t(1), pairs.size() / divisor);
      double t_cap = 0.;
      std::vector<double> capped = run(cap, seed, t_cap);
      for(double& x : capped) x *= double(pairs.size()) / double(cap);
      const std::vector<char> capped_top = top(capped);
      std::size_t kept = 0, k = 0;
      for(std::size_t v = 0; v < full.size(); ++v) { k += full_top[v]; kept += (full_top[v] && capped_top[v]); }
      std::cout << "| " << cap << " | 1/" << divisor << " | " << seed << " | " << std::setprecision(3) << t_cap
                << " | " << std::setprecision(2) << t_full / t_cap << "x | " << std::setprecision(3)
                << relative_l2(full, capped, identity) << " | " << std::setprecision(3)
                << 100. * double(kept) / double(k) << " % |\n";
    }
  std::cout << std::setprecision(6);
}

// ---------------------------------------------------------------- floor study

// share of true mirror quadruples passing d(a,p)~d(b,q) and d(a,q)~d(b,p):
// sample-level pairs (sample, sample nearest to its mirror vertex)
void quadruple_study()
{
  std::cout << "\n## Distance filter: % of true mirror quadruples {a,b},{p,q} passing d(a,p)~d(b,q) and "
               "d(a,q)~d(b,p) (eps 0.02), by floor (mean edge lengths)\n"
               "Pairs: farthest-point samples and the sample nearest to the mirror vertex; heat-method geodesics.\n\n"
               "| shape | symmetry | samples/vertices | floor 0 | 0.5 | 1 | 2 | 3 |\n|---|---|---|---|---|---|---|---|\n";
  std::vector<std::pair<std::string, IRS::Generated_shape<Mesh>>> shapes;
  shapes.emplace_back("ellipsoid", IRS::generate_ellipsoid<Mesh>(2500));
  shapes.emplace_back("capsule", IRS::generate_capsule<Mesh>(2500));
  shapes.emplace_back("snowman", IRS::generate_snowman<Mesh>(2500));
  shapes.emplace_back("two snowmen", IRS::generate_two_snowmen<Mesh>(2500));
  shapes.emplace_back("bent capsule", IRS::generate_bent_capsule<Mesh>(2500));
  for(auto& sh : shapes)
  {
    const Mesh& m = sh.second.mesh;
    IRS::Heat_method_geodesic_oracle<Mesh> oracle(m);
    for(double ratio : {0.25, 0.1})
    {
      const std::size_t ns = std::size_t(ratio * double(num_vertices(m)));
      const auto samples = IRS::farthest_point_samples(m, IRS::parameters::number_of_samples(ns).random_seed(1u));
      const auto D = IRS::compute_geodesic_distance_matrix(oracle, samples);
      const IRS::internal::Sample_distance_matrix dss(D);
      for(const auto& sym : sh.second.symmetries)
      {
        Pairs mp;
        for(std::size_t i = 0; i < ns; ++i)
        {
          if(sym.mirror[samples[i]] < 0) continue;
          const std::size_t mv = std::size_t(sym.mirror[samples[i]]);
          std::size_t best = 0;
          float bd = std::numeric_limits<float>::infinity();
          for(std::size_t j = 0; j < ns; ++j)
            if(D(j, mv) < bd) { bd = D(j, mv); best = j; }
          if(best > i) mp.emplace_back(i, best);
        }
        std::cout << "| " << sh.first << " | " << sym.name << " | " << std::fixed << std::setprecision(2) << ratio;
        for(double fl : {0., 0.5, 1., 2., 3.})
        {
          IRS::internal::Distance_tolerance tol;
          tol.set(0.02, fl * sh.second.mean_edge_length);
          std::size_t total = 0, pass = 0;
          for(const auto& ab : mp)
            for(const auto& pq : mp)
            {
              if(&ab == &pq) continue;
              ++total;
              pass += tol(dss(ab.first, pq.first), dss(ab.second, pq.second)) &&
                      tol(dss(ab.first, pq.second), dss(ab.second, pq.first));
            }
          std::cout << " | " << std::setprecision(1) << (total ? 100. * double(pass) / double(total) : 0.);
        }
        std::cout << " |" << std::endl;
      }
    }
  }
}

// mean tau over `axis` / mean tau, for several floors, with the SDF similarity filter
void ridge_row(Mesh& m, const std::string& name, const std::vector<std::vector<char>>& axes,
               const std::vector<std::string>& axis_names, std::size_t ns, const std::vector<double>& floors)
{
  const IRS::Geodesic_distance_matrix D = sample_geodesics(m, ns);
  const Pairs pairs = similar_pairs(m, D, IRS::vertex_sdf_values(m), IRS::vertex_areas(m));
  for(double fl : floors)
  {
    auto tau = m.add_property_map<Mesh::Vertex_index, double>("v:tau", 0.).first;
    const auto r = IRS::compute_irsa_transform(m, D, pairs, tau, IRS::parameters::distance_tolerance_floor(fl));
    double sum = 0.;
    for(auto v : m.vertices()) sum += tau[v];
    std::cout << "| " << name << " | " << num_vertices(m) << " / " << ns << " | " << std::fixed
              << std::setprecision(2) << 100. * double(pairs.size()) / (0.5 * double(ns) * double(ns - 1))
              << " % | " << std::setprecision(1) << fl << " | " << r.voting_pairs.size() << " / "
              << r.number_of_voting_pairs << " |";
    for(std::size_t k = 0; k < axes.size(); ++k)
    {
      double s = 0.;
      std::size_t c = 0;
      for(auto v : m.vertices())
        if(axes[k][v.idx()]) { s += tau[v]; ++c; }
      std::cout << " " << axis_names[k] << ": " << std::setprecision(2)
                << (c && sum > 0. ? (s / double(c)) / (sum / double(num_vertices(m))) : 0.);
    }
    std::cout << " | " << r.voting_seconds << " |" << std::endl;
    m.remove_property_map(tau);
  }
}

void ridge_study(const std::vector<std::string>& dirs, const std::string& faust)
{
  std::cout << "\n## Ridge contrast by floor, with the SDF similarity filter: mean tau on the known axis / mean tau\n"
               "(generated shapes: vertices within one mean edge length of each known mirror plane; FAUST: the\n"
               "ground-truth axis vertices; camel: within one mean edge of its best PCA mirror plane)\n\n"
               "| shape | vertices / samples | similar | floor | voted / voting pairs | axis ratios | voting s |\n"
               "|---|---|---|---|---|---|---|\n";
  const std::vector<double> floors = {0., 0.5, 1., 2., 3.};
  std::vector<std::pair<std::string, IRS::Generated_shape<Mesh>>> shapes;
  shapes.emplace_back("ellipsoid", IRS::generate_ellipsoid<Mesh>(2000));
  shapes.emplace_back("capsule", IRS::generate_capsule<Mesh>(2000));
  shapes.emplace_back("snowman", IRS::generate_snowman<Mesh>(2000));
  shapes.emplace_back("two snowmen", IRS::generate_two_snowmen<Mesh>(2000));
  for(auto& sh : shapes)
  {
    Mesh& m = sh.second.mesh;
    std::vector<std::vector<char>> axes;
    std::vector<std::string> names;
    for(const auto& s : sh.second.symmetries)
    {
      std::vector<char> on(num_vertices(m), 0);
      for(auto v : m.vertices())
      {
        const auto p = m.point(v);
        const double d = s.plane[0] * p.x() + s.plane[1] * p.y() + s.plane[2] * p.z() + s.plane[3];
        on[v.idx()] = s.mirror[v.idx()] >= 0 && std::abs(d) <= sh.second.mean_edge_length;
      }
      axes.push_back(on);
      names.push_back(s.name);
    }
    ridge_row(m, sh.first, axes, names, num_vertices(m) / 4, floors);
  }
  if(!faust.empty())
    for(const char* id : {"tr_reg_000", "tr_reg_001", "tr_reg_010"})
    {
      Mesh m;
      if(!CGAL::IO::read_polygon_mesh(faust + "/" + id + ".off", m)) continue;
      std::vector<char> on(num_vertices(m), 0);
      std::ifstream a(faust + "/corres/" + id + ".vts"), b(faust + "/corres/" + id + ".sym.vts");
      std::size_t x, y;
      while(a >> x && b >> y)
        if(x == y && x >= 1 && x <= on.size()) on[x - 1] = 1;
      ridge_row(m, std::string("FAUST ") + id, {on}, {"axis"}, num_vertices(m) / 4, floors);
    }
  std::string camel;
  if(find_file(dirs, "camel.off", camel))
  {
    Mesh m;
    CGAL::IO::read_polygon_mesh(camel, m);
    // best of the three PCA planes through the centroid (nearest-vertex mirror error)
    std::vector<Eigen::Vector3d> P;
    for(auto v : m.vertices()) P.emplace_back(m.point(v).x(), m.point(v).y(), m.point(v).z());
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for(const auto& p : P) c += p;
    c /= double(P.size());
    Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
    for(const auto& p : P) C += (p - c) * (p - c).transpose();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(C);
    double best = std::numeric_limits<double>::infinity();
    Eigen::Vector3d normal = es.eigenvectors().col(0);
    for(int k = 0; k < 3; ++k)
    {
      const Eigen::Vector3d nk = es.eigenvectors().col(k);
      double err = 0.;
      for(std::size_t i = 0; i < P.size(); i += 20)
      {
        const Eigen::Vector3d r = P[i] - 2 * (P[i] - c).dot(nk) * nk;
        double md = std::numeric_limits<double>::infinity();
        for(const auto& q : P) md = (std::min)(md, (q - r).squaredNorm());
        err += std::sqrt(md);
      }
      if(err < best) { best = err; normal = nk; }
    }
    const double e = IRS::check_input(m).mean_edge_length;
    std::vector<char> on(P.size(), 0);
    for(std::size_t i = 0; i < P.size(); ++i) on[i] = std::abs((P[i] - c).dot(normal)) <= e;
    ridge_row(m, "camel", {on}, {"PCA plane"}, 1000, floors);
  }
}

} // namespace

int main(int argc, char** argv)
{
  std::vector<std::string> dirs;
  std::vector<std::size_t> sample_counts = {500, 1000, 2000, 3000, 5000};
  std::vector<std::string> meshes = {"camel.off", "man.off"};
  std::size_t reference_samples = 300;
  int threads = 0;
  bool floor_study = false, robust = false, scaling_study = true;
  std::size_t robustness_samples = 1000, cap_samples = 1000;
  std::vector<double> reference_thresholds = {IRS::default_similarity_threshold, 0.05, 0.1, 0.2};
  std::string faust;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if(a == "--samples" && i + 1 < argc) { sample_counts.clear(); for(auto& s : split(argv[++i])) sample_counts.push_back(std::stoul(s)); }
    else if(a == "--meshes" && i + 1 < argc) meshes = split(argv[++i]);
    else if(a == "--threads" && i + 1 < argc) threads = std::stoi(argv[++i]);
    else if(a == "--reference-samples" && i + 1 < argc) reference_samples = std::stoul(argv[++i]);
    else if(a == "--floor-study") floor_study = true;
    else if(a == "--no-scaling") scaling_study = false;
    else if(a == "--robustness") robust = true;
    else if(a == "--robustness-samples" && i + 1 < argc) robustness_samples = std::stoul(argv[++i]);
    else if(a == "--reference-eps" && i + 1 < argc)
    { reference_thresholds.clear(); for(auto& x : split(argv[++i])) reference_thresholds.push_back(std::stod(x)); }
    else if(a == "--faust" && i + 1 < argc) faust = argv[++i];
    else if(a == "--cap-samples" && i + 1 < argc) cap_samples = std::stoul(argv[++i]);
    else dirs.push_back(a);
  }
#ifdef CGAL_LINKED_WITH_TBB
  std::unique_ptr<tbb::global_control> control;
  if(threads > 0)
    control.reset(new tbb::global_control(tbb::global_control::max_allowed_parallelism, std::size_t(threads)));
#endif
  std::cout << "# IRSA transform benchmark (heat-method geodesics, SDF signatures, default voting parameters; "
            << (threads > 0 ? std::to_string(threads) : std::string("all")) << " threads)\n"
            << "Stage columns after 'voting s' are CPU seconds summed over threads.\n";
  if(dirs.empty())
    std::cout << "No mesh directory given: pass the directories holding camel.off / man.off.\n";
  if(reference_samples > 0)
  {
    std::string camel;
    // the paper's similarity threshold and looser ones: the reference costs
    // O(voting pairs x (V + |beta| x similar pairs)), the fast voting about
    // O(voting pairs x (V / 16 + similar pairs + E K) + similar pairs x |beta|)
    if(find_file(dirs, meshes.front(), camel))
      versus_reference(camel, reference_samples, reference_thresholds);
    std::vector<std::pair<std::string, Mesh>> shapes;
    for(const std::string& name : meshes)
    {
      std::string path;
      Mesh m;
      if(find_file(dirs, name, path) && CGAL::IO::read_polygon_mesh(path, m) && !is_empty(m))
        shapes.emplace_back(name, std::move(m));
    }
    if(!faust.empty())
    {
      Mesh m;
      if(CGAL::IO::read_polygon_mesh(faust + "/tr_reg_000.off", m) && !is_empty(m))
        shapes.emplace_back("FAUST tr_reg_000", std::move(m));
    }
    shapes.emplace_back("generated two snowmen", IRS::generate_two_snowmen<Mesh>(3000).mesh);
    shapes.emplace_back("generated stick figure", IRS::generate_stick_figure<Mesh>(3000).mesh);
    shapes.emplace_back("generated snowman", IRS::generate_snowman<Mesh>(2500).mesh);
    versus_reference_by_shape(shapes, reference_samples);
  }
  for(const std::string& name : meshes)
  {
    std::string path;
    if(cap_samples > 0 && find_file(dirs, name, path)) cap_study(path, cap_samples);
  }
  for(const std::string& name : meshes)
  {
    if(!scaling_study) break;
    std::string path;
    if(find_file(dirs, name, path)) scaling(path, sample_counts);
    else std::cout << "\n" << name << " not found in the given directories\n";
  }
  if(robust)
    robustness_study(dirs, faust, robustness_samples);
  if(floor_study)
  {
    quadruple_study();
    ridge_study(dirs, faust);
  }
  return 0;
}
