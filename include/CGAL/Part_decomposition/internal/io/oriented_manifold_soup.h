// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_ORIENTED_MANIFOLD_SOUP_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_ORIENTED_MANIFOLD_SOUP_H

#include <CGAL/Part_decomposition/internal/toolbox/toolbox.h>

#include <CGAL/tags.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

// Whether the link edges e[0..n) (no repeated first end: else false) form one path or one cycle.
inline bool is_one_path_or_cycle(const std::pair<std::size_t, std::size_t>* e, std::size_t n)
{
  // a repeated directed edge from the vertex
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
  return steps == n;
}

// The corners of a triangle soup: corner c = 3t + k is the directed edge from vertex k of triangle
// t to the next vertex of t.
struct Soup_corners
{
  const std::vector<std::array<std::size_t, 3> >& triangles;

  std::size_t size() const { return 3 * triangles.size(); }
  std::size_t source(std::size_t c) const { return triangles[c / 3][c % 3]; }
  std::size_t target(std::size_t c) const { return triangles[c / 3][(c % 3 + 1) % 3]; }
};

// The corners of a soup grouped by source point in compressed rows: row p is [start[p],
// start[p + 1]) of `corner` and of `target` (each corner's target, so that a row is scanned
// without reading the triangles).
struct Corner_rows
{
  std::vector<std::size_t> start, corner, target;

  // A counting sort by source point, in one block of corners per thread: the rows list their
  // corners in increasing order whatever the blocks.
  Corner_rows(const Soup_corners& corners, std::size_t number_of_points)
    : start(number_of_points + 1, 0), corner(corners.size()), target(corners.size())
  {
    typedef CGAL::Parallel_if_available_tag Tag;
    const std::size_t nc = corners.size(), np = number_of_points;
    const std::size_t blocks = (std::min)(concurrency<Tag>(), nc / (std::size_t(1) << 16) + 1);
    const std::size_t block_size = (nc + blocks - 1) / blocks;
    std::vector<std::vector<std::size_t> > fill(blocks); // per block and point: a count, then a position
    for_each_block<Tag>(nc, block_size, [&](std::size_t b, std::size_t e) {
      std::vector<std::size_t>& f = fill[b / block_size];
      f.assign(np, 0);
      for(std::size_t c = b; c < e; ++c) ++f[corners.source(c)];
    });
    for(std::size_t p = 0; p < np; ++p)
    {
      std::size_t s = start[p];
      for(std::vector<std::size_t>& f : fill)
        if(!f.empty()) s += std::exchange(f[p], s);
      start[p + 1] = s;
    }
    for_each_block<Tag>(nc, block_size, [&](std::size_t b, std::size_t e) {
      std::vector<std::size_t>& f = fill[b / block_size];
      for(std::size_t c = b; c < e; ++c)
      {
        const std::size_t k = f[corners.source(c)]++;
        corner[k] = c;
        target[k] = corners.target(c);
      }
    });
  }
};

/*
Whether the triangles of `corners` (three distinct point ids each; `rows`: their corners by source
point) already form a consistently oriented 2-manifold, with or without border: then orienting the
soup changes nothing and most files skip CGAL's general orienter, the largest cost of reading a big
mesh.

- No directed edge occurs twice. This is edge-manifoldness and consistent orientation at once
  (three triangles on one edge give two of them the same direction).
  A directed edge v -> b is the first end of the link edge b -> c of triangle (v, b, c), so the
  check is done vertex by vertex on the links, with no global sort.
- The link of every vertex is connected. Without repeated directed edges, each link vertex has at
  most one outgoing and one incoming link edge, so the link is disjoint paths and cycles: walking it
  from its start covers every link edge exactly when it is one path or one cycle.

O(T) for T triangles (a vertex with more than 64 incident triangles fails early), linear memory;
the vertices are checked in parallel when `ConcurrencyTag` is.
*/
template <typename ConcurrencyTag>
bool is_oriented_manifold_soup(const Soup_corners& corners, const Corner_rows& rows)
{
  const std::size_t number_of_points = rows.start.size() - 1;
  std::atomic<bool> manifold(true);
  for_each_range<ConcurrencyTag>(number_of_points, [&](std::size_t b, std::size_t e) {
    std::array<std::pair<std::size_t, std::size_t>, 64> link;
    for(std::size_t v = b; v < e && manifold.load(std::memory_order_relaxed); ++v)
    {
      const std::size_t n = rows.start[v + 1] - rows.start[v];
      if(n < 2) continue;
      // a large fan: left to the general orienter (quadratic walk)
      bool ok = n <= link.size();
      for(std::size_t i = 0; ok && i < n; ++i)
      {
        const std::size_t c = rows.corner[rows.start[v] + i];
        link[i] = std::make_pair(corners.target(c), corners.source(3 * (c / 3) + (c % 3 + 2) % 3));
      }
      if(!ok || !is_one_path_or_cycle(link.data(), n)) manifold = false;
    }
  }, 4096);
  return manifold;
}

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_ORIENTED_MANIFOLD_SOUP_H
