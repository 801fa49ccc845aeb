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
#include <string_view>
#include <vector>

namespace CGAL {
namespace Part_decomposition {

// The package's own named parameters. CGAL 5.5.1 keeps its list of named parameters closed
// (STL_Extension/internal/parameters_interface.h), so a package outside CGAL declares its tags
// here and chains them with `parameters::combine()`. CGAL's own names (`geom_traits`,
// `vertex_point_map`, `face_index_map`, `number_of_points_per_face`, `verbose`, ...) are used
// unchanged wherever the meaning is the same.

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

// The switches of the method: each undoes a documented choice of this implementation or
// reproduces the paper literally. One line each: name, type, default, the paper's value, stage,
// meaning. They are the fields of `Method_variant`, one named parameter.
#define CGAL_PART_DECOMPOSITION_METHOD_SWITCHES(S)                                               \
  S(use_pieces, bool, true, false, PIECES,                                                        \
    "the parts follow the pieces of the mesh and their concave creases; false: the paper's volumetric parts alone") \
  S(use_concave_curvature, bool, true, false, PRIOR,                                              \
    "the curvature cue counts the concave vertices only (the minima rule); false: the paper's |H|/2 at every vertex") \
  S(use_density, bool, true, true, PRIOR,                                                         \
    "the topology score is weighted by the density sqrt(n_i); false: the paper's ablation")      \
  S(adaptive_grid, bool, true, false, DISTANCE_FIELD,                                             \
    "the leaves of the grid follow the shape; false: every leaf a voxel of the finest voxel resolution (the paper)") \
  S(interior_weight_mode, Interior_weight_mode, Interior_weight_mode::ONE_SHOT,                   \
    Interior_weight_mode::MPS_REESTIMATED, FITTING,                                               \
    "the variance of the interior inlier weight: one_shot, or mps_reestimated as MPS")            \
  S(use_freeze_zone, bool, true, true, FITTING,                                                   \
    "false: the paper's ablation w/o Freeze, Freeze voxels are Flow to the fitter")               \
  S(use_tsdf_guidance, bool, true, true, FITTING,                                                 \
    "false: the paper's ablation w/o TSDF, the fit sees the occupancy only")                      \
  S(use_body_seeds, bool, true, true, FITTING, "false: the paper's ablation w/o Body, surface seeds only") \
  S(use_exterior_band_samples, bool, true, false, FITTING,                                        \
    "the exterior voxels of the thin outer band are samples of the fit")                          \
  S(use_reachable_regions, bool, true, false, FITTING, "regions of interest and claims stop at Freeze walls") \
  S(use_seed_exclusion, bool, true, false, FITTING,                                               \
    "a rejected seed excludes a ball around it from later seeds of its stage")                    \
  S(merge_primitives, bool, true, false, FITTING,                                                 \
    "adjacent primitives that one superquadric explains are merged after the fit (not in the paper)") \
  S(keep_residual_patches, bool, false, true, ASSIGNMENT,                                         \
    "true: the paper's residual patches, Freeze-dominant patches no primitive explains, are parts of their own") \
  S(merge_thin_sheets, bool, true, false, ASSIGNMENT,                                             \
    "adjacent thin, flat parts that meet along smooth edges are merged (not in the paper)")

/*!
\ingroup PkgPartDecompositionRef
The switches of the method, passed as the one named parameter `method_variant`. Each undoes a
documented choice of this implementation or reproduces the paper literally; they exist for the
ablations of `benchmark/Part_decomposition` and for comparisons with the paper. A
default-constructed value is the package's method, `paper_literal()` the paper's. Every field is
a `bool` but `interior_weight_mode` (an `Interior_weight_mode`); the fields, with their defaults,
the paper's values and meanings, are listed in \ref PD_MethodSwitches.
*/
struct Method_variant
{
  /// \cond SKIP_IN_MANUAL
#define CGAL_PART_DECOMPOSITION_SWITCH_FIELD(NAME, TYPE, DEFAULT, ...) TYPE NAME = DEFAULT;
  CGAL_PART_DECOMPOSITION_METHOD_SWITCHES(CGAL_PART_DECOMPOSITION_SWITCH_FIELD)
#undef CGAL_PART_DECOMPOSITION_SWITCH_FIELD
  /// \endcond

  /// returns every switch at the paper's value.
  static constexpr Method_variant paper_literal()
  {
    Method_variant v;
#define CGAL_PART_DECOMPOSITION_SWITCH_PAPER(NAME, TYPE, DEFAULT, PAPER, ...) v.NAME = PAPER;
    CGAL_PART_DECOMPOSITION_METHOD_SWITCHES(CGAL_PART_DECOMPOSITION_SWITCH_PAPER)
#undef CGAL_PART_DECOMPOSITION_SWITCH_PAPER
    return v;
  }

  /// returns whether every switch of `a` and `b` is the same.
  friend constexpr bool operator==(const Method_variant& a, const Method_variant& b)
  {
    return true
#define CGAL_PART_DECOMPOSITION_SWITCH_EQUAL(NAME, ...) && a.NAME == b.NAME
      CGAL_PART_DECOMPOSITION_METHOD_SWITCHES(CGAL_PART_DECOMPOSITION_SWITCH_EQUAL);
#undef CGAL_PART_DECOMPOSITION_SWITCH_EQUAL
  }
};

// The named parameters that hold a value, in the order of their stages, one line each: name,
// value type, default (in parentheses: the arguments that make it; a list is a
// `std::vector`), stage, range, meaning. `P` is a parameter of the package, `C` one of \cgal's
// (its tag and function are \cgal's). From this list come the tags and the functions of
// `parameters`, `defaults`, `parameter_table` (and so the reference page and the options of the
// programs), and the one pack of fixed types that `decompose()` hands its pipeline, so that the
// pipeline is compiled once per mesh type whatever parameters a program gives.
#define CGAL_PART_DECOMPOSITION_PARAMETERS(P, C)                                                 \
  P(weld_tolerance, double, (5e-6), READING, "in [0, 0.01]",                                      \
    "border vertices closer than this fraction of the bounding box diagonal are welded; 0: none") \
  P(crease_angle, double, (60.), PIECES, "in (0, 180]",                                           \
    "the dihedral angle, in degrees, from which a concave edge separates two regions of a piece") \
  P(minimum_part_area, double, (0.005), PIECES, "in [0, 1]",                                      \
    "a smaller part (fraction of the mesh area) joins a neighbour")                               \
  P(voxel_resolutions, std::vector<int>, (16, 32, 64), PRIOR,                                     \
    "a non-empty list of powers of two from 1 to 256, each twice the previous",                   \
    "R: the grids of the prior, coarse to fine; the finest is the unit of the lengths of every volume stage") \
  C(number_of_points_per_face, unsigned int, (36), PRIOR, "a positive perfect square",            \
    "N_face: the barycentric samples per face")                                                   \
  P(number_of_neighbors, unsigned int, (8), PRIOR, "a positive integer",                          \
    "k: the nearest faces of the normal deviation cue")                                           \
  P(curvature_percentile, double, (99.5), PRIOR, "in [0, 100]",                                   \
    "the percentile at which the vertex curvatures are clipped")                                  \
  P(cue_weights, std::vector<double>, (1., 1., 1., 0.), PRIOR, "4 finite numbers",                \
    "lambda: the weights of curvature mean, deviation, gradient and normal deviation in the topology score") \
  P(freeze_ratio, double, (0.15), PRIOR, "in (0, 1)",                                             \
    "alpha: the fraction of the active voxels frozen at each resolution")                         \
  P(normalization_margin, double, (0.03125), DISTANCE_FIELD, "in [0, 0.25]",                      \
    "the free margin of the normalized cube (2/64: two voxels of the 64^3 grid)")                 \
  P(tsdf_truncation, double, (8.), DISTANCE_FIELD, "in (0, 4 * resolution]",                      \
    "tau: the truncation of the distance field, in voxels of the finest grid")                    \
  P(tsdf_sign_method, Tsdf_sign_method, (Tsdf_sign_method::AUTOMATIC), DISTANCE_FIELD, "",        \
    "how the inside is decided: automatic (ray_votes), ray_votes, inside_test, winding_number or flood_fill") \
  P(grid_resolution, int, (128), DISTANCE_FIELD,                                                  \
    "a power of two up to 256; raised to the finest voxel resolution",                            \
    "the resolution of the finest leaves of the adaptive grid, where the shape is thin")          \
  P(flow_zone_tolerance, double, (2.), FITTING, "non-negative and finite",                        \
    "the dilation of the Flow zone, in voxels of the fitting resolution")                         \
  P(trust_region_scales, std::vector<double>, (1., 0.5, 0.25), FITTING,                           \
    "a non-empty list of positive numbers", "eta: the semi-axis trust-region scales of the retries") \
  P(body_seed_threshold, double, (1.5), FITTING, "positive and finite",                           \
    "the depth, in voxels of the fitting resolution, below which seeds switch from body to surface") \
  P(minimum_body_volume, double, (5.), FITTING, "non-negative and finite",                        \
    "V_min of body seeds, in voxels of the fitting resolution")                                   \
  P(minimum_surface_volume, double, (3.), FITTING, "non-negative and finite",                     \
    "V_min of surface seeds, in voxels of the fitting resolution")                                \
  P(exterior_penalty, double, (5.), FITTING, "non-negative and finite",                           \
    "mu_ext: the exterior intrusion penalty")                                                     \
  P(coverage_target, double, (0.999), FITTING, "in (0, 1]",                                       \
    "the claimed fraction of the valid volume that ends a fitting stage")                         \
  P(roi_radius, double, (8.), FITTING, "positive and finite",                                     \
    "the radius of the region of interest of a seed, in voxels of the fitting resolution")        \
  P(maximum_number_of_primitives, std::size_t, (256), FITTING, "positive",                        \
    "a safety cap on the number of fitted superquadrics")                                         \
  P(fitting_resolution_cap, int, (0), FITTING, "non-negative",                                    \
    "r_fit = min(r, cap); 0: the resolution before the finest")                                   \
  P(maximum_solver_evaluations, int, (40), FITTING, "positive",                                   \
    "the residual evaluations of one least-squares solve")                                        \
  P(maximum_rejections_in_a_row, std::size_t, (4), FITTING, "non-negative",                       \
    "the rejected seeds in a row that end a fitting stage; 0: never")                             \
  P(minimum_merge_iou, double, (0.6), FITTING, "in (0, 1]",                                       \
    "the voxel intersection over union from which one superquadric explains two primitives")      \
  P(dihedral_percentile, double, (90.), OVER_SEGMENTATION, "in [0, 100]",                         \
    "q: edges whose dihedral angle is above this percentile are cut")                             \
  P(smoothing_iterations, unsigned int, (1), OVER_SEGMENTATION, "non-negative",                   \
    "the boundary-smoothing passes of the over-segmentation")                                     \
  P(minimum_patch_size, double, (0.001), OVER_SEGMENTATION, "in [0, 1]",                          \
    "a smaller patch (fraction of the mesh area) is merged into a neighbour")                     \
  P(patch_split_size, double, (0.0005), OVER_SEGMENTATION, "in (0, 1]",                           \
    "a larger patch of smooth surface (fraction of the mesh area) is split")                      \
  P(vote_temperature, double, (1.), ASSIGNMENT, "positive and finite",                            \
    "tau_v: the temperature of the patch vote, in voxels of the finest grid")                     \
  P(boundary_smoothness, double, (10.), ASSIGNMENT, "non-negative and finite",                    \
    "the cost of a part boundary across smooth surface in the final labelling; 0: the paper's patch vote") \
  P(residual_tolerance, double, (2.), ASSIGNMENT, "non-negative and finite",                      \
    "the mean distance to its primitive, in voxels of the finest grid, from which a patch is residual") \
  P(maximum_merge_cost, double, (0.003), HIERARCHY, "non-negative and finite",                    \
    "the parts go on merging in the part hierarchy while a merge costs less; 0: none")            \
  P(number_of_parts, std::optional<std::size_t>, (), HIERARCHY, "at least 1",                     \
    "exactly this many parts, a level of the part hierarchy (at most its leaves); none: the default granularity") \
  P(method_variant, Method_variant, (), HIERARCHY, "",                                            \
    "the switches of the method (Method_variant): default, paper_literal, or NAME=VALUE,... of the switches") \
  C(verbose, bool, (false), OUTPUT, "", "print what each stage does on std::cerr")

// The named parameters that hold an object (a normalization, what `decompose()` reports): name,
// type, default, stage, meaning.
#define CGAL_PART_DECOMPOSITION_OBJECT_PARAMETERS(O)                                             \
  O(normalization, "Normalization", "compute_normalization()", DISTANCE_FIELD,                    \
    "the normalization of the mesh into the unit cube")                                           \
  O(part_hierarchy, "Part_hierarchy<GeomTraits>*", "nullptr", OUTPUT, "receives the part hierarchy") \
  O(primitive_output_iterator, "an output iterator", "none", OUTPUT, "receives the superquadric of each part") \
  O(stage_timings, "Stage_timings*", "nullptr", OUTPUT, "receives the time of each stage")

/// \cond SKIP_IN_MANUAL
namespace internal {

// The default of a parameter of type T from the arguments of its list entry; a list is a
// `std::array`, so that every default is a constant.
template <typename T>
struct Default_of
{
  template <typename... A>
  static constexpr T make(A... a) { return T(a...); }
};

template <typename E>
struct Default_of<std::vector<E> >
{
  template <typename... A>
  static constexpr std::array<E, sizeof...(A)> make(A... a) { return {{E(a)...}}; }
};

// The text of a default as the list writes it, without its parentheses.
constexpr std::string_view unparenthesized(std::string_view text) { return text.substr(1, text.size() - 2); }

} // namespace internal
/// \endcond

/*!
\ingroup PkgPartDecompositionRef
The default value of each named parameter that holds a value: the paper's Table A.1 where it gives
one, the choices of this implementation elsewhere; a list is a `std::array`. Every function of the
package takes its defaults from here. The values are listed in \ref PD_ParameterTable, the choices explained in the
user manual, \ref PD_Parameters.
*/
namespace defaults {
/// \cond SKIP_IN_MANUAL
#define CGAL_PART_DECOMPOSITION_DEFAULT(NAME, TYPE, DEFAULT, ...)                                \
  inline constexpr auto NAME = internal::Default_of<TYPE>::make DEFAULT;
CGAL_PART_DECOMPOSITION_PARAMETERS(CGAL_PART_DECOMPOSITION_DEFAULT, CGAL_PART_DECOMPOSITION_DEFAULT)
#undef CGAL_PART_DECOMPOSITION_DEFAULT
/// \endcond
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
What an entry of `parameter_table` describes.
*/
enum class Parameter_kind
{
  VALUE,         ///< a named parameter that holds a value: an option of the programs
  OBJECT,        ///< a named parameter that holds an object (a normalization, an output)
  METHOD_SWITCH  ///< a field of `Method_variant`, passed by the named parameter `method_variant`
};

/*!
\ingroup PkgPartDecompositionRef
One entry of `parameter_table`.
*/
struct Parameter_description
{
  const char* name;               ///< the named-parameter function or the field, e.g.\ `"freeze_ratio"`
  const char* type;               ///< the value type
  std::string_view default_value; ///< the default, as the list writes it (a list: its items)
  std::string_view paper_value;   ///< a switch: its value in the paper; empty otherwise
  const char* range;              ///< the rule of the range check ("NAME must be RULE"); empty if none
  Parameter_stage stage;          ///< the stage that reads it
  Parameter_kind kind;            ///< a value, an object or a switch of the method
  const char* meaning;            ///< one line
};

/*!
\ingroup PkgPartDecompositionRef
Every named parameter that `decompose()` reads, the package's own and \cgal's
(`number_of_points_per_face`, `verbose`), the reader's `weld_tolerance`, and the switches of
`Method_variant`. The command-line tool `hitops`, the Python module and the reference pages
\ref PD_ParameterTable and \ref PD_MethodSwitches are made from it.
*/
constexpr Parameter_description parameter_table[] = {
#define CGAL_PART_DECOMPOSITION_VALUE_ROW(NAME, TYPE, DEFAULT, STAGE, RANGE, MEANING)            \
  {#NAME, #TYPE, internal::unparenthesized(#DEFAULT), "", RANGE, Parameter_stage::STAGE, Parameter_kind::VALUE, MEANING},
  CGAL_PART_DECOMPOSITION_PARAMETERS(CGAL_PART_DECOMPOSITION_VALUE_ROW, CGAL_PART_DECOMPOSITION_VALUE_ROW)
#undef CGAL_PART_DECOMPOSITION_VALUE_ROW
#define CGAL_PART_DECOMPOSITION_OBJECT_ROW(NAME, TYPE, DEFAULT, STAGE, MEANING)                  \
  {#NAME, TYPE, DEFAULT, "", "", Parameter_stage::STAGE, Parameter_kind::OBJECT, MEANING},
  CGAL_PART_DECOMPOSITION_OBJECT_PARAMETERS(CGAL_PART_DECOMPOSITION_OBJECT_ROW)
#undef CGAL_PART_DECOMPOSITION_OBJECT_ROW
#define CGAL_PART_DECOMPOSITION_SWITCH_ROW(NAME, TYPE, DEFAULT, PAPER, STAGE, MEANING)           \
  {#NAME, #TYPE, #DEFAULT, #PAPER, "", Parameter_stage::STAGE, Parameter_kind::METHOD_SWITCH, MEANING},
  CGAL_PART_DECOMPOSITION_METHOD_SWITCHES(CGAL_PART_DECOMPOSITION_SWITCH_ROW)
#undef CGAL_PART_DECOMPOSITION_SWITCH_ROW
};

/// \cond SKIP_IN_MANUAL
namespace internal {

// The entry of `name` in parameter_table, or nullptr.
constexpr const Parameter_description* find_parameter(std::string_view name)
{
  for(const Parameter_description& p : parameter_table)
    if(p.name == name) return &p;
  return nullptr;
}

// The rule of the range check of `name`, as the table states it.
constexpr const char* range_rule(std::string_view name)
{
  return find_parameter(name) == nullptr ? "" : find_parameter(name)->range;
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

} // namespace internal
/// \endcond

/// \cond SKIP_IN_MANUAL
namespace internal_np {
#define CGAL_PART_DECOMPOSITION_DECLARE_TAG(NAME, ...) enum NAME##_t { NAME };
#define CGAL_PART_DECOMPOSITION_CGAL_TAG(...)
CGAL_PART_DECOMPOSITION_PARAMETERS(CGAL_PART_DECOMPOSITION_DECLARE_TAG, CGAL_PART_DECOMPOSITION_CGAL_TAG)
CGAL_PART_DECOMPOSITION_OBJECT_PARAMETERS(CGAL_PART_DECOMPOSITION_DECLARE_TAG)
#undef CGAL_PART_DECOMPOSITION_CGAL_TAG
#undef CGAL_PART_DECOMPOSITION_DECLARE_TAG
} // namespace internal_np

namespace internal {

// The switches of the method given to a function, the package's method if none.
template <typename NamedParameters>
Method_variant method_switches(const NamedParameters& np)
{
  return CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np::method_variant),
                                            Method_variant());
}

} // namespace internal
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
stage that reads it. Every parameter, with its type, default, range and meaning, is in
`parameter_table`, from which the reference page \ref PD_ParameterTable is made; \cgal's
parameters of the mesh are described in \ref PD_MeshParameters.

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
#define CGAL_PART_DECOMPOSITION_CGAL_FUNCTION(...)
CGAL_PART_DECOMPOSITION_PARAMETERS(CGAL_PART_DECOMPOSITION_DECLARE_FUNCTION, CGAL_PART_DECOMPOSITION_CGAL_FUNCTION)
CGAL_PART_DECOMPOSITION_OBJECT_PARAMETERS(CGAL_PART_DECOMPOSITION_DECLARE_FUNCTION)
#undef CGAL_PART_DECOMPOSITION_CGAL_FUNCTION
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
