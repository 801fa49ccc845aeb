// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_FLOW_FREEZE_PRIOR_H
#define CGAL_PART_DECOMPOSITION_FLOW_FREEZE_PRIOR_H

#include <CGAL/Part_decomposition/stage_results.h>
#include <CGAL/Part_decomposition/Voxel_grid.h>
#include <CGAL/Part_decomposition/geometric_cues.h>
#include <CGAL/Part_decomposition/input_validation.h>
#include <CGAL/Part_decomposition/normalization.h>
#include <CGAL/Part_decomposition/parameters.h>
#include <CGAL/Part_decomposition/topology_score.h>
#include <CGAL/Part_decomposition/internal/Flow_freeze_octree.h>
#include <CGAL/Part_decomposition/internal/mean_curvature.h>
#include <CGAL/Part_decomposition/internal/normal_deviation.h>
#include <CGAL/Part_decomposition/internal/prior_parallel.h>
#include <CGAL/Part_decomposition/internal/sample_accumulation.h>
#include <CGAL/Part_decomposition/internal/triangle_arrays.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <string>
#include <vector>

namespace CGAL {
namespace Part_decomposition {



/// \cond SKIP_IN_MANUAL
namespace internal {

// Whether a parent at one level splits into its 8 children at the next level (App. E.1),
// before backward consistency. `support_below`: some voxel under the parent at a finer level is
// non-empty. An empty parent cannot have non-empty children when all levels come from the same
// samples; on hand-made grids it defers to the finer levels (splits) if they hold anything.
inline bool fusion_rule_splits(Voxel_class parent, const std::array<Voxel_class, 8>& children, bool support_below)
{
  if(parent == Voxel_class::EMPTY) return support_below;
  int nnz = 0, nfreeze = 0, ndiff = 0;
  for(Voxel_class c : children)
  {
    if(c == Voxel_class::EMPTY) continue;
    ++nnz;
    if(c == Voxel_class::FREEZE) ++nfreeze;
    if(c != parent) ++ndiff;
  }
  if(nnz == 0) return false;  // nothing finer to defer to
  if(nnz <= 2) return true;   // sparse-support refinement
  if(parent == Voxel_class::FLOW)
    return nfreeze > 0;       // (ii) fine-freeze promotion, else (i) coarse-flow preservation
  return 2 * ndiff >= nnz;    // (iv) coarse-freeze relaxation, else (iii) coarse-freeze inheritance
}

template <typename T, typename F>
void for_each_child(const Voxel_grid<T>& fine, int i, int j, int k, const F& f)
{
  for(int c = 0; c < 8; ++c)
    f(fine[fine.index(2 * i + (c & 1), 2 * j + ((c >> 1) & 1), 2 * k + ((c >> 2) & 1))]);
}

inline int log2_of_power_of_two(int r)
{
  int d = 0;
  while((1 << d) < r) ++d;
  return d;
}

} // namespace internal
/// \endcond

/*!
\ingroup PkgPartDecompositionRef
fuses per-level Flow/Freeze class grids into one non-overlapping octree carrier and projects it
on the finest grid (paper Sec.\ 3.2, App.\ E.1).

For each parent voxel of a level and its 8 children at the next level, with \f$n_{nz}\f$ the
number of non-empty children and \f$n_{diff}\f$ the number of non-empty children whose class
differs from the parent's, the parent splits (refines) or stays a leaf:
- a parent with \f$n_{nz} \le 2\f$ splits (sparse-support refinement), whatever its class;
- otherwise a `FLOW` parent splits iff a child is `FREEZE` (fine-freeze promotion), else stays a
  Flow leaf (coarse-flow preservation);
- a `FREEZE` parent splits iff \f$n_{diff} / n_{nz} \ge 0.5\f$ (coarse-freeze relaxation), else
  stays a Freeze leaf (coarse-freeze inheritance).

All parent/children decisions are taken independently, then backward consistency is applied
from fine to coarse: a parent that stays a leaf while one of its children splits is forced to
split. A leaf carries the class it has at its own level, except a child of a forced parent,
which carries the class its parent would have had as a leaf; at every level, a leaf that is
empty at its own level carries nothing. A single level means no fusion: every non-empty voxel is
a leaf. The rules never let a Flow leaf cover a Freeze voxel of a finer level (a Flow parent with
a Freeze child splits, and so does every ancestor of a split node): Freeze voxels of the finest
grid stay Freeze; coarse Freeze leaves may turn finer Flow voxels into Freeze.

These decisions drive one `CGAL::Octree` over \f$[-0.5,0.5]^3\f$ whose depth is that of the
finest grid (the cells of depth \f$d\f$ are the voxels of the \f$2^d\f$ grid; above the
coarsest level, only cells that hold support are split). Each finest voxel with surface support
(non-empty at the finest level) gets the class and resolution of its leaf; the other finest
voxels are `EMPTY` with resolution 0.

Grids that do not come from the same samples can be inconsistent; then: a parent that is empty
at its level splits if a voxel below it is non-empty at a finer level (its children carry their
own classes); a non-empty parent whose children are all empty stays a leaf, and the finest
non-empty voxels below it (at deeper levels) take its class.

\par Complexity
Linear in the total number of voxels of the levels, \f$\sum_l r_l^3\f$.

\param level_classes the class grids, coarse to fine, each of twice the resolution of the
       previous one (typically the `classes` of the `Topology_score_field`s at 16, 32, 64)

\returns a prior whose `resolutions`, `classes`, `leaf_resolution`, `number_of_flow_leaves` and
`number_of_freeze_leaves` are set (leaf counts per level, counting non-empty leaves only); its
`fields` are empty and its `normalization` is the identity.

\throws Invalid_input (`INVALID_PARAMETER`) if `level_classes` is empty, a resolution is not a
power of two, not twice the previous one, or the finest is above 256.
*/
inline Hierarchical_prior fuse_flow_freeze(const std::vector<Voxel_grid<Voxel_class> >& level_classes)
{
  typedef Voxel_grid<std::uint8_t> Mask;
  const std::size_t L = level_classes.size();
  if(L == 0)
    throw Invalid_input(Input_error::INVALID_PARAMETER, "fuse_flow_freeze needs at least one level");
  for(std::size_t l = 0; l < L; ++l)
  {
    const int r = level_classes[l].resolution();
    if(!internal::is_power_of_two(r) || (l > 0 && r != 2 * level_classes[l - 1].resolution()) || r > 256)
      throw Invalid_input(Input_error::INVALID_PARAMETER,
                          "level resolutions must be powers of two, each twice the previous, at most 256");
  }
  const std::vector<Voxel_grid<Voxel_class> >& C = level_classes;
  const Voxel_grid<Voxel_class>& finest = C[L - 1];

  // Support strictly below each voxel, fine to coarse.
  std::vector<Mask> below(L);
  below[L - 1] = Mask(finest.resolution(), 0);
  for(std::size_t l = L - 1; l-- > 0;)
  {
    const int r = C[l].resolution();
    below[l] = Mask(r, 0);
    for(int k = 0; k < r; ++k)
      for(int j = 0; j < r; ++j)
        for(int i = 0; i < r; ++i)
        {
          std::uint8_t any = 0;
          const std::size_t p = below[l].index(i, j, k);
          for(int c = 0; c < 8; ++c)
          {
            const std::size_t q = C[l + 1].index(2 * i + (c & 1), 2 * j + ((c >> 1) & 1), 2 * k + ((c >> 2) & 1));
            any |= std::uint8_t(C[l + 1][q] != Voxel_class::EMPTY || below[l + 1][q]);
          }
          below[l][p] = any;
        }
  }

  // Independent decisions (1 = split by a rule), then backward consistency (2 = forced).
  std::vector<Mask> split(L);
  for(std::size_t l = 0; l + 1 < L; ++l)
  {
    const int r = C[l].resolution();
    split[l] = Mask(r, 0);
    for(int k = 0; k < r; ++k)
      for(int j = 0; j < r; ++j)
        for(int i = 0; i < r; ++i)
        {
          std::array<Voxel_class, 8> children;
          int n = 0;
          internal::for_each_child(C[l + 1], i, j, k, [&](Voxel_class c) { children[n++] = c; });
          const std::size_t p = split[l].index(i, j, k);
          split[l][p] = internal::fusion_rule_splits(C[l][p], children, below[l][p] != 0) ? 1 : 0;
        }
  }
  for(std::size_t l = L >= 2 ? L - 2 : 0; l-- > 0;)
  {
    const int r = C[l].resolution();
    for(int k = 0; k < r; ++k)
      for(int j = 0; j < r; ++j)
        for(int i = 0; i < r; ++i)
        {
          const std::size_t p = split[l].index(i, j, k);
          if(split[l][p]) continue;
          bool child_splits = false;
          internal::for_each_child(split[l + 1], i, j, k, [&](std::uint8_t s) { child_splits |= (s != 0); });
          if(child_splits) split[l][p] = 2;
        }
  }

  // The class each voxel carries if it is a leaf.
  std::vector<Voxel_grid<Voxel_class> > carried(L);
  carried[0] = C[0];
  for(std::size_t l = 1; l < L; ++l)
  {
    const int r = C[l].resolution();
    carried[l] = Voxel_grid<Voxel_class>(r, Voxel_class::EMPTY);
    for(int k = 0; k < r; ++k)
      for(int j = 0; j < r; ++j)
        for(int i = 0; i < r; ++i)
        {
          const std::size_t q = carried[l].index(i, j, k);
          if(C[l][q] == Voxel_class::EMPTY) continue;
          const std::size_t p = carried[l - 1].index(i / 2, j / 2, k / 2);
          carried[l][q] = split[l - 1][p] == 2 ? carried[l - 1][p] : C[l][q];
        }
  }

  // Above the coarsest level: split the cells that hold support anywhere below.
  const int d0 = internal::log2_of_power_of_two(C[0].resolution());
  const int depth = d0 + int(L) - 1;
  std::vector<Mask> occupied(std::size_t(d0) + 1);
  occupied[std::size_t(d0)] = Mask(C[0].resolution(), 0);
  for(std::size_t p = 0; p < C[0].size(); ++p)
    occupied[std::size_t(d0)][p] = std::uint8_t(C[0][p] != Voxel_class::EMPTY || below[0][p]);
  for(int d = d0; d-- > 0;)
  {
    const int r = 1 << d;
    occupied[std::size_t(d)] = Mask(r, 0);
    for(int k = 0; k < r; ++k)
      for(int j = 0; j < r; ++j)
        for(int i = 0; i < r; ++i)
        {
          std::uint8_t any = 0;
          internal::for_each_child(occupied[std::size_t(d) + 1], i, j, k, [&](std::uint8_t o) { any |= o; });
          occupied[std::size_t(d)](i, j, k) = any;
        }
  }

  internal::Flow_freeze_octree octree;
  octree.refine([&](int d, const internal::Octree_cell& g) -> bool {
    const int i = int(g[0]), j = int(g[1]), k = int(g[2]);
    if(d < d0) return occupied[std::size_t(d)](i, j, k) != 0;
    if(d >= depth) return false;
    return split[std::size_t(d - d0)](i, j, k) != 0;
  });

  Hierarchical_prior prior;
  prior.resolutions.resize(L);
  for(std::size_t l = 0; l < L; ++l) prior.resolutions[l] = C[l].resolution();
  prior.classes = Voxel_grid<Voxel_class>(finest.resolution(), Voxel_class::EMPTY);
  prior.leaf_resolution = Voxel_grid<std::uint16_t>(finest.resolution(), 0);
  prior.number_of_flow_leaves.assign(L, 0);
  prior.number_of_freeze_leaves.assign(L, 0);
  octree.for_each_leaf([&](int d, const internal::Octree_cell& g) {
    if(d < d0) return; // a cell without support above the coarsest level
    const std::size_t l = std::size_t(d - d0);
    const Voxel_class cls = carried[l](int(g[0]), int(g[1]), int(g[2]));
    if(cls == Voxel_class::EMPTY) return;
    (cls == Voxel_class::FLOW ? prior.number_of_flow_leaves : prior.number_of_freeze_leaves)[l] += 1;
    const int s = int(L - 1 - l);
    const std::uint16_t res = std::uint16_t(C[l].resolution());
    const int n = 1 << s;
    for(int k = int(g[2]) << s; k < (int(g[2]) + 1) << s; ++k)
      for(int j = int(g[1]) << s; j < (int(g[1]) + 1) << s; ++j)
      {
        const std::size_t row = finest.index(int(g[0]) << s, j, k);
        for(int i = 0; i < n; ++i)
          if(finest[row + std::size_t(i)] != Voxel_class::EMPTY)
          {
            prior.classes[row + std::size_t(i)] = cls;
            prior.leaf_resolution[row + std::size_t(i)] = res;
          }
      }
  });
  return prior;
}

/// \cond SKIP_IN_MANUAL
namespace internal {

template <typename Range>
std::vector<int> checked_resolutions(const Range& range)
{
  std::vector<int> r;
  for(auto it = std::begin(range); it != std::end(range); ++it) r.push_back(int(*it));
  bool ok = !r.empty() && r.back() <= 256;
  for(std::size_t l = 0; ok && l < r.size(); ++l)
    ok = is_power_of_two(r[l]) && (l == 0 || r[l] == 2 * r[l - 1]);
  if(!ok)
    throw Invalid_input(Input_error::INVALID_PARAMETER,
                        "voxel_resolutions must be a non-empty list of powers of two, each twice the "
                        "previous one, the finest at most 256");
  return r;
}

} // namespace internal
/// \endcond

/*!
\ingroup PkgPartDecompositionRef
computes the hierarchical Flow/Freeze prior of `tm` (paper Alg.\ A.1, lines 1-5): the geometric
cues once (`compute_geometric_cues()`), the topology score and its Flow/Freeze cut at each of
the `voxel_resolutions` from a single pass over the surface samples (`compute_topology_score()`),
and their fusion (`fuse_flow_freeze()`).

The result is the same with `CGAL::Sequential_tag` and `CGAL::Parallel_tag`, for any number of
threads.

\par Complexity
\f$O(F \log F + F\,N_{face} + r^3)\f$ for \f$F\f$ faces, \f$N_{face}\f$ = `number_of_points_per_face` and
the finest resolution \f$r\f$: the cues (`compute_geometric_cues()`), one pass over the samples for all
resolutions, and the fusion.

\tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag`
\tparam TriangleMesh a model of `FaceListGraph` and `VertexListGraph`
\tparam NamedParameters a sequence of named parameters

\param tm the triangle mesh
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{vertex_point_map}
    \cgalParamDescription{a property map associating points to the vertices of `tm`}
    \cgalParamType{a class model of `ReadablePropertyMap` with
                   `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and
                   `%Point_3` as value type}
    \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
  \cgalParamNEnd
  \cgalParamNBegin{geom_traits}
    \cgalParamDescription{an instance of a geometric traits class; the computations are done in
                          `double` from the coordinates of the points, so only its point type matters}
    \cgalParamType{a model of `Kernel`}
    \cgalParamDefault{a \cgal kernel deduced from the point type}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_index_map}
    \cgalParamDescription{a property map associating to each vertex of `tm` a unique index in `[0, num_vertices(tm))`}
    \cgalParamType{a class model of `ReadablePropertyMap` with
                   `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `std::size_t` as value type}
    \cgalParamDefault{an automatically indexed internal map}
  \cgalParamNEnd
  \cgalParamNBegin{face_index_map}
    \cgalParamDescription{a property map associating to each face of `tm` a unique index in `[0, num_faces(tm))`}
    \cgalParamType{a class model of `ReadablePropertyMap` with
                   `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and `std::size_t` as value type}
    \cgalParamDefault{an automatically indexed internal map}
  \cgalParamNEnd
  \cgalParamNBegin{normalization}
    \cgalParamDescription{the map from input coordinates to the normalized cube \f$[-0.5,0.5]^3\f$}
    \cgalParamType{`CGAL::Part_decomposition::Normalization`}
    \cgalParamDefault{`compute_normalization(tm, np)`}
  \cgalParamNEnd
  \cgalParamNBegin{normalization_margin}
    \cgalParamDescription{passed to `compute_normalization()` when `normalization` is not given}
    \cgalParamType{`double`}
    \cgalParamDefault{`2.0/64`}
  \cgalParamNEnd
  \cgalParamNBegin{voxel_resolutions}
    \cgalParamDescription{the resolutions of the grids, coarse to fine}
    \cgalParamType{`std::vector<int>` (or any range of integers): powers of two, each twice the
                   previous one, the finest at most 256}
    \cgalParamDefault{`{16, 32, 64}`}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_points_per_face}
    \cgalParamDescription{the number of samples per face, \f$n^2\f$ for \f$n\f$ divisions per side (`barycentric_sample_grid()`)}
    \cgalParamType{an integer type, a positive perfect square}
    \cgalParamDefault{`36`}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_neighbors}
    \cgalParamDescription{the number \f$k\f$ of nearest faces of the normal deviation cue}
    \cgalParamType{an integer type, at least 1}
    \cgalParamDefault{`8`}
  \cgalParamNEnd
  \cgalParamNBegin{curvature_percentile}
    \cgalParamDescription{the percentile at which the vertex curvatures are clipped}
    \cgalParamType{`double`, in `[0, 100]`}
    \cgalParamDefault{`99.5`}
  \cgalParamNEnd
  \cgalParamNBegin{cue_weights}
    \cgalParamDescription{the weights \f$(\lambda_1, \lambda_2, \lambda_3, \lambda_4)\f$ of the topology score}
    \cgalParamType{`std::array<double, 4>` (or any range of 4 finite numbers)}
    \cgalParamDefault{`{1, 1, 1, 1}`}
  \cgalParamNEnd
  \cgalParamNBegin{freeze_ratio}
    \cgalParamDescription{the fraction \f$\alpha\f$ of active voxels that become Freeze at each resolution}
    \cgalParamType{`double`, in \f$(0, 1)\f$}
    \cgalParamDefault{`0.15`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the prior: the fields at each resolution, the fused classes and leaf resolutions on the
finest grid, the leaf counts per level and the normalization used.

\pre `tm` has no garbage (`Surface_mesh`)
\throws Invalid_input (`INVALID_PARAMETER`) if a parameter is out of range; (`NOT_TRIANGLE_MESH`)
if a face is not a triangle; the exceptions of `compute_normalization()` when `normalization` is
not given.
*/
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename TriangleMesh,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Hierarchical_prior compute_flow_freeze_prior(const TriangleMesh& tm,
                                             const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  internal::static_check_concurrency_tag<ConcurrencyTag>();

  // Every parameter is checked before any work.
  const std::vector<int> resolutions = internal::checked_resolutions(
    choose_parameter(get_parameter(np, internal_np::voxel_resolutions), defaults::voxel_resolutions()));
  const double percentile = internal::curvature_percentile_parameter(np);
  const std::size_t k = internal::number_of_neighbors_parameter(np);
  const std::vector<std::array<double, 3> > barycentric = internal::barycentric_sample_grid_parameter(np);
  const std::array<double, 4> weights = internal::cue_weights_parameter(np);
  const double alpha = internal::freeze_ratio_parameter(np);

  const internal::Triangle_arrays mesh = internal::make_triangle_arrays(tm, np);
  const Normalization normalization = internal::normalization_parameter(tm, np);

  const internal::Vertex_corners vc = internal::make_vertex_corners(mesh);
  const std::vector<double> kappa = internal::vertex_mean_curvatures<ConcurrencyTag>(mesh, vc);
  const std::vector<double> c = internal::face_curvature_cue(mesh, vc, kappa, percentile);
  const std::vector<double> phi = internal::face_normal_deviation<ConcurrencyTag>(mesh, k);

  std::vector<Topology_score_field> fields = internal::topology_score_fields<ConcurrencyTag>(
    mesh, c, phi, resolutions, normalization, barycentric, weights, alpha);

  std::vector<Voxel_grid<Voxel_class> > level_classes;
  level_classes.reserve(fields.size());
  for(const Topology_score_field& field : fields) level_classes.push_back(field.classes);
  Hierarchical_prior prior = fuse_flow_freeze(level_classes);
  prior.fields = std::move(fields);
  prior.normalization = normalization;
  return prior;
}

} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_FLOW_FREEZE_PRIOR_H
