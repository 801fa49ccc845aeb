// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_TRIANGULATE_POLYGON_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_TRIANGULATE_POLYGON_H

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

// Ear clipping of one polygon of a soup, in the plane of its Newell normal. `xyz(i)` returns the
// coordinates of point `i`. Appends `n-2` triangles (vertex ids, orientation of the polygon kept);
// falls back to a fan when no ear is found (self-overlapping or degenerate polygons).
template <typename Coordinates>
void triangulate_polygon(const std::vector<std::size_t>& poly, const Coordinates& xyz,
                         std::vector<std::array<std::size_t, 3> >& out)
{
  const std::size_t n = poly.size();
  if(n < 3) return;
  if(n == 3) { out.push_back({{poly[0], poly[1], poly[2]}}); return; }

  double nx = 0, ny = 0, nz = 0;
  for(std::size_t i = 0; i < n; ++i)
  {
    const std::array<double, 3> a = xyz(poly[i]), b = xyz(poly[(i + 1) % n]);
    nx += (a[1] - b[1]) * (a[2] + b[2]);
    ny += (a[2] - b[2]) * (a[0] + b[0]);
    nz += (a[0] - b[0]) * (a[1] + b[1]);
  }
  // project on the plane orthogonal to the dominant axis of the normal, keeping orientation
  int drop = 2;
  if(std::abs(nx) >= std::abs(ny) && std::abs(nx) >= std::abs(nz)) drop = 0;
  else if(std::abs(ny) >= std::abs(nz)) drop = 1;
  const double sign = (drop == 0 ? nx : (drop == 1 ? ny : nz)) >= 0 ? 1. : -1.;
  const int u = (drop + 1) % 3, v = (drop + 2) % 3;
  std::vector<std::array<double, 2> > p(n);
  for(std::size_t i = 0; i < n; ++i)
  {
    const std::array<double, 3> c = xyz(poly[i]);
    p[i] = {{c[u], sign * c[v]}};
  }
  auto cross = [&](std::size_t a, std::size_t b, std::size_t c) {
    return (p[b][0] - p[a][0]) * (p[c][1] - p[a][1]) - (p[b][1] - p[a][1]) * (p[c][0] - p[a][0]);
  };

  std::vector<std::size_t> ring(n);
  for(std::size_t i = 0; i < n; ++i) ring[i] = i;
  std::size_t guard = 0;
  while(ring.size() > 3 && guard < 2 * n * n)
  {
    bool clipped = false;
    for(std::size_t k = 0; k < ring.size(); ++k, ++guard)
    {
      const std::size_t a = ring[(k + ring.size() - 1) % ring.size()], b = ring[k],
                        c = ring[(k + 1) % ring.size()];
      if(cross(a, b, c) <= 0) continue; // reflex or flat corner
      bool empty = true;
      for(std::size_t q : ring)
      {
        if(q == a || q == b || q == c) continue;
        if(cross(a, b, q) >= 0 && cross(b, c, q) >= 0 && cross(c, a, q) >= 0) { empty = false; break; }
      }
      if(!empty) continue;
      out.push_back({{poly[a], poly[b], poly[c]}});
      ring.erase(ring.begin() + std::ptrdiff_t(k));
      clipped = true;
      break;
    }
    if(!clipped) break;
  }
  // remaining ring: fan (exact for the last triangle, a fallback for degenerate input)
  for(std::size_t k = 1; k + 1 < ring.size(); ++k)
    out.push_back({{poly[ring[0]], poly[ring[k]], poly[ring[k + 1]]}});
}

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_TRIANGULATE_POLYGON_H
