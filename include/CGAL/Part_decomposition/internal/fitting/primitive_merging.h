// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_PRIMITIVE_MERGING_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_PRIMITIVE_MERGING_H

// Merges fitted primitives whose claimed leaves one superquadric explains: a box tiled by
// several primitives becomes one.
//
// Inputs:  fit      the fitting result: primitives (normalized cube), claimed leaves per
//                   primitive and the `labels` of the leaves of the adaptive grid
//          classes  the Flow/Freeze class of each leaf of the same grid
//          tsdf     the signed distance field on the same grid (negative inside)
//          minimum_iou, maximum_freeze  see merge_explained_primitives()
// Output:  fit, with the merged primitives replaced by one superquadric each, the others kept,
//          numbered by smallest former index; labels and claimed voxels renumbered.
//
// Types: `Sq` a Superquadric, `Grid` the Adaptive_grid, `Field` the Truncated_signed_distance_field
// on it, `Class` Voxel_class, `FitResult` the Superquadric_fitting_result.

#include <CGAL/Part_decomposition/internal/parts/part_merging.h>
#include <CGAL/Part_decomposition/internal/fitting/superquadric_distance.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

// The volume of the leaves of `leaves` whose centre lies in the superquadric.
template <typename Sq, typename Grid>
double volume_within(const Sq& sq, const Grid& grid, const std::vector<std::size_t>& leaves)
{
  double e[3];
  superquadric_half_extents(sq.data(), e);
  double v = 0.;
  for(std::size_t l : leaves)
  {
    const std::array<double, 3> c = grid.center(l);
    bool in_box = true;
    for(int a = 0; a < 3; ++a) in_box = in_box && std::abs(c[a] - sq.data().c[a]) <= e[a];
    if(!in_box) continue;
    double x[3];
    sq.data().to_local(c.data(), x);
    if(local_point_within(sq.data(), x, 0.)) v += grid.volume(l);
  }
  return v;
}

// How well a superquadric explains a set of claimed leaves (`group`, of volume `group_volume`):
// the volume of their intersection over that of their union, where the unclaimed leaves inside the
// shape (Freeze and gaps between claims, `neutral`) count on neither side. A leaf is inside the
// superquadric if its centre is; the rest of the superquadric's volume is wrong: the exterior and
// the claims of other primitives it covers.
template <typename Sq, typename Grid>
double leaf_iou(const Sq& sq, const Grid& grid, const std::vector<std::size_t>& group,
                double group_volume, const std::vector<std::size_t>& neutral)
{
  const double inside = volume_within(sq, grid, group);
  const double wrong = (std::max)(0., sq.volume() - inside - volume_within(sq, grid, neutral));
  const double u = group_volume + wrong;
  return u > 0. ? (std::min)(1., inside / u) : 0.;
}

// The extents of `box` on its axes from the solid part of the leaves: the ball of each leaf whose
// centre is inside, as deep as the centre (all of it inside the shape) and no wider than the leaf.
// A coarse leaf the surface crosses has its centre up to half its width outside the shape.
template <typename Field>
void solid_extents(const std::vector<std::size_t>& leaves, const Field& tsdf, Part_box& box)
{
  const double finest_half = 0.5 / double(tsdf.grid.finest_resolution());
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for(std::size_t l : leaves)
  {
    const double v = tsdf.values[l];
    if(v > 0.) continue;
    const double r = (std::min)(0.5 * double(tsdf.grid.width(l)) / double(tsdf.grid.finest_resolution()), (std::max)(-v, finest_half));
    const std::array<double, 3> c = tsdf.grid.center(l);
    const Eigen::Vector3d x = box.axes.transpose() * (Eigen::Vector3d(c[0], c[1], c[2]) - box.center);
    lo = lo.cwiseMin(x - Eigen::Vector3d::Constant(r));
    hi = hi.cwiseMax(x + Eigen::Vector3d::Constant(r));
  }
  if(!(lo[0] <= hi[0])) // no leaf centre inside: the centres' box and a finest half voxel
  {
    box.half += Eigen::Vector3d::Constant(finest_half);
    return;
  }
  box.center += box.axes * ((hi + lo) / 2.);
  box.half = (hi - lo) / 2.;
}

// The superquadric of a set of leaves: their smallest box on principal, coordinate or the given
// axes, with the exponents (box-like, rounded, ellipsoid) that give the best IoU; returns it. The
// merge decides on the box of the leaf centres widened by `half_voxel` (the rule its threshold was
// chosen with); `solid` gives the superquadric of a merged group its solid extents and a finer
// choice of exponents.
template <typename Sq, typename Field>
double best_union_superquadric(const std::vector<std::size_t>& leaves, const Field& tsdf,
                               const std::vector<Eigen::Matrix3d>& axes, const std::vector<std::size_t>& neutral,
                               double neutral_volume, double minimum_iou, double half_voxel, bool solid,
                               Sq& best)
{
  const auto& grid = tsdf.grid;
  typedef typename Sq::Point_3 Point_3;
  Part_box box;
  std::vector<Eigen::Vector3d> points;
  points.reserve(leaves.size());
  for(std::size_t l : leaves)
  {
    const std::array<double, 3> c = grid.center(l);
    const double v = grid.volume(l);
    const Eigen::Vector3d p(c[0], c[1], c[2]);
    points.push_back(p);
    box.area += v;
    box.first += v * p;
    box.second += v * p * p.transpose();
  }
  fit_box_to_points(box, points, axes);
  if(solid) solid_extents(leaves, tsdf, box);
  else box.half += Eigen::Vector3d::Constant(half_voxel);
  typename Sq::Rotation R;
  for(int i = 0; i < 3; ++i)
    for(int j = 0; j < 3; ++j) R[std::size_t(3 * i + j)] = box.axes(i, j);
  const double union_volume = box.area;
  double best_iou = 0.;
  for(double e : {0.1, 0.25, 0.5, 1.})
  {
    if(e == 0.25 && !solid) continue;
    std::array<double, 3> scales;
    // a rounder solid reaches the corners of the box less
    for(int i = 0; i < 3; ++i) scales[std::size_t(i)] = box.half[i] * (e > 0.5 ? 1.15 : 1.);
    const Sq sq(scales, e, e, R, Point_3(box.center[0], box.center[1], box.center[2]));
    // the volume it covers beyond the union and every neutral leaf are wrong: a bound on its IoU
    const double bound = union_volume / (union_volume + (std::max)(0., sq.volume() - union_volume - neutral_volume));
    if(bound < minimum_iou) continue;
    const double iou = leaf_iou(sq, grid, leaves, union_volume, neutral);
    if(iou > best_iou) best_iou = iou, best = sq;
  }
  return best_iou;
}

// The rotation of a superquadric as a matrix.
template <typename Sq>
Eigen::Matrix3d rotation_matrix(const Sq& sq)
{
  const auto R = sq.rotation();
  Eigen::Matrix3d m;
  for(int i = 0; i < 3; ++i)
    for(int j = 0; j < 3; ++j) m(i, j) = R[std::size_t(3 * i + j)];
  return m;
}

// Per pair of primitives whose claimed leaves both meet the box of a surface leaf (Flow or Freeze)
// widened by a finest voxel (its 26-neighbourhood on a uniform grid): the area of such surface
// leaves and of the Freeze ones, in finest voxels squared.
template <typename Class, typename Grid>
std::map<std::pair<std::int32_t, std::int32_t>, std::array<double, 2> >
primitive_interfaces(const std::vector<std::int32_t>& labels, const std::vector<Class>& classes, const Grid& grid)
{
  std::map<std::pair<std::int32_t, std::int32_t>, std::array<double, 2> > out;
  std::vector<std::int32_t> near;
  for(std::size_t l = 0; l < grid.number_of_leaves(); ++l)
  {
    const Class c = classes[l];
    if(c == Class::EMPTY) continue;
    near.clear();
    const typename Grid::Voxel& o = grid.corner(l);
    const std::uint32_t w = grid.width(l);
    const typename Grid::Voxel lo = {{o[0] == 0 ? 0 : o[0] - 1, o[1] == 0 ? 0 : o[1] - 1, o[2] == 0 ? 0 : o[2] - 1}};
    const typename Grid::Voxel hi = {{o[0] + w, o[1] + w, o[2] + w}};
    grid.for_each_leaf_in_voxel_box(lo, hi, [&](std::size_t m) {
      if(labels[m] >= 0) near.push_back(labels[m]);
    });
    std::sort(near.begin(), near.end());
    near.erase(std::unique(near.begin(), near.end()), near.end());
    const double area = double(w) * double(w);
    for(std::size_t a = 0; a < near.size(); ++a)
      for(std::size_t b = a + 1; b < near.size(); ++b)
      {
        std::array<double, 2>& n = out[std::make_pair(near[a], near[b])];
        n[0] += area;
        if(c == Class::FREEZE) n[1] += area;
      }
  }
  return out;
}

// The unclaimed leaves inside the shape (Freeze and gaps between claims) and their volume.
template <typename Field>
std::vector<std::size_t> neutral_leaves(const std::vector<std::int32_t>& labels, const Field& tsdf, double& volume)
{
  std::vector<std::size_t> neutral;
  volume = 0.;
  for(std::size_t l = 0; l < labels.size(); ++l)
    if(labels[l] < 0 && tsdf.values[l] <= 0.)
    {
      neutral.push_back(l);
      volume += tsdf.grid.volume(l);
    }
  return neutral;
}

// Greedy agglomeration: the two adjacent groups of primitives whose union one superquadric
// explains best (IoU of leaf volumes; `delta`: the voxel of the finest prior resolution) are merged while that IoU is at least `minimum_iou`; groups
// whose common surface is more than `maximum_freeze` Freeze never merge (a boundary the prior
// saw). Returns the group (smallest member) of each primitive and the superquadric of each group.
template <typename FitResult, typename Class, typename Field, typename Sq>
std::vector<std::size_t> agglomerate_primitives(const FitResult& fit, const std::vector<Class>& classes,
                                                const Field& tsdf, double delta, double minimum_iou,
                                                double maximum_freeze, std::vector<Sq>& sq)
{
  typedef std::pair<std::size_t, std::size_t> Pair;
  const std::size_t K = fit.primitives.size();
  std::vector<std::size_t> group_of(K);
  std::vector<std::vector<std::size_t> > members(K), leaves(fit.claimed_leaves);
  std::vector<double> claimed_volume(K, 0.);
  for(std::size_t k = 0; k < K; ++k)
    for(std::size_t l : fit.claimed_leaves[k]) claimed_volume[k] += tsdf.grid.volume(l);
  for(std::size_t k = 0; k < K; ++k) group_of[k] = k, members[k].assign(1, k);
  sq = fit.primitives;
  double neutral_volume = 0.;
  const std::vector<std::size_t> neutral = neutral_leaves(fit.labels, tsdf, neutral_volume);
  std::map<Pair, std::array<double, 2> > link; // surface area, Freeze area
  for(const auto& i : primitive_interfaces(fit.labels, classes, tsdf.grid))
    link[Pair(std::size_t(i.first.first), std::size_t(i.first.second))] = i.second;
  auto largest_axes = [&](std::size_t g) { // of the largest primitive of group g
    std::size_t largest = members[g].front();
    for(std::size_t m : members[g])
      if(claimed_volume[m] > claimed_volume[largest]) largest = m;
    return rotation_matrix(fit.primitives[largest]);
  };
  std::map<Pair, std::pair<double, Sq> > score; // cached per pair of groups
  for(;;)
  {
    Pair best_pair(K, K);
    double best = minimum_iou;
    for(const auto& l : link)
    {
      if(double(l.second[1]) > maximum_freeze * double(l.second[0])) continue;
      auto it = score.find(l.first);
      if(it == score.end())
      {
        const std::size_t a = l.first.first, b = l.first.second;
        std::vector<std::size_t> u(leaves[a]);
        u.insert(u.end(), leaves[b].begin(), leaves[b].end());
        const std::vector<Eigen::Matrix3d> axes = {largest_axes(a), largest_axes(b)};
        Sq s = sq[a];
        const double iou =
          best_union_superquadric(u, tsdf, axes, neutral, neutral_volume, minimum_iou, 0.5 * delta, false, s);
        it = score.emplace(l.first, std::make_pair(iou, s)).first;
      }
      if(it->second.first >= best) best = it->second.first, best_pair = l.first;
    }
    if(best_pair.first == K) break;
    const std::size_t a = best_pair.first, b = best_pair.second; // a < b: the group keeps a
    sq[a] = score[best_pair].second;
    for(std::size_t m : members[b]) group_of[m] = a;
    members[a].insert(members[a].end(), members[b].begin(), members[b].end());
    members[b].clear();
    leaves[a].insert(leaves[a].end(), leaves[b].begin(), leaves[b].end());
    leaves[b].clear();
    std::map<Pair, std::array<double, 2> > relinked;
    for(const auto& l : link)
    {
      Pair p(l.first.first == b ? a : l.first.first, l.first.second == b ? a : l.first.second);
      if(p.first == p.second) continue;
      if(p.first > p.second) std::swap(p.first, p.second);
      std::array<double, 2>& n = relinked[p];
      n[0] += l.second[0];
      n[1] += l.second[1];
    }
    link.swap(relinked);
    for(auto it = score.begin(); it != score.end();)
      it = (it->first.first == a || it->first.second == a || it->first.first == b || it->first.second == b)
             ? score.erase(it) : std::next(it);
  }
  for(std::size_t g = 0; g < K; ++g)
    if(members[g].size() > 1)
      best_union_superquadric(leaves[g], tsdf, {largest_axes(g)}, neutral, neutral_volume, 0., 0., true, sq[g]);
  return group_of;
}

// Replaces each group of primitives of `agglomerate_primitives()` by its superquadric in `fit`.
template <typename FitResult, typename Class, typename Field>
void merge_explained_primitives(FitResult& fit, const std::vector<Class>& classes, const Field& tsdf, double delta,
                                double minimum_iou, double maximum_freeze)
{
  typedef typename decltype(FitResult::primitives)::value_type Sq;
  const std::size_t K = fit.primitives.size();
  if(K < 2) return;
  std::vector<Sq> sq;
  const std::vector<std::size_t> group_of = agglomerate_primitives(fit, classes, tsdf, delta, minimum_iou, maximum_freeze, sq);
  std::vector<double> claimed_volume(K, 0.);
  for(std::size_t k = 0; k < K; ++k)
    for(std::size_t l : fit.claimed_leaves[k]) claimed_volume[k] += tsdf.grid.volume(l);
  std::vector<std::size_t> index(K, K), representative(K, K); // new index of each group; its largest member
  std::size_t n = 0;
  for(std::size_t k = 0; k < K; ++k)
  {
    const std::size_t g = group_of[k];
    if(index[g] == K) index[g] = n++;
    if(representative[g] == K || claimed_volume[k] > claimed_volume[representative[g]])
      representative[g] = k;
  }
  if(n == K) return;
  FitResult out(fit);
  out.primitives.assign(n, Sq());
  out.claimed_leaves.assign(n, std::vector<std::size_t>());
  for(std::size_t k = 0; k < K; ++k)
  {
    const std::size_t g = group_of[k], i = index[g];
    out.claimed_leaves[i].insert(out.claimed_leaves[i].end(), fit.claimed_leaves[k].begin(), fit.claimed_leaves[k].end());
    if(representative[g] != k) continue;
    out.primitives[i] = sq[g];
    out.stage_resolution[i] = fit.stage_resolution[k];
    out.body_seeded[i] = fit.body_seeded[k];
    out.seed_leaf[i] = fit.seed_leaf[k];
    out.semi_axis_scale[i] = fit.semi_axis_scale[k];
    out.fit_cost[i] = fit.fit_cost[k];
  }
  out.stage_resolution.resize(n);
  out.body_seeded.resize(n);
  out.seed_leaf.resize(n);
  out.semi_axis_scale.resize(n);
  out.fit_cost.resize(n);
  out.input_primitives.clear();
  for(std::size_t i = 0; i < n; ++i)
  {
    std::sort(out.claimed_leaves[i].begin(), out.claimed_leaves[i].end());
    out.input_primitives.push_back(out.primitives[i].in_input_coordinates(fit.normalization));
  }
  for(std::size_t l = 0; l < out.labels.size(); ++l)
    if(out.labels[l] >= 0) out.labels[l] = std::int32_t(index[group_of[std::size_t(out.labels[l])]]);
  fit = std::move(out);
}

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_PRIMITIVE_MERGING_H
