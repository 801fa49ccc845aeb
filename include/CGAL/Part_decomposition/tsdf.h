// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_TSDF_H
#define CGAL_PART_DECOMPOSITION_TSDF_H

#include <CGAL/Part_decomposition/Voxel_grid.h>
#include <CGAL/Part_decomposition/normalization.h>
#include <CGAL/Part_decomposition/parameters.h>

namespace CGAL {
namespace Part_decomposition {

/*!
\ingroup PkgPartDecompositionRef
How the sign of the distance field is decided.
*/
enum class Tsdf_sign_method
{
  AUTOMATIC,      ///< `INSIDE_TEST` for closed meshes without self-intersection, `WINDING_NUMBER` otherwise
  INSIDE_TEST,    ///< exact inside test by ray parity (closed, consistently oriented meshes only)
  WINDING_NUMBER, ///< generalized winding number near the surface, exterior flood fill elsewhere
  FLOOD_FILL      ///< exterior flood fill of the grid around the surface voxels only
};

/*!
\ingroup PkgPartDecompositionRef
A truncated signed distance field \f$d_\mathcal{M}\f$ of a mesh sampled at the voxel centres of a
grid of the normalized cube: negative inside, positive outside, clipped to
\f$[-\tau, \tau]\f$.
*/
struct Truncated_signed_distance_field
{
  /// the signed distances in normalized units, clipped to `[-truncation, truncation]`.
  Voxel_grid<double> values;
  /// \f$\tau\f$ in normalized units.
  double truncation = 0.;
  /// the map from input coordinates to the normalized cube.
  Normalization normalization;
  /// the sign method actually used (never `AUTOMATIC`).
  Tsdf_sign_method sign_method = Tsdf_sign_method::AUTOMATIC;
};

} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_TSDF_H
