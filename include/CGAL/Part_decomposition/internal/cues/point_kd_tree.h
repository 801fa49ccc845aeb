// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_POINT_KD_TREE_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_POINT_KD_TREE_H

#include <CGAL/Kd_tree.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/property_map.h>

#include <cstddef>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

// The one kd-tree type of the package: indices into an array of points, searched for their k
// nearest neighbours. Every search uses this type, so the tree and its search are compiled once.
struct Point_kd_tree
{
  typedef CGAL::Simple_cartesian<double> Kernel;
  typedef Kernel::Point_3 Point;
  typedef CGAL::Pointer_property_map<Point>::const_type Point_map;
  typedef CGAL::Search_traits_3<Kernel> Base_traits;
  typedef CGAL::Search_traits_adapter<std::size_t, Point_map, Base_traits> Traits;
  typedef CGAL::Distance_adapter<std::size_t, Point_map, CGAL::Euclidean_distance<Base_traits> > Distance;
  typedef CGAL::Sliding_midpoint<Traits> Splitter;
  // The points cache keeps the coordinates in the tree's own order: no indirection per distance.
  typedef CGAL::Kd_tree<Traits, Splitter, CGAL::Tag_true, CGAL::Tag_true> Tree;
  typedef CGAL::Orthogonal_k_neighbor_search<Traits, Distance, Splitter, Tree> Knn;
};

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_POINT_KD_TREE_H
