// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_PARAMETER_CHECKS_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_PARAMETER_CHECKS_H

// The checks of the named parameters: one message format, "NAME must be RULE", for every stage;
// the RULE of a named parameter is its range in parameter_table.

#include <CGAL/Part_decomposition/input_validation.h>
#include <CGAL/Part_decomposition/parameters.h>

#include <CGAL/assertions.h>

#include <cmath>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

// Throws Invalid_input (INVALID_PARAMETER) "NAME must be RULE" unless `ok`.
inline void check_parameter(bool ok, const char* name, const char* rule)
{
  if(!ok) throw Invalid_input(Input_error::INVALID_PARAMETER, std::string(name) + " must be " + rule);
}

// The same for the named parameter `name`, whose rule is its range in parameter_table.
inline void check_parameter(bool ok, const char* name)
{
  CGAL_assertion(*range_rule(name) != '\0');
  check_parameter(ok, name, range_rule(name));
}

inline void check_positive(double x, const char* name) { check_parameter(x > 0. && std::isfinite(x), name); }

inline void check_non_negative(double x, const char* name) { check_parameter(x >= 0. && std::isfinite(x), name); }

// An integer named parameter converted to T, checked first to be at least `minimum` and to fit in T.
template <typename T, typename V>
T checked_integer(V value, T minimum, const char* name)
{
  static_assert(std::is_integral<V>::value, "this named parameter takes an integer");
  bool ok = true;
  if constexpr(std::is_signed<V>::value) ok = value >= V(0);
  typedef unsigned long long U;
  ok = ok && U(value) >= U(minimum) && U(value) <= U((std::numeric_limits<T>::max)());
  check_parameter(ok, name);
  return T(value);
}

// The rule of `voxel_resolutions`: powers of two from 1 to 256, each twice the previous.
inline void check_voxel_resolutions(const std::vector<int>& r)
{
  bool ok = !r.empty();
  for(std::size_t l = 0; ok && l < r.size(); ++l)
    ok = r[l] >= 1 && r[l] <= 256 && (r[l] & (r[l] - 1)) == 0 && (l == 0 || r[l] == 2 * r[l - 1]);
  check_parameter(ok, "voxel_resolutions");
}

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_PARAMETER_CHECKS_H
