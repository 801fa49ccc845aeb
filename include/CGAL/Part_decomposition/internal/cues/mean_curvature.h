// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_MEAN_CURVATURE_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_MEAN_CURVATURE_H

#include <CGAL/Part_decomposition/internal/toolbox/toolbox.h>
#include <CGAL/Part_decomposition/internal/toolbox/triangle_arrays.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

// What triangle (a,b,c) gives to its corner a: the cotangent Laplacian terms
// cot(c)(a-b) + cot(b)(a-c) over its two edges at a, the mixed Voronoi area of a (Meyer et al.
// 2003: Voronoi area if no angle is obtuse, else half the area at an obtuse a, a quarter
// otherwise), and twice the area times the unit normal. A degenerate triangle gives nothing
// (returns false): its cotangents are unbounded and its area is zero.
inline bool corner_terms(const Vec3& a, const Vec3& b, const Vec3& c, Vec3& laplacian, double& area, Vec3& normal)
{
  double twice_area;
  if(is_degenerate_triangle(a, b, c, twice_area))
  {
    laplacian = normal = Vec3{{0., 0., 0.}};
    area = 0.;
    return false;
  }
  const Vec3 ab = sub3(b, a), ac = sub3(c, a), bc = sub3(c, b);
  normal = cross3(ab, ac);
  const double dot_a = dot3(ab, ac);  // angle at a
  const double dot_b = -dot3(ab, bc); // angle at b: (a-b).(c-b)
  const double dot_c = dot3(ac, bc);  // angle at c: (a-c).(b-c)
  const double cot_b = dot_b / twice_area, cot_c = dot_c / twice_area;
  for(int i = 0; i < 3; ++i) laplacian[i] = -cot_c * ab[i] - cot_b * ac[i];
  const double T = 0.5 * twice_area;
  if(dot_a < 0.)
    area = T / 2;
  else if(dot_b < 0. || dot_c < 0.)
    area = T / 4;
  else
    area = (dot3(ac, ac) * cot_b + dot3(ab, ab) * cot_c) / 8;
  return true;
}

// Meyer's mixed Voronoi areas of the corners a, b, c of a triangle; they sum to its area.
inline std::array<double, 3> mixed_voronoi_areas(const Vec3& a, const Vec3& b, const Vec3& c)
{
  std::array<double, 3> area;
  Vec3 lap, n;
  corner_terms(a, b, c, lap, area[0], n);
  corner_terms(b, c, a, lap, area[1], n);
  corner_terms(c, a, b, lap, area[2], n);
  return area;
}

// The face corners incident to each vertex, in increasing face order (fixed summation order).
struct Vertex_corners
{
  std::vector<std::uint32_t> offsets; // size nv + 1
  std::vector<std::uint32_t> corners; // 3 * face + corner
};

inline Vertex_corners make_vertex_corners(const Triangle_arrays& mesh)
{
  Vertex_corners vc;
  const std::size_t nv = mesh.points.size();
  vc.offsets.assign(nv + 1, 0);
  for(const auto& f : mesh.faces)
    for(int c = 0; c < 3; ++c) ++vc.offsets[f[c] + 1];
  for(std::size_t v = 0; v < nv; ++v) vc.offsets[v + 1] += vc.offsets[v];
  vc.corners.resize(vc.offsets[nv]);
  std::vector<std::uint32_t> fill(vc.offsets.begin(), vc.offsets.end() - 1);
  for(std::size_t f = 0; f < mesh.faces.size(); ++f)
    for(int c = 0; c < 3; ++c) vc.corners[fill[mesh.faces[f][c]]++] = std::uint32_t(3 * f + c);
  return vc;
}

// kappa_v = |H_v| / 2, H_v = (1 / 2A_v) sum_j (cot alpha_ij + cot beta_ij)(x_v - x_j) with A_v the
// mixed Voronoi area. At a border edge the missing cotangent is skipped; the sum then also holds
// the in-plane curvature of the border itself (a flat sheet would get a curved rim), so at a
// border vertex only its component along the area-weighted vertex normal is kept. A vertex with no
// non-degenerate incident triangle (isolated, or only zero-area faces) gets 0. With `concave_only`,
// a vertex where the surface bends away from its normal (convex: sum_j (x_v - x_j) weighted as above
// points to the side the faces' normals point to) gets 0 too.
template <typename ConcurrencyTag>
std::vector<double> vertex_mean_curvatures(const Triangle_arrays& mesh, const Vertex_corners& vc,
                                           bool concave_only = false)
{
  const std::size_t nv = mesh.points.size();
  std::vector<double> kappa(nv, 0.);
  // Each corner is computed where it is summed, from the points: a per-face table would be
  // read in random face order and cost more in cache misses than the arithmetic.
  for_each_block<ConcurrencyTag>(nv, 2048, [&](std::size_t begin, std::size_t end) {
    std::vector<std::uint32_t> ring;     // the neighbours seen, with
    std::vector<std::uint32_t> ring_use; // the number of incident faces holding that edge
    for(std::size_t v = begin; v < end; ++v)
    {
      Vec3 lap{{0., 0., 0.}}, normal{{0., 0., 0.}};
      double area = 0.;
      ring.clear();
      ring_use.clear();
      for(std::uint32_t i = vc.offsets[v]; i < vc.offsets[v + 1]; ++i)
      {
        const auto& face = mesh.faces[vc.corners[i] / 3];
        const int c = int(vc.corners[i] % 3);
        const std::uint32_t w1 = face[(c + 1) % 3], w2 = face[(c + 2) % 3];
        Vec3 l, n;
        double a;
        corner_terms(mesh.points[v], mesh.points[w1], mesh.points[w2], l, a, n);
        for(int d = 0; d < 3; ++d)
        {
          lap[d] += l[d];
          normal[d] += n[d];
        }
        area += a;
        for(std::uint32_t w : {w1, w2})
        {
          std::size_t s = 0;
          while(s < ring.size() && ring[s] != w) ++s;
          if(s == ring.size())
          {
            ring.push_back(w);
            ring_use.push_back(0);
          }
          ++ring_use[s];
        }
      }
      if(!(area > 0.) || (concave_only && dot3(lap, normal) > 0.)) continue;
      bool border = false;
      for(std::uint32_t n : ring_use) border = border || n == 1;
      double k;
      if(border)
      {
        const double nn = std::sqrt(dot3(normal, normal));
        k = nn > 0. ? std::abs(dot3(lap, normal)) / nn / (4. * area) : 0.;
      }
      else
        k = std::sqrt(dot3(lap, lap)) / (4. * area);
      kappa[v] = std::isfinite(k) ? k : 0.;
    }
  });
  return kappa;
}

// c_f in [0,1]: kappa clipped at its `percentile`-th percentile (over the vertices incident to a
// face), divided by the clipped maximum, averaged over the three corners of f. All 0 when the
// clipped maximum is 0 or below 1e-9 / (bounding box diagonal), i.e. on a flat mesh.
inline std::vector<double> face_curvature_cue(const Triangle_arrays& mesh, const Vertex_corners& vc,
                                              const std::vector<double>& kappa, double percentile)
{
  std::vector<double> used;
  used.reserve(kappa.size());
  for(std::size_t v = 0; v < kappa.size(); ++v)
    if(vc.offsets[v + 1] > vc.offsets[v]) used.push_back(kappa[v]);
  std::vector<double> c(mesh.faces.size(), 0.);
  if(used.empty()) return c;
  const double clip = linear_quantile(used, percentile / 100.);
  // The maximum of the clipped values is the clip value itself. A radius of curvature above 1e9
  // times the size of the mesh is rounding noise on a flat mesh: normalizing it would make noise
  // look like curvature 1.
  double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for(const auto& f : mesh.faces)
    for(int i = 0; i < 3; ++i)
      for(int a = 0; a < 3; ++a)
      {
        lo[a] = (std::min)(lo[a], mesh.points[f[i]][a]);
        hi[a] = (std::max)(hi[a], mesh.points[f[i]][a]);
      }
  const double diagonal = std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                                    (hi[2] - lo[2]) * (hi[2] - lo[2]));
  if(!(clip * diagonal > 1e-9) || !std::isfinite(clip)) return c;
  for(std::size_t f = 0; f < mesh.faces.size(); ++f)
  {
    double s = 0.;
    for(int i = 0; i < 3; ++i) s += (std::min)(kappa[mesh.faces[f][i]], clip);
    c[f] = s / (3. * clip);
  }
  return c;
}

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_MEAN_CURVATURE_H
