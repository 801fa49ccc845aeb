// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_TRIANGLE_ARRAYS_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_TRIANGLE_ARRAYS_H

#include <CGAL/Part_decomposition/internal/toolbox/toolbox.h>

#include <CGAL/assertions.h>
#include <CGAL/number_utils.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

// Relative area below which a triangle counts as degenerate: twice its area must exceed this
// times its longest squared edge (a height of 1e-12 longest edges). Rounding noise of the
// cross product is ~1e-16 relative, so every triangle above the bound has a meaningful normal.
constexpr double degenerate_triangle_ratio = 1e-12;

inline bool is_degenerate_triangle(const Vec3& a, const Vec3& b, const Vec3& c, double& twice_area)
{
  const Vec3 ab = sub3(b, a), ac = sub3(c, a), bc = sub3(c, b);
  const Vec3 n = cross3(ab, ac);
  twice_area = std::sqrt(dot3(n, n));
  double l2 = dot3(ab, ab);
  l2 = (std::max)(l2, dot3(ac, ac));
  l2 = (std::max)(l2, dot3(bc, bc));
  return !(twice_area > degenerate_triangle_ratio * l2) || !std::isfinite(twice_area);
}

// The mesh as flat arrays in double: vertex points by vertex index, face corners by face index.
struct Triangle_arrays
{
  std::vector<Vec3> points;
  std::vector<std::array<std::uint32_t, 3> > faces;
};

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_TRIANGLE_ARRAYS_H
