// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_CLAIMED_VOXEL_SEARCH_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_CLAIMED_VOXEL_SEARCH_H

#include <CGAL/Part_decomposition/Voxel_grid.h>
#include <CGAL/Part_decomposition/internal/point_kd_tree.h>
#include <CGAL/Part_decomposition/internal/toolbox.h>

#include <CGAL/tags.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

// Nearest claimed voxel centre (label >= 0) of a point, exact up to ties. Most points are
// answered from the 27 voxels around them. The others go to a kd-tree that holds only the
// claimed voxels with a face neighbour that is not claimed (or on the grid border): for a point
// outside a claimed voxel, the face neighbour of an interior claimed voxel towards the point is
// strictly nearer, so an interior voxel is never the nearest.
class Claimed_voxel_search
{
  // the kd-tree of the normal deviation: one kd-tree type compiled for both
  typedef Point_kd_tree::Point Point;
  typedef Point_kd_tree::Tree Tree;

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
    const std::size_t r = std::size_t(claimed.resolution());
    m_points.clear();
    for(std::size_t idx = 0; idx < claimed.size(); ++idx)
    {
      if(claimed[idx] < 0) continue;
      m_any = true;
      // on the boundary: a face neighbour unclaimed or outside the grid (fewer than 6 claimed)
      int claimed_neighbors = 0;
      for_each_face_neighbor(idx, r, [&](std::size_t n) { claimed_neighbors += claimed[n] >= 0 ? 1 : 0; });
      if(claimed_neighbors == 6) continue;
      const std::array<double, 3> p = claimed.center(idx);
      m_points.push_back(Point(p[0], p[1], p[2]));
    }
    m_tree.reset();
    if(m_points.empty()) return;
    m_keys.resize(m_points.size());
    for(std::size_t i = 0; i < m_keys.size(); ++i) m_keys[i] = i;
    const Point_kd_tree::Point_map pmap(m_points.data());
    // CGAL's default bucket size (10)
    m_tree.reset(new Tree(m_keys.begin(), m_keys.end(), Point_kd_tree::Splitter(10), Point_kd_tree::Traits(pmap)));
    // Built before the concurrent queries (a lazy build is not thread-safe).
    m_tree->template build<ConcurrencyTag>();
  }

  // Whether some voxel is claimed.
  bool any() const { return m_any; }

  // The nearest claimed voxel of the normalized point u. \pre any()
  Result nearest(const std::array<double, 3>& u) const
  {
    Result out;
    const Voxel_grid<std::int32_t>& g = *m_grid;
    if(u[0] >= -0.5 && u[0] <= 0.5 && u[1] >= -0.5 && u[1] <= 0.5 && u[2] >= -0.5 && u[2] <= 0.5)
    {
      const int r = g.resolution();
      const double h = g.voxel_size();
      const std::int32_t* values = g.values().data();
      const std::array<int, 3> v = g.locate(u[0], u[1], u[2]);
      auto offset = [&](int a, int i) { return u[a] - (-0.5 + (double(i) + 0.5) * h); };
      // The voxel of u, if claimed, holds the nearest centre (the voxels are the Voronoi cells).
      const std::int32_t own = values[std::size_t(v[0]) + std::size_t(r) * (std::size_t(v[1]) + std::size_t(r) * std::size_t(v[2]))];
      if(own >= 0)
      {
        const double dx = offset(0, v[0]), dy = offset(1, v[1]), dz = offset(2, v[2]);
        out.label = own;
        out.distance = std::sqrt(dx * dx + dy * dy + dz * dz);
        return out;
      }
      // Else the 26 voxels around it: a centre beyond them is at least 1.5 voxels away, so a
      // claimed centre found within 1.5 voxels is the nearest (the first one on a tie).
      double best = std::numeric_limits<double>::infinity();
      std::int32_t label = -1;
      const int i0 = (std::max)(v[0] - 1, 0), i1 = (std::min)(v[0] + 1, r - 1);
      const int j0 = (std::max)(v[1] - 1, 0), j1 = (std::min)(v[1] + 1, r - 1);
      const int k0 = (std::max)(v[2] - 1, 0), k1 = (std::min)(v[2] + 1, r - 1);
      for(int k = k0; k <= k1; ++k)
      {
        const double dz = offset(2, k);
        for(int j = j0; j <= j1; ++j)
        {
          const double dy = offset(1, j);
          const std::int32_t* row = values + std::size_t(r) * (std::size_t(j) + std::size_t(r) * std::size_t(k));
          for(int i = i0; i <= i1; ++i)
          {
            if(row[i] < 0) continue;
            const double dx = offset(0, i);
            const double d = dx * dx + dy * dy + dz * dz;
            if(d < best) best = d, label = row[i];
          }
        }
      }
      if(label >= 0 && best <= 2.25 * h * h)
      {
        out.label = label;
        out.distance = std::sqrt(best);
        return out;
      }
    }
    const Point_kd_tree::Distance distance(Point_kd_tree::Point_map(m_points.data()));
    Point_kd_tree::Knn search(*m_tree, Point(u[0], u[1], u[2]), 1, 0., true, distance);
    const std::pair<std::size_t, double> nn = *search.begin(); // a copy: the iterator yields temporaries
    const Point& c = m_points[nn.first];
    const std::array<int, 3> v = g.locate(c.x(), c.y(), c.z()); // its voxel
    out.label = g(v[0], v[1], v[2]);
    out.distance = std::sqrt(nn.second);
    return out;
  }

  // The number of voxels in the kd-tree.
  std::size_t tree_size() const { return m_points.size(); }

private:
  const Voxel_grid<std::int32_t>* m_grid = nullptr;
  bool m_any = false;
  std::vector<Point> m_points;
  std::vector<std::size_t> m_keys; // the tree holds indices into m_points
  std::unique_ptr<Tree> m_tree;
};

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_CLAIMED_VOXEL_SEARCH_H
