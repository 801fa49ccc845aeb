// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_LEAF_SIGNS_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_LEAF_SIGNS_H

// The inside of the leaves of an adaptive grid, from exact signed ray crossings along the rows of
// its finest voxels.
//
// Inputs: the normalized triangles, the grid (its leaves' finest-voxel boxes) and, for the flood
// fill, whether the surface may meet each leaf. Output: one flag (1 inside) per leaf.
//
// A leaf is decided at its `sign point`: the centre of the finest voxel at the middle of the leaf
// (the centre itself for a leaf of one finest voxel, half a finest voxel beyond it otherwise), so
// that every leaf lies on a row of the finest grid. A leaf the surface does not cross has one side
// everywhere; one it crosses is within a finest voxel of the surface at its centre.

#include <CGAL/Part_decomposition/internal/grid/mesh_voxelization.h>
#include <CGAL/Part_decomposition/internal/toolbox/toolbox.h>
#include <CGAL/Part_decomposition/internal/grid/winding_number.h>

#include <CGAL/tags.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

// The finest voxel at the middle of leaf l.
template <typename Grid>
typename Grid::Voxel sign_voxel(const Grid& grid, std::size_t l)
{
  const typename Grid::Voxel& c = grid.corner(l);
  const std::uint32_t h = grid.width(l) / 2;
  return {{c[0] + h, c[1] + h, c[2] + h}};
}

template <typename Grid>
Vec3 sign_point(const Grid& grid, std::size_t l)
{
  const typename Grid::Voxel v = sign_voxel(grid, l);
  const double h = 1. / double(grid.finest_resolution());
  return {{-0.5 + (v[0] + 0.5) * h, -0.5 + (v[1] + 0.5) * h, -0.5 + (v[2] + 0.5) * h}};
}

// Per leaf, along `axis`: the signed crossings beyond its sign point in the + direction (the
// winding number that ray sees), the number of those crossings, and the signed crossings of the
// whole row (the - ray sees beyond minus total).
struct Axis_crossings
{
  std::vector<int> beyond, count, total;
};

template <typename ConcurrencyTag, typename Grid>
Axis_crossings crossings_along_axis(const std::vector<Triangle_points>& tris, const Grid& grid, int axis)
{
  const int r = grid.finest_resolution();
  // coordinate (axis, axis + 1, axis + 2) of a point becomes (x, y, z)
  std::vector<Triangle_points> permuted(tris.size());
  for(std::size_t t = 0; t < tris.size(); ++t)
    for(std::size_t c = 0; c < 3; ++c)
      for(std::size_t a = 0; a < 3; ++a) permuted[t][c][a] = tris[t][c][(std::size_t(axis) + a) % 3];
  const Row_crossings rc = row_crossings<ConcurrencyTag>(permuted, r);
  std::vector<Triangle_points>().swap(permuted);
  const double h = 1. / double(r);
  const std::size_t n = grid.number_of_leaves(), R = std::size_t(r);
  Axis_crossings out;
  out.beyond.assign(n, 0);
  out.count.assign(n, 0);
  out.total.assign(n, 0);
  for_each_range<ConcurrencyTag>(n, [&](std::size_t b, std::size_t e) {
    for(std::size_t l = b; l < e; ++l)
    {
      const typename Grid::Voxel v = sign_voxel(grid, l);
      const std::size_t row = std::size_t(v[(axis + 1) % 3]) + R * std::size_t(v[(axis + 2) % 3]);
      const double x = -0.5 + (double(v[std::size_t(axis)]) + 0.5) * h;
      const std::size_t first = rc.offsets[row], last = rc.offsets[row + 1];
      // crossings strictly beyond the point count for the + ray
      const std::size_t c = std::size_t(std::upper_bound(rc.x.begin() + std::ptrdiff_t(first),
                                                         rc.x.begin() + std::ptrdiff_t(last), x) - rc.x.begin());
      int beyond = 0, total = 0;
      for(std::size_t k = first; k < last; ++k)
      {
        total += rc.sign[k];
        if(k >= c) beyond += rc.sign[k];
      }
      out.beyond[l] = beyond;
      out.count[l] = int(last - c);
      out.total[l] = total;
    }
  }, 256);
  return out;
}

// Inside flags from the rows along x: winding number beyond the sign point non-zero, or (with
// `parity`) an odd number of crossings beyond it.
template <typename ConcurrencyTag, typename Grid>
std::vector<std::uint8_t> leaf_inside_from_rows(const std::vector<Triangle_points>& tris, const Grid& grid,
                                                bool parity)
{
  const Axis_crossings x = crossings_along_axis<ConcurrencyTag>(tris, grid, 0);
  std::vector<std::uint8_t> inside(grid.number_of_leaves(), 0);
  for(std::size_t l = 0; l < inside.size(); ++l)
    inside[l] = parity ? std::uint8_t(x.count[l] & 1) : std::uint8_t(x.beyond[l] != 0);
  return inside;
}

// Inside flags by the generalized winding number at the sign point of each leaf of `leaves`
// (all leaves if empty), |w| > 1/2.
template <typename ConcurrencyTag, typename Grid>
void leaf_inside_by_winding_number(const std::vector<Triangle_points>& tris, const Grid& grid,
                                   const std::vector<std::size_t>& leaves, std::vector<std::uint8_t>& inside)
{
  if(tris.empty()) return;
  const Fast_winding_number wn(tris);
  const std::size_t n = leaves.empty() ? grid.number_of_leaves() : leaves.size();
  for_each_range<ConcurrencyTag>(n, [&](std::size_t b, std::size_t e) {
    for(std::size_t i = b; i < e; ++i)
    {
      const std::size_t l = leaves.empty() ? i : leaves[i];
      inside[l] = std::abs(wn(sign_point(grid, l))) > 0.5 ? 1 : 0;
    }
  });
}

// Inside flags by ray votes: inside if the six axis rays from the sign point see a non-zero
// winding number, outside if at most three do; in between (rays that leave through a hole) the
// generalized winding number decides.
template <typename ConcurrencyTag, typename Grid>
std::vector<std::uint8_t> leaf_inside_by_ray_votes(const std::vector<Triangle_points>& tris, const Grid& grid)
{
  const std::size_t n = grid.number_of_leaves();
  std::vector<std::uint8_t> votes(n, 0);
  for(int axis = 0; axis < 3; ++axis)
  {
    const Axis_crossings a = crossings_along_axis<ConcurrencyTag>(tris, grid, axis);
    for(std::size_t l = 0; l < n; ++l)
      votes[l] = std::uint8_t(votes[l] + (a.beyond[l] != 0) + (a.beyond[l] - a.total[l] != 0));
  }
  std::vector<std::size_t> undecided;
  std::vector<std::uint8_t> inside(n, 0);
  for(std::size_t l = 0; l < n; ++l)
  {
    if(votes[l] == 4 || votes[l] == 5) undecided.push_back(l);
    inside[l] = votes[l] == 6 ? 1 : 0;
  }
  if(!undecided.empty()) leaf_inside_by_winding_number<ConcurrencyTag>(tris, grid, undecided, inside);
  return inside;
}

// Inside flags by the paper's flood fill: the leaves the surface does not meet (`crossed` is 0)
// are outside if they are joined to the border of the cube through such leaves, inside
// otherwise. A leaf the surface may meet takes its flag in `crossed_inside` if given (the exact
// winding number of a closed mesh), else it is outside if one of its face neighbours is such an
// outside leaf, inside otherwise (an open sheet bounds nothing).
template <typename Grid>
std::vector<std::uint8_t> leaf_inside_by_flood_fill(const Grid& grid, const std::vector<std::uint8_t>& crossed,
                                                           const std::vector<std::uint8_t>* crossed_inside = nullptr)
{
  const std::size_t n = grid.number_of_leaves();
  const std::uint32_t R = std::uint32_t(grid.finest_resolution());
  std::vector<std::uint8_t> outside(n, 0);
  std::vector<std::size_t> queue;
  for(std::size_t l = 0; l < n; ++l)
  {
    const typename Grid::Voxel& c = grid.corner(l);
    const std::uint32_t w = grid.width(l);
    const bool border = c[0] == 0 || c[1] == 0 || c[2] == 0 || c[0] + w == R || c[1] + w == R || c[2] + w == R;
    if(border && !crossed[l])
    {
      outside[l] = 1;
      queue.push_back(l);
    }
  }
  for(std::size_t head = 0; head < queue.size(); ++head)
    grid.for_each_neighbor(queue[head], [&](std::size_t m) {
      if(crossed[m] || outside[m]) return;
      outside[m] = 1;
      queue.push_back(m);
    });
  std::vector<std::uint8_t> inside(n, 0);
  for(std::size_t l = 0; l < n; ++l)
  {
    if(!crossed[l])
    {
      inside[l] = outside[l] ? 0 : 1;
      continue;
    }
    if(crossed_inside != nullptr)
    {
      inside[l] = (*crossed_inside)[l];
      continue;
    }
    bool next_to_outside = false;
    grid.for_each_neighbor(l, [&](std::size_t m) { next_to_outside = next_to_outside || (!crossed[m] && outside[m]); });
    inside[l] = next_to_outside ? 0 : 1;
  }
  return inside;
}

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_LEAF_SIGNS_H
