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
#include <CGAL/Part_decomposition/part_composition.h>
#include <CGAL/Part_decomposition/part_hierarchy.h>
#include <CGAL/Part_decomposition/parameters.h>
#include <CGAL/Part_decomposition/piece_segmentation.h>
#include <CGAL/Part_decomposition/primitive_assignment.h>
#include <CGAL/Part_decomposition/sheet_inflation.h>
#include <CGAL/Part_decomposition/superquadric_fitting.h>
#include <CGAL/Part_decomposition/thin_sheet_merging.h>
#include <CGAL/Part_decomposition/tsdf.h>
#include <CGAL/Part_decomposition/internal/parameter_checks.h>
#include <CGAL/Part_decomposition/internal/patch_operations.h>
#include <CGAL/Part_decomposition/internal/toolbox.h>

#include <CGAL/Bbox_3.h>
#include <CGAL/Default.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <utility>
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

namespace internal {

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

inline bool any_of_flags(const std::vector<std::uint8_t>& flags)
{
  return std::find(flags.begin(), flags.end(), std::uint8_t(1)) != flags.end();
}

// Per face index, whether its piece is flagged: the faces whose thin parts the grid refines are
// those of the pieces the volume stages may decompose.
inline std::vector<std::uint8_t> faces_of_pieces(const Piece_segmentation& pieces, const std::vector<std::uint8_t>& flags)
{
  std::vector<std::uint8_t> out(pieces.piece.size(), 0);
  for(std::size_t i = 0; i < out.size(); ++i) out[i] = flags[pieces.piece[i]];
  return out;
}

// The results of the stages of one decomposition, as the stage functions return them.
template <typename GeomTraits>
struct Stage_results
{
  Piece_segmentation pieces;
  std::vector<std::uint8_t> volumetric_pieces; // per piece; empty before the distance field
  Hierarchical_prior prior;
  Truncated_signed_distance_field tsdf;
  Fitting_zones zones;
  Superquadric_fitting_result<GeomTraits> fitting;
  Volumetric_parts volumetric;
  Composed_parts<GeomTraits> composed;
  Part_hierarchy<GeomTraits> hierarchy;
};

// The volumetric stages; returns whether the primitives were fitted (not if the distance field
// shows that no piece bounds a volume). The distance field is computed on the grid the prior asks
// for. The fitting's own loops are short (one primitive at a time), so its sequential part is the
// longest of the pipeline: the over-segmentation runs next to the volume stages.
template <typename ConcurrencyTag, typename GT, typename TriangleMesh, typename NamedParameters>
bool run_volumetric_stages(const TriangleMesh& tm, const NamedParameters& np, bool use_pieces,
                           const std::vector<std::uint8_t>& splittable, Stage_results<GT>& s, Stage_timings& t)
{
  const auto fim = CGAL::get_initialized_face_index_map(tm, np);
  bool fitted = false;
  s.volumetric.patches.assign(num_faces(tm), 0);
  std::vector<std::uint8_t> thin_faces;
  if(use_pieces) thin_faces = faces_of_pieces(s.pieces, splittable);
  run_side_by_side<ConcurrencyTag>(
    [&] {
      add_seconds(t.prior, [&] { s.prior = compute_flow_freeze_prior<ConcurrencyTag>(tm, np); });
      add_seconds(t.tsdf, [&] {
        s.tsdf = compute_tsdf_of_checked_mesh<ConcurrencyTag>(tm, &s.prior, np, use_pieces ? &thin_faces : nullptr);
      });
      if(use_pieces)
      {
        s.volumetric_pieces = Part_decomposition::volumetric_pieces<ConcurrencyTag>(tm, s.pieces, s.tsdf, np);
        if(!any_of_flags(s.volumetric_pieces)) return;
      }
      const int cap = read_fitting_parameters(np).fitting_resolution_cap;
      add_seconds(t.fitting_zones, [&] {
        s.zones = compute_fitting_zones<ConcurrencyTag>(s.prior, s.tsdf,
                                                        fitting_resolutions(s.prior.resolutions, cap), np);
      });
      add_seconds(t.fitting, [&] { s.fitting = fit_superquadrics<ConcurrencyTag, GT>(s.prior, s.tsdf, s.zones, np); });
      t.fitting += t.fitting_zones;
      fitted = true;
    },
    [&] {
      add_seconds(t.over_segmentation, [&] {
        over_segment<ConcurrencyTag>(tm, boost::make_iterator_property_map(s.volumetric.patches.begin(), fim), np);
      });
    });
  return fitted;
}

// The parts of the primitives (assignment, residual patches, thin-sheet merge) and their
// composition with the pieces.
template <typename ConcurrencyTag, typename GT, typename TriangleMesh, typename NamedParameters>
void run_part_stages(const TriangleMesh& tm, const NamedParameters& np, bool fitted, Stage_results<GT>& s)
{
  const auto fim = CGAL::get_initialized_face_index_map(tm, np);
  Volumetric_parts& v = s.volumetric;
  if(fitted)
  {
    v.parts.assign(num_faces(tm), 0);
    const auto part_map = boost::make_iterator_property_map(v.parts.begin(), fim);
    v.part_to_primitive = assign_parts<ConcurrencyTag>(
      tm, boost::make_iterator_property_map(v.patches.begin(), fim), s.fitting.labels, s.tsdf, part_map, np);
    if(read_assignment_parameters(np).keep_residual_patches) separate_residual_patches(tm, v, s.prior, s.fitting, np);
    if(read_sheet_merging_parameters(np).merge_thin_sheets)
      merge_thin_sheet_parts<ConcurrencyTag>(tm, part_map, v.part_to_primitive, s.fitting, s.tsdf, np);
  }
  s.composed = Part_decomposition::compose_parts<ConcurrencyTag>(tm, s.pieces, s.volumetric_pieces, v, s.fitting, np);
}

// The parts of one decomposition: per face index its part, per part its superquadric.
template <typename GeomTraits>
struct Decomposition_pass
{
  std::vector<std::size_t> parts;
  std::vector<Superquadric<GeomTraits> > primitives;
  std::size_t number_of_parts = 0;
  std::size_t default_number_of_parts = 0; // at the default granularity (maximum_merge_cost)
};

// The hierarchy when it is asked for or its cheap merges may go on, and the parts of its level if
// it is not that of the composed parts.
template <typename GT, typename TriangleMesh, typename NamedParameters>
void cut_hierarchy(const TriangleMesh& tm, const NamedParameters& np, Stage_results<GT>& s,
                   Decomposition_pass<GT>& out, Stage_timings& t)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const Hierarchy_parameters hp = read_hierarchy_parameters(np);
  Part_hierarchy<GT>* hierarchy_out =
    choose_parameter(get_parameter(np, internal_np::part_hierarchy), static_cast<Part_hierarchy<GT>*>(nullptr));
  const std::size_t composed = s.composed.number_of_parts();
  std::size_t K = composed;
  out.default_number_of_parts = composed;
  if(hp.has_number_of_parts || hierarchy_out != nullptr || (hp.maximum_merge_cost > 0. && composed > 1))
    add_seconds(t.hierarchy, [&] {
      s.hierarchy = build_part_hierarchy(tm, s.pieces, s.composed, np);
      out.default_number_of_parts = s.hierarchy.level_below_cost(composed, hp.maximum_merge_cost);
      K = hp.has_number_of_parts ? hp.number_of_parts : out.default_number_of_parts;
      if(hierarchy_out != nullptr)
      {
        *hierarchy_out = s.hierarchy;
        hierarchy_out->default_number_of_parts = out.default_number_of_parts;
      }
    });
  if(K == composed && !hp.has_number_of_parts)
  {
    out.parts = s.composed.parts;
    out.primitives = s.composed.part_primitives;
  }
  else
  {
    K = (std::min)(K, s.hierarchy.number_of_leaves());
    out.parts = s.hierarchy.labels(K);
    out.primitives = s.hierarchy.primitives(K);
  }
  out.number_of_parts = K;
}

// The stage functions in their documented order up to the composed parts, their results left in
// `s`; returns whether a primitive was fitted. `np` holds the normalization.
template <typename ConcurrencyTag, typename GT, typename TriangleMesh, typename NamedParameters>
bool compose_once(const TriangleMesh& tm, const NamedParameters& np, Stage_results<GT>& s, Stage_timings& timings)
{
  const bool use_pieces = read_piece_parameters(np).use_pieces;
  std::vector<std::uint8_t> splittable;
  add_seconds(timings.pieces, [&] {
    if(!use_pieces) return;
    s.pieces = segment_pieces<ConcurrencyTag>(tm, np);
    splittable = Part_decomposition::splittable_pieces<ConcurrencyTag>(tm, s.pieces, np);
  });
  const bool needs_volume = !use_pieces || any_of_flags(splittable);
  const bool fitted =
    needs_volume && run_volumetric_stages<ConcurrencyTag>(tm, np, use_pieces, splittable, s, timings);
  add_seconds(timings.assignment, [&] { run_part_stages<ConcurrencyTag>(tm, np, fitted, s); });
  return fitted;
}

// The composed parts of `tm` from those of the solid of its open sheets (`inflate_sheets()` of the
// faces `sheet`); returns per vertex index the point of `tm` on the solid's side of its normals.
template <typename ConcurrencyTag, typename GT, typename TriangleMesh, typename NamedParameters>
std::vector<typename GT::Point_3> compose_inflated_sheets(const TriangleMesh& tm, const NamedParameters& np,
                                                          const Face_corners& corners,
                                                          const std::vector<std::uint8_t>& sheet, Stage_results<GT>& s,
                                                          Stage_timings& timings)
{
  std::vector<typename GT::Point_3> raised;
  const auto solid = inflated_sheets(corners, sheet, raised);
  const auto solid_np = parameters::combine(np, CGAL::parameters::vertex_point_map(get(CGAL::vertex_point, solid)),
                                            CGAL::parameters::face_index_map(get(CGAL::face_index, solid)),
                                            face_graphs_parameter(nullptr));
  Stage_results<GT> r;
  compose_once<ConcurrencyTag>(
    solid, parameters::combine(solid_np, parameters::normalization(compute_normalization(solid, solid_np))), r, timings);
  s.composed = composed_parts_of_first_faces(r.composed, num_faces(tm));
  return raised;
}

// `decompose()`: the stage functions in their documented order, their results left in `s`; the
// solid of the open sheets when no piece bounds a volume. `np` holds the normalization.
template <typename ConcurrencyTag, typename GT, typename TriangleMesh, typename NamedParameters>
void decompose_once(const TriangleMesh& tm, const NamedParameters& np, Stage_results<GT>& s,
                    Decomposition_pass<GT>& out, Stage_timings& timings)
{
  timings.overlapping = is_parallel_tag<ConcurrencyTag>();
  // the stage times start at 0: each is added once
  const bool fitted = compose_once<ConcurrencyTag>(tm, np, s, timings);
  if(fitted || !read_piece_parameters(np).use_pieces) return cut_hierarchy(tm, np, s, out, timings);
  const Mesh_maps<TriangleMesh, NamedParameters> maps(tm, np);
  const Face_corners corners(tm, maps.fim, maps.vpm);
  std::vector<std::uint8_t> sheet;
  if(!decomposes_inflated_sheets(tm, s.pieces, corners, np, sheet)) return cut_hierarchy(tm, np, s, out, timings);
  // the hierarchy measures the boxes of the sheets' parts on the solid's side of their normals: a
  // flat part has no volume, so that every merge of flat parts would be cheap
  const std::vector<typename GT::Point_3> raised =
    compose_inflated_sheets<ConcurrencyTag>(tm, np, corners, sheet, s, timings);
  const auto raised_map = boost::make_iterator_property_map(raised.begin(), CGAL::get_initialized_vertex_index_map(tm));
  cut_hierarchy(tm, parameters::combine(np, CGAL::parameters::vertex_point_map(raised_map), face_graphs_parameter(nullptr)),
                s, out, timings);
}

} // namespace internal

/*!
\ingroup PkgPartDecompositionRef
The Hi-TOPS part decomposition of a triangle mesh, stage by stage (paper Algorithm A.1), keeping
the result of each stage for inspection. Its constructor fixes the mesh, its maps and its
normalization; each function runs one stage with the stage function of the same meaning
(`segment_pieces()`, `compute_flow_freeze_prior()`, `compute_tsdf()`, `compute_fitting_zones()`,
`fit_superquadrics()`, `over_segment()`, then `compose_parts()` for the parts and
`build_part_hierarchy()`), with the named parameters given to it, to which the mesh, vertex point
map, face index map and normalization of the decomposer are added.

A stage computes the earlier stages it needs that are missing, with its own named parameters, and
drops the results that depended on an earlier result it replaces: the stages may be called in
any order, and `compose_parts()` alone gives the parts of `decompose()` without the hierarchy's
merges. The results of a stage not computed yet are empty. A named parameter out of its range,
and a `normalization` or `normalization_margin` other than the decomposer's, throw
`Invalid_input` (`INVALID_PARAMETER`).

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

  /// splits the mesh into its pieces and their regions with `Part_decomposition::segment_pieces()`;
  /// once the distance field is computed too, an open piece that bounds a volume of it faces out
  /// of it (`volumetric_pieces()`).
  template <typename ConcurrencyTag = CGAL::Sequential_tag,
            typename NamedParameters = CGAL::parameters::Default_named_parameters>
  const Piece_segmentation& segment_pieces(const NamedParameters& np = CGAL::parameters::default_values())
  {
    m_segmented = Part_decomposition::segment_pieces<ConcurrencyTag>(m_tm, with_mesh(np));
    m_s.pieces = m_segmented;
    m_s.volumetric_pieces.clear();
    m_has_pieces = true;
    drop_parts();
    if(m_has_tsdf) volumetric_pieces(np);
    return m_s.pieces;
  }

  /// whether the parts of `compose_parts()` with the named parameters `np` need the volumetric
  /// stages (prior, distance field, fit, over-segmentation): with `use_pieces(false)`, or if a
  /// piece is splittable (`splittable_pieces()`) and, once the distance field is computed, the
  /// volumetric stages decompose it (`volumetric_pieces()`). Before the distance field is known,
  /// it tells whether it is worth computing. Segments the pieces if they are missing.
  template <typename NamedParameters = CGAL::parameters::Default_named_parameters>
  bool needs_volumetric_stages(const NamedParameters& np = CGAL::parameters::default_values())
  {
    if(!internal::read_piece_parameters(np).use_pieces) return true;
    if(!m_has_pieces) segment_pieces(np);
    if(m_has_tsdf) return internal::any_of_flags(volumetric_pieces(np));
    return internal::any_of_flags(Part_decomposition::splittable_pieces(m_tm, m_s.pieces, with_mesh(np)));
  }

  /// computes the hierarchical Flow/Freeze prior with `compute_flow_freeze_prior()`; the distance
  /// field, whose grid the prior shapes, is then out of date.
  template <typename ConcurrencyTag = CGAL::Sequential_tag,
            typename NamedParameters = CGAL::parameters::Default_named_parameters>
  const Hierarchical_prior& compute_prior(const NamedParameters& np = CGAL::parameters::default_values())
  {
    m_s.prior = compute_flow_freeze_prior<ConcurrencyTag>(m_tm, with_mesh(np));
    m_has_prior = true;
    m_has_tsdf = false;
    m_s.pieces = m_segmented;
    m_s.volumetric_pieces.clear();
    drop_fitting();
    return m_s.prior;
  }

  /// computes the truncated signed distance field with `compute_tsdf()` on the grid the prior
  /// asks for, computing the prior if missing; once the pieces are segmented too, an open piece
  /// that bounds a volume of it faces out of it (`volumetric_pieces()`).
  template <typename ConcurrencyTag = CGAL::Sequential_tag,
            typename NamedParameters = CGAL::parameters::Default_named_parameters>
  const Truncated_signed_distance_field& compute_distance_field(const NamedParameters& np = CGAL::parameters::default_values())
  {
    if(!m_has_prior) compute_prior<ConcurrencyTag>(np);
    std::vector<std::uint8_t> thin_faces;
    const bool use_pieces = internal::read_piece_parameters(np).use_pieces;
    if(use_pieces)
    {
      if(!m_has_pieces) segment_pieces<ConcurrencyTag>(np);
      thin_faces = internal::faces_of_pieces(m_segmented, Part_decomposition::splittable_pieces<ConcurrencyTag>(
                                                                m_tm, m_segmented, with_mesh(np)));
    }
    m_s.tsdf = internal::compute_tsdf_of_checked_mesh<ConcurrencyTag>(m_tm, &m_s.prior, with_mesh(np),
                                                                      use_pieces ? &thin_faces : nullptr);
    m_has_tsdf = true;
    m_s.pieces = m_segmented;
    m_s.volumetric_pieces.clear();
    drop_fitting();
    if(m_has_pieces) volumetric_pieces(np);
    return m_s.tsdf;
  }

  /// computes the zones of the fitter with `Part_decomposition::compute_fitting_zones()` at the
  /// `fitting_resolutions()` of the prior with the `fitting_resolution_cap` of `np`, computing the
  /// prior and the distance field if missing. `fit_primitives()` computes them if missing.
  template <typename ConcurrencyTag = CGAL::Sequential_tag,
            typename NamedParameters = CGAL::parameters::Default_named_parameters>
  const Fitting_zones& compute_fitting_zones(const NamedParameters& np = CGAL::parameters::default_values())
  {
    if(!m_has_prior) compute_prior<ConcurrencyTag>(np);
    if(!m_has_tsdf) compute_distance_field<ConcurrencyTag>(np);
    const int cap = internal::read_fitting_parameters(np).fitting_resolution_cap;
    m_s.zones = Part_decomposition::compute_fitting_zones<ConcurrencyTag>(
      m_s.prior, m_s.tsdf, fitting_resolutions(m_s.prior.resolutions, cap), np);
    m_has_zones = true;
    drop_fitting(false);
    return m_s.zones;
  }

  /// fits the superquadrics with `fit_superquadrics()`, computing the zones (and the prior and the
  /// distance field) if missing.
  /// \throws Invalid_input (`INVALID_PARAMETER`) if the prior and the distance field have different
  /// resolutions.
  template <typename ConcurrencyTag = CGAL::Sequential_tag,
            typename NamedParameters = CGAL::parameters::Default_named_parameters>
  const Superquadric_fitting_result<Geom_traits>& fit_primitives(const NamedParameters& np = CGAL::parameters::default_values())
  {
    check_frame_parameters(np);
    if(!m_has_zones) compute_fitting_zones<ConcurrencyTag>(np);
    m_s.fitting = fit_superquadrics<ConcurrencyTag, Geom_traits>(m_s.prior, m_s.tsdf, m_s.zones, np);
    m_has_fitting = true;
    drop_parts();
    return m_s.fitting;
  }

  /// computes the over-segmentation with `Part_decomposition::over_segment()` and returns the
  /// number of patches.
  template <typename ConcurrencyTag = CGAL::Sequential_tag,
            typename NamedParameters = CGAL::parameters::Default_named_parameters>
  std::size_t over_segment(const NamedParameters& np = CGAL::parameters::default_values())
  {
    m_s.volumetric.patches.assign(num_faces(m_tm), 0);
    const std::size_t count = Part_decomposition::over_segment<ConcurrencyTag>(
      m_tm, boost::make_iterator_property_map(m_s.volumetric.patches.begin(), m_fim), with_mesh(np));
    m_has_patches = true;
    drop_parts();
    return count;
  }

  /*!
  computes the parts as `decompose()` does before its part hierarchy, writes the part id (0 to
  `K-1`) of every face to `face_part_map`, once, and returns `K`: if `needs_volumetric_stages(np)`,
  the primitives are assigned to the patches (`assign_parts()`), the residual patches kept
  (`separate_residual_patches()`) with `keep_residual_patches(true)` and the thin sheets merged
  (`merge_thin_sheet_parts()`) unless `merge_thin_sheets(false)` is given; then the parts are
  composed with the pieces (`Part_decomposition::compose_parts()`). The stages it needs are
  computed if missing. Part `k` is explained by `part_primitives()[k]`.
  \tparam FacePartMap a model of `WritablePropertyMap` with
  `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and `std::size_t` as value type
  */
  template <typename ConcurrencyTag = CGAL::Sequential_tag, typename FacePartMap,
            typename NamedParameters = CGAL::parameters::Default_named_parameters>
  std::size_t compose_parts(FacePartMap face_part_map, const NamedParameters& np = CGAL::parameters::default_values())
  {
    const auto mnp = with_mesh(np);
    m_use_pieces = internal::read_piece_parameters(np).use_pieces;
    bool fitted = needs_volumetric_stages(np);
    // the distance field may show that no piece bounds a volume
    if(fitted && m_use_pieces && !m_has_tsdf)
    {
      compute_distance_field<ConcurrencyTag>(np);
      fitted = needs_volumetric_stages(np);
    }
    if(fitted)
    {
      if(!m_has_fitting) fit_primitives<ConcurrencyTag>(np);
      if(!m_has_patches) over_segment<ConcurrencyTag>(np);
    }
    m_s.volumetric.parts.clear();
    m_s.volumetric.residual_faces.clear();
    internal::run_part_stages<ConcurrencyTag>(m_tm, mnp, fitted, m_s);
    m_has_parts = true;
    m_has_hierarchy = false;
    internal::put_face_values(m_tm, m_fim, m_s.composed.parts, face_part_map);
    return m_s.composed.number_of_parts();
  }

  /*!
  builds the part hierarchy of the parts of `compose_parts()` with
  `Part_decomposition::build_part_hierarchy(tm, pieces, parts, np)` and returns it, composing the
  parts with default named parameters if they are missing. The parts of `compose_parts()` are
  level `part_primitives().size()` of the tree. `decompose()` goes on from that level with
  `Part_hierarchy::level_below_cost()` (named parameter `maximum_merge_cost`), from which merges
  are ordered by size first.
  */
  const Part_hierarchy<Geom_traits>& build_hierarchy(double maximum_merge_cost = defaults::maximum_merge_cost)
  {
    internal::check_non_negative(maximum_merge_cost, "maximum_merge_cost");
    if(!m_has_parts) compose_parts(boost::dummy_property_map());
    m_s.hierarchy = build_part_hierarchy(
      m_tm, m_s.pieces, m_s.composed,
      with_mesh(parameters::combine(parameters::use_pieces(m_use_pieces), parameters::maximum_merge_cost(maximum_merge_cost))));
    m_has_hierarchy = true;
    return m_s.hierarchy;
  }

  /*!
  writes the parts of level `k` of the hierarchy to `face_part_map` (ids `0` to `k - 1`, numbered
  by smallest face index), their superquadrics to `primitives` in the same order, and returns `k`,
  building the hierarchy if it is missing. A `k` above the number of leaves is clamped to it.
  \tparam FacePartMap a model of `WritablePropertyMap` with
  `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and `std::size_t` as value type
  \tparam OutputIterator a model of `OutputIterator` accepting `Superquadric<Geom_traits>`
  \throws Invalid_input (`INVALID_PARAMETER`) if `k` is 0.
  */
  template <typename FacePartMap, typename OutputIterator = CGAL::Emptyset_iterator>
  std::size_t parts_at_level(std::size_t k, FacePartMap face_part_map, OutputIterator primitives = OutputIterator())
  {
    internal::check_parameter(k >= 1, "number_of_parts");
    if(!m_has_hierarchy) build_hierarchy();
    k = (std::min)(k, m_s.hierarchy.number_of_leaves());
    internal::put_face_values(m_tm, m_fim, m_s.hierarchy.labels(k), face_part_map);
    for(const Primitive& q : m_s.hierarchy.primitives(k)) *primitives++ = q;
    return k;
  }
  /// @}

  /// \name Results
  /// Each is empty until its stage has run.
  /// @{

  /// the pieces and their regions; once the distance field is computed, an open piece that
  /// bounds a volume faces out of it, and its regions are those of that orientation.
  const Piece_segmentation& pieces() const { return m_s.pieces; }
  /// the normalization of the mesh into the cube of the grids.
  const Normalization& normalization() const { return m_normalization; }
  /// the face index map that indexes `patches()` and `parts()`.
  const Face_index_map& face_index_map() const { return m_fim; }
  /// the prior.
  const Hierarchical_prior& prior() const { return m_s.prior; }
  /// the zones of the fitter.
  const Fitting_zones& fitting_zones() const { return m_s.zones; }
  /// the distance field.
  const Truncated_signed_distance_field& distance_field() const { return m_s.tsdf; }
  /// the fitted primitives and claimed leaves.
  const Superquadric_fitting_result<Geom_traits>& fitting() const { return m_s.fitting; }
  /// the patch of each face, indexed by the face index map.
  const std::vector<std::size_t>& patches() const { return m_s.volumetric.patches; }
  /// the parts of the volumetric stages, before their composition with the pieces.
  const Volumetric_parts& volumetric_parts() const { return m_s.volumetric; }
  /// the parts of `compose_parts()`.
  const Composed_parts<Geom_traits>& composed_parts() const { return m_s.composed; }
  /// the part of each face, indexed by the face index map.
  const std::vector<std::size_t>& parts() const { return m_s.composed.parts; }
  /// for each part, the index in `fitting().primitives` of its primitive, or `no_primitive`.
  const std::vector<std::size_t>& part_to_primitive() const { return m_s.composed.part_to_primitive; }
  /// for each part, its superquadric in input coordinates (see `Composed_parts::part_primitives`).
  const std::vector<Primitive>& part_primitives() const { return m_s.composed.part_primitives; }
  /// per part, 1 if it is a residual part (see the named parameter `keep_residual_patches` of
  /// `decompose()`), whose superquadric is only the box-like superquadric of its bounding box.
  const std::vector<std::uint8_t>& residual_parts() const { return m_s.composed.residual_parts; }
  /// the part hierarchy.
  const Part_hierarchy<Geom_traits>& hierarchy() const { return m_s.hierarchy; }
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

  // A normalization or margin given to one stage would put its grids in another frame.
  template <typename NamedParameters>
  void check_frame_parameters(const NamedParameters& np) const
  {
    using CGAL::parameters::choose_parameter;
    using CGAL::parameters::get_parameter;
    internal::check_parameter(
      internal::same_frame(choose_parameter(get_parameter(np, internal_np::normalization), m_normalization), m_normalization),
      "normalization", "the decomposer's (same center and scale)");
    internal::check_parameter(choose_parameter(get_parameter(np, internal_np::normalization_margin), m_margin) == m_margin,
                              "normalization_margin", "the decomposer's (given to its constructor)");
  }

  // The volumetric pieces, computed once per pieces and distance field (they turn the pieces).
  template <typename NamedParameters>
  const std::vector<std::uint8_t>& volumetric_pieces(const NamedParameters& np)
  {
    if(m_s.volumetric_pieces.empty())
      m_s.volumetric_pieces = Part_decomposition::volumetric_pieces(m_tm, m_s.pieces, m_s.tsdf, with_mesh(np));
    return m_s.volumetric_pieces;
  }

  void drop_parts() { m_has_parts = m_has_hierarchy = false; }
  void drop_fitting(bool zones = true)
  {
    if(zones) m_has_zones = false;
    m_has_fitting = false;
    drop_parts();
  }

  const TriangleMesh& m_tm;
  Vertex_point_map m_vpm;
  Face_index_map m_fim;
  double m_margin;
  Normalization m_normalization;
  Piece_segmentation m_segmented; // as segmented, before volumetric_pieces() turned open pieces
  internal::Stage_results<Geom_traits> m_s;
  bool m_use_pieces = true; // of the last compose_parts(), for the hierarchy
  // which results are up to date; the stages compute the missing ones
  bool m_has_pieces = false, m_has_prior = false, m_has_tsdf = false, m_has_zones = false, m_has_fitting = false,
       m_has_patches = false, m_has_parts = false, m_has_hierarchy = false;
};

/*!
\ingroup PkgPartDecompositionRef
decomposes the triangle mesh `tm` into parts with the Hi-TOPS method (paper Algorithm A.1) and
writes the part id of every face, from 0 to `K-1`, to `face_part_map`. Each part is explained by
one superquadric, optionally written to an output iterator. The same input and parameters give
the same output, whatever the number of threads.

It is the sequence of the stage functions, which give the same parts when called in this
order with the same named parameters (see the user manual): `segment_pieces()` and
`splittable_pieces()`; if a piece is splittable, `compute_tsdf()` and `volumetric_pieces()`; if a
piece is volumetric, `compute_flow_freeze_prior()`, `compute_fitting_zones()`,
`fit_superquadrics()`, `over_segment()`, `assign_parts()`, `separate_residual_patches()` (with
`keep_residual_patches`) and `merge_thin_sheet_parts()`; then `compose_parts()` and the part
hierarchy (`build_part_hierarchy()`), whose merges go on from the composed parts as long as they
cost less than `maximum_merge_cost`. `Part_decomposer` keeps the result of each. When no piece is
volumetric and the open sheets that `inflate_sheets()` inflates hold at least half of the area
and have limbs (a cut-out figure, a relief; see `inflate_sheets()`), the stages up to `compose_parts()` run on that solid instead, each face
takes the part of its copy, and the hierarchy measures its parts on the solid's side of their
normals (`Part_decomposer` does not take this path). Every named
parameter of these functions is accepted here and passed to the stage that reads it; the table below lists them all, as does
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
  \cgalParamNBegin{use_concave_curvature}
    \cgalParamDescription{whether the curvature of the convex vertices is left out (the minima rule);
                          `false` gives the paper's \f$|H|/2\f$ at every vertex}
    \cgalParamType{`bool`}
    \cgalParamDefault{`true`}
  \cgalParamNEnd
  \cgalParamNBegin{cue_weights}
    \cgalParamDescription{\f$\lambda\f$: the weights of the curvature mean, curvature deviation,
                          curvature gradient and normal deviation in the topology score}
    \cgalParamType{`std::array<double, 4>`}
    \cgalParamDefault{`{1, 1, 1, 0}`: the normal deviation, which counts convex edges too, is off}
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
  \cgalParamNBegin{grid_resolution}
    \cgalParamDescription{the resolution of the finest leaves of the adaptive grid of the volume
                          stages, where the shape is thin (see `compute_tsdf()`); raised to the finest
                          of `voxel_resolutions` if below it}
    \cgalParamType{`int`, a power of two up to 256}
    \cgalParamDefault{`128`}
  \cgalParamNEnd
  \cgalParamNBegin{adaptive_grid}
    \cgalParamDescription{`false`: every leaf of the grid is a voxel of the finest of
                          `voxel_resolutions`, the dense grid of the paper}
    \cgalParamType{`bool`}
    \cgalParamDefault{`true`}
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
                          `Composed_parts::residual_parts` (`separate_residual_patches()`); like any part, it joins a neighbour if it
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
                          `volumetric_pieces()`). If `false`, the parts are
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
                          hierarchy (`build_part_hierarchy()`), each with the superquadric
                          of its node; a \f$k\f$ above the number of leaves of the hierarchy gives its
                          leaves. Without it, the parts are those of the default granularity.}
    \cgalParamType{`std::size_t`, at least 1}
    \cgalParamDefault{none}
  \cgalParamNEnd
  \cgalParamNBegin{maximum_merge_cost}
    \cgalParamDescription{the default granularity: the parts of `compose_parts()` go on
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
    \cgalParamDescription{if not null, receives the part hierarchy (`build_part_hierarchy()`),
                          built after the parts; its `default_number_of_parts` is the number of
                          parts of the default granularity (after the merges below
                          `maximum_merge_cost`)}
    \cgalParamType{`Part_hierarchy<GeomTraits>*`}
    \cgalParamDefault{`nullptr`}
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
  const auto t0 = std::chrono::steady_clock::now();
  check_input(tm, np);
  const auto fim = CGAL::get_initialized_face_index_map(tm, np);
  // the normalization of every stage; a given one must be it
  const Normalization normalization = compute_normalization(tm, np);
  internal::check_parameter(
    internal::same_frame(choose_parameter(get_parameter(np, internal_np::normalization), normalization), normalization),
    "normalization", "the one computed from normalization_margin (same center and scale)");
  internal::check_stage_parameters(np);
  Stage_timings timings;
  internal::Decomposition_pass<GT> pass;
  internal::Stage_results<GT> s;
  // every stage reads the face graphs built here once
  const internal::Face_graphs graphs = internal::add_seconds(timings.pieces, [&] {
    return internal::build_face_graphs<ConcurrencyTag>(
      tm, fim, choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm)),
      np);
  });
  internal::decompose_once<ConcurrencyTag>(
    tm, parameters::combine(np, parameters::normalization(normalization), internal::face_graphs_parameter(&graphs)), s,
    pass, timings);
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
