// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_PIPELINE_H
#define CGAL_PART_DECOMPOSITION_PIPELINE_H

#include <CGAL/Part_decomposition/Part_decomposer.h>
#include <CGAL/Part_decomposition/decompose.h>
#include <CGAL/Part_decomposition/part_hierarchy.h>
#include <CGAL/Part_decomposition/parameters.h>
#include <CGAL/Part_decomposition/sheet_inflation.h>
#include <CGAL/Part_decomposition/internal/toolbox/toolbox.h>

#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Part_decomposition {

/// \cond SKIP_IN_MANUAL
// `decompose()`: the decomposer's stages, then the part hierarchy's cut.
namespace internal {

// The hierarchy when it is asked for or its cheap merges may go on, and the parts of its level if
// it is not that of the composed parts.
template <typename ConcurrencyTag, typename GT, typename TriangleMesh, typename NamedParameters>
void cut_hierarchy(const TriangleMesh& tm, const NamedParameters& np, const Piece_segmentation& pieces,
                   const Composed_parts<GT>& composed_parts, Decomposition_pass<GT>& out, Stage_timings& t)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const Hierarchy_parameters hp = read_hierarchy_parameters(np);
  Part_hierarchy<GT>* hierarchy_out =
    choose_parameter(get_parameter(np, internal_np::part_hierarchy), static_cast<Part_hierarchy<GT>*>(nullptr));
  const std::size_t composed = composed_parts.number_of_parts();
  std::size_t K = composed;
  out.default_number_of_parts = composed;
  Part_hierarchy<GT> hierarchy;
  if(hp.has_number_of_parts || hierarchy_out != nullptr || (hp.maximum_merge_cost > 0. && composed > 1))
    add_seconds(t.hierarchy, [&] {
      hierarchy = build_part_hierarchy<ConcurrencyTag>(tm, pieces, composed_parts, np);
      out.default_number_of_parts = hierarchy.level_below_cost(composed, hp.maximum_merge_cost);
      K = hp.has_number_of_parts ? hp.number_of_parts : out.default_number_of_parts;
      if(hierarchy_out != nullptr)
      {
        *hierarchy_out = hierarchy;
        hierarchy_out->default_number_of_parts = out.default_number_of_parts;
      }
    });
  if(K == composed && !hp.has_number_of_parts)
  {
    out.parts = composed_parts.parts;
    out.primitives = composed_parts.part_primitives;
  }
  else
  {
    K = (std::min)(K, hierarchy.number_of_leaves());
    out.parts = hierarchy.labels(K);
    out.primitives = hierarchy.primitives(K);
  }
  out.number_of_parts = K;
}

// Adds the stage times of `from` to those of `to`.
inline void add_stage_timings(Stage_timings& to, const Stage_timings& from)
{
  to.pieces += from.pieces;
  to.prior += from.prior;
  to.tsdf += from.tsdf;
  to.fitting += from.fitting;
  to.fitting_zones += from.fitting_zones;
  to.over_segmentation += from.over_segmentation;
  to.assignment += from.assignment;
  to.hierarchy += from.hierarchy;
  to.overlapping = to.overlapping || from.overlapping;
}

// The composed parts of the decomposer's stages; returns whether a primitive was fitted. `np`
// holds the normalization.
template <typename ConcurrencyTag, typename Decomposer, typename NamedParameters>
bool compose_with(Decomposer& d, const NamedParameters& np, Stage_timings& timings)
{
  d.template compose_parts<ConcurrencyTag>(boost::dummy_property_map(), np);
  add_stage_timings(timings, d.stage_timings());
  // the volumetric parts are those of the primitives, and only fitted ones give them
  return !d.volumetric_parts().parts.empty();
}

// The composed parts of `tm` from those of the solid of its open sheets (`inflate_sheets()` of the
// faces `sheet`); returns per vertex index the point of `tm` on the solid's side of its normals.
template <typename ConcurrencyTag, typename GT, typename TriangleMesh, typename NamedParameters>
std::vector<typename GT::Point_3> compose_inflated_sheets(const TriangleMesh& tm, const NamedParameters& np,
                                                          const Face_corners& corners,
                                                          const std::vector<std::uint8_t>& sheet,
                                                          Composed_parts<GT>& composed, Stage_timings& timings)
{
  std::vector<typename GT::Point_3> raised;
  const auto solid = inflated_sheets(corners, sheet, raised);
  const double margin = CGAL::parameters::choose_parameter(
    CGAL::parameters::get_parameter(np, internal_np::normalization_margin), defaults::normalization_margin);
  Part_decomposer<std::decay_t<decltype(solid)>, GT> d(solid, get(CGAL::vertex_point, solid),
                                                       get(CGAL::face_index, solid), margin);
  const auto solid_np = parameters::combine(np, CGAL::parameters::vertex_point_map(get(CGAL::vertex_point, solid)),
                                            CGAL::parameters::face_index_map(get(CGAL::face_index, solid)),
                                            parameters::normalization(d.normalization()), face_graphs_parameter(nullptr));
  compose_with<ConcurrencyTag>(d, solid_np, timings);
  composed = composed_parts_of_first_faces(d.composed_parts(), num_faces(tm));
  return raised;
}

// `decompose()` on the decomposer `d` of `tm`: its composed parts, and the part hierarchy's cut;
// the solid of the open sheets when no piece bounds a volume. `np` holds the normalization.
template <typename ConcurrencyTag, typename GT, typename Decomposer, typename TriangleMesh, typename NamedParameters>
void decompose_once(Decomposer& d, const TriangleMesh& tm, const NamedParameters& np, Decomposition_pass<GT>& out,
                    Stage_timings& timings)
{
  timings.overlapping = is_parallel_tag<ConcurrencyTag>();
  const bool fitted = compose_with<ConcurrencyTag>(d, np, timings);
  if(fitted || !read_piece_parameters(np).use_pieces)
    return cut_hierarchy<ConcurrencyTag>(tm, np, d.pieces(), d.composed_parts(), out, timings);
  const Mesh_maps<TriangleMesh, NamedParameters> maps(tm, np);
  const auto shared_corners = shared_face_corners<ConcurrencyTag>(tm, maps.fim, maps.vpm, np);
  const Face_corners& corners = *shared_corners;
  std::vector<std::uint8_t> sheet;
  if(!decomposes_inflated_sheets(tm, d.pieces(), corners, np, sheet))
    return cut_hierarchy<ConcurrencyTag>(tm, np, d.pieces(), d.composed_parts(), out, timings);
  // the hierarchy measures the boxes of the sheets' parts on the solid's side of their normals: a
  // flat part has no volume, so that every merge of flat parts would be cheap
  Composed_parts<GT> composed;
  const std::vector<typename GT::Point_3> raised =
    compose_inflated_sheets<ConcurrencyTag>(tm, np, corners, sheet, composed, timings);
  const auto raised_map = boost::make_iterator_property_map(raised.begin(), CGAL::get_initialized_vertex_index_map(tm));
  cut_hierarchy<ConcurrencyTag>(tm, parameters::combine(np, CGAL::parameters::vertex_point_map(raised_map), face_graphs_parameter(nullptr)),
                d.pieces(), composed, out, timings);
}

// `decompose()` on the pack of `pipeline_parameters()` (every value present, with the types of
// `CGAL_PART_DECOMPOSITION_PARAMETERS`): the parts per face index, their superquadrics and
// the time of each stage but the total.
template <typename ConcurrencyTag, typename TriangleMesh, typename NamedParameters>
void decompose_with_parameters(const TriangleMesh& tm, const NamedParameters& np,
                               Decomposition_pass<typename GetGeomTraits<TriangleMesh, NamedParameters>::type>& pass,
                               Stage_timings& timings)
{
  typedef typename GetGeomTraits<TriangleMesh, NamedParameters>::type GT;
  const auto vpm = CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point);
  const auto fim = CGAL::parameters::get_parameter(np, CGAL::internal_np::face_index);
  // checks the input and computes the normalization of every stage; a given one must be it
  Part_decomposer<TriangleMesh, GT, std::decay_t<decltype(vpm)>, std::decay_t<decltype(fim)> > d(
    tm, vpm, fim, CGAL::parameters::get_parameter(np, internal_np::normalization_margin));
  check_parameter(same_frame(optional_parameter<Normalization>(np, internal_np::normalization).value_or(d.normalization()),
                             d.normalization()),
                  "normalization", "the one computed from normalization_margin (same center and scale)");
  check_stage_parameters(np);
  // every stage reads the face graphs built here once
  const Face_graphs graphs =
    add_seconds(timings.pieces, [&] { return build_face_graphs<ConcurrencyTag>(tm, fim, vpm, np); });
  decompose_once<ConcurrencyTag>(
    d, tm, parameters::combine(np, parameters::normalization(d.normalization()), face_graphs_parameter(&graphs)), pass,
    timings);
}

// The pack of named parameters of `decompose_values()`: every value present, in one type per mesh,
// vertex point map, face index map and traits.
template <typename GeomTraits, typename VertexPointMap, typename FaceIndexMap>
auto pipeline_parameters(const Pipeline_inputs<GeomTraits, VertexPointMap, FaceIndexMap>& in, const Pipeline_values& v)
{
  return parameters::combine(
    CGAL::parameters::geom_traits(in.traits), CGAL::parameters::vertex_point_map(in.vpm),
    CGAL::parameters::face_index_map(in.fim), parameters::normalization(in.normalization),
    parameters::part_hierarchy(in.hierarchy)
#define CGAL_PART_DECOMPOSITION_PIPELINE_VALUE(NAME, ...) , parameters::NAME(v.NAME)
#define CGAL_PART_DECOMPOSITION_PIPELINE_CGAL_VALUE(NAME, ...) , CGAL::parameters::NAME(v.NAME)
    CGAL_PART_DECOMPOSITION_PARAMETERS(CGAL_PART_DECOMPOSITION_PIPELINE_VALUE,
                                       CGAL_PART_DECOMPOSITION_PIPELINE_CGAL_VALUE)
#undef CGAL_PART_DECOMPOSITION_PIPELINE_CGAL_VALUE
#undef CGAL_PART_DECOMPOSITION_PIPELINE_VALUE
  );
}

template <typename ConcurrencyTag, typename TriangleMesh, typename GeomTraits, typename VertexPointMap,
          typename FaceIndexMap>
void decompose_values(const TriangleMesh& tm, const Pipeline_inputs<GeomTraits, VertexPointMap, FaceIndexMap>& in,
                      const Pipeline_values& values, Decomposition_pass<GeomTraits>& pass, Stage_timings& timings)
{
  decompose_with_parameters<ConcurrencyTag>(tm, pipeline_parameters(in, values), pass, timings);
}

} // namespace internal
/// \endcond


} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_PIPELINE_H
