// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_THIN_SHEET_MERGING_H
#define CGAL_PART_DECOMPOSITION_THIN_SHEET_MERGING_H

#include <CGAL/Part_decomposition/Adaptive_grid.h>
#include <CGAL/Part_decomposition/Superquadric.h>
#include <CGAL/Part_decomposition/input_validation.h>
#include <CGAL/Part_decomposition/normalization.h>
#include <CGAL/Part_decomposition/parameters.h>
#include <CGAL/Part_decomposition/stage_results.h>
#include <CGAL/Part_decomposition/internal/toolbox/face_adjacency.h>
#include <CGAL/Part_decomposition/internal/grid/leaf_distance.h>
#include <CGAL/Part_decomposition/internal/toolbox/toolbox.h>

#include <CGAL/Union_find.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/number_utils.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Part_decomposition {

/// \cond SKIP_IN_MANUAL
namespace internal {

// Thresholds of the sheet merge, measured on the development meshes (benchmark/Part_decomposition/RESULTS.md).
struct Sheet_merging_thresholds
{
  // a primitive is flat when its smallest semi-axis times this is below its middle one
  double flatness_ratio = 2.;
  // and thin when no voxel it claims lies deeper than this inside the shape, as a fraction of the
  // normalized cube (2.5 voxels of 64^3: the wall of a cup); a length, so that a finer grid keeps it
  double maximum_depth = 2.5 / 64.;
  // two sheets merge unless this fraction of their seam lies on sharp edges
  double sharp_seam_fraction = 0.5;
  // sharp: a dihedral angle at or above this percentile of the mesh's interior edges (nearest
  // rank below) and at or above the minimum angle, in degrees (the sides of a 16-gon prism,
  // 22.5 degrees apart, are smooth)
  double sharp_edge_percentile = 90.;
  double minimum_sharp_angle = 30.;
  // the angle an edge of a zero-area face (no normal) counts with, in degrees
  double degenerate_edge_angle = 90.;
  // two sheets whose thin axes meet at more than this angle (degrees) form a fold: their seam
  // counts as sharp where a sharp edge lies within one ring of faces of it, since the assignment
  // may leave a row of faces of one plate to the other
  double fold_angle = 45.;
};

// Whether each part is a thin sheet: its primitive is flat and claims no leaf deeper than the
// maximum depth inside the shape (`tsdf`: negative inside).
template <typename ConcurrencyTag, typename GeomTraits>
std::vector<char> thin_sheet_parts(const Truncated_signed_distance_field& tsdf,
                                   const Superquadric_fitting_result<GeomTraits>& fitting,
                                   const std::vector<std::size_t>& part_to_primitive,
                                   const Sheet_merging_thresholds& th)
{
  // Depth of each claimed leaf inside the shape: the distance from its centre to the nearest
  // centre of an outside leaf.
  const std::size_t n_leaves = tsdf.values.size();
  const std::vector<double> depth2 = leaf_squared_distances<ConcurrencyTag>(
    tsdf.grid, [&](std::size_t l) { return tsdf.values[l] > 0.; },
    [&](std::size_t l) { return l < fitting.labels.size() && fitting.labels[l] >= 0; });

  const double max_depth = th.maximum_depth;
  const std::size_t K = part_to_primitive.size();
  std::vector<char> sheet(K, 0);
  for(std::size_t k = 0; k < K; ++k)
  {
    const std::size_t q = part_to_primitive[k];
    if(q >= fitting.primitives.size()) continue;
    std::array<double, 3> a = fitting.primitives[q].scales();
    std::sort(a.begin(), a.end());
    double deepest2 = 0.;
    for(std::size_t l : fitting.claimed_leaves[q])
      if(l < n_leaves) deepest2 = (std::max)(deepest2, depth2[l]);
    sheet[k] = (a[0] * th.flatness_ratio < a[1] && deepest2 <= max_depth * max_depth * (1. + 1e-12)) ? 1 : 0;
  }
  return sheet;
}

// An interior edge between two sheets of different parts p < q.
struct Seam_edge
{
  std::size_t p, q;
  double angle, length;
  double near_angle; // the largest angle of the edges of the faces within one ring of the edge
};

// The dihedral angle across slot `k` of face `f` as the merge counts it, in degrees: the
// degenerate angle if either face has zero area.
inline double sheet_slot_angle(const Face_adjacency& adj, std::size_t f, std::size_t k,
                               const Sheet_merging_thresholds& th)
{
  const std::size_t g = adj.neighbor[3 * f + k];
  if(adj.degenerate[f] || (g != Face_adjacency::no_face && adj.degenerate[g])) return th.degenerate_edge_angle;
  return adj.angle[3 * f + k];
}

// The largest angle of the edges of each face and of its neighbours.
inline std::vector<double> largest_angle_nearby(const Face_adjacency& adj, const Sheet_merging_thresholds& th)
{
  const std::size_t n = adj.number_of_faces;
  std::vector<double> near(n, 0.);
  for(std::size_t f = 0; f < n; ++f)
    for(std::size_t k = 0; k < 3; ++k) near[f] = (std::max)(near[f], sheet_slot_angle(adj, f, k, th));
  std::vector<double> next = near;
  for(std::size_t f = 0; f < n; ++f)
    for(std::size_t k = 0; k < 3; ++k)
      if(adj.neighbor[3 * f + k] != Face_adjacency::no_face) next[f] = (std::max)(next[f], near[adj.neighbor[3 * f + k]]);
  return next;
}

// The angle of every interior edge (`angles`) and the seams between sheets of different parts,
// in the order of `edges(tm)` (the seam lengths are summed in this order).
// The angles of a zero-area face's edges are the degenerate angle.
template <typename TriangleMesh, typename VertexPointMap, typename FaceIndexMap>
void collect_seam_edges(const TriangleMesh& tm, const VertexPointMap& vpm, const FaceIndexMap& fim,
                        const Face_adjacency& adj, const std::vector<std::size_t>& part,
                        const std::vector<char>& sheet, const Sheet_merging_thresholds& th,
                        std::vector<double>& angles, std::vector<Seam_edge>& seam)
{
  const std::size_t K = sheet.size();
  const std::vector<double> near = largest_angle_nearby(adj, th);
  angles.reserve(num_edges(tm));
  for(auto e : edges(tm))
  {
    const auto h = halfedge(e, tm);
    if(is_border_edge(h, tm)) continue;
    const std::size_t fa = std::size_t(get(fim, face(h, tm))), fb = std::size_t(get(fim, face(opposite(h, tm), tm)));
    const double angle = sheet_slot_angle(adj, fa, std::size_t(slot_in_face(h, tm)), th);
    angles.push_back(angle);
    const std::size_t pa = part[fa], pb = part[fb];
    if(pa == pb || pa >= K || pb >= K || !sheet[pa] || !sheet[pb]) continue;
    const double length = norm3(sub3(vec3_of(get(vpm, source(h, tm))), vec3_of(get(vpm, target(h, tm)))));
    seam.push_back({(std::min)(pa, pb), (std::max)(pa, pb), angle, length, (std::max)({angle, near[fa], near[fb]})});
  }
}

// The angle from which an edge is sharp: the percentile of `angles` at the nearest rank below
// (`angles` is reordered), and at least the minimum angle.
inline double sharp_edge_angle(std::vector<double>& angles, const Sheet_merging_thresholds& th)
{
  const std::size_t rank = std::size_t(th.sharp_edge_percentile / 100. * double(angles.size() - 1));
  return (std::max)(value_at_rank(angles, double(rank)), th.minimum_sharp_angle);
}

// The axis of the smallest semi-axis of each part's primitive (0 for a part without one; every
// sheet has one).
template <typename GeomTraits>
std::vector<Vec3> thin_axes(const Superquadric_fitting_result<GeomTraits>& fitting,
                            const std::vector<std::size_t>& part_to_primitive)
{
  std::vector<Vec3> axis(part_to_primitive.size(), Vec3{{0., 0., 0.}});
  for(std::size_t k = 0; k < part_to_primitive.size(); ++k)
    if(part_to_primitive[k] < fitting.primitives.size())
    {
      const Superquadric<GeomTraits>& q = fitting.primitives[part_to_primitive[k]];
      const std::array<double, 3> a = q.scales();
      axis[k] = vec3_of(q.axis(int(std::min_element(a.begin(), a.end()) - a.begin())));
    }
  return axis;
}

// The new part of each old part: sheets joined across every seam that is mostly smooth, numbered
// in order of their first old part; the seam of a fold (the two parts' `thin_axis` apart by more
// than the fold angle) counts the angles near it. Returns the number of new parts.
inline std::size_t join_sheets_across_smooth_seams(const std::vector<Seam_edge>& seam, double sharp,
                                                   std::size_t K, const Sheet_merging_thresholds& th,
                                                   std::vector<std::size_t>& old_to_new,
                                                   const std::vector<Vec3>& thin_axis)
{
  const double fold_cosine = std::cos(th.fold_angle * CGAL_PI / 180.);
  // the lengths of the seam of each pair of sheets: on sharp edges, near sharp edges, in all
  struct Seam_lengths
  {
    double sharp = 0., sharp_nearby = 0., total = 0.;
  };
  std::map<std::pair<std::size_t, std::size_t>, Seam_lengths> seams;
  for(const Seam_edge& e : seam)
  {
    Seam_lengths& s = seams[std::make_pair(e.p, e.q)];
    s.total += e.length;
    if(e.angle >= sharp) s.sharp += e.length;
    if(e.near_angle >= sharp) s.sharp_nearby += e.length;
  }
  // the value of each set is one of its parts: the key of its new id
  typedef CGAL::Union_find<std::size_t> Groups;
  Groups groups;
  std::vector<Groups::handle> group_of;
  for(std::size_t k = 0; k < K; ++k) group_of.push_back(groups.make_set(k));
  for(const auto& s : seams)
  {
    const bool folded = std::abs(dot3(thin_axis[s.first.first], thin_axis[s.first.second])) < fold_cosine;
    const double sharp_length = folded ? s.second.sharp_nearby : s.second.sharp;
    if(sharp_length < th.sharp_seam_fraction * s.second.total)
      groups.unify_sets(group_of[s.first.first], group_of[s.first.second]);
  }

  const std::size_t unset = std::size_t(-1);
  std::vector<std::size_t> new_id(K, unset);
  old_to_new.assign(K, 0);
  std::size_t K2 = 0;
  for(std::size_t k = 0; k < K; ++k)
  {
    const std::size_t r = *groups.find(group_of[k]);
    if(new_id[r] == unset) new_id[r] = K2++;
    old_to_new[k] = new_id[r];
  }
  return K2;
}

// The primitive of each new part: of its old parts' primitives, the one that claimed the most
// volume (the first on a tie; a part without a primitive counts least).
template <typename GeomTraits>
std::vector<std::size_t> largest_primitives(const std::vector<std::size_t>& old_to_new, std::size_t K2,
                                            const std::vector<std::size_t>& part_to_primitive,
                                            const Superquadric_fitting_result<GeomTraits>& fitting, const Adaptive_grid& grid)
{
  std::vector<std::size_t> primitive(K2, 0);
  std::vector<double> volume(K2, 0.);
  std::vector<char> has(K2, 0);
  for(std::size_t k = 0; k < old_to_new.size(); ++k)
  {
    const std::size_t n = old_to_new[k], q = part_to_primitive[k];
    double size = -1.;
    if(q < fitting.claimed_leaves.size())
    {
      size = 0.;
      for(std::size_t l : fitting.claimed_leaves[q]) size += grid.volume(l);
    }
    if(!has[n] || size > volume[n])
    {
      primitive[n] = q;
      volume[n] = size;
      has[n] = 1;
    }
  }
  return primitive;
}

/*
The sheet merge (see `merge_thin_sheet_parts()`) on the face graph `adj` of the over-segmentation
of `tm` (face indices of `fim`): `part` holds the part of each face index and `part_to_primitive`
the primitive of each part; both are renumbered in place. Returns the new number of parts.
*/
template <typename ConcurrencyTag, typename TriangleMesh, typename VertexPointMap, typename FaceIndexMap,
          typename GeomTraits>
std::size_t merge_thin_sheets_on_faces(const TriangleMesh& tm, const VertexPointMap& vpm, const FaceIndexMap& fim,
                                       const Face_adjacency& adj, const Truncated_signed_distance_field& tsdf,
                                       const Superquadric_fitting_result<GeomTraits>& fitting,
                                       std::vector<std::size_t>& part,
                                       std::vector<std::size_t>& part_to_primitive,
                                       const Sheet_merging_thresholds& th = Sheet_merging_thresholds())
{
  const std::size_t K = part_to_primitive.size();
  if(K < 2) return K;
  const std::vector<char> sheet = thin_sheet_parts<ConcurrencyTag>(tsdf, fitting, part_to_primitive, th);
  if(std::find(sheet.begin(), sheet.end(), 1) == sheet.end()) return K;

  std::vector<double> angles;
  std::vector<Seam_edge> seam;
  collect_seam_edges(tm, vpm, fim, adj, part, sheet, th, angles, seam);
  if(seam.empty()) return K;
  const double sharp = sharp_edge_angle(angles, th);

  std::vector<std::size_t> old_to_new;
  const std::size_t K2 =
    join_sheets_across_smooth_seams(seam, sharp, K, th, old_to_new, thin_axes(fitting, part_to_primitive));
  part_to_primitive = largest_primitives(old_to_new, K2, part_to_primitive, fitting, tsdf.grid);
  for(std::size_t& p : part)
    if(p < K) p = old_to_new[p];
  return K2;
}

} // namespace internal
/// \endcond

/*!
\ingroup PkgPartDecompositionRef
merges the parts of a decomposition that tile one thin sheet: the stage of `decompose()` after
`assign_parts()` and before `compose_parts()` (the switch `merge_thin_sheets` of `method_variant`). This step is not
in the paper.

Thin shells (the wall of a cup, the skin of a wing, a table top a few voxels thick) are fitted by
several flat superquadrics: the fitter cannot grow one primitive along a curved shell.

1. A part is a <em>sheet</em> if its primitive is flat (its smallest semi-axis is below half the
   middle one) and thin (no voxel it claims lies deeper inside the shape than 2.5/64 of the
   normalized cube: 2.5 voxels of a \f$64^3\f$ grid of `tsdf`, 5 of a \f$128^3\f$ one; the depth
   being the distance to the nearest voxel of positive distance).
2. An interior edge is <em>sharp</em> if its dihedral angle (as in `over_segment()`; an edge of a
   face of zero area counts as 90 degrees) is at least the 90-th percentile of the angles of all
   interior edges, taken at the nearest rank below (position \f$\lfloor 0.9\,(n-1) \rfloor\f$ in
   the sorted list), and at least 30 degrees.
3. Two adjacent sheets are merged when less than half of the length of their common boundary
   runs over sharp edges; merging is transitive. A seam on a crease (the rim of a table top, a
   wing's edge against the fuselage) keeps them apart. Where the two sheets form a fold (the axes
   of the smallest semi-axes of their primitives more than 45 degrees apart), a boundary edge
   also counts as sharp if one of its two faces or of their neighbours has a sharp edge: the
   assignment may leave a row of one plate's faces to the other, which moves the seam off the
   crease.
4. The parts are renumbered `0` to `K_new - 1` in the order of their smallest former id; a merged part
   keeps the primitive that claimed the most volume (the one of the smallest former part on a tie).

\tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag` (needs TBB): the dihedral
        angles are computed in parallel
\tparam TriangleMesh a model of `FaceListGraph`
\tparam FacePartMap a model of `ReadWritePropertyMap` with
        `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and `std::size_t` as
        value type
\tparam GeomTraits the traits of the fitting result
\tparam NamedParameters a sequence of named parameters

\param tm the triangle mesh
\param face_part_map the part of each face, in `[0, K)` on input (a face of a larger id is left
       unchanged), in `[0, K_new)` on output
\param part_to_primitive the index in `fitting.primitives` of the primitive of each part (`K`
       values, as returned by `assign_parts()`); on output, the primitive of each new part
\param fitting the fitted primitives and the voxels each claimed
\param tsdf the distance field the primitives were fitted to
\param np an optional sequence of named parameters; this function reads `vertex_point_map`,
`face_index_map` and `geom_traits` (\ref PD_MeshParameters)

\pre `CGAL::is_triangle_mesh(tm)`
\pre `fitting` was computed on the grid of `tsdf` (`fit_superquadrics()` with `tsdf`).

\returns the number `K_new` of parts.

\throws Invalid_input (`INVALID_PARAMETER`) if the normalizations of `fitting` and `tsdf` differ.
*/
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename TriangleMesh, typename FacePartMap,
          typename GeomTraits, typename NamedParameters = CGAL::parameters::Default_named_parameters>
std::size_t merge_thin_sheet_parts(const TriangleMesh& tm, FacePartMap face_part_map,
                                   std::vector<std::size_t>& part_to_primitive,
                                   const Superquadric_fitting_result<GeomTraits>& fitting,
                                   const Truncated_signed_distance_field& tsdf,
                                   const NamedParameters& np = CGAL::parameters::default_values())
{
  internal::static_check_concurrency_tag<ConcurrencyTag>();
  typedef typename GetInitializedFaceIndexMap<TriangleMesh, NamedParameters>::const_type FIM;
  const auto vpm = CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                                      get_const_property_map(CGAL::vertex_point, tm));
  const FIM fim = CGAL::get_initialized_face_index_map(tm, np);
  internal::check_parameter(internal::same_frame(tsdf.normalization, fitting.normalization),
                            "the normalization of the distance field", "the one of the fitting (same center and scale)");
  CGAL_precondition(CGAL::is_triangle_mesh(tm));

  const auto graph = internal::shared_face_adjacency<ConcurrencyTag>(tm, fim, np);
  const internal::Face_adjacency& adj = *graph;
  std::vector<std::size_t> part(num_faces(tm));
  for(auto f : faces(tm)) part[std::size_t(get(fim, f))] = std::size_t(get(face_part_map, f));
  const std::size_t K = internal::merge_thin_sheets_on_faces<ConcurrencyTag>(tm, vpm, fim, adj, tsdf,
                                                                             fitting, part, part_to_primitive);
  internal::put_face_values(tm, fim, part, face_part_map);
  return K;
}

} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_THIN_SHEET_MERGING_H
