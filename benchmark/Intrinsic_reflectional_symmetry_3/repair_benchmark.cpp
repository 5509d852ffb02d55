// Copyright (c) 2026 The Intrinsic_reflectional_symmetry_3 project.
// SPDX-License-Identifier: LGPL-3.0-or-later
// Author(s)     : The Intrinsic_reflectional_symmetry_3 developers
//
// Symmetry-driven part repair (paper Sec. 4.2) by the package's protocol
// (run_part_repair_protocol() in part_repair.h: cut limbs off with a plane,
// cap, run the pipeline, repair, measure), on the generated stick figure,
// on CGAL's complete meshes (DATA_DIR/cgal_meshes, decimated to 5000
// vertices where larger; only the row "none") and on FAUST (DATA_DIR/faust_5k; each data
// set skipped when absent): per shape, the complete
// shape (row "none": nothing is missing, so "parts" must be 0), one limb
// (the right forearm, cut 0.2 from the hand tip) and two limbs (that forearm
// and the other side's lower leg, cut 0.3 from the foot tip). The limb tips
// are found through the data set's correspondences (corres/X.vts): the
// reference samples at the right hand (largest x on tr_reg_000) and at the
// lowest foot on the other side. Printed per run: the max (overall and per limb) and mean distance
// of the removed vertices to the repaired surface (% of its bounding-box
// diagonal), closed / valid / self-intersections (any, and through new faces;
// most FAUST meshes self-intersect already), parts added, times; and, on
// FAUST, the *oracle* figure: the max distance (same unit) of the removed
// vertices to the best rigid mirror copy of the intact limbs, built from the
// ground-truth symmetric correspondence (corres/X.sym.vts): reflection across
// the plane fitted to all ground-truth pairs (normal: main direction of the
// pair differences; through the centroid of their midpoints), then, per limb,
// the rigid motion (Eigen::umeyama) taking the reflected partners of the
// removed vertices onto them. No rigid mirror copy of the intact limb does
// much better, so where the oracle exceeds 2 % (posed limbs) the 2 % bar is
// out of reach of the paper's method.
//
// usage: repair_benchmark [DATA_DIR] [--samples N] [--only NAME] [--write DIR] [--oracle-only] [--cut-heights]
//                         [--no-complete]
//   DATA_DIR default ../shared/data;  N samples (default 1000);
//   NAME only the shapes whose name contains NAME;  DIR: damaged and repaired meshes written there;
//   --oracle-only: FAUST oracle figures only (no repair);
//   --cut-heights: also the stick figure's arm and leg, each cut alone at 0.4, 0.5, ..., 1.2 from
//   its tip (rows "arm@0.4" ...): where a limb is cut must not matter;
//   --no-complete: without the rows of CGAL's complete meshes (DATA_DIR/cgal_meshes)

#include <CGAL/Intrinsic_reflectional_symmetry_3/part_repair.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/prepare_mesh.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/shape_generators.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>

#include <Eigen/Dense>
#include <Eigen/Geometry>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <string>
#include <utility>
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
  bool oracle_only = false, cut_heights = false, complete = true;
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

typedef IRS::internal::Repair_point Point;

// the oracle figure (see the header), in % of the bbox diagonal of `m`; NaN without ground truth
double oracle_percent(const Mesh& m, const std::vector<long>& vts, const std::vector<long>& sym,
                      const std::vector<IRS::Limb_cut>& cuts)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if(vts.empty() || vts.size() != sym.size()) return nan;
  const IRS::internal::Repair_soup s = IRS::internal::mesh_to_repair_soup(m, CGAL::parameters::default_values());
  const std::size_t n = s.points.size();
  std::vector<long> partner(n, -1);
  for(std::size_t k = 0; k < vts.size(); ++k)
  {
    if(vts[k] < 0 || sym[k] < 0 || std::size_t(vts[k]) >= n || std::size_t(sym[k]) >= n) return nan;
    partner[std::size_t(vts[k])] = sym[k];
    if(partner[std::size_t(sym[k])] < 0) partner[std::size_t(sym[k])] = vts[k];
  }
  // the plane of all the ground-truth pairs
  Eigen::Matrix3d M = Eigen::Matrix3d::Zero();
  Eigen::Vector3d mid = Eigen::Vector3d::Zero();
  std::size_t used = 0;
  for(std::size_t k = 0; k < vts.size(); ++k)
  {
    const Point &p = s.points[std::size_t(vts[k])], &q = s.points[std::size_t(sym[k])];
    const Eigen::Vector3d d(p.x() - q.x(), p.y() - q.y(), p.z() - q.z());
    M += d * d.transpose();
    mid += 0.5 * Eigen::Vector3d(p.x() + q.x(), p.y() + q.y(), p.z() + q.z());
    ++used;
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(M);
  const Eigen::Vector3d nn = es.eigenvectors().col(2), c = mid / double(used);
  auto reflect = [&](const Point& p) {
    const Eigen::Vector3d x(p.x(), p.y(), p.z());
    return Eigen::Vector3d(x - 2. * (x - c).dot(nn) * nn);
  };
  const auto nb = IRS::internal::soup_neighbours(s);
  const double e = IRS::internal::soup_mean_edge_length(s), diag = IRS::internal::soup_bbox_diagonal(s.points);
  double worst = 0.;
  for(const IRS::Limb_cut& cut : cuts)
  {
    const std::vector<std::size_t> R = IRS::internal::limb_vertices(s, nb, cut.tip, cut.length, e);
    std::vector<std::size_t> with;
    for(std::size_t v : R) if(partner[v] >= 0) with.push_back(v);
    if(with.size() < 3) return nan;
    Eigen::Matrix3Xd A(3, Eigen::Index(with.size())), B(3, Eigen::Index(with.size()));
    std::vector<char> in(n, 0);
    for(std::size_t j = 0; j < with.size(); ++j)
    {
      const std::size_t v = with[j], w = std::size_t(partner[v]);
      A.col(Eigen::Index(j)) = reflect(s.points[w]);
      B.col(Eigen::Index(j)) = Eigen::Vector3d(s.points[v].x(), s.points[v].y(), s.points[v].z());
      in[w] = 1;
    }
    const Eigen::Matrix4d T = Eigen::umeyama(A, B, false);
    // the intact limb's surface (its partners' faces, one ring wider), reflected and moved
    std::vector<char> wide = in;
    for(std::size_t v = 0; v < n; ++v) if(in[v]) for(std::size_t w : nb[v]) wide[w] = 1;
    IRS::internal::Repair_soup copy;
    copy.points.resize(n);
    for(std::size_t v = 0; v < n; ++v)
    {
      const Eigen::Vector3d r = reflect(s.points[v]);
      const Eigen::Vector3d t = (T * Eigen::Vector4d(r.x(), r.y(), r.z(), 1.)).head<3>();
      copy.points[v] = Point(t.x(), t.y(), t.z());
    }
    for(const auto& t : s.triangles)
      if(wide[t[0]] && wide[t[1]] && wide[t[2]]) copy.triangles.push_back(t);
    const IRS::internal::Repair_surface cs = IRS::internal::soup_to_surface(IRS::internal::compact_soup(copy));
    IRS::internal::Repair_tree tree(faces(cs).first, faces(cs).second, cs);
    tree.accelerate_distance_queries();
    for(std::size_t v : R) worst = (std::max)(worst, std::sqrt(tree.squared_distance(s.points[v])));
  }
  return diag > 0. ? 100. * worst / diag : nan;
}

void print_header()
{
  std::printf("%-12s %-16s %7s %7s %-11s %7s %7s %6s %6s %6s %6s %5s %8s %8s  %s\n", "shape", "limbs", "removed",
              "max%", "per limb", "mean%", "oracle%", "closed", "valid", "SI", "newSI", "parts", "t_pipe", "t_repair", "error");
}

void run(const Options& o, const std::string& shape, const std::string& limbs, const Mesh& m,
         const std::vector<IRS::Limb_cut>& cuts, double oracle = std::numeric_limits<double>::quiet_NaN())
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
  std::string per_limb;
  for(double d : r.max_distance_per_cut)
  {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%s%.2f", per_limb.empty() ? "" : "/", d);
    per_limb += buf;
  }
  if(per_limb.empty()) per_limb = "-";
  std::printf("%-12s %-16s %7zu %7.2f %-11s %7.2f %7.2f %6s %6s %6s %6s %5zu %8.2f %8.2f  %s\n", shape.c_str(), limbs.c_str(),
              r.removed_vertices, r.max_distance, per_limb.c_str(), r.mean_distance, oracle, r.closed ? "yes" : "NO", r.valid ? "yes" : "NO",
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
    else if(a == "--oracle-only") o.oracle_only = true;
    else if(a == "--cut-heights") o.cut_heights = true;
    else if(a == "--no-complete") o.complete = false;
    else o.data = a;
  }
  std::printf("part repair protocol, %zu samples per shape; distances in %% of the repaired bbox diagonal\n",
              o.samples);
  print_header();

  // generated: the stick figure (right arm cut 0.7 from its tip, left leg 0.8 from its foot)
  if(!o.oracle_only && (o.only.empty() || std::string("stick").find(o.only) != std::string::npos))
  {
    Mesh m = IRS::generate_stick_figure<Mesh>(3000).mesh;
    IRS::Limb_cut arm, leg;
    arm.tip = extreme_vertex(m, [](const K::Point_3& p) { return p.x(); });
    arm.length = 0.7;
    leg.tip = extreme_vertex(m, [](const K::Point_3& p) { return p.x() < 0. ? -p.z() : -1e300; });
    leg.length = 0.8;
    run(o, "stick", "none", m, {});
    run(o, "stick", "arm", m, {arm});
    run(o, "stick", "arm+leg", m, {arm, leg});
    if(o.cut_heights)
      for(const auto& limb : {std::make_pair("arm", arm), std::make_pair("leg", leg)})
        for(int tenths = 4; tenths <= 12; ++tenths)
        {
          IRS::Limb_cut c = limb.second;
          c.length = 0.1 * tenths;
          char name[32];
          std::snprintf(name, sizeof name, "%s@%.1f", limb.first, c.length);
          run(o, "stick", name, m, {c});
        }
    for(Mesh::Vertex_index v : vertices(m))
      if(m.point(v).x() > 0.) m.point(v) = K::Point_3(1.03 * m.point(v).x(), m.point(v).y(), m.point(v).z());
    run(o, "stick-3%", "arm", m, {arm}); // imperfect symmetry: the right half 3 % longer
  }

  // CGAL's complete meshes with a mirror symmetry (DATA_DIR/cgal_meshes), each
  // decimated to 5000 vertices where larger, as `irsym --target-vertices 5000`
  // does (it would remesh the smaller ones up): on a complete shape nothing may
  // be added (row "none", "parts" must be 0)
  const fs::path cgal_dir = fs::path(o.data) / "cgal_meshes";
  if(o.complete && !o.oracle_only && fs::exists(cgal_dir))
  {
    std::vector<fs::path> files;
    for(const auto& f : fs::directory_iterator(cgal_dir))
      if(f.path().extension() == ".off" && (o.only.empty() || f.path().stem().string().find(o.only) != std::string::npos))
        files.push_back(f.path());
    std::sort(files.begin(), files.end());
    for(const fs::path& f : files)
    {
      Mesh input;
      if(!CGAL::IO::read_polygon_mesh(f.string(), input))
      {
        std::printf("%-12s %-16s  (read) could not read %s\n", f.stem().string().c_str(), "none", f.string().c_str());
        continue;
      }
      try
      {
        // decimated to 5000 vertices where larger, kept as it is where smaller
        const std::size_t target = (std::min)(std::size_t(5000), std::size_t(num_vertices(input)));
        const auto prepared = IRS::prepare_mesh(input, IRS::parameters::target_number_of_vertices(target));
        run(o, f.stem().string(), "none", prepared.working_mesh(), {});
      }
      catch(const std::exception& err)
      {
        std::printf("%-12s %-16s  (prepare) %s\n", f.stem().string().c_str(), "none", err.what());
      }
    }
  }
  else if(o.complete && !o.oracle_only)
    std::printf("CGAL meshes: %s absent, skipped\n", cgal_dir.string().c_str());

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
    const std::vector<long> sv = read_vts(dir / "corres" / (name + ".sym.vts"));
    if(o.oracle_only)
    {
      std::printf("%-12s %-16s oracle %.2f %%\n", name.c_str(), "forearm", oracle_percent(m, xv, sv, {hand}));
      std::printf("%-12s %-16s oracle %.2f %%\n", name.c_str(), "forearm+leg", oracle_percent(m, xv, sv, {hand, foot}));
      continue;
    }
    run(o, name, "none", m, {}); // the complete shape: nothing may be added
    run(o, name, "forearm", m, {hand}, oracle_percent(m, xv, sv, {hand}));
    run(o, name, "forearm+leg", m, {hand, foot}, oracle_percent(m, xv, sv, {hand, foot}));
  }
  return 0;
}
