// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_PRIMITIVE_MERGING_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_PRIMITIVE_MERGING_H

// Merges fitted primitives whose claimed voxels one superquadric explains: a box tiled by
// several primitives becomes one.
//
// Inputs:  fit      the fitting result: primitives (normalized cube), claimed voxels per
//                   primitive and the grid `labels` of the finest resolution r
//          classes  the Flow/Freeze class of each voxel of the same grid
//          distance the signed distance field on the same grid (negative inside)
//          minimum_iou, maximum_freeze  see merge_explained_primitives()
// Output:  fit, with the merged primitives replaced by one superquadric each, the others kept,
//          numbered by smallest former index; labels and claimed voxels renumbered.

#include <CGAL/Part_decomposition/Superquadric.h>
#include <CGAL/Part_decomposition/Voxel_grid.h>
#include <CGAL/Part_decomposition/stage_results.h>
#include <CGAL/Part_decomposition/internal/part_merging.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

// How well a superquadric explains a set of claimed voxels (`in_set` of their label): their
// intersection over union, where the unclaimed voxels inside the shape (Freeze and gaps between
// claims, `distance` <= 0) count on neither side. Counted on the grid of resolution `r_eval` (a
// divisor of the grid's), `group_size` being the number of claimed voxels: a large union is
// estimated from a coarser grid.
template <typename GeomTraits, typename InSet>
double voxel_iou(const Superquadric<GeomTraits>& sq, const Voxel_grid<std::int32_t>& labels,
                 const Voxel_grid<double>& distance, const InSet& in_set, std::size_t group_size, int r_eval)
{
  std::size_t inside = 0, wrong = 0;
  const bool same = r_eval == labels.resolution();
  const double h = 1. / double(r_eval);
  sq.for_each_covered_voxel(r_eval, [&](int i, int j, int k, std::size_t idx) {
    if(!same)
    {
      const std::array<int, 3> v =
        labels.locate(-0.5 + (i + 0.5) * h, -0.5 + (j + 0.5) * h, -0.5 + (k + 0.5) * h);
      idx = labels.index(v[0], v[1], v[2]);
    }
    const std::int32_t l = labels[idx];
    if(l >= 0 && in_set(std::size_t(l))) ++inside;
    else if(l >= 0 || distance[idx] > 0.) ++wrong;
  });
  const double scale = std::pow(double(r_eval) / double(labels.resolution()), 3);
  const double u = double(group_size) * scale + double(wrong);
  return u > 0. ? (std::min)(1., double(inside) / u) : 0.;
}

// The superquadric of a set of voxels: their smallest box on principal, coordinate or the given
// axes, with the exponents (box-like, rounded, ellipsoid) that give the best IoU; returns it.
template <typename GeomTraits, typename InSet>
double best_union_superquadric(const std::vector<std::size_t>& voxels, const Voxel_grid<std::int32_t>& labels,
                               const Voxel_grid<double>& distance, const InSet& in_set, const std::vector<Eigen::Matrix3d>& axes,
                               std::size_t neutral_voxels, double minimum_iou, Superquadric<GeomTraits>& best)
{
  typedef typename GeomTraits::Point_3 Point_3;
  Part_box box;
  std::vector<Eigen::Vector3d> points;
  points.reserve(voxels.size());
  for(std::size_t idx : voxels)
  {
    const std::array<double, 3> c = labels.center(idx);
    const Eigen::Vector3d p(c[0], c[1], c[2]);
    points.push_back(p);
    box.area += 1.;
    box.first += p;
    box.second += p * p.transpose();
  }
  fit_box_to_points(box, points, axes);
  const double h = labels.voxel_size();
  typename Superquadric<GeomTraits>::Rotation R;
  for(int i = 0; i < 3; ++i)
    for(int j = 0; j < 3; ++j) R[std::size_t(3 * i + j)] = box.axes(i, j);
  // about 4096 evaluation voxels or more in the union
  int r_eval = labels.resolution();
  while(r_eval % 2 == 0 && r_eval > 16 &&
        voxels.size() > std::size_t(4096) * std::size_t(labels.resolution() / r_eval) * std::size_t(labels.resolution() / r_eval) * std::size_t(labels.resolution() / r_eval) * 8)
    r_eval /= 2;
  double best_iou = 0.;
  for(double e : {0.1, 0.5, 1.})
  {
    std::array<double, 3> scales;
    // the voxels' own half size, and a rounder solid reaches the corners of the box less
    for(int i = 0; i < 3; ++i) scales[std::size_t(i)] = (box.half[i] + 0.5 * h) * (e > 0.5 ? 1.15 : 1.);
    const Superquadric<GeomTraits> sq(scales, e, e, R, Point_3(box.center[0], box.center[1], box.center[2]));
    // the voxels it covers beyond the union and every neutral voxel are wrong: a bound on its IoU
    const double union_size = double(voxels.size()), covered = sq.volume() / (h * h * h);
    const double bound = union_size / (union_size + (std::max)(0., covered - union_size - double(neutral_voxels)));
    if(bound < minimum_iou) continue;
    const double iou = voxel_iou(sq, labels, distance, in_set, voxels.size(), r_eval);
    if(iou > best_iou) best_iou = iou, best = sq;
  }
  return best_iou;
}

// The rotation of a superquadric as a matrix.
template <typename GeomTraits>
Eigen::Matrix3d rotation_matrix(const Superquadric<GeomTraits>& sq)
{
  const auto R = sq.rotation();
  Eigen::Matrix3d m;
  for(int i = 0; i < 3; ++i)
    for(int j = 0; j < 3; ++j) m(i, j) = R[std::size_t(3 * i + j)];
  return m;
}

// Per pair of primitives whose claimed voxels both lie in the 26-neighbourhood of a surface voxel
// (Flow or Freeze): the number of such surface voxels and how many are Freeze.
inline std::map<std::pair<std::int32_t, std::int32_t>, std::array<std::size_t, 2> >
primitive_interfaces(const Voxel_grid<std::int32_t>& labels, const Voxel_grid<Voxel_class>& classes)
{
  std::map<std::pair<std::int32_t, std::int32_t>, std::array<std::size_t, 2> > out;
  const int r = labels.resolution();
  std::vector<std::int32_t> near;
  for(int k = 0; k < r; ++k)
    for(int j = 0; j < r; ++j)
      for(int i = 0; i < r; ++i)
      {
        const Voxel_class c = classes(i, j, k);
        if(c == Voxel_class::EMPTY) continue;
        near.clear();
        for(int z = (std::max)(k - 1, 0); z <= (std::min)(k + 1, r - 1); ++z)
          for(int y = (std::max)(j - 1, 0); y <= (std::min)(j + 1, r - 1); ++y)
            for(int x = (std::max)(i - 1, 0); x <= (std::min)(i + 1, r - 1); ++x)
              if(labels(x, y, z) >= 0) near.push_back(labels(x, y, z));
        std::sort(near.begin(), near.end());
        near.erase(std::unique(near.begin(), near.end()), near.end());
        for(std::size_t a = 0; a < near.size(); ++a)
          for(std::size_t b = a + 1; b < near.size(); ++b)
          {
            std::array<std::size_t, 2>& n = out[std::make_pair(near[a], near[b])];
            ++n[0];
            if(c == Voxel_class::FREEZE) ++n[1];
          }
      }
  return out;
}


// Greedy agglomeration: the two adjacent groups of primitives whose union one superquadric
// explains best (voxel IoU) are merged while that IoU is at least `minimum_iou`; groups whose
// common surface voxels are more than `maximum_freeze` Freeze never merge (a boundary the prior
// saw). Returns the group (smallest member) of each primitive and the superquadric of each group.
template <typename GeomTraits>
std::vector<std::size_t> agglomerate_primitives(const Superquadric_fitting_result<GeomTraits>& fit,
                                                const Voxel_grid<Voxel_class>& classes,
                                                const Voxel_grid<double>& distance, double minimum_iou,
                                                double maximum_freeze, std::vector<Superquadric<GeomTraits> >& sq)
{
  typedef std::pair<std::size_t, std::size_t> Pair;
  const std::size_t K = fit.primitives.size();
  std::vector<std::size_t> group_of(K);
  std::vector<std::vector<std::size_t> > members(K), voxels(fit.claimed_voxels);
  for(std::size_t k = 0; k < K; ++k) group_of[k] = k, members[k].assign(1, k);
  sq = fit.primitives;
  std::size_t neutral = 0; // unclaimed voxels inside the shape
  for(std::size_t v = 0; v < fit.labels.size(); ++v) neutral += fit.labels[v] < 0 && distance[v] <= 0.;
  std::map<Pair, std::array<std::size_t, 2> > link; // surface voxels, Freeze ones
  for(const auto& i : primitive_interfaces(fit.labels, classes))
    link[Pair(std::size_t(i.first.first), std::size_t(i.first.second))] = i.second;
  std::map<Pair, std::pair<double, Superquadric<GeomTraits> > > score; // cached per pair of groups
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
        std::vector<std::size_t> u(voxels[a]);
        u.insert(u.end(), voxels[b].begin(), voxels[b].end());
        std::vector<Eigen::Matrix3d> axes; // of the largest primitive of each group
        for(std::size_t g : {a, b})
        {
          std::size_t largest = members[g].front();
          for(std::size_t m : members[g])
            if(fit.claimed_voxels[m].size() > fit.claimed_voxels[largest].size()) largest = m;
          axes.push_back(rotation_matrix(fit.primitives[largest]));
        }
        Superquadric<GeomTraits> s = sq[a];
        const double iou = best_union_superquadric(
            u, fit.labels, distance, [&](std::size_t k) { return group_of[k] == a || group_of[k] == b; }, axes,
            neutral, minimum_iou, s);
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
    voxels[a].insert(voxels[a].end(), voxels[b].begin(), voxels[b].end());
    voxels[b].clear();
    std::map<Pair, std::array<std::size_t, 2> > relinked;
    for(const auto& l : link)
    {
      Pair p(l.first.first == b ? a : l.first.first, l.first.second == b ? a : l.first.second);
      if(p.first == p.second) continue;
      if(p.first > p.second) std::swap(p.first, p.second);
      std::array<std::size_t, 2>& n = relinked[p];
      n[0] += l.second[0];
      n[1] += l.second[1];
    }
    link.swap(relinked);
    for(auto it = score.begin(); it != score.end();)
      it = (it->first.first == a || it->first.second == a || it->first.first == b || it->first.second == b)
             ? score.erase(it) : std::next(it);
  }
  return group_of;
}

// Replaces each group of primitives of `agglomerate_primitives()` by its superquadric in `fit`.
template <typename GeomTraits>
void merge_explained_primitives(Superquadric_fitting_result<GeomTraits>& fit, const Voxel_grid<Voxel_class>& classes,
                                const Voxel_grid<double>& distance, double minimum_iou, double maximum_freeze)
{
  const std::size_t K = fit.primitives.size();
  if(K < 2) return;
  std::vector<Superquadric<GeomTraits> > sq;
  const std::vector<std::size_t> group_of = agglomerate_primitives(fit, classes, distance, minimum_iou, maximum_freeze, sq);
  std::vector<std::size_t> index(K, K), representative(K, K); // new index of each group; its largest member
  std::size_t n = 0;
  for(std::size_t k = 0; k < K; ++k)
  {
    const std::size_t g = group_of[k];
    if(index[g] == K) index[g] = n++;
    if(representative[g] == K || fit.claimed_voxels[k].size() > fit.claimed_voxels[representative[g]].size())
      representative[g] = k;
  }
  if(n == K) return;
  Superquadric_fitting_result<GeomTraits> out(fit);
  out.primitives.assign(n, Superquadric<GeomTraits>());
  out.claimed_voxels.assign(n, std::vector<std::size_t>());
  for(std::size_t k = 0; k < K; ++k)
  {
    const std::size_t g = group_of[k], i = index[g];
    out.claimed_voxels[i].insert(out.claimed_voxels[i].end(), fit.claimed_voxels[k].begin(), fit.claimed_voxels[k].end());
    if(representative[g] != k) continue;
    out.primitives[i] = sq[g];
    out.stage_resolution[i] = fit.stage_resolution[k];
    out.body_seeded[i] = fit.body_seeded[k];
    out.seed_voxel[i] = fit.seed_voxel[k];
    out.semi_axis_scale[i] = fit.semi_axis_scale[k];
    out.fit_cost[i] = fit.fit_cost[k];
  }
  out.stage_resolution.resize(n);
  out.body_seeded.resize(n);
  out.seed_voxel.resize(n);
  out.semi_axis_scale.resize(n);
  out.fit_cost.resize(n);
  out.input_primitives.clear();
  for(std::size_t i = 0; i < n; ++i)
  {
    std::sort(out.claimed_voxels[i].begin(), out.claimed_voxels[i].end());
    out.input_primitives.push_back(out.primitives[i].in_input_coordinates(fit.normalization));
  }
  for(std::size_t v = 0; v < out.labels.size(); ++v)
    if(out.labels[v] >= 0) out.labels[v] = std::int32_t(index[group_of[std::size_t(out.labels[v])]]);
  fit = std::move(out);
}

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_PRIMITIVE_MERGING_H
