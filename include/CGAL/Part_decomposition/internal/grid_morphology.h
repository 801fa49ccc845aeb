// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_GRID_MORPHOLOGY_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_GRID_MORPHOLOGY_H

#include <CGAL/Part_decomposition/Voxel_grid.h>
#include <CGAL/Part_decomposition/internal/toolbox.h>

#include <CGAL/assertions.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

// Small reusable operations on dense voxel masks (`Voxel_grid<std::uint8_t>`, nonzero = in the
// mask). Neighbourhoods are 6-connected (face neighbours). Distances are in voxel units, measured
// between voxel centres. Every function is deterministic; the parallel variants give results
// identical to the sequential ones.

namespace CGAL {
namespace Part_decomposition {
namespace internal {

/// The value of a squared distance transform where no feature exists.
inline double no_feature_distance() { return std::numeric_limits<double>::infinity(); }

/// The nearest-feature index reported for the virtual features outside the grid.
inline std::size_t outside_grid_feature() { return std::numeric_limits<std::size_t>::max(); }

// Scratch buffers of the 1D lower envelope, sized once per chunk of lines.
struct Envelope_buffers
{
  std::vector<double> f, d, z;
  std::vector<int> v, site, nearest;
  explicit Envelope_buffers(int n)
    : f(n), d(n), z(n + 3), v(n + 2), site(n + 2), nearest(n)
  {}
};

// Felzenszwalb-Huttenlocher 1D squared distance: d[q] = min_p (q - p)^2 + f[p] over the finite
// f[p], p in [0, n); with `border_sites`, two more sites of value 0 at p = -1 and p = n. Writes the
// arg min into `nearest` (-2 for a border site, -1 if there is no site). Linear time.
inline void lower_envelope_1d(int n, bool border_sites, Envelope_buffers& b)
{
  auto value_at = [&](int p) -> double { return (p < 0 || p >= n) ? 0. : b.f[p]; };
  // The finite sites, in increasing position.
  int m = 0;
  if(border_sites) b.site[m++] = -1;
  for(int p = 0; p < n; ++p)
    if(b.f[p] != no_feature_distance()) b.site[m++] = p;
  if(border_sites) b.site[m++] = n;
  if(m == 0)
  {
    for(int q = 0; q < n; ++q)
    {
      b.d[q] = no_feature_distance();
      b.nearest[q] = -1;
    }
    return;
  }
  // Lower envelope of the parabolas y = (x - p)^2 + f(p); z[0] = -inf stops the pops.
  int k = 0;
  b.v[0] = b.site[0];
  b.z[0] = -no_feature_distance();
  b.z[1] = no_feature_distance();
  for(int t = 1; t < m; ++t)
  {
    const int q = b.site[t];
    const double hq = value_at(q) + double(q) * double(q);
    double s = 0.;
    for(;;)
    {
      const int p = b.v[k];
      s = (hq - (value_at(p) + double(p) * double(p))) / (2. * double(q - p));
      if(s > b.z[k]) break;
      --k;
    }
    ++k;
    b.v[k] = q;
    b.z[k] = s;
    b.z[k + 1] = no_feature_distance();
  }
  int j = 0;
  for(int q = 0; q < n; ++q)
  {
    while(b.z[j + 1] < double(q)) ++j;
    const int p = b.v[j];
    b.d[q] = double(q - p) * double(q - p) + value_at(p);
    b.nearest[q] = (p < 0 || p >= n) ? -2 : p;
  }
}

// The same as `lower_envelope_1d()` when every f[p] is 0 or infinite (the first pass over a mask):
// two sweeps for the nearest site on each side.
inline void binary_distance_1d(int n, bool border_sites, Envelope_buffers& b)
{
  const int none = std::numeric_limits<int>::min() / 2;
  int last = border_sites ? -1 : none;
  for(int q = 0; q < n; ++q)
  {
    if(b.f[q] == 0.) last = q;
    b.v[q] = last; // nearest site at or before q
  }
  int next = border_sites ? n : std::numeric_limits<int>::max() / 2;
  for(int q = n - 1; q >= 0; --q)
  {
    if(b.f[q] == 0.) next = q;
    const int before = b.v[q];
    const double db = before == none ? no_feature_distance() : double(q - before);
    const double da = next >= std::numeric_limits<int>::max() / 2 ? no_feature_distance() : double(next - q);
    if(db == no_feature_distance() && da == no_feature_distance())
    {
      b.d[q] = no_feature_distance();
      b.nearest[q] = -1;
      continue;
    }
    const int p = db <= da ? before : next;
    b.d[q] = double(q - p) * double(q - p);
    b.nearest[q] = (p < 0 || p >= n) ? -2 : p;
  }
}

/*
Exact squared Euclidean distance transform, in voxel units squared, from every voxel centre to
the nearest voxel centre where `feature` is nonzero: separable lower envelopes of parabolas
(Felzenszwalb-Huttenlocher), three linear passes. Values are integers stored in doubles (exact),
`no_feature_distance()` (+infinity) if there is no feature at all.

With `grid_border_is_feature`, the layer of voxels just outside the grid counts as feature
(distance to the complement of a mask when the grid's outside is not part of the mask).
If `nearest_feature` is not null it receives, per voxel, the linear index of one nearest feature
voxel, `outside_grid_feature()` for the virtual border layer, or `outside_grid_feature() - 1` if
there is no feature.
*/
template <typename ConcurrencyTag = CGAL::Sequential_tag>
Voxel_grid<double> squared_distance_transform(const Voxel_grid<std::uint8_t>& feature,
                                              bool grid_border_is_feature = false,
                                              Voxel_grid<std::size_t>* nearest_feature = nullptr)
{
  const int r = feature.resolution();
  Voxel_grid<double> dist(r, no_feature_distance());
  for(std::size_t i = 0; i < feature.size(); ++i)
    if(feature[i] != 0) dist[i] = 0.;
  if(r == 0) return dist;
  const bool track = nearest_feature != nullptr;
  if(track)
  {
    *nearest_feature = Voxel_grid<std::size_t>(r, outside_grid_feature() - 1);
    for(std::size_t i = 0; i < feature.size(); ++i)
      if(feature[i] != 0) (*nearest_feature)[i] = i;
  }
  const std::size_t R = std::size_t(r);
  const std::size_t stride[3] = {1, R, R * R};
  for(int axis = 0; axis < 3; ++axis)
  {
    const std::size_t s = stride[axis];
    // the other two axes, the one of smaller stride varying faster: lines taken one after the
    // other lie side by side in memory and share cache lines (4x faster along the middle axis)
    const std::size_t other1 = axis == 0 ? stride[1] : stride[0], other2 = axis == 2 ? stride[1] : stride[2];
    for_each_range<ConcurrencyTag>(R * R, [&](std::size_t begin, std::size_t end) {
      Envelope_buffers b(r);
      std::vector<std::size_t> line_nearest(track ? R : 0);
      for(std::size_t line = begin; line < end; ++line)
      {
        const std::size_t base = (line % R) * other1 + (line / R) * other2;
        for(int q = 0; q < r; ++q) b.f[q] = dist[base + std::size_t(q) * s];
        if(track)
          for(int q = 0; q < r; ++q) line_nearest[q] = (*nearest_feature)[base + std::size_t(q) * s];
        if(axis == 0)
          binary_distance_1d(r, grid_border_is_feature, b);
        else
          lower_envelope_1d(r, grid_border_is_feature, b);
        for(int q = 0; q < r; ++q)
        {
          const std::size_t idx = base + std::size_t(q) * s;
          dist[idx] = b.d[q];
          if(track)
            (*nearest_feature)[idx] = b.nearest[q] == -2   ? outside_grid_feature()
                                      : b.nearest[q] == -1 ? outside_grid_feature() - 1
                                                           : line_nearest[std::size_t(b.nearest[q])];
        }
      }
    });
  }
  return dist;
}

/*
Lowers the squared distance transform `sq_distance` (as computed by `squared_distance_transform()`
without border features) after the voxels `new_features` became features, so that it equals the
transform recomputed from scratch, exactly. Only the sub-box that the new features can influence is
processed: the box of the new features grown by the largest finite old distance.
*/
template <typename ConcurrencyTag = CGAL::Sequential_tag>
void add_features_to_squared_distance_transform(Voxel_grid<double>& sq_distance,
                                                const std::vector<std::size_t>& new_features)
{
  const int r = sq_distance.resolution();
  if(new_features.empty() || r == 0) return;
  std::array<int, 3> lo = {{r, r, r}}, hi = {{-1, -1, -1}};
  for(std::size_t idx : new_features)
  {
    CGAL_precondition(idx < sq_distance.size());
    const std::array<int, 3> c = sq_distance.coordinates(idx);
    for(int a = 0; a < 3; ++a)
    {
      lo[a] = (std::min)(lo[a], c[a]);
      hi[a] = (std::max)(hi[a], c[a]);
    }
  }
  double max_old = 0.;
  for(double v : sq_distance.values()) max_old = (std::max)(max_old, v);
  const int grow = (max_old == no_feature_distance()) ? r : int(std::ceil(std::sqrt(max_old)));
  for(int a = 0; a < 3; ++a)
  {
    lo[a] = (std::max)(0, lo[a] - grow);
    hi[a] = (std::min)(r - 1, hi[a] + grow);
  }
  const int n[3] = {hi[0] - lo[0] + 1, hi[1] - lo[1] + 1, hi[2] - lo[2] + 1};
  const std::size_t box_size = std::size_t(n[0]) * std::size_t(n[1]) * std::size_t(n[2]);
  auto box_index = [&](int i, int j, int k) {
    return std::size_t(i) + std::size_t(n[0]) * (std::size_t(j) + std::size_t(n[1]) * std::size_t(k));
  };
  std::vector<double> local(box_size, no_feature_distance());
  for(std::size_t idx : new_features)
  {
    const std::array<int, 3> c = sq_distance.coordinates(idx);
    local[box_index(c[0] - lo[0], c[1] - lo[1], c[2] - lo[2])] = 0.;
  }
  // Features inside the box only: exact for every voxel of the box since all new features are in it.
  const std::size_t stride[3] = {1, std::size_t(n[0]), std::size_t(n[0]) * std::size_t(n[1])};
  for(int axis = 0; axis < 3; ++axis)
  {
    const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
    const int len = n[axis];
    const std::size_t lines = std::size_t(n[a1]) * std::size_t(n[a2]);
    for_each_range<ConcurrencyTag>(lines, [&](std::size_t begin, std::size_t end) {
      Envelope_buffers b(len);
      for(std::size_t line = begin; line < end; ++line)
      {
        const std::size_t base = (line % std::size_t(n[a1])) * stride[a1] + (line / std::size_t(n[a1])) * stride[a2];
        for(int q = 0; q < len; ++q) b.f[q] = local[base + std::size_t(q) * stride[axis]];
        lower_envelope_1d(len, false, b);
        for(int q = 0; q < len; ++q) local[base + std::size_t(q) * stride[axis]] = b.d[q];
      }
    });
  }
  for(int k = 0; k < n[2]; ++k)
    for(int j = 0; j < n[1]; ++j)
      for(int i = 0; i < n[0]; ++i)
      {
        double& v = sq_distance(i + lo[0], j + lo[1], k + lo[2]);
        v = (std::min)(v, local[box_index(i, j, k)]);
      }
}

/// The mask of the voxels where `mask` is zero.
inline Voxel_grid<std::uint8_t> complement(const Voxel_grid<std::uint8_t>& mask)
{
  Voxel_grid<std::uint8_t> out(mask.resolution());
  for(std::size_t i = 0; i < mask.size(); ++i) out[i] = mask[i] != 0 ? 0 : 1;
  return out;
}

/*
Marks in the returned mask every voxel where `mask` is zero that is 6-connected, through voxels
where `mask` is zero, to a voxel of the grid border (the flood fill of the outside). Voxels of
`mask` are never marked.
*/
inline Voxel_grid<std::uint8_t> border_connected_complement(const Voxel_grid<std::uint8_t>& mask)
{
  const int r = mask.resolution();
  Voxel_grid<std::uint8_t> reached(r, 0);
  std::vector<std::size_t> queue;
  queue.reserve(mask.size() / 4 + 16);
  auto push = [&](std::size_t idx) {
    if(mask[idx] == 0 && reached[idx] == 0)
    {
      reached[idx] = 1;
      queue.push_back(idx);
    }
  };
  for(int k = 0; k < r; ++k)
    for(int j = 0; j < r; ++j)
      for(int i = 0; i < r; ++i)
        if(i == 0 || j == 0 || k == 0 || i == r - 1 || j == r - 1 || k == r - 1)
          push(mask.index(i, j, k));
  const std::size_t R = std::size_t(r);
  for(std::size_t head = 0; head < queue.size(); ++head)
  {
    for_each_face_neighbor(queue[head], R, push);
  }
  return reached;
}

/*
3D hole filling: the mask plus every voxel outside it that is not 6-connected to the grid border
through voxels outside the mask (cavities, the inside of closed shells).
*/
inline Voxel_grid<std::uint8_t> fill_holes(const Voxel_grid<std::uint8_t>& mask)
{
  Voxel_grid<std::uint8_t> out = border_connected_complement(mask);
  for(std::size_t i = 0; i < out.size(); ++i) out[i] = out[i] != 0 ? 0 : 1;
  return out;
}

/*
Euclidean dilation: the voxels whose centre lies within `radius` (voxel units) of the centre of a
voxel of `mask`. `radius = 0` returns the mask itself.
*/
template <typename ConcurrencyTag = CGAL::Sequential_tag>
Voxel_grid<std::uint8_t> dilate(const Voxel_grid<std::uint8_t>& mask, double radius)
{
  CGAL_precondition(radius >= 0.);
  const Voxel_grid<double> d2 = squared_distance_transform<ConcurrencyTag>(mask);
  // Squared distances are integers: the tolerance only absorbs the rounding of radius^2.
  const double limit = radius * radius * (1. + 1e-12) + 1e-9;
  Voxel_grid<std::uint8_t> out(mask.resolution(), 0);
  for(std::size_t i = 0; i < out.size(); ++i) out[i] = d2[i] <= limit ? 1 : 0;
  return out;
}

/*
6-connected components of a mask. `labels` holds -1 outside the mask and the component index
elsewhere; components are numbered in the order of their first voxel in linear-index order.
`sizes` counts their voxels and `centroids` is the mean of their voxel coordinates `(i,j,k)`
(voxel units; the point of the normalized cube is `-0.5 + (c + 0.5) / r` per axis).
*/
struct Grid_components
{
  Voxel_grid<int> labels;
  std::vector<std::size_t> sizes;
  std::vector<std::array<double, 3> > centroids;
  std::size_t size() const { return sizes.size(); }
};

inline Grid_components connected_components(const Voxel_grid<std::uint8_t>& mask)
{
  const int r = mask.resolution();
  const std::size_t R = std::size_t(r);
  Grid_components out;
  out.labels = Voxel_grid<int>(r, -1);
  std::vector<std::size_t> queue;
  for(std::size_t seed = 0; seed < mask.size(); ++seed)
  {
    if(mask[seed] == 0 || out.labels[seed] >= 0) continue;
    const int label = int(out.sizes.size());
    queue.clear();
    queue.push_back(seed);
    out.labels[seed] = label;
    double sum[3] = {0., 0., 0.};
    for(std::size_t head = 0; head < queue.size(); ++head)
    {
      const std::size_t idx = queue[head];
      const std::size_t i = idx % R, j = (idx / R) % R, k = idx / (R * R);
      sum[0] += double(i);
      sum[1] += double(j);
      sum[2] += double(k);
      for_each_face_neighbor(idx, R, [&](std::size_t n) {
        if(mask[n] != 0 && out.labels[n] < 0)
        {
          out.labels[n] = label;
          queue.push_back(n);
        }
      });
    }
    const double n = double(queue.size());
    out.sizes.push_back(queue.size());
    out.centroids.push_back({{sum[0] / n, sum[1] / n, sum[2] / n}});
  }
  return out;
}

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_GRID_MORPHOLOGY_H
