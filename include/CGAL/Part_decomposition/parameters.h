// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_PARAMETERS_H
#define CGAL_PART_DECOMPOSITION_PARAMETERS_H

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

namespace CGAL {
namespace Part_decomposition {

// The package's own named parameters. CGAL 5.5.1 keeps its list of named parameters closed
// (STL_Extension/internal/parameters_interface.h), so a package outside CGAL declares its tags
// here and chains them with `parameters::combine()`. CGAL's own names (`geom_traits`,
// `vertex_point_map`, `face_index_map`, `number_of_points_per_face`, `verbose`, ...) are used
// unchanged wherever the meaning is the same.
//
// Each line: tag type, tag value, function name.
#define CGAL_PART_DECOMPOSITION_PARAMETER_LIST(X)                                   \
  /* cues and topology score (paper App. B) */                                       \
  X(voxel_resolutions_t, voxel_resolutions, voxel_resolutions)                       \
  X(number_of_neighbors_t, number_of_neighbors, number_of_neighbors)                 \
  X(curvature_percentile_t, curvature_percentile, curvature_percentile)              \
  X(cue_weights_t, cue_weights, cue_weights)                                         \
  X(freeze_ratio_t, freeze_ratio, freeze_ratio)                                      \
  /* normalization and TSDF (App. E.2) */                                            \
  X(normalization_t, normalization, normalization)                                   \
  X(normalization_margin_t, normalization_margin, normalization_margin)              \
  X(tsdf_truncation_t, tsdf_truncation, tsdf_truncation)                             \
  X(tsdf_sign_method_t, tsdf_sign_method, tsdf_sign_method)                          \
  /* superquadric fitting (App. E.2, Alg. A.2, A.3) */                               \
  X(flow_zone_tolerance_t, flow_zone_tolerance, flow_zone_tolerance)                 \
  X(trust_region_scales_t, trust_region_scales, trust_region_scales)                 \
  X(body_seed_threshold_t, body_seed_threshold, body_seed_threshold)                 \
  X(minimum_body_volume_t, minimum_body_volume, minimum_body_volume)                 \
  X(minimum_surface_volume_t, minimum_surface_volume, minimum_surface_volume)        \
  X(exterior_penalty_t, exterior_penalty, exterior_penalty)                          \
  X(coverage_target_t, coverage_target, coverage_target)                             \
  X(roi_radius_t, roi_radius, roi_radius)                                            \
  X(interior_weight_mode_t, interior_weight_mode, interior_weight_mode)              \
  X(maximum_number_of_primitives_t, maximum_number_of_primitives,                    \
    maximum_number_of_primitives)                                                    \
  X(use_freeze_zone_t, use_freeze_zone, use_freeze_zone)                             \
  X(use_tsdf_guidance_t, use_tsdf_guidance, use_tsdf_guidance)                       \
  X(use_body_seeds_t, use_body_seeds, use_body_seeds)                                \
  /* over-segmentation and assignment (App. E.3, E.4) */                             \
  X(dihedral_quantile_t, dihedral_quantile, dihedral_quantile)                       \
  X(smoothing_iterations_t, smoothing_iterations, smoothing_iterations)              \
  X(minimum_patch_size_t, minimum_patch_size, minimum_patch_size)                    \
  X(maximum_patch_size_t, maximum_patch_size, maximum_patch_size)                    \
  X(vote_temperature_t, vote_temperature, vote_temperature)                          \
  /* the one-call decomposition */                                                   \
  X(primitive_output_iterator_t, primitive_output_iterator, primitive_output_iterator) \
  X(stage_timings_t, stage_timings, stage_timings)

/// \cond SKIP_IN_MANUAL
namespace internal_np {
#define CGAL_PART_DECOMPOSITION_DECLARE_TAG(TYPE, VALUE, FUNCTION) enum TYPE { VALUE };
CGAL_PART_DECOMPOSITION_PARAMETER_LIST(CGAL_PART_DECOMPOSITION_DECLARE_TAG)
#undef CGAL_PART_DECOMPOSITION_DECLARE_TAG
} // namespace internal_np
/// \endcond

/*!
\ingroup PkgPartDecompositionRef
The named parameters of the package. Each function `p(value)` returns a named parameter pack that
holds one value; packs are chained with `combine()`, including packs of \cgal's own parameters:

\code
namespace PD = CGAL::Part_decomposition;
PD::decompose(mesh, part_map,
              PD::parameters::combine(CGAL::parameters::verbose(true),
                                      PD::parameters::freeze_ratio(0.2),
                                      PD::parameters::voxel_resolutions(std::vector<int>{32, 64})));
\endcode

Which parameter a function reads, its type and its default are listed in that function's
documentation.
*/
namespace parameters {

/// \cond SKIP_IN_MANUAL
#define CGAL_PART_DECOMPOSITION_DECLARE_FUNCTION(TYPE, VALUE, FUNCTION)                       \
  template <typename T>                                                                     \
  CGAL::Named_function_parameters<T, internal_np::TYPE> FUNCTION(const T& t)                \
  {                                                                                         \
    return CGAL::Named_function_parameters<T, internal_np::TYPE>(t);                        \
  }
CGAL_PART_DECOMPOSITION_PARAMETER_LIST(CGAL_PART_DECOMPOSITION_DECLARE_FUNCTION)
#undef CGAL_PART_DECOMPOSITION_DECLARE_FUNCTION
/// \endcond

/// returns `np` unchanged: the end of a `combine()` chain.
template <typename T, typename Tag, typename Base>
const CGAL::Named_function_parameters<T, Tag, Base>&
combine(const CGAL::Named_function_parameters<T, Tag, Base>& np)
{
  return np;
}

/// returns one pack holding the parameters of `np`, `np2` and `rest` (\cgal 5.5 has no
/// `combine()`; later versions have a member of the same meaning). `np2` and every pack of
/// `rest` must hold a single parameter, as returned by one call of a parameter function.
template <typename T, typename Tag, typename Base, typename T2, typename Tag2, typename... NPs>
auto combine(const CGAL::Named_function_parameters<T, Tag, Base>& np,
             const CGAL::Named_function_parameters<T2, Tag2>& np2,
             const NPs&... rest)
{
  using Chained = CGAL::Named_function_parameters<T2, Tag2, CGAL::Named_function_parameters<T, Tag, Base> >;
  return combine(Chained(np2.v, np), rest...);
}

} // namespace parameters

} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_PARAMETERS_H
