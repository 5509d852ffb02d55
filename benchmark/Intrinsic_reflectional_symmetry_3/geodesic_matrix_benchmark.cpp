// Copyright (c) 2026 The Intrinsic_reflectional_symmetry_3 project.
// SPDX-License-Identifier: LGPL-3.0-or-later
// Author(s)     : The Intrinsic_reflectional_symmetry_3 developers
//
// Geodesic distance matrix benchmark: farthest-point sampling, then the full
// samples x vertices matrix with the heat-method and Dijkstra oracles, the
// exact oracle on a subset of the sources (its full time is extrapolated), and
// the accuracy of heat and Dijkstra against exact on that subset.
//
// usage: geodesic_matrix_benchmark [mesh files...] [--data DIR] [--samples N]
//                                  [--exact-sources K] [--threads T]
// (defaults: N = 3000, K = 50 (0 skips the exact oracle), T = all cores)
// Without mesh files, camel.off and man.off are looked up in DIR (or
// DIR/meshes), DIR being --data or the environment variable CGAL_DATA_DIR;
// missing files are skipped with a message. Timings are wall-clock.

#include <CGAL/Intrinsic_reflectional_symmetry_3/geodesic_distances.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/sampling.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Real_timer.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#include <tbb/task_arena.h>
#endif
#if defined(__unix__) || defined(__APPLE__)
#include <sys/resource.h>
#endif

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace IRS = CGAL::Intrinsic_reflectional_symmetry_3;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3>                      Mesh;

namespace {

// peak resident set size of the process so far, in MB (0 where unknown)
double peak_rss_mb()
{
#if defined(__APPLE__)
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / (1024. * 1024.); // bytes
#elif defined(__unix__)
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024.; // kilobytes
#else
  return 0.;
#endif
}

int threads_in_use()
{
#ifdef CGAL_LINKED_WITH_TBB
  return int((std::min)(std::size_t(tbb::this_task_arena::max_concurrency()),
                        tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism)));
#else
  return 1;
#endif
}

bool readable(const std::string& path) { return std::ifstream(path).good(); }

struct Row
{
  std::string what, time, note;
};

// the first `k` rows of a matrix (the subset on which exact distances are computed)
std::vector<std::vector<float> > first_rows(const IRS::Geodesic_distance_matrix& m, std::size_t k)
{
  std::vector<std::vector<float> > rows;
  for(std::size_t i = 0; i < k; ++i)
    rows.emplace_back(m.row(i), m.row(i) + m.number_of_vertices());
  return rows;
}

// mean and max |approx - exact| over the finite exact entries, relative to the largest exact distance
std::string accuracy(const std::vector<std::vector<float> >& approx, const std::vector<std::vector<float> >& exact)
{
  if(exact.empty())
    return "accuracy not measured (no exact sources)";
  double largest = 0, sum = 0, worst = 0;
  std::size_t count = 0;
  for(const auto& row : exact)
    for(float d : row)
      if(std::isfinite(d)) largest = (std::max)(largest, double(d));
  for(std::size_t i = 0; i < exact.size(); ++i)
    for(std::size_t v = 0; v < exact[i].size(); ++v)
      if(std::isfinite(exact[i][v])) {
        const double e = std::abs(double(approx[i][v]) - double(exact[i][v]));
        sum += e;
        worst = (std::max)(worst, e);
        ++count;
      }
  std::ostringstream s;
  s << std::fixed << std::setprecision(2) << "vs exact: mean " << 100 * sum / double(count ? count : 1) / largest
    << " %, max " << 100 * worst / largest << " % of the largest distance";
  return s.str();
}

std::string seconds(double t)
{
  std::ostringstream s;
  s << std::fixed << std::setprecision(t < 10 ? 3 : 1) << t << " s";
  return s.str();
}

void benchmark(const std::string& path, std::size_t requested_samples, std::size_t exact_sources)
{
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(path, mesh) || num_vertices(mesh) == 0) {
    std::cout << "skipping " << path << ": cannot read it as a polygon mesh\n";
    return;
  }
  if(!CGAL::is_triangle_mesh(mesh)) {
    std::cout << "skipping " << path << ": not a triangle mesh\n";
    return;
  }
  const std::size_t n = num_vertices(mesh);
  const std::size_t number_of_samples = (std::min)(requested_samples, n);
  exact_sources = (std::min)(exact_sources, number_of_samples);
  const int threads = threads_in_use();
  std::vector<Row> rows;
  CGAL::Real_timer timer;

  timer.start();
  const std::vector<std::size_t> samples =
    IRS::farthest_point_samples(mesh, IRS::parameters::number_of_samples(number_of_samples).random_seed(0u));
  timer.stop();
  rows.push_back({ "farthest-point sampling", seconds(timer.time()),
                   std::to_string(samples.size()) + " samples, 1 thread" });
  const std::vector<std::size_t> subset(samples.begin(), samples.begin() + exact_sources);
  const std::string size = std::to_string(samples.size()) + " x " + std::to_string(n);

  // exact first: its rows are the reference for the others
  std::vector<std::vector<float> > reference;
  if(!subset.empty()) {
    timer.reset(); timer.start();
    IRS::Exact_geodesic_oracle<Mesh> exact(mesh);
    timer.stop();
    const double exact_build = timer.time();
    timer.reset(); timer.start();
    reference = first_rows(IRS::compute_geodesic_distance_matrix(exact, subset), subset.size());
    timer.stop();
    const double exact_subset = timer.time();
    rows.push_back({ "exact: set-up", seconds(exact_build),
                     std::to_string(exact.number_of_components()) + " component(s)" });
    rows.push_back({ "exact: " + std::to_string(subset.size()) + " x " + std::to_string(n), seconds(exact_subset),
                     std::to_string(threads) + " thread(s)" });
    rows.push_back({ "exact: " + size + " (EXTRAPOLATED)",
                     seconds(exact_subset * double(samples.size()) / double(subset.size())),
                     "estimate = subset time x " + std::to_string(samples.size()) + " / " +
                     std::to_string(subset.size()) });
  }

  {
    timer.reset(); timer.start();
    IRS::Heat_method_geodesic_oracle<Mesh> heat(mesh, IRS::parameters::number_of_threads(threads));
    timer.stop();
    rows.push_back({ "heat: set-up", seconds(timer.time()),
                     std::to_string(heat.number_of_workers()) + " solver set(s)" });
    timer.reset(); timer.start();
    const IRS::Geodesic_distance_matrix m = IRS::compute_geodesic_distance_matrix(heat, samples);
    timer.stop();
    rows.push_back({ "heat: " + size, seconds(timer.time()),
                     std::to_string(threads) + " thread(s); " + accuracy(first_rows(m, subset.size()), reference) });
  }
  {
    timer.reset(); timer.start();
    IRS::Dijkstra_geodesic_oracle<Mesh> dijkstra(mesh);
    timer.stop();
    rows.push_back({ "dijkstra: set-up", seconds(timer.time()), "" });
    timer.reset(); timer.start();
    const IRS::Geodesic_distance_matrix m = IRS::compute_geodesic_distance_matrix(dijkstra, samples);
    timer.stop();
    rows.push_back({ "dijkstra: " + size, seconds(timer.time()),
                     std::to_string(threads) + " thread(s); " + accuracy(first_rows(m, subset.size()), reference) });
  }

  std::ostringstream rss;
  rss << std::fixed << std::setprecision(0) << peak_rss_mb() << " MB";
  rows.push_back({ "peak RSS of the process so far", rss.str(), "" });

  std::cout << "\n" << path << ": " << n << " vertices, " << num_faces(mesh) << " faces\n";
  std::size_t w = 0;
  for(const Row& r : rows) w = (std::max)(w, r.what.size());
  for(const Row& r : rows)
    std::cout << "  " << std::left << std::setw(int(w)) << r.what << "  " << std::right << std::setw(9) << r.time
              << "  " << r.note << "\n";
  std::cout << std::flush;
}

} // namespace

int main(int argc, char** argv)
{
  std::vector<std::string> files;
  std::string data_dir;
  if(const char* env = std::getenv("CGAL_DATA_DIR")) data_dir = env;
  std::size_t samples = 3000, exact_sources = 50;
  int threads = 0;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    const bool has_value = i + 1 < argc;
    if(a == "--data" && has_value) data_dir = argv[++i];
    else if(a == "--samples" && has_value) samples = std::stoul(argv[++i]);
    else if(a == "--exact-sources" && has_value) exact_sources = std::stoul(argv[++i]);
    else if(a == "--threads" && has_value) threads = std::stoi(argv[++i]);
    else if(a == "-h" || a == "--help") {
      std::cout << "usage: " << argv[0]
                << " [mesh files...] [--data DIR] [--samples N] [--exact-sources K] [--threads T]\n";
      return EXIT_SUCCESS;
    }
    else files.push_back(a);
  }
  if(samples == 0) {
    std::cerr << "--samples must be positive\n";
    return EXIT_FAILURE;
  }

#ifdef CGAL_LINKED_WITH_TBB
  std::unique_ptr<tbb::global_control> limit;
  if(threads > 0)
    limit.reset(new tbb::global_control(tbb::global_control::max_allowed_parallelism, std::size_t(threads)));
#else
  if(threads > 1)
    std::cout << "TBB is not linked: running on 1 thread\n";
#endif

  std::cout << "geodesic distance matrix benchmark: " << samples << " farthest-point samples, exact on "
            << exact_sources << " of them, " << threads_in_use() << " thread(s)\n";
  if(files.empty()) {
    for(const std::string name : { "camel.off", "man.off" }) {
      std::string found;
      for(const std::string& candidate : { data_dir + "/" + name, data_dir + "/meshes/" + name })
        if(!data_dir.empty() && readable(candidate)) { found = candidate; break; }
      if(found.empty())
        std::cout << "skipping " << name << ": not found in "
                  << (data_dir.empty() ? std::string("(no --data DIR and no CGAL_DATA_DIR)") : data_dir + "[/meshes]")
                  << "\n";
      else
        files.push_back(found);
    }
  }

  for(const std::string& f : files)
    benchmark(f, samples, exact_sources);
  return EXIT_SUCCESS;
}
