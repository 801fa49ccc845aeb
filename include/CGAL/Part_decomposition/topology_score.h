// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_TOPOLOGY_SCORE_H
#define CGAL_PART_DECOMPOSITION_TOPOLOGY_SCORE_H

#include <CGAL/Part_decomposition/stage_results.h>
#include <CGAL/Part_decomposition/Voxel_grid.h>
#include <CGAL/Part_decomposition/geometric_cues.h>
#include <CGAL/Part_decomposition/input_validation.h>
#include <CGAL/Part_decomposition/normalization.h>
#include <CGAL/Part_decomposition/parameters.h>
#include <CGAL/Part_decomposition/internal/grid/sample_accumulation.h>
#include <CGAL/Part_decomposition/internal/toolbox/toolbox.h>
#include <CGAL/Part_decomposition/internal/toolbox/triangle_arrays.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <vector>

namespace CGAL {
namespace Part_decomposition {



/// \cond SKIP_IN_MANUAL
namespace internal {

// Fills every grid of `field` but the cut from the sums; the density factor sqrt(n) only with
// `use_density` (the paper's "w/o Density" ablation drops it).
inline void make_score_field(const Voxel_sums& vs, const std::array<double, 4>& weights, bool use_density,
                             Topology_score_field& field)
{
  const int r = vs.r;
  field.resolution = r;
  field.sample_count = Voxel_grid<std::uint32_t>(r, 0);
  field.curvature_mean = Voxel_grid<double>(r, 0.);
  field.curvature_deviation = Voxel_grid<double>(r, 0.);
  field.curvature_gradient = Voxel_grid<double>(r, 0.);
  field.normal_deviation = Voxel_grid<double>(r, 0.);
  field.score = Voxel_grid<double>(r, 0.);
  field.sample_count.values() = vs.n;
  std::vector<double>& mu = field.curvature_mean.values();
  for(std::size_t v = 0; v < vs.n.size(); ++v)
  {
    if(vs.n[v] == 0) continue;
    const double inv = 1. / double(vs.n[v]);
    const double m = vs.s1[v] * inv;
    mu[v] = m;
    field.curvature_deviation[v] = std::sqrt((std::max)(0., vs.s2[v] * inv - m * m));
    field.normal_deviation[v] = vs.sphi[v] * inv;
  }
  for(int k = 0; k < r; ++k)
    for(int j = 0; j < r; ++j)
      for(int i = 0; i < r; ++i)
      {
        const std::size_t v = field.score.index(i, j, k);
        if(vs.n[v] == 0) continue;
        const double delta = dense_gradient_norm(mu, r, i, j, k);
        field.curvature_gradient[v] = delta;
        const double evidence = weights[0] * mu[v] + weights[1] * field.curvature_deviation[v] +
                                weights[2] * delta + weights[3] * field.normal_deviation[v];
        field.score[v] = use_density ? evidence * std::sqrt(double(vs.n[v])) : evidence;
      }
}

inline void check_freeze_ratio(double alpha)
{
  check_parameter(alpha > 0. && alpha < 1., "freeze_ratio");
}

// The Flow/Freeze cut of a field whose `sample_count` and `score` are set.
inline void flow_freeze_cut(Topology_score_field& field, double alpha)
{
  const std::size_t size = field.score.size();
  CGAL_precondition(field.sample_count.size() == size);
  field.classes = Voxel_grid<Voxel_class>(field.score.resolution(), Voxel_class::EMPTY);
  std::vector<double> active;
  for(std::size_t v = 0; v < size; ++v)
    if(field.sample_count[v] > 0) active.push_back(field.score[v]);
  field.number_of_active_voxels = active.size();
  field.number_of_freeze_voxels = 0;
  field.threshold = 0.;
  if(active.empty()) return;
  field.threshold = linear_quantile(active, 1. - alpha);
  for(std::size_t v = 0; v < size; ++v)
  {
    if(field.sample_count[v] == 0) continue;
    // A zero score carries no boundary evidence: it only ties at a zero threshold (more than
    // 1 - alpha of the voxels without any evidence, e.g. flat axis-aligned faces), where freezing
    // it would freeze the whole support.
    const bool freeze = field.score[v] >= field.threshold && field.score[v] > 0.;
    field.classes[v] = freeze ? Voxel_class::FREEZE : Voxel_class::FLOW;
    field.number_of_freeze_voxels += freeze ? 1 : 0;
  }
}

// The named parameters of the topology score (compute_topology_score(), and through it
// compute_flow_freeze_prior()): the samples of a face, the cue weights, alpha, the density switch.
struct Topology_score_parameters
{
  std::vector<std::array<double, 3> > barycentric;
  std::array<double, 4> cue_weights;
  double freeze_ratio;
  bool use_density;
};

// The score fields and cuts at every resolution of `resolutions`, all from one pass over the
// samples binned at `sampling_resolution`, a power of two times each of them: large faces are cut
// relative to that grid, and a coarser voxel sums the counts of the finer voxels it holds.
// `sampled`, if given, receives the voxels of the sampling grid that hold a sample.
template <typename ConcurrencyTag>
std::vector<Topology_score_field>
topology_score_fields(const Triangle_arrays& mesh, const std::vector<double>& c, const std::vector<double>& phi,
                      const std::vector<int>& resolutions, int sampling_resolution,
                      const Normalization& normalization, const Topology_score_parameters& parameters,
                      Voxel_grid<std::uint8_t>* sampled = nullptr)
{
  CGAL_precondition(!resolutions.empty());
  const int rf = sampling_resolution;
  std::vector<Voxel_sums> sums(resolutions.size());
  for(std::size_t l = 0; l < resolutions.size(); ++l)
  {
    const int r = resolutions[l];
    CGAL_precondition(r >= 1 && rf % r == 0 && is_power_of_two(rf / r));
    sums[l].r = r;
    while((r << sums[l].shift) < rf) ++sums[l].shift;
  }
  std::vector<Vec3> unit_points(mesh.points.size());
  for(std::size_t v = 0; v < unit_points.size(); ++v)
    unit_points[v] = normalization.to_unit(mesh.points[v][0], mesh.points[v][1], mesh.points[v][2]);
  accumulate_samples<ConcurrencyTag>(unit_points, mesh.faces, c, phi, parameters.barycentric, rf, sums, sampled);

  std::vector<Topology_score_field> fields(resolutions.size());
  for_each_block<ConcurrencyTag>(resolutions.size(), 1, [&](std::size_t begin, std::size_t end) {
    for(std::size_t l = begin; l < end; ++l)
    {
      make_score_field(sums[l], parameters.cue_weights, parameters.use_density, fields[l]);
      flow_freeze_cut(fields[l], parameters.freeze_ratio);
    }
  });
  return fields;
}

// The signature of the benchmark (benchmark/Part_decomposition/bench_prior.cpp): samples binned at
// the finest of `resolutions`, with the density term.
template <typename ConcurrencyTag>
std::vector<Topology_score_field>
topology_score_fields(const Triangle_arrays& mesh, const std::vector<double>& c, const std::vector<double>& phi,
                      const std::vector<int>& resolutions, const Normalization& normalization,
                      const std::vector<std::array<double, 3> >& barycentric,
                      const std::array<double, 4>& weights, double alpha)
{
  CGAL_precondition(!resolutions.empty());
  return topology_score_fields<ConcurrencyTag>(
    mesh, c, phi, resolutions, *std::max_element(resolutions.begin(), resolutions.end()), normalization,
    Topology_score_parameters{barycentric, weights, alpha, Method_variant().use_density});
}

} // namespace internal
/// \endcond

/*!
\ingroup PkgPartDecompositionRef
returns the barycentric coordinates \f$(u,v,w)\f$, \f$u+v+w=1\f$, of the deterministic sample
grid of a triangle (paper App.\ B, "Surface sampling"): each side is split in \f$n\f$ equal
parts, which cuts the triangle into \f$n^2\f$ congruent sub-triangles, and the samples are their
centroids. All samples are strictly inside the triangle, none is shared with a neighbouring
face, and they are evenly spread over its area. The order is fixed: the \f$n(n+1)/2\f$ upright
sub-triangles, then the \f$n(n-1)/2\f$ inverted ones. A sample is
\f$u\,\mathbf{v}_0 + v\,\mathbf{v}_1 + w\,\mathbf{v}_2\f$ for the face's vertices in
`vertices_around_face()` order.

\par Complexity
Linear in `number_of_points_per_face`.

\param number_of_points_per_face \f$n^2\f$, a perfect square (36 in the paper)

\throws Invalid_input (`INVALID_PARAMETER`) if `number_of_points_per_face` is not a positive
perfect square.
*/
inline std::vector<std::array<double, 3> > barycentric_sample_grid(std::size_t number_of_points_per_face)
{
  std::size_t n = std::size_t(std::llround(std::sqrt(double(number_of_points_per_face))));
  internal::check_parameter(number_of_points_per_face != 0 && n * n == number_of_points_per_face,
                            "number_of_points_per_face");
  std::vector<std::array<double, 3> > samples;
  samples.reserve(number_of_points_per_face);
  const double dn = double(n);
  // Upright sub-triangle at lattice node (i,j,k), i+j+k = n-1: centroid (i+1/3, j+1/3, k+1/3)/n.
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t j = 0; i + j < n; ++j)
    {
      const double u = (double(i) + 1. / 3.) / dn, v = (double(j) + 1. / 3.) / dn;
      samples.push_back({{u, v, 1. - u - v}});
    }
  // Inverted sub-triangle at (i,j,k), i+j+k = n-2: centroid (i+2/3, j+2/3, k+2/3)/n.
  for(std::size_t i = 0; i + 1 < n; ++i)
    for(std::size_t j = 0; i + j + 1 < n; ++j)
    {
      const double u = (double(i) + 2. / 3.) / dn, v = (double(j) + 2. / 3.) / dn;
      samples.push_back({{u, v, 1. - u - v}});
    }
  return samples;
}

/*!
\ingroup PkgPartDecompositionRef
(re)computes the Flow/Freeze cut of `field` (paper Eq.\ 4, 5) from its `sample_count` and
`score` grids: \f$\tau_\alpha\f$ is the \f$(1-\alpha)\f$-quantile of the scores of the active
voxels (`sample_count > 0`), computed with linear interpolation between order statistics (the
default of `numpy.quantile`: with the \f$m\f$ active scores sorted increasingly
\f$s_0 \le \dots \le s_{m-1}\f$ and \f$h = (m-1)(1-\alpha)\f$,
\f$\tau_\alpha = s_{\lfloor h\rfloor} + (h - \lfloor h\rfloor)(s_{\lfloor h\rfloor+1} - s_{\lfloor h\rfloor})\f$).
Active voxels with \f$S_B \geq \tau_\alpha\f$ become `FREEZE`, the others `FLOW`, inactive
voxels `EMPTY`; a zero score is never Freeze (when more than \f$1-\alpha\f$ of the active
voxels have no evidence at all, \f$\tau_\alpha = 0\f$ and only the positive scores freeze).
Without ties the number of Freeze voxels is \f$m - \lceil h \rceil\f$ (or
\f$m - h\f$ when \f$h\f$ is an integer), within one voxel of \f$\alpha m\f$; tied scores at the
threshold are all Freeze. Sets `classes`, `threshold`, `number_of_active_voxels` and
`number_of_freeze_voxels`.

\par Complexity
Linear in the number of voxels \f$r^3\f$ (the quantile is a selection).

\param field a field whose `sample_count` and `score` grids have the same resolution
\param freeze_ratio \f$\alpha\f$

\throws Invalid_input (`INVALID_PARAMETER`) unless \f$0 < \alpha < 1\f$.
*/
inline void apply_flow_freeze_cut(Topology_score_field& field, double freeze_ratio)
{
  internal::check_freeze_ratio(freeze_ratio);
  internal::flow_freeze_cut(field, freeze_ratio);
}

/// \cond SKIP_IN_MANUAL
namespace internal {

// Any range of 4 finite numbers (std::array, std::vector, ...) as the cue weights.
template <typename Range>
std::array<double, 4> to_cue_weights(const Range& range)
{
  std::array<double, 4> w{{0., 0., 0., 0.}};
  const bool four = std::distance(std::begin(range), std::end(range)) == 4;
  bool finite = true;
  std::size_t n = 0;
  for(auto it = std::begin(range); four && it != std::end(range); ++it, ++n)
  {
    w[n] = double(*it);
    finite = finite && std::isfinite(w[n]);
  }
  check_parameter(four && finite, "cue_weights");
  return w;
}

// The one reader of the parameters of the topology score, defaults from `defaults::`.
template <typename NamedParameters>
Topology_score_parameters read_topology_score_parameters(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  Topology_score_parameters p;
  const double n = double(choose_parameter(get_parameter(np, CGAL::internal_np::number_of_points_per_face),
                                           defaults::number_of_points_per_face));
  check_parameter(n >= 1. && n <= 1e7 && n == std::floor(n), "number_of_points_per_face");
  p.barycentric = barycentric_sample_grid(std::size_t(n));
  p.cue_weights = to_cue_weights(choose_parameter(get_parameter(np, internal_np::cue_weights), defaults::cue_weights));
  p.freeze_ratio = double(choose_parameter(get_parameter(np, internal_np::freeze_ratio), defaults::freeze_ratio));
  check_freeze_ratio(p.freeze_ratio);
  p.use_density = internal::method_switches(np).use_density;
  return p;
}

// The single resolution of compute_topology_score() and the grid its samples are binned in,
// checked as the lists of `voxel_resolutions` they stand for.
inline void check_topology_score_resolutions(int resolution, int sampling_resolution)
{
  check_voxel_resolutions(std::vector<int>(1, resolution));
  check_voxel_resolutions(std::vector<int>(1, sampling_resolution));
  check_parameter(sampling_resolution >= resolution, "sampling_resolution", "at least the resolution");
}

} // namespace internal
/// \endcond

/*!
\ingroup PkgPartDecompositionRef
computes the voxel cues, the topology score \f$S_B\f$ and its Flow/Freeze cut at resolution
`resolution` (paper Sec.\ 3.2, Eq.\ 3-5, App.\ B), from samples binned in the grid of resolution
`sampling_resolution`.

Every face gets the `number_of_points_per_face` (\f$N_{face}\f$) samples of
`barycentric_sample_grid()`; they are mapped to the normalized cube by `normalization` and binned
with `voxel_coordinate()` in the sampling grid, of resolution \f$r_s\f$ = `sampling_resolution`.
A face counts, in each voxel of the sampling grid:
- if its three corners lie in one voxel: its \f$N_{face}\f$ samples, all in that voxel;
- else, if its longest edge is at most \f$\sqrt{N_{face}}/2\f$ voxels (samples at most half a
  voxel apart): the number of its samples in the voxel (\f$N_{face}\f$ in total);
- else (a large face) it is cut by longest-edge bisection until no piece has an edge longer than
  \f$\sqrt{N_{face}}/2\f$ voxels (or a piece is \f$2^{-30}\f$ of the face); every piece gets the
  \f$N_{face}\f$ samples, each weighted by the piece's share of the face's area, and the face
  counts, in each voxel it reaches, the sum of the weights of its samples there rounded to the
  nearest integer, but at least 1. The weights sum to \f$N_{face}\f$, but the counts do not: the
  face counts at least the number of voxels it reaches (1 per voxel when a voxel gets less than
  half a sample's worth of its area), so that large triangles leave no hole in the active set.

A voxel of the grid of resolution \f$r\f$ sums the counts of the voxels of the sampling grid it
holds: \f$n\f$, the number of samples, and, with each sample carrying the values of its face, the
mean \f$\mu^\kappa\f$ and standard deviation \f$\sigma^\kappa = \sqrt{\max(0, E[c^2] - \mu^2)}\f$ of
the face curvature cue and the mean normal deviation \f$\phi_{norm}\f$.
\f$\Delta^\kappa = \|\nabla\mu^\kappa\|\f$ is taken on the dense \f$r^3\f$ array of
\f$\mu^\kappa\f$ (0 in empty voxels) with unit spacing: central differences inside, one-sided
differences at the border of the grid. Then
\f$S_B = (\lambda_1\mu^\kappa + \lambda_2\sigma^\kappa + \lambda_3\Delta^\kappa + \lambda_4\phi_{norm})\sqrt{n}\f$
on the active voxels (\f$n > 0\f$), without the density factor \f$\sqrt{n}\f$ when `use_density`
is `false`, and `apply_flow_freeze_cut()` with \f$\alpha\f$ = `freeze_ratio` gives the classes.
Every grid holds 0 (`EMPTY`) outside the active voxels.

With `sampling_resolution` the finest of the `voxel_resolutions` of `compute_flow_freeze_prior()`
(and the same named parameters), the result is the prior's field at `resolution`; the overload
without it bins the samples at `resolution` itself.

The sums are accumulated in face order whatever the number of threads: results are identical
with `CGAL::Sequential_tag` and `CGAL::Parallel_tag`.

\par Complexity
\f$O(F\,N_{face} + r_s^3)\f$ for \f$F\f$ faces with no large face; a large face costs
\f$N_{face}\f$ per piece.

\tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag`
\tparam TriangleMesh a model of `FaceListGraph` and `VertexListGraph`
\tparam FaceCurvatureMap a model of `ReadablePropertyMap` with
        `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and `double` as value type
\tparam FaceNormalDeviationMap a model of `ReadablePropertyMap` with
        `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and `double` as value type
\tparam NamedParameters a sequence of named parameters

\param tm the triangle mesh
\param face_curvature_map the face curvature cue \f$c_f\f$ (e.g.\ from `compute_geometric_cues()`)
\param face_normal_deviation_map the normal deviation \f$\phi_{norm}(f)\f$
\param resolution the resolution \f$r\f$ of the grid
\param sampling_resolution the resolution \f$r_s\f$ of the grid the samples are binned in, a
       power of two times `resolution`
\param np an optional sequence of named parameters; this function reads `vertex_point_map`,
`vertex_index_map`, `face_index_map` (\ref PD_MeshParameters), `normalization`,
`normalization_margin`, `number_of_points_per_face`, `cue_weights`, `freeze_ratio` and
`method_variant` (its switch `use_density`) (\ref PD_ParameterTable)

\returns the field at resolution `resolution`.

\pre `tm` has no garbage (`Surface_mesh`)
\throws Invalid_input (`INVALID_PARAMETER`) if `resolution` or `sampling_resolution`, each taken as
a list of one resolution, breaks the rule of `voxel_resolutions` (a power of two from 1 to 256),
if `sampling_resolution` is below `resolution`, or if a parameter is out of range;
(`NOT_TRIANGLE_MESH`) if a face is not a triangle; the exceptions of `compute_normalization()`
when `normalization` is not given.
*/
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename TriangleMesh,
          typename FaceCurvatureMap, typename FaceNormalDeviationMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Topology_score_field compute_topology_score(const TriangleMesh& tm, FaceCurvatureMap face_curvature_map,
                                            FaceNormalDeviationMap face_normal_deviation_map, int resolution,
                                            int sampling_resolution,
                                            const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  internal::static_check_concurrency_tag<ConcurrencyTag>();
  internal::check_topology_score_resolutions(resolution, sampling_resolution);
  const internal::Topology_score_parameters parameters = internal::read_topology_score_parameters(np);
  typedef typename GetVertexPointMap<TriangleMesh, NamedParameters>::const_type VPM;
  const VPM vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                   get_const_property_map(CGAL::vertex_point, tm));
  const auto fim = CGAL::get_initialized_face_index_map(tm, np);
  const internal::Triangle_arrays mesh =
    internal::make_triangle_arrays(tm, vpm, CGAL::get_initialized_vertex_index_map(tm, np), fim);
  std::vector<double> c(mesh.faces.size(), 0.), phi(mesh.faces.size(), 0.);
  for(auto f : faces(tm))
  {
    const std::size_t i = std::size_t(get(fim, f));
    c[i] = double(get(face_curvature_map, f));
    phi[i] = double(get(face_normal_deviation_map, f));
  }
  const Normalization normalization = internal::read_normalization(tm, np);
  std::vector<Topology_score_field> fields = internal::topology_score_fields<ConcurrencyTag>(
    mesh, c, phi, std::vector<int>(1, resolution), sampling_resolution, normalization, parameters);
  return std::move(fields.front());
}

/*!
\ingroup PkgPartDecompositionRef
computes the topology score at `resolution` with the samples binned at `resolution` itself:
`compute_topology_score(tm, face_curvature_map, face_normal_deviation_map, resolution, resolution, np)`.
*/
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename TriangleMesh,
          typename FaceCurvatureMap, typename FaceNormalDeviationMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Topology_score_field compute_topology_score(const TriangleMesh& tm, FaceCurvatureMap face_curvature_map,
                                            FaceNormalDeviationMap face_normal_deviation_map, int resolution,
                                            const NamedParameters& np = CGAL::parameters::default_values())
{
  return compute_topology_score<ConcurrencyTag>(tm, face_curvature_map, face_normal_deviation_map, resolution,
                                                resolution, np);
}

} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_TOPOLOGY_SCORE_H
