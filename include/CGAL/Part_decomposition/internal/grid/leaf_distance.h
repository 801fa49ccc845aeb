// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_LEAF_DISTANCE_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_LEAF_DISTANCE_H

// Distances between leaf centres of an adaptive grid: the distance transforms of the volume
// stages, where the dense grid had linear-time ones.
//
// Leaf_feature_search: built on a set of leaves (the features), the nearest feature centre of a
// point. Only the features with a face neighbour outside the set or on the cube's border are
// kept: on a uniform grid the neighbour of an inner feature towards a point outside the set is
// strictly nearer, so the answer is exact; on an adaptive grid it is the nearest of the boundary
// features.

#include <CGAL/Part_decomposition/internal/cues/point_kd_tree.h>
#include <CGAL/Part_decomposition/internal/toolbox/toolbox.h>

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

// `Grid`: Adaptive_grid.
template <typename Grid>
class Leaf_feature_search
{
  typedef Point_kd_tree::Point Point;
  typedef Point_kd_tree::Tree Tree;

public:
  static constexpr std::size_t no_leaf = (std::numeric_limits<std::size_t>::max)();

  // `is_feature(l)`: whether leaf l is a feature. With `border_is_feature`, the finest voxels just
  // outside the cube are features too, as the dense transform's virtual border layer.
  template <typename ConcurrencyTag, typename IsFeature>
  void build(const Grid& grid, const IsFeature& is_feature, bool border_is_feature = false)
  {
    m_grid = &grid;
    m_border = border_is_feature;
    m_points.clear();
    m_leaves.clear();
    const std::uint32_t R = std::uint32_t(grid.finest_resolution());
    for(std::size_t l = 0; l < grid.number_of_leaves(); ++l)
    {
      if(!is_feature(l)) continue;
      // a feature on the cube's border may be the nearest from a point outside the cube
      const typename Grid::Voxel& o = grid.corner(l);
      const std::uint32_t w = grid.width(l);
      bool boundary = o[0] == 0 || o[1] == 0 || o[2] == 0 || o[0] + w == R || o[1] + w == R || o[2] + w == R;
      grid.for_each_neighbor(l, [&](std::size_t m) { boundary = boundary || !is_feature(m); });
      if(!boundary) continue;
      const std::array<double, 3> c = grid.center(l);
      m_points.push_back(Point(c[0], c[1], c[2]));
      m_leaves.push_back(l);
    }
    build_tree<ConcurrencyTag>();
  }

  // The same on the listed feature leaves, all kept.
  template <typename ConcurrencyTag>
  void build_on(const Grid& grid, const std::vector<std::size_t>& features)
  {
    m_grid = &grid;
    m_border = false;
    m_points.clear();
    m_leaves = features;
    for(std::size_t l : features)
    {
      const std::array<double, 3> c = grid.center(l);
      m_points.push_back(Point(c[0], c[1], c[2]));
    }
    build_tree<ConcurrencyTag>();
  }

  bool empty() const { return m_points.empty() && !m_border; }
  std::size_t size() const { return m_points.size(); }

  // The nearest feature leaf of p (`no_leaf` for the border layer or no feature) and its squared
  // distance (+infinity if none).
  std::pair<std::size_t, double> nearest(const std::array<double, 3>& p) const
  {
    std::pair<std::size_t, double> best(no_leaf, std::numeric_limits<double>::infinity());
    if(m_border)
    {
      const double h = 0.5 / double(m_grid->finest_resolution());
      for(int a = 0; a < 3; ++a)
        best.second = (std::min)(best.second, (std::min)(std::pow(p[a] + 0.5 + h, 2), std::pow(0.5 - p[a] + h, 2)));
    }
    if(m_points.empty()) return best;
    const Point_kd_tree::Distance distance(Point_kd_tree::Point_map(m_points.data()));
    Point_kd_tree::Knn search(*m_tree, Point(p[0], p[1], p[2]), 1, 0., true, distance);
    const std::pair<std::size_t, double> nn = *search.begin();
    if(nn.second < best.second || (nn.second == best.second && best.first == no_leaf && !m_border))
      best = std::make_pair(m_leaves[nn.first], nn.second);
    return best;
  }

  // The squared distance from the centre of leaf l to the nearest feature.
  double squared_distance(std::size_t l) const { return nearest(m_grid->center(l)).second; }

private:
  template <typename ConcurrencyTag>
  void build_tree()
  {
    m_tree.reset();
    if(m_points.empty()) return;
    m_keys.resize(m_points.size());
    for(std::size_t i = 0; i < m_keys.size(); ++i) m_keys[i] = i;
    const Point_kd_tree::Point_map pmap(m_points.data());
    m_tree.reset(new Tree(m_keys.begin(), m_keys.end(), Point_kd_tree::Splitter(10), Point_kd_tree::Traits(pmap)));
    // built before concurrent queries (a lazy build is not thread-safe)
    m_tree->template build<ConcurrencyTag>();
  }

  const Grid* m_grid = nullptr;
  bool m_border = false;
  std::vector<Point> m_points;
  std::vector<std::size_t> m_leaves, m_keys;
  std::unique_ptr<Tree> m_tree;
};

// Per leaf, the squared distance from its centre to the nearest feature centre for the leaves
// `wanted(l)` asks for, +infinity for the others and where there is no feature.
template <typename ConcurrencyTag, typename Grid, typename IsFeature, typename Wanted>
std::vector<double> leaf_squared_distances(const Grid& grid, const IsFeature& is_feature, const Wanted& wanted,
                                           bool border_is_feature = false)
{
  Leaf_feature_search<Grid> search;
  search.template build<ConcurrencyTag>(grid, is_feature, border_is_feature);
  std::vector<double> d2(grid.number_of_leaves(), std::numeric_limits<double>::infinity());
  for_each_range<ConcurrencyTag>(grid.number_of_leaves(), [&](std::size_t b, std::size_t e) {
    for(std::size_t l = b; l < e; ++l)
    {
      if(is_feature(l)) d2[l] = 0.;
      else if(wanted(l) && !search.empty()) d2[l] = search.squared_distance(l);
    }
  }, 256);
  return d2;
}

// The 6-connected components of the leaves `in(l)`: a label per leaf (-1 outside), and per
// component its volume and volume-weighted centroid, numbered by smallest leaf.
struct Leaf_components
{
  std::vector<std::int32_t> labels;
  std::vector<double> volumes;
  std::vector<std::array<double, 3> > centroids;
  std::size_t size() const { return volumes.size(); }
};

template <typename Grid, typename In>
Leaf_components leaf_components(const Grid& grid, const In& in, const std::vector<std::size_t>* seeds = nullptr)
{
  Leaf_components out;
  out.labels.assign(grid.number_of_leaves(), -1);
  std::vector<std::size_t> queue;
  auto grow = [&](std::size_t start) {
    if(!in(start) || out.labels[start] >= 0) return;
    const std::int32_t label = std::int32_t(out.volumes.size());
    std::array<double, 3> g = {{0., 0., 0.}};
    double volume = 0.;
    queue.assign(1, start);
    out.labels[start] = label;
    for(std::size_t head = 0; head < queue.size(); ++head)
    {
      const std::size_t l = queue[head];
      const double v = grid.volume(l);
      const std::array<double, 3> c = grid.center(l);
      volume += v;
      for(int a = 0; a < 3; ++a) g[a] += v * c[a];
      grid.for_each_neighbor(l, [&](std::size_t m) {
        if(!in(m) || out.labels[m] >= 0) return;
        out.labels[m] = label;
        queue.push_back(m);
      });
    }
    for(int a = 0; a < 3; ++a) g[a] /= volume;
    out.volumes.push_back(volume);
    out.centroids.push_back(g);
  };
  if(seeds != nullptr)
    for(std::size_t l : *seeds) grow(l);
  else
    for(std::size_t l = 0; l < grid.number_of_leaves(); ++l) grow(l);
  return out;
}

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_LEAF_DISTANCE_H
