// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_FITTING_ZONES_H
#define CGAL_PART_DECOMPOSITION_FITTING_ZONES_H

#include <CGAL/Part_decomposition/Adaptive_grid.h>
#include <CGAL/Part_decomposition/stage_results.h>
#include <CGAL/Part_decomposition/Voxel_grid.h>
#include <CGAL/Part_decomposition/parameters.h>
#include <CGAL/Part_decomposition/input_validation.h>
#include <CGAL/Part_decomposition/internal/grid/leaf_distance.h>
#include <CGAL/Part_decomposition/internal/toolbox/toolbox.h>

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
  bool use_freeze_zone = Method_variant().use_freeze_zone;
};

template <typename NamedParameters>
Fitting_zone_parameters read_fitting_zone_parameters(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  Fitting_zone_parameters p;
  p.flow_zone_tolerance =
    choose_parameter(get_parameter(np, internal_np::flow_zone_tolerance), defaults::flow_zone_tolerance);
  p.use_freeze_zone = internal::method_switches(np).use_freeze_zone;
  check_non_negative(p.flow_zone_tolerance, "flow_zone_tolerance");
  return p;
}

// The fused prior on the leaves of `grid`. A leaf finer than the prior's finest voxels takes the
// resolution of the prior voxel that holds it if that voxel holds a sample, and its class: the
// whole of a Freeze voxel is Freeze, a Flow voxel carries the surface only in its leaves the
// surface may cross (their centre within half their diagonal of it). A leaf as large as a prior
// voxel or larger holds the prior voxels of its box: Freeze if one is, Flow if one holds a
// sample, and the finest of their resolutions.
inline void project_prior_on_leaves(const Hierarchical_prior& prior, const Adaptive_grid& grid,
                                    const std::vector<double>& field, Fitting_zones& zones)
{
  const Voxel_grid<Voxel_class>& classes = prior.classes;
  const int r = classes.resolution(), D = Adaptive_grid::depth_of(grid.finest_resolution());
  const int shift = D - Adaptive_grid::depth_of(r);
  const std::size_t n = grid.number_of_leaves();
  zones.classes.assign(n, Voxel_class::EMPTY);
  zones.leaf_resolution.assign(n, 0);
  for(std::size_t l = 0; l < n; ++l)
  {
    const bool crossed = std::abs(field[l]) <= 0.5 * std::sqrt(3.) * grid.size(l) * (1. + 1e-9);
    const Adaptive_grid::Voxel& c = grid.corner(l);
    const int w = int(grid.width(l) >> shift); // in prior voxels, 0 for a finer leaf
    const int i0 = int(c[0] >> shift), j0 = int(c[1] >> shift), k0 = int(c[2] >> shift);
    if(w == 0)
    {
      const std::size_t v = classes.index(i0, j0, k0);
      zones.leaf_resolution[l] = prior.leaf_resolution[v];
      if(classes[v] == Voxel_class::FREEZE || (classes[v] == Voxel_class::FLOW && crossed)) zones.classes[l] = classes[v];
      continue;
    }
    Voxel_class cls = Voxel_class::EMPTY;
    std::uint16_t res = 0;
    for(int k = k0; k < k0 + w; ++k)
      for(int j = j0; j < j0 + w; ++j)
        for(int i = i0; i < i0 + w; ++i)
        {
          const std::size_t v = classes.index(i, j, k);
          if(classes[v] == Voxel_class::EMPTY) continue;
          if(cls != Voxel_class::FREEZE) cls = classes[v];
          res = (std::max)(res, prior.leaf_resolution[v]);
        }
    zones.classes[l] = cls;
    zones.leaf_resolution[l] = res;
  }
}

// compute_fitting_zones() with its parameters read.
template <typename ConcurrencyTag>
Fitting_zones compute_fitting_zones(const Hierarchical_prior& prior, const Truncated_signed_distance_field& tsdf,
                                    const std::vector<int>& fitting_resolutions, const Fitting_zone_parameters& parameters)
{
  static_check_concurrency_tag<ConcurrencyTag>();
  for(int r_fit : fitting_resolutions) check_parameter(r_fit > 0, "fitting_resolutions", "positive");
  const Adaptive_grid& grid = tsdf.grid;
  check_parameter(tsdf.values.size() == grid.number_of_leaves() && prior.classes.resolution() > 0 &&
                    grid.finest_resolution() >= prior.classes.resolution(),
                  "the distance field", "computed on a grid at least as fine as the prior");
  Fitting_zones zones;
  project_prior_on_leaves(prior, grid, tsdf.values, zones);
  const std::size_t n = grid.number_of_leaves();
  zones.occupied.assign(n, 0);
  zones.exterior.assign(n, 0);
  double occupied_reach = 0.; // the largest half diagonal of an occupied leaf
  // The exterior is what the distance field's sign puts outside, not the flood fill of the
  // paper's fillholes(): a hole in the surface would let the fill into the interior.
  for(std::size_t l = 0; l < n; ++l)
  {
    zones.occupied[l] = zones.classes[l] != Voxel_class::EMPTY ? 1 : 0;
    zones.exterior[l] = (zones.occupied[l] == 0 && !std::signbit(tsdf.values[l])) ? 1 : 0;
    if(zones.occupied[l]) occupied_reach = (std::max)(occupied_reach, 0.5 * std::sqrt(3.) * grid.size(l));
  }
  zones.freeze_zone = zones.exterior;
  if(parameters.use_freeze_zone)
    for(std::size_t l = 0; l < n; ++l)
      if(zones.classes[l] == Voxel_class::FREEZE) zones.freeze_zone[l] = 1;

  // One search of the hull serves every dilation radius. An exterior leaf farther from the
  // surface than the radius plus the reach of an occupied leaf is farther from every hull centre.
  const double voxel = 1. / double(prior.classes.resolution());
  double largest = 0.;
  for(int r_fit : fitting_resolutions) largest = (std::max)(largest, parameters.flow_zone_tolerance / double(r_fit));
  const std::vector<double> to_hull = leaf_squared_distances<ConcurrencyTag>(
    grid, [&](std::size_t l) { return zones.exterior[l] == 0; },
    [&](std::size_t l) { return tsdf.values[l] < largest + occupied_reach + voxel; });
  for(int r_fit : fitting_resolutions)
  {
    if(zones.flow_zone.count(r_fit) != 0) continue;
    const double radius = parameters.flow_zone_tolerance / double(r_fit);
    const double limit = radius * radius * (1. + 1e-12) + 1e-9 * voxel * voxel; // as in internal::dilate()
    std::vector<std::uint8_t> flow(n, 0);
    for(std::size_t l = 0; l < n; ++l) flow[l] = to_hull[l] <= limit ? 1 : 0;
    zones.flow_zone.emplace(r_fit, std::move(flow));
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
on the leaves of the grid of the distance field `tsdf`, from the fused Flow/Freeze prior `prior`
and the sign of the field:

- `classes` and `leaf_resolution`: the prior projected on the leaves. A leaf finer than the
  prior's finest voxels takes the fused resolution \f$\mathcal{R}_{map}\f$ of the prior voxel that
  holds it if that voxel holds a surface sample, and its class: the whole of a `FREEZE` voxel is
  `FREEZE`, a `FLOW` voxel is `FLOW` in the leaves the surface may cross (their centre lies within
  half their diagonal of the surface). A leaf as large as a prior voxel or larger holds the prior
  voxels of its box: it is `FREEZE` if one of them is, `FLOW` if one holds a sample, and takes
  the finest of their resolutions;
- `occupied` = `FLOW` or `FREEZE` leaves;
- `exterior` (`ext_void`) = the leaves that are not occupied and whose centre the distance field
  puts outside (a non-negative value);
- `freeze_zone` = `FREEZE` leaves or `exterior` (`exterior` only if `use_freeze_zone` is `false`);
- for each \f$r_{fit}\f$ of `fitting_resolutions`: `flow_zone[r_fit]` = the leaves whose centre is
  within \f$t / r_{fit}\f$ (Euclidean, between leaf centres) of the centre of a non-exterior leaf,
  \f$t\f$ being `flow_zone_tolerance`, in voxels of \f$r_{fit}\f$ (paper Table A.1:
  \f$2\Delta^{r_{fit}}\f$).

The paper takes the exterior as the complement of `fillholes(occupied)`, the unoccupied voxels that
a flood fill reaches from the border of the grid. A hole in the surface wider than a voxel lets
that fill into the interior, which then becomes Freeze and leaves the fitter nothing to grow in; the
sign of the distance field (see `Tsdf_sign_method`) survives holes. On a closed surface the two
differ only where an outside pocket is walled off by occupied voxels (a gap narrower than a voxel,
such as between two fingers), which the fill takes as inside; the
`Tsdf_sign_method::FLOOD_FILL` sign is the paper's rule; `benchmark/Part_decomposition/RESULTS.md` measures both.

The distances between leaf centres are found in a kd-tree of the non-exterior leaves next to the
exterior: on a uniform grid they are exact, on an adaptive grid they are the distances to the
nearest of those leaves.

\par Complexity
\f$O(n \log n)\f$ for the \f$n\f$ leaves of the grid.

\tparam ConcurrencyTag enables sequential versus parallel computation (`CGAL::Sequential_tag`,
        `CGAL::Parallel_tag`, `CGAL::Parallel_if_available_tag`); the result does not depend on it.
\tparam NamedParameters a sequence of named parameters

\param prior the Flow/Freeze prior of the shape (`compute_flow_freeze_prior()`)
\param tsdf the distance field of the shape on its adaptive grid (`compute_tsdf()`): its sign tells
       the inside from the outside
\param fitting_resolutions the fitting resolutions \f$r_{fit}\f$ (paper: \f$\min(r, 32)\f$ for
       \f$r \in \{16, 32, 64\}\f$, i.e.\ 16 and 32)
\param np an optional sequence of named parameters; this function reads `flow_zone_tolerance` and
`method_variant` (its switch `use_freeze_zone`) (\ref PD_ParameterTable)

\returns the zones; `flow_zone` has one entry per distinct fitting resolution.

\throws Invalid_input with `Input_error::INVALID_PARAMETER` if a fitting resolution is not
        positive, the tolerance is negative or not finite, or the grid of the distance field is
        coarser than the prior's finest resolution.
*/
template <typename ConcurrencyTag = CGAL::Sequential_tag,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Fitting_zones compute_fitting_zones(const Hierarchical_prior& prior, const Truncated_signed_distance_field& tsdf,
                                    const std::vector<int>& fitting_resolutions,
                                    const NamedParameters& np = CGAL::parameters::default_values())
{
  return internal::compute_fitting_zones<ConcurrencyTag>(prior, tsdf, fitting_resolutions,
                                                         internal::read_fitting_zone_parameters(np));
}

} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_FITTING_ZONES_H
