// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_SUPERQUADRIC_FITTING_H
#define CGAL_PART_DECOMPOSITION_SUPERQUADRIC_FITTING_H

#include <CGAL/Part_decomposition/stage_results.h>
#include <CGAL/Part_decomposition/Superquadric.h>
#include <CGAL/Part_decomposition/Adaptive_grid.h>
#include <CGAL/Part_decomposition/fitting_zones.h>
#include <CGAL/Part_decomposition/parameters.h>
#include <CGAL/Part_decomposition/input_validation.h>
#include <CGAL/Part_decomposition/internal/fitting/primitive_merging.h>
#include <CGAL/Part_decomposition/internal/fitting/superquadric_fitter.h>
#include <CGAL/Part_decomposition/internal/toolbox/toolbox.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/tags.h>

#include <array>
#include <cstddef>
#include <iostream>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Part_decomposition {

/// \cond SKIP_IN_MANUAL
namespace internal {

// The named parameters of fit_superquadrics() (see its documentation), as read by
// read_fitting_parameters().
struct Fitting_parameters
{
  double flow_zone_tolerance = defaults::flow_zone_tolerance;
  std::vector<double> trust_region_scales{defaults::trust_region_scales.begin(), defaults::trust_region_scales.end()};
  double body_seed_threshold = defaults::body_seed_threshold;
  double minimum_body_volume = defaults::minimum_body_volume;
  double minimum_surface_volume = defaults::minimum_surface_volume;
  double exterior_penalty = defaults::exterior_penalty;
  double coverage_target = defaults::coverage_target;
  double roi_radius = defaults::roi_radius;
  Interior_weight_mode interior_weight_mode = Method_variant().interior_weight_mode;
  std::size_t maximum_number_of_primitives = defaults::maximum_number_of_primitives;
  bool use_freeze_zone = Method_variant().use_freeze_zone;
  bool use_tsdf_guidance = Method_variant().use_tsdf_guidance;
  bool use_body_seeds = Method_variant().use_body_seeds;
  int fitting_resolution_cap = defaults::fitting_resolution_cap;
  bool use_exterior_band_samples = Method_variant().use_exterior_band_samples;
  bool use_reachable_regions = Method_variant().use_reachable_regions;
  bool use_seed_exclusion = Method_variant().use_seed_exclusion;
  int maximum_solver_evaluations = defaults::maximum_solver_evaluations;
  std::size_t maximum_rejections_in_a_row = defaults::maximum_rejections_in_a_row;
  bool merge_primitives = Method_variant().merge_primitives;
  double minimum_merge_iou = defaults::minimum_merge_iou;
  bool verbose = false;
};

// The one reader of the named parameters of fit_superquadrics().
template <typename NamedParameters>
Fitting_parameters read_fitting_parameters(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  Fitting_parameters p;
  const Method_variant switches = internal::method_switches(np);
  const Fitting_zone_parameters zone_parameters = read_fitting_zone_parameters(np);
  p.flow_zone_tolerance = zone_parameters.flow_zone_tolerance;
  p.use_freeze_zone = zone_parameters.use_freeze_zone;
  const auto scales = choose_parameter(get_parameter(np, internal_np::trust_region_scales), defaults::trust_region_scales);
  p.trust_region_scales.assign(scales.begin(), scales.end());
  p.body_seed_threshold = choose_parameter(get_parameter(np, internal_np::body_seed_threshold), defaults::body_seed_threshold);
  p.minimum_body_volume = choose_parameter(get_parameter(np, internal_np::minimum_body_volume), defaults::minimum_body_volume);
  p.minimum_surface_volume =
    choose_parameter(get_parameter(np, internal_np::minimum_surface_volume), defaults::minimum_surface_volume);
  p.exterior_penalty = choose_parameter(get_parameter(np, internal_np::exterior_penalty), defaults::exterior_penalty);
  p.coverage_target = choose_parameter(get_parameter(np, internal_np::coverage_target), defaults::coverage_target);
  p.roi_radius = choose_parameter(get_parameter(np, internal_np::roi_radius), defaults::roi_radius);
  p.interior_weight_mode = switches.interior_weight_mode;
  p.maximum_number_of_primitives = checked_integer<std::size_t>(
    choose_parameter(get_parameter(np, internal_np::maximum_number_of_primitives), defaults::maximum_number_of_primitives),
    1, "maximum_number_of_primitives");
  p.use_tsdf_guidance = switches.use_tsdf_guidance;
  p.use_body_seeds = switches.use_body_seeds;
  p.fitting_resolution_cap = checked_integer<int>(
    choose_parameter(get_parameter(np, internal_np::fitting_resolution_cap), defaults::fitting_resolution_cap),
    0, "fitting_resolution_cap");
  p.use_exterior_band_samples = switches.use_exterior_band_samples;
  p.use_reachable_regions = switches.use_reachable_regions;
  p.use_seed_exclusion = switches.use_seed_exclusion;
  p.maximum_solver_evaluations = checked_integer<int>(
    choose_parameter(get_parameter(np, internal_np::maximum_solver_evaluations), defaults::maximum_solver_evaluations),
    1, "maximum_solver_evaluations");
  p.maximum_rejections_in_a_row = checked_integer<std::size_t>(
    choose_parameter(get_parameter(np, internal_np::maximum_rejections_in_a_row), defaults::maximum_rejections_in_a_row),
    0, "maximum_rejections_in_a_row");
  p.merge_primitives = switches.merge_primitives;
  p.minimum_merge_iou = choose_parameter(get_parameter(np, internal_np::minimum_merge_iou), defaults::minimum_merge_iou);
  p.verbose = choose_parameter(get_parameter(np, CGAL::internal_np::verbose), defaults::verbose);

  check_parameter(!p.trust_region_scales.empty(), "trust_region_scales");
  for(double eta : p.trust_region_scales) check_positive(eta, "trust_region_scales");
  check_positive(p.body_seed_threshold, "body_seed_threshold");
  check_non_negative(p.minimum_body_volume, "minimum_body_volume");
  check_non_negative(p.minimum_surface_volume, "minimum_surface_volume");
  check_non_negative(p.exterior_penalty, "exterior_penalty");
  check_parameter(p.coverage_target > 0. && p.coverage_target <= 1., "coverage_target");
  check_positive(p.roi_radius, "roi_radius");
  check_parameter(p.minimum_merge_iou > 0. && p.minimum_merge_iou <= 1., "minimum_merge_iou");
  return p;
}

// The types of the stage, for Superquadric_fitter.
template <typename GeomTraits>
struct Fitting_types
{
  typedef Superquadric_fitting_result<GeomTraits> Result;
  typedef Hierarchical_prior Prior;
  typedef Truncated_signed_distance_field Field;
  typedef Fitting_zones Zones;
  typedef Fitting_parameters Parameters;
};

// Fit_sdf_settings (internal/fit_sdf.h) defaults to the package's defaults.
static_assert(Fit_sdf_settings().exterior_penalty == defaults::exterior_penalty &&
                Fit_sdf_settings().maximum_evaluations == defaults::maximum_solver_evaluations,
              "Fit_sdf_settings and parameters.h disagree");

// The fraction of Freeze voxels along the common surface of two primitives from which they are
// never merged: a joint the prior marked (tuned with minimum_merge_iou, see the manual).
constexpr double primitive_merge_freeze_fraction = 0.2;

// The prior and the distance field come from other calls: a mismatch would index out of the grids.
inline void check_prior_and_distance_field(const Hierarchical_prior& prior, const Truncated_signed_distance_field& tsdf)
{
  bool consistent = !prior.resolutions.empty() && prior.resolutions.front() >= 1 &&
                    prior.resolutions.back() == prior.classes.resolution() &&
                    tsdf.values.size() == tsdf.grid.number_of_leaves() &&
                    tsdf.grid.finest_resolution() >= prior.classes.resolution() &&
                    std::abs(tsdf.voxel_size * double(prior.classes.resolution()) - 1.) < 1e-12;
  for(std::size_t l = 1; consistent && l < prior.resolutions.size(); ++l)
    consistent = prior.resolutions[l - 1] < prior.resolutions[l];
  check_parameter(consistent, "the prior and the distance field", "computed with the same voxel_resolutions");
}

inline void check_fitting_zones(const Fitting_zones& zones, const Truncated_signed_distance_field& tsdf,
                                const std::vector<int>& stage_fitting_resolutions)
{
  const std::size_t n = tsdf.grid.number_of_leaves();
  bool match = zones.freeze_zone.size() == n && zones.exterior.size() == n && zones.classes.size() == n &&
               zones.leaf_resolution.size() == n;
  for(int r_fit : stage_fitting_resolutions)
    match = match && zones.flow_zone.count(r_fit) == 1 && zones.flow_zone.at(r_fit).size() == n;
  check_parameter(match, "the fitting zones", "computed from this prior and distance field at its fitting_resolutions()");
}

// The leaves of the shape's volume that a primitive may claim: neither exterior nor Freeze, or, if
// there are none (every leaf of a thin shape is Freeze), all the leaves that are not exterior.
inline std::vector<std::size_t> claimable_volume(const Fitting_zones& zones)
{
  std::vector<std::size_t> leaves;
  for(std::size_t l = 0; l < zones.exterior.size(); ++l)
    if(!zones.freeze_zone[l]) leaves.push_back(l);
  if(leaves.empty())
    for(std::size_t l = 0; l < zones.exterior.size(); ++l)
      if(!zones.exterior[l]) leaves.push_back(l);
  return leaves;
}

// A fit that accepted no primitive on a shape that bounds a volume gets one: the box-like
// superquadric of the claimable volume on its principal axes, which claims it all. The parts then
// are those of the pieces and creases alone, each with a primitive. Returns false if there is no
// volume to stand for.
template <typename GeomTraits>
bool fall_back_to_one_primitive(Superquadric_fitting_result<GeomTraits>& result, const Fitting_zones& zones,
                                const Adaptive_grid& grid, const Normalization& normalization, int stage_resolution)
{
  const std::vector<std::size_t> leaves = claimable_volume(zones);
  if(leaves.empty()) return false;
  Part_box box;
  std::vector<Eigen::Vector3d> corners; // the box holds the leaves' cubes
  corners.reserve(8 * leaves.size());
  for(std::size_t l : leaves)
  {
    const std::array<double, 3> c = grid.center(l);
    const double v = grid.volume(l), h = 0.5 * grid.size(l);
    const Eigen::Vector3d p(c[0], c[1], c[2]);
    box.area += v;
    box.first += v * p;
    box.second += v * p * p.transpose();
    for(int k = 0; k < 8; ++k)
      corners.push_back(p + Eigen::Vector3d((k & 1) ? h : -h, (k & 2) ? h : -h, (k & 4) ? h : -h));
    result.labels[l] = 0;
  }
  fit_box_to_points(box, corners);
  const Superquadric<GeomTraits> sq = box_superquadric<GeomTraits>(box, Eigen::Vector3d::Zero());
  result.primitives.push_back(sq);
  result.input_primitives.push_back(sq.in_input_coordinates(normalization));
  result.stage_resolution.push_back(stage_resolution);
  result.body_seeded.push_back(false);
  result.seed_leaf.push_back(leaves[leaves.size() / 2]);
  result.semi_axis_scale.push_back(0.);
  result.fit_cost.push_back(0.);
  result.claimed_leaves.assign(1, leaves);
  return true;
}

// What `verbose` says when no superquadric was accepted.
template <typename GeomTraits>
void report_no_primitive(const Superquadric_fitting_result<GeomTraits>& result, bool fell_back)
{
  std::cerr << "no superquadric accepted: " << result.number_of_seeds << " seeds, "
            << result.rejected_by_flow_zone << " left the Flow zone, " << result.rejected_by_volume
            << " claimed less than V_min, " << result.rejected_degenerate << " had too few samples; "
            << (fell_back ? "one box-like superquadric of the whole volume stands for the shape ("
                              + std::to_string(result.claimed_leaves.front().size()) + " leaves)\n"
                          : "the shape bounds no volume on the grid\n");
}

// fit_superquadrics(): reads the parameters, checks the inputs, checks the given zones or
// computes them if `zones` is null, and runs the fitter.
template <typename ConcurrencyTag, typename GeomTraits, typename NamedParameters>
Superquadric_fitting_result<GeomTraits> fit_with_given_or_computed_zones(const Hierarchical_prior& prior,
                                                                         const Truncated_signed_distance_field& tsdf,
                                                                         const Fitting_zones* zones,
                                                                         const NamedParameters& np)
{
  static_check_concurrency_tag<ConcurrencyTag>();
  const Fitting_parameters parameters = read_fitting_parameters(np);
  check_prior_and_distance_field(prior, tsdf);
  const std::vector<int> fit_res = stage_fitting_resolutions(prior.resolutions, parameters.fitting_resolution_cap);
  Fitting_zones own_zones;
  if(zones == nullptr)
  {
    Fitting_zone_parameters zone_parameters;
    zone_parameters.flow_zone_tolerance = parameters.flow_zone_tolerance;
    zone_parameters.use_freeze_zone = parameters.use_freeze_zone;
    own_zones = compute_fitting_zones<ConcurrencyTag>(
      prior, tsdf, fitting_resolutions(prior.resolutions, parameters.fitting_resolution_cap), zone_parameters);
    zones = &own_zones;
  }
  else
    check_fitting_zones(*zones, tsdf, fit_res);
  Superquadric_fitter<ConcurrencyTag, Fitting_types<GeomTraits> > fitter(prior, tsdf, *zones, fit_res, parameters);
  Superquadric_fitting_result<GeomTraits> result = fitter.run();
  if(result.primitives.empty())
  {
    const bool fell_back =
      fall_back_to_one_primitive(result, *zones, tsdf.grid, prior.normalization, prior.resolutions.back());
    if(parameters.verbose) report_no_primitive(result, fell_back);
  }
  if(parameters.merge_primitives)
    merge_explained_primitives(result, zones->classes, tsdf, 1. / double(prior.resolutions.back()),
                               parameters.minimum_merge_iou, primitive_merge_freeze_fraction);
  return result;
}

} // namespace internal
/// \endcond

/*!
\ingroup PkgPartDecompositionRef
SDFSQFit (paper Alg.\ A.2, with FitSDF, Alg.\ A.3): fits superquadrics to the truncated signed
distance field of a shape, coarse to fine over the resolutions of the prior, growing them in the
Flow zone and stopping them at the Freeze zone.

For each stage \f$r\f$ (16, 32, 64), with \f$r_{fit} = \min(r, c)\f$, \f$c\f$ being
`fitting_resolution_cap` or by default the resolution before the finest (32), the valid set
\f$\Omega_{valid} = \{\mathcal{R}_{map} \le r\} \setminus \Omega_{freeze}\f$ is covered until a
fraction `coverage_target` of it is claimed (0.999 by default: the paper's 0.95 leaves thin
limbs, a few voxels each, without a primitive): a body seed is placed at the maximum of the
Euclidean distance transform of the unclaimed valid voxels if it reaches `body_seed_threshold`
voxels of \f$r_{fit}\f$ (never with `use_body_seeds = false`), otherwise a surface seed at the
centroid of the largest remaining 6-connected component; a superquadric is initialized there (a
ball of radius \f$\min(\Delta^{r_{fit}}, \mathrm{EDT}_{\Omega_{flow}}(s))\f$), fitted to the
samples of its region of interest with the trust-region scales \f$\eta\f$ (`trust_region_scales`)
in turn until its surface stays in the Flow zone, and accepted if the voxels within \f$2\Delta\f$
of it that are neither Freeze, claimed nor reserved for a finer stage number at least \f$V_{min}\f$
(`minimum_body_volume` or `minimum_surface_volume`).

Choices where the paper is silent or that depart from it (their measured effect is in the user
manual, \ref PD_Deviations):
- \f$\Omega_{Body}\f$ is the whole unclaimed valid volume (interior voxels included), not only
  its Flow carrier voxels, so that EDT maxima are centres of thick cross-sections.
- \f$\Delta\f$ of the sample band (\f$d_\mathcal{M} < 1.5\Delta\f$) and of
  \f$M_{fit} = \{\tilde d \le 2\Delta\}\f$ is the voxel of the finest grid; \f$V_{min}\f$ counts
  voxels of \f$r_{fit}\f$; the region of interest is the ball of radius `roi_radius`
  \f$\cdot\Delta^{r_{fit}}\f$ restricted to the voxels reachable from the seed without crossing
  Freeze or claimed voxels, and a claim keeps only the voxels of \f$M_{fit}\f$ connected to that
  region, so that no claim jumps across a Freeze wall (`use_reachable_regions`; the paper's plain
  ball if `false`).
- Samples are the finest-grid voxel centres of the region (on a lattice of stride 2 or 4 when
  there are more than 4096), plus the exterior voxels of the \f$1.5\Delta\f$ band in the ball as
  evidence that is never claimed (`use_exterior_band_samples`).
- Bounds: semi-axes in \f$[\Delta^{r_{fit}}/4, \rho]\f$, exponents in \f$[10^{-3}, 2]\f$, centre
  within \f$\rho/2\f$ of the seed; rotations are unbounded (body-frame increments).
- A rejected body seed excludes its inscribed ball from later seeds of the stage, a rejected
  surface seed the ball of radius \f$\rho/2\f$ around it (the rest of its component is seeded
  again at the centroid of what remains; `use_seed_exclusion`, the paper excludes the seed
  voxel only); components smaller than \f$V_{min}\f$ are not seeded; a stage also ends after
  `maximum_rejections_in_a_row` (4) rejected seeds in a row (the paper ends a stage on its
  iteration budget only).
- Claimed voxels include reserved voxels of finer stages (Alg.\ A.2 line 22); the volume test
  does not count them.
- FitSDF runs the projected Levenberg-Marquardt solver of the package (active-set freezing,
  Marquardt scaling divided by \f$\eta^2\f$ along the semi-axes, i.e.\ scipy's `x_scale`) with
  at most `maximum_solver_evaluations` (40) residual evaluations per solve, and stops when a
  step gains less than \f$10^{-8}\f$ of the cost (scipy's `ftol`); the first interior-weight
  variance is the mean squared clipped residual at \f$\theta_0\f$, set once (`ONE_SHOT`, the
  default) or re-estimated after each solve as MPS does (`MPS_REESTIMATED`).
- A fit that accepts no superquadric on a shape that bounds a volume (every seed rejected) is
  given one: the box-like superquadric (exponents 0.1) of the voxels neither exterior nor Freeze
  (or, if every voxel is Freeze, of the voxels that are not exterior) on their principal axes,
  which claims them all; `verbose` says so and why the seeds were rejected. The paper leaves the
  shape without a primitive.
- Without TSDF guidance (`use_tsdf_guidance = false`), \f$d_\mathcal{M}\f$ is replaced by
  \f$-\tau\f$ inside the hull and \f$+\tau\f$ in the exterior.
- Small residual regions: unclaimed non-Freeze components smaller than the surface \f$V_{min}\f$
  of the last stage take the label of their nearest claimed voxel.
- Merged primitives (`merge_primitives`): the fitter may tile one box or one rounded solid with
  several primitives. After the last stage, the two adjacent groups of primitives (claimed voxels
  in the 26-neighbourhood of one surface voxel) whose union one superquadric explains best are
  merged, as long as that superquadric reaches `minimum_merge_iou`, and never when more than 20% of
  the surface voxels along their common boundary are Freeze (a joint the prior saw). The
  superquadric of a union is the smallest box of its voxel centres on their principal axes, the
  coordinate axes or the axes of the largest primitive of each group, with exponents 0.1, 0.5 or 1
  (the best), and its score is the intersection over union of its voxels with the union's claimed
  voxels, the unclaimed voxels inside the shape counting on neither side. The merged group's
  primitive is that superquadric; the others are kept as fitted.

The paper's literal version is reached with `fitting_resolution_cap(32)`,
`use_exterior_band_samples = false`, `use_reachable_regions = false`, `use_seed_exclusion = false`,
`maximum_rejections_in_a_row(0)`, `maximum_solver_evaluations(1100)` (the default of scipy's
`least_squares`, \f$100 \times 11\f$) and `coverage_target(0.95)`. With `verbose`, every accepted
primitive, every rejected seed with the reason, a summary of every stage and the time spent in
each step are printed to `std::cerr`.

\tparam ConcurrencyTag enables sequential versus parallel evaluation of the residuals and
distance transforms. Possible values are `Sequential_tag`, `Parallel_tag` and
`Parallel_if_available_tag`. Results are identical for every number of threads.
\tparam GeomTraits a model of `PartDecompositionTraits`, the traits of the returned superquadrics
\tparam NamedParameters a sequence of named parameters

\param prior the hierarchical Flow/Freeze prior (`classes`, `leaf_resolution`, `resolutions`,
       `normalization` are read)
\param tsdf the truncated signed distance field on the finest grid of the prior
\param np an optional sequence of named parameters; this function reads `flow_zone_tolerance`,
`trust_region_scales`, `body_seed_threshold`, `minimum_body_volume`, `minimum_surface_volume`,
`exterior_penalty`, `coverage_target`, `roi_radius`, `maximum_number_of_primitives`,
`fitting_resolution_cap`, `maximum_solver_evaluations`, `maximum_rejections_in_a_row`,
`minimum_merge_iou`, `verbose` and `method_variant` (its switches `interior_weight_mode`,
`use_freeze_zone`, `use_tsdf_guidance`, `use_body_seeds`, `use_exterior_band_samples`,
`use_reachable_regions`, `use_seed_exclusion` and `merge_primitives`) (\ref PD_ParameterTable)

\par Complexity
Independent of the number of faces of the mesh. A stage ends after \f$k\f$ =
`maximum_rejections_in_a_row` rejected seeds in a row, so there are at most \f$(k+1)P + kL\f$ seeds
for \f$P\f$ accepted primitives and \f$L\f$ resolutions (\f$k = 0\f$: at most
\f$16\max(P_{max}, 16)\f$ per stage). Each seed
costs at most linear time in the \f$r^3\f$ voxels of the finest grid (finding it, claiming, and the
incremental update of the distance transform after an acceptance) plus its solves: one fit per
trust-region scale, each of one solve (`ONE_SHOT`) or at most 4 (`MPS_REESTIMATED`), and each solve
evaluates the residuals of at most about 4096 samples (plus exterior band samples) at most
`maximum_solver_evaluations` times.

\returns the accepted superquadrics and the claimed-voxel labels.
\throws Invalid_input (`INVALID_PARAMETER`), with a message that names the parameter, if a parameter
is out of range, or unless `tsdf.values`
has the resolution of `prior.classes`, the resolutions of the prior are increasing, and the finest
is that of `prior.classes`.
*/
template <typename ConcurrencyTag = CGAL::Sequential_tag,
          typename GeomTraits = CGAL::Exact_predicates_inexact_constructions_kernel,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Superquadric_fitting_result<GeomTraits> fit_superquadrics(const Hierarchical_prior& prior,
                                                          const Truncated_signed_distance_field& tsdf,
                                                          const NamedParameters& np = CGAL::parameters::default_values())
{
  return internal::fit_with_given_or_computed_zones<ConcurrencyTag, GeomTraits>(prior, tsdf, nullptr, np);
}

/*!
\ingroup PkgPartDecompositionRef
the same as `fit_superquadrics(prior, tsdf, np)` with the zones computed beforehand by
`compute_fitting_zones(prior.classes, tsdf, fitting_resolutions(prior.resolutions, c), np)` with the same
`flow_zone_tolerance` and `use_freeze_zone`, \f$c\f$ being the `fitting_resolution_cap` of `np`
(0 by default).
\throws Invalid_input (`INVALID_PARAMETER`) as `fit_superquadrics(prior, tsdf, np)`, and if
`zones` are not on the grid of `prior.classes` or miss one of its fitting resolutions.
*/
template <typename ConcurrencyTag = CGAL::Sequential_tag,
          typename GeomTraits = CGAL::Exact_predicates_inexact_constructions_kernel,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Superquadric_fitting_result<GeomTraits> fit_superquadrics(const Hierarchical_prior& prior,
                                                          const Truncated_signed_distance_field& tsdf,
                                                          const Fitting_zones& zones,
                                                          const NamedParameters& np = CGAL::parameters::default_values())
{
  return internal::fit_with_given_or_computed_zones<ConcurrencyTag, GeomTraits>(prior, tsdf, &zones, np);
}

} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_SUPERQUADRIC_FITTING_H
