// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_PART_COMPOSITION_H
#define CGAL_PART_DECOMPOSITION_PART_COMPOSITION_H

#include <CGAL/Part_decomposition/Superquadric.h>
#include <CGAL/Part_decomposition/normalization.h>
#include <CGAL/Part_decomposition/parameters.h>
#include <CGAL/Part_decomposition/part_hierarchy.h>
#include <CGAL/Part_decomposition/piece_segmentation.h>
#include <CGAL/Part_decomposition/primitive_assignment.h>
#include <CGAL/Part_decomposition/stage_results.h>
#include <CGAL/Part_decomposition/input_validation.h>
#include <CGAL/Part_decomposition/Voxel_grid.h>
#include <CGAL/Part_decomposition/internal/grid/bounded_volume.h>
#include <CGAL/Part_decomposition/internal/toolbox/face_adjacency.h>
#include <CGAL/Part_decomposition/internal/parts/part_merging.h>
#include <CGAL/Part_decomposition/internal/parts/piece_regions.h>
#include <CGAL/Part_decomposition/internal/parts/superface_labelling.h>
#include <CGAL/Part_decomposition/internal/toolbox/toolbox.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Part_decomposition {

/*!
\ingroup PkgPartDecompositionRef
The parts of the volumetric stages, before they are composed with the pieces (`compose_parts()`).
Vectors indexed by face are indexed by the face index map; an empty vector means that the step
that fills it was not run.
*/
struct Volumetric_parts
{
  /// the patch of each face, written by `over_segment()`.
  std::vector<std::size_t> patches;
  /// the part of each face, written by `assign_parts()`, then changed by
  /// `separate_residual_patches()` and `merge_thin_sheet_parts()`; empty if the volumetric stages
  /// did not run.
  std::vector<std::size_t> parts;
  /// per part, the index of its primitive in the fitting result, or `no_primitive`: the value of
  /// `assign_parts()`, changed by the same steps.
  std::vector<std::size_t> part_to_primitive;
  /// per face, 1 if it lies in a residual patch (`separate_residual_patches()`).
  std::vector<std::uint8_t> residual_faces;
};

/*!
\ingroup PkgPartDecompositionRef
The parts of a decomposition (`compose_parts()`): the parts of the volumetric stages cut by the
regions of the pieces, each with its superquadric, and the finer parts from which the part
hierarchy starts. Vectors indexed by face are indexed by the face index map.
*/
template <typename GeomTraits>
struct Composed_parts
{
  /// the part of each face, `0` to `K - 1`, numbered by smallest face index.
  std::vector<std::size_t> parts;
  /// per part, the index in the fitting result of the primitive it keeps, or `no_primitive`.
  std::vector<std::size_t> part_to_primitive;
  /// per part, its superquadric in input coordinates: its fitted primitive if no other part has it
  /// and it lies on average as close to the part's vertices, else the box-like superquadric of its
  /// principal-axis bounding box.
  std::vector<Superquadric<GeomTraits> > part_primitives;
  /// per part, 1 if most of its area lies in residual patches (see `Volumetric_parts`).
  std::vector<std::uint8_t> residual_parts;
  /// the leaf of the part hierarchy of each face: its part cut by the regions of the pieces and,
  /// in the pieces the volumetric stages decomposed, by the patches; numbered by smallest face index.
  std::vector<std::size_t> finest_parts;
  /// the number of finest parts.
  std::size_t number_of_finest_parts = 0;
  /// the group of each face inside its part: its part and its volumetric part (the hierarchy
  /// merges inside a group first).
  std::vector<std::size_t> part_groups;

  /// the number `K` of parts.
  std::size_t number_of_parts() const { return part_to_primitive.size(); }
};

/// \cond SKIP_IN_MANUAL
namespace internal {

// Per face, 1 if its patch is residual: at least half of the patch's area lies in Freeze voxels
// of the prior (`classes`) and its faces are on average farther than `tolerance` (normalized units)
// from the primitive (`primitives`, normalized) of their part (`part_to_primitive[part[i]]`).
template <typename GeomTraits>
std::vector<std::uint8_t> residual_faces(const Face_adjacency& adj, const Face_corners& corners,
                                         const std::vector<std::size_t>& patch, std::size_t number_of_patches,
                                         const std::vector<std::size_t>& part,
                                         const std::vector<std::size_t>& part_to_primitive,
                                         const std::vector<Superquadric<GeomTraits> >& primitives,
                                         const Voxel_grid<Voxel_class>& classes, const Normalization& normalization,
                                         double tolerance)
{
  typedef typename GeomTraits::Point_3 Point_3;
  std::vector<double> area(number_of_patches, 0.), frozen(number_of_patches, 0.), distance(number_of_patches, 0.);
  for(std::size_t i = 0; i < adj.number_of_faces; ++i)
  {
    const std::size_t q = part_to_primitive[part[i]];
    if(q >= primitives.size()) continue;
    const Eigen::Vector3d c = (corners(i, 0) + corners(i, 1) + corners(i, 2)) / 3.;
    const std::array<double, 3> u = normalization.to_unit(c[0], c[1], c[2]);
    const std::array<int, 3> v = classes.locate(u[0], u[1], u[2]);
    const double a = adj.area[i];
    area[patch[i]] += a;
    if(classes(v[0], v[1], v[2]) == Voxel_class::FREEZE) frozen[patch[i]] += a;
    distance[patch[i]] += a * std::abs(primitives[q].signed_distance(Point_3(u[0], u[1], u[2])));
  }
  std::vector<std::uint8_t> residual(adj.number_of_faces, 0);
  for(std::size_t i = 0; i < adj.number_of_faces; ++i)
  {
    const std::size_t p = patch[i];
    residual[i] = area[p] > 0. && frozen[p] >= 0.5 * area[p] && distance[p] > tolerance * area[p];
  }
  return residual;
}

// Moves each edge-connected set of residual faces to a part of its own, appended after the
// existing parts with no primitive; returns the number of parts added.
template <typename ConcurrencyTag>
std::size_t split_residual_parts(const Face_adjacency& adj, const std::vector<std::uint8_t>& residual,
                                        std::vector<std::size_t>& part, std::vector<std::size_t>& part_to_primitive,
                                        std::size_t no_primitive)
{
  std::vector<std::size_t> component;
  face_components<ConcurrencyTag>(
    adj, [&](std::size_t i, int k) { return residual[i] && residual[adj.neighbor[3 * i + k]]; }, component);
  const std::size_t first = part_to_primitive.size();
  std::vector<std::size_t> id_of(adj.number_of_faces, no_primitive);
  for(std::size_t i = 0; i < adj.number_of_faces; ++i)
  {
    if(!residual[i]) continue;
    std::size_t& id = id_of[component[i]];
    if(id == no_primitive)
    {
      id = part_to_primitive.size();
      part_to_primitive.push_back(no_primitive);
    }
    part[i] = id;
  }
  return part_to_primitive.size() - first;
}


// A piece bounds a volume of the distance field if at least this fraction of its area separates
// the field's inside from its outside, probed at this depth, in voxels of the field, on both sides
// of each face: an open sheet has the outside on both sides, a piece thinner than a voxel too.
constexpr double bounding_probe_depth = 1.;
constexpr double minimum_bounding_fraction = 0.5;
// A piece whose non-manifold junctions (edges of three faces or more) make up at least this
// fraction of the length of its edges is an assembly of sheets (walls and shelves glued along
// lines), whose parts are its sheets; only long chains of junctions count (see
// minimum_junction_chain), so that a scan's scattered non-manifold edges do not. The CAD-style
// set gives the same parts from 0.0003 to 0.01 (benchmark/Part_decomposition/RESULTS.md).
constexpr double maximum_junction_fraction = 0.001;

// The box-like superquadric of the principal-axis bounding box of a surface given as triangles
// (`points` holds three corners per triangle): what a part gets when no primitive was fitted to
// it (a flat sheet has no volume to fit). The axes are those of the surface's second moments, so
// that a plate of two large triangles gets the axes of its rectangle, not of its diagonal.
template <typename GeomTraits>
Superquadric<GeomTraits> bounding_superquadric(const std::vector<std::array<double, 3> >& points)
{
  // moments relative to a corner: far-off meshes stay accurate
  const Eigen::Vector3d origin =
    points.empty() ? Eigen::Vector3d::Zero() : Eigen::Vector3d(points[0][0], points[0][1], points[0][2]);
  std::vector<Eigen::Vector3d> relative;
  relative.reserve(points.size());
  for(const std::array<double, 3>& p : points) relative.push_back(Eigen::Vector3d(p[0], p[1], p[2]) - origin);
  Part_box box;
  for(std::size_t t = 0; t + 2 < relative.size(); t += 3)
    add_triangle_moments(box, relative[t], relative[t + 1], relative[t + 2]);
  fit_box_to_points(box, relative);
  return box_superquadric<GeomTraits>(box, origin);
}

// The mean absolute radial distance from the points to the surface of `sq`, over the points at a
// fixed stride that leaves at most `samples` of them: a large part costs no more than a small one.
template <typename GeomTraits>
double mean_surface_distance(const Superquadric<GeomTraits>& sq, const std::vector<std::array<double, 3> >& points,
                             std::size_t samples = 30000)
{
  typedef typename GeomTraits::Point_3 Point_3;
  const std::size_t stride = (points.size() + samples - 1) / samples;
  double sum = 0.;
  std::size_t n = 0;
  for(std::size_t k = 0; k < points.size(); k += stride, ++n)
    sum += std::abs(sq.signed_distance(Point_3(points[k][0], points[k][1], points[k][2])));
  return n == 0 ? 0. : sum / double(n);
}

// A part keeps its fitted primitive (of `fitted`, in input coordinates) if no other part has it
// and it lies on the part's surface at least as closely as the box-like superquadric of the
// part's faces; parts that share one (a part cut by the regions of the pieces, a thin plate the
// fitter saw as one with its neighbour), parts without one and parts thinner than the fitting
// grid get that box.
template <typename ConcurrencyTag, typename GeomTraits, typename TriangleMesh, typename FIM>
std::vector<Superquadric<GeomTraits> > part_primitives(const TriangleMesh& tm, const FIM& fim, const Face_corners& corners,
                                                       const std::vector<std::size_t>& part,
                                                       const std::vector<std::size_t>& part_to_primitive,
                                                       const std::vector<Superquadric<GeomTraits> >& fitted)
{
  const std::size_t K = part_to_primitive.size(), P = fitted.size();
  std::vector<std::size_t> users(P, 0);
  for(std::size_t k = 0; k < K; ++k)
    if(part_to_primitive[k] < P) ++users[part_to_primitive[k]];
  // the faces of each part in the order of faces(tm), then one part at a time
  const std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor> face_list(faces(tm).begin(), faces(tm).end());
  const auto part_of = [&](std::size_t r) { return part[std::size_t(get(fim, face_list[r]))]; };
  std::vector<std::size_t> start, order;
  group_indices(face_list.size(), K, part_of, [&](std::size_t r) { return part_of(r) < K; }, start, order);
  std::vector<Superquadric<GeomTraits> > result(K);
  for_each_range<ConcurrencyTag>(K, [&](std::size_t b, std::size_t e) {
    std::vector<std::array<double, 3> > points;
    for(std::size_t k = b; k < e; ++k)
    {
      points.resize(3 * (start[k + 1] - start[k]));
      for_each_range<ConcurrencyTag>(start[k + 1] - start[k], [&](std::size_t first, std::size_t last) {
        for(std::size_t s = first; s < last; ++s)
        {
          const std::size_t i = std::size_t(get(fim, face_list[order[start[k] + s]]));
          for(int c = 0; c < 3; ++c)
            points[3 * s + std::size_t(c)] = {{corners(i, c).x(), corners(i, c).y(), corners(i, c).z()}};
        }
      }, 4096);
      const Superquadric<GeomTraits> box = bounding_superquadric<GeomTraits>(points);
      const std::size_t q = part_to_primitive[k];
      const bool own = q < P && users[q] == 1;
      result[k] = own && mean_surface_distance(fitted[q], points) <= mean_surface_distance(box, points) ? fitted[q] : box;
    }
  });
  return result;
}

// A part is residual if most of its area is residual faces.
inline std::vector<std::uint8_t> residual_part_flags(const std::vector<double>& face_area,
                                                     const std::vector<std::size_t>& part, std::size_t K,
                                                     const std::vector<std::uint8_t>& residual_face)
{
  std::vector<std::uint8_t> flags(K, 0);
  if(residual_face.empty()) return flags;
  std::vector<double> area(K, 0.), residual(K, 0.);
  for(std::size_t i = 0; i < part.size(); ++i)
  {
    area[part[i]] += face_area[i];
    if(residual_face[i]) residual[part[i]] += face_area[i];
  }
  for(std::size_t k = 0; k < K; ++k) flags[k] = area[k] > 0. && 2. * residual[k] > area[k];
  return flags;
}

// The leaves and groups of the hierarchy: faces with the same (part, volumetric part, region,
// patch) are one leaf, with the same (part, volumetric part) one group. A patch counts only in
// the pieces the volumetric stages decomposed (`patch_of_face`).
template <typename ConcurrencyTag, typename GeomTraits, typename PatchOfFace>
void finest_parts(const std::vector<std::size_t>& volume_part, const std::vector<std::size_t>& region,
                  const PatchOfFace& patch_of_face, Composed_parts<GeomTraits>& c)
{
  const std::size_t nf = c.parts.size();
  std::vector<std::array<std::size_t, 4> > key(nf);
  for_each_range<ConcurrencyTag>(nf, [&](std::size_t b, std::size_t e) {
    for(std::size_t i = b; i < e; ++i)
      key[i] = {{c.parts[i], volume_part.empty() ? 0 : volume_part[i], region.empty() ? 0 : region[i], patch_of_face(i)}};
  }, 4096);
  index_of_keys<ConcurrencyTag>(key, 2, c.finest_parts, c.part_groups);
  c.number_of_finest_parts = renumber_by_first_face(c.finest_parts);
}

// The bounding fractions of the pieces (`bounding_area_fractions()`) of a mesh of F faces, probed
// face by face, or once per superface of `sf` where the faces are much smaller than its cells.
template <typename ConcurrencyTag, typename TriangleOf, typename Grid>
Bounding_fractions piece_bounding_fractions(const Superfaces& sf, std::size_t F, const TriangleOf& triangle,
                                            const Piece_segmentation& pieces, const Grid& grid,
                                            const std::vector<double>& field, double depth)
{
  if(superfaces_pay(sf, F))
    return bounding_area_fractions<ConcurrencyTag>(
      sf.size(),
      [&](std::size_t s, double& twice_area) {
        return bounding_side_of_faces(sf.face, sf.start[s], sf.start[s + 1], triangle, grid, field, depth, twice_area);
      },
      [&](std::size_t s) { return pieces.piece[sf.face[sf.start[s]]]; }, pieces.number_of_pieces);
  return bounding_area_fractions<ConcurrencyTag>(
    F, [&](std::size_t i, double& twice_area) { return bounding_side(triangle(i), grid, field, depth, twice_area); },
    [&](std::size_t i) { return pieces.piece[i]; }, pieces.number_of_pieces);
}

// Per piece: 1 if it is splittable (`splittable_pieces(adj, ...)`) and not an assembly of sheets,
// whose parts are its regions: only such a piece needs the distance field.
inline std::vector<std::uint8_t> splittable_solid_pieces(const Face_adjacency& adj, const Face_corners& corners,
                                                         const Piece_segmentation& pieces, const Piece_parameters& p)
{
  std::vector<std::uint8_t> splittable = splittable_pieces(adj, pieces.piece, pieces.number_of_pieces,
                                                           p.minimum_part_area * pieces.area, convexity_tolerance);
  const std::vector<double> junction = junction_length_fractions(adj, corners, pieces.piece, pieces.number_of_pieces);
  for(std::size_t q = 0; q < splittable.size(); ++q)
    splittable[q] = splittable[q] && junction[q] < maximum_junction_fraction;
  return splittable;
}

} // namespace internal
/// \endcond

/*!
\ingroup PkgPartDecompositionRef
returns, per piece of `pieces`, 1 if the volumetric stages may split it: it is not convex (an edge
is concave by at least one degree as the piece is oriented), its area is at least twice
`minimum_part_area` of the mesh area, and it is not an assembly of sheets: its non-manifold
junctions (edges of three faces or more) in chains at least 1/20 of the piece's bounding-box diagonal
long make up less than 0.1% of the length of its edges, so that a scan's scattered defective edges
do not count but the walls and shelves of a cabinet, glued along lines, do (the parts of an
assembly of sheets are its regions). The prior, the distance field, the fit and the
over-segmentation are worth computing only if one piece is splittable (or with `use_pieces = false`);
`volumetric_pieces()` then tells which of them the volumetric stages decompose.

\tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag`; the result is the same
\param tm the mesh
\param pieces the pieces of `tm`, as `segment_pieces()` returned them
\param np the named parameters `vertex_point_map`, `face_index_map`, `geom_traits`
(\ref PD_MeshParameters) and `minimum_part_area` (\ref PD_ParameterTable)
\throws Invalid_input (`INVALID_PARAMETER`) if a named parameter is out of its range.
*/
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename TriangleMesh,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
std::vector<std::uint8_t> splittable_pieces(const TriangleMesh& tm, const Piece_segmentation& pieces,
                                            const NamedParameters& np = CGAL::parameters::default_values())
{
  const internal::Mesh_maps<TriangleMesh, NamedParameters> maps(tm, np);
  const auto graph = internal::shared_piece_adjacency<ConcurrencyTag>(tm, maps.fim, maps.vpm, np);
  const internal::Face_adjacency& adj = *graph;
  return internal::splittable_solid_pieces(adj, internal::Face_corners(tm, maps.fim, maps.vpm, ConcurrencyTag()), pieces,
                                          internal::read_piece_parameters(np));
}

/*!
\ingroup PkgPartDecompositionRef
returns, per piece of `pieces`, 1 if the volumetric stages decompose it: it is splittable
(`splittable_pieces()`, which also tells an assembly of sheets) and it bounds a volume of the
distance field `tsdf`, closed or not: at least half of its area separates the field's inside from
its outside, probed one voxel away on both sides of each face (an open sheet has the outside on
both sides, a piece thinner than a voxel too, a wall inside a volume the inside on both); this
holds for a scan with holes and for each piece of a group that encloses space together. Where the
faces are much smaller than a voxel (see `assign_parts()`), each superface is probed once, at its
faces' area-weighted centroid along their mean normal.

An open piece that the volumetric stages decompose is turned in `pieces` to face out of the volume
(as the reader turns closed ones), and the regions are recomputed for that orientation: its
concave creases are then those of the solid.

\tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag`; the result is the same
\param tm the mesh
\param pieces the pieces of `tm`, as `segment_pieces()` returned them (with its `crease_angle`)
\param tsdf the distance field of `tm` (`compute_tsdf()`)
\param np the named parameters of `splittable_pieces()` and `crease_angle`
\throws Invalid_input (`INVALID_PARAMETER`) if a named parameter is out of its range.
*/
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename TriangleMesh,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
std::vector<std::uint8_t> volumetric_pieces(const TriangleMesh& tm, Piece_segmentation& pieces,
                                            const Truncated_signed_distance_field& tsdf,
                                            const NamedParameters& np = CGAL::parameters::default_values())
{
  const internal::Piece_parameters p = internal::read_piece_parameters(np);
  const internal::Mesh_maps<TriangleMesh, NamedParameters> maps(tm, np);
  const auto graph = internal::shared_piece_adjacency<ConcurrencyTag>(tm, maps.fim, maps.vpm, np);
  const internal::Face_adjacency& adj = *graph;
  const auto shared_corners = internal::shared_face_corners<ConcurrencyTag>(tm, maps.fim, maps.vpm, np);
  const internal::Face_corners& corners = *shared_corners;
  std::vector<std::uint8_t> volumetric = internal::splittable_solid_pieces(adj, corners, pieces, p);
  // the triangle of face i, in the unit frame of the field
  const auto triangle = [&](std::size_t i) {
    internal::Triangle_points t;
    for(int c = 0; c < 3; ++c)
      t[std::size_t(c)] = tsdf.normalization.to_unit(corners(i, c).x(), corners(i, c).y(), corners(i, c).z());
    return t;
  };
  const double depth = internal::bounding_probe_depth * tsdf.voxel_size;
  // superfaces of the graph without glued edges: they never cross a piece
  const auto superfaces = internal::shared_superfaces<ConcurrencyTag>(
    *internal::shared_face_adjacency<ConcurrencyTag>(tm, maps.fim, np),
    internal::superface_cell(tsdf.voxel_size, tsdf.normalization.scale()), np);
  const internal::Bounding_fractions sides = internal::piece_bounding_fractions<ConcurrencyTag>(
    *superfaces, num_faces(tm), triangle, pieces, tsdf.grid, tsdf.values, depth);
  bool reoriented = false;
  for(std::size_t q = 0; q < pieces.number_of_pieces; ++q)
  {
    volumetric[q] = volumetric[q] && sides.bounding[q] >= internal::minimum_bounding_fraction;
    const int outward = sides.outward[q] < 0. ? -1 : 1;
    if(volumetric[q] && !pieces.closed[q] && pieces.orientation[q] != outward)
    {
      pieces.orientation[q] = outward;
      reoriented = true;
    }
  }
  if(reoriented)
    pieces.number_of_regions =
      internal::crease_regions<ConcurrencyTag>(adj, pieces.piece, pieces.orientation, p.crease_angle, pieces.region);
  return volumetric;
}

/*!
\ingroup PkgPartDecompositionRef
keeps the residual patches of the assignment (paper Sec.\ 3.4) as parts of their own instead of
forcing them onto a primitive: the patches of `parts.patches` of which at least half of the area
lies in Freeze voxels of `prior` and whose faces are on average farther than `residual_tolerance`
voxels of the finest grid from the primitive of their part. Each edge-connected set of residual
faces becomes a part, appended with `no_primitive`; `parts.residual_faces` receives the residual
faces. `decompose()` calls it, between `assign_parts()` and `merge_thin_sheet_parts()`, when its
switch `keep_residual_patches` of `method_variant` is `true`.

\param tm the mesh
\param parts the patches, parts and primitives of `over_segment()` and `assign_parts()`
\param prior the prior of `tm`
\param fitting the primitives `assign_parts()` assigned
\param np the named parameters `vertex_point_map`, `face_index_map`, `geom_traits`
(\ref PD_MeshParameters) and `residual_tolerance` (\ref PD_ParameterTable)
\throws Invalid_input (`INVALID_PARAMETER`) if a named parameter is out of its range or `prior` and
`fitting` have different normalizations.
*/
template <typename TriangleMesh, typename GeomTraits,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
void separate_residual_patches(const TriangleMesh& tm, Volumetric_parts& parts, const Hierarchical_prior& prior,
                               const Superquadric_fitting_result<GeomTraits>& fitting,
                               const NamedParameters& np = CGAL::parameters::default_values())
{
  const double tolerance = internal::read_assignment_parameters(np).residual_tolerance;
  internal::check_parameter(internal::same_frame(prior.normalization, fitting.normalization),
                            "the normalization of the prior", "the one of the fitting (same center and scale)");
  const internal::Mesh_maps<TriangleMesh, NamedParameters> maps(tm, np);
  const auto graph = internal::shared_face_adjacency<CGAL::Sequential_tag>(tm, maps.fim, np);
  const internal::Face_adjacency& adj = *graph;
  const internal::Face_corners corners(tm, maps.fim, maps.vpm);
  const std::size_t number_of_patches =
    parts.patches.empty() ? 0 : *std::max_element(parts.patches.begin(), parts.patches.end()) + 1;
  parts.residual_faces = internal::residual_faces<GeomTraits>(
    adj, corners, parts.patches, number_of_patches, parts.parts, parts.part_to_primitive, fitting.primitives,
    prior.classes, fitting.normalization, tolerance / double(prior.classes.resolution()));
  internal::split_residual_parts<CGAL::Sequential_tag>(adj, parts.residual_faces, parts.parts, parts.part_to_primitive, no_primitive);
}

/*!
\ingroup PkgPartDecompositionRef
composes the parts of the volumetric stages with the pieces and regions of `segment_pieces()`: the
last step of the parts of `decompose()`, before the part hierarchy. This step is not in the paper.

With `use_pieces` (the default), the faces of a piece the volumetric stages decomposed
(`volumetric`) keep their volumetric part, moved to the region that holds most of it where it
crosses a concave crease, and are cut by the regions; the faces of any other piece take their
region. Where a volumetric part covers separate edge-connected stretches of a region, each stretch
whose boundary is concave on average by at least 0.15 (an edge counting
\f$\min(1, \theta / 60^\circ)\f$ if concave with dihedral angle \f$\theta\f$, 0 if convex,
weighted by length) is a part of its own, and the others stay with the largest: a limb ends at a
concave root, a stray claim does not. Parts smaller than `minimum_part_area` of the mesh area are
merged into the neighbour across their weakest shared edge. With `use_pieces = false`, the parts are those of `parts`.

Each part keeps the primitive of the volumetric part that covers most of it, and gets its
superquadric (see `Composed_parts::part_primitives`).

\tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag`; the result is the same
\param tm the mesh
\param pieces the pieces of `tm`, after `volumetric_pieces()` if it was called (ignored with
`use_pieces = false`)
\param volumetric per piece, 1 if the volumetric stages decomposed it (`volumetric_pieces()`);
ignored if `parts.parts` is empty
\param parts the parts of the volumetric stages; `parts.parts` is empty if they did not run
\param fitting the primitives of `parts.part_to_primitive` (unused if `parts.parts` is empty)
\param np the named parameters `vertex_point_map`, `face_index_map`, `geom_traits`
(\ref PD_MeshParameters), `minimum_part_area` and `method_variant` (its switch `use_pieces`)
(\ref PD_ParameterTable)
\throws Invalid_input (`INVALID_PARAMETER`) if a named parameter is out of its range, if a vector
of `parts` or `pieces` indexed by face does not have one value per face, if `volumetric` does not
have one flag per piece while `parts.parts` is not empty, or if `parts.parts` is empty with
`use_pieces = false`.
*/
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename TriangleMesh, typename GeomTraits,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Composed_parts<GeomTraits> compose_parts(const TriangleMesh& tm, const Piece_segmentation& pieces,
                                         const std::vector<std::uint8_t>& volumetric, const Volumetric_parts& parts,
                                         const Superquadric_fitting_result<GeomTraits>& fitting,
                                         const NamedParameters& np = CGAL::parameters::default_values())
{
  const internal::Piece_parameters p = internal::read_piece_parameters(np);
  const internal::Mesh_maps<TriangleMesh, NamedParameters> maps(tm, np);
  const bool has_volume = !parts.parts.empty();
  const std::size_t nf = num_faces(tm);
  internal::check_parameter(parts.parts.empty() || parts.parts.size() == nf, "parts.parts", "one part per face");
  internal::check_parameter(!p.use_pieces || (pieces.piece.size() == nf && pieces.region.size() == nf), "pieces",
                            "the pieces of the mesh, with use_pieces");
  internal::check_parameter(!p.use_pieces || !has_volume || volumetric.size() == pieces.number_of_pieces,
                            "volumetric", "one flag per piece, with parts of the volumetric stages");
  internal::check_parameter(p.use_pieces || has_volume, "parts.parts", "the parts of assign_parts() with use_pieces(false)");
  Composed_parts<GeomTraits> c;
  std::vector<std::size_t> volume_part;
  std::vector<double> face_area;
  if(p.use_pieces)
  {
    const auto graph = internal::shared_piece_adjacency<ConcurrencyTag>(tm, maps.fim, maps.vpm, np);
    const internal::Face_adjacency& adj = *graph;
    if(has_volume)
    {
      volume_part = parts.parts;
      for(std::size_t i = 0; i < volume_part.size(); ++i)
        if(!volumetric[pieces.piece[i]]) volume_part[i] = no_primitive;
      internal::keep_volume_parts_in_their_regions(adj, pieces.region, volume_part, no_primitive);
    }
    const std::vector<std::size_t> source =
      internal::compose_parts<ConcurrencyTag>(adj, *internal::shared_face_corners<ConcurrencyTag>(tm, maps.fim, maps.vpm, np), pieces.region, pieces.piece,
                              pieces.orientation, volume_part, p.minimum_part_area * pieces.area, c.parts, no_primitive);
    c.part_to_primitive.assign(source.size(), no_primitive);
    for(std::size_t k = 0; k < source.size(); ++k)
      if(source[k] != no_primitive) c.part_to_primitive[k] = parts.part_to_primitive[source[k]];
    face_area = adj.area;
  }
  else
  {
    // residual patches are appended parts: renumber as the composed parts are documented
    c.parts = parts.parts;
    std::vector<std::size_t> former;
    internal::renumber_by_first_face(c.parts, &former);
    for(std::size_t k : former) c.part_to_primitive.push_back(parts.part_to_primitive[k]);
    face_area = internal::shared_face_adjacency<ConcurrencyTag>(tm, maps.fim, np)->area;
  }
  c.part_primitives =
    internal::part_primitives<ConcurrencyTag, GeomTraits>(tm, maps.fim, *internal::shared_face_corners<ConcurrencyTag>(tm, maps.fim, maps.vpm, np),
                                                          c.parts, c.part_to_primitive, fitting.input_primitives);
  c.residual_parts = internal::residual_part_flags(face_area, c.parts, c.number_of_parts(), parts.residual_faces);
  const bool patches = has_volume && !parts.patches.empty();
  internal::finest_parts<ConcurrencyTag>(volume_part, p.use_pieces ? pieces.region : std::vector<std::size_t>(), [&](std::size_t i) {
    return patches && (!p.use_pieces || volumetric[pieces.piece[i]]) ? parts.patches[i] : std::size_t(0);
  }, c);
  return c;
}

/*!
\ingroup PkgPartDecompositionRef
builds the part hierarchy of the composed parts `parts` with the merge order of
`build_part_hierarchy(tm, face_part_map, np)`. Its leaves are `parts.finest_parts`; the merges
inside a part come first, so that the composed parts are a level of the tree (level
`parts.number_of_parts()`), each with its superquadric, while the other nodes get their box-like
superquadric. `decompose()` goes on from that level with `Part_hierarchy::level_below_cost()`
(named parameter `maximum_merge_cost`), from which cost on the merges are ordered by size first.

\tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag`; the result is the same
\param tm the mesh
\param pieces the pieces given to `compose_parts()` (ignored with `use_pieces = false`)
\param parts the result of `compose_parts()`
\param np the named parameters `vertex_point_map`, `face_index_map`, `geom_traits`
(\ref PD_MeshParameters) and `method_variant` given to `compose_parts()`, and `maximum_merge_cost`
(\ref PD_ParameterTable; see `build_part_hierarchy(tm, face_part_map, np)`)
*/
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename TriangleMesh, typename GeomTraits,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Part_hierarchy<GeomTraits> build_part_hierarchy(const TriangleMesh& tm, const Piece_segmentation& pieces,
                                                const Composed_parts<GeomTraits>& parts,
                                                const NamedParameters& np = CGAL::parameters::default_values())
{
  const internal::Mesh_maps<TriangleMesh, NamedParameters> maps(tm, np);
  const auto shared_corners = internal::shared_face_corners<ConcurrencyTag>(tm, maps.fim, maps.vpm, np);
  const internal::Face_corners& corners = *shared_corners;
  const double maximum_merge_cost = internal::read_hierarchy_parameters(np).maximum_merge_cost;
  if(internal::read_piece_parameters(np).use_pieces)
    return internal::hierarchy_of_leaves<ConcurrencyTag, GeomTraits>(
      *internal::shared_piece_adjacency<ConcurrencyTag>(tm, maps.fim, maps.vpm, np), corners, parts.finest_parts,
      parts.number_of_finest_parts, parts.part_groups, parts.parts, parts.part_primitives, pieces.piece,
      pieces.orientation, maximum_merge_cost);
  const auto graph = internal::shared_face_adjacency<ConcurrencyTag>(tm, maps.fim, np);
  const internal::Face_adjacency& adj = *graph;
  std::vector<std::size_t> piece;
  const std::vector<int> orientation(internal::label_pieces<ConcurrencyTag>(adj, piece), 1);
  return internal::hierarchy_of_leaves<ConcurrencyTag, GeomTraits>(adj, corners, parts.finest_parts, parts.number_of_finest_parts,
                                                   parts.part_groups, parts.parts, parts.part_primitives, piece,
                                                   orientation, maximum_merge_cost);
}

} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_PART_COMPOSITION_H
