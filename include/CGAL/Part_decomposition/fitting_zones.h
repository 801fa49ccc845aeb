// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_FITTING_ZONES_H
#define CGAL_PART_DECOMPOSITION_FITTING_ZONES_H

#include <CGAL/Part_decomposition/Voxel_grid.h>
#include <CGAL/Part_decomposition/parameters.h>

#include <cstdint>
#include <map>

namespace CGAL {
namespace Part_decomposition {

/*!
\ingroup PkgPartDecompositionRef
The volumetric zones that constrain the superquadric fitter (paper App. E.2 (A.1), Alg. A.2
lines 1-4), on the finest grid of the prior. Masks hold 1 inside the zone and 0 outside.
*/
struct Fitting_zones
{
  /// the carrier: `FLOW` or `FREEZE` voxels of the prior.
  Voxel_grid<std::uint8_t> occupied;
  /// `ext_void`: the complement of the hole-filled carrier, the exterior of the shape.
  Voxel_grid<std::uint8_t> exterior;
  /// \f$\Omega_{freeze}\f$: the `FREEZE` voxels and the exterior.
  Voxel_grid<std::uint8_t> freeze_zone;
  /// \f$\Omega_{flow}\f$ for each fitting resolution \f$r_{fit}\f$: the non-exterior voxels
  /// dilated by the Flow-zone tolerance (in voxels of \f$r_{fit}\f$).
  std::map<int, Voxel_grid<std::uint8_t> > flow_zone;
  /// for each fitting resolution, the Euclidean distance (normalized units) from each voxel of the
  /// Flow zone to the nearest voxel outside it; 0 outside the zone.
  std::map<int, Voxel_grid<double> > flow_zone_distance;
};

} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_FITTING_ZONES_H
