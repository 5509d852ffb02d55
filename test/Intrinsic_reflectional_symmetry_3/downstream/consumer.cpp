// Built against the installed package only: the headers and the named
// parameters must be usable from a project that knows nothing of the source tree.
#include <CGAL/Intrinsic_reflectional_symmetry_3/parameters.h>
#include <CGAL/Intrinsic_reflectional_symmetry_3/errors.h>
#include <iostream>

namespace IRS = CGAL::Intrinsic_reflectional_symmetry_3;

int main()
{
  auto np = IRS::parameters::number_of_samples(123).random_seed(7u);
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const int n = choose_parameter(get_parameter(np, IRS::internal_np::number_of_samples), 0);
  const unsigned s = choose_parameter(get_parameter(np, CGAL::internal_np::random_seed), 0u);
  if(n != 123 || s != 7u) { std::cerr << "named parameters lost\n"; return 1; }
  std::cout << "downstream consumer ok\n";
  return 0;
}
