// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_FLOW_FREEZE_PRIOR_H
#define CGAL_PART_DECOMPOSITION_FLOW_FREEZE_PRIOR_H

#include <CGAL/Part_decomposition/Voxel_grid.h>
#include <CGAL/Part_decomposition/normalization.h>
#include <CGAL/Part_decomposition/parameters.h>
#include <CGAL/Part_decomposition/topology_score.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Part_decomposition {

/*!
\ingroup PkgPartDecompositionRef
The hierarchical Flow/Freeze prior (paper Sec. 3.2, App. E.1): the per-resolution topology
score fields, fused on an octree and projected on the finest grid.
*/
struct Hierarchical_prior
{
  /// the resolutions, coarse to fine, each twice the previous one (default 16, 32, 64).
  std::vector<int> resolutions;
  /// the score field and Flow/Freeze cut at each resolution, in the order of `resolutions`.
  std::vector<Topology_score_field> fields;
  /// the class of the fused leaf that contains each voxel of the finest grid; `EMPTY` outside
  /// the surface support of the finest grid.
  Voxel_grid<Voxel_class> classes;
  /// \f$\mathcal{R}_{map}\f$: the resolution of the fused leaf that contains each voxel of the
  /// finest grid, 0 for empty voxels.
  Voxel_grid<std::uint16_t> leaf_resolution;
  /// the number of `FLOW` leaves of the fused octree at each resolution.
  std::vector<std::size_t> number_of_flow_leaves;
  /// the number of `FREEZE` leaves of the fused octree at each resolution.
  std::vector<std::size_t> number_of_freeze_leaves;
  /// the map from input coordinates to the normalized cube the grids live in.
  Normalization normalization;
};

} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_FLOW_FREEZE_PRIOR_H
