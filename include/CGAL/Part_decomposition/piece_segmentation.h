// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_PIECE_SEGMENTATION_H
#define CGAL_PART_DECOMPOSITION_PIECE_SEGMENTATION_H

#include <CGAL/Part_decomposition/parameters.h>
#include <CGAL/Part_decomposition/stage_results.h>
#include <CGAL/Part_decomposition/input_validation.h>
#include <CGAL/Part_decomposition/internal/toolbox/face_adjacency.h>
#include <CGAL/Part_decomposition/internal/parts/piece_regions.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

// The package parameters of `segment_pieces()` and of the part composition that uses it.
struct Piece_parameters
{
  bool use_pieces = Method_variant().use_pieces;
  double crease_angle = defaults::crease_angle;
  double minimum_part_area = defaults::minimum_part_area;
};

template <typename NamedParameters>
Piece_parameters read_piece_parameters(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  namespace inp = Part_decomposition::internal_np;
  Piece_parameters p;
  p.use_pieces = internal::method_switches(np).use_pieces;
  p.crease_angle = choose_parameter(get_parameter(np, inp::crease_angle), p.crease_angle);
  p.minimum_part_area = choose_parameter(get_parameter(np, inp::minimum_part_area), p.minimum_part_area);
  check_parameter(p.crease_angle > 0. && p.crease_angle <= 180., "crease_angle");
  check_parameter(p.minimum_part_area >= 0. && p.minimum_part_area <= 1., "minimum_part_area");
  return p;
}

// `segment_pieces()` on the face graph `adj`.
template <typename ConcurrencyTag>
Piece_segmentation segment_pieces_of_graph(const Face_adjacency& adj, const Piece_parameters& p)
{
  Piece_segmentation s;
  s.number_of_pieces = label_pieces<ConcurrencyTag>(adj, s.piece);
  s.closed = closed_pieces(adj, s.piece, s.number_of_pieces);
  s.orientation = piece_orientations(adj, s.piece, s.closed, p.crease_angle);
  s.number_of_regions = crease_regions<ConcurrencyTag>(adj, s.piece, s.orientation, p.crease_angle, s.region);
  for(double a : adj.area) s.area += a;
  return s;
}

} // namespace internal

/*!
\ingroup PkgPartDecompositionRef
splits `tm` into its pieces and each piece into the regions between its concave creases: the
evidence that an assembly of separate pieces (a CAD model, an artist's mesh) carries about its
parts, which the volume-based stages cannot see. This stage is not in the paper.

1. <b>Pieces.</b> The edge-connected components of the faces, two faces being connected when
   they share an edge or have edges with the same two end points (an edge that the reader split
   because it is non-manifold, or because its faces have opposite orientations). Pieces that only
   touch at a vertex or pass through each other are separate. A piece is <em>closed</em> if every
   edge of its faces has exactly two faces (no border edge, no edge of three faces or more).
   Whether a piece bounds a volume is not decided here but by the distance field (see
   `volumetric_pieces()`): a scan with holes does, an open sheet does not.
2. <b>Orientation.</b> A closed piece keeps its orientation (the reader orients it outward). An
   open shell has no outside; it is taken in the orientation that makes most of its creases
   convex (the edges of dihedral angle at least `crease_angle`, each weighted by the area of the
   smaller of its two faces): the surface of a man-made piece is convex except where two of its
   parts meet.
3. <b>Regions.</b> An interior edge is a <em>concave crease</em> if its dihedral angle (as in
   `over_segment()`) is at least `crease_angle` and the neighbouring face bends towards the
   normal of the face (its centroid lies above the face's plane); an edge of a face of zero area
   (no normal) never is. An edge of three faces or more separates regions too: sheets meet there.
   The regions are the connected components of each piece across the other edges, faces with the
   same three corners being always in one region: parts meet along concave creases (the minima
   rule of Hoffman and Richards).
4. Pieces and regions are numbered by increasing smallest face index.

The result does not depend on the number of threads.

\par Complexity
Linear in the number of faces, up to the inverse Ackermann factor of the union-find.

\tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag` (needs TBB); the face
        normals and dihedral angles are computed in parallel
\tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
\tparam NamedParameters a sequence of named parameters

\param tm the triangle mesh
\param np an optional sequence of named parameters; this function reads `vertex_point_map`,
`face_index_map`, `geom_traits` (\ref PD_MeshParameters) and `crease_angle`
(\ref PD_ParameterTable); it checks the range of `minimum_part_area`, which `splittable_pieces()`
and `compose_parts()` read. `decompose()` segments the pieces unless the switch `use_pieces` of
`method_variant` is `false`.

\pre `CGAL::is_triangle_mesh(tm)`

\returns the pieces and regions, indexed by the face index map.

\throws Invalid_input (`INVALID_PARAMETER`) if `crease_angle` is out of its range.
*/
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename TriangleMesh,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Piece_segmentation segment_pieces(const TriangleMesh& tm,
                                  const NamedParameters& np = CGAL::parameters::default_values())
{
  internal::static_check_concurrency_tag<ConcurrencyTag>();
  const internal::Piece_parameters p = internal::read_piece_parameters(np);
  CGAL_precondition(CGAL::is_triangle_mesh(tm));
  const auto fim = CGAL::get_initialized_face_index_map(tm, np);
  const auto vpm = CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                                      get_const_property_map(CGAL::vertex_point, tm));
  return internal::segment_pieces_of_graph<ConcurrencyTag>(*internal::shared_piece_adjacency<ConcurrencyTag>(tm, fim, vpm, np), p);
}

} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_PIECE_SEGMENTATION_H
