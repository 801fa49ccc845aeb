// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_BOUNDED_VOLUME_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_BOUNDED_VOLUME_H

// Whether each piece of a mesh bounds a volume of a signed distance field.
//
// Inputs: the triangles of the mesh in the normalized cube, by face index (made one at a time by
// `triangle(i)`, so that a large mesh's copy is never held); the piece of each
// face; a signed distance field on a grid of the cube (negative inside). Output: per piece, the
// fraction of its area whose faces have the field's inside at `depth` on one side and its outside
// at `depth` on the other, and on which side the outside mostly is.

#include <CGAL/Part_decomposition/internal/toolbox/toolbox.h>
#include <CGAL/Part_decomposition/internal/grid/winding_number.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

// The value of a field on the leaves of `grid` at p: the trilinear interpolation of the values at
// the centres of the eight leaves around p when they are as large as the leaf of p (beyond the
// outermost centres the nearest ones hold), else the value of the leaf of p.
template <typename Grid>
double interpolate_field(const Grid& grid, const std::vector<double>& field, const Vec3& p)
{
  const std::size_t own = grid.locate(p[0], p[1], p[2]);
  const int r = grid.resolution(own);
  if(r == 1) return field[own];
  int i0[3];
  double t[3];
  for(int a = 0; a < 3; ++a)
  {
    const double u = (p[a] + 0.5) * double(r) - 0.5;
    i0[a] = (std::min)((std::max)(int(std::floor(u)), 0), r - 2);
    t[a] = (std::min)((std::max)(u - double(i0[a]), 0.), 1.);
  }
  const std::uint32_t width = grid.width(own);
  double value = 0.;
  for(int c = 0; c < 8; ++c)
  {
    const int di = c & 1, dj = (c >> 1) & 1, dk = (c >> 2) & 1;
    const double w = (di ? t[0] : 1. - t[0]) * (dj ? t[1] : 1. - t[1]) * (dk ? t[2] : 1. - t[2]);
    if(!(w > 0.)) continue;
    const std::size_t l = grid.leaf_of_voxel(std::uint32_t(i0[0] + di) * width, std::uint32_t(i0[1] + dj) * width,
                                             std::uint32_t(i0[2] + dk) * width);
    if(grid.width(l) != width) return field[own];
    value += w * field[l];
  }
  return value;
}

// Per piece, the fractions of its area made of faces that separate the inside of `field` from its
// outside, probed at `depth` (normalized units) along the face normal on both sides of the
// centroid: `bounding`, all of them; `outward`, those whose normal points to the outside minus
// those whose normal points to the inside (1 for a closed piece oriented outward). A face of an
// open sheet has the outside on both sides, a face buried in a volume the inside on both; a face
// of a piece thinner than `depth` sees through it. Faces of zero area weigh nothing.
struct Bounding_fractions
{
  std::vector<double> bounding, outward;
};

// +1 if face `t` has the inside of `field` below it (against its normal) and the outside above, -1
// for the reverse, 0 otherwise or for a face of zero area; `twice_area` receives its double area.
template <typename Grid>
int bounding_side(const Triangle_points& t, const Grid& grid, const std::vector<double>& field, double depth,
                  double& twice_area)
{
  const Vec3 n = cross3(sub3(t[1], t[0]), sub3(t[2], t[0]));
  twice_area = norm3(n);
  if(!(twice_area > 0.)) return 0;
  Vec3 below, above;
  for(int a = 0; a < 3; ++a)
  {
    const double c = (t[0][a] + t[1][a] + t[2][a]) / 3., step = depth * n[a] / twice_area;
    below[a] = c - step;
    above[a] = c + step;
  }
  const bool inside_below = std::signbit(interpolate_field(grid, field, below));
  if(inside_below == std::signbit(interpolate_field(grid, field, above))) return 0;
  return inside_below ? 1 : -1;
}

template <typename ConcurrencyTag, typename Grid, typename TriangleOf>
Bounding_fractions bounding_area_fractions(std::size_t number_of_faces, const TriangleOf& triangle,
                                           const std::vector<std::size_t>& piece, std::size_t number_of_pieces,
                                           const Grid& grid, const std::vector<double>& field, double depth)
{
  const std::size_t nf = number_of_faces;
  std::vector<double> twice_area(nf);
  std::vector<signed char> side(nf);
  for_each_range<ConcurrencyTag>(nf, [&](std::size_t b, std::size_t e) {
    for(std::size_t i = b; i < e; ++i) side[i] = (signed char)(bounding_side(triangle(i), grid, field, depth, twice_area[i]));
  }, 1024);
  // the sums in face order, whatever the number of threads
  std::vector<double> area(number_of_pieces, 0.);
  Bounding_fractions out;
  out.bounding.assign(number_of_pieces, 0.);
  out.outward.assign(number_of_pieces, 0.);
  for(std::size_t i = 0; i < nf; ++i)
  {
    if(!(twice_area[i] > 0.)) continue;
    area[piece[i]] += twice_area[i];
    if(side[i] == 0) continue;
    out.bounding[piece[i]] += twice_area[i];
    out.outward[piece[i]] += side[i] > 0 ? twice_area[i] : -twice_area[i];
  }
  for(std::size_t p = 0; p < number_of_pieces; ++p)
    if(area[p] > 0.)
    {
      out.bounding[p] /= area[p];
      out.outward[p] /= area[p];
    }
  return out;
}

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_BOUNDED_VOLUME_H
