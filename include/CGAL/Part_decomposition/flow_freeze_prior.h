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
#include <CGAL/Part_decomposition/internal/grid/unit_cube_octree.h>
#include <CGAL/Part_decomposition/internal/cues/mean_curvature.h>
#include <CGAL/Part_decomposition/internal/cues/normal_deviation.h>
#include <CGAL/Part_decomposition/internal/toolbox/toolbox.h>
#include <CGAL/Part_decomposition/internal/toolbox/triangle_arrays.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>
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

typedef Voxel_grid<std::uint8_t> Level_mask;
typedef std::vector<Voxel_grid<Voxel_class> > Level_classes;

// The level resolutions follow the one rule of `voxel_resolutions`.
inline void check_level_resolutions(const Level_classes& C)
{
  std::vector<int> resolutions;
  for(const Voxel_grid<Voxel_class>& level : C) resolutions.push_back(level.resolution());
  check_voxel_resolutions(resolutions);
}

// Per level, whether some voxel strictly below each voxel (at a finer level) is non-empty.
inline std::vector<Level_mask> support_below(const Level_classes& C)
{
  const std::size_t L = C.size();
  std::vector<Level_mask> below(L);
  below[L - 1] = Level_mask(C[L - 1].resolution(), 0);
  for(std::size_t l = L - 1; l-- > 0;)
  {
    const int r = C[l].resolution();
    below[l] = Level_mask(r, 0);
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
  return below;
}

// Per level but the finest, whether each voxel splits: 1 by a fusion rule, taken independently,
// then 2 when forced by backward consistency (a child splits), from fine to coarse.
inline std::vector<Level_mask> split_decisions(const Level_classes& C, const std::vector<Level_mask>& below)
{
  const std::size_t L = C.size();
  std::vector<Level_mask> split(L);
  for(std::size_t l = 0; l + 1 < L; ++l)
  {
    const int r = C[l].resolution();
    split[l] = Level_mask(r, 0);
    for(int k = 0; k < r; ++k)
      for(int j = 0; j < r; ++j)
        for(int i = 0; i < r; ++i)
        {
          std::array<Voxel_class, 8> children;
          int n = 0;
          for_each_child(C[l + 1], i, j, k, [&](Voxel_class c) { children[n++] = c; });
          const std::size_t p = split[l].index(i, j, k);
          split[l][p] = fusion_rule_splits(C[l][p], children, below[l][p] != 0) ? 1 : 0;
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
          for_each_child(split[l + 1], i, j, k, [&](std::uint8_t s) { child_splits |= (s != 0); });
          if(child_splits) split[l][p] = 2;
        }
  }
  return split;
}

// Per level, the class each voxel carries if it is a leaf: its own, or, below a forced parent,
// the class its parent would have carried.
inline Level_classes carried_classes(const Level_classes& C, const std::vector<Level_mask>& split)
{
  const std::size_t L = C.size();
  Level_classes carried(L);
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
  return carried;
}

// Per octree depth up to the coarsest level (depth d0), whether a cell holds support anywhere below.
inline std::vector<Level_mask> occupied_above_coarsest(const Level_classes& C, const std::vector<Level_mask>& below)
{
  const int d0 = log2_of_power_of_two(C[0].resolution());
  std::vector<Level_mask> occupied(std::size_t(d0) + 1);
  occupied[std::size_t(d0)] = Level_mask(C[0].resolution(), 0);
  for(std::size_t p = 0; p < C[0].size(); ++p)
    occupied[std::size_t(d0)][p] = std::uint8_t(C[0][p] != Voxel_class::EMPTY || below[0][p]);
  for(int d = d0; d-- > 0;)
  {
    const int r = 1 << d;
    occupied[std::size_t(d)] = Level_mask(r, 0);
    for(int k = 0; k < r; ++k)
      for(int j = 0; j < r; ++j)
        for(int i = 0; i < r; ++i)
        {
          std::uint8_t any = 0;
          for_each_child(occupied[std::size_t(d) + 1], i, j, k, [&](std::uint8_t o) { any |= o; });
          occupied[std::size_t(d)](i, j, k) = any;
        }
  }
  return occupied;
}

// Gives the finest voxels with support under each non-empty leaf of `octree` the leaf's carried
// class and resolution, and counts the leaves per level.
inline void project_leaves_on_finest(const Unit_cube_octree& octree, const Level_classes& C,
                                     const Level_classes& carried, Hierarchical_prior& prior)
{
  const std::size_t L = C.size();
  const int d0 = log2_of_power_of_two(C[0].resolution());
  const Voxel_grid<Voxel_class>& finest = C[L - 1];
  prior.classes = Voxel_grid<Voxel_class>(finest.resolution(), Voxel_class::EMPTY);
  prior.leaf_resolution = Voxel_grid<std::uint16_t>(finest.resolution(), 0);
  prior.number_of_flow_leaves.assign(L, 0);
  prior.number_of_freeze_leaves.assign(L, 0);
  octree.for_each_leaf([&](int d, const Octree_cell& g) {
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

\throws Invalid_input (`INVALID_PARAMETER`) if the resolutions of `level_classes` break the rule
of `voxel_resolutions`: a non-empty list of powers of two from 1 to 256, each twice the previous.
*/
inline Hierarchical_prior fuse_flow_freeze(const std::vector<Voxel_grid<Voxel_class> >& level_classes)
{
  const internal::Level_classes& C = level_classes;
  internal::check_level_resolutions(C);
  const std::size_t L = C.size();
  const std::vector<internal::Level_mask> below = internal::support_below(C);
  const std::vector<internal::Level_mask> split = internal::split_decisions(C, below);
  const internal::Level_classes carried = internal::carried_classes(C, split);
  const std::vector<internal::Level_mask> occupied = internal::occupied_above_coarsest(C, below);

  const int d0 = internal::log2_of_power_of_two(C[0].resolution());
  const int depth = d0 + int(L) - 1;
  internal::Unit_cube_octree octree;
  octree.refine([&](int d, const internal::Octree_cell& g) -> bool {
    const int i = int(g[0]), j = int(g[1]), k = int(g[2]);
    if(d < d0) return occupied[std::size_t(d)](i, j, k) != 0;
    if(d >= depth) return false;
    return split[std::size_t(d - d0)](i, j, k) != 0;
  });

  Hierarchical_prior prior;
  prior.resolutions.resize(L);
  for(std::size_t l = 0; l < L; ++l) prior.resolutions[l] = C[l].resolution();
  internal::project_leaves_on_finest(octree, C, carried, prior);
  return prior;
}

/// \cond SKIP_IN_MANUAL
namespace internal {

// The named parameters of the prior: its resolutions, and those of the cues and of the score.
struct Prior_parameters
{
  std::vector<int> resolutions;
  Cue_parameters cues;
  Topology_score_parameters score;
};

template <typename NamedParameters>
Prior_parameters read_prior_parameters(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  Prior_parameters p{read_voxel_resolutions(np), read_cue_parameters(np), read_topology_score_parameters(np)};
  return p;
}

} // namespace internal
/// \endcond

/*!
\ingroup PkgPartDecompositionRef
computes the hierarchical Flow/Freeze prior of `tm` (paper Alg.\ A.1, lines 1-5): the geometric
cues once (`compute_geometric_cues()`), the topology score and its Flow/Freeze cut at each of
the `voxel_resolutions` from a single pass over the surface samples, and their fusion
(`fuse_flow_freeze()`).

The samples are binned once, in the grid of the finest resolution \f$r_L\f$: the field at
resolution \f$r\f$ is `compute_topology_score(tm, c, phi, r, r_L, np)` with the cues of
`compute_geometric_cues(tm, c, phi, np)`, i.e.\ large faces are cut relative to the finest grid
and a coarse voxel sums the counts of the finest voxels it holds. It differs from
`compute_topology_score(tm, c, phi, r, np)` (samples binned at \f$r\f$) for \f$r < r_L\f$. The
normal deviation is not computed when its weight \f$\lambda_4\f$ is 0 (the default): the
`normal_deviation` grids of the fields then hold 0.

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
\param np an optional sequence of named parameters; this function reads `vertex_point_map`,
`vertex_index_map`, `face_index_map` (\ref PD_MeshParameters), `normalization`,
`normalization_margin`, `voxel_resolutions`, `number_of_points_per_face`, `number_of_neighbors`,
`curvature_percentile`, `cue_weights`, `freeze_ratio` and `method_variant` (its switches
`use_concave_curvature` and `use_density`) (\ref PD_ParameterTable)

\returns the prior: the fields at each scored resolution, the fused classes and leaf resolutions on the
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
  internal::static_check_concurrency_tag<ConcurrencyTag>();
  // Every parameter is checked before any work.
  const internal::Prior_parameters parameters = internal::read_prior_parameters(np);

  const internal::Triangle_arrays mesh = internal::make_triangle_arrays(tm, np);
  const Normalization normalization = internal::read_normalization(tm, np);

  const std::vector<double> c =
    internal::face_curvatures<ConcurrencyTag>(mesh, internal::make_vertex_corners(mesh), parameters.cues);
  // the normal deviation is not computed at weight 0 (its k-NN is half the cues' cost): its grids hold 0
  const std::vector<double> phi =
    parameters.score.cue_weights[3] == 0.
      ? std::vector<double>(mesh.faces.size(), 0.)
      : internal::face_normal_deviation<ConcurrencyTag>(mesh, parameters.cues.number_of_neighbors);

  // Every level from the samples binned at the finest resolution (the list is increasing).
  std::vector<Topology_score_field> fields = internal::topology_score_fields<ConcurrencyTag>(
    mesh, c, phi, parameters.resolutions, parameters.resolutions.back(), normalization, parameters.score, nullptr);

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
