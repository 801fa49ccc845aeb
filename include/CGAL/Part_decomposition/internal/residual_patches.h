// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_RESIDUAL_PATCHES_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_RESIDUAL_PATCHES_H

// The residual patches of the assignment (paper Sec. 3.4): surface details that no primitive
// explains, kept apart instead of being forced onto a primitive.

#include <CGAL/Part_decomposition/Superquadric.h>
#include <CGAL/Part_decomposition/Voxel_grid.h>
#include <CGAL/Part_decomposition/normalization.h>
#include <CGAL/Part_decomposition/internal/face_adjacency.h>
#include <CGAL/Part_decomposition/internal/piece_regions.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

// Per face, 1 if its patch is residual: at least half of the patch's area lies in Freeze voxels
// of the prior (`classes`) and its faces are on average farther than `tolerance` (normalized units)
// from the primitive (`primitives`, normalized) of their part (`part_to_primitive[part[i]]`).
template <typename GeomTraits>
std::vector<std::uint8_t> residual_faces(const Face_adjacency& adj, const Face_corners& corners,
                                         const std::vector<std::size_t>& patch, std::size_t number_of_patches,
                                         const std::vector<std::size_t>& part,
                                         const std::vector<std::size_t>& part_to_primitive,
                                         const std::vector<Superquadric<GeomTraits> >& primitives,
                                         const Voxel_grid<Voxel_class>& classes, const Normalization& normalization,
                                         double tolerance)
{
  typedef typename GeomTraits::Point_3 Point_3;
  std::vector<double> area(number_of_patches, 0.), frozen(number_of_patches, 0.), distance(number_of_patches, 0.);
  for(std::size_t i = 0; i < adj.number_of_faces; ++i)
  {
    const std::size_t q = part_to_primitive[part[i]];
    if(q >= primitives.size()) continue;
    const Eigen::Vector3d c = (corners(i, 0) + corners(i, 1) + corners(i, 2)) / 3.;
    const std::array<double, 3> u = normalization.to_unit(c[0], c[1], c[2]);
    const std::array<int, 3> v = classes.locate(u[0], u[1], u[2]);
    const double a = adj.area[i];
    area[patch[i]] += a;
    if(classes(v[0], v[1], v[2]) == Voxel_class::FREEZE) frozen[patch[i]] += a;
    distance[patch[i]] += a * std::abs(primitives[q].signed_distance(Point_3(u[0], u[1], u[2])));
  }
  std::vector<std::uint8_t> residual(adj.number_of_faces, 0);
  for(std::size_t i = 0; i < adj.number_of_faces; ++i)
  {
    const std::size_t p = patch[i];
    residual[i] = area[p] > 0. && frozen[p] >= 0.5 * area[p] && distance[p] > tolerance * area[p];
  }
  return residual;
}

// Moves each edge-connected set of residual faces to a part of its own, appended after the
// existing parts with no primitive; returns the number of parts added.
inline std::size_t split_residual_parts(const Face_adjacency& adj, const std::vector<std::uint8_t>& residual,
                                        std::vector<std::size_t>& part, std::vector<std::size_t>& part_to_primitive,
                                        std::size_t no_primitive)
{
  std::vector<std::size_t> component;
  face_components(adj, [&](std::size_t i, int k) { return residual[i] && residual[adj.neighbor[3 * i + k]]; },
                  component);
  const std::size_t first = part_to_primitive.size();
  std::vector<std::size_t> id_of(adj.number_of_faces, no_primitive);
  for(std::size_t i = 0; i < adj.number_of_faces; ++i)
  {
    if(!residual[i]) continue;
    std::size_t& id = id_of[component[i]];
    if(id == no_primitive)
    {
      id = part_to_primitive.size();
      part_to_primitive.push_back(no_primitive);
    }
    part[i] = id;
  }
  return part_to_primitive.size() - first;
}

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_RESIDUAL_PATCHES_H
