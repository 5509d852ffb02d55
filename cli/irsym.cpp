// Copyright (c) 2026 The Intrinsic_reflectional_symmetry_3 project.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// irsym: partial intrinsic reflectional symmetry of a closed triangle mesh,
// from the command line. Runs the package's pipeline stage by stage and writes
// every output in terms of the INPUT mesh's vertices and faces.

#include <CGAL/Intrinsic_reflectional_symmetry_3/check_input.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/geodesic_distances.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/irsa_curves.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/irsa_transform.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/part_repair.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/prepare_mesh.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/sampling.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/segmentation.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/shape_generators.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/signatures.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/symmetric_map.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/symmetry_detection.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#include <tbb/info.h>
#endif

#include "irsym_output.h"

#include <algorithm>
#include <cmath>
#include <chrono>
#include <filesystem>
#include <iomanip>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <thread>

namespace IRS = CGAL::Intrinsic_reflectional_symmetry_3;
namespace fs = std::filesystem;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

namespace {

// What one seed of the samples gives, from the samples to the symmetric map;
// --tries keeps the first run whose map is not suspect, or else the one of
// least symmetric_map_defect()
// one run of the pipeline (the package's, as detect_reflectional_symmetry() runs it):
// everything it makes, which irsym writes out
using Seed_run = IRS::internal::Detection_run_data;

const char* usage_text =
R"(irsym - partial intrinsic reflectional symmetry of a closed triangle mesh

usage: irsym MESH --out DIR [options]
       irsym --shape NAME --out DIR [options]

  MESH                 input mesh (OFF, OBJ, PLY or STL); it is never modified
  --shape NAME         use a generated shape instead of a file: sphere, ellipsoid,
                       capsule, torus, snowman, two_snowmen, bent_capsule, stick_figure,
                       stick_figure_missing_arm (the stick figure with its right arm cut
                       off and the cut capped, as in the package's repair protocol)
  --out DIR            output directory (created if missing)
  --samples N          number of samples (default: min(3000, vertices / 4), the paper's ratio)
  --seed S             random seed (default: 0); same seed, same result
  --tries N            where the symmetric map is suspect (results.map_suspect below), run
                       again from the samples on with seeds S+1, S+2, ..., at most N runs in
                       all, stopping at the first map that is not suspect; keep the one of
                       least isometric_distortion + 0.3 fixed_point_share (default: 5; 1 runs
                       seed S alone). When every run's map is suspect, one more run on the
                       samples of the map kept lets only the sample pairs vote that the
                       shape's global reflection swaps (global_reflection_map(), from the
                       Laplace spectrum); its map replaces the kept one if less defective, or
                       if it holds nothing in place with a distortion of at most 0.1 and
                       turns the surface over almost as much
                       (orientation_reversing_share() at most 0.1 lower)
                       (keeps_guided_run(); results.guided). That run's map is the global
                       reflection itself, over the whole shape (one region, of its first
                       curve; results.whole_shape_reflection), where that map turns the
                       surface over, as a reflection does and a rotation does not
                       (orientation_reversing_share() at least 0.5), and is less defective
                       than the map of the run's regions (takes_whole_shape_reflection()); the
                       reflection is first refined over the whole mesh by 150 Laplace functions
                       where that makes it less defective (refine_symmetric_map()), and the
                       first curve then follows that map's axis (reflection_axis()); a map
                       without an axis fixes no curve and is no reflection, and is not taken. Measured: no second run on
                       FAUST's 19 humans, 2.9 runs per mesh on SCAPE's 18 (seed 2, the
                       guided run counted; before it, 5 tries instead of 3 gave +0.8 to
                       +1.6 points of correspondence rate there, over three seeds)
  --geodesics G        geodesic oracle: heat (default), exact or dijkstra
  --threads T          worker threads (default: all cores); results do not depend on it
  --target-vertices N  first remesh or decimate to about N vertices (default: keep the mesh)
  --remesh             reach --target-vertices by isotropic remeshing (default: decimation
                       when reducing, remeshing when refining)
  --mend-input         first mend on a copy what repair_input() mends: pinched (non-manifold)
                       vertices, polygons, degenerate faces (collinear corners or near-zero
                       area) and isolated vertices (prepare_mesh's mend_input; SCAPE's meshes
                       have a pinched vertex); all outputs still refer to the input's
                       vertices and faces, report.json says what was mended ("mended") and
                       its "input" statistics are those of the mended copy. Without it such
                       a mesh is bad input; what the mending leaves still is
  --fill-holes         first fill every hole (boundary cycle) of the mesh with a refined and
                       faired patch (prepare_mesh's fill_holes, CGAL's hole filling); all
                       outputs still refer to the input's vertices and faces. Every boundary
                       is filled, unless --max-hole-length bounds them. Measured on FAUST and
                       SCAPE with 8 holes cut (symmetry_map_benchmark --holes 8 --fill-holes):
                       see the manual, "Filling the holes first"
  --max-hole-length L  with --fill-holes, fill only the boundary cycles at most L long (in the
                       mesh's units; the others stay open, report.json: holes_left_open),
                       for a surface with an opening by design besides its holes
  --max-similar-pairs-per-sample K  keep at most K times the number of samples of the
                       pairs that pass the similarity filter, drawn at random with --seed
                       (similar_sample_pairs' maximum_similar_pairs_per_sample; default 64,
                       'none' for the paper's filter without a cap). Where the SDF is
                       nearly uniform (cups, bearings, tables) 100-450 pairs per sample pass
                       and the voting, whose cost grows as their square, takes minutes
  --max-voting-pairs N at most N of the similar sample pairs vote for boundaries, drawn at
                       random with --seed (all of them still support); default: all. Where
                       many pairs pass the similarity filter even so, the voting can take
                       minutes; the tool then says so before voting
  --nested-symmetries  also extract the axes of smaller parts (limbs) below the paper's
                       selection (extract_irsa_curves' nested_symmetries): more curves,
                       regions and segments
  --repair             also rebuild a missing part from its mirror part (part repair) on
                       the mesh the pipeline ran on; not possible is reported, not an error
  --up AXIS            the mesh axis drawn upwards in the pictures: +X, -X, +Y, -Y, +Z
                       (default) or -Z
  --time-limit S       stop S seconds after the mesh is read (exit status 4), checked during
                       the geodesic matrix, the voting, the curves and the map (the library's
                       callback), and once the preparation and the SDF end; once a map is
                       complete, the segmentation, the repair and the outputs run to their
                       end. Reached during a second
                       or later --tries run, it keeps the best complete run and goes on (a
                       warning in report.json; results.tries marks the run "stopped")
  --help               this text

outputs in DIR:
  report.json          input statistics, parameters, time and peak memory per stage;
                       results.map_suspect when the map keeps more than 10 % of the
                       vertices far from the curves in place (fixed_point_share) or
                       changes the distances between landmarks by more than 0.04
                       sqrt(area) on average (isometric_distortion); results.tries: seed,
                       fixed_point_share and isometric_distortion of each run, and
                       results.seed_kept: the seed whose run all outputs come from;
                       results.guided: whether that run is the guided one (see --tries),
                       results.whole_shape_reflection: whether its map is the global one
  samples.txt          the samples, as input vertex ids (one per line)
  tau.txt              the IRSA transform, one value per input vertex (input order;
                       nan for an isolated vertex that --mend-input removed)
  transform.ply        input mesh coloured by the IRSA transform (vertex scalar 'transform')
  sdf.ply              input mesh coloured by the shape diameter function (SDF)
  geodesics.ply        input mesh coloured by the geodesic distance from the first sample
  curves.txt           the IRSA curves, best first, one per line: input vertex ids in
                       order (the pieces of a pruned curve one after the other)
  curves.polylines.txt the same curves in CGAL's polylines format (one line per piece:
                       number of points, then x y z of each; closed pieces repeat the first)
  regions.txt          the symmetric region (curve index) of each input face, -1 for none
  symmetric_map.txt    the mirror partner of each input vertex, -1 for none (and for
                       an isolated vertex that --mend-input removed)
  curves.ply           input mesh coloured by region, curves in black
  symmetric_map.ply    input mesh coloured so that mirror partners share a colour (the
                       geodesic distances from the two ends of the top curve, averaged
                       over each vertex and its partner, as the hue and the brightness;
                       the same for both where the map is an involution, and alike for
                       a part in any pose): a right map gives a mirror-symmetric picture;
                       vertices without a partner dark grey
  segmentation.txt     symmetry-aware segmentation: one segment id per input face
  segmentation.ply     input mesh, faces coloured by segment
  repaired.ply         with --repair, if the repair succeeded: the repaired mesh (closed,
                       2-manifold), grey, with the vertices it added in orange; the
                       "repair" object of report.json says what was found and added, or why
                       the repair was not possible (never a broken mesh)
  *.png                pictures of the PLY files, where f3d and xvfb-run are installed

exit status: 0 success, 1 usage error, 2 bad input (the message names the problem),
3 other error, 4 time limit reached
)";

struct Options
{
  std::string mesh_path, shape, out_dir, geodesics = "heat";
  std::optional<long long> samples;
  unsigned seed = 0;
  int tries = 5; // seeds tried while the map is suspect
  int threads = 0;
  long long target_vertices = 0, max_voting_pairs = 0; // 0: no cap
  double time_limit = 0.; // seconds, 0: none
  double max_hole_length = std::numeric_limits<double>::infinity(); // --fill-holes bound, infinity: none
  double max_similar_per_sample = IRS::default_maximum_similar_pairs_per_sample; // infinity: none
  bool remesh = false, repair = false, nested = false, fill_holes = false, mend_input = false;
  std::string up = "+Z";
};

struct Usage_error : std::runtime_error { using std::runtime_error::runtime_error; };

long long parse_integer(const std::string& option, const std::string& text, long long lo,
                        long long hi = std::numeric_limits<int>::max())
{
  std::size_t used = 0;
  long long v = 0;
  try { v = std::stoll(text, &used); } catch(...) { used = 0; }
  if(used != text.size() || text.empty())
    throw Usage_error(option + " expects an integer, got '" + text + "'");
  if(v < lo)
    throw Usage_error(option + " must be at least " + std::to_string(lo) + ", got " + text);
  if(v > hi)
    throw Usage_error(option + " must be at most " + std::to_string(hi) + ", got " + text);
  return v;
}

double parse_positive(const std::string& option, const std::string& text)
{
  std::size_t used = 0;
  double v = 0.;
  try { v = std::stod(text, &used); } catch(...) { used = 0; }
  if(used != text.size() || text.empty() || !(v > 0.) || !std::isfinite(v))
    throw Usage_error(option + " expects a positive number, got '" + text + "'");
  return v;
}

Options parse_options(int argc, char** argv)
{
  Options o;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if(i + 1 >= argc) throw Usage_error(a + " expects a value");
      return argv[++i];
    };
    if(a == "--help" || a == "-h") { std::cout << usage_text; std::exit(0); }
    else if(a == "--out") o.out_dir = value();
    else if(a == "--shape") o.shape = value();
    else if(a == "--samples") o.samples = parse_integer(a, value(), 1);
    else if(a == "--seed") o.seed = unsigned(parse_integer(a, value(), 0, std::numeric_limits<unsigned>::max()));
    else if(a == "--tries") o.tries = int(parse_integer(a, value(), 1, 100));
    else if(a == "--threads") o.threads = int(parse_integer(a, value(), 1));
    else if(a == "--target-vertices") o.target_vertices = parse_integer(a, value(), 4);
    else if(a == "--max-voting-pairs") o.max_voting_pairs = parse_integer(a, value(), 1);
    else if(a == "--max-similar-pairs-per-sample")
    {
      const std::string k = value();
      o.max_similar_per_sample = k == "none" ? std::numeric_limits<double>::infinity() : parse_positive(a, k);
    }
    else if(a == "--time-limit") o.time_limit = parse_positive(a, value());
    else if(a == "--remesh") o.remesh = true;
    else if(a == "--fill-holes") o.fill_holes = true;
    else if(a == "--mend-input") o.mend_input = true;
    else if(a == "--max-hole-length") o.max_hole_length = parse_positive(a, value());
    else if(a == "--repair") o.repair = true;
    else if(a == "--nested-symmetries") o.nested = true;
    else if(a == "--up") {
      o.up = value();
      if(o.up.size() != 2 || (o.up[0] != '+' && o.up[0] != '-') || o.up.find_first_of("XYZ", 1) != 1)
        throw Usage_error("--up expects +X, -X, +Y, -Y, +Z or -Z, got '" + o.up + "'");
    }
    else if(a == "--geodesics") {
      o.geodesics = value();
      if(o.geodesics != "heat" && o.geodesics != "exact" && o.geodesics != "dijkstra")
        throw Usage_error("--geodesics expects heat, exact or dijkstra, got '" + o.geodesics + "'");
    }
    else if(!a.empty() && a[0] == '-') throw Usage_error("unknown option " + a);
    else if(o.mesh_path.empty()) o.mesh_path = a;
    else throw Usage_error("more than one input mesh given: '" + o.mesh_path + "' and '" + a + "'");
  }
  if(o.out_dir.empty()) throw Usage_error("--out DIR is required");
  if(o.mesh_path.empty() == o.shape.empty()) throw Usage_error("give either MESH or --shape NAME");
  if(std::isfinite(o.max_hole_length) && !o.fill_holes)
    throw Usage_error("--max-hole-length bounds the holes --fill-holes fills: give --fill-holes too");
  return o;
}

IRS::Generated_shape<Mesh> generate(const std::string& name)
{
  if(name == "sphere") return IRS::generate_sphere<Mesh>();
  if(name == "ellipsoid") return IRS::generate_ellipsoid<Mesh>();
  if(name == "capsule") return IRS::generate_capsule<Mesh>();
  if(name == "torus") return IRS::generate_torus<Mesh>();
  if(name == "snowman") return IRS::generate_snowman<Mesh>();
  if(name == "two_snowmen") return IRS::generate_two_snowmen<Mesh>();
  if(name == "bent_capsule") return IRS::generate_bent_capsule<Mesh>();
  if(name == "stick_figure") return IRS::generate_stick_figure<Mesh>();
  if(name == "stick_figure_missing_arm") {
    // the damage step of run_part_repair_protocol() (and of test_repair): the
    // right arm (tip: largest x) cut 0.7 from its tip by a plane, the cut capped
    IRS::Generated_shape<Mesh> g = IRS::generate_stick_figure<Mesh>();
    namespace in = IRS::internal;
    const in::Repair_soup s = in::mesh_to_repair_soup(g.mesh, IRS::parameters::default_values());
    std::size_t tip = 0;
    for(std::size_t v = 1; v < s.points.size(); ++v)
      if(s.points[v].x() > s.points[tip].x()) tip = v;
    std::vector<char> removed(s.points.size(), 0);
    for(std::size_t v : in::limb_vertices(s, in::soup_neighbours(s), tip, 0.7, in::soup_mean_edge_length(s)))
      removed[v] = 1;
    IRS::Generated_shape<Mesh> damaged;
    in::cut_and_cap(s, removed, damaged.mesh); // no known symmetry any more: none listed
    return damaged;
  }
  throw Usage_error("unknown shape '" + name + "' (sphere, ellipsoid, capsule, torus, snowman, two_snowmen, "
                    "bent_capsule, stick_figure, stick_figure_missing_arm)");
}

/// The colour fields of the map's picture: the geodesic distances from the
/// two ends of the top curve (the curve vertex farthest from another, then
/// the one farthest from it). Points on a mirror axis are fixed by the
/// reflection, so these distances are the same at a point and at its mirror
/// image, and being intrinsic they colour a part alike in any pose. Empty
/// without a curve.
template <typename Oracle>
std::vector<std::vector<double>> axis_end_distances(const Oracle& oracle, const std::vector<IRS::Irsa_curve>& curves)
{
  std::vector<std::size_t> along;
  if(!curves.empty())
    for(const auto& pl : curves.front().polylines) along.insert(along.end(), pl.begin(), pl.end());
  if(along.empty()) return {};
  std::vector<float> d(oracle.number_of_vertices());
  const auto farthest_from = [&](std::size_t source) {
    oracle.distances_from(source, d.data());
    return *std::max_element(along.begin(), along.end(), [&](std::size_t u, std::size_t v) { return d[u] < d[v]; });
  };
  const std::size_t end = farthest_from(farthest_from(along.front()));
  std::vector<std::vector<double>> fields(1, std::vector<double>(d.begin(), d.end())); // from the first end
  oracle.distances_from(end, d.data());
  fields.emplace_back(d.begin(), d.end());
  return fields;
}

/// Writes curves, regions and the symmetric map in terms of the input mesh:
/// working vertices go to their nearest input vertex, input vertices and
/// faces take the partner / region of their working counterpart.
template <typename Prepared>
void write_symmetry_outputs(const Mesh& input, const Prepared& prepared, const std::vector<IRS::Irsa_curve>& curves,
                            const std::vector<long>& region, const std::vector<long>& partner,
                            const std::vector<std::vector<double>>& map_colour_fields, const fs::path& out,
                            const std::string& up, irsym::Json& files)
{
  std::vector<std::vector<std::vector<std::size_t>>> pieces; // curve -> piece -> input vertex ids
  for(const IRS::Irsa_curve& c : curves) {
    pieces.emplace_back();
    for(const auto& pl : c.polylines) {
      std::vector<std::size_t> ids;
      for(std::size_t w : pl) {
        const std::size_t i = prepared.working_to_input_vertex(w);
        if(ids.empty() || ids.back() != i) ids.push_back(i);
      }
      pieces.back().push_back(std::move(ids));
    }
  }
  {
    std::ofstream s(out / "curves.txt");
    for(const auto& c : pieces) {
      const char* sep = "";
      for(const auto& pl : c)
        for(std::size_t i : pl) { s << sep << i; sep = " "; }
      s << '\n';
    }
    std::ofstream p(out / "curves.polylines.txt");
    p << std::setprecision(17);
    for(std::size_t k = 0; k < pieces.size(); ++k)
      for(std::size_t j = 0; j < pieces[k].size(); ++j) {
        const auto& pl = pieces[k][j];
        const bool closed = curves[k].closed[j] && pl.size() > 2;
        p << pl.size() + (closed ? 1 : 0);
        for(std::size_t t = 0; t < pl.size() + (closed ? 1 : 0); ++t)
          p << ' ' << input.point(Mesh::Vertex_index(Mesh::size_type(pl[t % pl.size()])));
        p << '\n';
      }
  }
  const std::vector<long> region_in = IRS::transfer_face_labels_to_input(prepared, region);
  {
    std::ofstream s(out / "regions.txt");
    for(long r : region_in) s << r << '\n';
  }
  const std::vector<std::ptrdiff_t> partner_in = IRS::transfer_vertex_map_to_input(prepared, partner);
  {
    std::ofstream m(out / "symmetric_map.txt");
    for(std::ptrdiff_t p : partner_in) m << p << '\n';
  }
  for(const char* f : {"curves.txt", "curves.polylines.txt", "regions.txt", "symmetric_map.txt"})
    files.push(irsym::Json::object().add("file", f));
  irsym::write_picture(out, "symmetric_map", [&](const std::string& ply) {
    std::vector<std::vector<double>> fields;
    for(const std::vector<double>& f : map_colour_fields) fields.push_back(IRS::transfer_vertex_field_to_input(prepared, f));
    if(fields.empty()) fields = irsym::coordinate_fields(input);
    return irsym::write_coloured_ply(input, irsym::partner_colours(partner_in, fields), ply);
  }, files, up);

  // picture: vertices take the region of an incident face; the curves and
  // their one-ring in black, so that they show at any resolution
  std::vector<CGAL::IO::Color> colour(num_vertices(input), irsym::label_colour(-1));
  for(auto f : faces(input))
    if(region_in[f.idx()] >= 0)
      for(auto v : CGAL::vertices_around_face(halfedge(f, input), input))
        colour[v.idx()] = irsym::label_colour(region_in[f.idx()]);
  for(const auto& c : pieces)
    for(const auto& pl : c)
      for(std::size_t i : pl) {
        const Mesh::Vertex_index v{Mesh::size_type(i)};
        colour[i] = CGAL::IO::Color(0, 0, 0);
        for(auto u : CGAL::vertices_around_target(halfedge(v, input), input)) colour[u.idx()] = CGAL::IO::Color(0, 0, 0);
      }
  irsym::write_picture(out, "curves", [&](const std::string& ply) {
    return irsym::write_coloured_ply(input, colour, ply);
  }, files, up);
}

/// Part repair (--repair) on the working mesh with the pipeline's distance
/// matrix and curves; writes repaired.ply/png when the result passes the
/// checks and returns the report's "repair" object. A repair that is not
/// possible (Input_error) is reported, not thrown: the tool still succeeds.
irsym::Json repair_outputs(const Mesh& work, const IRS::Geodesic_distance_matrix& D,
                           const IRS::Irsa_voting_result& voting, const std::vector<double>& tau,
                           const std::vector<IRS::Irsa_curve>& curves, const fs::path& out, const std::string& up, irsym::Json& files)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  irsym::Json j = irsym::Json::object();
  j.add("on", "working mesh").add("curves_available", curves.size());
  Mesh repaired;
  IRS::Part_repair_report r;
  try {
    // from the transform: its first round tries the curves above (extracted
    // with the same defaults), each with its own map (not the CLI's map: the
    // repair's is not locally refined, see part_repair.h); the later rounds
    // extract again without the ones that detect nothing (a damaged body's
    // left-right curve can rank behind its front-back one)
    r = IRS::repair_missing_parts(work, D, voting,
                                  boost::make_iterator_property_map(tau.begin(), get(boost::vertex_index, work)),
                                  repaired);
  }
  catch(const IRS::Input_error& e) {
    return j.add("possible", false).add("missing_part_found", false).add("error", std::string(e.what()));
  }

  // checks of the result, before anything is written
  const bool valid = CGAL::is_valid_polygon_mesh(repaired) && CGAL::is_triangle_mesh(repaired);
  const bool closed = valid && CGAL::is_closed(repaired);
  bool manifold = valid;
  for(auto v : vertices(repaired))
    if(manifold && PMP::is_non_manifold_vertex(v, repaired)) manifold = false;
  const bool self_intersecting = !valid || PMP::does_self_intersect(repaired);
  // a mesh that already self-intersects (e.g. a scan) keeps its intersections: only new ones are a defect
  const bool input_self_intersecting = self_intersecting && PMP::does_self_intersect(work);
  std::set<K::Point_3> old_points(work.points().begin(), work.points().end());
  std::vector<CGAL::IO::Color> colour(num_vertices(repaired), irsym::label_colour(-1));
  std::size_t new_vertices = 0;
  for(auto v : vertices(repaired))
    if(old_points.count(repaired.point(v)) == 0) { colour[v.idx()] = irsym::label_colour(1); ++new_vertices; }

  j.add("possible", true).add("missing_part_found", r.number_of_parts > 0)
   .add("parts_added", r.number_of_parts)
   .add("vertices_added", (long long)(num_vertices(repaired)) - (long long)(num_vertices(work)))
   .add("faces_added", (long long)(num_faces(repaired)) - (long long)(num_faces(work)))
   .add("new_vertices", new_vertices)
   .add("vertices", std::size_t(num_vertices(repaired))).add("faces", std::size_t(num_faces(repaired)))
   .add("valid", valid).add("closed", closed).add("manifold", manifold)
   .add("self_intersecting", self_intersecting).add("input_self_intersecting", input_self_intersecting);
  if(r.number_of_parts > 0) {
    irsym::Json parts = irsym::Json::array();
    for(std::size_t k = 0; k < r.number_of_parts; ++k)
      parts.push(irsym::Json::object().add("mirror_part_vertices", r.part_sizes[k]).add("icp_rms", r.icp_rms[k]));
    irsym::Json plane = irsym::Json::array();
    for(double c : r.mirror_plane) plane.push(c);
    j.add("curve", r.curve).add("mirror_plane", plane).add("parts", parts).add("seams_faired", r.seams_faired);
  }
  if(!(valid && closed && manifold && (!self_intersecting || input_self_intersecting))) {
    j.add("error", "the repaired mesh failed the checks; repaired.ply not written");
    return j;
  }
  irsym::write_picture(out, "repaired", [&](const std::string& ply) {
    return irsym::write_coloured_ply(repaired, colour, ply);
  }, files, up);
  return j;
}

// what prepare_mesh() did, for report.json
template <typename GeomTraits>
std::string preparation_words(const IRS::Prepared_mesh<GeomTraits>& prepared)
{
  std::string words = prepared.input_repairs().any() ? "mended" : "";
  if(prepared.number_of_filled_holes() > 0) words += std::string(words.empty() ? "" : ", ") + "holes filled";
  if(prepared.preparation() != IRS::Mesh_preparation::none)
    words += std::string(words.empty() ? "" : ", ") +
             (prepared.preparation() == IRS::Mesh_preparation::decimation ? "decimated" : "remeshed");
  return words.empty() ? "none" : words;
}

// what --mend-input mended (repair_input()), for report.json
irsym::Json mended_json(const IRS::Input_repairs& r)
{
  irsym::Json j = irsym::Json::object();
  j.add("duplicated_non_manifold_vertices", r.duplicated_non_manifold_vertices)
   .add("triangulated_faces", r.triangulated_faces)
   .add("removed_degenerate_faces", r.removed_degenerate_faces)
   .add("removed_isolated_vertices", r.removed_isolated_vertices);
  return j;
}

// the stages that depend on the seed: samples, geodesic matrix, signatures,
// voting, curves, regions and map (internal::detection_run(), the package's
// run of detect_reflectional_symmetry()), each logged and timed; stage names
// carry the seed after the first try
template <typename Oracle>
Seed_run run_seed(const Options& opt, const Mesh& work, const Oracle& oracle, const std::vector<double>& vertex_sdf,
                  const std::vector<double>& areas, unsigned seed, const std::function<bool(double)>& within_limit,
                  irsym::Stage_log& log, const Seed_run* guided_by = nullptr,
                  const std::vector<long>* global_map = nullptr)
{
  const std::string suffix = guided_by != nullptr ? " (seed " + std::to_string(seed) + ", guided)"
                             : seed == opt.seed   ? ""
                                                  : " (seed " + std::to_string(seed) + ")";
  using Stage = IRS::internal::Detection_stage;
  const auto observe = [&](Stage stage, bool begins, const Seed_run& r) {
    if(!begins) { log.stop(); return; }
    switch(stage) {
      case Stage::sampling: log.start("sampling" + suffix); break;
      case Stage::geodesic_matrix: log.start("geodesic matrix" + suffix); break;
      case Stage::signatures: log.start("signatures" + suffix); break;
      case Stage::voting:
      {
        log.start("IRSA transform (voting)" + suffix);
        // the voting's cost grows with its pairs times the similar pairs: a hint
        // where that many is unusual (PSB's table 156 at 1,000 samples: 159,402
        // similar pairs without the cap, 22 s on two cores; typical meshes: a few
        // thousand to 60,000)
        const std::size_t many_similar_pairs = 100000;
        if(opt.max_voting_pairs == 0 && r.similar_pairs > many_similar_pairs)
          std::cerr << "[irsym] " << r.similar_pairs << " of " << r.samples.size() * (r.samples.size() - 1) / 2
                    << " sample pairs are kept by the similarity filter (a nearly uniform SDF): the voting may take "
                       "minutes; --max-similar-pairs-per-sample K keeps fewer of them, --max-voting-pairs N lets only "
                       "N vote\n";
        break;
      }
      case Stage::curves: log.start("IRSA curves" + suffix); break;
      case Stage::regions_and_map: log.start("symmetric regions and map" + suffix); break;
    }
  };
  const std::size_t cap = opt.max_voting_pairs > 0 ? std::size_t(opt.max_voting_pairs)
                                                   : std::numeric_limits<std::size_t>::max(); // the default: no cap
  const auto np = IRS::parameters::callback(within_limit)
                    .maximum_similar_pairs_per_sample(opt.max_similar_per_sample)
                    .maximum_number_of_voting_pairs(cap)
                    .nested_symmetries(opt.nested);
  // without --samples, the package's default number
  return opt.samples
    ? IRS::internal::detection_run<CGAL::Parallel_if_available_tag>(
        work, oracle, vertex_sdf, areas, seed, np.number_of_samples(std::size_t(*opt.samples)), guided_by,
        global_map, observe)
    : IRS::internal::detection_run<CGAL::Parallel_if_available_tag>(work, oracle, vertex_sdf, areas, seed, np,
                                                                    guided_by, global_map, observe);
}

template <typename Oracle>
int run_pipeline(const Options& opt, const Mesh& input, irsym::Stage_log& log, irsym::Json& report)
{
  // --time-limit: the long stages ask this callback whether to go on
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(opt.time_limit);
  const bool limited = opt.time_limit > 0.;
  const std::function<bool(double)> within_limit = [deadline, limited](double) {
    return !limited || std::chrono::steady_clock::now() < deadline;
  };
  // the stages without a callback (CGAL's remeshing and SDF) are checked once they end
  auto stop_if_late = [&within_limit](const std::string& stage) {
    if(!within_limit(1.)) throw IRS::Operation_cancelled("the " + stage + " ended after it");
  };
  const fs::path out(opt.out_dir);
  log.start("prepare");
  // without --remesh, prepare_mesh() decimates to a lower target and remeshes to a higher one
  const auto fill = IRS::parameters::fill_holes(opt.fill_holes).maximum_hole_boundary_length(opt.max_hole_length)
                      .mend_input(opt.mend_input);
  const auto prepared = opt.target_vertices <= 0 ? IRS::prepare_mesh(input, fill)
    : opt.remesh ? IRS::prepare_mesh(input, fill.target_number_of_vertices(std::size_t(opt.target_vertices))
                                              .isotropic_remeshing(true))
                 : IRS::prepare_mesh(input, fill.target_number_of_vertices(std::size_t(opt.target_vertices)));
  const Mesh& work = prepared.working_mesh();
  log.stop();
  // prepare_mesh() checks the input (with --mend-input its mended copy, as the
  // input fails the check) and keeps the statistics for report.json
  const IRS::Input_report& stats = prepared.input_report();
  {
    irsym::Json in = irsym::Json::object();
    in.add("vertices", stats.number_of_vertices).add("faces", stats.number_of_faces)
      .add("edges", stats.number_of_edges)
      .add("connected_components", stats.number_of_connected_components)
      .add("boundary_cycles", stats.number_of_boundary_cycles)
      .add("longest_boundary_cycle_length", stats.longest_boundary_cycle_length)
      .add("bounding_box_diagonal", stats.bounding_box_diagonal)
      .add("mean_edge_length", stats.mean_edge_length).add("area", stats.area);
    report.add("input", in);
  }
  // Small holes are tolerated (paper, Fig. 11), large missing parts are not:
  // geodesics then run around the hole. A round hole whose rim is as long as
  // sqrt(area) covers about 8 % of the surface.
  irsym::Json warnings = irsym::Json::array();
  if(stats.longest_boundary_cycle_length > std::sqrt(stats.area)) {
    std::ostringstream os;
    os << "the mesh has a boundary (hole or open border) of length " << stats.longest_boundary_cycle_length
       << ", more than the square root of its area (" << std::sqrt(stats.area) << "): the method expects a closed mesh with small holes, "
       << (opt.fill_holes && stats.longest_boundary_cycle_length <= opt.max_hole_length
             ? "and --fill-holes covers a large missing part with an invented patch that the symmetry takes for surface "
               "(--max-hole-length keeps the longer boundaries open)"
             : "and large missing parts distort the geodesics");
    std::cerr << "irsym: warning: " << os.str() << '\n';
    warnings.push(os.str());
  }

  stop_if_late("preparation");

  log.start("geodesic oracle (" + opt.geodesics + ")");
  const Oracle oracle(work);
  log.stop();
  stop_if_late("geodesic oracle's set-up");

  // the SDF does not depend on the samples: once for all tries
  log.start("vertex SDF");
  const std::vector<double> vertex_sdf = IRS::vertex_sdf_values(work);
  const std::vector<double> areas = IRS::vertex_areas(work);
  log.stop();
  stop_if_late("vertex SDF");

  // --tries: another seed while the map is suspect (it holds parts far from
  // the curves in place, or does not preserve distances) until a map is not
  // suspect; the map of least defect of those runs is kept
  // (internal::best_of_tries(): the package's retry rule). A time limit
  // reached during a later try keeps the best earlier run, with a warning.
  irsym::Json tries = irsym::Json::array();
  bool guided_started = false;
  auto outcome = IRS::internal::best_of_tries<Seed_run>(
    [&](unsigned seed) {
      Seed_run run = run_seed(opt, work, oracle, vertex_sdf, areas, seed, within_limit, log);
      tries.push(irsym::Json::object().add("seed", run.seed).add("curves", run.curves.size())
                   .add("fixed_point_share", run.fixed_share).add("isometric_distortion", run.distortion)
                   .add("orientation_reversing_share", run.reversing_share));
      if(run.suspect() && seed + 1u < opt.seed + unsigned(opt.tries))
        std::cerr << "[irsym] the symmetric map of seed " << seed << " is suspect (" << 100. * run.fixed_share
                  << " % of the vertices far from the curves kept in place, isometric distortion " << run.distortion
                  << "): trying seed " << seed + 1u << '\n';
      return run;
    },
    opt.seed, opt.tries,
    // every try suspect: the global reflection (from the spectrum) picks the
    // pairs of the kept run's samples that vote again
    [&](const Seed_run& suspect_run, Seed_run& guided) {
      guided_started = true;
      log.start("global reflection");
      std::vector<long> global_map(num_vertices(work), -1);
      const bool found = IRS::global_reflection_map(
        work, suspect_run.samples, boost::make_iterator_property_map(global_map.begin(), get(boost::vertex_index, work)));
      log.stop();
      if(!found) {
        std::cerr << "[irsym] every try's map is suspect, and no global reflection was found\n";
        tries.push(irsym::Json::object().add("seed", suspect_run.seed).add("guided", true).add("found", false));
        return false;
      }
      std::cerr << "[irsym] every try's map is suspect: voting again on the samples of seed " << suspect_run.seed
                << " with the pairs that the global reflection swaps\n";
      guided = run_seed(opt, work, oracle, vertex_sdf, areas, suspect_run.seed, within_limit, log, &suspect_run,
                        &global_map);
      tries.push(irsym::Json::object().add("seed", guided.seed).add("guided", true)
                   .add("whole_shape_reflection", guided.whole_shape_reflection)
                   .add("global_reflection_reversing_share", guided.global_reversing_share)
                   .add("global_reflection_refined", guided.global_refined)
                   .add("curves", guided.curves.size())
                   .add("fixed_point_share", guided.fixed_share).add("isometric_distortion", guided.distortion)
                   .add("orientation_reversing_share", guided.reversing_share));
      return true;
    });
  if(outcome.stopped) {
    log.abandon();
    const unsigned stopped_seed = opt.seed + unsigned(outcome.runs);
    std::ostringstream os;
    os << "the time limit of " << opt.time_limit << " s was reached during the "
       << (guided_started ? "guided run" : "run of seed " + std::to_string(stopped_seed)) << " ("
       << outcome.stop_message << "); the outputs come from seed "
       << outcome.kept.seed << ", the best of the " << outcome.runs << " complete run(s)";
    std::cerr << "irsym: warning: " << os.str() << '\n';
    warnings.push(os.str());
    tries.push(irsym::Json::object().add("seed", guided_started ? outcome.kept.seed : stopped_seed)
                 .add("guided", guided_started).add("stopped", true));
  }
  Seed_run kept = std::move(outcome.kept);
  report.add("warnings", warnings);
  const bool map_suspect = kept.suspect();
  if(map_suspect)
    std::cerr << "irsym: warning: the symmetric map keeps " << 100. * kept.fixed_share
              << " % of the vertices far from the curves in place and changes the distances between landmarks by "
              << kept.distortion << " sqrt(area) on average, where a reflection moves every point off its axis "
                 "and preserves distances: parts of the map are likely wrong (a limb mapped onto itself or by "
                 "another symmetry); more --tries or another --seed may do better\n";
  const std::vector<std::size_t>& samples = kept.samples;
  const IRS::Geodesic_distance_matrix& D = kept.D;
  const IRS::Irsa_voting_result& voting = kept.voting;
  const std::vector<double>& tau = kept.tau;
  const std::vector<IRS::Irsa_curve>& curves = kept.curves;
  const std::vector<long>& region = kept.region;
  const std::vector<long>& partner = kept.partner;

  log.start("segmentation");
  std::vector<long> segment(num_faces(work), -1);
  const std::size_t segments = IRS::symmetry_aware_segmentation(
    work, D, curves, boost::make_iterator_property_map(segment.begin(), get(boost::face_index, work)));
  log.stop();

  // ---- outputs, on the input mesh ----
  {
    std::ofstream s(out / "samples.txt");
    for(std::size_t v : samples) s << prepared.working_to_input_vertex(v) << '\n';
  }
  const std::vector<double> sdf_in = IRS::transfer_vertex_field_to_input(prepared, vertex_sdf);
  std::vector<double> first_row(D.row(0), D.row(0) + D.number_of_vertices());
  const std::vector<double> geo_in = IRS::transfer_vertex_field_to_input(prepared, first_row);
  irsym::Json files = irsym::Json::array();
  auto emit = [&](const std::vector<double>& field, const std::string& name) {
    irsym::write_picture(out, name, [&](const std::string& ply) {
      return irsym::write_scalar_ply(input, field, name, ply);
    }, files, opt.up);
  };
  const std::vector<double> tau_in = IRS::transfer_vertex_field_to_input(prepared, tau);
  {
    std::ofstream t(out / "tau.txt");
    t << std::setprecision(9);
    for(double x : tau_in) t << x << '\n';
  }
  write_symmetry_outputs(input, prepared, curves, region, partner, axis_end_distances(oracle, curves), out, opt.up,
                         files);
  {
    const std::vector<long> segment_in = IRS::transfer_face_labels_to_input(prepared, segment);
    std::ofstream t(out / "segmentation.txt");
    std::vector<CGAL::IO::Color> colour(segment_in.size());
    for(std::size_t f = 0; f < segment_in.size(); ++f) {
      t << segment_in[f] << '\n';
      colour[f] = irsym::label_colour(segment_in[f]);
    }
    files.push(irsym::Json::object().add("file", "segmentation.txt"));
    irsym::write_picture(out, "segmentation", [&](const std::string& ply) {
      return irsym::write_face_coloured_ply(input, colour, ply);
    }, files, opt.up, true);
  }
  std::optional<irsym::Json> repair;
  if(opt.repair) {
    log.start("part repair");
    repair = repair_outputs(work, D, voting, tau, curves, out, opt.up, files);
    log.stop();
  }
  emit(tau_in, "transform");
  emit(sdf_in, "sdf");
  emit(geo_in, "geodesics");

  irsym::Json res = irsym::Json::object();
  res.add("working_vertices", std::size_t(num_vertices(work)))
     .add("working_faces", std::size_t(num_faces(work)))
     .add("preparation", preparation_words(prepared))
     .add("mended", mended_json(prepared.input_repairs()))
     .add("filled_holes", prepared.number_of_filled_holes())
     .add("holes_left_open", prepared.number_of_holes_left_open())
     .add("samples", samples.size())
     .add("largest_geodesic_distance", D.largest_finite_distance())
     .add("sample_pairs", samples.size() * (samples.size() - 1) / 2)
     .add("similar_sample_pairs", kept.similar_pairs)
     .add("voting_pairs", voting.number_of_voting_pairs)
     .add("voting_pairs_with_support", voting.voting_pairs.size())
     .add("gaussian_width_sigma", voting.sigma)
     .add("distance_tolerance_floor", voting.distance_tolerance_floor)
     .add("locality_radius", voting.locality_radius)
     .add("largest_tau", *std::max_element(tau.begin(), tau.end()))
     .add("curves", curves.size())
     .add("faces_in_regions", kept.region_faces)
     .add("vertices_with_partner", kept.mapped_vertices)
     .add("fixed_point_share", kept.fixed_share)
     .add("isometric_distortion", kept.distortion)
     .add("orientation_reversing_share", kept.reversing_share)
     .add("map_suspect", map_suspect)
     .add("seed_kept", kept.seed)
     .add("guided", kept.guided)
     .add("whole_shape_reflection", kept.whole_shape_reflection)
     .add("tries", tries)
     .add("segments", segments);
  irsym::Json curve_list = irsym::Json::array();
  for(const IRS::Irsa_curve& c : curves)
    curve_list.push(irsym::Json::object().add("vertices", c.vertices().size()).add("pieces", c.polylines.size())
                      .add("nu", c.nu).add("largest_support", c.maximum_support())
                      .add("refinement_iterations", c.number_of_iterations).add("converged", c.converged)
                      .add("nested", c.nested));
  res.add("curve_details", curve_list);
  report.add("results", res);
  if(repair) report.add("repair", *repair);
  report.add("outputs", files);
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  Options opt;
  try { opt = parse_options(argc, argv); }
  catch(const Usage_error& e) {
    std::cerr << "irsym: " << e.what() << "\n(irsym --help lists the options)\n";
    return 1;
  }

  const int threads = opt.threads > 0 ? opt.threads : int((std::max)(1u, std::thread::hardware_concurrency()));
#ifdef CGAL_LINKED_WITH_TBB
  tbb::global_control thread_limit(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
#endif

  irsym::Stage_log log;
  irsym::Json report = irsym::Json::object();
  try {
    fs::create_directories(opt.out_dir);
    Mesh input;
    log.start("input");
    if(!opt.shape.empty()) {
      input = generate(opt.shape).mesh;
      opt.mesh_path = (fs::path(opt.out_dir) / (opt.shape + ".off")).string();
      CGAL::IO::write_polygon_mesh(opt.mesh_path, input, CGAL::parameters::stream_precision(17));
    }
    else
      IRS::read_mesh(opt.mesh_path, input);
    log.stop();

    irsym::Json params = irsym::Json::object();
    params.add("mesh", opt.mesh_path).add("shape", opt.shape)
          .add("samples", opt.samples ? double(*opt.samples) : std::numeric_limits<double>::quiet_NaN())
          .add("seed", opt.seed).add("tries", opt.tries).add("geodesics", opt.geodesics).add("threads", threads)
          .add("target_vertices", opt.target_vertices).add("remesh", opt.remesh).add("fill_holes", opt.fill_holes)
          .add("mend_input", opt.mend_input)
          .add("max_hole_length", opt.max_hole_length).add("up", opt.up)
          .add("repair", opt.repair).add("nested_symmetries", opt.nested).add("time_limit", opt.time_limit)
          .add("max_similar_pairs_per_sample", opt.max_similar_per_sample) // null: none
          .add("max_voting_pairs", opt.max_voting_pairs > 0 ? double(opt.max_voting_pairs)
                                                            : std::numeric_limits<double>::quiet_NaN());
    report.add("parameters", params);

    int rc = 0;
    if(opt.geodesics == "heat")
      rc = run_pipeline<IRS::Heat_method_geodesic_oracle<Mesh>>(opt, input, log, report);
    else if(opt.geodesics == "exact")
      rc = run_pipeline<IRS::Exact_geodesic_oracle<Mesh>>(opt, input, log, report);
    else
      rc = run_pipeline<IRS::Dijkstra_geodesic_oracle<Mesh>>(opt, input, log, report);

    report.add("stages", log.to_json());
    report.add("total_seconds", log.total_seconds());
    report.add("peak_memory_mib", irsym::peak_memory_mib());
    const fs::path json = fs::path(opt.out_dir) / "report.json";
    std::ofstream(json) << report.str() << '\n';
    std::cerr << "[irsym] done in " << log.total_seconds() << " s; outputs in " << opt.out_dir << "\n";
    return rc;
  }
  catch(const IRS::Input_error& e) {
    // say where --mend-input would help: the defects repair_input() mends
    const bool mendable = !opt.mend_input && (e.problem() == IRS::Input_problem::non_manifold_vertex ||
                                              e.problem() == IRS::Input_problem::not_triangle_mesh ||
                                              e.problem() == IRS::Input_problem::isolated_vertex ||
                                              e.problem() == IRS::Input_problem::degenerate_face);
    std::cerr << "irsym: bad input: " << e.what()
              << (mendable ? " (--mend-input tries to mend it, on a copy)" : "") << '\n';
    return 2;
  }
  catch(const IRS::Operation_cancelled& e) {
    std::cerr << "irsym: stopped, the time limit of " << opt.time_limit << " s was reached (" << e.what() << ")\n";
    return 4;
  }
  catch(const Usage_error& e) {
    std::cerr << "irsym: " << e.what() << "\n(irsym --help lists the options)\n";
    return 1;
  }
  catch(const std::exception& e) {
    std::cerr << "irsym: error: " << e.what() << '\n';
    return 3;
  }
}
