// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_ORIENTED_MANIFOLD_SOUP_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_ORIENTED_MANIFOLD_SOUP_H

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

/*
Whether the triangles (three distinct vertex ids below `number_of_points` each) already form a
consistently oriented 2-manifold, with or without border: then orienting the soup changes nothing
and most files skip CGAL's general orienter, the largest cost of reading a big mesh.

- No directed edge occurs twice. This is edge-manifoldness and consistent orientation at once
  (three triangles on one edge give two of them the same direction).
  A directed edge v -> b is the first end of the link edge b -> c of triangle (v, b, c), so the
  check is done vertex by vertex on the links, with no global sort.
- The link of every vertex is connected. Without repeated directed edges, each link vertex has at
  most one outgoing and one incoming link edge, so the link is disjoint paths and cycles: walking it
  from its start covers every link edge exactly when it is one path or one cycle.

O(T) for T triangles (a vertex with more than 64 incident triangles fails early), linear memory.
*/
template <typename TriangleRange>
bool is_oriented_manifold_soup(const TriangleRange& triangles, std::size_t number_of_points)
{
  std::vector<std::uint32_t> degree(number_of_points + 1, 0);
  for(const auto& t : triangles)
    for(int k = 0; k < 3; ++k) ++degree[t[k]];

  // Link edges of each vertex, b -> c for a triangle (v, b, c), in compressed rows.
  std::vector<std::size_t> offset(number_of_points + 1, 0);
  for(std::size_t v = 0; v < number_of_points; ++v) offset[v + 1] = offset[v] + degree[v];
  std::vector<std::pair<std::size_t, std::size_t> > link(offset.back());
  std::vector<std::size_t> fill(offset.begin(), offset.end() - 1);
  for(const auto& t : triangles)
    for(int k = 0; k < 3; ++k)
      link[fill[t[k]]++] = std::make_pair(std::size_t(t[(k + 1) % 3]), std::size_t(t[(k + 2) % 3]));

  for(std::size_t v = 0; v < number_of_points; ++v)
  {
    const std::size_t first = offset[v], n = offset[v + 1] - first;
    if(n < 2) continue;
    if(n > 64) return false; // a large fan: left to the general orienter (quadratic walk)
    const std::pair<std::size_t, std::size_t>* e = link.data() + first;
    // a repeated directed edge from v
    for(std::size_t i = 1; i < n; ++i)
      for(std::size_t j = 0; j < i; ++j)
        if(e[i].first == e[j].first) return false;
    // start at an edge whose source ends no other edge (a path's start), else anywhere (a cycle)
    std::size_t start = 0;
    for(std::size_t i = 0; i < n; ++i)
    {
      bool has_predecessor = false;
      for(std::size_t j = 0; j < n && !has_predecessor; ++j) has_predecessor = e[j].second == e[i].first;
      if(!has_predecessor)
      {
        start = i;
        break;
      }
    }
    std::size_t steps = 1, current = start;
    for(;;)
    {
      std::size_t next = n;
      for(std::size_t j = 0; j < n; ++j)
        if(e[j].first == e[current].second)
        {
          next = j;
          break;
        }
      if(next == n || next == start) break;
      current = next;
      if(++steps > n) return false;
    }
    if(steps != n) return false;
  }
  return true;
}

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_ORIENTED_MANIFOLD_SOUP_H
