// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_THIN_SHEET_MERGING_H
#define CGAL_PART_DECOMPOSITION_THIN_SHEET_MERGING_H

#include <CGAL/Part_decomposition/input_validation.h>
#include <CGAL/Part_decomposition/normalization.h>
#include <CGAL/Part_decomposition/parameters.h>
#include <CGAL/Part_decomposition/stage_results.h>
#include <CGAL/Part_decomposition/internal/face_adjacency.h>
#include <CGAL/Part_decomposition/internal/parameter_checks.h>
#include <CGAL/Part_decomposition/internal/sheet_merging.h>
#include <CGAL/Part_decomposition/internal/toolbox.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

// The package parameters of the thin-sheet merge: its switch in `decompose()`.
struct Sheet_merging_parameters
{
  bool merge_thin_sheets = defaults::merge_thin_sheets;
};

template <typename NamedParameters>
Sheet_merging_parameters read_sheet_merging_parameters(const NamedParameters& np)
{
  Sheet_merging_parameters p;
  p.merge_thin_sheets = CGAL::parameters::choose_parameter(
      CGAL::parameters::get_parameter(np, internal_np::merge_thin_sheets), p.merge_thin_sheets);
  return p;
}

} // namespace internal

/*!
\ingroup PkgPartDecompositionRef
merges the parts of a decomposition that tile one thin sheet: the stage of `decompose()` after
`assign_parts()` and before `compose_parts()` (its named parameter `merge_thin_sheets` is the switch). This step is not
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
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{vertex_point_map}
    \cgalParamDescription{a property map associating points to the vertices of `tm`}
    \cgalParamType{a class model of `ReadablePropertyMap` with
                   `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and
                   `%Point_3` as value type}
    \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
  \cgalParamNEnd
  \cgalParamNBegin{geom_traits}
    \cgalParamDescription{an instance of a geometric traits class, used for the face normals}
    \cgalParamType{a class model of `Kernel`}
    \cgalParamDefault{a \cgal kernel deduced from the point type, using `CGAL::Kernel_traits`}
  \cgalParamNEnd
  \cgalParamNBegin{face_index_map}
    \cgalParamDescription{a property map associating to each face of `tm` a unique index between
                          `0` and `num_faces(tm) - 1`}
    \cgalParamType{a class model of `ReadablePropertyMap` with
                   `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and
                   `std::size_t` as value type}
    \cgalParamDefault{an automatically indexed internal map}
  \cgalParamNEnd
\cgalNamedParamsEnd

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
