// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_PRIMITIVE_ASSIGNMENT_H
#define CGAL_PART_DECOMPOSITION_PRIMITIVE_ASSIGNMENT_H

#include <CGAL/Part_decomposition/stage_results.h>
#include <CGAL/Part_decomposition/Adaptive_grid.h>
#include <CGAL/Part_decomposition/input_validation.h>
#include <CGAL/Part_decomposition/normalization.h>
#include <CGAL/Part_decomposition/parameters.h>
#include <CGAL/Part_decomposition/internal/parts/boundary_graph_cut.h>
#include <CGAL/Part_decomposition/internal/parts/superface_labelling.h>
#include <CGAL/Part_decomposition/internal/fitting/claimed_leaf_search.h>
#include <CGAL/Part_decomposition/internal/toolbox/face_adjacency.h>
#include <CGAL/Part_decomposition/internal/toolbox/toolbox.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/number_utils.h>
#include <CGAL/tags.h>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numeric>
#include <utility>
#include <memory>
#include <vector>

namespace CGAL {
namespace Part_decomposition {

namespace internal {

// Per face index: the nearest claimed voxel of the face centroid (label, normalized distance).
template <typename ConcurrencyTag, typename TriangleMesh, typename FaceIndexMap, typename VertexPointMap>
void nearest_claimed_voxels(const TriangleMesh& tm, const FaceIndexMap& fim, const VertexPointMap& vpm,
                            const Claimed_leaf_search<Adaptive_grid>& search, const Normalization& normalization,
                            std::vector<std::int32_t>& face_label, std::vector<double>& face_distance)
{
  const std::size_t nf = num_faces(tm);
  const auto face_of = faces_by_index(tm, fim);
  face_label.assign(nf, -1);
  face_distance.assign(nf, 0.);
  for_each_range<ConcurrencyTag>(nf, [&](std::size_t b, std::size_t e) {
    for(std::size_t i = b; i < e; ++i)
    {
      double c[3] = {0., 0., 0.};
      int n = 0;
      for(auto v : vertices_around_face(halfedge(face_of[i], tm), tm))
      {
        const auto& p = get(vpm, v);
        c[0] += CGAL::to_double(p.x());
        c[1] += CGAL::to_double(p.y());
        c[2] += CGAL::to_double(p.z());
        ++n;
      }
      const std::array<double, 3> u = normalization.to_unit(c[0] / n, c[1] / n, c[2] / n);
      const Claimed_leaf_search<Adaptive_grid>::Result r = search.nearest(u);
      face_label[i] = r.label;
      face_distance[i] = r.distance;
    }
  }, 1024);
}

// The candidates of a point u of the normalized cube standing for `area` (in voxels of side h)
// for the final labelling, written at index i of `out`: its nearest claimed leaf (label k0,
// distance d0) and the other labels claimed within the window of the leaf holding u
// (`Claimed_leaf_search::labels_near()`) at a distance below d0 + `margin`, nearest first; a
// candidate at distance d costs area * (d - d0) / tau, so that the cost of a face is an area in
// voxels; a label that is not a candidate costs at least the margin: `excluded`. `near` is scratch.
inline void add_point_candidates(const Claimed_leaf_search<Adaptive_grid>& search, const Weighted_point& u,
                                 double tau, double margin, std::vector<std::pair<double, std::int32_t> >& near,
                                 Face_candidates& out, std::size_t i)
{
  const Claimed_leaf_search<Adaptive_grid>::Result nearest = search.nearest(u.point);
  near.assign(1, std::make_pair(nearest.distance, nearest.label));
  out.excluded[i] = u.area * margin / tau;
  const std::size_t own = search.leaf_of(u.point);
  for(std::int32_t k : search.labels_near(own))
  {
    if(k < 0) break;
    if(k == nearest.label) continue;
    const double d = std::sqrt(search.squared_distance_to_label(k, u.point, own));
    if(d <= nearest.distance + margin) near.emplace_back(d, k);
  }
  std::sort(near.begin() + 1, near.end());
  const std::size_t n = (std::min)(near.size(), std::size_t(Face_candidates::capacity));
  for(std::size_t k = 0; k < n; ++k)
  {
    out.label[i][k] = near[k].second;
    out.cost[i][k] = u.area * (std::max)(0., near[k].first - nearest.distance) / tau;
  }
}

// The centroid of face index i in the normalized cube and its area in voxels of side h.
inline Weighted_point face_point(const Face_corners& corners, const Normalization& normalization, double h,
                                 std::size_t i)
{
  std::array<Eigen::Vector3d, 3> u;
  for(int k = 0; k < 3; ++k)
  {
    const std::array<double, 3> q = normalization.to_unit(corners(i, k).x(), corners(i, k).y(), corners(i, k).z());
    u[std::size_t(k)] = Eigen::Vector3d(q[0], q[1], q[2]);
  }
  const Eigen::Vector3d c = (u[0] + u[1] + u[2]) / 3.;
  return Weighted_point{{{c.x(), c.y(), c.z()}}, 0.5 * (u[1] - u[0]).cross(u[2] - u[0]).norm() / (h * h)};
}

// The candidates of `n` points, `point_of(i)` the i-th (see add_point_candidates()).
template <typename ConcurrencyTag, typename PointOf>
Face_candidates point_candidates(std::size_t n, const PointOf& point_of,
                                 const Claimed_leaf_search<Adaptive_grid>& search, double tau, double margin)
{
  Face_candidates out;
  out.resize(n);
  for_each_range<ConcurrencyTag>(n, [&](std::size_t b, std::size_t e) {
    std::vector<std::pair<double, std::int32_t> > near; // (distance, label), one per label
    for(std::size_t i = b; i < e; ++i) add_point_candidates(search, point_of(i), tau, margin, near, out, i);
  }, 256);
  return out;
}

// Eq. 9 on flat arrays: patch[i] in [0, number_of_patches) for each face index i; writes the
// winning label of each patch (-1 for a patch without faces).
template <typename ConcurrencyTag>
std::vector<std::int32_t> vote_patch_labels(const std::vector<std::size_t>& patch, std::size_t number_of_patches,
                                            const std::vector<std::int32_t>& face_label,
                                            const std::vector<double>& face_distance, double tau)
{
  const std::size_t nf = patch.size();
  // faces grouped by patch, in a fixed order whatever the number of threads
  std::vector<std::size_t> start, order;
  group_indices(nf, number_of_patches, [&](std::size_t i) { return patch[i]; }, [](std::size_t) { return true; },
                start, order);
  std::vector<std::int32_t> winner(number_of_patches, -1);
  for_each_range<ConcurrencyTag>(number_of_patches, [&](std::size_t b, std::size_t e) {
    std::vector<std::pair<std::int32_t, double> > votes;
    for(std::size_t p = b; p < e; ++p)
    {
      if(start[p] == start[p + 1]) continue;
      // exp(-(d - d_min)/tau) differs from exp(-d/tau) by a factor common to the patch: same
      // argmax, no underflow far from every voxel.
      double d_min = std::numeric_limits<double>::infinity();
      for(std::size_t s = start[p]; s < start[p + 1]; ++s) d_min = (std::min)(d_min, face_distance[order[s]]);
      votes.clear();
      for(std::size_t s = start[p]; s < start[p + 1]; ++s)
      {
        const std::size_t i = order[s];
        const double w = std::exp(-(face_distance[i] - d_min) / tau);
        auto it = std::find_if(votes.begin(), votes.end(),
                               [&](const std::pair<std::int32_t, double>& v) { return v.first == face_label[i]; });
        if(it == votes.end()) votes.emplace_back(face_label[i], w);
        else it->second += w;
      }
      std::pair<std::int32_t, double> best = votes.front();
      for(const auto& v : votes)
        if(v.second > best.second || (v.second == best.second && v.first < best.first)) best = v;
      winner[p] = best.first;
    }
  }, 1024);
  return winner;
}

// The package parameters of `assign_parts()`.
struct Assignment_parameters
{
  double vote_temperature = defaults::vote_temperature;
  double residual_tolerance = defaults::residual_tolerance;
  double boundary_smoothness = defaults::boundary_smoothness;
};

template <typename NamedParameters>
Assignment_parameters read_assignment_parameters(const NamedParameters& np)
{
  Assignment_parameters p;
  p.vote_temperature = CGAL::parameters::choose_parameter(
      CGAL::parameters::get_parameter(np, internal_np::vote_temperature), p.vote_temperature);
  check_positive(p.vote_temperature, "vote_temperature");
  p.residual_tolerance = CGAL::parameters::choose_parameter(
      CGAL::parameters::get_parameter(np, internal_np::residual_tolerance), p.residual_tolerance);
  check_non_negative(p.residual_tolerance, "residual_tolerance");
  p.boundary_smoothness = CGAL::parameters::choose_parameter(
      CGAL::parameters::get_parameter(np, internal_np::boundary_smoothness), p.boundary_smoothness);
  check_non_negative(p.boundary_smoothness, "boundary_smoothness");
  return p;
}

// Renumbers the patch ids to 0..A-1 in increasing order of the given ids; returns A.
inline std::size_t make_patch_ids_consecutive(std::vector<std::size_t>& patch)
{
  std::size_t max_id = 0;
  for(std::size_t p : patch) max_id = (std::max)(max_id, p);
  std::size_t number_of_patches = 0;
  if(max_id < patch.size())
  {
    std::vector<std::size_t> new_id(max_id + 1, 0);
    for(std::size_t p : patch) new_id[p] = 1;
    for(std::size_t& n : new_id) { const std::size_t used = n; n = number_of_patches; number_of_patches += used; }
    for(std::size_t& p : patch) p = new_id[p];
  }
  else
  {
    std::vector<std::size_t> ids(patch);
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    for(std::size_t& p : patch) p = std::size_t(std::lower_bound(ids.begin(), ids.end(), p) - ids.begin());
    number_of_patches = ids.size();
  }
  return number_of_patches;
}

// Step 3: the patches of one primitive form one part, parts by increasing primitive index.
// `part` receives the part of each face index; returns the primitive of each part.
inline std::vector<std::size_t> parts_of_winners(const std::vector<std::int32_t>& winner,
                                                 const std::vector<std::size_t>& patch,
                                                 std::vector<std::size_t>& part)
{
  std::vector<std::size_t> primitives;
  for(std::int32_t w : winner) primitives.push_back(std::size_t(w));
  std::sort(primitives.begin(), primitives.end());
  primitives.erase(std::unique(primitives.begin(), primitives.end()), primitives.end());
  std::vector<std::size_t> part_of_patch(winner.size());
  for(std::size_t p = 0; p < winner.size(); ++p)
    part_of_patch[p] = std::size_t(
        std::lower_bound(primitives.begin(), primitives.end(), std::size_t(winner[p])) - primitives.begin());
  part.resize(patch.size());
  for(std::size_t i = 0; i < patch.size(); ++i) part[i] = part_of_patch[patch[i]];
  return primitives;
}

// The window and margin of the candidate primitives of a face, in voxels: a face farther than
// three voxels from a primitive's claimed leaves than from its nearest one has no say in it.
constexpr double candidate_window = 3.;
constexpr double candidate_margin = 3.;

// The final labelling of `cut_face_labels()`: the primitive of each face index; `h` is the voxel
// of the finest prior resolution, the unit of lengths. Where the faces are much smaller than the
// cells of the clusters (twice as many faces as superfaces), on superfaces
// (`superface_labels()`).
template <typename ConcurrencyTag>
std::vector<std::int32_t> cut_primitive_labels(const Face_corners& corners, const Face_adjacency& adj,
                                               const Superfaces& sf,
                                               const Claimed_leaf_search<Adaptive_grid>& search, double h,
                                               const Normalization& normalization,
                                               const Assignment_parameters& p)
{
  const double tau = p.vote_temperature * h, margin = candidate_margin * h;
  const double cell = superface_cell(h, normalization.scale());
  // the cut cost of an edge is measured in voxels of length, like the data cost in voxels of area
  const double edge_scale = p.boundary_smoothness * normalization.scale() / h;
  const std::vector<int> outward(adj.number_of_faces, 1);
  const auto point_of_face = [&](std::size_t i) { return face_point(corners, normalization, h, i); };
  if(superfaces_pay(sf, adj.number_of_faces))
    return superface_labels<ConcurrencyTag>(adj, corners, outward, edge_scale, sf, point_of_face,
                                            [&](const std::vector<Weighted_point>& points) {
      return point_candidates<ConcurrencyTag>(points.size(), [&](std::size_t i) { return points[i]; }, search, tau,
                                              margin);
    });
  const Face_candidates candidates =
    point_candidates<ConcurrencyTag>(adj.number_of_faces, point_of_face, search, tau, margin);
  return cut_face_labels<ConcurrencyTag>(adj, corners, candidates, outward, edge_scale, cell);
}

// `assign_parts()` on vectors indexed by the face index map `fim`: `patch` holds the patch of
// each face (any ids), `part` receives its part; returns the primitive of each part. With a
// positive `boundary_smoothness`, the faces are labelled by `cut_primitive_labels()` on `adj`,
// `corners` and `superfaces` instead of the patch vote (none is read otherwise).
template <typename ConcurrencyTag, typename TriangleMesh, typename FaceIndexMap, typename VertexPointMap>
std::vector<std::size_t> assign_patches_to_primitives(const TriangleMesh& tm, const FaceIndexMap& fim,
                                                      const VertexPointMap& vpm, std::vector<std::size_t> patch,
                                                      const std::vector<std::int32_t>& claimed_labels,
                                                      const Adaptive_grid& grid, double h,
                                                      const Normalization& normalization,
                                                      const Assignment_parameters& p, const Face_adjacency& adj,
                                                      const Face_corners* corners, const Superfaces* superfaces,
                                                      std::vector<std::size_t>& part)
{
  Claimed_leaf_search<Adaptive_grid> search;
  search.build<ConcurrencyTag>(grid, claimed_labels, p.boundary_smoothness > 0. ? candidate_window * h : 0.);
  if(!search.any())
  {
    part.assign(patch.size(), 0);
    return std::vector<std::size_t>(1, no_primitive);
  }
  if(p.boundary_smoothness > 0.)
  {
    const std::vector<std::int32_t> label =
        cut_primitive_labels<ConcurrencyTag>(*corners, adj, *superfaces, search, h, normalization, p);
    std::iota(patch.begin(), patch.end(), std::size_t(0)); // one patch per face
    return parts_of_winners(label, patch, part);
  }
  const std::size_t number_of_patches = make_patch_ids_consecutive(patch);
  std::vector<std::int32_t> face_label;
  std::vector<double> face_distance;
  nearest_claimed_voxels<ConcurrencyTag>(tm, fim, vpm, search, normalization, face_label, face_distance);
  const double tau = p.vote_temperature * h;
  const std::vector<std::int32_t> winner =
      vote_patch_labels<ConcurrencyTag>(patch, number_of_patches, face_label, face_distance, tau);
  return parts_of_winners(winner, patch, part);
}

} // namespace internal

/*!
\ingroup PkgPartDecompositionRef
transfers the primitives fitted on the leaves of the adaptive grid to the mesh (paper Sec.\ 3.3,
App.\ E.4, Eq.\ 9). With `boundary_smoothness(0)`, as in the paper, each patch of an
over-segmentation of `tm` (see `over_segment()`) is given one primitive by a distance-weighted vote
of its faces, and the patches given the same primitive form one part:
1. The centroid of each face \f$f\f$, mapped to the normalized cube by the normalization of
   `tsdf`, is matched to the nearest centre of a claimed leaf (a leaf of `tsdf.grid` whose
   `claimed_labels` entry is a primitive index \f$\ge 0\f$): \f$\hat k_f\f$ is that leaf's
   primitive and \f$d_f\f$ the Euclidean distance (normalized units). A face in a claimed leaf
   takes that leaf; the others are answered by a kd-tree of the claimed leaves next to
   unclaimed ones.
2. Each patch \f$j\f$ takes
   \f$k^*_j = \arg\max_k \sum_{f \in j} \exp(-d_f/\tau_v)\,[\hat k_f = k]\f$, the smallest \f$k\f$
   on a tie, with \f$\tau_v\f$ = `vote_temperature` voxels \f$\Delta\f$ (`tsdf.voxel_size`).
3. The patches with the same \f$k^*\f$ form one part. Parts are numbered `0` to `K-1` by increasing
   primitive index.

By default (`boundary_smoothness` \f$\lambda > 0\f$, not in the paper) the faces are labelled one
by one instead, by minimizing
\f[
E(k) = \sum_f \frac{A_f}{h^2}\,\frac{d_f(k_f) - d_f}{\tau_v}
     + \lambda \sum_{e = (f, g),\, k_f \ne k_g} \frac{\ell_e}{h}\, c(\theta_e),
\quad c(\theta) = -\log \max\left(10^{-3},\ \frac{\theta}{180^\circ} \cdot \begin{cases} 1 & \text{concave} \\ 0.08 & \text{convex}\end{cases}\right)
\f]
where \f$A_f\f$ is the area of face \f$f\f$, \f$d_f(k)\f$ the distance from its centroid to the
nearest claimed leaf of primitive \f$k\f$, \f$h = \Delta\f$, \f$\ell_e\f$ the length of
edge \f$e\f$ and \f$\theta_e\f$ its dihedral angle (concave for the orientation of `tm`): a cut is
cheap along a concave crease and expensive across smooth or convex surface, as in
`CGAL::Surface_mesh_segmentation`. A face may only take the primitives claimed within three
voxels of the leaf of its centroid and at most three voxels farther than its nearest one; the
faces with a single such primitive take it, and each edge-connected set of the others is labelled
by alpha expansion \cgalCite{Boykov2001FastApproximate}, each expansion move solved exactly by one
minimum cut on the faces that may take the expanded primitive. Where the faces are much smaller
than a voxel (at least twice as many faces as superfaces: the edge-connected faces whose centroids
lie in one cell of half a voxel), the energy is minimized on the superfaces first, each weighed as
one point (its faces' area-weighted centroid and their area), then face by face on the superfaces
next to a cut; otherwise, each set whose faces are much smaller than that cell is labelled in the
same two levels. The faces of one primitive form one part, and the patches of
`face_patch_map` are not used.
If no leaf is claimed, all faces form the single part `0` and its primitive is `no_primitive`.
The result does not depend on the number of threads.

\par Complexity
\f$O(n \log n + F \log n)\f$ for \f$n\f$ leaves and \f$F\f$ faces: one kd-tree of the claimed leaves and
at most one nearest-neighbour query per face; the vote is linear.

\tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag` (needs TBB); the
        nearest-leaf queries and the votes run in parallel.
\tparam TriangleMesh a model of `FaceListGraph`
\tparam FacePatchMap a model of `ReadablePropertyMap` with
        `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and an unsigned integer
        type as value type
\tparam FacePartMap a model of `WritablePropertyMap` with
        `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and `std::size_t` as
        value type
\tparam NamedParameters a sequence of named parameters

\param tm the triangle mesh
\param face_patch_map the patch of each face; ids need not be consecutive
\param claimed_labels for each leaf of `tsdf.grid`, the index of the primitive that claims it, or
       a negative value (the `labels` of `fit_superquadrics()`)
\param tsdf the distance field whose grid the labels are given on; its normalization maps the
       coordinates of `tm` to the normalized cube, its `voxel_size` is the unit of lengths
\param face_part_map receives the part id of each face, in `[0, K)`
\param np an optional sequence of named parameters; this function reads `vertex_point_map`,
`face_index_map`, `geom_traits` (if \f$\lambda > 0\f$; \ref PD_MeshParameters), `vote_temperature`
and `boundary_smoothness` (\ref PD_ParameterTable); it checks the range of `residual_tolerance`,
which `separate_residual_patches()` reads. The switches `keep_residual_patches` and
`merge_thin_sheets` of `method_variant` decide whether `decompose()` runs
`separate_residual_patches()` and `merge_thin_sheet_parts()` after it.

\pre `CGAL::is_triangle_mesh(tm)`
\pre if `TriangleMesh` is a `CGAL::Surface_mesh`, it has no garbage (or a `face_index_map` is given)

\returns the primitive index of each part, increasing: `K` values.

\throws Invalid_input (`INVALID_PARAMETER`) if `vote_temperature` is not a positive finite number,
`boundary_smoothness` is negative, or `claimed_labels` does not have one entry per leaf.
*/
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename TriangleMesh, typename FacePatchMap,
          typename FacePartMap, typename NamedParameters = CGAL::parameters::Default_named_parameters>
std::vector<std::size_t> assign_parts(const TriangleMesh& tm, FacePatchMap face_patch_map,
                                      const std::vector<std::int32_t>& claimed_labels,
                                      const Truncated_signed_distance_field& tsdf, FacePartMap face_part_map,
                                      const NamedParameters& np = CGAL::parameters::default_values())
{
  internal::static_check_concurrency_tag<ConcurrencyTag>();
  typedef typename GetInitializedFaceIndexMap<TriangleMesh, NamedParameters>::const_type FIM;
  const auto vpm = CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                                      get_const_property_map(CGAL::vertex_point, tm));
  const FIM fim = CGAL::get_initialized_face_index_map(tm, np);
  const internal::Assignment_parameters p = internal::read_assignment_parameters(np);
  internal::check_parameter(claimed_labels.size() == tsdf.grid.number_of_leaves() && tsdf.voxel_size > 0.,
                            "claimed_labels", "one label per leaf of the grid of the distance field");
  CGAL_precondition(CGAL::is_triangle_mesh(tm));

  // the one conversion from the caller's map, and the one to the other
  std::vector<std::size_t> patch(num_faces(tm)), part;
  for(auto f : faces(tm)) patch[std::size_t(get(fim, f))] = std::size_t(get(face_patch_map, f));
  const auto graph = p.boundary_smoothness > 0. ? internal::shared_face_adjacency<ConcurrencyTag>(tm, fim, np)
                                                : std::make_shared<const internal::Face_adjacency>();
  const internal::Face_adjacency& adj = *graph;
  const auto corners = p.boundary_smoothness > 0. ? internal::shared_face_corners<ConcurrencyTag>(tm, fim, vpm, np)
                                                  : std::shared_ptr<const internal::Face_corners>();
  const auto superfaces =
    p.boundary_smoothness > 0.
      ? internal::shared_superfaces<ConcurrencyTag>(
          adj, internal::superface_cell(tsdf.voxel_size, tsdf.normalization.scale()), np)
      : std::shared_ptr<const internal::Superfaces>();
  std::vector<std::size_t> primitives = internal::assign_patches_to_primitives<ConcurrencyTag>(
      tm, fim, vpm, std::move(patch), claimed_labels, tsdf.grid, tsdf.voxel_size, tsdf.normalization, p, adj,
      corners.get(), superfaces.get(), part);
  internal::put_face_values(tm, fim, part, face_part_map);
  return primitives;
}

} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_PRIMITIVE_ASSIGNMENT_H
