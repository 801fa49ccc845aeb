// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_MESH_VOXELIZATION_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_MESH_VOXELIZATION_H

#include <CGAL/Part_decomposition/Voxel_grid.h>
#include <CGAL/Part_decomposition/normalization.h>
#include <CGAL/Part_decomposition/internal/grid_morphology.h>
#include <CGAL/Part_decomposition/internal/toolbox.h>
#include <CGAL/Part_decomposition/internal/winding_number.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

// The mesh as a triangle soup in the normalized cube, the voxels its triangles touch, and exact
// ray crossings along the grid rows: the geometric building blocks of the TSDF.

namespace CGAL {
namespace Part_decomposition {
namespace internal {

// The triangles of `tm` in normalized coordinates, in the iteration order of `faces(tm)`. Every
// vertex is mapped once per incident face with the same arithmetic, so shared vertices keep equal
// coordinates (the crossing counts below rely on it).
template <typename TriangleMesh, typename VertexPointMap>
std::vector<Triangle_points> normalized_triangles(const TriangleMesh& tm, const VertexPointMap& vpm,
                                                  const Normalization& normalization)
{
  std::vector<Triangle_points> out;
  out.reserve(num_faces(tm));
  for(auto f : faces(tm))
  {
    Triangle_points t;
    int c = 0;
    for(auto v : vertices_around_face(halfedge(f, tm), tm))
    {
      CGAL_precondition(c < 3);
      if(c < 3) t[c] = normalization.to_unit(get(vpm, v));
      ++c;
    }
    CGAL_precondition(c == 3);
    out.push_back(t);
  }
  return out;
}

// Whether no halfedge of a face of `tm` is a border halfedge: then the triangles form a 2-cycle and
// the winding number of every point off the surface is an integer, given exactly by ray crossings.
// Not CGAL::is_closed(): that one also fails on an edge no face uses, which bounds nothing here.
template <typename TriangleMesh>
bool faces_form_closed_surface(const TriangleMesh& tm)
{
  for(auto f : faces(tm))
    for(auto h : halfedges_around_face(halfedge(f, tm), tm))
      if(is_border(opposite(h, tm), tm)) return false;
  return true;
}

// Separating-axis test of a triangle against the axis-aligned cube of centre `c` and half side `h`
// (Akenine-Moeller). Closed boxes: touching counts.
inline bool triangle_intersects_cube(const Triangle_points& t, const Vec3& c, double h)
{
  const Vec3 v[3] = {sub3(t[0], c), sub3(t[1], c), sub3(t[2], c)};
  for(int a = 0; a < 3; ++a)
  {
    const double lo = (std::min)({v[0][a], v[1][a], v[2][a]}), hi = (std::max)({v[0][a], v[1][a], v[2][a]});
    if(lo > h || hi < -h) return false;
  }
  const Vec3 e[3] = {sub3(v[1], v[0]), sub3(v[2], v[1]), sub3(v[0], v[2])};
  const Vec3 n = cross3(e[0], e[1]);
  if(std::abs(dot3(n, v[0])) > h * (std::abs(n[0]) + std::abs(n[1]) + std::abs(n[2]))) return false;
  for(int i = 0; i < 3; ++i)
    for(int a = 0; a < 3; ++a)
    {
      Vec3 unit = {{0., 0., 0.}};
      unit[a] = 1.;
      const Vec3 axis = cross3(e[i], unit);
      const double p0 = dot3(axis, v[0]), p1 = dot3(axis, v[1]), p2 = dot3(axis, v[2]);
      const double rad = h * (std::abs(axis[0]) + std::abs(axis[1]) + std::abs(axis[2]));
      if((std::min)({p0, p1, p2}) > rad || (std::max)({p0, p1, p2}) < -rad) return false;
    }
  return true;
}

// The voxels of the `r`-grid touched by the triangles and, per voxel, the triangles touching it
// (compressed rows: the triangles of voxel v are `triangles[offsets[v] .. offsets[v+1])`, in
// increasing order). Voxel boxes are enlarged by a tiny fraction of their size, so that a surface
// running along a voxel face marks the voxels on both sides whatever the rounding: the surface
// voxels then separate the inside from the outside for every closed surface.
struct Surface_voxels
{
  Voxel_grid<std::uint8_t> mask;
  std::vector<std::size_t> offsets;
  std::vector<std::uint32_t> triangles;
};

template <typename ConcurrencyTag>
Surface_voxels surface_voxels(const std::vector<Triangle_points>& tris, int r)
{
  const double h = 1. / double(r);
  const double half = 0.5 * h * (1. + 1e-7);
  const std::size_t n = tris.size();
  // Fixed chunks concatenated in order: the output does not depend on the thread count.
  const std::size_t nchunks = (std::min<std::size_t>)(64, (n + 255) / 256 + 1);
  std::vector<std::vector<std::pair<std::uint32_t, std::uint32_t> > > pairs(nchunks);
  for_each_range<ConcurrencyTag>(nchunks, [&](std::size_t cb, std::size_t ce) {
    for(std::size_t chunk = cb; chunk < ce; ++chunk)
    {
      const std::size_t tb = n * chunk / nchunks, te = n * (chunk + 1) / nchunks;
      std::vector<std::pair<std::uint32_t, std::uint32_t> >& out = pairs[chunk];
      for(std::size_t t = tb; t < te; ++t)
      {
        int lo[3], hi[3];
        bool outside = false;
        for(int a = 0; a < 3; ++a)
        {
          const double mn = (std::min)({tris[t][0][a], tris[t][1][a], tris[t][2][a]});
          const double mx = (std::max)({tris[t][0][a], tris[t][1][a], tris[t][2][a]});
          lo[a] = int(std::floor((mn + 0.5) * r - 1e-6));
          hi[a] = int(std::floor((mx + 0.5) * r + 1e-6));
          if(hi[a] < 0 || lo[a] >= r) outside = true;
          lo[a] = (std::max)(lo[a], 0);
          hi[a] = (std::min)(hi[a], r - 1);
        }
        if(outside) continue;
        for(int k = lo[2]; k <= hi[2]; ++k)
          for(int j = lo[1]; j <= hi[1]; ++j)
            for(int i = lo[0]; i <= hi[0]; ++i)
            {
              const Vec3 c = {{-0.5 + (i + 0.5) * h, -0.5 + (j + 0.5) * h, -0.5 + (k + 0.5) * h}};
              if(triangle_intersects_cube(tris[t], c, half))
                out.emplace_back(std::uint32_t(i + r * (j + r * k)), std::uint32_t(t));
            }
      }
    }
  });
  Surface_voxels s;
  s.mask = Voxel_grid<std::uint8_t>(r, 0);
  const std::size_t size = s.mask.size();
  s.offsets.assign(size + 1, 0);
  std::size_t total = 0;
  for(const auto& chunk : pairs)
  {
    total += chunk.size();
    for(const auto& p : chunk) ++s.offsets[p.first + 1];
  }
  for(std::size_t v = 0; v < size; ++v) s.offsets[v + 1] += s.offsets[v];
  s.triangles.resize(total);
  std::vector<std::size_t> fill(s.offsets.begin(), s.offsets.end() - 1);
  for(const auto& chunk : pairs)
    for(const auto& p : chunk)
    {
      s.triangles[fill[p.first]++] = p.second;
      s.mask[p.first] = 1;
    }
  return s;
}

// Signed crossings of the rows of the grid (lines parallel to x through the voxel centres
// (y_j, z_k)) with the triangles. The containment of a row in a projected triangle is decided
// with exact orientation predicates and a symbolic perturbation of the row, so that every row
// crosses a closed surface a consistent number of times even through edges and vertices: the
// signed count beyond a point is then exactly its winding number. Row (j,k) has index j + r*k.
struct Row_crossings
{
  std::vector<std::size_t> offsets;            // per row, into the arrays below
  std::vector<double> x;                       // crossing abscissa, sorted per row
  std::vector<signed char> sign;               // +1 where the surface normal has a positive x
};

// Sign of orient2d(u, v, q) in the (y,z) plane for q perturbed by (eps, eps^2): never 0 unless u = v.
inline int perturbed_orientation(const Epick::Point_2& u, const Epick::Point_2& v, const Epick::Point_2& q)
{
  const CGAL::Orientation o = CGAL::orientation(u, v, q);
  if(o != CGAL::COLLINEAR) return o == CGAL::LEFT_TURN ? 1 : -1;
  if(v.y() != u.y()) return u.y() > v.y() ? 1 : -1;
  if(v.x() != u.x()) return v.x() > u.x() ? 1 : -1;
  return 0;
}

template <typename ConcurrencyTag>
Row_crossings row_crossings(const std::vector<Triangle_points>& tris, int r)
{
  const double h = 1. / double(r);
  const std::size_t n = tris.size();
  struct Hit
  {
    std::uint32_t row;
    double x;
    signed char sign;
  };
  const std::size_t nchunks = (std::min<std::size_t>)(64, (n + 255) / 256 + 1);
  std::vector<std::vector<Hit> > hits(nchunks);
  for_each_range<ConcurrencyTag>(nchunks, [&](std::size_t cb, std::size_t ce) {
    for(std::size_t chunk = cb; chunk < ce; ++chunk)
    {
      const std::size_t tb = n * chunk / nchunks, te = n * (chunk + 1) / nchunks;
      for(std::size_t t = tb; t < te; ++t)
      {
        const Triangle_points& T = tris[t];
        // Rows whose centre may lie in the projection; the exact test decides.
        int lo[2], hi[2];
        bool empty = false;
        for(int a = 0; a < 2; ++a)
        {
          const double mn = (std::min)({T[0][a + 1], T[1][a + 1], T[2][a + 1]});
          const double mx = (std::max)({T[0][a + 1], T[1][a + 1], T[2][a + 1]});
          lo[a] = (std::max)(0, int(std::ceil((mn + 0.5) * r - 0.5 - 1e-6)));
          hi[a] = (std::min)(r - 1, int(std::floor((mx + 0.5) * r - 0.5 + 1e-6)));
          if(lo[a] > hi[a]) empty = true;
        }
        if(empty) continue;
        const Epick::Point_2 a2(T[0][1], T[0][2]), b2(T[1][1], T[1][2]), c2(T[2][1], T[2][2]);
        for(int k = lo[1]; k <= hi[1]; ++k)
          for(int j = lo[0]; j <= hi[0]; ++j)
          {
            const double y = -0.5 + (j + 0.5) * h, z = -0.5 + (k + 0.5) * h;
            const Epick::Point_2 q(y, z);
            const int s0 = perturbed_orientation(a2, b2, q);
            if(s0 == 0) continue;
            const int s1 = perturbed_orientation(b2, c2, q);
            if(s1 != s0) continue;
            const int s2 = perturbed_orientation(c2, a2, q);
            if(s2 != s0) continue;
            // Barycentric abscissa, from the (approximate) sub-areas.
            auto area = [&](const Vec3& u, const Vec3& v) {
              return (v[1] - u[1]) * (z - u[2]) - (v[2] - u[2]) * (y - u[1]);
            };
            const double wa = std::abs(area(T[1], T[2])), wb = std::abs(area(T[2], T[0])),
                         wc = std::abs(area(T[0], T[1]));
            const double sum = wa + wb + wc;
            double x = sum > 0. ? (wa * T[0][0] + wb * T[1][0] + wc * T[2][0]) / sum
                                : (T[0][0] + T[1][0] + T[2][0]) / 3.;
            x = (std::min)((std::max)(x, (std::min)({T[0][0], T[1][0], T[2][0]})),
                           (std::max)({T[0][0], T[1][0], T[2][0]}));
            hits[chunk].push_back(Hit{std::uint32_t(j + r * k), x, static_cast<signed char>(s0)});
          }
      }
    }
  });
  Row_crossings rc;
  const std::size_t rows = std::size_t(r) * std::size_t(r);
  rc.offsets.assign(rows + 1, 0);
  std::size_t total = 0;
  for(const auto& chunk : hits)
  {
    total += chunk.size();
    for(const Hit& hit : chunk) ++rc.offsets[hit.row + 1];
  }
  for(std::size_t i = 0; i < rows; ++i) rc.offsets[i + 1] += rc.offsets[i];
  std::vector<std::pair<double, signed char> > sorted(total);
  std::vector<std::size_t> fill(rc.offsets.begin(), rc.offsets.end() - 1);
  for(const auto& chunk : hits)
    for(const Hit& hit : chunk) sorted[fill[hit.row]++] = std::make_pair(hit.x, hit.sign);
  for(std::size_t i = 0; i < rows; ++i)
    std::sort(sorted.begin() + rc.offsets[i], sorted.begin() + rc.offsets[i + 1]);
  rc.x.resize(total);
  rc.sign.resize(total);
  for(std::size_t i = 0; i < total; ++i)
  {
    rc.x[i] = sorted[i].first;
    rc.sign[i] = sorted[i].second;
  }
  return rc;
}

// Inside flags (1/0) of every voxel centre from the row crossings: winding number beyond the
// centre along +x, inside if |w| > 0.5 (`parity = false`), or odd number of crossings beyond it
// (`parity = true`).
inline std::vector<std::uint8_t> inside_from_rows(const Row_crossings& rc, int r, bool parity)
{
  const double h = 1. / double(r);
  const std::size_t R = std::size_t(r);
  std::vector<std::uint8_t> inside(R * R * R, 0);
  for(std::size_t row = 0; row < R * R; ++row)
  {
    std::size_t c = rc.offsets[row + 1];
    const std::size_t first = rc.offsets[row];
    int w = 0, count = 0;
    for(int i = r - 1; i >= 0; --i)
    {
      const double x = -0.5 + (i + 0.5) * h;
      while(c > first && rc.x[c - 1] > x)
      {
        --c;
        w += rc.sign[c];
        ++count;
      }
      inside[std::size_t(i) + R * row] = parity ? std::uint8_t(count & 1) : std::uint8_t(w != 0);
    }
  }
  return inside;
}

// Per voxel centre, how many of its six axis rays see a non-zero winding number, counted exactly
// from the signed crossings of the ray's row with the triangles (Nooruddin and Turk 2003, with
// signed crossings). On a closed surface the six agree (the winding number); a hole turns only the
// rays that leave through it, and an open sheet gives the rays that cross it. Rows are computed
// along x, y and z on the triangles with permuted coordinates.
template <typename ConcurrencyTag>
std::vector<std::uint8_t> ray_votes(const std::vector<Triangle_points>& tris, int r)
{
  const std::size_t R = std::size_t(r);
  std::vector<std::uint8_t> votes(R * R * R, 0);
  std::vector<Triangle_points> permuted(tris.size());
  for(int axis = 0; axis < 3; ++axis)
  {
    // coordinate (axis, axis + 1, axis + 2) of a point becomes (x, y, z)
    for(std::size_t t = 0; t < tris.size(); ++t)
      for(int c = 0; c < 3; ++c)
        for(int a = 0; a < 3; ++a) permuted[t][std::size_t(c)][std::size_t(a)] = tris[t][std::size_t(c)][std::size_t((axis + a) % 3)];
    const Row_crossings rc = row_crossings<ConcurrencyTag>(permuted, r);
    const double h = 1. / double(r);
    for_each_range<ConcurrencyTag>(R * R, [&](std::size_t b, std::size_t e) {
      for(std::size_t row = b; row < e; ++row)
      {
        const std::size_t first = rc.offsets[row], last = rc.offsets[row + 1];
        int total = 0;
        for(std::size_t c = first; c < last; ++c) total += rc.sign[c];
        std::size_t c = last;
        int beyond = 0; // signed crossings beyond the centre along +x: the winding number of the + ray
        std::size_t g[3];
        g[(axis + 1) % 3] = row % R;
        g[(axis + 2) % 3] = row / R;
        for(int i = r - 1; i >= 0; --i)
        {
          const double x = -0.5 + (i + 0.5) * h;
          while(c > first && rc.x[c - 1] > x) beyond += rc.sign[--c];
          g[axis] = std::size_t(i);
          // the - ray sees the crossings before the centre, with the opposite orientation
          votes[g[0] + R * (g[1] + R * g[2])] += std::uint8_t((beyond != 0) + (beyond - total != 0));
        }
      }
    });
  }
  return votes;
}

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_MESH_VOXELIZATION_H
