// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_FITTING_ZONES_H
#define CGAL_PART_DECOMPOSITION_FITTING_ZONES_H

#include <CGAL/Part_decomposition/stage_results.h>
#include <CGAL/Part_decomposition/Voxel_grid.h>
#include <CGAL/Part_decomposition/parameters.h>
#include <CGAL/Part_decomposition/internal/grid_morphology.h>
#include <CGAL/Part_decomposition/internal/parameter_checks.h>
#include <CGAL/Part_decomposition/internal/toolbox.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Part_decomposition {

namespace internal {

// r_fit of each stage: min(r, cap); a cap of 0 stands for the resolution before the finest, or
// half the only resolution.
inline std::vector<int> stage_fitting_resolutions(const std::vector<int>& resolutions, int cap = 0)
{
  check_parameter(cap >= 0, "fitting_resolution_cap");
  std::vector<int> out;
  if(resolutions.empty()) return out;
  if(cap == 0)
    cap = resolutions.size() >= 2 ? resolutions[resolutions.size() - 2] : (std::max)(1, resolutions.back() / 2);
  for(int r : resolutions) out.push_back((std::min)(r, cap));
  return out;
}

// The named parameters of compute_fitting_zones(), also read by fit_superquadrics().
struct Fitting_zone_parameters
{
  double flow_zone_tolerance = defaults::flow_zone_tolerance;
  bool use_freeze_zone = defaults::use_freeze_zone;
};

template <typename NamedParameters>
Fitting_zone_parameters read_fitting_zone_parameters(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  Fitting_zone_parameters p;
  p.flow_zone_tolerance =
    choose_parameter(get_parameter(np, internal_np::flow_zone_tolerance), defaults::flow_zone_tolerance);
  p.use_freeze_zone = choose_parameter(get_parameter(np, internal_np::use_freeze_zone), defaults::use_freeze_zone);
  check_non_negative(p.flow_zone_tolerance, "flow_zone_tolerance");
  return p;
}

// compute_fitting_zones() with its parameters read.
template <typename ConcurrencyTag>
Fitting_zones compute_fitting_zones(const Voxel_grid<Voxel_class>& classes, const Voxel_grid<double>& field,
                                    const std::vector<int>& fitting_resolutions, const Fitting_zone_parameters& parameters)
{
  static_check_concurrency_tag<ConcurrencyTag>();
  for(int r_fit : fitting_resolutions) check_parameter(r_fit > 0, "fitting_resolutions", "positive");
  check_parameter(field.resolution() == classes.resolution(), "the distance field",
                  "of the resolution of the classes");

  const int r = classes.resolution();
  Fitting_zones zones;
  zones.occupied = Voxel_grid<std::uint8_t>(r, 0);
  zones.exterior = Voxel_grid<std::uint8_t>(r, 0);
  // The exterior is what the distance field's sign puts outside, not the flood fill of the
  // paper's fillholes(): a hole in the surface would let the fill into the interior.
  for(std::size_t i = 0; i < classes.size(); ++i)
  {
    zones.occupied[i] = classes[i] != Voxel_class::EMPTY ? 1 : 0;
    zones.exterior[i] = (zones.occupied[i] == 0 && !std::signbit(field[i])) ? 1 : 0;
  }
  zones.freeze_zone = zones.exterior;
  if(parameters.use_freeze_zone)
    for(std::size_t i = 0; i < classes.size(); ++i)
      if(classes[i] == Voxel_class::FREEZE) zones.freeze_zone[i] = 1;

  // One distance transform of the hull serves every dilation radius.
  const Voxel_grid<double> to_hull = squared_distance_transform<ConcurrencyTag>(complement(zones.exterior));
  for(int r_fit : fitting_resolutions)
  {
    if(zones.flow_zone.count(r_fit) != 0) continue;
    const double radius = parameters.flow_zone_tolerance * double(r) / double(r_fit);
    const double limit = radius * radius * (1. + 1e-12) + 1e-9; // as in internal::dilate()
    Voxel_grid<std::uint8_t> flow(r, 0), outside(r, 0);
    for(std::size_t i = 0; i < flow.size(); ++i)
    {
      flow[i] = to_hull[i] <= limit ? 1 : 0;
      outside[i] = 1 - flow[i];
    }
    const Voxel_grid<double> d2 = squared_distance_transform<ConcurrencyTag>(outside, true);
    Voxel_grid<double> distance(r, 0.);
    for(std::size_t i = 0; i < distance.size(); ++i)
      if(flow[i] != 0) distance[i] = std::sqrt(d2[i]) / double(r);
    zones.flow_zone.emplace(r_fit, std::move(flow));
    zones.flow_zone_distance.emplace(r_fit, std::move(distance));
  }
  return zones;
}

} // namespace internal

/*!
\ingroup PkgPartDecompositionRef
returns the fitting resolutions \f$r_{fit}\f$ of the stages of a prior computed at `resolutions`
(coarse to fine), without repetition, in stage order: \f$r_{fit} = \min(r, cap)\f$. A `cap` of 0
(the default) stands for \f$r_{L-1}\f$, the resolution before the finest (`{16, 32}` for
`{16, 32, 64}`), or half the resolution if there is only one; the paper's literal rule is
`cap = 32`. These are the resolutions `fit_superquadrics()` needs zones at, with the same cap as
its named parameter `fitting_resolution_cap`.
\throws Invalid_input (`INVALID_PARAMETER`) if `cap` is negative.
*/
inline std::vector<int> fitting_resolutions(const std::vector<int>& resolutions, int cap = 0)
{
  std::vector<int> distinct;
  for(int r_fit : internal::stage_fitting_resolutions(resolutions, cap))
    if(std::find(distinct.begin(), distinct.end(), r_fit) == distinct.end()) distinct.push_back(r_fit);
  return distinct;
}

/*!
\ingroup PkgPartDecompositionRef
builds the volumetric zones of the superquadric fitter (paper App.\ E.2 (A.1), Alg.\ A.2 lines 1-4)
from the fused Flow/Freeze classes on the finest grid, of resolution `r = classes.resolution()`,
and the sign of the distance field `tsdf` on the same grid:

- `occupied` = `FLOW` or `FREEZE` voxels;
- `exterior` (`ext_void`) = the voxels that are not occupied and whose centre the distance field
  puts outside (a non-negative value);
- `freeze_zone` = `FREEZE` voxels or `exterior` (`exterior` only if `use_freeze_zone` is `false`);
- for each \f$r_{fit}\f$ of `fitting_resolutions`: `flow_zone[r_fit]` = the voxels whose centre is
  within \f$t \cdot r / r_{fit}\f$ voxels (Euclidean, between voxel centres) of a non-exterior voxel,
  \f$t\f$ being the Flow-zone tolerance in voxels of \f$r_{fit}\f$; and `flow_zone_distance[r_fit]`
  = the Euclidean distance, in normalized units, from the centre of each voxel of the Flow zone to
  the centre of the nearest voxel outside it (the layer just outside the grid counts as outside),
  0 outside the zone.

The paper takes the exterior as the complement of `fillholes(occupied)`, the unoccupied voxels that
a flood fill reaches from the border of the grid. A hole in the surface wider than a voxel lets
that fill into the interior, which then becomes Freeze and leaves the fitter nothing to grow in; the
sign of the distance field (see `Tsdf_sign_method`) survives holes. On a closed surface the two
differ only where an outside pocket is walled off by occupied voxels (a gap narrower than a voxel,
such as between two fingers), which the fill takes as inside; the
`Tsdf_sign_method::FLOOD_FILL` sign is the paper's rule; `benchmark/Part_decomposition/RESULTS.md` measures both.

The morphology is exact (linear-time Euclidean distance transforms) and deterministic.

\par Complexity
Linear in the number of voxels \f$r^3\f$ for each distinct fitting resolution (exact linear-time
Euclidean distance transforms).

\tparam ConcurrencyTag enables sequential versus parallel computation (`CGAL::Sequential_tag`,
        `CGAL::Parallel_tag`, `CGAL::Parallel_if_available_tag`); the result does not depend on it.
\tparam NamedParameters a sequence of named parameters

\param classes the class of every voxel of the finest grid (the hierarchical prior projected on it)
\param tsdf the distance field of the shape on the same grid (`compute_tsdf()`): its sign tells the
       inside from the outside
\param fitting_resolutions the fitting resolutions \f$r_{fit}\f$ (paper: \f$\min(r, 32)\f$ for
       \f$r \in \{16, 32, 64\}\f$, i.e.\ 16 and 32)
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{flow_zone_tolerance}
    \cgalParamDescription{the dilation of the Flow zone, in voxels of each fitting resolution
                          (paper Table A.1: \f$2\Delta^{r_{fit}}\f$)}
    \cgalParamType{`double`, non-negative}
    \cgalParamDefault{`2.0`}
  \cgalParamNEnd
  \cgalParamNBegin{use_freeze_zone}
    \cgalParamDescription{whether `FREEZE` voxels belong to the Freeze zone; `false` leaves the
                          exterior only (the paper's "w/o Freeze" ablation)}
    \cgalParamType{`bool`}
    \cgalParamDefault{`true`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the zones; `flow_zone` and `flow_zone_distance` have one entry per distinct fitting
          resolution.

\throws Invalid_input with `Input_error::INVALID_PARAMETER` if a fitting resolution is not
        positive, the tolerance is negative or not finite, or the distance field has another
        resolution than `classes`.
*/
template <typename ConcurrencyTag = CGAL::Sequential_tag,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Fitting_zones compute_fitting_zones(const Voxel_grid<Voxel_class>& classes,
                                    const Truncated_signed_distance_field& tsdf,
                                    const std::vector<int>& fitting_resolutions,
                                    const NamedParameters& np = CGAL::parameters::default_values())
{
  return internal::compute_fitting_zones<ConcurrencyTag>(classes, tsdf.values, fitting_resolutions,
                                                         internal::read_fitting_zone_parameters(np));
}

} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_FITTING_ZONES_H
