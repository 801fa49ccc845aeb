// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_TOPOLOGY_SCORE_H
#define CGAL_PART_DECOMPOSITION_TOPOLOGY_SCORE_H

#include <CGAL/Part_decomposition/Voxel_grid.h>
#include <CGAL/Part_decomposition/normalization.h>
#include <CGAL/Part_decomposition/parameters.h>

#include <cstddef>
#include <cstdint>

namespace CGAL {
namespace Part_decomposition {

/*!
\ingroup PkgPartDecompositionRef
The voxel cues, the topology score \f$S_B\f$ (paper Eq. 3) and its Flow/Freeze cut (Eq. 4, 5) at
one resolution `r`. Grids have resolution `r`; empty voxels (no sample) hold 0 and are not part of
the field.
*/
struct Topology_score_field
{
  /// the resolution `r`.
  int resolution = 0;
  /// \f$n_i\f$: the number of surface samples in each voxel.
  Voxel_grid<std::uint32_t> sample_count;
  /// \f$\mu^\kappa_i\f$: the mean of the face curvature cue over the samples of each voxel.
  Voxel_grid<double> curvature_mean;
  /// \f$\sigma^\kappa_i\f$: the standard deviation of the face curvature cue in each voxel.
  Voxel_grid<double> curvature_deviation;
  /// \f$\Delta^\kappa_i\f$: the magnitude of the gradient of the dense \f$\mu^\kappa\f$ field
  /// (unit voxel spacing).
  Voxel_grid<double> curvature_gradient;
  /// \f$\phi_{norm}\f$: the mean normal deviation of the samples of each voxel.
  Voxel_grid<double> normal_deviation;
  /// \f$S_B\f$: the topology score.
  Voxel_grid<double> score;
  /// the Flow/Freeze cut: `FREEZE` where \f$S_B \geq \tau_\alpha\f$, `FLOW` elsewhere in the field.
  Voxel_grid<Voxel_class> classes;
  /// \f$\tau_\alpha\f$: the \f$(1-\alpha)\f$-quantile of the score over the active voxels.
  double threshold = 0.;
  /// the number of voxels with at least one sample.
  std::size_t number_of_active_voxels = 0;
  /// the number of `FREEZE` voxels.
  std::size_t number_of_freeze_voxels = 0;
};

} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_TOPOLOGY_SCORE_H
