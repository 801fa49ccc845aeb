// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_ADAPTIVE_GRID_H
#define CGAL_PART_DECOMPOSITION_ADAPTIVE_GRID_H

#include <CGAL/assertions.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {
namespace Part_decomposition {

/*!
\ingroup PkgPartDecompositionRef
The leaves of an octree over the normalized cube \f$[-0.5,0.5]^3\f$: cubes of side
\f$2^{-d}\f$ that tile the cube, a leaf of depth \f$d\f$ being a voxel of the grid of resolution
\f$2^d\f$. Every volume stage of the method (distance field, zones, fitting, claims) stores one
value per leaf, in a `std::vector` indexed like the leaves.

Positions are given in <em>finest voxels</em>, the voxels of the grid of resolution
`finest_resolution()` \f$= 2^D\f$: leaf `l` is the box of `width(l)` finest voxels per side whose
smallest corner is the finest voxel `corner(l)`, that is the cube
\f$[-0.5 + c_x/2^D, -0.5 + (c_x + w)/2^D] \times \dots\f$. The leaves are numbered in the order
of their smallest corners, \f$z\f$ first, then \f$y\f$, then \f$x\f$: the leaves of a uniform grid
(`uniform()`) are numbered like the voxels of a `Voxel_grid` of the same resolution.

The grid also gives, for each leaf, its face neighbours (the leaves whose cube shares a piece of a
face with it), and locates points and boxes.
*/
class Adaptive_grid
{
public:
  /// a position in finest voxels.
  typedef std::array<std::uint32_t, 3> Voxel;

  /// a cell of the octree: its depth and its coordinates in the grid of resolution `2^depth`.
  struct Cell
  {
    int depth;     ///< the depth, from 0 (the whole cube) to the finest
    Voxel position; ///< the coordinates of the cell in the grid of its own depth
  };

  /// the largest finest resolution.
  static constexpr int maximum_resolution = 1024;

  /// creates a grid without leaves.
  Adaptive_grid() = default;

  /// creates the grid of the cells `leaves` at the finest resolution `finest_resolution`.
  /// \pre `finest_resolution` is a power of two, at most `maximum_resolution`; the cells are no
  ///      deeper than its depth and tile the cube: every point of the cube lies in exactly one of
  ///      them (checked: `std::invalid_argument` otherwise).
  Adaptive_grid(int finest_resolution, const std::vector<Cell>& leaves) { build(finest_resolution, leaves); }

  /// the grid of one leaf per voxel of the grid of resolution `r` (a power of two, at most
  /// `maximum_resolution`), numbered like the voxels of `Voxel_grid`.
  static Adaptive_grid uniform(int r)
  {
    check_resolution(r);
    std::vector<Cell> cells;
    cells.reserve(std::size_t(r) * std::size_t(r) * std::size_t(r));
    const int d = depth_of(r);
    for(int k = 0; k < r; ++k)
      for(int j = 0; j < r; ++j)
        for(int i = 0; i < r; ++i) cells.push_back(Cell{d, {{std::uint32_t(i), std::uint32_t(j), std::uint32_t(k)}}});
    return Adaptive_grid(r, cells);
  }

  /// \name Leaves
  /// @{

  /// the resolution \f$2^D\f$ of the finest voxels, in which positions are given.
  int finest_resolution() const { return m_resolution; }
  /// the number of leaves.
  std::size_t number_of_leaves() const { return m_depth.size(); }
  /// the number of leaves of depth `d`.
  std::size_t number_of_leaves_of_depth(int d) const
  {
    return d >= 0 && std::size_t(d) < m_count_of_depth.size() ? m_count_of_depth[std::size_t(d)] : 0;
  }
  /// the depth of leaf `l`.
  int depth(std::size_t l) const { return int(m_depth[l]); }
  /// the resolution \f$2^{depth}\f$ of the grid of which leaf `l` is a voxel.
  int resolution(std::size_t l) const { return 1 << depth(l); }
  /// the side of leaf `l` in finest voxels.
  std::uint32_t width(std::size_t l) const { return std::uint32_t(m_resolution >> depth(l)); }
  /// the smallest corner of leaf `l`, in finest voxels.
  const Voxel& corner(std::size_t l) const { return m_corner[l]; }
  /// the side of leaf `l` in the normalized cube.
  double size(std::size_t l) const { return double(width(l)) / double(m_resolution); }
  /// the volume of leaf `l` in the normalized cube.
  double volume(std::size_t l) const
  {
    const double s = size(l);
    return s * s * s;
  }
  /// the centre of leaf `l` in the normalized cube.
  std::array<double, 3> center(std::size_t l) const
  {
    const double h = 1. / double(m_resolution), half = 0.5 * double(width(l));
    const Voxel& c = m_corner[l];
    return {{-0.5 + (double(c[0]) + half) * h, -0.5 + (double(c[1]) + half) * h, -0.5 + (double(c[2]) + half) * h}};
  }
  /// @}

  /// \name Neighbours
  /// @{

  /// the number of face neighbours of leaf `l`.
  std::size_t number_of_neighbors(std::size_t l) const { return m_first_neighbor[l + 1] - m_first_neighbor[l]; }
  /// the first of the face neighbours of leaf `l`: in the order `-x`, `+x`, `-y`, `+y`, `-z`,
  /// `+z`, and within a face in the order of a quadtree of the face (by the second axis, then by
  /// the first, at each level).
  const std::uint32_t* neighbors_begin(std::size_t l) const { return m_neighbors.data() + m_first_neighbor[l]; }
  /// past the last face neighbour of leaf `l`.
  const std::uint32_t* neighbors_end(std::size_t l) const { return m_neighbors.data() + m_first_neighbor[l + 1]; }
  /// calls `f(m)` for every face neighbour `m` of leaf `l`, in the order of `neighbors_begin()`.
  template <typename F>
  void for_each_neighbor(std::size_t l, const F& f) const
  {
    for(const std::uint32_t* n = neighbors_begin(l); n != neighbors_end(l); ++n) f(std::size_t(*n));
  }
  /// @}

  /// \name Location
  /// @{

  /// the leaf that contains the finest voxel `(i,j,k)`. \pre the voxel is in the grid.
  std::size_t leaf_of_voxel(std::uint32_t i, std::uint32_t j, std::uint32_t k) const
  {
    CGAL_precondition(i < std::uint32_t(m_resolution) && j < std::uint32_t(m_resolution) && k < std::uint32_t(m_resolution));
    const std::uint32_t key = morton_key(i, j, k);
    const std::size_t block = key >> m_block_shift;
    const auto first = m_morton_keys.begin() + std::ptrdiff_t(m_block_start[block]);
    // the leaf covering the next block's first key may start in this block
    const auto last = m_morton_keys.begin() + std::ptrdiff_t(m_block_start[block + 1] + 1);
    const auto it = std::upper_bound(first, last, key);
    return m_morton_leaf[std::size_t(it - m_morton_keys.begin()) - 1];
  }
  /// the finest voxel that contains the coordinate `p` along one axis, clamped to the grid (as
  /// `voxel_coordinate()`).
  std::uint32_t voxel_coordinate(double p) const
  {
    const double t = std::floor((p + 0.5) * double(m_resolution));
    if(!(t > 0.)) return 0;
    if(t >= double(m_resolution - 1)) return std::uint32_t(m_resolution - 1);
    return std::uint32_t(t);
  }
  /// the leaf that contains the point `(x,y,z)` of the normalized cube (points outside are
  /// clamped to the border leaves).
  std::size_t locate(double x, double y, double z) const
  {
    return leaf_of_voxel(voxel_coordinate(x), voxel_coordinate(y), voxel_coordinate(z));
  }
  /// calls `f(l)` once for every leaf `l` that holds a finest voxel of the box `[lo, hi]`
  /// (inclusive, in finest voxels, clamped to the grid), in the order of their smallest corners
  /// along the Morton curve.
  template <typename F>
  void for_each_leaf_in_voxel_box(const Voxel& lo, const Voxel& hi, const F& f) const
  {
    if(m_depth.empty()) return;
    const std::uint32_t top = std::uint32_t(m_resolution - 1);
    Voxel a, b;
    for(int x = 0; x < 3; ++x)
    {
      a[x] = (std::min)(lo[x], top);
      b[x] = (std::min)(hi[x], top);
      if(a[x] > b[x]) return;
    }
    // depth-first over the octree nodes that meet the box: a node holding one leaf reports it
    struct Node
    {
      int depth;
      Voxel position;
    };
    Node stack[8 * 11];
    int size = 0;
    stack[size++] = Node{0, {{0, 0, 0}}};
    while(size > 0)
    {
      const Node n = stack[--size];
      const std::uint32_t w = std::uint32_t(m_resolution >> n.depth);
      const Voxel c = {{n.position[0] * w, n.position[1] * w, n.position[2] * w}};
      const std::size_t l = leaf_of_voxel(c[0], c[1], c[2]);
      if(depth(l) <= n.depth)
      {
        f(l);
        continue;
      }
      const std::uint32_t half = w / 2;
      for(int child = 7; child >= 0; --child)
      {
        Voxel p;
        bool meets = true;
        for(int x = 0; x < 3; ++x)
        {
          p[x] = 2 * n.position[x] + std::uint32_t((child >> x) & 1);
          const std::uint32_t from = p[x] * half, to = from + half - 1;
          meets = meets && to >= a[x] && from <= b[x];
        }
        if(meets) stack[size++] = Node{n.depth + 1, p};
      }
    }
  }
  /// calls `f(l)` once for every leaf `l` that meets the box `[lo, hi]` of the normalized cube
  /// (clamped to the cube), in the order of `for_each_leaf_in_voxel_box()`.
  template <typename F>
  void for_each_leaf_in_box(const std::array<double, 3>& lo, const std::array<double, 3>& hi, const F& f) const
  {
    for(int x = 0; x < 3; ++x)
      if(!(lo[x] <= hi[x])) return;
    for_each_leaf_in_voxel_box({{voxel_coordinate(lo[0]), voxel_coordinate(lo[1]), voxel_coordinate(lo[2])}},
                               {{voxel_coordinate(hi[0]), voxel_coordinate(hi[1]), voxel_coordinate(hi[2])}}, f);
  }
  /// @}

  /// the depth \f$d\f$ of the resolution \f$r = 2^d\f$. \pre `r` is a power of two.
  static int depth_of(int r)
  {
    int d = 0;
    while((1 << d) < r) ++d;
    return d;
  }

  friend bool operator==(const Adaptive_grid& a, const Adaptive_grid& b)
  {
    return a.m_resolution == b.m_resolution && a.m_depth == b.m_depth && a.m_corner == b.m_corner;
  }
  friend bool operator!=(const Adaptive_grid& a, const Adaptive_grid& b) { return !(a == b); }

private:
  static void check_resolution(int r)
  {
    if(r < 1 || r > maximum_resolution || (r & (r - 1)) != 0)
      throw std::invalid_argument("Adaptive_grid: the finest resolution must be a power of two from 1 to 1024");
  }

  // Interleaved bits of (i, j, k), i lowest: the leaves of one node form a contiguous range.
  static std::uint32_t morton_key(std::uint32_t i, std::uint32_t j, std::uint32_t k)
  {
    std::uint32_t key = 0;
    for(int b = 0; b < 10; ++b)
      key |= (((i >> b) & 1u) << (3 * b)) | (((j >> b) & 1u) << (3 * b + 1)) | (((k >> b) & 1u) << (3 * b + 2));
    return key;
  }

  void build(int finest_resolution, const std::vector<Cell>& leaves)
  {
    check_resolution(finest_resolution);
    m_resolution = finest_resolution;
    const int D = depth_of(finest_resolution);
    const std::size_t n = leaves.size();
    // leaves sorted by smallest corner, z first
    std::vector<std::pair<std::uint64_t, std::size_t> > order(n);
    for(std::size_t l = 0; l < n; ++l)
    {
      const Cell& c = leaves[l];
      if(c.depth < 0 || c.depth > D || c.position[0] >> c.depth || c.position[1] >> c.depth || c.position[2] >> c.depth)
        throw std::invalid_argument("Adaptive_grid: a cell lies outside the grid");
      const std::uint64_t s = std::uint64_t(D - c.depth), R = std::uint64_t(finest_resolution);
      order[l] = {(std::uint64_t(c.position[0]) << s) + R * ((std::uint64_t(c.position[1]) << s) + R * (std::uint64_t(c.position[2]) << s)), l};
    }
    std::sort(order.begin(), order.end());
    m_depth.resize(n);
    m_corner.resize(n);
    m_count_of_depth.assign(std::size_t(D) + 1, 0);
    for(std::size_t l = 0; l < n; ++l)
    {
      const Cell& c = leaves[order[l].second];
      const int s = D - c.depth;
      m_depth[l] = std::uint8_t(c.depth);
      m_corner[l] = {{c.position[0] << s, c.position[1] << s, c.position[2] << s}};
      ++m_count_of_depth[std::size_t(c.depth)];
    }
    build_location_index();
    build_neighbors();
  }

  // The leaves sorted by the Morton key of their smallest corner: a leaf covers the keys from its
  // own to the next leaf's. Checks that they tile the cube. Each of the 4096 (or fewer) top blocks
  // of keys knows its range of leaves, so that a search looks at the leaves of one block.
  void build_location_index()
  {
    const std::size_t n = m_depth.size();
    std::vector<std::pair<std::uint32_t, std::uint32_t> > keyed(n);
    for(std::size_t l = 0; l < n; ++l) keyed[l] = {morton_key(m_corner[l][0], m_corner[l][1], m_corner[l][2]), std::uint32_t(l)};
    std::sort(keyed.begin(), keyed.end());
    m_morton_keys.resize(n);
    m_morton_leaf.resize(n);
    std::uint64_t expected = 0;
    for(std::size_t i = 0; i < n; ++i)
    {
      m_morton_keys[i] = keyed[i].first;
      m_morton_leaf[i] = keyed[i].second;
      if(keyed[i].first != expected) throw std::invalid_argument("Adaptive_grid: the cells do not tile the cube");
      const std::uint64_t w = std::uint64_t(width(keyed[i].second));
      expected += w * w * w;
    }
    const std::uint64_t total = std::uint64_t(m_resolution) * std::uint64_t(m_resolution) * std::uint64_t(m_resolution);
    if(expected != total) throw std::invalid_argument("Adaptive_grid: the cells do not tile the cube");
    const int D = depth_of(m_resolution);
    const int block_depth = (std::min)(D, 4);
    m_block_shift = 3 * (D - block_depth);
    const std::size_t blocks = std::size_t(1) << (3 * block_depth);
    m_block_start.assign(blocks + 1, 0);
    // block b holds the keys [b << shift, (b + 1) << shift); the leaf covering its first key
    // starts at or before it
    std::size_t i = 0;
    for(std::size_t b = 0; b < blocks; ++b)
    {
      const std::uint64_t first_key = std::uint64_t(b) << m_block_shift;
      while(i + 1 < n && std::uint64_t(m_morton_keys[i + 1]) <= first_key) ++i;
      m_block_start[b] = i;
    }
    m_block_start[blocks] = n - 1;
  }

  // Per leaf and direction, the leaves across the face: the one that holds the whole face, or the
  // smaller ones tiling it (quads split until one leaf covers each).
  void build_neighbors()
  {
    const std::size_t n = m_depth.size();
    const std::uint32_t R = std::uint32_t(m_resolution);
    m_first_neighbor.assign(n + 1, 0);
    m_neighbors.clear();
    m_neighbors.reserve(6 * n);
    struct Quad
    {
      std::uint32_t u, v, w;
    };
    std::vector<Quad> stack;
    for(std::size_t l = 0; l < n; ++l)
    {
      const Voxel& c = m_corner[l];
      const std::uint32_t w = width(l);
      for(int dir = 0; dir < 6; ++dir)
      {
        const int a = dir / 2, ua = a == 0 ? 1 : 0, va = a == 2 ? 1 : 2;
        if(dir % 2 == 0 ? c[a] == 0 : c[a] + w >= R) continue;
        const std::uint32_t across = dir % 2 == 0 ? c[a] - 1 : c[a] + w;
        stack.assign(1, Quad{c[ua], c[va], w});
        while(!stack.empty())
        {
          const Quad q = stack.back();
          stack.pop_back();
          Voxel p;
          p[a] = across;
          p[ua] = q.u;
          p[va] = q.v;
          const std::size_t m = leaf_of_voxel(p[0], p[1], p[2]);
          if(width(m) >= q.w)
          {
            if(m_neighbors.size() == m_first_neighbor[l] || m_neighbors.back() != std::uint32_t(m))
              m_neighbors.push_back(std::uint32_t(m));
            continue;
          }
          const std::uint32_t h = q.w / 2;
          // pushed in reverse: popped by v, then u
          stack.push_back(Quad{q.u + h, q.v + h, h});
          stack.push_back(Quad{q.u, q.v + h, h});
          stack.push_back(Quad{q.u + h, q.v, h});
          stack.push_back(Quad{q.u, q.v, h});
        }
      }
      m_first_neighbor[l + 1] = m_neighbors.size();
    }
  }

  int m_resolution = 0;
  int m_block_shift = 0;
  std::vector<std::uint8_t> m_depth;
  std::vector<Voxel> m_corner;
  std::vector<std::size_t> m_count_of_depth;
  std::vector<std::uint32_t> m_morton_keys, m_morton_leaf;
  std::vector<std::size_t> m_block_start;
  std::vector<std::size_t> m_first_neighbor;
  std::vector<std::uint32_t> m_neighbors;
};

} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_ADAPTIVE_GRID_H
