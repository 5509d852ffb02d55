// SDF map signatures and the similarity filter on a generated snowman:
// samples are taken in mirror pairs (v and its image across the plane x=0),
// and the program counts how many pairs pass the paper's similarity filter,
// and how many pairs of the whole sample set do.
//
// usage: sdf_signatures_example [number_of_vertices [number_of_pairs]]

#include <CGAL/Intrinsic_reflectional_symmetry_3/signatures.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/shape_generators.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/Heat_method_geodesic_oracle.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/geodesic_distances.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Random.h>
#include <CGAL/Surface_mesh.h>

#include <cstdlib>
#include <iostream>
#include <iterator>
#include <utility>
#include <vector>

namespace IRS = CGAL::Intrinsic_reflectional_symmetry_3;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

int main(int argc, char** argv)
{
  const std::size_t n = argc > 1 ? std::size_t(std::atoi(argv[1])) : 2500;
  const std::size_t pairs = argc > 2 ? std::size_t(std::atoi(argv[2])) : 200;

  // a snowman with its known mirror maps (planes x=0 and y=0)
  const IRS::Generated_shape<Mesh> snowman = IRS::generate_snowman<Mesh>(n);
  const std::vector<std::ptrdiff_t>& mirror = snowman.symmetries[0].mirror; // x=0 plane
  std::cout << "snowman: " << num_vertices(snowman.mesh) << " vertices, mean edge length "
            << snowman.mean_edge_length << std::endl;

  // samples: random vertices off the plane, each followed by its mirror vertex
  CGAL::Random rnd(42);
  std::vector<std::size_t> samples;
  std::vector<bool> taken(num_vertices(snowman.mesh), false);
  while(samples.size() < 2 * pairs) {
    const std::size_t v = std::size_t(rnd.get_int(0, int(num_vertices(snowman.mesh))));
    const std::ptrdiff_t w = mirror[v];
    if(w < 0 || std::size_t(w) == v || taken[v] || taken[std::size_t(w)]) continue;
    taken[v] = taken[std::size_t(w)] = true;
    samples.push_back(v);
    samples.push_back(std::size_t(w));
  }

  // geodesic distances from the samples, then their signatures (paper defaults:
  // 6 rings, eps_SIM = 0.025; radius 0.1 sqrt(area); CGAL's SDF defaults)
  IRS::Heat_method_geodesic_oracle<Mesh> oracle(snowman.mesh);
  const IRS::Geodesic_distance_matrix distances = IRS::compute_geodesic_distance_matrix(oracle, samples);
  const IRS::Sdf_signatures signatures = IRS::compute_sdf_signatures(snowman.mesh, distances);
  std::cout << "signatures: " << signatures.number_of_samples() << " samples, " << signatures.number_of_rings()
            << " rings up to geodesic radius " << signatures.radius() << std::endl;

  std::size_t passing = 0;
  for(std::size_t i = 0; i < signatures.number_of_samples(); i += 2)
    if(IRS::passes_similarity_filter(signatures.signature(i), signatures.signature(i + 1)))
      ++passing;
  std::cout << passing << " of " << pairs << " mirror pairs pass the similarity filter" << std::endl;

  std::vector<std::pair<std::size_t, std::size_t> > similar;
  IRS::similar_sample_pairs(signatures, std::back_inserter(similar));
  const std::size_t all = signatures.number_of_samples() * (signatures.number_of_samples() - 1) / 2;
  std::cout << similar.size() << " of all " << all << " sample pairs pass it" << std::endl;
  return passing * 10 >= pairs * 9 ? EXIT_SUCCESS : EXIT_FAILURE;
}
