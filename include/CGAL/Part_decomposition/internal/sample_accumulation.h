// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_SAMPLE_ACCUMULATION_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_SAMPLE_ACCUMULATION_H

#include <CGAL/Part_decomposition/Voxel_grid.h>
#include <CGAL/Part_decomposition/input_validation.h>
#include <CGAL/Part_decomposition/normalization.h>
#include <CGAL/Part_decomposition/internal/prior_parallel.h>
#include <CGAL/Part_decomposition/internal/triangle_arrays.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <utility>
#include <vector>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

// Copies any range of 4 numbers (std::array, std::vector, ...) into weights.
template <typename Range>
std::array<double, 4> to_cue_weights(const Range& range)
{
  std::array<double, 4> w{{0., 0., 0., 0.}};
  std::size_t n = 0;
  for(auto it = std::begin(range); it != std::end(range); ++it, ++n)
  {
    if(n >= 4) break;
    w[n] = double(*it);
  }
  if(n != 4 || std::distance(std::begin(range), std::end(range)) != 4)
    throw Invalid_input(Input_error::INVALID_PARAMETER, "cue_weights must hold exactly 4 values");
  for(double x : w)
    if(!std::isfinite(x))
      throw Invalid_input(Input_error::INVALID_PARAMETER, "cue_weights must be finite");
  return w;
}

inline double checked_freeze_ratio(double alpha)
{
  if(!(alpha > 0. && alpha < 1.))
    throw Invalid_input(Input_error::INVALID_PARAMETER, "freeze_ratio must be in (0, 1)");
  return alpha;
}

inline bool is_power_of_two(int r) { return r > 0 && (r & (r - 1)) == 0; }

// The per-voxel sums of one resolution: n, sum c, sum c^2, sum phi.
struct Voxel_sums
{
  int r = 0;
  int shift = 0; // log2(finest / r)
  std::vector<std::uint32_t> n;
  std::vector<double> s1, s2, sphi;
};

// voxel_coordinate(p, r) without std::floor (a libm call on baseline x86-64): for t >= 0
// truncation is floor, and t <= 0 or NaN gives 0 in both.
inline int voxel_of_scaled(double t, int r)
{
  if(!(t > 0.)) return 0;
  if(t >= double(r - 1)) return r - 1;
  return int(t);
}

inline int fast_voxel_coordinate(double p, int r) { return voxel_of_scaled((p + 0.5) * double(r), r); }

// One (face, voxel of the finest grid, number of samples) entry; faces ascending.
struct Face_voxel_count
{
  std::uint32_t face, voxel, count;
};

// Bins the samples of every face at the finest resolution `rf` and accumulates the four sums at
// every resolution of `sums` in one pass. Samples are never stored: each block of faces lists
// its (face, voxel, count) triples, and the blocks are merged in face order, so the sums have the
// same bits for any number of threads. A coarser voxel index is the finest one shifted: with
// r = rf / 2^s, floor((p+0.5) r) = floor((p+0.5) rf) >> s exactly (scaling by a power of two is
// exact), including the clamp of p = +0.5 to the last voxel.
template <typename ConcurrencyTag>
void accumulate_samples(const std::vector<Vec3>& unit_points,
                        const std::vector<std::array<std::uint32_t, 3> >& faces,
                        const std::vector<double>& c, const std::vector<double>& phi,
                        const std::vector<std::array<double, 3> >& barycentric, int rf,
                        std::vector<Voxel_sums>& sums)
{
  const std::size_t nf = faces.size(), ns = barycentric.size();
  // Samples at most half a voxel apart: n per side over an edge of at most n/2 voxels.
  const double dense_edge = 0.5 * std::sqrt(double(ns));
  // A piece never gets smaller than 2^-30 of its face: the cut is bounded for any triangle.
  const double minimum_piece_weight = std::ldexp(1., -30);
  const std::size_t block_size = 1024;
  const std::size_t number_of_blocks = (nf + block_size - 1) / block_size;
  std::vector<std::vector<Face_voxel_count> > blocks(number_of_blocks);
  for_each_block<ConcurrencyTag>(nf, block_size, [&](std::size_t begin, std::size_t end) {
    std::vector<Face_voxel_count>& out = blocks[begin / block_size];
    out.reserve(2 * (end - begin));
    std::vector<std::uint32_t> voxel(ns), count(ns);
    struct Piece
    {
      std::array<Vec3, 3> corners;
      double weight; // share of the face's area
    };
    std::vector<Piece> pieces;
    std::vector<std::pair<std::uint32_t, double> > weighted;
    // the longest edge of a triangle: its first corner (it runs to the next one), its length in voxels
    auto longest_edge = [&](const std::array<Vec3, 3>& corners) {
      int longest = 0;
      double longest2 = -1.;
      for(int e = 0; e < 3; ++e)
      {
        double l2 = 0.;
        for(int x = 0; x < 3; ++x)
        {
          const double dx = corners[e][x] - corners[(e + 1) % 3][x];
          l2 += dx * dx;
        }
        if(l2 > longest2) longest = e, longest2 = l2;
      }
      return std::make_pair(longest, std::sqrt(longest2) * double(rf));
    };
    for(std::size_t f = begin; f < end; ++f)
    {
      const Vec3& a = unit_points[faces[f][0]];
      const Vec3& b = unit_points[faces[f][1]];
      const Vec3& d = unit_points[faces[f][2]];
      // Along an axis where the three corners lie in one slab of voxels with a margin of 1e-9
      // voxel, every sample does too (a sample's rounding error is ~1e-16 relative): no binning.
      int fixed[3];
      bool all_fixed = true;
      for(int x = 0; x < 3; ++x)
      {
        const double ta = (a[x] + 0.5) * double(rf), tb = (b[x] + 0.5) * double(rf), td = (d[x] + 0.5) * double(rf);
        const double lo = (std::min)((std::min)(ta, tb), td) - 1e-9, hi = (std::max)((std::max)(ta, tb), td) + 1e-9;
        const int c0 = voxel_of_scaled(lo, rf);
        fixed[x] = c0 == voxel_of_scaled(hi, rf) ? c0 : -1;
        all_fixed = all_fixed && fixed[x] >= 0;
      }
      const std::uint32_t urf = std::uint32_t(rf);
      if(all_fixed)
      {
        out.push_back(Face_voxel_count{std::uint32_t(f),
                                       std::uint32_t(fixed[0]) + urf * (std::uint32_t(fixed[1]) + urf * std::uint32_t(fixed[2])),
                                       std::uint32_t(ns)});
        continue;
      }
      // A face whose samples would lie more than half a voxel apart (the large, long triangles of
      // CAD meshes) would leave holes in the occupancy, through which the exterior flood fill of
      // the zones enters the shape. It is cut by longest-edge bisection until its samples are
      // dense enough; each piece gets the same barycentric samples, weighted by its share of the
      // face's area, so that the face still counts `ns` samples in total (at least one in every
      // voxel it reaches).
      if(longest_edge({{a, b, d}}).second > dense_edge)
      {
        pieces.clear();
        weighted.clear();
        pieces.push_back(Piece{{{a, b, d}}, 1.});
        while(!pieces.empty())
        {
          const Piece piece = pieces.back();
          pieces.pop_back();
          const std::pair<int, double> edge = longest_edge(piece.corners);
          if(edge.second > dense_edge && piece.weight > minimum_piece_weight)
          {
            // split the longest edge at its midpoint: two halves of equal area
            const int e = edge.first;
            const Vec3& u = piece.corners[e];
            const Vec3& v = piece.corners[(e + 1) % 3];
            const Vec3& o = piece.corners[(e + 2) % 3];
            const Vec3 mid = {{0.5 * (u[0] + v[0]), 0.5 * (u[1] + v[1]), 0.5 * (u[2] + v[2])}};
            pieces.push_back(Piece{{{u, mid, o}}, 0.5 * piece.weight});
            pieces.push_back(Piece{{{mid, v, o}}, 0.5 * piece.weight});
            continue;
          }
          const Vec3 &p = piece.corners[0], &q = piece.corners[1], &t = piece.corners[2];
          for(const auto& w : barycentric)
          {
            const int i = fast_voxel_coordinate(w[0] * p[0] + w[1] * q[0] + w[2] * t[0], rf);
            const int j = fast_voxel_coordinate(w[0] * p[1] + w[1] * q[1] + w[2] * t[1], rf);
            const int k = fast_voxel_coordinate(w[0] * p[2] + w[1] * q[2] + w[2] * t[2], rf);
            weighted.push_back(std::make_pair(std::uint32_t(i) + urf * (std::uint32_t(j) + urf * std::uint32_t(k)),
                                              piece.weight));
          }
        }
        std::sort(weighted.begin(), weighted.end());
        for(std::size_t s = 0; s < weighted.size();)
        {
          double total = 0.;
          std::size_t e = s;
          for(; e < weighted.size() && weighted[e].first == weighted[s].first; ++e) total += weighted[e].second;
          const double rounded = std::floor(total + 0.5);
          out.push_back(Face_voxel_count{std::uint32_t(f), weighted[s].first,
                                         rounded < 1. ? 1u : std::uint32_t(rounded)});
          s = e;
        }
        continue;
      }
      std::size_t distinct = 0;
      for(const auto& w : barycentric)
      {
        const int i = fixed[0] >= 0 ? fixed[0] : fast_voxel_coordinate(w[0] * a[0] + w[1] * b[0] + w[2] * d[0], rf);
        const int j = fixed[1] >= 0 ? fixed[1] : fast_voxel_coordinate(w[0] * a[1] + w[1] * b[1] + w[2] * d[1], rf);
        const int k = fixed[2] >= 0 ? fixed[2] : fast_voxel_coordinate(w[0] * a[2] + w[1] * b[2] + w[2] * d[2], rf);
        const std::uint32_t idx = std::uint32_t(i) + urf * (std::uint32_t(j) + urf * std::uint32_t(k));
        std::size_t s = 0;
        while(s < distinct && voxel[s] != idx) ++s;
        if(s == distinct)
        {
          voxel[distinct] = idx;
          count[distinct++] = 0;
        }
        ++count[s];
      }
      for(std::size_t s = 0; s < distinct; ++s)
        out.push_back(Face_voxel_count{std::uint32_t(f), voxel[s], count[s]});
    }
  });

  for(Voxel_sums& vs : sums)
  {
    const std::size_t size = std::size_t(vs.r) * std::size_t(vs.r) * std::size_t(vs.r);
    vs.n.assign(size, 0);
    vs.s1.assign(size, 0.);
    vs.s2.assign(size, 0.);
    vs.sphi.assign(size, 0.);
  }
  const std::uint32_t urf = std::uint32_t(rf);
  for(const auto& block : blocks)
    for(const Face_voxel_count& e : block)
    {
      const std::uint32_t i = e.voxel % urf, j = (e.voxel / urf) % urf, k = e.voxel / (urf * urf);
      const double cf = c[e.face], pf = phi[e.face], n = double(e.count);
      for(Voxel_sums& vs : sums)
      {
        const std::uint32_t r = std::uint32_t(vs.r);
        const std::size_t idx = std::size_t(i >> vs.shift) +
                                std::size_t(r) * (std::size_t(j >> vs.shift) + std::size_t(r) * std::size_t(k >> vs.shift));
        vs.n[idx] += e.count;
        vs.s1[idx] += n * cf;
        vs.s2[idx] += n * (cf * cf);
        vs.sphi[idx] += n * pf;
      }
    }
}

// Gradient magnitude of the dense field at (i,j,k), unit spacing: central differences
// (f[i+1]-f[i-1])/2 inside, one-sided f[1]-f[0] and f[r-1]-f[r-2] at the border, 0 if r = 1.
inline double dense_gradient_norm(const std::vector<double>& f, int r, int i, int j, int k)
{
  if(r < 2) return 0.;
  const std::size_t sx = 1, sy = std::size_t(r), sz = std::size_t(r) * std::size_t(r);
  const std::size_t idx = std::size_t(i) * sx + std::size_t(j) * sy + std::size_t(k) * sz;
  auto partial = [&](int x, std::size_t stride) {
    if(x == 0) return f[idx + stride] - f[idx];
    if(x == r - 1) return f[idx] - f[idx - stride];
    return 0.5 * (f[idx + stride] - f[idx - stride]);
  };
  const double gx = partial(i, sx), gy = partial(j, sy), gz = partial(k, sz);
  return std::sqrt(gx * gx + gy * gy + gz * gz);
}

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_SAMPLE_ACCUMULATION_H
