// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_PART_DECOMPOSER_H
#define CGAL_PART_DECOMPOSITION_PART_DECOMPOSER_H

#include <CGAL/Part_decomposition/Superquadric.h>
#include <CGAL/Part_decomposition/fitting_zones.h>
#include <CGAL/Part_decomposition/flow_freeze_prior.h>
#include <CGAL/Part_decomposition/input_validation.h>
#include <CGAL/Part_decomposition/normalization.h>
#include <CGAL/Part_decomposition/over_segmentation.h>
#include <CGAL/Part_decomposition/part_composition.h>
#include <CGAL/Part_decomposition/part_hierarchy.h>
#include <CGAL/Part_decomposition/parameters.h>
#include <CGAL/Part_decomposition/stage_results.h>
#include <CGAL/Part_decomposition/piece_segmentation.h>
#include <CGAL/Part_decomposition/primitive_assignment.h>
#include <CGAL/Part_decomposition/superquadric_fitting.h>
#include <CGAL/Part_decomposition/thin_sheet_merging.h>
#include <CGAL/Part_decomposition/tsdf.h>
#include <CGAL/Part_decomposition/internal/parts/patch_operations.h>
#include <CGAL/Part_decomposition/internal/toolbox/toolbox.h>


#include <CGAL/Default.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Part_decomposition {

/// \cond SKIP_IN_MANUAL
// What the stages of `Part_decomposer` share.
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
    const Method_variant switches = method_switches(np);
    if(switches.keep_residual_patches) separate_residual_patches(tm, v, s.prior, s.fitting, np);
    if(switches.merge_thin_sheets)
      merge_thin_sheet_parts<ConcurrencyTag>(tm, part_map, v.part_to_primitive, s.fitting, s.tsdf, np);
  }
  s.composed = Part_decomposition::compose_parts<ConcurrencyTag>(tm, s.pieces, s.volumetric_pieces, v, s.fitting, np);
}

} // namespace internal
/// \endcond

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
merges: `decompose()` runs its stages through a decomposer, then cuts the part hierarchy. With
`CGAL::Parallel_tag`, `compose_parts()` runs the over-segmentation beside the volumetric stages
when both are missing. The results of a stage not computed yet are empty. A named parameter out of its range,
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
    internal::add_seconds(m_timings.pieces,
                          [&] { m_segmented = Part_decomposition::segment_pieces<ConcurrencyTag>(m_tm, with_mesh(np)); });
    m_splittable.clear();
    m_s.pieces = m_segmented;
    m_s.volumetric_pieces.clear();
    computed(PIECES);
    if(has(DISTANCE_FIELD)) volumetric_pieces<ConcurrencyTag>(np);
    return m_s.pieces;
  }

  /// whether the parts of `compose_parts()` with the named parameters `np` need the volumetric
  /// stages (prior, distance field, fit, over-segmentation): with `use_pieces = false`, or if a
  /// piece is splittable (`splittable_pieces()`) and, once the distance field is computed, the
  /// volumetric stages decompose it (`volumetric_pieces()`). Before the distance field is known,
  /// it tells whether it is worth computing. Segments the pieces if they are missing.
  template <typename ConcurrencyTag = CGAL::Sequential_tag,
            typename NamedParameters = CGAL::parameters::Default_named_parameters>
  bool needs_volumetric_stages(const NamedParameters& np = CGAL::parameters::default_values())
  {
    if(!internal::read_piece_parameters(np).use_pieces) return true;
    if(!has(PIECES)) segment_pieces<ConcurrencyTag>(np);
    if(has(DISTANCE_FIELD)) return internal::any_of_flags(volumetric_pieces<ConcurrencyTag>(np));
    return internal::any_of_flags(splittable<ConcurrencyTag>(np));
  }

  /// computes the hierarchical Flow/Freeze prior with `compute_flow_freeze_prior()`; the distance
  /// field, whose grid the prior shapes, is then out of date.
  template <typename ConcurrencyTag = CGAL::Sequential_tag,
            typename NamedParameters = CGAL::parameters::Default_named_parameters>
  const Hierarchical_prior& compute_prior(const NamedParameters& np = CGAL::parameters::default_values())
  {
    internal::add_seconds(m_timings.prior, [&] { m_s.prior = compute_flow_freeze_prior<ConcurrencyTag>(m_tm, with_mesh(np)); });
    computed(PRIOR);
    m_s.pieces = m_segmented;
    m_s.volumetric_pieces.clear();
    return m_s.prior;
  }

  /// computes the truncated signed distance field with `compute_tsdf()` on the grid the prior
  /// asks for, computing the prior if missing; once the pieces are segmented too, an open piece
  /// that bounds a volume of it faces out of it (`volumetric_pieces()`).
  template <typename ConcurrencyTag = CGAL::Sequential_tag,
            typename NamedParameters = CGAL::parameters::Default_named_parameters>
  const Truncated_signed_distance_field& compute_distance_field(const NamedParameters& np = CGAL::parameters::default_values())
  {
    if(!has(PRIOR)) compute_prior<ConcurrencyTag>(np);
    std::vector<std::uint8_t> thin_faces;
    const bool use_pieces = internal::read_piece_parameters(np).use_pieces;
    if(use_pieces)
    {
      if(!has(PIECES)) segment_pieces<ConcurrencyTag>(np);
      thin_faces = internal::faces_of_pieces(m_segmented, splittable<ConcurrencyTag>(np));
    }
    internal::add_seconds(m_timings.tsdf, [&] {
      m_s.tsdf = internal::compute_tsdf_of_checked_mesh<ConcurrencyTag>(m_tm, &m_s.prior, with_mesh(np),
                                                                        use_pieces ? &thin_faces : nullptr);
    });
    computed(DISTANCE_FIELD);
    m_s.pieces = m_segmented;
    m_s.volumetric_pieces.clear();
    if(has(PIECES)) volumetric_pieces<ConcurrencyTag>(np);
    return m_s.tsdf;
  }

  /// computes the zones of the fitter with `Part_decomposition::compute_fitting_zones()` at the
  /// `fitting_resolutions()` of the prior with the `fitting_resolution_cap` of `np`, computing the
  /// prior and the distance field if missing. `fit_primitives()` computes them if missing.
  template <typename ConcurrencyTag = CGAL::Sequential_tag,
            typename NamedParameters = CGAL::parameters::Default_named_parameters>
  const Fitting_zones& compute_fitting_zones(const NamedParameters& np = CGAL::parameters::default_values())
  {
    if(!has(PRIOR)) compute_prior<ConcurrencyTag>(np);
    if(!has(DISTANCE_FIELD)) compute_distance_field<ConcurrencyTag>(np);
    const int cap = internal::read_fitting_parameters(np).fitting_resolution_cap;
    double seconds = 0.;
    internal::add_seconds(seconds, [&] {
      m_s.zones = Part_decomposition::compute_fitting_zones<ConcurrencyTag>(
        m_s.prior, m_s.tsdf, fitting_resolutions(m_s.prior.resolutions, cap), np);
    });
    // the fitting's time includes its zones'
    m_timings.fitting_zones += seconds;
    m_timings.fitting += seconds;
    computed(ZONES);
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
    if(!has(ZONES)) compute_fitting_zones<ConcurrencyTag>(np);
    internal::add_seconds(m_timings.fitting, [&] {
      m_s.fitting = fit_superquadrics<ConcurrencyTag, Geom_traits>(m_s.prior, m_s.tsdf, m_s.zones, np);
    });
    computed(FITTING);
    return m_s.fitting;
  }

  /// computes the over-segmentation with `Part_decomposition::over_segment()` and returns the
  /// number of patches.
  template <typename ConcurrencyTag = CGAL::Sequential_tag,
            typename NamedParameters = CGAL::parameters::Default_named_parameters>
  std::size_t over_segment(const NamedParameters& np = CGAL::parameters::default_values())
  {
    const std::size_t count = patches_into<ConcurrencyTag>(m_s.volumetric.patches, np);
    computed(PATCHES);
    return count;
  }

  /*!
  computes the parts as `decompose()` does before its part hierarchy, writes the part id (0 to
  `K-1`) of every face to `face_part_map`, once, and returns `K`: if `needs_volumetric_stages(np)`,
  the primitives are assigned to the patches (`assign_parts()`), the residual patches kept
  (`separate_residual_patches()`) with `keep_residual_patches = true` and the thin sheets merged
  (`merge_thin_sheet_parts()`) unless `merge_thin_sheets = false` is given; then the parts are
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
    m_switches = internal::method_switches(np);
    bool fitted = needs_volumetric_stages<ConcurrencyTag>(np);
    if(fitted && !has(FITTING) && !has(PATCHES))
    {
      // The fitting's own loops are short (one primitive at a time), so its sequential part is the
      // longest of the stages: the over-segmentation runs next to the volumetric stages.
      std::vector<std::size_t> patches;
      m_timings.overlapping = m_timings.overlapping || internal::is_parallel_tag<ConcurrencyTag>();
      internal::run_side_by_side<ConcurrencyTag>([&] { fitted = fit_if_volumetric<ConcurrencyTag>(np); },
                                                 [&] { patches_into<ConcurrencyTag>(patches, np); });
      m_s.volumetric.patches = std::move(patches);
      computed(PATCHES);
    }
    else if(fitted)
    {
      fitted = has(FITTING) || fit_if_volumetric<ConcurrencyTag>(np);
      if(fitted && !has(PATCHES)) over_segment<ConcurrencyTag>(np);
    }
    m_s.volumetric.parts.clear();
    m_s.volumetric.residual_faces.clear();
    internal::add_seconds(m_timings.assignment, [&] { internal::run_part_stages<ConcurrencyTag>(m_tm, mnp, fitted, m_s); });
    computed(PARTS);
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
  \tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag`; the tree is the same
  */
  template <typename ConcurrencyTag = CGAL::Sequential_tag>
  const Part_hierarchy<Geom_traits>& build_hierarchy(double maximum_merge_cost = defaults::maximum_merge_cost)
  {
    internal::check_non_negative(maximum_merge_cost, "maximum_merge_cost");
    if(!has(PARTS)) compose_parts<ConcurrencyTag>(boost::dummy_property_map());
    internal::add_seconds(m_timings.hierarchy, [&] {
      m_s.hierarchy = build_part_hierarchy<ConcurrencyTag>(m_tm, m_s.pieces, m_s.composed,
                                           with_mesh(parameters::combine(parameters::method_variant(m_switches),
                                                                         parameters::maximum_merge_cost(maximum_merge_cost))));
    });
    computed(HIERARCHY);
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
    if(!has(HIERARCHY)) build_hierarchy();
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
  /// per part, 1 if it is a residual part (see the switch `keep_residual_patches` of
  /// `decompose()`), whose superquadric is only the box-like superquadric of its bounding box.
  const std::vector<std::uint8_t>& residual_parts() const { return m_s.composed.residual_parts; }
  /// the part hierarchy.
  const Part_hierarchy<Geom_traits>& hierarchy() const { return m_s.hierarchy; }
  /// the seconds spent in each stage by this decomposer, summed over its calls (`total` is 0; with
  /// a parallel `compose_parts()`, the over-segmentation runs beside the volumetric stages and
  /// `overlapping` is `true`).
  const Stage_timings& stage_timings() const { return m_timings; }
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
      internal::same_frame(
        internal::optional_parameter<Normalization>(np, internal_np::normalization).value_or(m_normalization),
        m_normalization),
      "normalization", "the decomposer's (same center and scale)");
    internal::check_parameter(choose_parameter(get_parameter(np, internal_np::normalization_margin), m_margin) == m_margin,
                              "normalization_margin", "the decomposer's (given to its constructor)");
  }

  // The over-segmentation into `patches` (indexed by the face index map), timed; the stage's
  // bookkeeping is left to the caller, so that it may run beside the other stages.
  template <typename ConcurrencyTag, typename NamedParameters>
  std::size_t patches_into(std::vector<std::size_t>& patches, const NamedParameters& np)
  {
    return internal::add_seconds(m_timings.over_segmentation, [&] {
      patches.assign(num_faces(m_tm), 0);
      return Part_decomposition::over_segment<ConcurrencyTag>(
        m_tm, boost::make_iterator_property_map(patches.begin(), m_fim), with_mesh(np));
    });
  }

  // The primitives if the volumetric stages decompose a piece (always without pieces): the distance
  // field may show that no piece bounds a volume. Returns whether they were fitted.
  template <typename ConcurrencyTag, typename NamedParameters>
  bool fit_if_volumetric(const NamedParameters& np)
  {
    if(m_switches.use_pieces && !has(DISTANCE_FIELD))
    {
      compute_distance_field<ConcurrencyTag>(np);
      if(!needs_volumetric_stages<ConcurrencyTag>(np)) return false;
    }
    fit_primitives<ConcurrencyTag>(np);
    return true;
  }

  // The volumetric pieces, computed once per pieces and distance field (they turn the pieces).
  template <typename ConcurrencyTag, typename NamedParameters>
  const std::vector<std::uint8_t>& volumetric_pieces(const NamedParameters& np)
  {
    if(m_s.volumetric_pieces.empty())
      m_s.volumetric_pieces =
        Part_decomposition::volumetric_pieces<ConcurrencyTag>(m_tm, m_s.pieces, m_s.tsdf, with_mesh(np));
    return m_s.volumetric_pieces;
  }

  // The splittable pieces of the segmented pieces, computed once per segmentation.
  template <typename ConcurrencyTag, typename NamedParameters>
  const std::vector<std::uint8_t>& splittable(const NamedParameters& np)
  {
    if(m_splittable.empty())
      internal::add_seconds(m_timings.pieces, [&] {
        m_splittable = Part_decomposition::splittable_pieces<ConcurrencyTag>(m_tm, m_segmented, with_mesh(np));
      });
    return m_splittable;
  }

  // The stage dependencies, written once: the stages each result feeds directly. A stage computed
  // anew drops the results it feeds, and theirs.
  enum Stage { PIECES, PRIOR, DISTANCE_FIELD, ZONES, FITTING, PATCHES, PARTS, HIERARCHY, NUMBER_OF_STAGES };
  static unsigned int feeds(Stage s)
  {
    constexpr unsigned int direct[NUMBER_OF_STAGES] = {
      1u << PARTS,                                // pieces
      (1u << DISTANCE_FIELD) | (1u << ZONES),     // prior: the grid of the distance field and the zones
      1u << ZONES,                                // distance field
      1u << FITTING,                              // zones
      1u << PARTS,                                // fitting
      1u << PARTS,                                // patches
      1u << HIERARCHY,                            // parts
      0u};                                        // hierarchy
    return direct[s];
  }
  bool has(Stage s) const { return (m_computed >> s) & 1u; }
  void drop_fed_by(Stage s)
  {
    for(int t = 0; t < NUMBER_OF_STAGES; ++t)
      if((feeds(s) >> t) & 1u)
      {
        m_computed &= ~(1u << t);
        drop_fed_by(Stage(t));
      }
  }
  void computed(Stage s)
  {
    drop_fed_by(s);
    m_computed |= 1u << s;
  }

  const TriangleMesh& m_tm;
  Vertex_point_map m_vpm;
  Face_index_map m_fim;
  double m_margin;
  Normalization m_normalization;
  Piece_segmentation m_segmented; // as segmented, before volumetric_pieces() turned open pieces
  std::vector<std::uint8_t> m_splittable; // per piece of m_segmented; empty until known
  internal::Stage_results<Geom_traits> m_s;
  Method_variant m_switches; // of the last compose_parts(), for the hierarchy
  Stage_timings m_timings;
  // which results are up to date; the stages compute the missing ones
  unsigned int m_computed = 0; // the stages whose results are current, one bit per Stage
};

} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_PART_DECOMPOSER_H
