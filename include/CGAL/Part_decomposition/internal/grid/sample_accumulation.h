// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_SAMPLE_ACCUMULATION_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_SAMPLE_ACCUMULATION_H

#include <CGAL/Part_decomposition/internal/toolbox/toolbox.h>
#include <CGAL/Part_decomposition/internal/toolbox/triangle_arrays.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

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

// A piece of a face cut by bisection, with its share of the face's area.
struct Face_piece
{
  std::array<Vec3, 3> corners;
  double weight;
};

inline std::uint32_t linear_voxel_index(int i, int j, int k, int r)
{
  const std::uint32_t ur = std::uint32_t(r);
  return std::uint32_t(i) + ur * (std::uint32_t(j) + ur * std::uint32_t(k));
}

// The longest edge of a triangle: its first corner (it runs to the next one) and its length in
// voxels of the rf grid.
inline std::pair<int, double> longest_edge(const std::array<Vec3, 3>& corners, int rf)
{
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
}

// Along an axis where the three corners lie in one slab of voxels with a margin of 1e-9 voxel,
// every sample does too (a sample's rounding error is ~1e-16 relative): `fixed[x]` is that slab,
// -1 elsewhere. Returns whether the face lies in a single voxel.
inline bool fixed_voxel_slabs(const Vec3& a, const Vec3& b, const Vec3& d, int rf, int fixed[3])
{
  bool all_fixed = true;
  for(int x = 0; x < 3; ++x)
  {
    const double ta = (a[x] + 0.5) * double(rf), tb = (b[x] + 0.5) * double(rf), td = (d[x] + 0.5) * double(rf);
    const double lo = (std::min)((std::min)(ta, tb), td) - 1e-9, hi = (std::max)((std::max)(ta, tb), td) + 1e-9;
    const int c0 = voxel_of_scaled(lo, rf);
    fixed[x] = c0 == voxel_of_scaled(hi, rf) ? c0 : -1;
    all_fixed = all_fixed && fixed[x] >= 0;
  }
  return all_fixed;
}

// Cuts the face (a, b, d) by longest-edge bisection, depth first, until the samples of each piece
// are at most half a voxel apart (`dense_edge`); `weighted` receives the voxel of every sample of
// every piece with the piece's weight.
inline void sample_bisected_face(const Vec3& a, const Vec3& b, const Vec3& d,
                                 const std::vector<std::array<double, 3> >& barycentric, int rf,
                                 double dense_edge, std::vector<Face_piece>& pieces,
                                 std::vector<std::pair<std::uint32_t, double> >& weighted)
{
  // A piece never gets smaller than 2^-30 of its face: the cut is bounded for any triangle.
  const double minimum_piece_weight = std::ldexp(1., -30);
  pieces.clear();
  weighted.clear();
  pieces.push_back(Face_piece{{{a, b, d}}, 1.});
  while(!pieces.empty())
  {
    const Face_piece piece = pieces.back();
    pieces.pop_back();
    const std::pair<int, double> edge = longest_edge(piece.corners, rf);
    if(edge.second > dense_edge && piece.weight > minimum_piece_weight)
    {
      // split the longest edge at its midpoint: two halves of equal area
      const int e = edge.first;
      const Vec3& u = piece.corners[e];
      const Vec3& v = piece.corners[(e + 1) % 3];
      const Vec3& o = piece.corners[(e + 2) % 3];
      const Vec3 mid = {{0.5 * (u[0] + v[0]), 0.5 * (u[1] + v[1]), 0.5 * (u[2] + v[2])}};
      pieces.push_back(Face_piece{{{u, mid, o}}, 0.5 * piece.weight});
      pieces.push_back(Face_piece{{{mid, v, o}}, 0.5 * piece.weight});
      continue;
    }
    const Vec3 &p = piece.corners[0], &q = piece.corners[1], &t = piece.corners[2];
    for(const auto& w : barycentric)
    {
      const int i = fast_voxel_coordinate(w[0] * p[0] + w[1] * q[0] + w[2] * t[0], rf);
      const int j = fast_voxel_coordinate(w[0] * p[1] + w[1] * q[1] + w[2] * t[1], rf);
      const int k = fast_voxel_coordinate(w[0] * p[2] + w[1] * q[2] + w[2] * t[2], rf);
      weighted.push_back(std::make_pair(linear_voxel_index(i, j, k, rf), piece.weight));
    }
  }
}

// The entries of face f from its weighted samples: per voxel, the summed weight rounded to the
// nearest integer, at least 1 (so every voxel the face reaches is active), in voxel order.
inline void append_weighted_counts(std::uint32_t f, std::vector<std::pair<std::uint32_t, double> >& weighted,
                                   std::vector<Face_voxel_count>& out)
{
  std::sort(weighted.begin(), weighted.end());
  for(std::size_t s = 0; s < weighted.size();)
  {
    double total = 0.;
    std::size_t e = s;
    for(; e < weighted.size() && weighted[e].first == weighted[s].first; ++e) total += weighted[e].second;
    const double rounded = std::floor(total + 0.5);
    out.push_back(Face_voxel_count{f, weighted[s].first, rounded < 1. ? 1u : std::uint32_t(rounded)});
    s = e;
  }
}

// The entries of face f from its own samples: one per distinct voxel, in order of first sample.
inline void append_sample_counts(std::uint32_t f, const Vec3& a, const Vec3& b, const Vec3& d, const int fixed[3],
                                 const std::vector<std::array<double, 3> >& barycentric, int rf,
                                 std::vector<std::uint32_t>& voxel, std::vector<std::uint32_t>& count,
                                 std::vector<Face_voxel_count>& out)
{
  std::size_t distinct = 0;
  for(const auto& w : barycentric)
  {
    const int i = fixed[0] >= 0 ? fixed[0] : fast_voxel_coordinate(w[0] * a[0] + w[1] * b[0] + w[2] * d[0], rf);
    const int j = fixed[1] >= 0 ? fixed[1] : fast_voxel_coordinate(w[0] * a[1] + w[1] * b[1] + w[2] * d[1], rf);
    const int k = fixed[2] >= 0 ? fixed[2] : fast_voxel_coordinate(w[0] * a[2] + w[1] * b[2] + w[2] * d[2], rf);
    const std::uint32_t idx = linear_voxel_index(i, j, k, rf);
    std::size_t s = 0;
    while(s < distinct && voxel[s] != idx) ++s;
    if(s == distinct)
    {
      voxel[distinct] = idx;
      count[distinct++] = 0;
    }
    ++count[s];
  }
  for(std::size_t s = 0; s < distinct; ++s) out.push_back(Face_voxel_count{f, voxel[s], count[s]});
}

// The (face, voxel, count) entries of the faces [begin, end) at the finest resolution `rf`.
// A face within one voxel puts all its samples there. A face whose samples would lie more than
// half a voxel apart (the large, long triangles of CAD meshes) would leave holes in the
// occupancy, through which the exterior flood fill of the zones enters the shape: it is cut by
// longest-edge bisection (sample_bisected_face()) and counts its rounded weights per voxel
// (append_weighted_counts()), at least 1 in every voxel it reaches.
inline void list_face_voxel_counts(const std::vector<Vec3>& unit_points,
                                   const std::vector<std::array<std::uint32_t, 3> >& faces,
                                   const std::vector<std::array<double, 3> >& barycentric, int rf,
                                   std::size_t begin, std::size_t end, std::vector<Face_voxel_count>& out)
{
  const std::size_t ns = barycentric.size();
  // Samples at most half a voxel apart: n per side over an edge of at most n/2 voxels.
  const double dense_edge = 0.5 * std::sqrt(double(ns));
  out.reserve(2 * (end - begin));
  std::vector<std::uint32_t> voxel(ns), count(ns);
  std::vector<Face_piece> pieces;
  std::vector<std::pair<std::uint32_t, double> > weighted;
  for(std::size_t f = begin; f < end; ++f)
  {
    const Vec3& a = unit_points[faces[f][0]];
    const Vec3& b = unit_points[faces[f][1]];
    const Vec3& d = unit_points[faces[f][2]];
    int fixed[3];
    if(fixed_voxel_slabs(a, b, d, rf, fixed))
      out.push_back(Face_voxel_count{std::uint32_t(f), linear_voxel_index(fixed[0], fixed[1], fixed[2], rf),
                                     std::uint32_t(ns)});
    else if(longest_edge({{a, b, d}}, rf).second > dense_edge)
    {
      sample_bisected_face(a, b, d, barycentric, rf, dense_edge, pieces, weighted);
      append_weighted_counts(std::uint32_t(f), weighted, out);
    }
    else
      append_sample_counts(std::uint32_t(f), a, b, d, fixed, barycentric, rf, voxel, count, out);
  }
}

// Adds the entries, in order, to the sums of every resolution.
inline void add_counts_to_sums(const std::vector<std::vector<Face_voxel_count> >& blocks,
                               const std::vector<double>& c, const std::vector<double>& phi, int rf,
                               std::vector<Voxel_sums>& sums)
{
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

// Bins the samples of every face at the finest resolution `rf` and accumulates the four sums at
// every resolution of `sums` in one pass. Samples are never stored: each block of faces lists
// its (face, voxel, count) entries, and the blocks are merged in face order, so the sums have the
// same bits for any number of threads. A coarser voxel index is the finest one shifted: with
// r = rf / 2^s, floor((p+0.5) r) = floor((p+0.5) rf) >> s exactly (scaling by a power of two is
// exact), including the clamp of p = +0.5 to the last voxel. `sampled` (a Voxel_grid<std::uint8_t>),
// if not null, receives the voxels of resolution `rf` that hold a sample.
template <typename ConcurrencyTag, typename SampledGrid>
void accumulate_samples(const std::vector<Vec3>& unit_points,
                        const std::vector<std::array<std::uint32_t, 3> >& faces,
                        const std::vector<double>& c, const std::vector<double>& phi,
                        const std::vector<std::array<double, 3> >& barycentric, int rf,
                        std::vector<Voxel_sums>& sums, SampledGrid* sampled)
{
  const std::size_t nf = faces.size();
  const std::size_t block_size = 1024;
  std::vector<std::vector<Face_voxel_count> > blocks((nf + block_size - 1) / block_size);
  for_each_block<ConcurrencyTag>(nf, block_size, [&](std::size_t begin, std::size_t end) {
    list_face_voxel_counts(unit_points, faces, barycentric, rf, begin, end, blocks[begin / block_size]);
  });
  add_counts_to_sums(blocks, c, phi, rf, sums);
  if(sampled == nullptr) return;
  *sampled = SampledGrid(rf, 0);
  for(const std::vector<Face_voxel_count>& block : blocks)
    for(const Face_voxel_count& e : block) (*sampled)[e.voxel] = 1;
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
