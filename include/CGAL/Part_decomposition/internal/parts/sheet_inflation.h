// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_SHEET_INFLATION_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_SHEET_INFLATION_H

// The solid of open sheets: each sheet inflated on both sides by its distance to its border.
//
// Inputs: `point` (per vertex), `vertex` (three per face), `inflate` (per face: 1 if its sheet is
// inflated).
// Output: the points and triangles of the solid. Triangle i < F copies face i (on the side of its
// normal for an inflated face); triangles F.. are the other sides of the inflated faces. The
// border vertices of the inflated sheets are shared by both sides, so a sheet becomes closed.

#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/convex_hull_2.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <iterator>
#include <limits>
#include <queue>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

// Per vertex, 1 if it lies on a border edge (an edge of one face) of the faces with `inflate`.
inline std::vector<std::uint8_t> sheet_border_vertices(std::size_t number_of_points, const std::vector<std::size_t>& vertex,
                                                       const std::vector<std::uint8_t>& inflate)
{
  std::unordered_map<std::uint64_t, int> count;
  auto key = [](std::size_t a, std::size_t b) { return (std::uint64_t((std::min)(a, b)) << 32) | std::uint64_t((std::max)(a, b)); };
  for(std::size_t i = 0; i < inflate.size(); ++i)
    if(inflate[i])
      for(int k = 0; k < 3; ++k) ++count[key(vertex[3 * i + k], vertex[3 * i + (k + 1) % 3])];
  std::vector<std::uint8_t> border(number_of_points, 0);
  for(const auto& e : count)
    if(e.second == 1) border[std::size_t(e.first >> 32)] = border[std::size_t(e.first & 0xffffffffu)] = 1;
  return border;
}

// The distance along the edges of the inflated faces from each vertex to the nearest border
// vertex (Dijkstra from all of them; infinite where no border is reached). Written here: the
// graph is a face subset of a soup, which neither BGL's mesh adaptors nor the heat method take.
inline std::vector<double> border_distances(const std::vector<Eigen::Vector3d>& point, const std::vector<std::size_t>& vertex,
                                            const std::vector<std::uint8_t>& inflate, const std::vector<std::uint8_t>& border)
{
  std::vector<std::vector<std::size_t> > neighbors(point.size());
  for(std::size_t i = 0; i < inflate.size(); ++i)
    if(inflate[i])
      for(int k = 0; k < 3; ++k)
        neighbors[vertex[3 * i + k]].push_back(vertex[3 * i + (k + 1) % 3]), neighbors[vertex[3 * i + (k + 1) % 3]].push_back(vertex[3 * i + k]);
  std::vector<double> d(point.size(), std::numeric_limits<double>::infinity());
  typedef std::pair<double, std::size_t> Entry;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry> > queue;
  for(std::size_t v = 0; v < point.size(); ++v)
    if(border[v]) queue.push({d[v] = 0., v});
  while(!queue.empty())
  {
    const Entry e = queue.top();
    queue.pop();
    if(e.first > d[e.second]) continue;
    for(std::size_t u : neighbors[e.second])
    {
      const double du = e.first + (point[u] - point[e.second]).norm();
      if(du < d[u]) queue.push({d[u] = du, u});
    }
  }
  return d;
}

// The solid (see the file's comment): each vertex of an inflated face moves along its normal (the
// area-weighted mean of its faces' normals) by its distance to the border, one copy each way.
inline void inflate_sheet_soup(const std::vector<Eigen::Vector3d>& point, const std::vector<std::size_t>& vertex,
                               const std::vector<std::uint8_t>& inflate, std::vector<Eigen::Vector3d>& out_points,
                               std::vector<std::array<std::size_t, 3> >& out_triangles)
{
  const std::size_t nv = point.size(), nf = inflate.size();
  const std::vector<std::uint8_t> border = sheet_border_vertices(nv, vertex, inflate);
  const std::vector<double> d = border_distances(point, vertex, inflate, border);
  std::vector<Eigen::Vector3d> normal(nv, Eigen::Vector3d::Zero());
  for(std::size_t i = 0; i < nf; ++i)
    if(inflate[i])
    {
      const Eigen::Vector3d& a = point[vertex[3 * i]];
      const Eigen::Vector3d n = (point[vertex[3 * i + 1]] - a).cross(point[vertex[3 * i + 2]] - a);
      for(int k = 0; k < 3; ++k) normal[vertex[3 * i + k]] += n;
    }
  // the other side's copy of each moved vertex, after the input's vertices
  out_points = point;
  std::vector<std::size_t> other(nv);
  for(std::size_t v = 0; v < nv; ++v)
  {
    other[v] = v;
    const double length = normal[v].norm();
    if(border[v] || length == 0. || !(d[v] < std::numeric_limits<double>::infinity())) continue;
    const Eigen::Vector3d offset = d[v] / length * normal[v];
    out_points[v] = point[v] + offset;
    other[v] = out_points.size();
    out_points.push_back(point[v] - offset);
  }
  out_triangles.clear();
  for(std::size_t i = 0; i < nf; ++i) out_triangles.push_back({{vertex[3 * i], vertex[3 * i + 1], vertex[3 * i + 2]}});
  for(std::size_t i = 0; i < nf; ++i)
    if(inflate[i]) out_triangles.push_back({{other[vertex[3 * i]], other[vertex[3 * i + 2]], other[vertex[3 * i + 1]]}});
}

// The area of the inflated faces projected on their least-squares plane, as a fraction of the
// area of the convex hull of their projected corners: about 1 for a sheet whose outline is convex
// (a plate, a disk: no limbs), well below for a figure with limbs.
inline double outline_fill_fraction(const std::vector<Eigen::Vector3d>& point, const std::vector<std::size_t>& vertex,
                                    const std::vector<std::uint8_t>& inflate)
{
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  std::size_t n = 0;
  for(std::size_t i = 0; i < inflate.size(); ++i)
    if(inflate[i])
      for(int k = 0; k < 3; ++k, ++n) mean += point[vertex[3 * i + k]];
  if(n == 0) return 1.;
  mean /= double(n);
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for(std::size_t i = 0; i < inflate.size(); ++i)
    if(inflate[i])
      for(int k = 0; k < 3; ++k) cov += (point[vertex[3 * i + k]] - mean) * (point[vertex[3 * i + k]] - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  // unit-free coordinates, and exact predicates: the hull of nearly collinear points is still one
  const double scale = std::sqrt((std::max)(eig.eigenvalues()[2] / double(n), std::numeric_limits<double>::min()));
  const Eigen::Vector3d u = eig.eigenvectors().col(2) / scale, v = eig.eigenvectors().col(1) / scale;
  typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_2 P;
  std::vector<P> projected, hull;
  double area = 0.;
  for(std::size_t i = 0; i < inflate.size(); ++i)
    if(inflate[i])
    {
      std::array<P, 3> c;
      for(int k = 0; k < 3; ++k)
      {
        const Eigen::Vector3d d = point[vertex[3 * i + k]] - mean;
        projected.push_back(c[k] = P(d.dot(u), d.dot(v)));
      }
      area += std::abs(CGAL::area(c[0], c[1], c[2]));
    }
  CGAL::convex_hull_2(projected.begin(), projected.end(), std::back_inserter(hull));
  const double hull_area =
    hull.size() < 3 ? 0. : CGAL::polygon_area_2(hull.begin(), hull.end(), CGAL::Exact_predicates_inexact_constructions_kernel());
  return hull_area > 0. ? area / hull_area : 1.;
}

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_SHEET_INFLATION_H
