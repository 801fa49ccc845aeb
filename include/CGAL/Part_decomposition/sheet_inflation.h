// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_SHEET_INFLATION_H
#define CGAL_PART_DECOMPOSITION_SHEET_INFLATION_H

#include <CGAL/Part_decomposition/part_composition.h>
#include <CGAL/Part_decomposition/stage_results.h>
#include <CGAL/Part_decomposition/internal/toolbox/face_adjacency.h>
#include <CGAL/Part_decomposition/internal/parts/patch_operations.h>
#include <CGAL/Part_decomposition/internal/parts/piece_regions.h>
#include <CGAL/Part_decomposition/internal/parts/sheet_inflation.h>

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

// A mesh of open sheets is decomposed as their solid (`inflate_sheets()`) if its open pieces free of
// junctions (not assemblies of sheets) hold at least this fraction of its area.
constexpr double minimum_inflated_area_fraction = 0.5;
// A sheet whose outline fills at least this fraction of its convex hull has no limbs to find: a
// plate or a disk stays one part without inflation.
constexpr double maximum_outline_fill = 0.9;

// Per face index, 1 if its piece is an open sheet that `inflate_sheets()` inflates: open and not
// an assembly of sheets (its junction chains below `maximum_junction_fraction`). `corners`: of `tm`.
template <typename TriangleMesh, typename NamedParameters>
std::vector<std::uint8_t> inflated_sheet_faces(const TriangleMesh& tm, const Piece_segmentation& pieces,
                                               const Face_corners& corners, const NamedParameters& np)
{
  const Mesh_maps<TriangleMesh, NamedParameters> maps(tm, np);
  const auto graph = shared_piece_adjacency<CGAL::Sequential_tag>(tm, maps.fim, maps.vpm, np);
  const std::vector<double> junction = junction_length_fractions(*graph, corners, pieces.piece, pieces.number_of_pieces);
  std::vector<std::uint8_t> sheet(graph->number_of_faces, 0);
  for(std::size_t i = 0; i < sheet.size(); ++i)
    sheet[i] = !pieces.closed[pieces.piece[i]] && junction[pieces.piece[i]] < maximum_junction_fraction;
  return sheet;
}

// Whether `decompose()` decomposes the solid of the open sheets of `tm`, given that no piece bounds
// a volume: the sheets it inflates (`sheet`, per face index) hold most of the area, and their
// outline has limbs (it fills less than `maximum_outline_fill` of its convex hull).
template <typename TriangleMesh, typename NamedParameters>
bool decomposes_inflated_sheets(const TriangleMesh& tm, const Piece_segmentation& pieces, const Face_corners& corners,
                                const NamedParameters& np, std::vector<std::uint8_t>& sheet)
{
  // most meshes without a volume are closed pieces: no sheet to look at
  if(std::all_of(pieces.closed.begin(), pieces.closed.end(), [](std::uint8_t c) { return c != 0; })) return false;
  sheet = inflated_sheet_faces(tm, pieces, corners, np);
  const Mesh_maps<TriangleMesh, NamedParameters> maps(tm, np);
  const std::vector<double>& area = shared_face_adjacency<CGAL::Sequential_tag>(tm, maps.fim, np)->area;
  double sheet_area = 0.;
  for(std::size_t i = 0; i < sheet.size(); ++i)
    if(sheet[i]) sheet_area += area[i];
  if(!(sheet_area > 0.) || sheet_area < minimum_inflated_area_fraction * pieces.area) return false;
  return outline_fill_fraction(corners.point, corners.vertex, sheet) < maximum_outline_fill;
}

// The composed parts of the faces [0, number_of_faces) of a mesh whose first faces are those of
// another mesh (the solid of `inflate_sheets()`), renumbered by first face.
template <typename GeomTraits>
Composed_parts<GeomTraits> composed_parts_of_first_faces(const Composed_parts<GeomTraits>& c, std::size_t number_of_faces)
{
  Composed_parts<GeomTraits> r;
  r.parts.assign(c.parts.begin(), c.parts.begin() + std::ptrdiff_t(number_of_faces));
  std::vector<std::size_t> former;
  renumber_by_first_face(r.parts, &former);
  for(std::size_t k : former)
  {
    r.part_to_primitive.push_back(c.part_to_primitive[k]);
    r.part_primitives.push_back(c.part_primitives[k]);
    r.residual_parts.push_back(c.residual_parts[k]);
  }
  r.finest_parts.assign(c.finest_parts.begin(), c.finest_parts.begin() + std::ptrdiff_t(number_of_faces));
  r.number_of_finest_parts = renumber_by_first_face(r.finest_parts);
  r.part_groups.assign(c.part_groups.begin(), c.part_groups.begin() + std::ptrdiff_t(number_of_faces));
  renumber_by_first_face(r.part_groups);
  return r;
}

// The solid of `inflate_sheets()` from the corners of `tm` and the faces to inflate; also returns,
// per vertex index of `tm` (`Face_corners`), its point on the side of the normals of the solid.
template <typename Point_3>
CGAL::Surface_mesh<Point_3> inflated_sheets(const Face_corners& corners, const std::vector<std::uint8_t>& sheet,
                                            std::vector<Point_3>& raised)
{
  std::vector<Eigen::Vector3d> points;
  std::vector<std::array<std::size_t, 3> > triangles;
  inflate_sheet_soup(corners.point, corners.vertex, sheet, points, triangles);
  std::vector<Point_3> soup_points;
  for(const Eigen::Vector3d& p : points) soup_points.emplace_back(p[0], p[1], p[2]);
  raised.assign(soup_points.begin(), soup_points.begin() + std::ptrdiff_t(corners.point.size()));
  namespace PMP = CGAL::Polygon_mesh_processing;
  PMP::orient_polygon_soup(soup_points, triangles);
  CGAL::Surface_mesh<Point_3> solid;
  PMP::polygon_soup_to_polygon_mesh(soup_points, triangles, solid);
  return solid;
}

} // namespace internal

/*!
\ingroup PkgPartDecompositionRef
returns the solid of the open sheets of `tm`: each open piece (`Piece_segmentation::closed` is 0)
that is not an assembly of sheets (see `splittable_pieces()`) inflated on both sides, each vertex moved along its normal (the area-weighted mean of its faces'
normals), one copy each way, by its distance to the piece's border along the edges; the border
stays in place and joins the two sides, so that an open sheet becomes a closed solid whose
thickness grows from its outline inwards: a limb of a flat figure becomes a limb of the solid, as
thick as it is wide. The other pieces are copied unchanged.

`decompose()` decomposes this solid instead of `tm` when no piece of `tm` bounds a volume
(`volumetric_pieces()`), the sheets it inflates hold at least half of its area and their outline
has limbs (projected on their least-squares plane, they fill less than 90% of their convex hull): a one-sided cut-out figure or a relief has
no inside, but its outline has limbs. Each face of `tm` then gets the part of its copy.

\tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
\param tm the mesh
\param pieces the pieces of `tm` (`segment_pieces()`)
\param np the named parameters `vertex_point_map`, `face_index_map` and `geom_traits`
(\ref PD_MeshParameters)
\returns the solid: its face `i` (in the order of its faces) is the copy of the face of index `i`
of `tm`, on the side of its normal; the faces after `num_faces(tm)` are the other sides of the
open pieces. Non-manifold points of the solid (where a sheet's border touches itself) are
duplicated, as `CGAL::Polygon_mesh_processing::orient_polygon_soup()` does.
*/
template <typename TriangleMesh, typename NamedParameters = CGAL::parameters::Default_named_parameters>
CGAL::Surface_mesh<typename GetGeomTraits<TriangleMesh, NamedParameters>::type::Point_3>
inflate_sheets(const TriangleMesh& tm, const Piece_segmentation& pieces,
               const NamedParameters& np = CGAL::parameters::default_values())
{
  const internal::Mesh_maps<TriangleMesh, NamedParameters> maps(tm, np);
  const internal::Face_corners corners(tm, maps.fim, maps.vpm);
  std::vector<typename GetGeomTraits<TriangleMesh, NamedParameters>::type::Point_3> raised;
  return internal::inflated_sheets(corners, internal::inflated_sheet_faces(tm, pieces, corners, np), raised);
}

} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_SHEET_INFLATION_H
