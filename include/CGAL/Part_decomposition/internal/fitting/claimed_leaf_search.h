// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_CLAIMED_LEAF_SEARCH_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_CLAIMED_LEAF_SEARCH_H

// The claimed leaves of an adaptive grid seen from points of the normalized cube: the nearest
// claimed leaf centre and its label, and the other labels claimed within a window.
//
// Inputs: the grid and one label per leaf (-1: not claimed). Queries: points of the cube.

#include <CGAL/Part_decomposition/internal/grid/leaf_distance.h>
#include <CGAL/Part_decomposition/internal/toolbox/toolbox.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

// `Grid`: Adaptive_grid.
template <typename Grid>
class Claimed_leaf_search
{
public:
  struct Result
  {
    std::int32_t label = -1;
    double distance = 0.;
  };
  // the most labels listed near a leaf
  static constexpr std::uint8_t capacity = 4;
  typedef std::array<std::int32_t, capacity> Labels;

  // `window`: the reach, in normalized units, beyond which other labels do not matter (0: only
  // the nearest label is asked for); the labels within it are found by fronts propagated along
  // the leaves.
  template <typename ConcurrencyTag>
  void build(const Grid& grid, const std::vector<std::int32_t>& labels, double window = 0.)
  {
    m_grid = &grid;
    m_labels = &labels;
    m_any = false;
    for(std::int32_t k : labels) m_any = m_any || k >= 0;
    // a claimed leaf whose neighbours are all claimed is never the nearest from a point outside
    // it on a uniform grid
    m_boundary.template build<ConcurrencyTag>(grid, [&](std::size_t l) { return labels[l] >= 0; });
    if(window <= 0.) return;
    m_window = std::int64_t(std::ceil(window * double(grid.finest_resolution()) - 1e-9));
    mark_label_boundaries();
    std::int32_t K = 0;
    for(std::int32_t k : labels) K = (std::max)(K, k + 1);
    std::vector<std::vector<std::size_t> > boundary_of(static_cast<std::size_t>(K));
    for(std::size_t l = 0; l < grid.number_of_leaves(); ++l)
      if(labels[l] >= 0 && m_label_boundary[l]) boundary_of[std::size_t(labels[l])].push_back(l);
    m_label_search = std::vector<Leaf_feature_search<Grid> >(std::size_t(K));
    for(std::size_t k = 0; k < std::size_t(K); ++k) m_label_search[k].template build_on<ConcurrencyTag>(grid, boundary_of[k]);
    find_near_labels(window);
  }

  bool any() const { return m_any; }

  // The nearest claimed leaf centre of the normalized point u: the leaf of u if it is claimed,
  // else the nearest boundary claimed leaf. \pre any()
  Result nearest(const std::array<double, 3>& u) const
  {
    Result out;
    const Grid& g = *m_grid;
    const std::vector<std::int32_t>& labels = *m_labels;
    if(u[0] >= -0.5 && u[0] <= 0.5 && u[1] >= -0.5 && u[1] <= 0.5 && u[2] >= -0.5 && u[2] <= 0.5)
    {
      const std::size_t l = g.locate(u[0], u[1], u[2]);
      if(labels[l] >= 0)
      {
        const std::array<double, 3> c = g.center(l);
        out.label = labels[l];
        out.distance = std::sqrt((u[0] - c[0]) * (u[0] - c[0]) + (u[1] - c[1]) * (u[1] - c[1]) + (u[2] - c[2]) * (u[2] - c[2]));
        return out;
      }
    }
    const std::pair<std::size_t, double> nn = m_boundary.nearest(u);
    out.label = labels[nn.first];
    out.distance = std::sqrt(nn.second);
    return out;
  }

  // The leaf of the grid holding u, for the two queries below.
  std::size_t leaf_of(const std::array<double, 3>& u) const { return m_grid->locate(u[0], u[1], u[2]); }

  // The labels that may be claimed within the window of leaf `own`, nearest first along the
  // leaves, -1 past the last. \pre the search was built with a window
  const Labels& labels_near(std::size_t own) const { return m_near[own]; }

  // The squared distance from u (in leaf `own`) to the nearest centre of the leaves on the
  // boundary of label k, +infinity if it has none or if that leaf lies outside the window around
  // `own` (a box of `window` beyond it on each side). \pre the search was built with a window
  double squared_distance_to_label(std::int32_t k, const std::array<double, 3>& u, std::size_t own) const
  {
    const Grid& g = *m_grid;
    const std::pair<std::size_t, double> nn = m_label_search[std::size_t(k)].nearest(u);
    if(nn.first == Leaf_feature_search<Grid>::no_leaf) return nn.second;
    const typename Grid::Voxel &a = g.corner(own), &b = g.corner(nn.first);
    for(int x = 0; x < 3; ++x)
      if(std::int64_t(b[x]) + g.width(nn.first) <= std::int64_t(a[x]) - m_window ||
         std::int64_t(b[x]) >= std::int64_t(a[x]) + g.width(own) + m_window)
        return std::numeric_limits<double>::infinity();
    return nn.second;
  }

  // The number of leaves in the kd-tree of the nearest claimed leaf.
  std::size_t tree_size() const { return m_boundary.size(); }

private:
  // A claimed leaf on the cube's border or with a neighbour of another label (or none); the
  // others are never the nearest of their label from a point outside it on a uniform grid.
  void mark_label_boundaries()
  {
    const Grid& g = *m_grid;
    const std::vector<std::int32_t>& labels = *m_labels;
    const std::uint32_t R = std::uint32_t(g.finest_resolution());
    m_label_boundary.assign(g.number_of_leaves(), 0);
    for(std::size_t l = 0; l < g.number_of_leaves(); ++l)
    {
      if(labels[l] < 0) continue;
      const typename Grid::Voxel& c = g.corner(l);
      const std::uint32_t w = g.width(l);
      bool boundary = c[0] == 0 || c[1] == 0 || c[2] == 0 || c[0] + w == R || c[1] + w == R || c[2] + w == R;
      g.for_each_neighbor(l, [&](std::size_t m) { boundary = boundary || labels[m] != labels[l]; });
      m_label_boundary[l] = boundary ? 1 : 0;
    }
  }

  // Per leaf, the labels claimed within reach of it (the window around any of its points) along
  // paths of leaf centres, its own first, at most `capacity`: fronts of labels propagated from
  // the boundaries of the labels, each leaf settling one distance per label. A path through face
  // neighbours is at most sqrt(3) times the straight distance, about 1.2 times between leaves of
  // one size: `path_slack` keeps the labels a window reaches.
  static constexpr double path_slack = 1.5;
  void find_near_labels(double window)
  {
    const Grid& g = *m_grid;
    const std::vector<std::int32_t>& labels = *m_labels;
    const std::size_t n = g.number_of_leaves();
    Labels none;
    none.fill(-1);
    m_near.assign(n, none);
    std::vector<std::uint8_t> settled(n, 0);
    auto has = [&](std::size_t l, std::int32_t k) {
      for(std::uint8_t i = 0; i < settled[l]; ++i)
        if(m_near[l][i] == k) return true;
      return false;
    };
    // (distance, leaf, label) entries
    typedef std::pair<double, std::pair<std::size_t, std::int32_t> > Entry;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry> > front;
    for(std::size_t l = 0; l < n; ++l)
    {
      if(labels[l] < 0) continue;
      m_near[l][0] = labels[l];
      settled[l] = 1;
      if(m_label_boundary[l]) front.push(Entry(0., std::make_pair(l, labels[l])));
    }
    while(!front.empty())
    {
      const Entry e = front.top();
      front.pop();
      const std::size_t l = e.second.first;
      const std::int32_t k = e.second.second;
      if(e.first > 0.)
      {
        const double reach = std::sqrt(3.) * window + 0.5 * std::sqrt(3.) * g.size(l);
        if(settled[l] >= capacity || has(l, k) || e.first > path_slack * reach) continue;
        m_near[l][settled[l]++] = k;
      }
      const std::array<double, 3> c = g.center(l);
      g.for_each_neighbor(l, [&](std::size_t m) {
        if(settled[m] >= capacity || has(m, k)) return;
        const std::array<double, 3> d = g.center(m);
        const double step =
          std::sqrt((c[0] - d[0]) * (c[0] - d[0]) + (c[1] - d[1]) * (c[1] - d[1]) + (c[2] - d[2]) * (c[2] - d[2]));
        front.push(Entry(e.first + step, std::make_pair(m, k)));
      });
    }
  }

  const Grid* m_grid = nullptr;
  const std::vector<std::int32_t>* m_labels = nullptr;
  bool m_any = false;
  Leaf_feature_search<Grid> m_boundary;
  std::vector<std::uint8_t> m_label_boundary;
  std::vector<Leaf_feature_search<Grid> > m_label_search;
  std::vector<Labels> m_near;
  std::int64_t m_window = 0; // in finest voxels
};

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_CLAIMED_LEAF_SEARCH_H
