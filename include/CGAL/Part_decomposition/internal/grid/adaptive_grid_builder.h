// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_ADAPTIVE_GRID_BUILDER_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_ADAPTIVE_GRID_BUILDER_H

// The cells of the adaptive grid, chosen level by level from the distance of their centres to
// the surface, and fed to a CGAL Orthtree that holds the tree.
//
// Inputs: the normalized triangles and their AABB tree; the refinement rule (below).
// Outputs: the leaves (depth and coordinates, in the Orthtree's leaf order) and, per leaf, the
// unsigned distance from its centre to the surface, exact below `band`, `band` beyond it.

#include <CGAL/Part_decomposition/internal/toolbox/toolbox.h>
#include <CGAL/Part_decomposition/internal/grid/triangle_distance.h>
#include <CGAL/Part_decomposition/internal/grid/triangle_soup_aabb_tree.h>
#include <CGAL/Part_decomposition/internal/grid/unit_cube_octree.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

// The depth the surface asks for near each point of the cube, on a uniform grid of resolution
// 2^depth_of_resolution (the resolution of the prior's fused leaves); empty: `base_depth` everywhere.
struct Surface_depths
{
  int resolution = 0;
  std::vector<std::uint8_t> depth;
};

// Which cells are split. Uniform: every cell down to `finest_depth`. Adaptive: a cell is split
// while its centre is closer to the surface than `grading` times its side and it is larger than
// the surface needs at the nearest surface point: the depth of `surface` there, and beyond it,
// for a cell on the surface, where the surface faces another sheet closer than `feature_sides` of
// its sides (a thin part or a narrow gap), down to `finest_depth`.
struct Grid_refinement_rule
{
  int base_depth = 6;
  int finest_depth = 7;
  bool uniform = false;
  double grading = 1.;
  double feature_sides = 2.;
  double band = 0.125; // distances are exact below it
  Surface_depths surface;
  // per triangle of the tree's soup, whether its thin parts are refined below the surface depth
  // (empty: all of them)
  std::vector<std::uint8_t> thin_triangles;

  bool refines_thin(std::uint32_t t) const { return thin_triangles.empty() || thin_triangles[t] != 0; }

  int surface_depth(const Vec3& p) const
  {
    if(surface.resolution == 0) return base_depth;
    const int r = surface.resolution;
    auto cell = [r](double x) {
      const double t = std::floor((x + 0.5) * double(r));
      return !(t > 0.) ? 0 : (t >= double(r - 1) ? r - 1 : int(t));
    };
    return int(surface.depth[std::size_t(cell(p[0])) + std::size_t(r) * (std::size_t(cell(p[1])) + std::size_t(r) * std::size_t(cell(p[2])))]);
  }
};

struct Grid_leaf
{
  int depth;
  Octree_cell position;
  double distance; // clipped to the band
  bool crossed;    // the surface may meet the leaf: its centre is within half its diagonal of it
};

// One cell of a level of the sweep: its lower bound on the distance of its centre (from its
// parent's) and the triangle closest to the parent's centre, a bound for its own query.
struct Grid_sweep_node
{
  int depth;
  Octree_cell position;
  double lower;
  std::uint32_t hint;
  bool has_hint;
};

inline Vec3 cell_center(int depth, const Octree_cell& g)
{
  const double s = std::ldexp(1., -depth);
  return {{-0.5 + (double(g[0]) + 0.5) * s, -0.5 + (double(g[1]) + 0.5) * s, -0.5 + (double(g[2]) + 0.5) * s}};
}

inline Vec3 unit_normal(const Triangle_points& t)
{
  Vec3 n = cross3(sub3(t[1], t[0]), sub3(t[2], t[0]));
  const double l = norm3(n);
  if(!(l > 0.)) return {{0., 0., 0.}};
  return {{n[0] / l, n[1] / l, n[2] / l}};
}

// Whether the surface at the point of triangle `t` closest to `c` faces another sheet closer
// than `reach` on either side: the ball of radius `reach` tangent there holds a triangle turned
// by more than 120 degrees from it (the other side of a thin part, or across a narrow gap).
inline bool faces_near_sheet(const Triangle_soup_aabb_tree& tree, const Triangle_points& t, const Vec3& c,
                             double reach)
{
  const Vec3 n = unit_normal(t);
  if(n[0] == 0. && n[1] == 0. && n[2] == 0.) return false;
  const Vec3 p = closest_point_on_triangle(c, t[0], t[1], t[2]);
  const double bound2 = reach * reach * (1. - 1e-6);
  for(double side : {-1., 1.})
  {
    const Vec3 q = {{p[0] + side * reach * n[0], p[1] + side * reach * n[1], p[2] + side * reach * n[2]}};
    const std::pair<std::uint32_t, double> best = tree.closest(q, bound2);
    if(best.second < bound2 && dot3(unit_normal(tree.triangle(best.first)), n) < -0.5) return true;
  }
  return false;
}

// The distance of one node's centre (exact below `cap`, else a lower bound at least `cap`) and
// whether it is exact; `closest` receives the closest triangle when exact.
inline std::pair<double, bool> node_distance(const Triangle_soup_aabb_tree& tree, const Grid_sweep_node& node,
                                             double cap, std::uint32_t& closest)
{
  if(!(node.lower < cap)) return std::make_pair(node.lower, false);
  const Vec3 c = cell_center(node.depth, node.position);
  double bound2 = cap * cap;
  std::uint32_t bound_triangle = 0;
  if(node.has_hint)
  {
    const Triangle_points t = tree.triangle(node.hint);
    const double d = squared_distance_to_triangle(c, t[0], t[1], t[2]);
    if(d < bound2) bound2 = d, bound_triangle = node.hint;
  }
  const std::pair<std::uint32_t, double> best = tree.closest(c, bound2, bound_triangle);
  if(!(best.second < cap * cap)) return std::make_pair(cap, false);
  closest = best.first;
  return std::make_pair(std::sqrt(best.second), true);
}

// The sweep over one level: the distances of its nodes and which of them split.
template <typename ConcurrencyTag>
void sweep_level(const Triangle_soup_aabb_tree& tree, const Grid_refinement_rule& rule,
                 const std::vector<Grid_sweep_node>& level, std::vector<double>& distance,
                 std::vector<std::uint32_t>& closest, std::vector<std::uint8_t>& exact, std::vector<std::uint8_t>& split)
{
  const std::size_t n = level.size();
  distance.assign(n, 0.);
  closest.assign(n, 0);
  exact.assign(n, 0);
  split.assign(n, 0);
  if(n == 0) return;
  const int d = level.front().depth;
  const double side = std::ldexp(1., -d), half_diagonal = 0.5 * std::sqrt(3.) * side;
  const bool deepest = d >= rule.finest_depth;
  const double cap = deepest || rule.uniform ? rule.band : (std::max)(rule.band, rule.grading * side);
  for_each_range<ConcurrencyTag>(n, [&](std::size_t b, std::size_t e) {
    for(std::size_t i = b; i < e; ++i)
    {
      const std::pair<double, bool> dist = node_distance(tree, level[i], cap, closest[i]);
      distance[i] = dist.first;
      exact[i] = dist.second ? 1 : 0;
      if(deepest) continue;
      if(rule.uniform)
      {
        split[i] = 1;
        continue;
      }
      if(!dist.second || !(dist.first < rule.grading * side)) continue;
      const Triangle_points t = tree.triangle(closest[i]);
      const Vec3 c = cell_center(d, level[i].position);
      if(d < rule.surface_depth(closest_point_on_triangle(c, t[0], t[1], t[2])))
        split[i] = 1;
      else if(dist.first <= half_diagonal && rule.refines_thin(closest[i]))
        split[i] = faces_near_sheet(tree, t, c, rule.feature_sides * side) ? 1 : 0;
    }
  }, 64);
}

// The leaves of the grid of `rule` over the triangles of `tree`, in the leaf order of a CGAL
// Orthtree refined with the sweep's decisions, each with the distance of its centre.
template <typename ConcurrencyTag>
std::vector<Grid_leaf> adaptive_grid_leaves(const Triangle_soup_aabb_tree& tree, const Grid_refinement_rule& rule)
{
  // per depth, the sorted Morton-free keys of the split cells, and every leaf with its distance
  std::vector<std::vector<std::uint64_t> > split_keys(std::size_t(rule.finest_depth) + 1);
  std::vector<std::pair<std::pair<int, std::uint64_t>, std::pair<double, bool> > > leaf_distance;
  auto key = [](int d, const Octree_cell& g) {
    const std::uint64_t r = std::uint64_t(1) << d;
    return std::uint64_t(g[0]) + r * (std::uint64_t(g[1]) + r * std::uint64_t(g[2]));
  };
  std::vector<Grid_sweep_node> level{Grid_sweep_node{0, {{0, 0, 0}}, 0., 0, false}}, next;
  std::vector<double> distance;
  std::vector<std::uint32_t> closest;
  std::vector<std::uint8_t> exact, split;
  for(int d = 0; d <= rule.finest_depth && !level.empty(); ++d)
  {
    sweep_level<ConcurrencyTag>(tree, rule, level, distance, closest, exact, split);
    // a child's centre lies half the parent's half diagonal away from the parent's
    const double offset = 0.25 * std::sqrt(3.) * std::ldexp(1., -d), half_diagonal = 2. * offset;
    next.clear();
    for(std::size_t i = 0; i < level.size(); ++i)
    {
      const Octree_cell& g = level[i].position;
      if(!split[i])
      {
        // an unqueried leaf's bound exceeds its side: the surface does not meet it
        leaf_distance.push_back(
          {{d, key(d, g)}, {(std::min)(distance[i], rule.band), exact[i] != 0 && distance[i] <= half_diagonal * (1. + 1e-9)}});
        continue;
      }
      split_keys[std::size_t(d)].push_back(key(d, g));
      for(std::uint32_t c = 0; c < 8; ++c)
        next.push_back(Grid_sweep_node{d + 1, {{2 * g[0] + (c & 1), 2 * g[1] + ((c >> 1) & 1), 2 * g[2] + ((c >> 2) & 1)}},
                                       distance[i] - offset, closest[i], exact[i] != 0});
    }
    level.swap(next);
  }
  for(std::vector<std::uint64_t>& keys : split_keys) std::sort(keys.begin(), keys.end());
  std::sort(leaf_distance.begin(), leaf_distance.end());

  Unit_cube_octree octree;
  octree.refine([&](int d, const Octree_cell& g) {
    const std::vector<std::uint64_t>& keys = split_keys[std::size_t(d)];
    return d < rule.finest_depth && std::binary_search(keys.begin(), keys.end(), key(d, g));
  });
  std::vector<Grid_leaf> leaves;
  leaves.reserve(leaf_distance.size());
  octree.for_each_leaf([&](int d, const Octree_cell& g) {
    const std::pair<int, std::uint64_t> k(d, key(d, g));
    const auto it = std::lower_bound(leaf_distance.begin(), leaf_distance.end(), k,
                                     [](const std::pair<std::pair<int, std::uint64_t>, std::pair<double, bool> >& a,
                                        const std::pair<int, std::uint64_t>& b) { return a.first < b; });
    CGAL_assertion(it != leaf_distance.end() && it->first == k);
    leaves.push_back(Grid_leaf{d, g, it->second.first, it->second.second});
  });
  return leaves;
}

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_ADAPTIVE_GRID_BUILDER_H
