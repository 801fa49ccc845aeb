// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_UNIT_CUBE_OCTREE_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_UNIT_CUBE_OCTREE_H

#include <CGAL/config.h>
#include <CGAL/version.h>

#include <CGAL/Simple_cartesian.h>

#if CGAL_VERSION_NR >= CGAL_VERSION_NUMBER(6, 0, 0)
#include <CGAL/Orthtree.h>
#include <CGAL/Orthtree_traits_base.h>
#else
#include <CGAL/Octree.h>
#include <CGAL/property_map.h>
#endif

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

// The only place that names Orthtree types: an octree without data whose root box is exactly
// [-0.5,0.5]^3, so that the cells of depth d are the voxels of the 2^d grid. It is driven by a
// split predicate on (depth, voxel coordinates at that depth) and read back leaf by leaf.
typedef std::array<std::uint32_t, 3> Octree_cell;

#if CGAL_VERSION_NR >= CGAL_VERSION_NUMBER(6, 0, 0)

// 6.x: traits without node data, root box given by the traits.
struct Unit_cube_octree_traits : CGAL::Orthtree_traits_base<CGAL::Simple_cartesian<double>, 3>
{
  typedef CGAL::Orthtree_traits_base<CGAL::Simple_cartesian<double>, 3> Base;
  auto construct_root_node_bbox_object() const
  {
    return []() -> typename Base::Bbox_d {
      return {typename Base::Point_d(-0.5, -0.5, -0.5), typename Base::Point_d(0.5, 0.5, 0.5)};
    };
  }
};

class Unit_cube_octree
{
  typedef CGAL::Orthtree<Unit_cube_octree_traits> Tree;

public:
  Unit_cube_octree() : m_tree(Unit_cube_octree_traits()) {}
  Unit_cube_octree(const Unit_cube_octree&) = delete;
  Unit_cube_octree& operator=(const Unit_cube_octree&) = delete;

  // Call once: the predicate is asked for every node created.
  void refine(const std::function<bool(int, const Octree_cell&)>& split)
  {
    m_tree.refine([&](typename Tree::Node_index n, const Tree& t) {
      return split(int(t.depth(n)), t.global_coordinates(n));
    });
  }

  template <typename F>
  void for_each_leaf(const F& f) const
  {
    for(auto n : m_tree.traverse(CGAL::Orthtrees::Leaves_traversal<Tree>(m_tree)))
      f(int(m_tree.depth(n)), m_tree.global_coordinates(n));
  }

private:
  Tree m_tree;
};

#else // CGAL 5.x

class Unit_cube_octree
{
  typedef CGAL::Simple_cartesian<double> K;
  typedef K::Point_3 Point;
  typedef std::vector<Point> Range;
  typedef CGAL::Octree<K, Range> Tree;

  // The root box of 5.x is the bounding cube of the range times enlarge_ratio: the two opposite
  // corners and a ratio of 1 give exactly [-0.5,0.5]^3 (and a non-empty range, which 5.5.1 needs).
  static Range corners() { return {Point(-0.5, -0.5, -0.5), Point(0.5, 0.5, 0.5)}; }

public:
  Unit_cube_octree() : m_corners(corners()), m_tree(m_corners, CGAL::Identity_property_map<Point>(), 1.0) {}
  Unit_cube_octree(const Unit_cube_octree&) = delete;
  Unit_cube_octree& operator=(const Unit_cube_octree&) = delete;

  // Call once: in 5.5.1 a second refine() discards the first one.
  void refine(const std::function<bool(int, const Octree_cell&)>& split)
  {
    m_tree.refine([&](const typename Tree::Node& n) {
      return split(int(n.depth()), n.global_coordinates());
    });
  }

  // Leaves_traversal only: Level_traversal of 5.5.1 prints to std::cerr.
  template <typename F>
  void for_each_leaf(const F& f) const
  {
    for(const typename Tree::Node& n : m_tree.traverse(CGAL::Orthtrees::Leaves_traversal()))
      f(int(n.depth()), n.global_coordinates());
  }

private:
  Range m_corners; // the tree keeps a reference to its range: declared before it
  Tree m_tree;
};

#endif

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_UNIT_CUBE_OCTREE_H
