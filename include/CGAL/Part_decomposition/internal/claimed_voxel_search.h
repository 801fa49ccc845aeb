// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_CLAIMED_VOXEL_SEARCH_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_CLAIMED_VOXEL_SEARCH_H

#include <CGAL/Part_decomposition/Voxel_grid.h>

#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/property_map.h>
#include <CGAL/tags.h>

#include <boost/iterator/counting_iterator.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

// Nearest claimed voxel centre (label >= 0) of a point of the normalized cube, exact.
// A point inside a claimed voxel is nearest to that voxel's centre (the Voronoi cells of the
// centres are the voxels). Otherwise the nearest claimed centre has a face neighbour that is not
// claimed (or lies on the grid border): from an interior claimed voxel, the face neighbour
// towards the point is strictly nearer. So the kd-tree holds only those boundary voxels.
class Claimed_voxel_search
{
  typedef CGAL::Simple_cartesian<double> K;
  typedef K::Point_3 Point;
  typedef CGAL::Search_traits_3<K> Base_traits;
  typedef CGAL::Pointer_property_map<Point>::const_type Point_map;
  typedef CGAL::Search_traits_adapter<std::size_t, Point_map, Base_traits> Traits;
  typedef CGAL::Distance_adapter<std::size_t, Point_map, CGAL::Euclidean_distance<Base_traits> > Distance;
  typedef CGAL::Orthogonal_k_neighbor_search<Traits, Distance> Search;
  typedef Search::Tree Tree;

public:
  struct Result
  {
    std::int32_t label = -1;
    double distance = 0.;
  };

  template <typename ConcurrencyTag>
  void build(const Voxel_grid<std::int32_t>& claimed)
  {
    m_grid = &claimed;
    m_any = false;
    const int r = claimed.resolution();
    m_points.clear();
    m_labels.clear();
    for(std::size_t idx = 0; idx < claimed.size(); ++idx)
    {
      if(claimed[idx] < 0) continue;
      m_any = true;
      const std::array<int, 3> c = claimed.coordinates(idx);
      bool boundary = false;
      for(int a = 0; a < 3 && !boundary; ++a)
        for(int s = -1; s <= 1 && !boundary; s += 2)
        {
          std::array<int, 3> n = c;
          n[a] += s;
          boundary = n[a] < 0 || n[a] >= r || claimed(n[0], n[1], n[2]) < 0;
        }
      if(!boundary) continue;
      const std::array<double, 3> p = claimed.center(idx);
      m_points.push_back(Point(p[0], p[1], p[2]));
      m_labels.push_back(claimed[idx]);
    }
    m_tree.reset();
    if(m_points.empty()) return;
    const Point_map pmap(m_points.data());
    m_tree.reset(new Tree(boost::counting_iterator<std::size_t>(0),
                          boost::counting_iterator<std::size_t>(m_points.size()),
                          typename Tree::Splitter(), Traits(pmap)));
    // Built before the concurrent queries (a lazy build is not thread-safe).
    m_tree->template build<ConcurrencyTag>();
  }

  // Whether some voxel is claimed.
  bool any() const { return m_any; }

  // The nearest claimed voxel of the normalized point u. \pre any()
  Result nearest(const std::array<double, 3>& u) const
  {
    Result out;
    const double lo = -0.5, hi = 0.5;
    if(u[0] >= lo && u[0] <= hi && u[1] >= lo && u[1] <= hi && u[2] >= lo && u[2] <= hi)
    {
      const std::array<int, 3> v = m_grid->locate(u[0], u[1], u[2]);
      const std::int32_t l = (*m_grid)(v[0], v[1], v[2]);
      if(l >= 0)
      {
        const std::array<double, 3> c = m_grid->center(v[0], v[1], v[2]);
        out.label = l;
        out.distance = std::sqrt((u[0] - c[0]) * (u[0] - c[0]) + (u[1] - c[1]) * (u[1] - c[1]) +
                                 (u[2] - c[2]) * (u[2] - c[2]));
        return out;
      }
    }
    const Point_map pmap(m_points.data());
    Search search(*m_tree, Point(u[0], u[1], u[2]), 1, 0, true, Distance(pmap));
    const auto it = search.begin();
    out.label = m_labels[it->first];
    out.distance = std::sqrt(it->second);
    return out;
  }

  // The number of voxels in the kd-tree.
  std::size_t tree_size() const { return m_points.size(); }

private:
  const Voxel_grid<std::int32_t>* m_grid = nullptr;
  bool m_any = false;
  std::vector<Point> m_points;
  std::vector<std::int32_t> m_labels;
  std::unique_ptr<Tree> m_tree;
};

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_CLAIMED_VOXEL_SEARCH_H
