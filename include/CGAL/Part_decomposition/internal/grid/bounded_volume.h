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
// `triangle(i)`, so that a large mesh's copy is never held), probed face by face or in groups of
// faces; the piece of each face or group; a signed distance field on a grid of the cube (negative
// inside). Output: per piece, the fraction of its area whose faces have the field's inside at
// `depth` on one side and its outside at `depth` on the other, and on which side the outside
// mostly is.

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

// +1 if the point c has the inside of `field` at `depth` below it along n (of length `length`) and
// its outside above, -1 for the reverse, 0 otherwise or for a zero n.
template <typename Grid>
int probe_side(const Vec3& c, const Vec3& n, double length, const Grid& grid, const std::vector<double>& field,
               double depth)
{
  if(!(length > 0.)) return 0;
  Vec3 below, above;
  for(int a = 0; a < 3; ++a)
  {
    const double step = depth * n[a] / length;
    below[a] = c[a] - step;
    above[a] = c[a] + step;
  }
  const bool inside_below = std::signbit(interpolate_field(grid, field, below));
  if(inside_below == std::signbit(interpolate_field(grid, field, above))) return 0;
  return inside_below ? 1 : -1;
}

// The side of face `t` (probe_side() at its centroid along its normal); `twice_area` receives its
// double area.
template <typename Grid>
int bounding_side(const Triangle_points& t, const Grid& grid, const std::vector<double>& field, double depth,
                  double& twice_area)
{
  const Vec3 n = cross3(sub3(t[1], t[0]), sub3(t[2], t[0]));
  twice_area = norm3(n);
  Vec3 c;
  for(int a = 0; a < 3; ++a) c[a] = (t[0][a] + t[1][a] + t[2][a]) / 3.;
  return probe_side(c, n, twice_area, grid, field, depth);
}

// The side of the faces [first, last) of `faces` taken as one surface, probed once at their
// area-weighted centroid along the sum of their area-weighted normals, each turned to the side of
// the first (a face and its twin do not cancel); `twice_area` receives their double area. Faces
// within a fraction of a voxel see the same field one voxel away.
template <typename Grid, typename TriangleOf>
int bounding_side_of_faces(const std::vector<std::size_t>& faces, std::size_t first, std::size_t last,
                           const TriangleOf& triangle, const Grid& grid, const std::vector<double>& field,
                           double depth, double& twice_area)
{
  Vec3 c = {{0., 0., 0.}}, n = {{0., 0., 0.}};
  twice_area = 0.;
  for(std::size_t r = first; r < last; ++r)
  {
    const Triangle_points t = triangle(faces[r]);
    const Vec3 m = cross3(sub3(t[1], t[0]), sub3(t[2], t[0]));
    const double a = norm3(m), turn = dot3(m, n) < 0. ? -1. : 1.;
    for(int x = 0; x < 3; ++x)
    {
      c[x] += a * (t[0][x] + t[1][x] + t[2][x]) / 3.;
      n[x] += turn * m[x];
    }
    twice_area += a;
  }
  if(!(twice_area > 0.)) return 0;
  for(int x = 0; x < 3; ++x) c[x] /= twice_area;
  return probe_side(c, n, norm3(n), grid, field, depth);
}

// Per piece, the bounding fractions of `number_of_items` surface elements (faces, or groups of
// faces): `side(i, twice_area)` probes element i (bounding_side()), `piece_of(i)` is its piece.
template <typename ConcurrencyTag, typename Side, typename PieceOf>
Bounding_fractions bounding_area_fractions(std::size_t number_of_items, const Side& side_of,
                                           const PieceOf& piece_of, std::size_t number_of_pieces)
{
  const std::size_t n = number_of_items;
  std::vector<double> twice_area(n);
  std::vector<signed char> side(n);
  for_each_range<ConcurrencyTag>(n, [&](std::size_t b, std::size_t e) {
    for(std::size_t i = b; i < e; ++i) side[i] = (signed char)(side_of(i, twice_area[i]));
  }, 1024);
  // the sums in item order, whatever the number of threads
  std::vector<double> area(number_of_pieces, 0.);
  Bounding_fractions out;
  out.bounding.assign(number_of_pieces, 0.);
  out.outward.assign(number_of_pieces, 0.);
  for(std::size_t i = 0; i < n; ++i)
  {
    if(!(twice_area[i] > 0.)) continue;
    const std::size_t q = piece_of(i);
    area[q] += twice_area[i];
    if(side[i] == 0) continue;
    out.bounding[q] += twice_area[i];
    out.outward[q] += side[i] > 0 ? twice_area[i] : -twice_area[i];
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
