// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_OVER_SEGMENTATION_H
#define CGAL_PART_DECOMPOSITION_OVER_SEGMENTATION_H

#include <CGAL/Part_decomposition/input_validation.h>
#include <CGAL/Part_decomposition/parameters.h>
#include <CGAL/Part_decomposition/internal/toolbox/face_adjacency.h>
#include <CGAL/Part_decomposition/internal/parts/patch_operations.h>
#include <CGAL/Part_decomposition/internal/parts/piece_regions.h>
#include <CGAL/Part_decomposition/internal/toolbox/toolbox.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

#include <boost/property_map/property_map.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

// Edges whose dihedral angle is at most this many degrees are flat and never cut.
constexpr double flat_dihedral_angle = 0.05;
// The squared radius of gyration of a piece built by the size cap is at most this fraction of
// the cap area (a disk of the cap area has 1/(2 pi) = 0.16): pieces stay compact.
constexpr double patch_gyration_ratio = 0.2;
// Angles this close (degrees) to the quantile count as equal to it: rounding must not decide
// whether a crease of a rotated cube is cut.
constexpr double dihedral_tie_tolerance = 1e-6;

// Statistics of one over-segmentation, for benchmarks and tests.
struct Over_segmentation_statistics
{
  double threshold = 0.;                 // the dihedral percentile, degrees
  std::size_t number_of_cut_edges = 0;   // interior edges cut (each once)
  std::size_t number_of_components = 0;  // after the flood fill
  std::size_t number_of_split_patches = 0;  // after splitting the large components
  std::size_t number_of_merged_patches = 0; // after the clean-up
  std::size_t number_of_smoothed_faces = 0;
};

// The package parameters of `over_segment()`.
struct Over_segmentation_parameters
{
  double dihedral_percentile = defaults::dihedral_percentile;
  double minimum_patch_size = defaults::minimum_patch_size;
  double patch_split_size = defaults::patch_split_size;
  int smoothing_iterations = int(defaults::smoothing_iterations);
};

template <typename NamedParameters>
Over_segmentation_parameters read_over_segmentation_parameters(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  namespace inp = Part_decomposition::internal_np;
  Over_segmentation_parameters p;
  p.dihedral_percentile = choose_parameter(get_parameter(np, inp::dihedral_percentile), p.dihedral_percentile);
  p.minimum_patch_size = choose_parameter(get_parameter(np, inp::minimum_patch_size), p.minimum_patch_size);
  p.patch_split_size = choose_parameter(get_parameter(np, inp::patch_split_size), p.patch_split_size);
  p.smoothing_iterations = choose_parameter(get_parameter(np, inp::smoothing_iterations), p.smoothing_iterations);
  check_parameter(p.dihedral_percentile >= 0. && p.dihedral_percentile <= 100., "dihedral_percentile");
  check_parameter(p.minimum_patch_size >= 0. && p.minimum_patch_size <= 1., "minimum_patch_size");
  check_parameter(p.patch_split_size > 0. && p.patch_split_size <= 1., "patch_split_size");
  check_parameter(p.smoothing_iterations >= 0, "smoothing_iterations");
  return p;
}

// Steps 2 and 3: the cut flag of each slot; `threshold` receives the percentile.
template <typename ConcurrencyTag>
std::vector<std::uint8_t> cut_sharp_edges(const Face_adjacency& adj, double dihedral_percentile, double& threshold)
{
  std::vector<double> angles = interior_edge_angles(adj);
  threshold = percentile(angles, dihedral_percentile);
  const double cut_from = (std::max)(threshold - dihedral_tie_tolerance, 0.);
  const std::size_t nf = adj.number_of_faces;
  std::vector<std::uint8_t> cut(3 * nf, 0);
  for_each_range<ConcurrencyTag>(nf, [&](std::size_t b, std::size_t e) {
    for(std::size_t i = b; i < e; ++i)
      for(int k = 0; k < 3; ++k)
      {
        const std::size_t j = adj.neighbor[3 * i + k];
        if(j == Face_adjacency::no_face) continue;
        const double s = adj.angle[3 * i + k];
        cut[3 * i + k] = (adj.degenerate[i] || adj.degenerate[j] ||
                          (s >= cut_from && s > flat_dihedral_angle)) ? 1 : 0;
      }
  }, 1024);
  return cut;
}

// Step 7: the smoothing passes; returns the number of faces moved.
template <typename ConcurrencyTag>
std::size_t smooth_patches(const Face_adjacency& adj, int iterations, std::vector<std::size_t>& label)
{
  std::size_t smoothed = 0;
  for(int it = 0; it < iterations; ++it)
  {
    const std::size_t moved = smooth_patch_boundaries<ConcurrencyTag>(adj, label);
    smoothed += moved;
    if(moved == 0) break;
  }
  return smoothed;
}

inline std::size_t number_of_cut_edges(const Face_adjacency& adj, const std::vector<std::uint8_t>& cut)
{
  std::size_t n = 0;
  for(std::size_t i = 0; i < adj.number_of_faces; ++i)
    for(int k = 0; k < 3; ++k)
      if(cut[3 * i + k] && adj.neighbor[3 * i + k] > i) ++n;
  return n;
}

// The over-segmentation (steps 2 to 8 of `over_segment()`) of the face graph `adj`, as one label
// per face index; returns the number of patches.
template <typename ConcurrencyTag>
std::size_t over_segment_faces(const Face_adjacency& adj, const Over_segmentation_parameters& p,
                               std::vector<std::size_t>& label, Over_segmentation_statistics* stats = nullptr)
{
  const std::size_t nf = adj.number_of_faces;
  label.assign(nf, 0);
  if(nf == 0) return 0;

  double threshold = 0.;
  const std::vector<std::uint8_t> cut = cut_sharp_edges<ConcurrencyTag>(adj, p.dihedral_percentile, threshold);
  // the flood fill, numbered by first face (the cut of an edge is the same from both faces)
  const std::size_t components =
    face_components<ConcurrencyTag>(adj, [&](std::size_t i, int k) { return !cut[3 * i + std::size_t(k)]; }, label);

  double total_area = 0.;
  for(double a : adj.area) total_area += a;
  std::size_t patches = components;
  if(p.patch_split_size < 1.)
    patches = split_large_patches<ConcurrencyTag>(adj, cut, label, components, p.patch_split_size * total_area,
                                                  patch_gyration_ratio, flat_dihedral_angle);
  const std::size_t split = patches;
  merge_small_patches(adj, label, patches, p.minimum_patch_size * total_area);
  std::size_t merged = 0;
  if(stats) merged = renumber_by_first_face(label);
  const std::size_t smoothed = smooth_patches<ConcurrencyTag>(adj, p.smoothing_iterations, label);
  const std::size_t count = renumber_by_first_face(label);

  if(stats)
  {
    stats->threshold = threshold;
    stats->number_of_cut_edges = number_of_cut_edges(adj, cut);
    stats->number_of_components = components;
    stats->number_of_split_patches = split;
    stats->number_of_merged_patches = merged;
    stats->number_of_smoothed_faces = smoothed;
  }
  return count;
}

// The over-segmentation as one label per face index; returns the number of patches.
// `fim` is the face index map of `np` (or the default one), passed to be built only once.
// `adjacency`, if given, receives the face graph and dihedral angles it used.
template <typename ConcurrencyTag, typename TriangleMesh, typename FaceIndexMap, typename NamedParameters>
std::size_t over_segment_labels(const TriangleMesh& tm, const FaceIndexMap& fim, std::vector<std::size_t>& label,
                                const NamedParameters& np, Over_segmentation_statistics* stats = nullptr,
                                Face_adjacency* adjacency = nullptr)
{
  static_check_concurrency_tag<ConcurrencyTag>();
  const Over_segmentation_parameters p = read_over_segmentation_parameters(np);
  CGAL_precondition(CGAL::is_triangle_mesh(tm));
  const std::shared_ptr<const Face_adjacency> graph = shared_face_adjacency<ConcurrencyTag>(tm, fim, np);
  if(adjacency) *adjacency = *graph;
  return over_segment_faces<ConcurrencyTag>(*graph, p, label, stats);
}

} // namespace internal

/*!
\ingroup PkgPartDecompositionRef
computes the curvature-aware over-segmentation of `tm` into edge primitives (paper App.\ E.3):
patches of faces bounded by the sharpest edges of the mesh. It is the first half of the
superquadric-to-mesh assignment (`assign_parts()`) and is usable on its own.

The steps are:
1. <b>Dihedral angles.</b> Each interior edge between faces of unit normals \f$n_1, n_2\f$ gets
   \f$s = \arccos\langle n_1, n_2\rangle\f$ in degrees, in \f$[0, 180]\f$. An edge incident to a
   face of zero area (no normal) gets \f$s = 180\f$ and takes no part in the distribution below.
2. <b>Threshold.</b> \f$t\f$ is the `dihedral_percentile`-th percentile of the angles of the interior
   edges (each edge once), with linear interpolation between the closest ranks (position
   \f$(n-1)\,q/100\f$ in the sorted list).
3. <b>Cut.</b> An edge is cut if \f$s \ge t\f$ (up to \f$10^{-6}\f$ degree of rounding) and
   \f$s > 0.05\f$ degree: ties at the quantile are cut (on a cube tessellated with two triangles per
   side, 12 of the 18 edges are creases and the 90-th percentile is 90 degrees), and flat edges
   never are, even when more than `100 - dihedral_percentile` percent of the edges are flat. Edges
   incident to a face of zero area are always cut.
4. <b>Flood fill.</b> The connected components of the faces across edges that are not cut; border
   edges are never crossed.
5. <b>Size cap.</b> The cuts of a smooth surface are scattered and rarely close a loop, so the
   flood fill alone leaves one patch over most of an organic shape, where the paper reports 200 to
   500 patches. A component larger than `patch_split_size` (\f$a_{max}\f$; 1: no cap) times the
   area of the mesh is split by an ordered flood fill: its uncut edges are crossed by increasing
   dihedral angle, joining the two sides unless the joined piece would have an area above
   \f$a_{max}\f$ or a squared radius of gyration (of its face centroids, area-weighted) above
   \f$0.2\,a_{max}\f$, so that compact pieces meet along the locally sharpest edges. Flat edges
   (\f$s \le 0.05\f$ degree) are always crossed: a planar region is never split.
6. <b>Fragment clean-up.</b> A patch whose area is below `minimum_patch_size` (0: no clean-up)
   times the area of the mesh is merged into the neighbouring patch across its weakest shared edge
   (the one of smallest dihedral angle; on a tie, the neighbour of smallest area, then of smallest
   id), the smallest patch first, repeated until every patch is large enough or has no neighbour
   (a small connected component of the mesh stays a patch of its own).
7. <b>Boundary smoothing</b>, `smoothing_iterations` times: a face moves to the patch that holds at
   least two of its three neighbours, counting only neighbours that do not move in the same pass
   (this keeps every patch edge-connected). Patches are never created; one may vanish.
8. Patches are numbered `0` to `A-1` by increasing smallest face index.

With the default `patch_split_size` and `minimum_patch_size`, the patches are compact and cover
0.1 to 0.2 percent of the area each, so that a patch rarely straddles two parts.

The result does not depend on the number of threads.

\par Complexity
\f$O(E \log E)\f$ for \f$E\f$ edges: the edges of the size cap are sorted by dihedral angle; the other
steps are linear (the percentile is a selection), up to the priority queue of the fragment
clean-up, logarithmic in the number of patches.

\tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag` (needs TBB); the dihedral
        angles, the sort of the size cap and the smoothing run in parallel.
\tparam TriangleMesh a model of `FaceListGraph`
\tparam FacePatchMap a model of `WritablePropertyMap` with
        `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and `std::size_t` as
        value type
\tparam NamedParameters a sequence of named parameters

\param tm the triangle mesh
\param face_patch_map receives the patch id of each face, in `[0, A)`
\param np an optional sequence of named parameters; this function reads `vertex_point_map`,
`face_index_map`, `geom_traits` (\ref PD_MeshParameters), `dihedral_percentile`,
`minimum_patch_size`, `patch_split_size` and `smoothing_iterations` (\ref PD_ParameterTable)

\pre `CGAL::is_triangle_mesh(tm)`
\pre if `TriangleMesh` is a `CGAL::Surface_mesh`, it has no garbage (or a `face_index_map` is given)

\returns the number `A` of patches (0 if `tm` has no face).

\throws Invalid_input (`INVALID_PARAMETER`) if a named parameter is out of its range.
*/
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename TriangleMesh, typename FacePatchMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
std::size_t over_segment(const TriangleMesh& tm, FacePatchMap face_patch_map,
                         const NamedParameters& np = CGAL::parameters::default_values())
{
  typedef typename GetInitializedFaceIndexMap<TriangleMesh, NamedParameters>::const_type FIM;
  const FIM fim = CGAL::get_initialized_face_index_map(tm, np);
  std::vector<std::size_t> label;
  const std::size_t count = internal::over_segment_labels<ConcurrencyTag>(tm, fim, label, np);
  // the one conversion to the caller's map
  for(auto f : faces(tm)) put(face_patch_map, f, label[std::size_t(get(fim, f))]);
  return count;
}

} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_OVER_SEGMENTATION_H
