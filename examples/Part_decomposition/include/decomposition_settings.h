// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef PART_DECOMPOSITION_TOOLS_DECOMPOSITION_SETTINGS_H
#define PART_DECOMPOSITION_TOOLS_DECOMPOSITION_SETTINGS_H

// The named parameters of Part_decomposition::decompose() as plain values at the package's
// defaults, for the programs that take them from their users (hitops, the Python module) or vary
// them (the benchmark), and the one named-parameter pack that passes them all: the list is
// written once.

#include <CGAL/Part_decomposition/decompose.h>

#include <array>
#include <cstddef>
#include <vector>

namespace Part_decomposition_tools {

namespace PD = CGAL::Part_decomposition;

struct Decomposition_settings
{
  std::vector<int> voxel_resolutions = PD::defaults::voxel_resolutions();
  unsigned int number_of_points_per_face = PD::defaults::number_of_points_per_face;
  unsigned int number_of_neighbors = PD::defaults::number_of_neighbors;
  double curvature_percentile = PD::defaults::curvature_percentile;
  std::array<double, 4> cue_weights = PD::defaults::cue_weights;
  double freeze_ratio = PD::defaults::freeze_ratio;
  bool use_density = PD::defaults::use_density;
  int prior_resolution_cap = PD::defaults::prior_resolution_cap;
  double normalization_margin = PD::defaults::normalization_margin;
  double tsdf_truncation = PD::defaults::tsdf_truncation;
  PD::Tsdf_sign_method tsdf_sign_method = PD::defaults::tsdf_sign_method;
  double flow_zone_tolerance = PD::defaults::flow_zone_tolerance;
  std::vector<double> trust_region_scales = PD::defaults::trust_region_scales();
  double body_seed_threshold = PD::defaults::body_seed_threshold;
  double minimum_body_volume = PD::defaults::minimum_body_volume;
  double minimum_surface_volume = PD::defaults::minimum_surface_volume;
  double exterior_penalty = PD::defaults::exterior_penalty;
  double coverage_target = PD::defaults::coverage_target;
  double roi_radius = PD::defaults::roi_radius;
  PD::Interior_weight_mode interior_weight_mode = PD::defaults::interior_weight_mode;
  std::size_t maximum_number_of_primitives = PD::defaults::maximum_number_of_primitives;
  bool use_freeze_zone = PD::defaults::use_freeze_zone;
  bool use_tsdf_guidance = PD::defaults::use_tsdf_guidance;
  bool use_body_seeds = PD::defaults::use_body_seeds;
  int fitting_resolution_cap = PD::defaults::fitting_resolution_cap;
  bool use_exterior_band_samples = PD::defaults::use_exterior_band_samples;
  bool use_reachable_regions = PD::defaults::use_reachable_regions;
  bool use_seed_exclusion = PD::defaults::use_seed_exclusion;
  int maximum_solver_evaluations = PD::defaults::maximum_solver_evaluations;
  std::size_t maximum_rejections_in_a_row = PD::defaults::maximum_rejections_in_a_row;
  double dihedral_percentile = PD::defaults::dihedral_percentile;
  unsigned int smoothing_iterations = PD::defaults::smoothing_iterations;
  double minimum_patch_size = PD::defaults::minimum_patch_size;
  double patch_split_size = PD::defaults::patch_split_size;
  double vote_temperature = PD::defaults::vote_temperature;
  double boundary_smoothness = PD::defaults::boundary_smoothness;
  bool merge_primitives = PD::defaults::merge_primitives;
  double minimum_merge_iou = PD::defaults::minimum_merge_iou;
  bool merge_thin_sheets = PD::defaults::merge_thin_sheets;
  bool use_pieces = PD::defaults::use_pieces;
  double crease_angle = PD::defaults::crease_angle;
  double minimum_part_area = PD::defaults::minimum_part_area;
  double maximum_merge_cost = PD::defaults::maximum_merge_cost;
  bool keep_residual_patches = PD::defaults::keep_residual_patches;
  double residual_tolerance = PD::defaults::residual_tolerance;
  int thin_part_resolution = PD::defaults::thin_part_resolution;
  bool verbose = false;
};

// All the settings as one pack; the caller chains its own parameters (outputs, timings) after it
// with PD::parameters::combine().
inline auto named_parameters(const Decomposition_settings& s)
{
  namespace PDP = PD::parameters;
  return PDP::combine(
    CGAL::parameters::number_of_points_per_face(s.number_of_points_per_face).verbose(s.verbose),
    PDP::voxel_resolutions(s.voxel_resolutions), PDP::number_of_neighbors(s.number_of_neighbors),
    PDP::curvature_percentile(s.curvature_percentile), PDP::cue_weights(s.cue_weights),
    PDP::freeze_ratio(s.freeze_ratio), PDP::use_density(s.use_density),
    PDP::prior_resolution_cap(s.prior_resolution_cap),
    PDP::normalization_margin(s.normalization_margin), PDP::tsdf_truncation(s.tsdf_truncation),
    PDP::tsdf_sign_method(s.tsdf_sign_method), PDP::flow_zone_tolerance(s.flow_zone_tolerance),
    PDP::trust_region_scales(s.trust_region_scales), PDP::body_seed_threshold(s.body_seed_threshold),
    PDP::minimum_body_volume(s.minimum_body_volume), PDP::minimum_surface_volume(s.minimum_surface_volume),
    PDP::exterior_penalty(s.exterior_penalty), PDP::coverage_target(s.coverage_target),
    PDP::roi_radius(s.roi_radius), PDP::interior_weight_mode(s.interior_weight_mode),
    PDP::maximum_number_of_primitives(s.maximum_number_of_primitives), PDP::use_freeze_zone(s.use_freeze_zone),
    PDP::use_tsdf_guidance(s.use_tsdf_guidance), PDP::use_body_seeds(s.use_body_seeds),
    PDP::fitting_resolution_cap(s.fitting_resolution_cap),
    PDP::use_exterior_band_samples(s.use_exterior_band_samples), PDP::use_reachable_regions(s.use_reachable_regions),
    PDP::use_seed_exclusion(s.use_seed_exclusion), PDP::maximum_solver_evaluations(s.maximum_solver_evaluations),
    PDP::maximum_rejections_in_a_row(s.maximum_rejections_in_a_row), PDP::dihedral_percentile(s.dihedral_percentile),
    PDP::smoothing_iterations(s.smoothing_iterations), PDP::minimum_patch_size(s.minimum_patch_size),
    PDP::patch_split_size(s.patch_split_size), PDP::vote_temperature(s.vote_temperature),
    PDP::boundary_smoothness(s.boundary_smoothness), PDP::merge_primitives(s.merge_primitives),
    PDP::minimum_merge_iou(s.minimum_merge_iou), PDP::merge_thin_sheets(s.merge_thin_sheets),
    PDP::use_pieces(s.use_pieces), PDP::crease_angle(s.crease_angle), PDP::minimum_part_area(s.minimum_part_area),
    PDP::maximum_merge_cost(s.maximum_merge_cost),
    PDP::keep_residual_patches(s.keep_residual_patches), PDP::residual_tolerance(s.residual_tolerance),
    PDP::thin_part_resolution(s.thin_part_resolution));
}

} // namespace Part_decomposition_tools

#endif // PART_DECOMPOSITION_TOOLS_DECOMPOSITION_SETTINGS_H
