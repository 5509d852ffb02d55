// The whole pipeline on one mesh: samples, geodesics, signatures, IRSA
// transform, IRSA curves, symmetric regions and the symmetric vertex map.
// Prints the curves, for a few vertices their mirror partners, and the share
// of the vertices that the map holds in place far from the curves. A mesh with
// holes or mendable defects (pinched vertices, polygons, degenerate faces) is
// first filled and mended on a copy, and the map brought back to its vertices.
//
// usage: symmetric_map_example [mesh.off [number_of_samples]]
//        (default: a generated bent capsule, whose end-to-end symmetry is intrinsic only)

#include <CGAL/Intrinsic_reflectional_symmetry_3/Heat_method_geodesic_oracle.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/check_input.h> // read_mesh()
#include <CGAL/Intrinsic_reflectional_symmetry_3/geodesic_distances.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/irsa_curves.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/irsa_transform.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/prepare_mesh.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/sampling.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/shape_generators.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/signatures.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/symmetric_map.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cstddef>
#include <cstdlib>
#include <iostream>
#include <iterator>
#include <utility>
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

  // 1. samples and the sample-to-vertex geodesic distance matrix
  const std::vector<std::size_t> samples =
    IRS::farthest_point_samples(mesh, IRS::parameters::number_of_samples(n).random_seed(0u));
  const IRS::Heat_method_geodesic_oracle<Mesh> oracle(mesh);
  const IRS::Geodesic_distance_matrix D = IRS::compute_geodesic_distance_matrix(oracle, samples);

  // 2. the similarity filter on SDF map signatures
  const IRS::Sdf_signatures signatures = IRS::compute_sdf_signatures(mesh, D);
  std::vector<std::pair<std::size_t, std::size_t>> similar;
  IRS::similar_sample_pairs(signatures, std::back_inserter(similar));

  // 3. the IRSA transform, into a vertex property map
  auto tau = mesh.add_property_map<vertex_descriptor, double>("v:tau", 0.).first;
  const IRS::Irsa_voting_result voting = IRS::compute_irsa_transform(mesh, D, similar, tau);

  // 4. the curves, their regions and the mirror map
  std::vector<IRS::Irsa_curve> curves;
  IRS::extract_irsa_curves(mesh, D, voting, tau, std::back_inserter(curves));
  auto region = mesh.add_property_map<face_descriptor, int>("f:region", -1).first;
  auto partner = mesh.add_property_map<vertex_descriptor, long>("v:partner", -1).first;
  const std::size_t in_regions = IRS::symmetric_regions(mesh, D, curves, region);
  // map_region: which curve's reflection gives each vertex its partner
  auto map_region = mesh.add_property_map<vertex_descriptor, int>("v:map_region", -1).first;
  const std::size_t mapped =
    IRS::symmetric_vertex_map(mesh, D, curves, partner, IRS::parameters::vertex_region_map(map_region));

  std::cout << num_vertices(mesh) << " vertices, " << samples.size() << " samples, " << similar.size()
            << " similar pairs, " << curves.size() << " IRSA curve(s)" << std::endl;
  for(std::size_t c = 0; c < curves.size(); ++c)
    std::cout << "  curve " << c << ": " << curves[c].vertices().size() << " vertices in "
              << curves[c].polylines.size() << " piece(s), nu = " << curves[c].nu << std::endl;
  std::cout << in_regions << " of " << num_faces(mesh) << " faces in a symmetric region, " << mapped
            << " vertices with a mirror partner" << std::endl;
  for(std::size_t i = 0; i < 5 && i < samples.size(); ++i) {
    const vertex_descriptor v(Mesh::size_type(samples[i]));
    std::cout << "  vertex " << std::size_t(v) << " <-> " << get(partner, v) << std::endl;
  }

  // 5. checks that need no ground truth: a reflection fixes its axis alone
  // and preserves distances, so a map that holds parts far from the curves in
  // place (a limb onto itself) or sends a part by another symmetry is
  // suspect; irsym --tries then runs again with the next seeds
  const double fixed = IRS::fixed_point_share(mesh, curves, partner);
  const double distortion =
    IRS::isometric_distortion(mesh, partner, IRS::parameters::vertex_region_map(map_region));
  std::cout << 100. * fixed << " % of the vertices far from the curves are (nearly) their own partner; the map "
            << "changes the distances between landmarks by " << distortion << " sqrt(area) on average"
            << (IRS::is_suspect_symmetric_map(fixed, distortion)
                  ? ": the map is suspect, another random_seed may do better" : "")
            << std::endl;

  // 6. the map on the input's vertices (the same map when nothing was filled or mended)
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
