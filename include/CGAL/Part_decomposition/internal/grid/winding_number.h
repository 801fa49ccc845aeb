// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_WINDING_NUMBER_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_WINDING_NUMBER_H

#include <CGAL/Part_decomposition/internal/toolbox/toolbox.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

// Generalized winding number of a triangle soup (Jacobson et al. 2013): w(q) = sum of the signed
// solid angles of the triangles seen from q, over 4 pi. 1 inside a closed outward-oriented
// surface, 0 outside, -1 inside an inward-oriented one, and a smooth harmonic function that still
// separates inside from outside near holes and across self-intersections.
// The fast evaluation is a Barnes-Hut approximation on a bounding volume hierarchy: a cluster seen
// from farther than `accuracy` times its radius counts as one dipole (the sum of its area vectors
// at its area centroid), the first-order term of Barill et al. 2018. With the default accuracy 2
// the error stays below 0.06 on the development meshes (measured against the exact sum), far from
// the 1/2 threshold that decides inside; the second-order term did not improve it at that distance.

namespace CGAL {
namespace Part_decomposition {
namespace internal {

// Signed solid angle of triangle (a,b,c) seen from q (Van Oosterom-Strackee), in [-2pi, 2pi];
// positive when q is on the side opposite to the normal (b-a)x(c-a), i.e. behind the triangle.
inline double triangle_solid_angle(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& q)
{
  const Vec3 u = sub3(a, q), v = sub3(b, q), w = sub3(c, q);
  const double lu = norm3(u), lv = norm3(v), lw = norm3(w);
  const double det = dot3(u, cross3(v, w));
  const double den = lu * lv * lw + dot3(u, v) * lw + dot3(v, w) * lu + dot3(w, u) * lv;
  if(det == 0. && den >= 0.) return 0.; // q in the plane, outside the triangle (or degenerate)
  return 2. * std::atan2(det, den);
}

class Fast_winding_number
{
public:
  /// `accuracy`: the ratio distance / cluster radius above which a cluster is approximated.
  explicit Fast_winding_number(const std::vector<Triangle_points>& triangles, double accuracy = 2.)
    : m_triangles(&triangles), m_accuracy2(accuracy * accuracy)
  {
    const std::size_t n = triangles.size();
    m_order.resize(n);
    for(std::size_t i = 0; i < n; ++i) m_order[i] = std::uint32_t(i);
    m_centroid.resize(n);
    m_area_normal.resize(n);
    for(std::size_t i = 0; i < n; ++i)
    {
      const Triangle_points& t = triangles[i];
      for(int a = 0; a < 3; ++a) m_centroid[i][a] = (t[0][a] + t[1][a] + t[2][a]) / 3.;
      const Vec3 nn = cross3(sub3(t[1], t[0]), sub3(t[2], t[0]));
      m_area_normal[i] = {{0.5 * nn[0], 0.5 * nn[1], 0.5 * nn[2]}};
    }
    m_nodes.reserve(n / 2 + 2);
    if(n > 0) build(0, n);
  }

  /// the approximate winding number at `q`.
  double operator()(const Vec3& q) const
  {
    if(m_nodes.empty()) return 0.;
    const std::vector<Triangle_points>& tris = *m_triangles;
    double sum = 0.;
    std::uint32_t stack[128];
    int top = 0;
    stack[top++] = 0;
    while(top > 0)
    {
      const Node& node = m_nodes[stack[--top]];
      const Vec3 d = sub3(node.center, q);
      const double d2 = dot3(d, d);
      if(d2 > m_accuracy2 * node.radius2)
      {
        // Dipole: solid angle of a small oriented patch = (c - q) . N / |c - q|^3.
        sum += dot3(d, node.area_normal) / (d2 * std::sqrt(d2));
        continue;
      }
      if(node.left == no_child())
      {
        for(std::uint32_t i = node.first; i < node.first + node.count; ++i)
        {
          const Triangle_points& t = tris[m_order[i]];
          sum += triangle_solid_angle(t[0], t[1], t[2], q);
        }
        continue;
      }
      CGAL_assertion(top + 2 <= 128);
      stack[top++] = node.right;
      stack[top++] = node.left;
    }
    return sum / (4. * pi());
  }

  /// the winding number at `q` summed over every triangle (reference, linear time).
  double exact(const Vec3& q) const
  {
    double sum = 0.;
    for(const Triangle_points& t : *m_triangles) sum += triangle_solid_angle(t[0], t[1], t[2], q);
    return sum / (4. * pi());
  }

private:
  static double pi() { return 3.14159265358979323846; }
  static std::uint32_t no_child() { return std::numeric_limits<std::uint32_t>::max(); }

  struct Node
  {
    Vec3 center;      // area-weighted centroid of the triangles
    Vec3 area_normal; // sum of the area vectors
    double radius2;   // squared radius of a ball around `center` holding the triangles
    std::uint32_t first, count, left, right;
  };

  std::uint32_t build(std::size_t first, std::size_t last)
  {
    const std::uint32_t id = std::uint32_t(m_nodes.size());
    m_nodes.push_back(Node());
    const std::vector<Triangle_points>& tris = *m_triangles;
    double area = 0.;
    Vec3 c = {{0., 0., 0.}}, nsum = {{0., 0., 0.}}, lo, hi;
    lo.fill(std::numeric_limits<double>::infinity());
    hi.fill(-std::numeric_limits<double>::infinity());
    for(std::size_t i = first; i < last; ++i)
    {
      const std::uint32_t t = m_order[i];
      const double a = norm3(m_area_normal[t]);
      area += a;
      for(int k = 0; k < 3; ++k)
      {
        c[k] += a * m_centroid[t][k];
        nsum[k] += m_area_normal[t][k];
        lo[k] = (std::min)(lo[k], m_centroid[t][k]);
        hi[k] = (std::max)(hi[k], m_centroid[t][k]);
      }
    }
    if(area > 0.)
      for(int k = 0; k < 3; ++k) c[k] /= area;
    else
      for(int k = 0; k < 3; ++k) c[k] = 0.5 * (lo[k] + hi[k]);
    double r2 = 0.;
    for(std::size_t i = first; i < last; ++i)
      for(const Vec3& p : tris[m_order[i]])
        r2 = (std::max)(r2, dot3(sub3(p, c), sub3(p, c)));
    Node node;
    node.center = c;
    node.area_normal = nsum;
    node.radius2 = r2;
    node.first = std::uint32_t(first);
    node.count = std::uint32_t(last - first);
    node.left = node.right = no_child();
    if(last - first > leaf_size())
    {
      int axis = 0;
      for(int k = 1; k < 3; ++k)
        if(hi[k] - lo[k] > hi[axis] - lo[axis]) axis = k;
      const std::size_t mid = first + (last - first) / 2;
      // Ties broken by index: the split, hence the sums, do not depend on the library's sort.
      std::nth_element(m_order.begin() + first, m_order.begin() + mid, m_order.begin() + last,
                       [&](std::uint32_t x, std::uint32_t y) {
                         return m_centroid[x][axis] < m_centroid[y][axis] ||
                                (m_centroid[x][axis] == m_centroid[y][axis] && x < y);
                       });
      node.left = build(first, mid);
      node.right = build(mid, last);
    }
    m_nodes[id] = node;
    return id;
  }
  static std::size_t leaf_size() { return 8; }

  const std::vector<Triangle_points>* m_triangles;
  double m_accuracy2;
  std::vector<std::uint32_t> m_order;
  std::vector<Vec3> m_centroid, m_area_normal;
  std::vector<Node> m_nodes;
};

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_WINDING_NUMBER_H
