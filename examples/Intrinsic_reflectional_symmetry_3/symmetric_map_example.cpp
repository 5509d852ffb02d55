// The whole pipeline on one mesh in one call, detect_reflectional_symmetry():
// samples, geodesics, signatures, IRSA transform, IRSA curves, symmetric
// regions and the symmetric vertex map, run again with the next seed while the
// map is suspect (it holds parts far from the curves in place, or does not
// preserve distances), as irsym does. Prints the curves, for a few vertices
// their mirror partners, and what each run found. A mesh with holes or
// mendable defects (pinched vertices, polygons, degenerate faces) is first
// filled and mended on a copy, and the map brought back to its vertices.
// Each stage is also a free function of its own (see the manual's pipeline).
//
// usage: symmetric_map_example [mesh.off [number_of_samples]]
//        (default: a generated bent capsule, whose end-to-end symmetry is intrinsic only)

#include <CGAL/Intrinsic_reflectional_symmetry_3/check_input.h> // read_mesh()
#include <CGAL/Intrinsic_reflectional_symmetry_3/prepare_mesh.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/shape_generators.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/symmetry_detection.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cstddef>
#include <cstdlib>
#include <iostream>
#include <vector>

namespace IRS = CGAL::Intrinsic_reflectional_symmetry_3;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Vertex_index vertex_descriptor;
typedef Mesh::Face_index face_descriptor;

int run(int argc, char** argv)
{
  Mesh input;
  if(argc > 1) IRS::read_mesh(argv[1], input); // throws Input_error naming the problem
  else input = IRS::generate_bent_capsule<Mesh>(2000).mesh;
  // 0. holes would bend the geodesics around them: the pipeline runs on a copy
  // whose holes are filled (CGAL's refined and faired hole filling) and whose
  // defects are mended (repair_input()); the maps lead back to the input's
  // vertices. A valid closed mesh is copied as it is. What cannot be mended
  // throws Input_error, naming the problem.
  const auto prepared = IRS::prepare_mesh(input, IRS::parameters::fill_holes(true).mend_input(true));
  Mesh mesh = prepared.working_mesh();
  const std::size_t n = argc > 2 ? std::size_t(std::atoi(argv[2])) : (num_vertices(mesh) + 3) / 4;

  // 1. the pipeline, into property maps: the mirror partner of each vertex,
  // the IRSA transform and each face's symmetric region
  auto partner = mesh.add_property_map<vertex_descriptor, long>("v:partner", -1).first;
  auto tau = mesh.add_property_map<vertex_descriptor, double>("v:tau", 0.).first;
  auto region = mesh.add_property_map<face_descriptor, int>("f:region", -1).first;
  const IRS::Reflectional_symmetry symmetry = IRS::detect_reflectional_symmetry(
    mesh, partner,
    IRS::parameters::number_of_samples(n).random_seed(0u).irsa_transform_map(tau).face_region_map(region));

  // 2. what it found
  const IRS::Symmetry_detection_run& kept = symmetry.kept();
  std::cout << num_vertices(mesh) << " vertices, " << symmetry.samples.size() << " samples, " << kept.similar_pairs
            << " similar pairs, " << symmetry.curves.size() << " IRSA curve(s)" << std::endl;
  for(std::size_t c = 0; c < symmetry.curves.size(); ++c)
    std::cout << "  curve " << c << ": " << symmetry.curves[c].vertices().size() << " vertices in "
              << symmetry.curves[c].polylines.size() << " piece(s), nu = " << symmetry.curves[c].nu << std::endl;
  std::cout << kept.region_faces << " of " << num_faces(mesh) << " faces in a symmetric region, "
            << kept.mapped_vertices << " vertices with a mirror partner" << std::endl;
  for(std::size_t i = 0; i < 5 && i < symmetry.samples.size(); ++i) {
    const vertex_descriptor v(Mesh::size_type(symmetry.samples[i]));
    std::cout << "  vertex " << std::size_t(v) << " <-> " << get(partner, v) << ", tau " << get(tau, v) << std::endl;
  }

  // 3. checks that need no ground truth: a reflection fixes its axis alone
  // and preserves distances, so a map that holds parts far from the curves in
  // place (a limb onto itself) or sends a part by another symmetry is
  // suspect, and the next seed runs
  for(const IRS::Symmetry_detection_run& run : symmetry.runs)
    std::cout << "  run of seed " << run.seed << (run.guided ? " (guided by the global reflection)" : "") << ": "
              << 100. * run.fixed_share << " % of the vertices far from the curves (nearly) their own partner, "
              << "distances between landmarks changed by " << run.distortion << " sqrt(area) on average, "
              << run.seconds << " s" << (run.suspect() ? ", suspect" : "") << std::endl;
  if(kept.suspect()) std::cout << "the map kept is suspect: another random_seed may do better" << std::endl;

  // 4. the map on the input's vertices (the same map when nothing was filled or mended)
  const IRS::Input_repairs& mended = prepared.input_repairs();
  if(mended.any())
    std::cout << "mended first: " << mended.duplicated_non_manifold_vertices
              << " new vertex(es) splitting pinched vertices, " << mended.triangulated_faces
              << " polygon(s) triangulated, " << mended.removed_degenerate_faces << " degenerate face(s) and "
              << mended.removed_isolated_vertices << " isolated vertex(es) removed" << std::endl;
  std::vector<long> working_partners(num_vertices(mesh));
  for(vertex_descriptor v : vertices(mesh)) working_partners[std::size_t(v)] = get(partner, v);
  const std::vector<std::ptrdiff_t> input_partners = IRS::transfer_vertex_map_to_input(prepared, working_partners);
  std::cout << prepared.number_of_filled_holes() << " hole(s) filled first; "
            << std::count_if(input_partners.begin(), input_partners.end(), [](std::ptrdiff_t p) { return p >= 0; })
            << " of the " << num_vertices(input) << " input vertices with a mirror partner" << std::endl;
  return EXIT_SUCCESS;
}

int main(int argc, char** argv)
{
  try {
    return run(argc, argv);
  } catch(const IRS::Input_error& e) {
    std::cerr << "bad input: " << e.what() << std::endl;
    return EXIT_FAILURE;
  }
}
