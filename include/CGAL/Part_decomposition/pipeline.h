// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_PIPELINE_H
#define CGAL_PART_DECOMPOSITION_PIPELINE_H

#include <CGAL/Part_decomposition/decompose.h>
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
#include <CGAL/Part_decomposition/internal/parts/patch_operations.h>
#include <CGAL/Part_decomposition/internal/toolbox/toolbox.h>

#include <CGAL/Bbox_3.h>
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

/// \cond SKIP_IN_MANUAL
// The stage functions composed: what `decompose()` and `Part_decomposer` run.
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

// `decompose()` on the pack of `pipeline_parameters()` (every value present, with the types of
// `CGAL_PART_DECOMPOSITION_PARAMETERS`): the parts per face index, their superquadrics and
// the time of each stage but the total. The compiled library holds it for the common mesh types.
template <typename ConcurrencyTag, typename TriangleMesh, typename NamedParameters>
void decompose_with_parameters(const TriangleMesh& tm, const NamedParameters& np,
                               Decomposition_pass<typename GetGeomTraits<TriangleMesh, NamedParameters>::type>& pass,
                               Stage_timings& timings)
{
  typedef typename GetGeomTraits<TriangleMesh, NamedParameters>::type GT;
  check_input(tm, np);
  const auto fim = CGAL::get_initialized_face_index_map(tm, np);
  // the normalization of every stage; a given one must be it
  const Normalization normalization = compute_normalization(tm, np);
  check_parameter(same_frame(optional_parameter<Normalization>(np, internal_np::normalization).value_or(normalization),
                             normalization),
                  "normalization", "the one computed from normalization_margin (same center and scale)");
  check_stage_parameters(np);
  Stage_results<GT> s;
  // every stage reads the face graphs built here once
  const Face_graphs graphs = add_seconds(timings.pieces, [&] {
    return build_face_graphs<ConcurrencyTag>(
      tm, fim, CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point), np);
  });
  decompose_once<ConcurrencyTag>(
    tm, parameters::combine(np, parameters::normalization(normalization), face_graphs_parameter(&graphs)), s, pass,
    timings);
}

} // namespace internal
/// \endcond

} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_PIPELINE_H
