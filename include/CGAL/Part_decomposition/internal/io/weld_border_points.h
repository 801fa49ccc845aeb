// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_WELD_BORDER_POINTS_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_WELD_BORDER_POINTS_H

// Welding of the points of a triangle soup that lie within a tolerance of each other.
//
// Inputs: the points; the triangles, three distinct point ids each; an absolute tolerance.
// Output: the triangles renumbered onto the welded points, and per point the point it was welded
// to (itself if none, always the smallest id of its group, whose coordinates the group keeps).
// Only points on a border edge (an edge of one triangle) are welded: round-off on a seam leaves
// two borders, while a point inside a surface has no seam to close. Two points of one triangle are
// never welded, even through a third point: the triangles keep three distinct points.

#include <CGAL/assertions.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

// Per point, the other corners of its triangles, in compressed rows (`offset` has one more entry
// than points).
struct Point_neighbors
{
  std::vector<std::size_t> offset, corner;

  Point_neighbors(const std::vector<std::array<std::size_t, 3> >& triangles, std::size_t number_of_points)
    : offset(number_of_points + 1, 0), corner(6 * triangles.size())
  {
    for(const auto& t : triangles)
      for(int k = 0; k < 3; ++k) offset[t[k] + 1] += 2;
    for(std::size_t v = 0; v < number_of_points; ++v) offset[v + 1] += offset[v];
    std::vector<std::size_t> fill(offset.begin(), offset.end() - 1);
    for(const auto& t : triangles)
      for(int k = 0; k < 3; ++k)
      {
        corner[fill[t[k]]++] = t[(k + 1) % 3];
        corner[fill[t[k]]++] = t[(k + 2) % 3];
      }
    for(std::size_t v = 0; v < number_of_points; ++v)
      std::sort(corner.begin() + std::ptrdiff_t(offset[v]), corner.begin() + std::ptrdiff_t(offset[v + 1]));
  }

  // whether `v` lies on an edge of one triangle: a neighbour met once in its sorted row
  bool on_border(std::size_t v) const
  {
    for(std::size_t i = offset[v]; i < offset[v + 1];)
    {
      std::size_t j = i + 1;
      while(j < offset[v + 1] && corner[j] == corner[i]) ++j;
      if(j - i == 1) return true;
      i = j;
    }
    return false;
  }

  bool share_a_triangle(std::size_t u, std::size_t v) const
  {
    return std::binary_search(corner.begin() + std::ptrdiff_t(offset[u]), corner.begin() + std::ptrdiff_t(offset[u + 1]), v);
  }
};

// The pairs (i < j) of `candidates` at most `tolerance` apart, by increasing distance (then ids):
// the candidates are sorted by their cell of side `tolerance`, and each looks in the 27 cells
// around its own.
inline std::vector<std::pair<std::size_t, std::size_t> >
close_pairs(const std::vector<std::array<double, 3> >& points, const std::vector<std::size_t>& candidates,
            double tolerance)
{
  typedef std::array<std::int64_t, 3> Cell;
  std::array<double, 3> lo = points[candidates.front()];
  for(std::size_t c : candidates)
    for(int a = 0; a < 3; ++a) lo[a] = (std::min)(lo[a], points[c][a]);
  std::vector<std::pair<Cell, std::size_t> > cells;
  cells.reserve(candidates.size());
  for(std::size_t c : candidates)
  {
    Cell k;
    for(int a = 0; a < 3; ++a) k[a] = std::int64_t(std::floor((points[c][a] - lo[a]) / tolerance));
    cells.emplace_back(k, c);
  }
  std::sort(cells.begin(), cells.end());
  std::vector<std::tuple<double, std::size_t, std::size_t> > found;
  const double tolerance2 = tolerance * tolerance;
  for(const auto& e : cells)
    for(int d = 0; d < 27; ++d)
    {
      const Cell k = {{e.first[0] + d % 3 - 1, e.first[1] + (d / 3) % 3 - 1, e.first[2] + d / 9 - 1}};
      auto it = std::lower_bound(cells.begin(), cells.end(), std::make_pair(k, std::size_t(0)));
      for(; it != cells.end() && it->first == k; ++it)
      {
        if(it->second <= e.second) continue;
        double d2 = 0.;
        for(int a = 0; a < 3; ++a)
          d2 += (points[it->second][a] - points[e.second][a]) * (points[it->second][a] - points[e.second][a]);
        if(d2 <= tolerance2) found.emplace_back(d2, e.second, it->second);
      }
    }
  std::sort(found.begin(), found.end());
  std::vector<std::pair<std::size_t, std::size_t> > pairs;
  pairs.reserve(found.size());
  for(const auto& f : found) pairs.emplace_back(std::get<1>(f), std::get<2>(f));
  return pairs;
}

// Welds the border points of the soup within `tolerance` (closest pairs first) and renumbers the
// triangles; returns per point the point it is welded to. `welded` receives how many points were
// welded to another one.
inline std::vector<std::size_t> weld_border_points(const std::vector<std::array<double, 3> >& points,
                                                   std::vector<std::array<std::size_t, 3> >& triangles,
                                                   double tolerance, std::size_t& welded)
{
  const std::size_t n = points.size();
  std::vector<std::size_t> target(n);
  for(std::size_t i = 0; i < n; ++i) target[i] = i;
  welded = 0;
  if(!(tolerance > 0.) || triangles.empty()) return target;
  const Point_neighbors neighbors(triangles, n);
  std::vector<std::size_t> candidates;
  for(std::size_t v = 0; v < n; ++v)
    if(neighbors.on_border(v)) candidates.push_back(v);
  if(candidates.size() < 2) return target;

  const std::vector<std::pair<std::size_t, std::size_t> > pairs = close_pairs(points, candidates, tolerance);
  if(pairs.empty()) return target; // the common case: no seam left open
  // groups by union-find; the root of a group is its smallest point, at whose rank among the
  // points of the pairs the group's members are listed
  std::vector<std::size_t> paired;
  for(const auto& p : pairs)
  {
    paired.push_back(p.first);
    paired.push_back(p.second);
  }
  std::sort(paired.begin(), paired.end());
  paired.erase(std::unique(paired.begin(), paired.end()), paired.end());
  std::vector<std::vector<std::size_t> > members(paired.size());
  for(std::size_t c = 0; c < paired.size(); ++c) members[c].push_back(paired[c]);
  auto rank = [&](std::size_t v) {
    return std::size_t(std::lower_bound(paired.begin(), paired.end(), v) - paired.begin());
  };
  auto root = [&](std::size_t v) {
    while(target[v] != v) v = target[v] = target[target[v]];
    return v;
  };
  for(const auto& p : pairs)
  {
    std::size_t a = root(p.first), b = root(p.second);
    if(a == b) continue;
    if(a > b) std::swap(a, b);
    std::vector<std::size_t>& group_a = members[rank(a)];
    std::vector<std::size_t>& group_b = members[rank(b)];
    bool apart = false;
    for(std::size_t u : group_a)
      for(std::size_t v : group_b) apart = apart || neighbors.share_a_triangle(u, v);
    if(apart) continue;
    target[b] = a;
    group_a.insert(group_a.end(), group_b.begin(), group_b.end());
    std::vector<std::size_t>().swap(group_b);
    ++welded;
  }
  for(std::size_t v = 0; v < n; ++v) target[v] = root(v);
  for(auto& t : triangles)
    for(std::size_t& id : t) id = target[id];
  return target;
}

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_WELD_BORDER_POINTS_H
