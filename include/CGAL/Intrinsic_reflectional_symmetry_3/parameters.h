// Copyright (c) 2026 The Intrinsic_reflectional_symmetry_3 project.
// SPDX-License-Identifier: LGPL-3.0-or-later
// Author(s)     : The Intrinsic_reflectional_symmetry_3 developers

#ifndef CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_PARAMETERS_H
#define CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_PARAMETERS_H

#include <CGAL/disable_warnings.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

/// \file parameters.h
/// Named parameters of the package, in CGAL's style.
///
/// CGAL 5.5 cannot be taught new setter names from outside its tree, so the
/// package derives its own pack type from `CGAL::Named_function_parameters`:
/// a pack made here *is* a CGAL pack (CGAL functions accept it and ignore the
/// package's tags), and the package's setters chain with the CGAL names the
/// package reads:
/// \code
/// namespace IRS = CGAL::Intrinsic_reflectional_symmetry_3;
/// IRS::parameters::number_of_samples(2000).random_seed(7).vertex_point_map(vpm)
/// \endcode
/// Pass `.cgal()` to hand such a pack to a CGAL function that only accepts its
/// own pack type.

namespace CGAL {
namespace Intrinsic_reflectional_symmetry_3 {
namespace internal_np {
#define CGAL_IRS_add_named_parameter(X, Y, Z) enum X { Y };
#define CGAL_IRS_import_named_parameter(X, Z)
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/parameters_interface.h>
#undef CGAL_IRS_add_named_parameter
#undef CGAL_IRS_import_named_parameter
} // namespace internal_np

/// The package's parameter pack: a CGAL pack with the package's setters.
template <typename T, typename Tag, typename Base = CGAL::internal_np::No_property>
struct Named_function_parameters : CGAL::Named_function_parameters<T, Tag, Base>
{
  typedef CGAL::Named_function_parameters<T, Tag, Base> CGAL_np;
  typedef Named_function_parameters<T, Tag, Base> self;

  Named_function_parameters() : CGAL_np() {}
  Named_function_parameters(const T& v) : CGAL_np(v) {}
  Named_function_parameters(const T& v, const Base& b) : CGAL_np(v, b) {}

  /// the same pack, typed as a plain CGAL pack
  const CGAL_np& cgal() const { return *this; }

#define CGAL_IRS_add_named_parameter(X, Y, Z)                                        \
  template <typename K>                                                               \
  Named_function_parameters<K, internal_np::X, self> Z(const K& k) const              \
  { return Named_function_parameters<K, internal_np::X, self>(k, *this); }
#define CGAL_IRS_import_named_parameter(X, Z)                                        \
  template <typename K>                                                               \
  Named_function_parameters<K, CGAL::internal_np::X, self> Z(const K& k) const        \
  { return Named_function_parameters<K, CGAL::internal_np::X, self>(k, *this); }
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/parameters_interface.h>
#undef CGAL_IRS_add_named_parameter
#undef CGAL_IRS_import_named_parameter
};

namespace parameters {

/// the empty pack: every parameter takes its default
inline CGAL::parameters::Default_named_parameters default_values()
{ return CGAL::parameters::default_values(); }

#define CGAL_IRS_add_named_parameter(X, Y, Z)                                        \
  template <typename K>                                                               \
  Named_function_parameters<K, internal_np::X> Z(const K& k)                          \
  { return Named_function_parameters<K, internal_np::X>(k); }
#define CGAL_IRS_import_named_parameter(X, Z)                                        \
  template <typename K>                                                               \
  Named_function_parameters<K, CGAL::internal_np::X> Z(const K& k)                    \
  { return Named_function_parameters<K, CGAL::internal_np::X>(k); }
#include <CGAL/Intrinsic_reflectional_symmetry_3/internal/parameters_interface.h>
#undef CGAL_IRS_add_named_parameter
#undef CGAL_IRS_import_named_parameter

} // namespace parameters
} // namespace Intrinsic_reflectional_symmetry_3
} // namespace CGAL

#include <CGAL/enable_warnings.h>

#endif // CGAL_INTRINSIC_REFLECTIONAL_SYMMETRY_3_PARAMETERS_H
