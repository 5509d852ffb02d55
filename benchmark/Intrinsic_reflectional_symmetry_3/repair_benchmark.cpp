// Copyright (c) 2026 The Intrinsic_reflectional_symmetry_3 project.
// SPDX-License-Identifier: LGPL-3.0-or-later
// Author(s)     : The Intrinsic_reflectional_symmetry_3 developers
//
// Symmetry-driven part repair (paper Sec. 4.2) by the package's protocol
// (run_part_repair_protocol() in part_repair.h: cut limbs off with a plane,
// cap, run the pipeline, repair, measure), on the generated stick figure and
// on FAUST (DATA_DIR/faust_5k, skipped when absent): per shape, one limb
// (the right forearm, cut 0.2 from the hand tip) and two limbs (that forearm
// and the other side's lower leg, cut 0.3 from the foot tip). The limb tips
// are found through the data set's correspondences (corres/X.vts): the
// reference samples at the right hand (largest x on tr_reg_000) and at the
// lowest foot on the other side. Printed per run: the max and mean distance
// of the removed vertices to the repaired surface (% of its bounding-box
// diagonal), closed / valid / self-intersections (any, and through new faces;
// most FAUST meshes self-intersect already), parts added, times.
//
// usage: repair_benchmark [DATA_DIR] [--samples N] [--only NAME] [--write DIR]
//   DATA_DIR default ../shared/data;  N samples (default 1000);
//   NAME only the shapes whose name contains NAME;  DIR: damaged and repaired meshes written there

#include <CGAL/Intrinsic_reflectional_symmetry_3/part_repair.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/shape_generators.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace IRS = CGAL::Intrinsic_reflectional_symmetry_3;
namespace fs = std::filesystem;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

namespace {

struct Options
{
  std::string data = "../shared/data", only, write;
  std::size_t samples = 1000;
};

std::vector<long> read_vts(const fs::path& p)
{
  std::ifstream in(p);
  std::vector<long> v;
  long x;
  while(in >> x) v.push_back(x - 1); // 1-based
  return v;
}

template <typename Score>
std::size_t extreme_vertex(const Mesh& m, const Score& score)
{
  std::size_t best = 0;
  double bs = -1e300;
  for(Mesh::Vertex_index v : vertices(m))
    if(score(m.point(v)) > bs) { bs = score(m.point(v)); best = v.idx(); }
  return best;
}

void print_header()
{
  std::printf("%-12s %-16s %7s %7s %7s %6s %6s %6s %6s %5s %8s %8s  %s\n", "shape", "limbs", "removed",
              "max%", "mean%", "closed", "valid", "SI", "newSI", "parts", "t_pipe", "t_repair", "error");
}

void run(const Options& o, const std::string& shape, const std::string& limbs, const Mesh& m,
         const std::vector<IRS::Limb_cut>& cuts)
{
  Mesh damaged, repaired;
  IRS::Part_repair_protocol_result r;
  try
  {
    r = IRS::run_part_repair_protocol(m, cuts, damaged, repaired, IRS::parameters::number_of_samples(o.samples));
  }
  catch(const IRS::Input_error& e)
  {
    r.error = std::string("(cut) ") + e.what();
  }
  std::printf("%-12s %-16s %7zu %7.2f %7.2f %6s %6s %6s %6s %5zu %8.2f %8.2f  %s\n", shape.c_str(), limbs.c_str(),
              r.removed_vertices, r.max_distance, r.mean_distance, r.closed ? "yes" : "NO", r.valid ? "yes" : "NO",
              r.self_intersecting ? (r.input_self_intersecting ? "input" : "YES") : "no",
              r.new_self_intersections ? "YES" : "no", r.report.number_of_parts, r.seconds_pipeline,
              r.seconds_repair, r.error.c_str());
  std::fflush(stdout);
  if(!o.write.empty())
  {
    fs::create_directories(o.write);
    const std::string base = (fs::path(o.write) / (shape + "_" + limbs)).string();
    CGAL::IO::write_polygon_mesh(base + "_damaged.off", damaged, CGAL::parameters::stream_precision(10));
    if(num_vertices(repaired) > 0)
      CGAL::IO::write_polygon_mesh(base + "_repaired.off", repaired, CGAL::parameters::stream_precision(10));
  }
}

} // namespace

int main(int argc, char** argv)
{
  Options o;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if(a == "--samples" && i + 1 < argc) o.samples = std::size_t(std::atol(argv[++i]));
    else if(a == "--only" && i + 1 < argc) o.only = argv[++i];
    else if(a == "--write" && i + 1 < argc) o.write = argv[++i];
    else o.data = a;
  }
  std::printf("part repair protocol, %zu samples per shape; distances in %% of the repaired bbox diagonal\n",
              o.samples);
  print_header();

  // generated: the stick figure (right arm cut 0.7 from its tip, left leg 0.8 from its foot)
  if(o.only.empty() || std::string("stick").find(o.only) != std::string::npos)
  {
    Mesh m = IRS::generate_stick_figure<Mesh>(3000).mesh;
    IRS::Limb_cut arm, leg;
    arm.tip = extreme_vertex(m, [](const K::Point_3& p) { return p.x(); });
    arm.length = 0.7;
    leg.tip = extreme_vertex(m, [](const K::Point_3& p) { return p.x() < 0. ? -p.z() : -1e300; });
    leg.length = 0.8;
    run(o, "stick", "arm", m, {arm});
    run(o, "stick", "arm+leg", m, {arm, leg});
    for(Mesh::Vertex_index v : vertices(m))
      if(m.point(v).x() > 0.) m.point(v) = K::Point_3(1.03 * m.point(v).x(), m.point(v).y(), m.point(v).z());
    run(o, "stick-3%", "arm", m, {arm}); // imperfect symmetry: the right half 3 % longer
  }

  const fs::path dir = fs::path(o.data) / "faust_5k" / "faust";
  if(!fs::exists(dir / "tr_reg_000.off"))
  {
    std::printf("FAUST: %s absent, skipped\n", dir.string().c_str());
    return 0;
  }
  Mesh ref;
  CGAL::IO::read_polygon_mesh((dir / "tr_reg_000.off").string(), ref);
  const std::vector<long> rv = read_vts(dir / "corres" / "tr_reg_000.vts");
  auto P = [&](std::size_t k) { return ref.point(Mesh::Vertex_index(Mesh::size_type(rv[k]))); };
  std::size_t kh = 0, kf = rv.size();
  double mid = 0.;
  for(std::size_t k = 0; k < rv.size(); ++k) { if(P(k).x() > P(kh).x()) kh = k; mid += P(k).x(); }
  mid /= double(rv.size());
  for(std::size_t k = 0; k < rv.size(); ++k)
    if(P(k).x() < mid && (kf == rv.size() || P(k).y() < P(kf).y())) kf = k;

  std::vector<std::string> names;
  for(const auto& f : fs::directory_iterator(dir))
    if(f.path().extension() == ".off") names.push_back(f.path().stem().string());
  std::sort(names.begin(), names.end());
  for(const std::string& name : names)
  {
    if(!o.only.empty() && name.find(o.only) == std::string::npos) continue;
    Mesh m;
    const std::vector<long> xv = read_vts(dir / "corres" / (name + ".vts"));
    if(!CGAL::IO::read_polygon_mesh((dir / (name + ".off")).string(), m) || xv.size() != rv.size()) continue;
    IRS::Limb_cut hand, foot;
    hand.tip = std::size_t(xv[kh]);
    hand.length = 0.2;
    foot.tip = std::size_t(xv[kf]);
    foot.length = 0.3;
    run(o, name, "forearm", m, {hand});
    run(o, name, "forearm+leg", m, {hand, foot});
  }
  return 0;
}
