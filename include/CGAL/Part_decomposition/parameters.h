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

#include <array>
#include <cstddef>
#include <iterator>
#include <optional>
#include <vector>

namespace CGAL {
namespace Part_decomposition {

// The package's own named parameters. CGAL 5.5.1 keeps its list of named parameters closed
// (STL_Extension/internal/parameters_interface.h), so a package outside CGAL declares its tags
// here and chains them with `parameters::combine()`. CGAL's own names (`geom_traits`,
// `vertex_point_map`, `face_index_map`, `number_of_points_per_face`, `verbose`, ...) are used
// unchanged wherever the meaning is the same.
//
// The values, one line each: name, value type, default. `decompose()` hands its pipeline one
// pack holding all of them with these types, so that the pipeline is compiled once per mesh type
// whatever parameters a program gives (and once for all in the compiled library).
#define CGAL_PART_DECOMPOSITION_VALUE_PARAMETERS(X)                                              \
  /* reading a mesh */                                                                             \
  X(weld_tolerance, double, defaults::weld_tolerance)                                              \
  /* pieces and creases */                                                                         \
  X(use_pieces, bool, defaults::use_pieces)                                                        \
  X(crease_angle, double, defaults::crease_angle)                                                  \
  X(minimum_part_area, double, defaults::minimum_part_area)                                        \
  /* cues and topology score (paper App. B) */                                                     \
  X(voxel_resolutions, std::vector<int>, defaults::voxel_resolutions())                            \
  X(number_of_neighbors, unsigned int, defaults::number_of_neighbors)                              \
  X(curvature_percentile, double, defaults::curvature_percentile)                                  \
  X(use_concave_curvature, bool, defaults::use_concave_curvature)                                  \
  X(cue_weights, std::vector<double>,                                                              \
    std::vector<double>(defaults::cue_weights.begin(), defaults::cue_weights.end()))               \
  X(freeze_ratio, double, defaults::freeze_ratio)                                                  \
  X(use_density, bool, defaults::use_density)                                                      \
  /* normalization and TSDF (App. E.2) */                                                          \
  X(normalization_margin, double, defaults::normalization_margin)                                  \
  X(tsdf_truncation, double, defaults::tsdf_truncation)                                            \
  X(tsdf_sign_method, Tsdf_sign_method, defaults::tsdf_sign_method)                                \
  X(grid_resolution, int, defaults::grid_resolution)                                               \
  X(adaptive_grid, bool, defaults::adaptive_grid)                                                  \
  /* superquadric fitting (App. E.2, Alg. A.2, A.3) */                                             \
  X(flow_zone_tolerance, double, defaults::flow_zone_tolerance)                                    \
  X(trust_region_scales, std::vector<double>, defaults::trust_region_scales())                     \
  X(body_seed_threshold, double, defaults::body_seed_threshold)                                    \
  X(minimum_body_volume, double, defaults::minimum_body_volume)                                    \
  X(minimum_surface_volume, double, defaults::minimum_surface_volume)                              \
  X(exterior_penalty, double, defaults::exterior_penalty)                                          \
  X(coverage_target, double, defaults::coverage_target)                                            \
  X(roi_radius, double, defaults::roi_radius)                                                      \
  X(interior_weight_mode, Interior_weight_mode, defaults::interior_weight_mode)                    \
  X(maximum_number_of_primitives, std::size_t, defaults::maximum_number_of_primitives)             \
  X(use_freeze_zone, bool, defaults::use_freeze_zone)                                              \
  X(use_tsdf_guidance, bool, defaults::use_tsdf_guidance)                                          \
  X(use_body_seeds, bool, defaults::use_body_seeds)                                                \
  X(fitting_resolution_cap, int, defaults::fitting_resolution_cap)                                 \
  X(use_exterior_band_samples, bool, defaults::use_exterior_band_samples)                          \
  X(use_reachable_regions, bool, defaults::use_reachable_regions)                                  \
  X(use_seed_exclusion, bool, defaults::use_seed_exclusion)                                        \
  X(maximum_solver_evaluations, int, defaults::maximum_solver_evaluations)                         \
  X(maximum_rejections_in_a_row, std::size_t, defaults::maximum_rejections_in_a_row)               \
  X(merge_primitives, bool, defaults::merge_primitives)                                            \
  X(minimum_merge_iou, double, defaults::minimum_merge_iou)                                        \
  /* over-segmentation and assignment (App. E.3, E.4) */                                           \
  X(dihedral_percentile, double, defaults::dihedral_percentile)                                    \
  X(smoothing_iterations, unsigned int, defaults::smoothing_iterations)                            \
  X(minimum_patch_size, double, defaults::minimum_patch_size)                                      \
  X(patch_split_size, double, defaults::patch_split_size)                                          \
  X(vote_temperature, double, defaults::vote_temperature)                                          \
  X(boundary_smoothness, double, defaults::boundary_smoothness)                                    \
  X(merge_thin_sheets, bool, defaults::merge_thin_sheets)                                          \
  /* the part hierarchy and residual patches; number_of_parts: none, the default granularity */    \
  X(number_of_parts, std::optional<std::size_t>, std::optional<std::size_t>())                     \
  X(maximum_merge_cost, double, defaults::maximum_merge_cost)                                      \
  X(keep_residual_patches, bool, defaults::keep_residual_patches)                                  \
  X(residual_tolerance, double, defaults::residual_tolerance)

// The objects: a normalization, and what `decompose()` reports.
#define CGAL_PART_DECOMPOSITION_OBJECT_PARAMETERS(X)                                             \
  X(normalization) X(part_hierarchy) X(primitive_output_iterator) X(stage_timings)

/*!
\ingroup PkgPartDecompositionRef
How the sign of the distance field is decided, i.e.\ which voxel centres are inside the shape.

Each leaf of the grid of the distance field is decided at its <em>sign point</em>, the centre of
the finest voxel in the middle of the leaf, from the exact signed crossings of the rows of the
finest voxels with the triangles.

- `INSIDE_TEST`: ray parity. A point is inside if a ray from it crosses the surface an odd
  number of times. Exact for closed meshes; meaningless for open ones, and a region covered
  twice by self-intersecting parts counts as outside.
- `WINDING_NUMBER`: the generalized winding number \f$w\f$ (Jacobson et al.\ 2013); a point is
  inside if \f$|w| > 1/2\f$, so that inward-oriented components, nested and overlapping
  (self-intersecting) closed parts are handled. On a closed mesh (no border edge) \f$w\f$ is an
  integer and is computed exactly by signed ray crossings, at the cost of `INSIDE_TEST`. On an
  open mesh \f$w\f$ is evaluated at every sign point with a hierarchical (Barnes-Hut)
  approximation: holes are bridged as the winding number bridges them. Needs a consistent
  orientation of each connected part.
- `FLOOD_FILL`: the leaves the surface does not meet (their centre is farther from it than half
  their diagonal) are outside if they are joined to the border of the cube through such leaves,
  inside otherwise; a leaf the surface may meet takes the sign of `RAY_VOTES`. Seals holes
  smaller than a leaf but leaks through larger ones; closed hollow shells become solid. This is the paper's exterior,
  the complement of `fillholes()` of the surface leaves.
- `RAY_VOTES`: ray voting (Nooruddin and Turk 2003) with signed crossings. Along each of the six
  axis rays from a sign point, the signed crossings of its row with the triangles give the
  winding number that ray sees, exactly (the crossings of `WINDING_NUMBER` on a closed mesh);
  the point is inside if the six are non-zero and outside if at most three are; in between (the
  rays that leave through a hole) the generalized winding number at the point decides. On a
  closed mesh the six agree and this is the exact winding number, computed along one axis; on an
  open mesh a hole turns only the rays that leave through it, and an open sheet gives at most the
  two rays that cross it. Needs a consistent orientation of each connected part.
- `AUTOMATIC` = `RAY_VOTES`: exact on every closed mesh, self-intersecting or not, with no
  costly self-intersection test, and robust on open ones: on the development shapes with holes
  it put 1.5 to 3.7 times fewer voxels on the wrong side than `WINDING_NUMBER` (against the
  closed originals), in half its time (`benchmark/Part_decomposition/RESULTS.md`).
*/
enum class Tsdf_sign_method
{
  AUTOMATIC,      ///< `RAY_VOTES`
  INSIDE_TEST,    ///< ray parity (closed meshes only)
  WINDING_NUMBER, ///< \f$|w| > 1/2\f$: exact by signed ray crossings if closed, hierarchical elsewhere
  FLOOD_FILL,     ///< exterior flood fill of the grid around the surface leaves (the paper's `fillholes`)
  RAY_VOTES       ///< four of the six axis rays see a non-zero winding number
};

/*!
\ingroup PkgPartDecompositionRef
How FitSDF (paper Alg.\ A.3) sets the variance \f$\sigma^2\f$ of the Gaussian inlier weight of
interior samples, \f$w = p/(C+p)\f$ with \f$p = e^{-r^2/2\sigma^2}\f$ and
\f$C = w_o\sqrt{2\pi\sigma^2}/((1-w_o)\tau)\f$, \f$w_o = 0.99\f$ (inherited from MPS; the paper
does not say how \f$\sigma^2\f$ is set).
*/
enum class Interior_weight_mode
{
  /// as MPS: after each of up to 4 solves (an outer pass stops early when the cost changes by
  /// less than 0.1%), \f$\sigma^2 = \sum w r^2 / \sum w\f$ over the active samples and the
  /// interior weights are recomputed at the new parameters. The first \f$\sigma^2\f$ is the
  /// mean squared clipped residual at the initial parameters.
  MPS_REESTIMATED,
  /// \f$\sigma^2\f$ (the mean squared clipped residual) and the weights are computed once at the
  /// initial parameters; one solve.
  ONE_SHOT
};

/*!
\ingroup PkgPartDecompositionRef
The default value of each named parameter of the package: the paper's Table A.1 where
it gives one, the choices of this implementation (explained in the user manual, \ref PD_Parameters)
elsewhere. Every function of the package takes its defaults from here. The namespace is made from
`parameter_table` (by `doc/Part_decomposition/tools/parameter_table.py`), a list as a function
that returns it.
*/
namespace defaults {
// defaults: made by doc/Part_decomposition/tools/parameter_table.py from parameter_table, do not edit
/// border vertices closer than this fraction of the bounding box diagonal are welded; 0: none
constexpr double weld_tolerance = 5e-06;
/// the parts follow the pieces of the mesh and their concave creases; false: the paper's volumetric parts alone
constexpr bool use_pieces = true;
/// the dihedral angle, in degrees, from which a concave edge separates two regions of a piece
constexpr double crease_angle = 60.;
/// a smaller part (fraction of the mesh area) joins a neighbour
constexpr double minimum_part_area = 0.005;
/// R: the grids of the prior, coarse to fine; the finest is the unit of the lengths of every volume stage
inline std::vector<int> voxel_resolutions() { return {16, 32, 64}; }
/// N_face: the barycentric samples per face
constexpr unsigned int number_of_points_per_face = 36;
/// k: the nearest faces of the normal deviation cue
constexpr unsigned int number_of_neighbors = 8;
/// the percentile at which the vertex curvatures are clipped
constexpr double curvature_percentile = 99.5;
/// the curvature cue counts the concave vertices only (the minima rule); false: the paper's |H|/2 at every vertex
constexpr bool use_concave_curvature = true;
/// lambda: the weights of curvature mean, deviation, gradient and normal deviation in the topology score
constexpr std::array<double, 4> cue_weights = {{1., 1., 1., 0.}};
/// alpha: the fraction of the active voxels frozen at each resolution
constexpr double freeze_ratio = 0.15;
/// the topology score is weighted by the density sqrt(n_i); false: the paper's ablation
constexpr bool use_density = true;
/// the free margin of the normalized cube (2/64: two voxels of the 64^3 grid)
constexpr double normalization_margin = 0.03125;
/// tau: the truncation of the distance field, in voxels of the finest grid
constexpr double tsdf_truncation = 8.;
/// how the inside is decided: automatic (ray_votes), ray_votes, inside_test, winding_number or flood_fill
constexpr Tsdf_sign_method tsdf_sign_method = Tsdf_sign_method::AUTOMATIC;
/// the resolution of the finest leaves of the adaptive grid, where the shape is thin
constexpr int grid_resolution = 128;
/// the leaves of the grid follow the shape; false: every leaf a voxel of the finest voxel resolution (the paper)
constexpr bool adaptive_grid = true;
/// the dilation of the Flow zone, in voxels of the fitting resolution
constexpr double flow_zone_tolerance = 2.;
/// eta: the semi-axis trust-region scales of the retries
inline std::vector<double> trust_region_scales() { return {1., 0.5, 0.25}; }
/// the depth, in voxels of the fitting resolution, below which seeds switch from body to surface
constexpr double body_seed_threshold = 1.5;
/// V_min of body seeds, in voxels of the fitting resolution
constexpr double minimum_body_volume = 5.;
/// V_min of surface seeds, in voxels of the fitting resolution
constexpr double minimum_surface_volume = 3.;
/// mu_ext: the exterior intrusion penalty
constexpr double exterior_penalty = 5.;
/// the claimed fraction of the valid volume that ends a fitting stage
constexpr double coverage_target = 0.999;
/// the radius of the region of interest of a seed, in voxels of the fitting resolution
constexpr double roi_radius = 8.;
/// the variance of the interior inlier weight: one_shot, or mps_reestimated as MPS
constexpr Interior_weight_mode interior_weight_mode = Interior_weight_mode::ONE_SHOT;
/// a safety cap on the number of fitted superquadrics
constexpr std::size_t maximum_number_of_primitives = 256;
/// false: the paper's ablation w/o Freeze, Freeze voxels are Flow to the fitter
constexpr bool use_freeze_zone = true;
/// false: the paper's ablation w/o TSDF, the fit sees the occupancy only
constexpr bool use_tsdf_guidance = true;
/// false: the paper's ablation w/o Body, surface seeds only
constexpr bool use_body_seeds = true;
/// r_fit = min(r, cap); 0: the resolution before the finest
constexpr int fitting_resolution_cap = 0;
/// the exterior voxels of the thin outer band are samples of the fit
constexpr bool use_exterior_band_samples = true;
/// regions of interest and claims stop at Freeze walls
constexpr bool use_reachable_regions = true;
/// a rejected seed excludes a ball around it from later seeds of its stage
constexpr bool use_seed_exclusion = true;
/// the residual evaluations of one least-squares solve
constexpr int maximum_solver_evaluations = 40;
/// the rejected seeds in a row that end a fitting stage; 0: never
constexpr std::size_t maximum_rejections_in_a_row = 4;
/// adjacent primitives that one superquadric explains are merged after the fit (not in the paper)
constexpr bool merge_primitives = true;
/// the voxel intersection over union from which one superquadric explains two primitives
constexpr double minimum_merge_iou = 0.6;
/// q: edges whose dihedral angle is above this percentile are cut
constexpr double dihedral_percentile = 90.;
/// the boundary-smoothing passes of the over-segmentation
constexpr unsigned int smoothing_iterations = 1;
/// a smaller patch (fraction of the mesh area) is merged into a neighbour
constexpr double minimum_patch_size = 0.001;
/// a larger patch of smooth surface (fraction of the mesh area) is split
constexpr double patch_split_size = 0.0005;
/// tau_v: the temperature of the patch vote, in voxels of the finest grid
constexpr double vote_temperature = 1.;
/// the cost of a part boundary across smooth surface in the final labelling; 0: the paper's patch vote
constexpr double boundary_smoothness = 10.;
/// true: the paper's residual patches, Freeze-dominant patches no primitive explains, are parts of their own
constexpr bool keep_residual_patches = false;
/// the mean distance to its primitive, in voxels of the finest grid, from which a patch is residual
constexpr double residual_tolerance = 2.;
/// adjacent thin, flat parts that meet along smooth edges are merged (not in the paper)
constexpr bool merge_thin_sheets = true;
/// the parts go on merging in the part hierarchy while a merge costs less; 0: none
constexpr double maximum_merge_cost = 0.003;
/// print what each stage does on std::cerr
constexpr bool verbose = false;
// end of the defaults
} // namespace defaults

/*!
\ingroup PkgPartDecompositionRef
The stage of the decomposition that reads a named parameter, in the order `decompose()` runs them;
the programs group their options by it.
*/
enum class Parameter_stage
{
  READING,           ///< the mesh reader, `IO::read_triangle_mesh()`
  PIECES,            ///< the pieces and their creases, `segment_pieces()`
  PRIOR,             ///< the Flow/Freeze prior, `compute_flow_freeze_prior()`
  DISTANCE_FIELD,    ///< the normalization and the distance field, `compute_tsdf()`
  FITTING,           ///< the superquadrics, `fit_superquadrics()`
  OVER_SEGMENTATION, ///< the patches, `over_segment()`
  ASSIGNMENT,        ///< the parts, `assign_parts()`
  HIERARCHY,         ///< the part hierarchy and the granularity, `decompose()`
  OUTPUT             ///< what `decompose()` reports
};

/*!
\ingroup PkgPartDecompositionRef
One named parameter of the package, as listed by `parameter_table`.
*/
struct Parameter_description
{
  const char* name;          ///< the named-parameter function, e.g.\ `"freeze_ratio"`
  const char* type;          ///< the value type
  const char* default_value; ///< the default of `defaults`, as the programs print it
  const char* range;         ///< the rule of the range check ("NAME must be RULE"); empty if none
  Parameter_stage stage;     ///< the stage that reads it
  const char* read_by;       ///< the functions that read it
  bool is_value;             ///< `false` for objects (outputs, a normalization): no option of the programs
  bool is_ablation;          ///< exists only to undo a documented choice or to reproduce the paper literally
  const char* meaning;       ///< one line
};

/*!
\ingroup PkgPartDecompositionRef
Every named parameter that `decompose()` reads, the package's own and \cgal's
(`number_of_points_per_face`, `verbose`), and the reader's `weld_tolerance`, in the order of their
stages. The command-line tool `hitops`, the Python module and the manual's table of parameters
are made from it; a test checks that they list every entry with the same default.
*/
constexpr Parameter_description parameter_table[] = {
  // name, type, default, range, stage, read by, value, ablation, meaning
  {"weld_tolerance", "double", "5e-06", "in [0, 0.01]", Parameter_stage::READING,
   "IO::read_triangle_mesh(), IO::triangle_mesh_from_polygon_soup()", true, false,
   "border vertices closer than this fraction of the bounding box diagonal are welded; 0: none"},
  {"use_pieces", "bool", "true", "", Parameter_stage::PIECES, "decompose(), compose_parts()", true, true,
   "the parts follow the pieces of the mesh and their concave creases; false: the paper's volumetric parts alone"},
  {"crease_angle", "double", "60", "in (0, 180]", Parameter_stage::PIECES, "segment_pieces()", true, false,
   "the dihedral angle, in degrees, from which a concave edge separates two regions of a piece"},
  {"minimum_part_area", "double", "0.005", "in [0, 1]", Parameter_stage::PIECES,
   "decompose(), splittable_pieces(), compose_parts()", true, false,
   "a smaller part (fraction of the mesh area) joins a neighbour"},
  {"voxel_resolutions", "std::vector<int>", "16,32,64",
   "a non-empty list of powers of two from 1 to 256, each twice the previous", Parameter_stage::PRIOR,
   "compute_flow_freeze_prior(), compute_tsdf()", true, false,
   "R: the grids of the prior, coarse to fine; the finest is the unit of the lengths of every volume stage"},
  {"number_of_points_per_face", "unsigned int", "36", "a positive perfect square", Parameter_stage::PRIOR,
   "compute_topology_score()", true, false, "N_face: the barycentric samples per face"},
  {"number_of_neighbors", "unsigned int", "8", "a positive integer", Parameter_stage::PRIOR,
   "compute_face_normal_deviation()", true, false, "k: the nearest faces of the normal deviation cue"},
  {"curvature_percentile", "double", "99.5", "in [0, 100]", Parameter_stage::PRIOR, "compute_face_curvature_cue()",
   true, false, "the percentile at which the vertex curvatures are clipped"},
  {"use_concave_curvature", "bool", "true", "", Parameter_stage::PRIOR,
   "compute_face_curvature_cue(), compute_geometric_cues(), compute_flow_freeze_prior()", true, true,
   "the curvature cue counts the concave vertices only (the minima rule); false: the paper's |H|/2 at every vertex"},
  {"cue_weights", "std::array<double, 4>", "1,1,1,0", "4 finite numbers", Parameter_stage::PRIOR,
   "compute_topology_score()", true, false,
   "lambda: the weights of curvature mean, deviation, gradient and normal deviation in the topology score"},
  {"freeze_ratio", "double", "0.15", "in (0, 1)", Parameter_stage::PRIOR, "compute_topology_score()", true, false,
   "alpha: the fraction of the active voxels frozen at each resolution"},
  {"use_density", "bool", "true", "", Parameter_stage::PRIOR,
   "compute_topology_score(), compute_flow_freeze_prior()", true, true,
   "the topology score is weighted by the density sqrt(n_i); false: the paper's ablation"},
  {"normalization", "Normalization", "compute_normalization()", "", Parameter_stage::DISTANCE_FIELD,
   "every stage on the mesh", false, false, "the normalization of the mesh into the unit cube"},
  {"normalization_margin", "double", "0.03125", "in [0, 0.25]", Parameter_stage::DISTANCE_FIELD,
   "compute_normalization()", true, false,
   "the free margin of the normalized cube (2/64: two voxels of the 64^3 grid)"},
  {"tsdf_truncation", "double", "8", "in (0, 4 * resolution]", Parameter_stage::DISTANCE_FIELD, "compute_tsdf()",
   true, false, "tau: the truncation of the distance field, in voxels of the finest grid"},
  {"tsdf_sign_method", "Tsdf_sign_method", "automatic", "", Parameter_stage::DISTANCE_FIELD, "compute_tsdf()", true,
   false, "how the inside is decided: automatic (ray_votes), ray_votes, inside_test, winding_number or flood_fill"},
  {"grid_resolution", "int", "128", "a power of two up to 256; raised to the finest voxel resolution",
   Parameter_stage::DISTANCE_FIELD, "compute_tsdf()", true, false,
   "the resolution of the finest leaves of the adaptive grid, where the shape is thin"},
  {"adaptive_grid", "bool", "true", "", Parameter_stage::DISTANCE_FIELD, "compute_tsdf()", true, true,
   "the leaves of the grid follow the shape; false: every leaf a voxel of the finest voxel resolution (the paper)"},
  {"flow_zone_tolerance", "double", "2", "non-negative and finite", Parameter_stage::FITTING,
   "compute_fitting_zones(), fit_superquadrics()", true, false,
   "the dilation of the Flow zone, in voxels of the fitting resolution"},
  {"trust_region_scales", "std::vector<double>", "1,0.5,0.25", "a non-empty list of positive numbers",
   Parameter_stage::FITTING, "fit_superquadrics()", true, false, "eta: the semi-axis trust-region scales of the retries"},
  {"body_seed_threshold", "double", "1.5", "positive and finite", Parameter_stage::FITTING, "fit_superquadrics()", true,
   false, "the depth, in voxels of the fitting resolution, below which seeds switch from body to surface"},
  {"minimum_body_volume", "double", "5", "non-negative and finite", Parameter_stage::FITTING, "fit_superquadrics()",
   true, false, "V_min of body seeds, in voxels of the fitting resolution"},
  {"minimum_surface_volume", "double", "3", "non-negative and finite", Parameter_stage::FITTING,
   "fit_superquadrics()", true, false, "V_min of surface seeds, in voxels of the fitting resolution"},
  {"exterior_penalty", "double", "5", "non-negative and finite", Parameter_stage::FITTING, "fit_superquadrics()", true,
   false, "mu_ext: the exterior intrusion penalty"},
  {"coverage_target", "double", "0.999", "in (0, 1]", Parameter_stage::FITTING, "fit_superquadrics()", true, false,
   "the claimed fraction of the valid volume that ends a fitting stage"},
  {"roi_radius", "double", "8", "positive and finite", Parameter_stage::FITTING, "fit_superquadrics()", true, false,
   "the radius of the region of interest of a seed, in voxels of the fitting resolution"},
  {"interior_weight_mode", "Interior_weight_mode", "one_shot", "", Parameter_stage::FITTING, "fit_superquadrics()",
   true, true, "the variance of the interior inlier weight: one_shot, or mps_reestimated as MPS"},
  {"maximum_number_of_primitives", "std::size_t", "256", "positive", Parameter_stage::FITTING, "fit_superquadrics()",
   true, false, "a safety cap on the number of fitted superquadrics"},
  {"use_freeze_zone", "bool", "true", "", Parameter_stage::FITTING, "compute_fitting_zones(), fit_superquadrics()",
   true, true, "false: the paper's ablation w/o Freeze, Freeze voxels are Flow to the fitter"},
  {"use_tsdf_guidance", "bool", "true", "", Parameter_stage::FITTING, "fit_superquadrics()", true, true,
   "false: the paper's ablation w/o TSDF, the fit sees the occupancy only"},
  {"use_body_seeds", "bool", "true", "", Parameter_stage::FITTING, "fit_superquadrics()", true, true,
   "false: the paper's ablation w/o Body, surface seeds only"},
  {"fitting_resolution_cap", "int", "0", "non-negative", Parameter_stage::FITTING,
   "fitting_resolutions(), fit_superquadrics()", true, false,
   "r_fit = min(r, cap); 0: the resolution before the finest"},
  {"use_exterior_band_samples", "bool", "true", "", Parameter_stage::FITTING, "fit_superquadrics()", true, true,
   "the exterior voxels of the thin outer band are samples of the fit"},
  {"use_reachable_regions", "bool", "true", "", Parameter_stage::FITTING, "fit_superquadrics()", true, true,
   "regions of interest and claims stop at Freeze walls"},
  {"use_seed_exclusion", "bool", "true", "", Parameter_stage::FITTING, "fit_superquadrics()", true, true,
   "a rejected seed excludes a ball around it from later seeds of its stage"},
  {"maximum_solver_evaluations", "int", "40", "positive", Parameter_stage::FITTING, "fit_superquadrics()", true, false,
   "the residual evaluations of one least-squares solve"},
  {"maximum_rejections_in_a_row", "std::size_t", "4", "non-negative", Parameter_stage::FITTING, "fit_superquadrics()",
   true, false, "the rejected seeds in a row that end a fitting stage; 0: never"},
  {"merge_primitives", "bool", "true", "", Parameter_stage::FITTING, "fit_superquadrics()", true, true,
   "adjacent primitives that one superquadric explains are merged after the fit (not in the paper)"},
  {"minimum_merge_iou", "double", "0.6", "in (0, 1]", Parameter_stage::FITTING, "fit_superquadrics()", true, false,
   "the voxel intersection over union from which one superquadric explains two primitives"},
  {"dihedral_percentile", "double", "90", "in [0, 100]", Parameter_stage::OVER_SEGMENTATION, "over_segment()", true,
   false, "q: edges whose dihedral angle is above this percentile are cut"},
  {"smoothing_iterations", "unsigned int", "1", "non-negative", Parameter_stage::OVER_SEGMENTATION, "over_segment()",
   true, false, "the boundary-smoothing passes of the over-segmentation"},
  {"minimum_patch_size", "double", "0.001", "in [0, 1]", Parameter_stage::OVER_SEGMENTATION, "over_segment()", true,
   false, "a smaller patch (fraction of the mesh area) is merged into a neighbour"},
  {"patch_split_size", "double", "0.0005", "in (0, 1]", Parameter_stage::OVER_SEGMENTATION, "over_segment()", true,
   false, "a larger patch of smooth surface (fraction of the mesh area) is split"},
  {"vote_temperature", "double", "1", "positive and finite", Parameter_stage::ASSIGNMENT, "assign_parts()", true,
   false, "tau_v: the temperature of the patch vote, in voxels of the finest grid"},
  {"boundary_smoothness", "double", "10", "non-negative and finite", Parameter_stage::ASSIGNMENT, "assign_parts()",
   true, false, "the cost of a part boundary across smooth surface in the final labelling; 0: the paper's patch vote"},
  {"keep_residual_patches", "bool", "false", "", Parameter_stage::ASSIGNMENT,
   "decompose(), Part_decomposer::compose_parts()", true, true,
   "true: the paper's residual patches, Freeze-dominant patches no primitive explains, are parts of their own"},
  {"residual_tolerance", "double", "2", "non-negative and finite", Parameter_stage::ASSIGNMENT,
   "decompose(), separate_residual_patches()", true, false,
   "the mean distance to its primitive, in voxels of the finest grid, from which a patch is residual"},
  {"merge_thin_sheets", "bool", "true", "", Parameter_stage::ASSIGNMENT,
   "decompose(), Part_decomposer::compose_parts()", true, true,
   "adjacent thin, flat parts that meet along smooth edges are merged (not in the paper)"},
  {"maximum_merge_cost", "double", "0.003", "non-negative and finite", Parameter_stage::HIERARCHY, "decompose()", true,
   false, "the parts go on merging in the part hierarchy while a merge costs less; 0: none"},
  {"number_of_parts", "std::size_t", "none", "at least 1", Parameter_stage::HIERARCHY, "decompose()", true, false,
   "exactly this many parts, a level of the part hierarchy (at most its leaves); none: the default granularity"},
  {"part_hierarchy", "Part_hierarchy<GeomTraits>*", "nullptr", "", Parameter_stage::OUTPUT, "decompose()", false,
   false, "receives the part hierarchy"},
  {"primitive_output_iterator", "an output iterator", "none", "", Parameter_stage::OUTPUT, "decompose()", false, false,
   "receives the superquadric of each part"},
  {"stage_timings", "Stage_timings*", "nullptr", "", Parameter_stage::OUTPUT, "decompose()", false, false,
   "receives the time of each stage"},
  {"verbose", "bool", "false", "", Parameter_stage::OUTPUT, "decompose()", true, false,
   "print what each stage does on std::cerr"}};

/// \cond SKIP_IN_MANUAL
namespace internal {

constexpr bool same_name(const char* a, const char* b)
{
  return *a == *b && (*a == '\0' || same_name(a + 1, b + 1));
}

// The entry of `name` in parameter_table, or nullptr.
constexpr const Parameter_description* find_parameter(const char* name)
{
  for(const Parameter_description& p : parameter_table)
    if(same_name(p.name, name)) return &p;
  return nullptr;
}

// The value of a parameter whose absence means something (`number_of_parts`, `normalization`);
// empty if absent. The pack of `decompose()` holds such a parameter as a `std::optional`.
template <typename T>
std::optional<T> as_optional(const T& t)
{
  return t;
}

template <typename T>
std::optional<T> as_optional(const std::optional<T>& t)
{
  return t;
}

template <typename T, typename NamedParameters, typename Tag>
std::optional<T> optional_parameter(const NamedParameters& np, Tag tag)
{
  if constexpr(CGAL::parameters::is_default_parameter<NamedParameters, Tag>::value)
    return std::nullopt;
  else
  {
    const auto given = as_optional(CGAL::parameters::get_parameter(np, tag));
    return given ? std::optional<T>(T(*given)) : std::nullopt;
  }
}

// The rule of the range check of `name`, as the table states it.
constexpr const char* range_rule(const char* name)
{
  return find_parameter(name) == nullptr ? "" : find_parameter(name)->range;
}

} // namespace internal

// The table cannot miss a named parameter, nor list one that does not exist: it has one entry per
// tag plus the three of CGAL and of the reader that it adds.
#define CGAL_PART_DECOMPOSITION_CHECK_TABLE_ENTRY(NAME, ...)                                     \
  static_assert(internal::find_parameter(#NAME) != nullptr, "parameter_table misses " #NAME);
CGAL_PART_DECOMPOSITION_VALUE_PARAMETERS(CGAL_PART_DECOMPOSITION_CHECK_TABLE_ENTRY)
CGAL_PART_DECOMPOSITION_OBJECT_PARAMETERS(CGAL_PART_DECOMPOSITION_CHECK_TABLE_ENTRY)
#undef CGAL_PART_DECOMPOSITION_CHECK_TABLE_ENTRY
#define CGAL_PART_DECOMPOSITION_COUNT_TAG(NAME, ...) +1
static_assert(std::size(parameter_table) ==
                2 CGAL_PART_DECOMPOSITION_VALUE_PARAMETERS(CGAL_PART_DECOMPOSITION_COUNT_TAG)
                  CGAL_PART_DECOMPOSITION_OBJECT_PARAMETERS(CGAL_PART_DECOMPOSITION_COUNT_TAG),
              "parameter_table lists a parameter that has no tag");
#undef CGAL_PART_DECOMPOSITION_COUNT_TAG
static_assert(internal::find_parameter("number_of_points_per_face") && internal::find_parameter("verbose"),
              "parameter_table misses a parameter of CGAL");
/// \endcond

/// \cond SKIP_IN_MANUAL
namespace internal_np {
#define CGAL_PART_DECOMPOSITION_DECLARE_TAG(NAME, ...) enum NAME##_t { NAME };
CGAL_PART_DECOMPOSITION_VALUE_PARAMETERS(CGAL_PART_DECOMPOSITION_DECLARE_TAG)
CGAL_PART_DECOMPOSITION_OBJECT_PARAMETERS(CGAL_PART_DECOMPOSITION_DECLARE_TAG)
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

Each function lists the parameters it reads; `decompose()` accepts them all and passes each to the
stage that reads it. Every parameter, with its type, default, range, meaning and the functions that
read it, is in `parameter_table`, from which the reference page \ref PD_ParameterTable is made;
\cgal's parameters of the mesh are described in \ref PD_MeshParameters.

Each function is `template <typename T> Named_function_parameters<T, Tag> name(const T& value)`.
\cgal's own parameters keep their names: `vertex_point_map`, `vertex_index_map`,
`face_index_map`, `geom_traits`, `number_of_points_per_face` (36), `verbose`, and, for
`evaluate_segmentation()`, `number_of_points_on_faces` and `random_seed`.
*/
namespace parameters {

/// \cond SKIP_IN_MANUAL
#define CGAL_PART_DECOMPOSITION_DECLARE_FUNCTION(NAME, ...)                                      \
  template <typename T>                                                                       \
  CGAL::Named_function_parameters<T, internal_np::NAME##_t> NAME(const T& t)                  \
  {                                                                                           \
    return CGAL::Named_function_parameters<T, internal_np::NAME##_t>(t);                      \
  }
CGAL_PART_DECOMPOSITION_VALUE_PARAMETERS(CGAL_PART_DECOMPOSITION_DECLARE_FUNCTION)
CGAL_PART_DECOMPOSITION_OBJECT_PARAMETERS(CGAL_PART_DECOMPOSITION_DECLARE_FUNCTION)
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
