// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_IO_READ_MESH_H
#define CGAL_PART_DECOMPOSITION_IO_READ_MESH_H

#include <CGAL/Part_decomposition/input_validation.h>
#include <CGAL/Part_decomposition/parameters.h>
#include <CGAL/Part_decomposition/internal/io/polygon_soup.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/assertions.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#if defined(CGAL_PART_DECOMPOSITION_COMPILED_LIBRARY) || defined(CGAL_PART_DECOMPOSITION_BUILDING_LIBRARY)
#include <CGAL/Part_decomposition/compiled_types.h>
#endif

namespace CGAL {
namespace Part_decomposition {

namespace IO {

/*!
\ingroup PkgPartDecompositionIO
What `read_triangle_mesh()` did to turn a file into a triangle mesh, and the correspondence
between the faces of the mesh and the faces of the file, so that per-face results can be written
in the file's face order with `labels_in_file_order()`.
*/
struct Mesh_file_info
{
  /// the number of faces (polygons) in the file.
  std::size_t number_of_input_faces = 0;
  /// the number of vertices in the file.
  std::size_t number_of_input_vertices = 0;
  /// for the `i`-th face of the mesh, in the iteration order of `faces(tm)`, the index of the
  /// file face it comes from (a polygon of the file gives several triangles).
  std::vector<std::size_t> face_to_input;
  /// the file faces that gave no triangle (fewer than three distinct vertices), each with the
  /// index (iteration order) of the mesh face whose result it takes: a face sharing a vertex with
  /// it, or else the face with the nearest centroid.
  std::vector<std::pair<std::size_t, std::size_t> > dropped_faces;
  /// the number of file faces with more than three vertices, triangulated by ear clipping.
  std::size_t number_of_triangulated_faces = 0;
  /// the number of file vertices merged into another one with the same coordinates.
  std::size_t number_of_merged_vertices = 0;
  /// the number of vertices welded to another one within `weld_tolerance` (see `read_triangle_mesh()`).
  std::size_t number_of_welded_vertices = 0;
  /// the number of vertices duplicated to make the surface manifold and orientable.
  std::size_t number_of_duplicated_vertices = 0;
  /// the number of closed connected components whose orientation was reversed to point outward.
  std::size_t number_of_reversed_components = 0;
  /// the number of values of an ASCII PLY file after the properties its header declares for an
  /// element (an element is read from one line; MeshLab writes lists its header does not declare),
  /// ignored.
  std::size_t number_of_ignored_values = 0;
};

} // namespace IO

/// \cond SKIP_IN_MANUAL
namespace internal {

// The polygon soup of a file, as read, and the triangles made from it.
struct File_soup
{
  Polygon_soup_arrays file;
  // the file points with equal coordinates merged; merged[i] is the point of file point i
  std::vector<std::array<double, 3> > points;
  std::vector<std::size_t> merged;
  // the triangles with three distinct points, the file face of each, the faces that gave none
  std::vector<std::array<std::size_t, 3> > triangles;
  std::vector<std::size_t> triangle_to_input;
  std::vector<std::size_t> dropped;
};

// The weld tolerance of `np`, checked: a fraction of the bounding box diagonal.
template <typename NamedParameters>
double read_weld_tolerance(const NamedParameters& np)
{
  const double t = CGAL::parameters::choose_parameter(
    CGAL::parameters::get_parameter(np, internal_np::weld_tolerance), defaults::weld_tolerance);
  check_parameter(t >= 0. && t <= 0.01, "weld_tolerance");
  return t;
}

// An index of a polygon given by the user: a negative one is no vertex.
template <typename Integer>
std::size_t soup_index(Integer id)
{
  if constexpr(std::is_signed<Integer>::value)
    if(id < 0) return invalid_vertex_index;
  return std::size_t(id);
}

// Builds `tm` from the parsed soup: the common part of every reader. `name` is the file name in
// quotes, or what the soup is, for the messages.
template <typename TriangleMesh>
IO::Mesh_file_info build_triangle_mesh(File_soup& soup, const std::string& name, double weld_tolerance,
                                       TriangleMesh& tm);

#ifdef CGAL_PART_DECOMPOSITION_COMPILED_LIBRARY
#define CGAL_PART_DECOMPOSITION_CHECK_COMPILED_MESH(TriangleMesh)                                     \
  static_assert(std::is_same<TriangleMesh, internal::Compiled_mesh>::value,                        \
                "the library CGAL::Part_decomposition holds the reader for a CGAL::Surface_mesh of Epick " \
                "points: link CGAL::Part_decomposition_headers for other mesh types")
#else
#define CGAL_PART_DECOMPOSITION_CHECK_COMPILED_MESH(TriangleMesh) static_assert(true, "")
#endif

// `IO::read_triangle_mesh()` with its checked weld tolerance.
template <typename TriangleMesh>
IO::Mesh_file_info read_mesh_file(const std::string& filename, double weld_tolerance, TriangleMesh& tm);

} // namespace internal
/// \endcond

namespace IO {

/*!
\ingroup PkgPartDecompositionIO
reads the file `filename` (OFF, OBJ, PLY, STL, glTF 2.0 as `.gltf` or `.glb`; chosen by extension)
into the triangle mesh `tm`,
whatever the file holds: polygons are triangulated, vertices with equal coordinates are merged,
vertices on a border that differ only by round-off are welded, the soup is oriented consistently
(vertices are duplicated where the surface is non-manifold or not orientable), and every closed
connected component is oriented outward. Open, non-manifold, self-intersecting meshes and meshes
made of many pieces are all accepted. Faces with fewer than three distinct vertices are left out
of `tm` and reported in the returned information.

<b>Welding.</b> An exporter that writes one surface as several meshes (by material, or one of them
under a node transform in glTF) leaves the two copies of each seam vertex a few float32 units of
round-off apart: the seam would be a crack, and the surface two pieces. After the merging of equal
vertices, every vertex on a border edge (an edge of one triangle) is welded to the border vertices
within `weld_tolerance` of the bounding box diagonal, closest pairs first, keeping the coordinates
of the vertex that comes first in the file. Two vertices of one triangle are never welded, also
through a third vertex, so that no triangle degenerates; vertices inside a surface are never moved.
The default, \f$5 \cdot 10^{-6}\f$, lies between the round-off measured on seams (at most
\f$6.4 \cdot 10^{-7}\f$ of the diagonal for float32 positions and node transforms, objects up to two
sizes from the origin) and the smallest gap between distinct border vertices in the test data
(\f$4 \cdot 10^{-5}\f$); see the user manual. A mesh stored in float32 far from the origin (more
than about ten times its size) has a larger round-off and needs a larger tolerance.

The file is read into memory at once and parsed in place by the package's own parsers (an ASCII
OFF file in blocks of lines, and the halfedges of a `CGAL::Surface_mesh`, in parallel when TBB is
available); a broken or hostile file gives `Invalid_input` (`UNREADABLE_FILE`) with the line (the
byte of binary data) and what was expected, e.g.\ `cannot parse 'x.obj' as OBJ: line 12: expected
a vertex index after 'f', got 'abc'`. OBJ: vertices and faces (`f`, corners `i`, `i/t`, `i//n`,
`i/t/n`, negative indices, a trailing backslash continuing the line) are read, every other
statement skipped. ASCII PLY: an element is one line, and values after the properties its header declares (MeshLab writes
lists its header does not declare) are ignored and counted
(`Mesh_file_info::number_of_ignored_values`); a line with fewer values is an error naming it. A
UTF-8 byte-order mark before an OFF, OBJ or PLY file is skipped. glTF: every triangle primitive
(`TRIANGLES`, `TRIANGLE_STRIP`, `TRIANGLE_FAN`) of every mesh instanced by a node of the default
scene, transformed by the node's global transform; the file's faces are the triangles of the nodes
depth first (a node before its children), the primitives of a node's mesh in their order, the
triangles of a primitive in the order of its indices. Sparse accessors, compressed geometry
(Draco, meshopt) and buffers outside the file's folder are refused; without nlohmann/json
(Debian: `nlohmann-json3-dev`) glTF files are refused. An STL file stores the corners of each triangle apart: its vertices are
the distinct corners, so that `Mesh_file_info::number_of_input_vertices` counts them and
`Mesh_file_info::number_of_merged_vertices` is 0.

\tparam TriangleMesh a model of `MutableFaceGraph` whose point type is a \cgal point
\tparam NamedParameters a sequence of named parameters

\param filename the file
\param tm an empty mesh that receives the triangles
\param np an optional sequence of named parameters; this function reads `weld_tolerance`
(\ref PD_ParameterTable)

\returns the correspondence between the faces of `tm` and those of the file.

\par Complexity
\f$O(n \log n)\f$ for a file of size \f$n\f$ (the merging of equal vertices, a sort, and, when an
edge has one triangle only, the search of the border vertices to weld), plus the ear
clipping of the polygons, quadratic in the number of vertices of each polygon, and the orientation
of the soup by `CGAL::Polygon_mesh_processing::orient_polygon_soup()`, which is skipped when the
triangles already form a consistently oriented manifold (checked in linear time).

\throws Invalid_input if the file cannot be opened or parsed (`UNREADABLE_FILE`, the message then
names the line, or the byte of binary data, and what was expected there), holds no face
(`NO_FACES`), has a face with fewer than three vertices or an out-of-range vertex index
(`INVALID_FACE`), or a vertex with a non-finite coordinate (`NON_FINITE_COORDINATES`), and if
`weld_tolerance` is out of its range (`INVALID_PARAMETER`).
*/
template <typename TriangleMesh, typename NamedParameters = CGAL::parameters::Default_named_parameters>
Mesh_file_info read_triangle_mesh(const std::string& filename, TriangleMesh& tm,
                                  const NamedParameters& np = CGAL::parameters::default_values())
{
  CGAL_PART_DECOMPOSITION_CHECK_COMPILED_MESH(TriangleMesh);
  return internal::read_mesh_file(filename, internal::read_weld_tolerance(np), tm);
}

/*!
\ingroup PkgPartDecompositionIO
builds the triangle mesh `tm` from a polygon soup exactly as `read_triangle_mesh()` builds it from
the points and faces of a file (triangulation, merging of equal points, welding of border points
within `weld_tolerance`, its only named parameter, orientation, faces with fewer than three
distinct vertices left out), so that one label per polygon is obtained with
`labels_in_file_order()`, polygon `i` being the `i`-th face of the "file".

\tparam PointRange a model of `RandomAccessRange` whose value type `p` gives its coordinates as
`p[0]`, `p[1]`, `p[2]` (convertible to `double`), e.g.\ `std::array<double, 3>`
\tparam PolygonRange a model of `RandomAccessRange` whose value type is a range of integer vertex
indices, e.g.\ `std::vector<std::array<std::size_t, 3> >`
\tparam TriangleMesh a model of `MutableFaceGraph` whose point type is a \cgal point
\tparam NamedParameters a sequence of named parameters

\param points the points
\param polygons the polygons, each as indices into `points`
\param tm an empty mesh that receives the triangles
\param np an optional sequence of named parameters; this function reads `weld_tolerance`
(\ref PD_ParameterTable)

\returns the correspondence between the faces of `tm` and the polygons.

\throws Invalid_input if there is no polygon (`NO_FACES`), a polygon with fewer than three
vertices or an index out of `[0, points.size())` (`INVALID_FACE`), a non-finite coordinate
(`NON_FINITE_COORDINATES`), no polygon with three distinct points (`NO_FACES`), or a
`weld_tolerance` out of its range (`INVALID_PARAMETER`).
*/
template <typename PointRange, typename PolygonRange, typename TriangleMesh,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Mesh_file_info triangle_mesh_from_polygon_soup(const PointRange& points, const PolygonRange& polygons,
                                               TriangleMesh& tm,
                                               const NamedParameters& np = CGAL::parameters::default_values())
{
  CGAL_PART_DECOMPOSITION_CHECK_COMPILED_MESH(TriangleMesh);
  const double weld_tolerance = internal::read_weld_tolerance(np);
  internal::File_soup soup;
  soup.file.points.reserve(points.size());
  for(const auto& p : points) soup.file.add_point(double(p[0]), double(p[1]), double(p[2]));
  soup.file.polygon_start.reserve(polygons.size() + 1);
  for(const auto& polygon : polygons)
  {
    for(const auto& id : polygon)
      soup.file.add_vertex_index(internal::soup_index(id));
    soup.file.end_polygon();
  }
  return internal::build_triangle_mesh(soup, "the polygon soup", weld_tolerance, tm);
}

/*!
\ingroup PkgPartDecompositionIO
turns one label per mesh face (in the iteration order of `faces(tm)`, as read by
`read_triangle_mesh()`) into one label per face of the file, in the file's order. A polygon
triangulated into several faces takes the label most of its triangles carry (the smallest one on a
tie); a face left out of the mesh takes the label of its donor face.

\par Complexity
Linear in the number of faces, up to a sort of the labels of each triangulated polygon.

\pre `mesh_labels.size() == info.face_to_input.size()`
*/
template <typename Label>
std::vector<Label> labels_in_file_order(const Mesh_file_info& info, const std::vector<Label>& mesh_labels)
{
  CGAL_precondition(mesh_labels.size() == info.face_to_input.size());
  std::vector<std::vector<Label> > votes(info.number_of_input_faces);
  for(std::size_t i = 0; i < mesh_labels.size(); ++i)
    votes[info.face_to_input[i]].push_back(mesh_labels[i]);
  std::vector<Label> out(info.number_of_input_faces, Label());
  for(std::size_t f = 0; f < votes.size(); ++f)
  {
    std::vector<Label>& v = votes[f];
    if(v.empty()) continue;
    std::sort(v.begin(), v.end());
    std::size_t best_count = 0;
    for(std::size_t i = 0; i < v.size();)
    {
      std::size_t j = i;
      while(j < v.size() && v[j] == v[i]) ++j;
      if(j - i > best_count) { best_count = j - i; out[f] = v[i]; }
      i = j;
    }
  }
  for(const auto& d : info.dropped_faces)
    out[d.first] = mesh_labels[d.second];
  return out;
}

} // namespace IO
} // namespace Part_decomposition
} // namespace CGAL

// The library CGAL::Part_decomposition holds the reader for its mesh type (see decompose.h);
// programs that do not link it compile the reader themselves, for any mesh.
#if defined(CGAL_PART_DECOMPOSITION_COMPILED_LIBRARY) || defined(CGAL_PART_DECOMPOSITION_BUILDING_LIBRARY)
/// \cond SKIP_IN_MANUAL
#define CGAL_PART_DECOMPOSITION_INSTANTIATE_READER(EXTERN)                                           \
  namespace CGAL { namespace Part_decomposition { namespace internal {                              \
  EXTERN template IO::Mesh_file_info read_mesh_file<Compiled_mesh>(const std::string&, double, Compiled_mesh&); \
  EXTERN template IO::Mesh_file_info build_triangle_mesh<Compiled_mesh>(File_soup&, const std::string&, double, \
                                                                        Compiled_mesh&);            \
  } } }
/// \endcond
#endif

#ifdef CGAL_PART_DECOMPOSITION_COMPILED_LIBRARY
CGAL_PART_DECOMPOSITION_INSTANTIATE_READER(extern)
#else
#include <CGAL/Part_decomposition/IO/read_mesh_impl.h>
#endif

#endif // CGAL_PART_DECOMPOSITION_IO_READ_MESH_H
