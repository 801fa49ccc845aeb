// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_SUPERQUADRIC_LEAVES_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_SUPERQUADRIC_LEAVES_H

// The leaves of an adaptive grid whose centre lies within a superquadric.
//
// Inputs: the superquadric, the grid, a margin (d~ <= margin; 0: the plain inside test).
// Output: f(l) for each such leaf l, in the order of Adaptive_grid::for_each_leaf_in_box().

#include <CGAL/Part_decomposition/internal/fitting/superquadric_distance.h>

#include <array>
#include <cstddef>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

template <typename Grid, typename F>
void for_each_leaf_within(const Superquadric_data& q, const Grid& grid, double margin, const F& f)
{
  double e[3];
  superquadric_half_extents(q, e);
  std::array<double, 3> lo, hi;
  for(int a = 0; a < 3; ++a)
  {
    lo[a] = q.c[a] - e[a] - margin;
    hi[a] = q.c[a] + e[a] + margin;
    if(!(lo[a] <= 0.5 && hi[a] >= -0.5)) return;
  }
  grid.for_each_leaf_in_box(lo, hi, [&](std::size_t l) {
    const std::array<double, 3> c = grid.center(l);
    for(int a = 0; a < 3; ++a)
      if(c[a] < lo[a] || c[a] > hi[a]) return;
    double x[3];
    q.to_local(c.data(), x);
    if(local_point_within(q, x, margin)) f(l);
  });
}

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_SUPERQUADRIC_LEAVES_H
