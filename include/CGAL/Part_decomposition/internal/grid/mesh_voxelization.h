// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_MESH_VOXELIZATION_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_MESH_VOXELIZATION_H

#include <CGAL/Part_decomposition/internal/toolbox/toolbox.h>

#include <CGAL/assertions.h>
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

// The mesh as a triangle soup in the normalized cube and exact ray crossings along the rows of a
// grid: the geometric building blocks of the TSDF.

namespace CGAL {
namespace Part_decomposition {
namespace internal {

// The triangles of `tm` in normalized coordinates, in the iteration order of `faces(tm)`. Every
// vertex is mapped once per incident face with the same arithmetic, so shared vertices keep equal
// coordinates (the crossing counts below rely on it).
// `Normalization`: Part_decomposition::Normalization.
template <typename TriangleMesh, typename VertexPointMap, typename Normalization,
          typename ConcurrencyTag = CGAL::Sequential_tag>
std::vector<Triangle_points> normalized_triangles(const TriangleMesh& tm, const VertexPointMap& vpm,
                                                  const Normalization& normalization,
                                                  ConcurrencyTag = ConcurrencyTag())
{
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  const std::vector<face_descriptor> face_list(faces(tm).begin(), faces(tm).end());
  std::vector<Triangle_points> out(face_list.size());
  for_each_range<ConcurrencyTag>(face_list.size(), [&](std::size_t b, std::size_t e) {
    for(std::size_t i = b; i < e; ++i)
    {
      int c = 0;
      for(auto v : vertices_around_face(halfedge(face_list[i], tm), tm))
      {
        CGAL_precondition(c < 3);
        if(c < 3) out[i][c] = normalization.to_unit(get(vpm, v));
        ++c;
      }
      CGAL_precondition(c == 3);
    }
  }, 4096);
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

// A crossing of row `row` (index j + r*k) at abscissa `x`, `sign` as in Row_crossings.
struct Row_hit
{
  std::uint32_t row;
  double x;
  signed char sign;
};

// Appends to `hits` the crossings of triangle T with the rows of the grid of resolution r.
inline void triangle_row_hits(const Triangle_points& T, int r, std::vector<Row_hit>& hits)
{
  const double h = 1. / double(r);
  // Rows whose centre may lie in the projection; the exact test decides.
  int lo[2], hi[2];
  for(int a = 0; a < 2; ++a)
  {
    const double mn = (std::min)({T[0][a + 1], T[1][a + 1], T[2][a + 1]});
    const double mx = (std::max)({T[0][a + 1], T[1][a + 1], T[2][a + 1]});
    lo[a] = (std::max)(0, int(std::ceil((mn + 0.5) * r - 0.5 - 1e-6)));
    hi[a] = (std::min)(r - 1, int(std::floor((mx + 0.5) * r - 0.5 + 1e-6)));
  }
  if(lo[0] > hi[0] || lo[1] > hi[1]) return;
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
      hits.push_back(Row_hit{std::uint32_t(j + r * k), x, static_cast<signed char>(s0)});
    }
}

// The crossings of the rows of the grid of resolution r, gathered from chunks of hits: per row,
// sorted by abscissa.
inline Row_crossings sorted_row_crossings(const std::vector<std::vector<Row_hit> >& hits, int r)
{
  Row_crossings rc;
  const std::size_t rows = std::size_t(r) * std::size_t(r);
  rc.offsets.assign(rows + 1, 0);
  std::size_t total = 0;
  for(const auto& chunk : hits)
  {
    total += chunk.size();
    for(const Row_hit& hit : chunk) ++rc.offsets[hit.row + 1];
  }
  for(std::size_t i = 0; i < rows; ++i) rc.offsets[i + 1] += rc.offsets[i];
  std::vector<std::pair<double, signed char> > sorted(total);
  std::vector<std::size_t> fill(rc.offsets.begin(), rc.offsets.end() - 1);
  for(const auto& chunk : hits)
    for(const Row_hit& hit : chunk) sorted[fill[hit.row]++] = std::make_pair(hit.x, hit.sign);
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

template <typename ConcurrencyTag>
Row_crossings row_crossings(const std::vector<Triangle_points>& tris, int r)
{
  const std::size_t n = tris.size();
  const std::size_t nchunks = (std::min<std::size_t>)(64, (n + 255) / 256 + 1);
  std::vector<std::vector<Row_hit> > hits(nchunks);
  for_each_range<ConcurrencyTag>(nchunks, [&](std::size_t cb, std::size_t ce) {
    for(std::size_t chunk = cb; chunk < ce; ++chunk)
    {
      const std::size_t tb = n * chunk / nchunks, te = n * (chunk + 1) / nchunks;
      for(std::size_t t = tb; t < te; ++t) triangle_row_hits(tris[t], r, hits[chunk]);
    }
  });
  return sorted_row_crossings(hits, r);
}

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_MESH_VOXELIZATION_H
