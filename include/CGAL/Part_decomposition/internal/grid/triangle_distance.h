// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_TRIANGLE_DISTANCE_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_TRIANGLE_DISTANCE_H

#include <CGAL/Part_decomposition/internal/grid/winding_number.h>

#include <algorithm>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

// Squared distance from p to triangle (a,b,c) (Ericson, Real-Time Collision Detection, 5.1.5).
inline double squared_distance_to_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c)
{
  const Vec3 ab = sub3(b, a), ac = sub3(c, a), ap = sub3(p, a);
  auto d2 = [](const Vec3& u) { return dot3(u, u); };
  const double d1 = dot3(ab, ap), d2_ = dot3(ac, ap);
  if(d1 <= 0. && d2_ <= 0.) return d2(ap);
  const Vec3 bp = sub3(p, b);
  const double d3 = dot3(ab, bp), d4 = dot3(ac, bp);
  if(d3 >= 0. && d4 <= d3) return d2(bp);
  const double vc = d1 * d4 - d3 * d2_;
  if(vc <= 0. && d1 >= 0. && d3 <= 0.)
  {
    const double v = d1 / (d1 - d3);
    return d2(sub3(ap, {{v * ab[0], v * ab[1], v * ab[2]}}));
  }
  const Vec3 cp = sub3(p, c);
  const double d5 = dot3(ab, cp), d6 = dot3(ac, cp);
  if(d6 >= 0. && d5 <= d6) return d2(cp);
  const double vb = d5 * d2_ - d1 * d6;
  if(vb <= 0. && d2_ >= 0. && d6 <= 0.)
  {
    const double w = d2_ / (d2_ - d6);
    return d2(sub3(ap, {{w * ac[0], w * ac[1], w * ac[2]}}));
  }
  const double va = d3 * d6 - d5 * d4;
  if(va <= 0. && (d4 - d3) >= 0. && (d5 - d6) >= 0.)
  {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    const Vec3 bc = sub3(c, b);
    return d2(sub3(bp, {{w * bc[0], w * bc[1], w * bc[2]}}));
  }
  const double sum = va + vb + vc;
  if(!(sum > 0.)) // degenerate triangle: nearest of its edges
  {
    auto seg = [&](const Vec3& u, const Vec3& v) {
      const Vec3 uv = sub3(v, u), up = sub3(p, u);
      const double l = dot3(uv, uv);
      const double t = l > 0. ? (std::min)(1., (std::max)(0., dot3(up, uv) / l)) : 0.;
      return d2(sub3(up, {{t * uv[0], t * uv[1], t * uv[2]}}));
    };
    return (std::min)({seg(a, b), seg(b, c), seg(c, a)});
  }
  const double v = vb / sum, w = vc / sum;
  return d2(sub3(ap, {{v * ab[0] + w * ac[0], v * ab[1] + w * ac[1], v * ab[2] + w * ac[2]}}));
}

// The point of triangle (a,b,c) closest to p, the same case analysis as
// squared_distance_to_triangle().
inline Vec3 closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c)
{
  auto along = [](const Vec3& o, const Vec3& u, double t) { return Vec3{{o[0] + t * u[0], o[1] + t * u[1], o[2] + t * u[2]}}; };
  const Vec3 ab = sub3(b, a), ac = sub3(c, a), ap = sub3(p, a);
  const double d1 = dot3(ab, ap), d2 = dot3(ac, ap);
  if(d1 <= 0. && d2 <= 0.) return a;
  const Vec3 bp = sub3(p, b);
  const double d3 = dot3(ab, bp), d4 = dot3(ac, bp);
  if(d3 >= 0. && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if(vc <= 0. && d1 >= 0. && d3 <= 0.) return along(a, ab, d1 / (d1 - d3));
  const Vec3 cp = sub3(p, c);
  const double d5 = dot3(ab, cp), d6 = dot3(ac, cp);
  if(d6 >= 0. && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if(vb <= 0. && d2 >= 0. && d6 <= 0.) return along(a, ac, d2 / (d2 - d6));
  const double va = d3 * d6 - d5 * d4;
  if(va <= 0. && (d4 - d3) >= 0. && (d5 - d6) >= 0.) return along(b, sub3(c, b), (d4 - d3) / ((d4 - d3) + (d5 - d6)));
  const double sum = va + vb + vc;
  if(!(sum > 0.)) // degenerate triangle: its nearest corner
  {
    const double da = dot3(ap, ap), db = dot3(bp, bp), dc = dot3(cp, cp);
    return da <= db && da <= dc ? a : (db <= dc ? b : c);
  }
  const double v = vb / sum, w = vc / sum;
  return {{a[0] + v * ab[0] + w * ac[0], a[1] + v * ab[1] + w * ac[1], a[2] + v * ab[2] + w * ac[2]}};
}

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_TRIANGLE_DISTANCE_H
