// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_STAGE_RESULTS_H
#define CGAL_PART_DECOMPOSITION_STAGE_RESULTS_H

// The results of the stages, without the code that computes them: a header that only passes
// results on (the fitter reads the prior and the distance field) includes this one.

#include <CGAL/Part_decomposition/Adaptive_grid.h>
#include <CGAL/Part_decomposition/Superquadric.h>
#include <CGAL/Part_decomposition/Voxel_grid.h>
#include <CGAL/Part_decomposition/normalization.h>
#include <CGAL/Part_decomposition/internal/parts/merge_kind.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <vector>

namespace CGAL {
namespace Part_decomposition {

/*!
\ingroup PkgPartDecompositionRef
The primitive index that `assign_parts()` returns for its single part when no voxel is claimed, and that
`Composed_parts::part_to_primitive` gives a part without a fitted primitive.
*/
constexpr std::size_t no_primitive = (std::numeric_limits<std::size_t>::max)();

/*!
\ingroup PkgPartDecompositionRef
The voxel cues, the topology score \f$S_B\f$ (paper Eq.\ 3) and its Flow/Freeze cut (Eq.\ 4, 5) at
one resolution `r`. Grids have resolution `r`; empty voxels (no sample) hold 0 and are not part of
the field.
*/
struct Topology_score_field
{
  /// the resolution `r`.
  int resolution = 0;
  /// \f$n_i\f$: the number of surface samples in each voxel.
  Voxel_grid<std::uint32_t> sample_count;
  /// \f$\mu^\kappa_i\f$: the mean of the face curvature cue over the samples of each voxel.
  Voxel_grid<double> curvature_mean;
  /// \f$\sigma^\kappa_i\f$: the standard deviation of the face curvature cue in each voxel.
  Voxel_grid<double> curvature_deviation;
  /// \f$\Delta^\kappa_i\f$: the magnitude of the gradient of the dense \f$\mu^\kappa\f$ field
  /// (unit voxel spacing).
  Voxel_grid<double> curvature_gradient;
  /// \f$\phi_{norm}\f$: the mean normal deviation of the samples of each voxel (0 if
  /// `compute_flow_freeze_prior()` did not compute it: \f$\lambda_4 = 0\f$).
  Voxel_grid<double> normal_deviation;
  /// \f$S_B\f$: the topology score.
  Voxel_grid<double> score;
  /// the Flow/Freeze cut: `FREEZE` where \f$S_B \geq \tau_\alpha\f$, `FLOW` elsewhere in the field.
  Voxel_grid<Voxel_class> classes;
  /// \f$\tau_\alpha\f$: the \f$(1-\alpha)\f$-quantile of the score over the active voxels.
  double threshold = 0.;
  /// the number of voxels with at least one sample.
  std::size_t number_of_active_voxels = 0;
  /// the number of `FREEZE` voxels.
  std::size_t number_of_freeze_voxels = 0;
};

/*!
\ingroup PkgPartDecompositionRef
The hierarchical Flow/Freeze prior (paper Sec.\ 3.2, App.\ E.1): the per-resolution topology
score fields, fused on an octree and projected on the finest grid.
*/
struct Hierarchical_prior
{
  /// the resolutions, coarse to fine, each twice the previous one (default 16, 32, 64).
  std::vector<int> resolutions;
  /// the score field and Flow/Freeze cut at each resolution, in the order of `resolutions`.
  std::vector<Topology_score_field> fields;
  /// the class of the fused leaf that contains each voxel of the finest grid; `EMPTY` outside
  /// the surface support of the finest grid.
  Voxel_grid<Voxel_class> classes;
  /// \f$\mathcal{R}_{map}\f$: the resolution of the fused leaf that contains each voxel of the
  /// finest grid, 0 for empty voxels.
  Voxel_grid<std::uint16_t> leaf_resolution;
  /// the number of `FLOW` leaves of the fused octree at each resolution.
  std::vector<std::size_t> number_of_flow_leaves;
  /// the number of `FREEZE` leaves of the fused octree at each resolution.
  std::vector<std::size_t> number_of_freeze_leaves;
  /// the map from input coordinates to the normalized cube the grids live in.
  Normalization normalization;
};


/*!
\ingroup PkgPartDecompositionRef
A truncated signed distance field \f$d_\mathcal{M}\f$ of a mesh sampled at the leaf centres of an
adaptive grid of the normalized cube: negative inside, positive outside, clipped to
\f$[-\tau, \tau]\f$.
*/
struct Truncated_signed_distance_field
{
  /// the leaves on which the field is sampled.
  Adaptive_grid grid;
  /// the signed distance at the centre of each leaf of `grid`, in normalized units, clipped to
  /// `[-truncation, truncation]`.
  std::vector<double> values;
  /// \f$\tau\f$ in normalized units.
  double truncation = 0.;
  /// \f$\Delta\f$: the side of a voxel of the finest of `voxel_resolutions`, the unit in which the
  /// lengths of the method (truncation, bands, temperatures) are given, in normalized units.
  double voxel_size = 0.;
  /// the map from input coordinates to the normalized cube.
  Normalization normalization;
  /// the sign method actually used (never `AUTOMATIC`).
  Tsdf_sign_method sign_method = Tsdf_sign_method::AUTOMATIC;
};

/*!
\ingroup PkgPartDecompositionRef
The volumetric zones that constrain the superquadric fitter (paper App.\ E.2 (A.1), Alg.\ A.2
lines 1-4), one value per leaf of the grid of the distance field. Masks hold 1 inside the zone and
0 outside.
*/
struct Fitting_zones
{
  /// the class of the fused prior leaf at each leaf; `EMPTY` for a leaf without surface support.
  std::vector<Voxel_class> classes;
  /// \f$\mathcal{R}_{map}\f$: the resolution of the fused prior leaf at each leaf, 0 for a leaf
  /// without surface support (valid from the first stage).
  std::vector<std::uint16_t> leaf_resolution;
  /// the carrier: the leaves with surface support (`FLOW` or `FREEZE`).
  std::vector<std::uint8_t> occupied;
  /// `ext_void`: the exterior of the shape, the unoccupied leaves the distance field puts outside.
  std::vector<std::uint8_t> exterior;
  /// \f$\Omega_{freeze}\f$: the `FREEZE` leaves and the exterior.
  std::vector<std::uint8_t> freeze_zone;
  /// \f$\Omega_{flow}\f$ for each fitting resolution \f$r_{fit}\f$: the leaves whose centre lies
  /// within the Flow-zone tolerance (in voxels of \f$r_{fit}\f$) of the centre of a non-exterior leaf.
  std::map<int, std::vector<std::uint8_t> > flow_zone;
};


/*!
\ingroup PkgPartDecompositionRef
The output of `fit_superquadrics()`: the accepted superquadrics in acceptance order, the leaves of
the grid of the distance field they claimed, and statistics of the run. Primitive `k` is the `k`-th
entry of every per-primitive vector.
*/
template <typename GeomTraits>
struct Superquadric_fitting_result
{
  /// \name Primitives
  /// @{

  /// the accepted superquadrics in the coordinates of the normalized cube \f$[-0.5,0.5]^3\f$.
  std::vector<Superquadric<GeomTraits> > primitives;
  /// the same superquadrics in the input coordinates of the mesh (through `normalization`).
  std::vector<Superquadric<GeomTraits> > input_primitives;
  /// the resolution \f$r\f$ of the stage that accepted each primitive.
  std::vector<int> stage_resolution;
  /// whether each primitive grew from a body seed (EDT maximum) or a surface seed (component centroid).
  std::vector<bool> body_seeded;
  /// the seed leaf of each primitive.
  std::vector<std::size_t> seed_leaf;
  /// the trust-region scale \f$\eta\f$ of the fit that passed the Flow-zone test.
  std::vector<double> semi_axis_scale;
  /// the FitSDF cost \f$\sum w r^2 / |P_a|\f$ of each accepted fit.
  std::vector<double> fit_cost;
  /// the leaves of each primitive in `labels` (claimed, then merged residuals), in increasing index.
  std::vector<std::vector<std::size_t> > claimed_leaves;
  /// @}

  /// \name Leaves
  /// @{

  /// per leaf of the grid of the distance field: the primitive that claimed it (hard-clipped
  /// claims plus small residual regions merged into the nearest primitive), or -1.
  std::vector<std::int32_t> labels;
  /// the map from input coordinates to the normalized cube (from the prior).
  Normalization normalization;
  /// @}

  /// \name Statistics
  /// @{
  std::size_t number_of_seeds = 0;          ///< seeds tried
  std::size_t number_of_body_seeds = 0;     ///< of which body seeds
  std::size_t number_of_rejected_seeds = 0; ///< seeds rejected (all three sub-cases below)
  std::size_t rejected_by_flow_zone = 0;    ///< every retry left the Flow zone
  std::size_t rejected_by_volume = 0;       ///< the net claim was below \f$V_{min}\f$
  std::size_t rejected_degenerate = 0;      ///< fewer active samples than parameters
  std::size_t number_of_solves = 0;         ///< least-squares solves (FitSDF calls times outer passes)
  std::size_t number_of_evaluations = 0;    ///< residual evaluations in all solves
  std::size_t number_of_samples = 0;        ///< samples over all FitSDF calls
  std::size_t merged_leaves = 0;            ///< residual leaves merged into a primitive
  std::vector<double> stage_coverage;       ///< coverage of \f$\Omega_{valid}\f$ at the end of each stage
  double seconds = 0.;                      ///< wall-clock time of the call
  /// @}
};

/*!
\ingroup PkgPartDecompositionRef
The output of `segment_pieces()`: the pieces of a mesh (its edge-connected components) and the
regions of each piece between its concave creases. Vectors indexed by face are indexed by the
face index map.
*/
struct Piece_segmentation
{
  /// the piece of each face, numbered `0` to `number_of_pieces - 1` by smallest face index.
  std::vector<std::size_t> piece;
  /// the region of each face, numbered `0` to `number_of_regions - 1` by smallest face index; a
  /// region lies in one piece.
  std::vector<std::size_t> region;
  /// per piece: 1 if the piece is closed (no border edge and no edge of three faces or more).
  std::vector<std::uint8_t> closed;
  /// per piece: +1, or -1 for an open piece whose orientation was reversed to tell its concave
  /// creases (see `segment_pieces()`; `volumetric_pieces()` turns an open piece that bounds a volume
  /// to face out of it).
  std::vector<int> orientation;
  std::size_t number_of_pieces = 0;  ///< the number of pieces
  std::size_t number_of_regions = 0; ///< the number of regions
  double area = 0.;                  ///< the area of the mesh

  /// whether any piece is closed.
  bool has_closed_piece() const
  {
    for(std::uint8_t c : closed)
      if(c) return true;
    return false;
  }
};


#ifdef DOXYGEN_RUNNING
// The enum is declared in internal/merge_kind.h, for the merge tree of internal/part_merging.h;
// it is documented here, where users find it: keep the two lists equal.
/*!
\ingroup PkgPartDecompositionRef
How two parts of a `Part_hierarchy` are related when they are merged; the merges are made in this
order, each kind by increasing `Part_hierarchy_node::merge_cost`.
*/
enum class Merge_kind
{
  NONE,           ///< a leaf: no merge
  SAME_PRIMITIVE, ///< two pieces of one part of the default decomposition explained by one fitted primitive
  SAME_PART,      ///< two pieces of one part of the default decomposition
  ATTACHED,       ///< a crumb, a repeated piece or a tile and the piece it is grouped with (see `build_part_hierarchy()`)
  SAME_PIECE,   ///< two parts of one piece of the mesh that share an edge
  CONTACT,      ///< two parts of different pieces whose surfaces touch
  NO_CONTACT    ///< two parts that do not touch (the parts of a mesh in separate places)
};
#endif


/*!
\ingroup PkgPartDecompositionRef
A node of a `Part_hierarchy`: a leaf (a finest part) or the union of its two children.
*/
template <typename GeomTraits>
struct Part_hierarchy_node
{
  /// the index of a node that does not exist (the children of a leaf, the parent of the root)
  static constexpr std::size_t no_node = (std::numeric_limits<std::size_t>::max)();
  /// the two children, `no_node` for a leaf.
  std::array<std::size_t, 2> children = {{no_node, no_node}};
  /// the parent, `no_node` for the root.
  std::size_t parent = no_node;
  /// how the children are related (`NONE` for a leaf).
  Merge_kind kind = Merge_kind::NONE;
  /// the cost of the merge that made the node (0 for a leaf): the volume that one box-like
  /// superquadric of the union adds to the boxes of the two children, as a fraction of the box of
  /// the whole mesh, plus a term for the concavity of their common boundary (see `build_part_hierarchy()`).
  double merge_cost = 0.;
  /// the area of the node's faces.
  double area = 0.;
  /// the number of the node's faces.
  std::size_t number_of_faces = 0;
  /// the smallest face index of the node's faces; the parts of a level are numbered by it.
  std::size_t first_face = 0;
  /// the superquadric that explains the node, in input coordinates: the primitive of the part of
  /// the default decomposition the node is equal to, if there is one, else the box-like
  /// superquadric of the principal axes of the node's area moments.
  Superquadric<GeomTraits> primitive;
};

/*!
\ingroup PkgPartDecompositionRef
A binary merge tree of the parts of a mesh (`build_part_hierarchy()`): the leaves are the finest
parts, each inner node is the union of two nodes, and the root is the whole mesh. Leaves are nodes `0` to
`number_of_leaves() - 1`; the merges follow in the order they were made, so that the `k` parts of
level `k` are the nodes left after the first `number_of_leaves() - k` merges. Each level is a
partition of the faces, and the parts of a level are unions of the parts of any finer level.
Vectors indexed by face are indexed by the face index map.
*/
template <typename GeomTraits>
struct Part_hierarchy
{
  /// the node type
  typedef Part_hierarchy_node<GeomTraits> Node;
  /// the leaves, then one node per merge, in merge order; the root is the last node.
  std::vector<Node> nodes;
  /// the leaf of each face.
  std::vector<std::size_t> leaf;
  /// the number of parts of the default decomposition (a level of the tree), 0 if unknown.
  std::size_t default_number_of_parts = 0;

  /// the number of leaves, the finest level.
  std::size_t number_of_leaves() const { return (nodes.size() + 1) / 2; }

  /// the nodes of level `k`, ordered by their smallest face index.
  /// \pre `1 <= k <= number_of_leaves()`
  std::vector<std::size_t> level(std::size_t k) const
  {
    CGAL_precondition(k >= 1 && k <= number_of_leaves());
    const std::size_t end = 2 * number_of_leaves() - k; // nodes made by the first L - k merges
    std::vector<std::size_t> result;
    for(std::size_t n = 0; n < end && n < nodes.size(); ++n)
      if(nodes[n].parent == Node::no_node || nodes[n].parent >= end) result.push_back(n);
    std::sort(result.begin(), result.end(),
              [&](std::size_t a, std::size_t b) { return nodes[a].first_face < nodes[b].first_face; });
    return result;
  }

  /// the superquadrics of the nodes of level `k`, in the order of `level(k)`.
  /// \pre `1 <= k <= number_of_leaves()`
  std::vector<Superquadric<GeomTraits> > primitives(std::size_t k) const
  {
    std::vector<Superquadric<GeomTraits> > result;
    for(std::size_t n : level(k)) result.push_back(nodes[n].primitive);
    return result;
  }

  /// the coarsest level reached from level `k` by the merges that follow it in order, as long as
  /// each costs less than `maximum_cost` and joins parts that touch (not `Merge_kind::NO_CONTACT`):
  /// `k` if the next merge does not.
  /// \pre `1 <= k <= number_of_leaves()`
  std::size_t level_below_cost(std::size_t k, double maximum_cost) const
  {
    CGAL_precondition(k >= 1 && k <= number_of_leaves());
    // the nodes made by the first L - k merges are [0, 2L - k): the next merge makes node 2L - k
    for(std::size_t next = 2 * number_of_leaves() - k;
        k > 1 && !internal::merge_beyond_default_parts(nodes[next].kind, nodes[next].merge_cost, maximum_cost);
        ++next)
      --k;
    return k;
  }

  /// the part (`0` to `k - 1`, in the order of `level(k)`) of each face at level `k`.
  /// \pre `1 <= k <= number_of_leaves()`
  std::vector<std::size_t> labels(std::size_t k) const
  {
    const std::vector<std::size_t> parts = level(k);
    const std::size_t end = 2 * number_of_leaves() - k;
    std::vector<std::size_t> part_of_node(nodes.size(), Node::no_node);
    for(std::size_t p = 0; p < parts.size(); ++p) part_of_node[parts[p]] = p;
    for(std::size_t n = end; n-- > 0;) // parents come after their children
      if(part_of_node[n] == Node::no_node && nodes[n].parent < end) part_of_node[n] = part_of_node[nodes[n].parent];
    std::vector<std::size_t> result(leaf.size());
    for(std::size_t i = 0; i < leaf.size(); ++i) result[i] = part_of_node[leaf[i]];
    return result;
  }
};

/*!
\ingroup PkgPartDecompositionRef
Wall-clock seconds spent in each stage of `decompose()`.
*/
struct Stage_timings
{
  double pieces = 0.;            ///< pieces and their regions between concave creases
  double prior = 0.;             ///< geometric cues, topology scores and Flow/Freeze fusion
  double tsdf = 0.;              ///< the adaptive grid and the truncated signed distance field on it
  double fitting = 0.;           ///< fitting zones and superquadric fitting
  double fitting_zones = 0.;     ///< of which the fitting zones
  double over_segmentation = 0.; ///< curvature-aware over-segmentation
  double assignment = 0.;        ///< assignment, thin-sheet merge and composition with the pieces
  double hierarchy = 0.;         ///< the part hierarchy and its cut (0 if it was not built)
  double total = 0.;             ///< the whole call, input checks included
  /// whether some stages ran at the same time (parallel `decompose()`): then the stage times
  /// overlap and their sum exceeds `total`.
  bool overlapping = false;
};

} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_STAGE_RESULTS_H
