// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_DECOMPOSE_H
#define CGAL_PART_DECOMPOSITION_DECOMPOSE_H

#include <CGAL/Part_decomposition/Superquadric.h>
#include <CGAL/Part_decomposition/fitting_zones.h>
#include <CGAL/Part_decomposition/flow_freeze_prior.h>
#include <CGAL/Part_decomposition/input_validation.h>
#include <CGAL/Part_decomposition/normalization.h>
#include <CGAL/Part_decomposition/over_segmentation.h>
#include <CGAL/Part_decomposition/part_hierarchy.h>
#include <CGAL/Part_decomposition/parameters.h>
#include <CGAL/Part_decomposition/piece_segmentation.h>
#include <CGAL/Part_decomposition/primitive_assignment.h>
#include <CGAL/Part_decomposition/superquadric_fitting.h>
#include <CGAL/Part_decomposition/thin_sheet_merging.h>
#include <CGAL/Part_decomposition/tsdf.h>
#include <CGAL/Part_decomposition/internal/bounded_volume.h>
#include <CGAL/Part_decomposition/internal/face_adjacency.h>
#include <CGAL/Part_decomposition/internal/parameter_checks.h>
#include <CGAL/Part_decomposition/internal/residual_patches.h>
#include <CGAL/Part_decomposition/internal/toolbox.h>

#include <CGAL/Default.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

#include <Eigen/Dense>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Part_decomposition {

/*!
\ingroup PkgPartDecompositionRef
Wall-clock seconds spent in each stage of `decompose()`.
*/
struct Stage_timings
{
  double pieces = 0.;            ///< pieces and their regions between concave creases
  double prior = 0.;             ///< geometric cues, topology scores and Flow/Freeze fusion
  double tsdf = 0.;              ///< truncated signed distance field
  double fitting = 0.;           ///< fitting zones and superquadric fitting
  double fitting_zones = 0.;     ///< of which the fitting zones
  double over_segmentation = 0.; ///< curvature-aware over-segmentation
  double assignment = 0.;        ///< superquadric-to-mesh assignment and primitive output
  double hierarchy = 0.;         ///< the part hierarchy and its cut (0 if it was not built)
  double thin_parts = 0.;        ///< the finer pass of `thin_part_resolution` and its thin parts (0 without it)
  double total = 0.;             ///< the whole call, input checks included
  /// whether some stages ran at the same time (parallel `decompose()`): then the stage times
  /// overlap and their sum exceeds `total`.
  bool overlapping = false;
};

namespace internal {

// A piece bounds a volume of the distance field if at least this fraction of its area separates
// the field's inside from its outside, probed at this depth, in voxels of the field, on both sides
// of each face: an open sheet has the outside on both sides, a piece thinner than a voxel too.
constexpr double bounding_probe_depth = 1.;
constexpr double minimum_bounding_fraction = 0.5;
// A piece whose non-manifold junctions (edges of three faces or more) make up at least this
// fraction of the length of its edges is an assembly of sheets (walls and shelves glued along
// lines), whose parts are its sheets; a scan's few non-manifold edges make up far less. The CAD-style
// set gives the same parts from 0.0003 to 0.01 (benchmark/Part_decomposition/RESULTS.md).
constexpr double maximum_junction_fraction = 0.001;

// The box-like superquadric of the principal-axis bounding box of a surface given as triangles
// (`points` holds three corners per triangle): what a part gets when no primitive was fitted to
// it (a flat sheet has no volume to fit). The axes are those of the surface's second moments, so
// that a plate of two large triangles gets the axes of its rectangle, not of its diagonal.
template <typename GeomTraits>
Superquadric<GeomTraits> bounding_superquadric(const std::vector<std::array<double, 3> >& points)
{
  CGAL_precondition(points.size() % 3 == 0);
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

// Reads (and so checks) the parameters of every stage, also of those a mesh may not need: a
// parameter out of its range is an error whatever the mesh.
template <typename NamedParameters>
void check_stage_parameters(const NamedParameters& np)
{
  read_prior_parameters(np);
  read_tsdf_parameters(np);
  read_fitting_zone_parameters(np);
  read_fitting_parameters(np);
  read_over_segmentation_parameters(np);
  read_assignment_parameters(np);
  read_sheet_merging_parameters(np);
  read_piece_parameters(np);
  read_hierarchy_parameters(np);
}

} // namespace internal

/*!
\ingroup PkgPartDecompositionRef
The Hi-TOPS part decomposition of a triangle mesh, stage by stage (paper Algorithm A.1):
`segment_pieces()`, `compute_prior()`, `compute_distance_field()`, `fit_primitives()`,
`over_segment()` and `assign_parts()` (which ends with the thin-sheet merge, `merge_thin_sheets()`,
and the composition with the pieces), in this order, each keeping its result for inspection.
`decompose()` runs them all in one call. The volumetric stages (prior to over-segmentation) may be
left out when `needs_volumetric_stages()` is `false`.
`compute_fitting_zones()`, between the distance field and the fit, is optional: it lets the
zones of the fitter be inspected.

Every stage function takes its own named parameters (those of the function it calls, listed in
its documentation); the mesh, vertex point map, face index map and normalization of the
decomposer are added to them. A `normalization` or `normalization_margin` given to a stage must be
the decomposer's.

\tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
\tparam GeomTraits a model of `PartDecompositionTraits`; `CGAL::Default` means the kernel of the
points of `VertexPointMap`
\tparam VertexPointMap a model of `ReadablePropertyMap` with
`boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `GeomTraits::Point_3` as
value type; `CGAL::Default` means the internal vertex point map of `TriangleMesh`
\tparam FaceIndexMap a model of `ReadablePropertyMap` with
`boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and `std::size_t` as value type,
a bijection onto `[0, num_faces(tm))`; `CGAL::Default` means the (initialized) internal face index
map of `TriangleMesh`
*/
template <typename TriangleMesh, typename GeomTraits_ = CGAL::Default, typename VertexPointMap_ = CGAL::Default,
          typename FaceIndexMap_ = CGAL::Default>
class Part_decomposer
{
public:
  /// \name Types
  /// @{

  /// the vertex point map
  typedef typename CGAL::Default::Get<
    VertexPointMap_, typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>::type
    Vertex_point_map;
  /// the face index map
  typedef typename CGAL::Default::Get<
    FaceIndexMap_, typename GetInitializedFaceIndexMap<TriangleMesh>::const_type>::type
    Face_index_map;
  /// the geometric traits
  typedef typename CGAL::Default::Get<
    GeomTraits_, typename CGAL::Kernel_traits<typename boost::property_traits<Vertex_point_map>::value_type>::Kernel>::type
    Geom_traits;
  /// the superquadric type
  typedef Superquadric<Geom_traits> Primitive;
  /// @}

  /// \name Creation
  /// @{
  /*!
  prepares the decomposition of `tm`, with its internal vertex point map and face index map and
  the default normalization margin: checks the input and computes its normalization.
  \param tm the mesh; it must outlive the decomposer and stay unchanged
  \throws Invalid_input if `tm` cannot be decomposed (see `check_input()`).
  */
  explicit Part_decomposer(const TriangleMesh& tm)
    : Part_decomposer(tm, get_const_property_map(CGAL::vertex_point, tm))
  {}

  /*!
  prepares the decomposition of `tm` with its internal face index map: checks the input and
  computes its normalization.
  \param tm the mesh; it must outlive the decomposer and stay unchanged
  \param vpm the vertex point map
  \param margin the free margin of the normalization (see `compute_normalization()`)
  \throws Invalid_input if `tm` cannot be decomposed (see `check_input()`).
  */
  Part_decomposer(const TriangleMesh& tm, Vertex_point_map vpm, double margin = defaults::normalization_margin)
    : Part_decomposer(tm, vpm, CGAL::get_initialized_face_index_map(tm), margin)
  {}

  /*!
  prepares the decomposition of `tm`: checks the input and computes its normalization.
  \param tm the mesh; it must outlive the decomposer and stay unchanged
  \param vpm the vertex point map
  \param fim the face index map; every stage indexes the faces with it
  \param margin the free margin of the normalization (see `compute_normalization()`)
  \throws Invalid_input if `tm` cannot be decomposed (see `check_input()`).
  */
  Part_decomposer(const TriangleMesh& tm, Vertex_point_map vpm, Face_index_map fim,
                  double margin = defaults::normalization_margin)
    : m_tm(tm), m_vpm(vpm), m_fim(fim), m_margin(margin)
  {
    check_input(tm, CGAL::parameters::vertex_point_map(m_vpm).face_index_map(m_fim));
    m_normalization = compute_normalization(
      tm, parameters::combine(CGAL::parameters::vertex_point_map(m_vpm), parameters::normalization_margin(margin)));
  }
  /// @}

  /// \name Stages
  /// @{

  /*!
  splits the mesh into its pieces and their regions between concave creases with
  `Part_decomposition::segment_pieces()` (its named parameters, and `minimum_part_area`).
  `assign_parts()` calls it if it was not called, unless `use_pieces(false)` is given; afterwards
  `needs_volumetric_stages()` tells whether the other stages are needed.
  */
  template <typename ConcurrencyTag = CGAL::Sequential_tag,
            typename NamedParameters = CGAL::parameters::Default_named_parameters>
  const Piece_segmentation& segment_pieces(const NamedParameters& np = CGAL::parameters::default_values())
  {
    m_piece_adjacency = internal::piece_adjacency<ConcurrencyTag>(m_tm, m_fim, m_vpm, with_mesh(np));
    const internal::Piece_parameters p = internal::read_piece_parameters(np);
    m_pieces = internal::segment_pieces_of_graph(m_piece_adjacency, p);
    m_crease_angle = p.crease_angle;
    m_splittable_piece = internal::splittable_pieces(m_piece_adjacency, m_pieces.piece, m_pieces.number_of_pieces,
                                                     p.minimum_part_area * m_pieces.area,
                                                     internal::convexity_tolerance);
    m_has_pieces = true;
    mark_volumetric_pieces();
    return m_pieces;
  }

  /// whether `assign_parts()` with the named parameters `np` needs the volumetric stages (prior,
  /// distance field, fit, over-segmentation): with `use_pieces(false)`, or if a piece can hold
  /// several parts of which its surface does not show the boundaries. Such a piece is not convex
  /// (an edge is concave by at least one degree as the mesh is oriented), has at
  /// least twice `minimum_part_area`, and, once `compute_distance_field()` was called, bounds a
  /// volume of the distance field, closed or not:
  /// - at least half of its area separates the field's inside from its outside, probed one voxel
  ///   away on both sides of each face (an open sheet has the outside on both sides, a piece
  ///   thinner than a voxel too, a wall inside a volume the inside on both); this holds for a scan
  ///   with holes and for each piece of a group that encloses space together;
  /// - it is not an assembly of sheets: its non-manifold junctions (edges of three faces or more)
  ///   make up less than 0.1% of the length of its edges, so that a few defective edges do not
  ///   count but the walls and shelves of a cabinet do; the parts of an assembly of sheets are its
  ///   regions.
  ///
  /// The volumetric parts are used in such pieces only. Before the distance field is known, this
  /// function tells whether it is worth computing.
  /// \pre `segment_pieces()` was called, or `use_pieces(false)` is given.
  template <typename NamedParameters = CGAL::parameters::Default_named_parameters>
  bool needs_volumetric_stages(const NamedParameters& np = CGAL::parameters::default_values()) const
  {
    if(!internal::read_piece_parameters(np).use_pieces || !m_has_pieces) return true;
    for(std::uint8_t v : m_volumetric_piece)
      if(v) return true;
    return false;
  }

  /// computes the hierarchical Flow/Freeze prior with `compute_flow_freeze_prior()`.
  template <typename ConcurrencyTag = CGAL::Sequential_tag,
            typename NamedParameters = CGAL::parameters::Default_named_parameters>
  const Hierarchical_prior& compute_prior(const NamedParameters& np = CGAL::parameters::default_values())
  {
    m_prior = compute_flow_freeze_prior<ConcurrencyTag>(m_tm, with_mesh(np));
    m_has_prior = true;
    m_has_zones = false;
    return m_prior;
  }

  /// computes the zones of the fitter from the prior and the distance field with
  /// `compute_fitting_zones()` at the `fitting_resolutions()` of the prior with the
  /// `fitting_resolution_cap` of `np`; `fit_primitives()` uses them (it computes them itself if
  /// this function was not called after `compute_prior()` and `compute_distance_field()`). Pass the
  /// same `flow_zone_tolerance`, `use_freeze_zone` and `fitting_resolution_cap` as to
  /// `fit_primitives()`.
  /// \pre `compute_prior()` and `compute_distance_field()` were called.
  template <typename ConcurrencyTag = CGAL::Sequential_tag,
            typename NamedParameters = CGAL::parameters::Default_named_parameters>
  const Fitting_zones& compute_fitting_zones(const NamedParameters& np = CGAL::parameters::default_values())
  {
    CGAL_precondition(m_has_prior && m_has_tsdf);
    if(!m_has_prior || !m_has_tsdf)
      throw std::logic_error("Part_decomposer::compute_fitting_zones() needs the prior and the distance field");
    const int cap = internal::read_fitting_parameters(np).fitting_resolution_cap;
    m_zones = Part_decomposition::compute_fitting_zones<ConcurrencyTag>(
      m_prior.classes, m_tsdf, fitting_resolutions(m_prior.resolutions, cap), np);
    m_has_zones = true;
    return m_zones;
  }

  /// computes the truncated signed distance field with `compute_tsdf()`, on the finest grid of
  /// the prior's resolutions (pass the same `voxel_resolutions` as to `compute_prior()`).
  template <typename ConcurrencyTag = CGAL::Sequential_tag,
            typename NamedParameters = CGAL::parameters::Default_named_parameters>
  const Truncated_signed_distance_field& compute_distance_field(const NamedParameters& np = CGAL::parameters::default_values())
  {
    m_tsdf = internal::compute_tsdf_of_checked_mesh<ConcurrencyTag>(m_tm, with_mesh(np));
    m_has_tsdf = true;
    m_has_zones = false;
    if(m_has_pieces) mark_volumetric_pieces();
    return m_tsdf;
  }

  /// fits the superquadrics with `fit_superquadrics()`.
  /// \pre `compute_prior()` and `compute_distance_field()` were called.
  /// \throws Invalid_input (`INVALID_PARAMETER`) if the prior and the distance field have different
  /// resolutions or normalizations.
  template <typename ConcurrencyTag = CGAL::Sequential_tag,
            typename NamedParameters = CGAL::parameters::Default_named_parameters>
  const Superquadric_fitting_result<Geom_traits>& fit_primitives(const NamedParameters& np = CGAL::parameters::default_values())
  {
    CGAL_precondition(m_has_prior && m_has_tsdf);
    if(!m_has_prior || !m_has_tsdf)
      throw std::logic_error("Part_decomposer::fit_primitives() needs the prior and the distance field");
    internal::check_parameter(m_tsdf.values.resolution() == m_prior.classes.resolution(),
                              "the resolution of the distance field", "the finest resolution of the prior");
    check_frame(m_prior.normalization, "the normalization of the prior");
    check_frame(m_tsdf.normalization, "the normalization of the distance field");
    check_frame_parameters(np);
    m_fitting = m_has_zones ? fit_superquadrics<ConcurrencyTag, Geom_traits>(m_prior, m_tsdf, m_zones, np)
                            : fit_superquadrics<ConcurrencyTag, Geom_traits>(m_prior, m_tsdf, np);
    m_has_fitting = true;
    return m_fitting;
  }

  /// computes the curvature-aware over-segmentation with `Part_decomposition::over_segment()`
  /// and returns the number of patches; its face graph and dihedral angles are kept for
  /// `merge_thin_sheets()`.
  template <typename ConcurrencyTag = CGAL::Sequential_tag,
            typename NamedParameters = CGAL::parameters::Default_named_parameters>
  std::size_t over_segment(const NamedParameters& np = CGAL::parameters::default_values())
  {
    m_number_of_patches =
      internal::over_segment_labels<ConcurrencyTag>(m_tm, m_fim, m_patches, with_mesh(np), nullptr, &m_adjacency);
    m_has_patches = true;
    return m_number_of_patches;
  }

  /*!
  assigns every patch to a primitive with `Part_decomposition::assign_parts()`, merges the thin
  sheets with `merge_thin_sheets()` unless the named parameter `merge_thin_sheets` is `false` (see
  `decompose()`), composes these parts with the pieces and regions of `segment_pieces()` (calling
  it if needed) unless `use_pieces` is `false`, writes the part id (0 to `K-1`) of every face to
  `face_part_map`, once, and returns `K`. Part `k` is explained by `part_primitives()[k]`; its
  fitted primitive, if any, is `part_to_primitive()[k]` (else `no_primitive`).
  \tparam FacePartMap a model of `WritablePropertyMap` with
  `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and `std::size_t` as value type
  \pre `fit_primitives()` and `over_segment()` were called, unless `needs_volumetric_stages(np)`
  is `false`.
  */
  template <typename ConcurrencyTag = CGAL::Sequential_tag, typename FacePartMap,
            typename NamedParameters = CGAL::parameters::Default_named_parameters>
  std::size_t assign_parts(FacePartMap face_part_map, const NamedParameters& np = CGAL::parameters::default_values())
  {
    const internal::Piece_parameters pieces = internal::read_piece_parameters(np);
    if(pieces.use_pieces && !m_has_pieces) segment_pieces<ConcurrencyTag>(np);
    const bool volumetric = needs_volumetric_stages(np);
    CGAL_precondition(!volumetric || (m_has_fitting && m_has_patches));
    if(volumetric && (!m_has_fitting || !m_has_patches))
      throw std::logic_error("Part_decomposer::assign_parts() needs the primitives and the patches");
    check_frame_parameters(np);
    // new parts: the residual faces and the hierarchy of an earlier call no longer hold
    m_residual_face.clear();
    m_has_hierarchy = false;
    if(volumetric)
    {
      check_frame(m_fitting.normalization, "the normalization of the fitting");
      const internal::Assignment_parameters ap = internal::read_assignment_parameters(np);
      m_part_to_primitive = internal::assign_patches_to_primitives<ConcurrencyTag>(
        m_tm, m_fim, m_vpm, m_patches, m_fitting.labels, m_normalization, ap, m_adjacency, m_parts);
      if(ap.keep_residual_patches && m_has_prior) keep_residual_patches(ap.residual_tolerance);
      m_has_parts = true;
      if(internal::read_sheet_merging_parameters(np).merge_thin_sheets)
        merge_thin_sheet_parts<ConcurrencyTag>();
    }
    m_has_parts = true;
    if(pieces.use_pieces) compose_with_pieces(volumetric, pieces.minimum_part_area);
    else make_part_primitives();
    mark_residual_parts();
    internal::put_face_values(m_tm, m_fim, m_parts, face_part_map);
    return m_part_to_primitive.size();
  }

  /*!
  merges the parts that tile one thin sheet with `merge_thin_sheet_parts()`, on the face graph and
  dihedral angles of the over-segmentation, and returns the new number of parts. `assign_parts()`
  calls it unless `merge_thin_sheets(false)` is given; call it after such an `assign_parts()` to
  compare `parts()` before and after.
  \tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag` (for the depth of the
  claimed voxels); the result is the same
  \pre `assign_parts()` was called.
  */
  template <typename ConcurrencyTag = CGAL::Sequential_tag>
  std::size_t merge_thin_sheets()
  {
    CGAL_precondition(m_has_parts);
    if(!m_has_parts)
      throw std::logic_error("Part_decomposer::merge_thin_sheets() needs the parts");
    merge_thin_sheet_parts<ConcurrencyTag>();
    make_part_primitives();
    mark_residual_parts(); // the parts were renumbered
    m_has_hierarchy = false;
    return m_part_to_primitive.size();
  }

  /*!
  builds the part hierarchy of the parts of `assign_parts()` with `build_part_hierarchy()`'s merge
  order and returns it. Its leaves are the finest parts: the parts of `assign_parts()` cut by the
  regions of `segment_pieces()` (before small parts were merged) and, in the pieces the volumetric
  stages decomposed, by the patches of `over_segment()`. The merges inside a part come first, so
  that the parts of `assign_parts()` are a level of the tree (level `part_primitives().size()`, its
  `default_number_of_parts`), with their primitives; the other nodes get their box-like
  superquadric. `decompose()` goes on from that level with `Part_hierarchy::level_below_cost()`
  (named parameter `maximum_merge_cost`), from which merges are ordered by size first.
  \pre `assign_parts()` was called.
  */
  const Part_hierarchy<Geom_traits>& build_hierarchy(double maximum_merge_cost = defaults::maximum_merge_cost)
  {
    CGAL_precondition(m_has_parts);
    if(!m_has_parts)
      throw std::logic_error("Part_decomposer::build_hierarchy() needs the parts");
    const internal::Face_adjacency& adj = m_has_pieces ? m_piece_adjacency : m_adjacency;
    std::vector<std::size_t> piece;
    std::vector<int> orientation;
    if(m_has_pieces) { piece = m_pieces.piece; orientation = m_pieces.orientation; }
    else orientation.assign(internal::label_pieces(adj, piece), 1);
    // leaves: (part, volumetric part, region, patch); subgroups: (part, volumetric part)
    const std::size_t nf = m_parts.size();
    std::vector<std::array<std::size_t, 4> > key(nf);
    for(std::size_t i = 0; i < nf; ++i)
    {
      const bool patch = m_has_patches && (!m_has_pieces || m_volumetric_piece[piece[i]]);
      key[i] = {{m_parts[i], m_volume_part.empty() ? 0 : m_volume_part[i], m_has_pieces ? m_pieces.region[i] : 0,
                 patch ? m_patches[i] : 0}};
    }
    std::vector<std::size_t> leaf, subgroup;
    internal::index_of_keys(key, leaf);
    const std::size_t number_of_leaves = internal::renumber_by_first_face(leaf); // the finest level's numbering
    for(auto& k : key) k[2] = k[3] = 0;
    internal::index_of_keys(key, subgroup);
    const internal::Face_corners corners(m_tm, m_fim, m_vpm);
    m_hierarchy = internal::hierarchy_of_leaves<Geom_traits>(adj, corners, leaf, number_of_leaves, subgroup, m_parts,
                                                             m_part_primitives, piece, orientation, maximum_merge_cost);
    m_has_hierarchy = true;
    return m_hierarchy;
  }

  /*!
  writes the parts of level `k` of the hierarchy to `face_part_map` (ids `0` to `k - 1`, numbered
  by smallest face index), their superquadrics to `primitives` in the same order, and returns `k`.
  A `k` above the number of leaves is clamped to it: the finest level.
  \tparam FacePartMap a model of `WritablePropertyMap` with
  `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and `std::size_t` as value type
  \tparam OutputIterator a model of `OutputIterator` accepting `Superquadric<Geom_traits>`
  \pre `build_hierarchy()` was called.
  \throws Invalid_input (`INVALID_PARAMETER`) if `k` is 0.
  */
  template <typename FacePartMap, typename OutputIterator = CGAL::Emptyset_iterator>
  std::size_t parts_at_level(std::size_t k, FacePartMap face_part_map,
                             OutputIterator primitives = OutputIterator()) const
  {
    CGAL_precondition(m_has_hierarchy);
    if(!m_has_hierarchy)
      throw std::logic_error("Part_decomposer::parts_at_level() needs the hierarchy");
    internal::check_parameter(k >= 1, "number_of_parts");
    k = (std::min)(k, m_hierarchy.number_of_leaves());
    internal::put_face_values(m_tm, m_fim, m_hierarchy.labels(k), face_part_map);
    for(std::size_t n : m_hierarchy.level(k)) *primitives++ = m_hierarchy.nodes[n].primitive;
    return k;
  }
  /// @}

  /// \name Results
  /// @{

  /// the pieces and their regions; once `compute_distance_field()` was called, an open piece that
  /// bounds a volume faces out of it, and its regions are those of that orientation.
  /// \pre `segment_pieces()` was called.
  const Piece_segmentation& pieces() const { return m_pieces; }
  /// the normalization of the mesh into the cube of the grids.
  const Normalization& normalization() const { return m_normalization; }
  /// the face index map that indexes `patches()` and `parts()`.
  const Face_index_map& face_index_map() const { return m_fim; }
  /// the prior. \pre `compute_prior()` was called.
  const Hierarchical_prior& prior() const { return m_prior; }
  /// the zones of the fitter. \pre `compute_fitting_zones()` was called.
  const Fitting_zones& fitting_zones() const { return m_zones; }
  /// the distance field. \pre `compute_distance_field()` was called.
  const Truncated_signed_distance_field& distance_field() const { return m_tsdf; }
  /// the fitted primitives and claimed voxels. \pre `fit_primitives()` was called.
  const Superquadric_fitting_result<Geom_traits>& fitting() const { return m_fitting; }
  /// the patch of each face, indexed by the face index map. \pre `over_segment()` was called.
  const std::vector<std::size_t>& patches() const { return m_patches; }
  /// the part of each face, indexed by the face index map. \pre `assign_parts()` was called.
  const std::vector<std::size_t>& parts() const { return m_parts; }
  /// for each part, the index in `fitting().primitives` of its primitive, or `no_primitive`
  /// when no primitive was fitted to it. \pre `assign_parts()` was called.
  const std::vector<std::size_t>& part_to_primitive() const { return m_part_to_primitive; }
  /// for each part, its superquadric in input coordinates: its fitted primitive if no other part
  /// has the same one and it lies on average as close to the part's vertices, else (and for a
  /// part without one) the box-like superquadric of its principal-axis bounding box.
  /// \pre `assign_parts()` was called.
  const std::vector<Primitive>& part_primitives() const { return m_part_primitives; }
  /// per part, 1 if it is a residual part: surface details that no primitive explains (see the
  /// named parameter `keep_residual_patches` of `decompose()`), whose superquadric is only the
  /// box-like superquadric of its principal-axis bounding box. \pre `assign_parts()` was called.
  const std::vector<std::uint8_t>& residual_parts() const { return m_residual_parts; }
  /// the part hierarchy. \pre `build_hierarchy()` was called.
  const Part_hierarchy<Geom_traits>& hierarchy() const { return m_hierarchy; }
  /// @}

private:
  // the stage's parameters with the decomposer's mesh maps and normalization
  template <typename NamedParameters>
  auto with_mesh(const NamedParameters& np) const
  {
    check_frame_parameters(np);
    return parameters::combine(np, CGAL::parameters::vertex_point_map(m_vpm), CGAL::parameters::face_index_map(m_fim),
                               parameters::normalization(m_normalization));
  }

  // A normalization computed in another frame than the decomposer's: its grids would not match.
  void check_frame(const Normalization& n, const char* what) const
  {
    internal::check_parameter(internal::same_frame(n, m_normalization), what,
                              "the decomposer's (same center and scale)");
  }

  // A normalization or margin given to one stage would put its grids in another frame.
  template <typename NamedParameters>
  void check_frame_parameters(const NamedParameters& np) const
  {
    using CGAL::parameters::choose_parameter;
    using CGAL::parameters::get_parameter;
    check_frame(choose_parameter(get_parameter(np, internal_np::normalization), m_normalization), "normalization");
    internal::check_parameter(choose_parameter(get_parameter(np, internal_np::normalization_margin), m_margin) == m_margin,
                              "normalization_margin", "the decomposer's (given to its constructor)");
  }

  // The pieces the volumetric stages decompose: the splittable pieces, and once the distance field
  // is known, those of them that bound a volume of it and are not assemblies of sheets.
  void mark_volumetric_pieces()
  {
    m_volumetric_piece = m_splittable_piece;
    if(!m_has_tsdf) return;
    const internal::Face_corners corners(m_tm, m_fim, m_vpm);
    // the triangles by face index, in the unit frame of the field
    std::vector<internal::Triangle_points> triangles(num_faces(m_tm));
    for(std::size_t i = 0; i < triangles.size(); ++i)
      for(int c = 0; c < 3; ++c)
        triangles[i][std::size_t(c)] = m_normalization.to_unit(corners(i, c).x(), corners(i, c).y(), corners(i, c).z());
    const double depth = internal::bounding_probe_depth / double(m_tsdf.values.resolution());
    const internal::Bounding_fractions sides = internal::bounding_area_fractions(
      triangles, m_pieces.piece, m_pieces.number_of_pieces, m_tsdf.values, depth);
    const std::vector<double> junction =
      internal::junction_length_fractions(m_piece_adjacency, corners, m_pieces.piece, m_pieces.number_of_pieces);
    bool reoriented = false;
    for(std::size_t p = 0; p < m_pieces.number_of_pieces; ++p)
    {
      m_volumetric_piece[p] = m_splittable_piece[p] && sides.bounding[p] >= internal::minimum_bounding_fraction &&
                              junction[p] < internal::maximum_junction_fraction;
      // an open piece that bounds a volume faces out of it, as the reader turns closed ones: its
      // concave creases are those of the solid
      const int outward = sides.outward[p] < 0. ? -1 : 1;
      if(m_volumetric_piece[p] && !m_pieces.closed[p] && m_pieces.orientation[p] != outward)
      {
        m_pieces.orientation[p] = outward;
        reoriented = true;
      }
    }
    if(reoriented)
      m_pieces.number_of_regions = internal::crease_regions(m_piece_adjacency, m_pieces.piece, m_pieces.orientation,
                                                            m_crease_angle, m_pieces.region);
  }

  // The patches no primitive explains (`internal::residual_faces()`) become parts of their own.
  void keep_residual_patches(double tolerance_in_voxels)
  {
    const internal::Face_corners corners(m_tm, m_fim, m_vpm);
    m_residual_face = internal::residual_faces<Geom_traits>(
      m_adjacency, corners, m_patches, m_number_of_patches, m_parts, m_part_to_primitive, m_fitting.primitives,
      m_prior.classes, m_normalization, tolerance_in_voxels / double(m_prior.classes.resolution()));
    internal::split_residual_parts(m_adjacency, m_residual_face, m_parts, m_part_to_primitive, no_primitive);
  }

  // A part is residual if most of its area is residual faces; it keeps no fitted primitive.
  void mark_residual_parts()
  {
    const std::size_t K = m_part_to_primitive.size();
    m_residual_parts.assign(K, 0);
    if(m_residual_face.empty()) return;
    std::vector<double> area(K, 0.), residual(K, 0.);
    for(std::size_t i = 0; i < m_parts.size(); ++i)
    {
      area[m_parts[i]] += m_adjacency.area[i];
      if(m_residual_face[i]) residual[m_parts[i]] += m_adjacency.area[i];
    }
    for(std::size_t k = 0; k < K; ++k) m_residual_parts[k] = area[k] > 0. && 2. * residual[k] > area[k];
  }

  // The thin-sheet merge on the parts, without their primitives (the composition with the pieces
  // makes them after it).
  template <typename ConcurrencyTag>
  void merge_thin_sheet_parts()
  {
    check_frame(m_tsdf.normalization, "the normalization of the distance field");
    internal::merge_thin_sheets_on_faces<ConcurrencyTag>(m_tm, m_vpm, m_fim, m_adjacency, m_tsdf.values, m_fitting,
                                                         m_parts, m_part_to_primitive);
  }

  // The parts of the pieces and regions (`internal::compose_parts()`), with the volumetric parts
  // in the pieces that need them if they were computed; a part keeps the primitive of the
  // volumetric part covering most of it, or gets its bounding superquadric.
  void compose_with_pieces(bool volumetric, double minimum_part_area)
  {
    std::vector<std::size_t>& volume_part = m_volume_part;
    volume_part.clear();
    if(volumetric)
    {
      volume_part.swap(m_parts);
      for(std::size_t i = 0; i < volume_part.size(); ++i)
        if(!m_volumetric_piece[m_pieces.piece[i]]) volume_part[i] = no_primitive;
      internal::keep_volume_parts_in_their_regions(m_piece_adjacency, m_pieces.region, volume_part, no_primitive);
    }
    const std::vector<std::size_t> source =
      internal::compose_parts(m_piece_adjacency, m_pieces.region, volume_part,
                              minimum_part_area * m_pieces.area, m_parts, no_primitive);
    const std::vector<std::size_t> volume_primitive(m_part_to_primitive);
    m_part_to_primitive.assign(source.size(), no_primitive);
    for(std::size_t k = 0; k < source.size(); ++k)
      if(source[k] != no_primitive) m_part_to_primitive[k] = volume_primitive[source[k]];
    make_part_primitives();
  }

  // A part keeps its fitted primitive if no other part has it and it lies on the part's surface
  // at least as closely as the box-like superquadric of the part's faces; parts that share one
  // (a part cut by the regions of the pieces, a thin plate the fitter saw as one with its
  // neighbour), parts without one and parts thinner than the fitting grid get that box.
  void make_part_primitives()
  {
    const std::size_t K = m_part_to_primitive.size(), P = m_fitting.input_primitives.size();
    std::vector<std::size_t> users(P, 0);
    for(std::size_t k = 0; k < K; ++k)
      if(m_part_to_primitive[k] < P) ++users[m_part_to_primitive[k]];
    std::vector<std::vector<std::array<double, 3> > > points(K);
    for(auto f : faces(m_tm))
    {
      const std::size_t k = m_parts[std::size_t(get(m_fim, f))];
      if(k >= K) continue;
      for(auto v : vertices_around_face(halfedge(f, m_tm), m_tm))
      {
        const auto& p = get(m_vpm, v);
        points[k].push_back({{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}});
      }
    }
    m_part_primitives.clear();
    for(std::size_t k = 0; k < K; ++k)
    {
      const Primitive box = internal::bounding_superquadric<Geom_traits>(points[k]);
      const bool own = m_part_to_primitive[k] < P && users[m_part_to_primitive[k]] == 1;
      if(own && internal::mean_surface_distance(m_fitting.input_primitives[m_part_to_primitive[k]], points[k]) <=
                  internal::mean_surface_distance(box, points[k]))
        m_part_primitives.push_back(m_fitting.input_primitives[m_part_to_primitive[k]]);
      else
        m_part_primitives.push_back(box);
    }
  }

  const TriangleMesh& m_tm;
  Vertex_point_map m_vpm;
  Face_index_map m_fim;
  double m_margin;
  Normalization m_normalization;
  Hierarchical_prior m_prior;
  Truncated_signed_distance_field m_tsdf;
  Fitting_zones m_zones;
  Superquadric_fitting_result<Geom_traits> m_fitting;
  internal::Face_adjacency m_adjacency; // of the over-segmentation, reused by the sheet merge
  internal::Face_adjacency m_piece_adjacency; // of the pieces, reused by the part composition
  Piece_segmentation m_pieces;
  std::vector<std::uint8_t> m_splittable_piece; // per piece: non-convex, large enough to hold two parts
  double m_crease_angle = defaults::crease_angle;  // of segment_pieces()
  std::vector<std::uint8_t> m_volumetric_piece; // per piece: decomposed by the volumetric stages
  std::vector<std::size_t> m_patches;
  std::size_t m_number_of_patches = 0;
  std::vector<std::size_t> m_parts;
  std::vector<std::uint8_t> m_residual_face; // per face: in a residual patch (empty: none kept)
  std::vector<std::uint8_t> m_residual_parts;
  std::vector<std::size_t> m_volume_part; // per face: the volumetric part composed with the pieces, or empty
  std::vector<std::size_t> m_part_to_primitive;
  std::vector<Primitive> m_part_primitives;
  Part_hierarchy<Geom_traits> m_hierarchy;
  bool m_has_pieces = false, m_has_hierarchy = false;
  bool m_has_prior = false, m_has_zones = false, m_has_tsdf = false, m_has_fitting = false, m_has_patches = false,
       m_has_parts = false;
};

namespace internal {

// The parts of one decomposition: per face index its part, per part its superquadric.
template <typename GeomTraits>
struct Decomposition_pass
{
  std::vector<std::size_t> parts;
  std::vector<Superquadric<GeomTraits> > primitives;
  std::size_t number_of_parts = 0;
  double scale = 1.; // of the normalization: mesh lengths times this are lengths in the unit cube
};

// `decompose()` at the resolutions of `np`, without the finer pass of `thin_part_resolution`;
// `out.parts` is indexed by `fim`, the face index map of both passes and of the final write.
template <typename ConcurrencyTag, typename GT, typename TriangleMesh, typename FIM, typename NamedParameters>
void decompose_once(const TriangleMesh& tm, const FIM& fim, const NamedParameters& np, Decomposition_pass<GT>& out,
                    Stage_timings& timings)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename GetVertexPointMap<TriangleMesh, NamedParameters>::const_type VPM;

  const VPM vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                   get_const_property_map(CGAL::vertex_point, tm));
  const double margin = choose_parameter(get_parameter(np, internal_np::normalization_margin), defaults::normalization_margin);
  Part_decomposer<TriangleMesh, GT, VPM, FIM> decomposer(tm, vpm, fim, margin);

  internal::check_stage_parameters(np);
  timings.overlapping = internal::is_parallel_tag<ConcurrencyTag>();
  out.parts.assign(num_faces(tm), 0);
  // the stage times start at 0: each is added once
  internal::add_seconds(timings.pieces, [&] {
    if(internal::read_piece_parameters(np).use_pieces) decomposer.template segment_pieces<ConcurrencyTag>(np);
  });
  // The fitting's own loops are short (one primitive at a time), so its sequential part is the
  // longest of the pipeline: the over-segmentation runs next to it, and the prior and the
  // distance field next to each other before it.
  if(decomposer.needs_volumetric_stages(np))
  internal::run_side_by_side<ConcurrencyTag>(
    [&] {
      internal::run_side_by_side<ConcurrencyTag>(
        [&] { internal::add_seconds(timings.prior, [&] { decomposer.template compute_prior<ConcurrencyTag>(np); }); },
        [&] {
          internal::add_seconds(timings.tsdf, [&] { decomposer.template compute_distance_field<ConcurrencyTag>(np); });
        });
      // the distance field may show that no piece bounds a volume
      if(!decomposer.needs_volumetric_stages(np)) return;
      internal::add_seconds(timings.fitting_zones, [&] { decomposer.template compute_fitting_zones<ConcurrencyTag>(np); });
      internal::add_seconds(timings.fitting, [&] { decomposer.template fit_primitives<ConcurrencyTag>(np); });
      timings.fitting += timings.fitting_zones;
    },
    [&] {
      internal::add_seconds(timings.over_segmentation, [&] { decomposer.template over_segment<ConcurrencyTag>(np); });
    });

  // the assignment (with the thin-sheet merge unless merge_thin_sheets(false)), then the hierarchy
  // when it is asked for or its cheap merges may go on, and the level of the hierarchy if it is
  // not the assignment's
  const internal::Hierarchy_parameters hp = internal::read_hierarchy_parameters(np);
  Part_hierarchy<GT>* hierarchy_out =
    choose_parameter(get_parameter(np, internal_np::part_hierarchy), static_cast<Part_hierarchy<GT>*>(nullptr));
  const std::size_t assigned = internal::add_seconds(timings.assignment, [&] {
    return decomposer.template assign_parts<ConcurrencyTag>(boost::dummy_property_map(), np);
  });
  std::size_t K = assigned;
  if(hp.has_number_of_parts || hierarchy_out != nullptr || (hp.maximum_merge_cost > 0. && assigned > 1))
    internal::add_seconds(timings.hierarchy, [&] {
      decomposer.build_hierarchy(hp.maximum_merge_cost);
      const std::size_t default_parts = decomposer.hierarchy().level_below_cost(assigned, hp.maximum_merge_cost);
      K = hp.has_number_of_parts ? hp.number_of_parts : default_parts;
      if(hierarchy_out != nullptr)
      {
        *hierarchy_out = decomposer.hierarchy();
        hierarchy_out->default_number_of_parts = default_parts;
      }
    });
  out.primitives.clear();
  if(K == assigned && !hp.has_number_of_parts)
  {
    out.parts = decomposer.parts();
    out.primitives = decomposer.part_primitives();
  }
  else
    K = decomposer.parts_at_level(K, boost::make_iterator_property_map(out.parts.begin(), decomposer.face_index_map()),
                                  std::back_inserter(out.primitives));
  out.number_of_parts = K;
  out.scale = decomposer.normalization().scale();
}


// A part of the finer pass is thin if its superquadric's smallest semi-axis is below this length
// of the normalized cube (5 voxels of the default 64^3 grid; tuned on half A of the development
// shapes, see benchmark/Part_decomposition/RESULTS.md).
constexpr double thin_part_semi_axis = 5. / 64.;

// The thin parts of `finer` replace, face by face, the parts of `pass`, each with its superquadric:
// the parts of `pass` keep their order (those left without faces are dropped), the thin parts
// follow in the order of `finer`.
template <typename GT>
void carve_thin_parts(Decomposition_pass<GT>& pass, const Decomposition_pass<GT>& finer)
{
  const std::size_t K = pass.number_of_parts, nf = pass.parts.size();
  std::vector<std::size_t> thin(finer.number_of_parts, 0); // 1 + rank among the thin parts, or 0
  std::size_t number_of_thin = 0;
  for(std::size_t k = 0; k < finer.number_of_parts; ++k)
  {
    const std::array<double, 3> a = finer.primitives[k].scales();
    if((std::min)({a[0], a[1], a[2]}) * finer.scale < thin_part_semi_axis) thin[k] = ++number_of_thin;
  }
  if(number_of_thin == 0) return;
  std::vector<std::size_t> part(nf);
  std::vector<std::uint8_t> used(K, 0);
  for(std::size_t i = 0; i < nf; ++i)
  {
    const std::size_t t = thin[finer.parts[i]];
    part[i] = t > 0 ? K + t - 1 : pass.parts[i];
    if(t == 0) used[pass.parts[i]] = 1;
  }
  std::vector<std::size_t> new_id(K + number_of_thin);
  std::vector<Superquadric<GT> > primitives;
  for(std::size_t k = 0; k < K; ++k)
    if(used[k]) { new_id[k] = primitives.size(); primitives.push_back(pass.primitives[k]); }
  for(std::size_t k = 0; k < finer.number_of_parts; ++k)
    if(thin[k] > 0) { new_id[K + thin[k] - 1] = primitives.size(); primitives.push_back(finer.primitives[k]); }
  for(std::size_t i = 0; i < nf; ++i) pass.parts[i] = new_id[part[i]];
  pass.primitives.swap(primitives);
  pass.number_of_parts = pass.primitives.size();
}

// The resolution of the finer pass (0: none), checked: a power of two up to 256, at least twice
// the finest of `voxel_resolutions`, and not with `number_of_parts` nor `part_hierarchy`, whose
// hierarchy is that of one pass.
template <typename TriangleMesh, typename NamedParameters>
int read_thin_part_resolution(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const int r = choose_parameter(get_parameter(np, internal_np::thin_part_resolution), defaults::thin_part_resolution);
  if(r == 0) return 0;
  check_parameter(r >= 4 && r <= 256 && (r & (r - 1)) == 0 && r >= 2 * read_voxel_resolutions(np).back(),
                  "thin_part_resolution");
  typedef typename GetGeomTraits<TriangleMesh, NamedParameters>::type GT;
  check_parameter(CGAL::parameters::is_default_parameter<NamedParameters, internal_np::number_of_parts_t>::value &&
                    choose_parameter(get_parameter(np, internal_np::part_hierarchy),
                                     static_cast<Part_hierarchy<GT>*>(nullptr)) == nullptr,
                  "thin_part_resolution", "0 when number_of_parts or a part_hierarchy is given");
  return r;
}

} // namespace internal

/*!
\ingroup PkgPartDecompositionRef
decomposes the triangle mesh `tm` into parts with the Hi-TOPS method (paper Algorithm A.1) and
writes the part id of every face, from 0 to `K-1`, to `face_part_map`. Each part is explained by
one superquadric, optionally written to an output iterator. The same input and parameters give
the same output, whatever the number of threads.

The stages, each also available on its own: `segment_pieces()`, `compute_flow_freeze_prior()`, `compute_tsdf()`,
`fit_superquadrics()`, `over_segment()`, `assign_parts()` and `merge_thin_sheet_parts()`, then
the part hierarchy (`build_part_hierarchy()`), whose merges go on from the assigned parts as long
as they cost less than `maximum_merge_cost`; `Part_decomposer` runs them one by one. Every named parameter of these functions is accepted here
and passed to the stage that reads it; the table below lists them all, as does
`parameter_table` (with `weld_tolerance`, read by the mesh reader only). The normalization is
computed once from `normalization_margin` (a `normalization` given here must be that one).
`face_part_map` is written once, at the end.

With a parallel `ConcurrencyTag`, the stages that do not depend on each other also run at the same
time: the prior and the distance field side by side, followed by the fitting, while the
over-segmentation (which needs only the mesh) runs next to the three of them; every stage also
runs its own loops in parallel. The result is the same: each stage is deterministic and none
reads what another writes.

\tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or
`CGAL::Parallel_if_available_tag` (parallel with TBB when it is linked)
\tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
\tparam FacePartMap a model of `WritablePropertyMap` with
`boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and `std::size_t` as value type
\tparam NamedParameters a sequence of named parameters

\param tm the mesh: any triangle mesh, open, non-manifold, self-intersecting or made of several
components
\param face_part_map receives the part id of each face
\param np an optional sequence of named parameters among the ones listed below (package parameters
are chained with `parameters::combine()`)

\cgalNamedParamsBegin
  \cgalParamNBegin{vertex_point_map}
    \cgalParamDescription{a property map associating points to the vertices of `tm`}
    \cgalParamType{a class model of `ReadablePropertyMap` with
                   `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and
                   `%Point_3` as value type}
    \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
  \cgalParamNEnd
  \cgalParamNBegin{geom_traits}
    \cgalParamDescription{an instance of a geometric traits class}
    \cgalParamType{a model of `PartDecompositionTraits`}
    \cgalParamDefault{the kernel of the point type of the vertex point map}
  \cgalParamNEnd
  \cgalParamNBegin{face_index_map}
    \cgalParamDescription{a property map associating to each face of `tm` a unique index between `0` and `num_faces(tm) - 1`}
    \cgalParamType{a class model of `ReadablePropertyMap` with
                   `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and `std::size_t` as value type}
    \cgalParamDefault{an automatically indexed internal map}
  \cgalParamNEnd
  \cgalParamNBegin{voxel_resolutions}
    \cgalParamDescription{\f$R\f$: the resolutions of the prior, coarse to fine, each twice the
                          previous; the distance field and the fitter use the finest}
    \cgalParamType{`std::vector<int>`}
    \cgalParamDefault{`{16, 32, 64}`}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_points_per_face}
    \cgalParamDescription{\f$N_{face}\f$: barycentric samples per face (a perfect square)}
    \cgalParamType{`unsigned int`}
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
    \cgalParamDescription{\f$\lambda\f$: the weights of the curvature mean, curvature deviation,
                          curvature gradient and normal deviation in the topology score}
    \cgalParamType{`std::array<double, 4>`}
    \cgalParamDefault{`{1, 1, 1, 1}`}
  \cgalParamNEnd
  \cgalParamNBegin{freeze_ratio}
    \cgalParamDescription{\f$\alpha\f$: the fraction of active voxels frozen at each resolution}
    \cgalParamType{`double`, in \f$(0,1)\f$}
    \cgalParamDefault{`0.15`}
  \cgalParamNEnd
  \cgalParamNBegin{use_density}
    \cgalParamDescription{if `false` (ablation), the topology score is not weighted by the density term \f$\sqrt{n_i}\f$}
    \cgalParamType{`bool`}
    \cgalParamDefault{`true`}
  \cgalParamNEnd
  \cgalParamNBegin{prior_resolution_cap}
    \cgalParamDescription{the finest resolution of the topology score; finer `voxel_resolutions` only
                          refine the grid of the distance field, the zones and the claims, with the
                          classes of the cap (see `compute_flow_freeze_prior()`). 0: every resolution}
    \cgalParamType{`int`, 0 or one of `voxel_resolutions`}
    \cgalParamDefault{`0`}
  \cgalParamNEnd
  \cgalParamNBegin{normalization}
    \cgalParamDescription{the normalization of the mesh into the unit cube; it must be the one `compute_normalization()` computes from `normalization_margin`}
    \cgalParamType{`Normalization`}
    \cgalParamDefault{computed by `compute_normalization()`}
  \cgalParamNEnd
  \cgalParamNBegin{normalization_margin}
    \cgalParamDescription{the free margin left on each side of the normalized cube (see `compute_normalization()`)}
    \cgalParamType{`double`, in `[0, 0.25]`}
    \cgalParamDefault{`2.0/64`}
  \cgalParamNEnd
  \cgalParamNBegin{tsdf_truncation}
    \cgalParamDescription{\f$\tau\f$, in voxels of the finest grid}
    \cgalParamType{`double`}
    \cgalParamDefault{`8`}
  \cgalParamNEnd
  \cgalParamNBegin{tsdf_sign_method}
    \cgalParamDescription{how the inside of the shape is decided}
    \cgalParamType{`CGAL::Part_decomposition::Tsdf_sign_method`}
    \cgalParamDefault{`Tsdf_sign_method::AUTOMATIC` (ray votes of winding numbers)}
  \cgalParamNEnd
  \cgalParamNBegin{flow_zone_tolerance}
    \cgalParamDescription{the dilation of the Flow zone, in voxels of the fitting resolution}
    \cgalParamType{`double`}
    \cgalParamDefault{`2`}
  \cgalParamNEnd
  \cgalParamNBegin{trust_region_scales}
    \cgalParamDescription{\f$\{\eta\}\f$: the semi-axis trust-region scales of the retries}
    \cgalParamType{`std::vector<double>`}
    \cgalParamDefault{`{1, 0.5, 0.25}`}
  \cgalParamNEnd
  \cgalParamNBegin{body_seed_threshold}
    \cgalParamDescription{the EDT depth, in voxels of the fitting resolution, below which seeds switch from body to surface}
    \cgalParamType{`double`}
    \cgalParamDefault{`1.5`}
  \cgalParamNEnd
  \cgalParamNBegin{minimum_body_volume}
    \cgalParamDescription{\f$V_{min}\f$ of body seeds, in voxels of the fitting resolution \f$r_{fit}\f$}
    \cgalParamType{`double`}
    \cgalParamDefault{`5`}
  \cgalParamNEnd
  \cgalParamNBegin{minimum_surface_volume}
    \cgalParamDescription{\f$V_{min}\f$ of surface seeds, in voxels of the fitting resolution \f$r_{fit}\f$}
    \cgalParamType{`double`}
    \cgalParamDefault{`3`}
  \cgalParamNEnd
  \cgalParamNBegin{exterior_penalty}
    \cgalParamDescription{\f$\mu_{ext}\f$: the exterior intrusion penalty}
    \cgalParamType{`double`}
    \cgalParamDefault{`5`}
  \cgalParamNEnd
  \cgalParamNBegin{coverage_target}
    \cgalParamDescription{the fraction of the valid volume claimed before a fitting stage ends}
    \cgalParamType{`double`, in \f$(0,1]\f$}
    \cgalParamDefault{`0.999`}
  \cgalParamNEnd
  \cgalParamNBegin{roi_radius}
    \cgalParamDescription{the radius of the region of interest of a seed, in voxels of the fitting resolution}
    \cgalParamType{`double`, positive}
    \cgalParamDefault{`8`}
  \cgalParamNEnd
  \cgalParamNBegin{interior_weight_mode}
    \cgalParamDescription{how the variance of the interior Gaussian weight of the fit is set}
    \cgalParamType{`CGAL::Part_decomposition::Interior_weight_mode`}
    \cgalParamDefault{`Interior_weight_mode::ONE_SHOT`}
  \cgalParamNEnd
  \cgalParamNBegin{maximum_number_of_primitives}
    \cgalParamDescription{a safety cap on the number of fitted superquadrics}
    \cgalParamType{`std::size_t`, positive}
    \cgalParamDefault{`256`}
  \cgalParamNEnd
  \cgalParamNBegin{use_freeze_zone}
    \cgalParamDescription{if `false` (ablation "w/o Freeze"), Freeze voxels are treated as Flow by the fitter}
    \cgalParamType{`bool`}
    \cgalParamDefault{`true`}
  \cgalParamNEnd
  \cgalParamNBegin{use_tsdf_guidance}
    \cgalParamDescription{if `false` (ablation "w/o TSDF"), the fit sees the occupancy only}
    \cgalParamType{`bool`}
    \cgalParamDefault{`true`}
  \cgalParamNEnd
  \cgalParamNBegin{use_body_seeds}
    \cgalParamDescription{if `false` (ablation "w/o Body"), only surface seeds are used}
    \cgalParamType{`bool`}
    \cgalParamDefault{`true`}
  \cgalParamNEnd
  \cgalParamNBegin{fitting_resolution_cap}
    \cgalParamDescription{the cap of the fitting resolution, \f$r_{fit} = \min(r, cap)\f$; 0 stands for the resolution before the finest (see `fitting_resolutions()`)}
    \cgalParamType{`int`, non-negative}
    \cgalParamDefault{`0`}
  \cgalParamNEnd
  \cgalParamNBegin{use_exterior_band_samples}
    \cgalParamDescription{if `false` (ablation), the exterior voxels of the thin outer band are not samples of the fit (\ref PD_Deviations)}
    \cgalParamType{`bool`}
    \cgalParamDefault{`true`}
  \cgalParamNEnd
  \cgalParamNBegin{use_reachable_regions}
    \cgalParamDescription{if `false` (ablation), regions of interest and claims do not stop at Freeze walls (\ref PD_Deviations)}
    \cgalParamType{`bool`}
    \cgalParamDefault{`true`}
  \cgalParamNEnd
  \cgalParamNBegin{use_seed_exclusion}
    \cgalParamDescription{if `false` (ablation), a rejected seed does not exclude a ball around it from later seeds of its stage (\ref PD_Deviations)}
    \cgalParamType{`bool`}
    \cgalParamDefault{`true`}
  \cgalParamNEnd
  \cgalParamNBegin{maximum_solver_evaluations}
    \cgalParamDescription{the residual evaluations of one least-squares solve}
    \cgalParamType{`int`, positive}
    \cgalParamDefault{`40`}
  \cgalParamNEnd
  \cgalParamNBegin{maximum_rejections_in_a_row}
    \cgalParamDescription{the rejected seeds in a row that end a fitting stage (0: never)}
    \cgalParamType{`std::size_t`}
    \cgalParamDefault{`4`}
  \cgalParamNEnd
  \cgalParamNBegin{dihedral_percentile}
    \cgalParamDescription{\f$q\f$: the percentile of the dihedral angles above which edges are cut}
    \cgalParamType{`double`}
    \cgalParamDefault{`90`}
  \cgalParamNEnd
  \cgalParamNBegin{smoothing_iterations}
    \cgalParamDescription{the boundary-smoothing iterations of the over-segmentation}
    \cgalParamType{`unsigned int`}
    \cgalParamDefault{`1`}
  \cgalParamNEnd
  \cgalParamNBegin{minimum_patch_size}
    \cgalParamDescription{the smallest patch area kept by the over-segmentation, as a fraction of the mesh area}
    \cgalParamType{`double`, in `[0, 1]`}
    \cgalParamDefault{`0.001`}
  \cgalParamNEnd
  \cgalParamNBegin{patch_split_size}
    \cgalParamDescription{the largest patch area the over-segmentation builds on smooth regions, as a fraction of the mesh area}
    \cgalParamType{`double`, in `(0, 1]`}
    \cgalParamDefault{`0.0005`}
  \cgalParamNEnd
  \cgalParamNBegin{vote_temperature}
    \cgalParamDescription{\f$\tau_v\f$: the temperature of the patch vote, in voxels of the finest grid}
    \cgalParamType{`double`, positive}
    \cgalParamDefault{`1`}
  \cgalParamNEnd
  \cgalParamNBegin{boundary_smoothness}
    \cgalParamDescription{\f$\lambda\f$: the weight of the cost of cutting along the edges against the
                          primitives' evidence in the final labelling of the faces (see
                          `assign_parts()`); 0 gives the paper's vote of the patches}
    \cgalParamType{`double`, non-negative}
    \cgalParamDefault{`10`}
  \cgalParamNEnd
  \cgalParamNBegin{merge_primitives}
    \cgalParamDescription{if `true`, adjacent fitted primitives that one superquadric explains are
                          merged after the fit (see `fit_superquadrics()`). This step is not in the paper.}
    \cgalParamType{`bool`}
    \cgalParamDefault{`true`}
  \cgalParamNEnd
  \cgalParamNBegin{minimum_merge_iou}
    \cgalParamDescription{the voxel intersection over union from which one superquadric explains two
                          groups of primitives (see `fit_superquadrics()`)}
    \cgalParamType{`double`, in `(0, 1]`}
    \cgalParamDefault{`0.6`}
  \cgalParamNEnd
  \cgalParamNBegin{keep_residual_patches}
    \cgalParamDescription{if `true`, the residual patches of the assignment (paper Sec.\ 3.4) are kept
                          as parts of their own instead of being forced onto a primitive: the patches
                          of the over-segmentation of which at least half of the area lies in Freeze
                          voxels of the prior and whose faces are on average farther than
                          `residual_tolerance` from the primitive they were assigned to. Each
                          edge-connected set of them is one part, without fitted primitive, flagged by
                          `Part_decomposer::residual_parts()`; like any part, it joins a neighbour if it
                          is smaller than `minimum_part_area`.}
    \cgalParamType{`bool`}
    \cgalParamDefault{`false`}
  \cgalParamNEnd
  \cgalParamNBegin{residual_tolerance}
    \cgalParamDescription{the mean distance to its primitive, in voxels of the finest grid, from which a
                          Freeze-dominant patch is residual}
    \cgalParamType{`double`, non-negative}
    \cgalParamDefault{`2`}
  \cgalParamNEnd
  \cgalParamNBegin{merge_thin_sheets}
    \cgalParamDescription{if `true`, the parts are merged by `merge_thin_sheet_parts()`: adjacent
                          parts whose primitives are flat and thin are merged when less than half
                          of the length of their common boundary runs over sharp edges, so that a
                          thin curved shell, such as the wall of a cup or the skin of a wing, tiled
                          by several flat primitives, is one part. This step is not in the paper.}
    \cgalParamType{`bool`}
    \cgalParamDefault{`true`}
  \cgalParamNEnd
  \cgalParamNBegin{use_pieces}
    \cgalParamDescription{if `true`, the parts follow the pieces of the mesh and their concave
                          creases (`segment_pieces()`): the volumetric stages decompose only the
                          non-convex pieces that bound a volume, closed or not, whose parts are cut by the regions of
                          `segment_pieces()`; every other piece is decomposed into its regions (see
                          `Part_decomposer::needs_volumetric_stages()`). If `false`, the parts are
                          those of the volumetric stages alone, as in the paper. This step is not
                          in the paper.}
    \cgalParamType{`bool`}
    \cgalParamDefault{`true`}
  \cgalParamNEnd
  \cgalParamNBegin{crease_angle}
    \cgalParamDescription{the dihedral angle, in degrees, from which a concave edge separates two
                          regions of a piece (`segment_pieces()`)}
    \cgalParamType{`double`, in `(0, 180]`}
    \cgalParamDefault{`60`}
  \cgalParamNEnd
  \cgalParamNBegin{minimum_part_area}
    \cgalParamDescription{with `use_pieces`, the area, as a fraction of the mesh area, below which a
                          part is merged into the neighbour across its weakest shared edge (a
                          separate piece without neighbour stays a part); a piece smaller than
                          twice this area is not decomposed by the volumetric stages}
    \cgalParamType{`double`, in `[0, 1]`}
    \cgalParamDefault{`0.005`}
  \cgalParamNEnd
  \cgalParamNBegin{verbose}
    \cgalParamDescription{if `true`, the fitter prints every accepted primitive and stage to `std::cerr`}
    \cgalParamType{`bool`}
    \cgalParamDefault{`false`}
  \cgalParamNEnd
  \cgalParamNBegin{primitive_output_iterator}
    \cgalParamDescription{receives, for each part in increasing id, its superquadric in input
                          coordinates: its fitted primitive if no other part has the same one
                          and it lies on average as close to the part's vertices, else (several
                          parts explained by one primitive, a part thinner than the fitting grid,
                          or a part no primitive could be fitted to, as a flat sheet) the box-like
                          superquadric of its principal-axis bounding box}
    \cgalParamType{a model of `OutputIterator` accepting `Superquadric<GeomTraits>`}
    \cgalParamDefault{none}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_parts}
    \cgalParamDescription{the number \f$k\f$ of parts: the parts are those of level \f$k\f$ of the part
                          hierarchy (`Part_decomposer::build_hierarchy()`), each with the superquadric
                          of its node; a \f$k\f$ above the number of leaves of the hierarchy gives its
                          leaves. Without it, the parts are those of the default granularity.}
    \cgalParamType{`std::size_t`, at least 1}
    \cgalParamDefault{none}
  \cgalParamNEnd
  \cgalParamNBegin{maximum_merge_cost}
    \cgalParamDescription{the default granularity: the parts of `Part_decomposer::assign_parts()` go on
                          merging in the order of the part hierarchy as long as each merge costs less
                          than this (`Part_hierarchy::level_below_cost()`; the cost is that of
                          `build_part_hierarchy()`: the volume one box of the union adds to the boxes
                          of the two parts, as a fraction of the bounding box, plus a term for a
                          concave common boundary). Two parts that touch and that one box explains
                          about as well as their two boxes, along a boundary that is not a concave
                          crease, become one part with the box-like superquadric of its node; parts
                          in separate places never merge. 0: the parts of the assignment}
    \cgalParamType{`double`, finite, at least 0}
    \cgalParamDefault{`0.003`}
  \cgalParamNEnd
  \cgalParamNBegin{part_hierarchy}
    \cgalParamDescription{if not null, receives the part hierarchy (`Part_decomposer::build_hierarchy()`),
                          built after the parts; its `default_number_of_parts` is the number of
                          parts of the default granularity (after the merges below
                          `maximum_merge_cost`)}
    \cgalParamType{`Part_hierarchy<GeomTraits>*`}
    \cgalParamDefault{`nullptr`}
  \cgalParamNEnd
  \cgalParamNBegin{thin_part_resolution}
    \cgalParamDescription{if not 0, the resolution \f$r_t\f$ of a second, finer pass: the whole
                          decomposition runs again with `voxel_resolutions` \f$\{r_t/4, r_t/2, r_t\}\f$,
                          `fitting_resolution_cap(`\f$r_t/4\f$`)` and `prior_resolution_cap(`\f$r_t/2\f$`)`,
                          and each of its parts whose superquadric has a smallest semi-axis below
                          5/64 of the normalized cube (5 voxels of the default \f$64^3\f$ grid) replaces
                          the parts of the first pass on its faces, with its superquadric. The parts
                          of the first pass keep theirs. Thin parts (wings, fins, legs, plates) that the
                          default grid cannot resolve are separated; the bodies keep the parts of
                          the default grid, which the finer grid tends to tile. Costs a second,
                          finer decomposition (its time and memory: `benchmark/Part_decomposition/RESULTS.md`)}
    \cgalParamType{`int`: 0, or a power of two up to 256 and at least twice the finest of
                   `voxel_resolutions`; not with `number_of_parts` nor `part_hierarchy`}
    \cgalParamDefault{`0`}
  \cgalParamNEnd
  \cgalParamNBegin{stage_timings}
    \cgalParamDescription{receives the wall-clock time of each stage}
    \cgalParamType{`Stage_timings*`}
    \cgalParamDefault{`nullptr`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the number `K` of parts (the clamped \f$k\f$ with `number_of_parts`).

\par Complexity
The sum of the costs of the stages, \f$O(F \log F + F\,N_{face} + r^3)\f$ for \f$F\f$ faces and the finest
resolution \f$r\f$, plus the superquadric fits, whose number and cost depend on the shape and on
\f$r\f$, not on \f$F\f$ (see `fit_superquadrics()`).

\throws Invalid_input if `tm` cannot be decomposed (no face, a face that is not a triangle, a
non-finite coordinate, all vertices equal, coordinates out of the range of `maximum_coordinate` and
`minimum_extent`, a `CGAL::Surface_mesh` with garbage: see `check_input()`) or a named parameter is
out of its range (`INVALID_PARAMETER`, also for a `normalization` that is not the one computed, or
a `number_of_parts` of 0).

\cgalExample{Part_decomposition/decompose_example.cpp}
*/
template <typename ConcurrencyTag = CGAL::Parallel_if_available_tag, typename TriangleMesh,
          typename FacePartMap, typename NamedParameters = CGAL::parameters::Default_named_parameters>
std::size_t decompose(const TriangleMesh& tm, FacePartMap face_part_map,
                      const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename GetGeomTraits<TriangleMesh, NamedParameters>::type GT;
  typedef typename GetInitializedFaceIndexMap<TriangleMesh, NamedParameters>::const_type FIM;
  const auto t0 = std::chrono::steady_clock::now();
  const int fine = internal::read_thin_part_resolution<TriangleMesh>(np);
  const FIM fim = CGAL::get_initialized_face_index_map(tm, np);
  Stage_timings timings;
  internal::Decomposition_pass<GT> pass;
  internal::decompose_once<ConcurrencyTag>(tm, fim, np, pass, timings);
  if(fine > 0)
    internal::add_seconds(timings.thin_parts, [&] {
      internal::Decomposition_pass<GT> finer;
      Stage_timings finer_timings;
      internal::decompose_once<ConcurrencyTag>(
        tm, fim, parameters::combine(np, parameters::voxel_resolutions(std::vector<int>{fine / 4, fine / 2, fine}),
                                parameters::fitting_resolution_cap(fine / 4), parameters::prior_resolution_cap(fine / 2)),
        finer, finer_timings);
      internal::carve_thin_parts(pass, finer);
    });
  internal::put_face_values(tm, fim, pass.parts, face_part_map);
  auto out = choose_parameter(get_parameter(np, internal_np::primitive_output_iterator), CGAL::Emptyset_iterator());
  for(const Superquadric<GT>& sq : pass.primitives) *out++ = sq;
  timings.total = internal::seconds_since(t0);
  if(Stage_timings* st = choose_parameter(get_parameter(np, internal_np::stage_timings),
                                          static_cast<Stage_timings*>(nullptr)))
    *st = timings;
  return pass.number_of_parts;
}

} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_DECOMPOSE_H
