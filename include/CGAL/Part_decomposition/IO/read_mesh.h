// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_IO_READ_MESH_H
#define CGAL_PART_DECOMPOSITION_IO_READ_MESH_H

#include <CGAL/Part_decomposition/input_validation.h>
#include <CGAL/Part_decomposition/internal/read_off_soup.h>
#include <CGAL/Part_decomposition/internal/read_ply_soup.h>
#include <CGAL/Part_decomposition/internal/oriented_manifold_soup.h>
#include <CGAL/Part_decomposition/internal/triangulate_polygon.h>

#include <CGAL/IO/OBJ.h>
#include <CGAL/IO/STL.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Dynamic_property_map.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <new>
#include <string>
#include <vector>

namespace CGAL {
namespace Part_decomposition {

/// \cond SKIP_IN_MANUAL
namespace internal {

// The largest single allocation, in bytes, of the containers the file parser fills on this thread.
inline std::size_t& read_allocation_limit()
{
  thread_local std::size_t limit = std::size_t(-1);
  return limit;
}

// Sets the limit for the lifetime of the object.
class Read_allocation_limit
{
public:
  explicit Read_allocation_limit(std::size_t bytes) : m_previous(read_allocation_limit())
  {
    read_allocation_limit() = bytes;
  }
  ~Read_allocation_limit() { read_allocation_limit() = m_previous; }
  Read_allocation_limit(const Read_allocation_limit&) = delete;
  Read_allocation_limit& operator=(const Read_allocation_limit&) = delete;

private:
  std::size_t m_previous;
};

// std::allocator that throws std::bad_alloc beyond read_allocation_limit().
template <typename T>
struct Bounded_allocator
{
  typedef T value_type;
  Bounded_allocator() = default;
  template <typename U>
  Bounded_allocator(const Bounded_allocator<U>&) {}
  T* allocate(std::size_t n)
  {
    if(n > read_allocation_limit() / sizeof(T)) throw std::bad_alloc();
    return std::allocator<T>().allocate(n);
  }
  void deallocate(T* p, std::size_t n) { std::allocator<T>().deallocate(p, n); }
  template <typename U>
  bool operator==(const Bounded_allocator<U>&) const { return true; }
  template <typename U>
  bool operator!=(const Bounded_allocator<U>&) const { return false; }
};

} // namespace internal
/// \endcond

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
  /// the number of vertices duplicated to make the surface manifold and orientable.
  std::size_t number_of_duplicated_vertices = 0;
  /// the number of closed connected components whose orientation was reversed to point outward.
  std::size_t number_of_reversed_components = 0;
};

} // namespace IO

/// \cond SKIP_IN_MANUAL
namespace internal {

typedef CGAL::Simple_cartesian<double>::Point_3 Read_point;

// The polygon soup of a file, as read, and the triangles made from it.
struct File_soup
{
  std::vector<Read_point> file_points;
  std::vector<std::vector<std::size_t> > polygons;
  // the file points with equal coordinates merged; merged[i] is the point of file point i
  std::vector<std::array<double, 3> > points;
  std::vector<std::size_t> merged;
  // the triangles with three distinct points, the file face of each, the faces that gave none
  std::vector<std::vector<std::size_t> > triangles;
  std::vector<std::size_t> triangle_to_input;
  std::vector<std::size_t> dropped;
};

inline std::size_t size_of_file(const std::string& filename)
{
  std::ifstream probe(filename, std::ios::binary | std::ios::ate);
  if(!probe)
    throw Invalid_input(Input_error::UNREADABLE_FILE, "cannot open '" + filename + "'");
  const std::streamoff end = probe.tellg();
  return end > 0 ? std::size_t(end) : 0;
}

// Parses the file into `soup.file_points` and `soup.polygons`; false if it cannot be parsed.
inline bool parse_polygon_soup(const std::string& filename, File_soup& soup)
{
  const std::size_t file_size = size_of_file(filename);
  try
  {
    // A header may promise more than the file holds (an OFF count or face degree of 10^9 in a
    // few bytes): no single allocation of the parser may exceed a multiple of the file size.
    Read_allocation_limit limit(64 * file_size + (std::size_t(1) << 20));
    std::vector<Read_point, Bounded_allocator<Read_point> > bounded_points;
    std::vector<std::vector<std::size_t, Bounded_allocator<std::size_t> >,
                Bounded_allocator<std::vector<std::size_t, Bounded_allocator<std::size_t> > > >
      bounded_polygons;
    // CGAL's OFF and PLY parsers have undefined behaviour or allocate without bound on some
    // broken files: these two formats are read by our own parsers.
    const std::string extension = CGAL::IO::internal::get_file_extension(filename);
    std::ifstream in(filename, std::ios::binary);
    bool ok = false;
    if(extension == "off")
      ok = Off_soup_reader(in).read(bounded_points, bounded_polygons);
    else if(extension == "ply")
      ok = Ply_soup_reader(in).read(bounded_points, bounded_polygons);
    else if(extension == "obj")
      ok = CGAL::IO::read_OBJ(filename, bounded_points, bounded_polygons, CGAL::parameters::verbose(false));
    else if(extension == "stl")
      ok = CGAL::IO::read_STL(filename, bounded_points, bounded_polygons, CGAL::parameters::verbose(false));
    // only the four formats: CGAL's reader of every format costs a user seconds of compilation
    if(!ok) return false;
    soup.file_points.assign(bounded_points.begin(), bounded_points.end());
    soup.polygons.reserve(bounded_polygons.size());
    for(const auto& poly : bounded_polygons) soup.polygons.emplace_back(poly.begin(), poly.end());
    return true;
  }
  catch(const std::exception&)
  {
    return false;
  }
}

inline void check_polygon_soup(const std::string& filename, const File_soup& soup)
{
  if(soup.polygons.empty())
    throw Invalid_input(Input_error::NO_FACES, "'" + filename + "' has no face");
  for(const Read_point& p : soup.file_points)
    if(!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z()))
      throw Invalid_input(Input_error::NON_FINITE_COORDINATES,
                          "'" + filename + "' has a vertex with a non-finite coordinate");
  for(const std::vector<std::size_t>& poly : soup.polygons)
  {
    if(poly.size() < 3)
      throw Invalid_input(Input_error::INVALID_FACE, "'" + filename + "' has a face with fewer than 3 vertices");
    for(std::size_t id : poly)
      if(id >= soup.file_points.size())
        throw Invalid_input(Input_error::INVALID_FACE,
                            "'" + filename + "' has a face with an out-of-range vertex index");
  }
}

// Merges points with equal coordinates (STL stores each triangle's corners separately).
inline void merge_equal_points(File_soup& soup)
{
  soup.merged.resize(soup.file_points.size());
  std::map<std::array<double, 3>, std::size_t> index;
  for(std::size_t i = 0; i < soup.file_points.size(); ++i)
  {
    const std::array<double, 3> c = {{soup.file_points[i].x(), soup.file_points[i].y(), soup.file_points[i].z()}};
    auto res = index.emplace(c, soup.points.size());
    if(res.second) soup.points.push_back(c);
    soup.merged[i] = res.first->second;
  }
}

// Triangulates every polygon on the merged points; returns the number of polygons with more than
// three vertices after merging.
inline std::size_t triangulate_polygons(File_soup& soup)
{
  std::size_t triangulated = 0;
  auto xyz = [&](std::size_t i) { return soup.points[i]; };
  std::vector<std::array<std::size_t, 3> > tris;
  for(std::size_t f = 0; f < soup.polygons.size(); ++f)
  {
    std::vector<std::size_t> poly;
    for(std::size_t id : soup.polygons[f])
      if(poly.empty() || poly.back() != soup.merged[id]) poly.push_back(soup.merged[id]);
    while(poly.size() > 1 && poly.front() == poly.back()) poly.pop_back();
    tris.clear();
    if(poly.size() >= 3)
    {
      if(poly.size() > 3) ++triangulated;
      triangulate_polygon(poly, xyz, tris);
    }
    bool any = false;
    for(const std::array<std::size_t, 3>& t : tris)
    {
      if(t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) continue;
      soup.triangles.push_back({t[0], t[1], t[2]});
      soup.triangle_to_input.push_back(f);
      any = true;
    }
    if(!any) soup.dropped.push_back(f);
  }
  return triangulated;
}

// Adds the triangles to `tm` one by one, so that a face refused by add_face cannot shift the
// order; points no triangle uses are not added. Returns the face of each triangle (null if refused).
template <typename TriangleMesh, typename Point>
std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>
add_triangles(const std::vector<Point>& soup_points, const std::vector<std::vector<std::size_t> >& triangles,
              TriangleMesh& tm)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  std::vector<typename GT::vertex_descriptor> vmap(soup_points.size(), GT::null_vertex());
  for(const std::vector<std::size_t>& t : triangles)
    for(std::size_t id : t)
      if(vmap[id] == GT::null_vertex())
      {
        vmap[id] = add_vertex(tm);
        put(get(CGAL::vertex_point, tm), vmap[id], soup_points[id]);
      }
  std::vector<typename GT::face_descriptor> triangle_face(triangles.size(), GT::null_face());
  std::vector<typename GT::vertex_descriptor> corners(3);
  for(std::size_t t = 0; t < triangles.size(); ++t)
  {
    for(int k = 0; k < 3; ++k) corners[k] = vmap[triangles[t][k]];
    triangle_face[t] = CGAL::Euler::add_face(corners, tm);
  }
  return triangle_face;
}

// A refused triangle (should not happen after orientation) is treated like a dropped face.
template <typename TriangleMesh>
void drop_faces_of_refused_triangles(
  const std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>& triangle_face, File_soup& soup)
{
  const auto null_face = boost::graph_traits<TriangleMesh>::null_face();
  std::vector<char> input_has_face(soup.polygons.size(), 0);
  for(std::size_t t = 0; t < triangle_face.size(); ++t)
    if(triangle_face[t] != null_face) input_has_face[soup.triangle_to_input[t]] = 1;
  for(std::size_t t = 0; t < triangle_face.size(); ++t)
    if(triangle_face[t] == null_face && !input_has_face[soup.triangle_to_input[t]])
    {
      input_has_face[soup.triangle_to_input[t]] = 2; // mark once
      soup.dropped.push_back(soup.triangle_to_input[t]);
    }
}

// Orients every closed connected component outward (positive enclosed volume); returns how many
// were reversed. Closedness is per component here, so not CGAL::is_closed().
template <typename TriangleMesh>
std::size_t orient_closed_components_outward(TriangleMesh& tm)
{
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  typedef typename boost::property_traits<typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::type>::value_type Point;
  auto fcc = get(CGAL::dynamic_face_property_t<std::size_t>(), tm);
  const std::size_t ncc = CGAL::Polygon_mesh_processing::connected_components(tm, fcc);
  std::vector<double> volume(ncc, 0.);
  std::vector<char> closed(ncc, 1);
  for(face_descriptor f : faces(tm))
  {
    const std::size_t c = get(fcc, f);
    std::array<std::array<double, 3>, 3> p;
    int k = 0;
    for(auto h : halfedges_around_face(halfedge(f, tm), tm))
    {
      const Point& q = get(get(CGAL::vertex_point, tm), target(h, tm));
      p[k++] = {{CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z())}};
      if(is_border(opposite(h, tm), tm)) closed[c] = 0;
    }
    volume[c] += p[0][0] * (p[1][1] * p[2][2] - p[1][2] * p[2][1])
               - p[0][1] * (p[1][0] * p[2][2] - p[1][2] * p[2][0])
               + p[0][2] * (p[1][0] * p[2][1] - p[1][1] * p[2][0]);
  }
  std::vector<face_descriptor> to_reverse;
  for(face_descriptor f : faces(tm))
    if(closed[get(fcc, f)] && volume[get(fcc, f)] < 0.) to_reverse.push_back(f);
  std::size_t reversed = 0;
  for(std::size_t c = 0; c < ncc; ++c)
    if(closed[c] && volume[c] < 0.) ++reversed;
  if(!to_reverse.empty())
    CGAL::Polygon_mesh_processing::reverse_face_orientations(to_reverse, tm);
  return reversed;
}

// The mesh face (iteration order) whose result the dropped file face f takes: one sharing a
// point with it, or else the one with the nearest centroid.
template <typename Point>
std::size_t donor_of_dropped_face(std::size_t f, const File_soup& soup, const std::vector<Point>& soup_points,
                                  const std::vector<std::size_t>& triangle_of_point,
                                  const std::vector<std::size_t>& position_of_triangle)
{
  for(std::size_t id : soup.polygons[f])
  {
    const std::size_t t = triangle_of_point[soup.merged[id]];
    if(t != std::size_t(-1) && position_of_triangle[t] != std::size_t(-1)) return position_of_triangle[t];
  }
  // isolated degenerate face: the mesh face with the nearest centroid
  std::size_t donor = std::size_t(-1);
  std::array<double, 3> c = {{0., 0., 0.}};
  for(std::size_t id : soup.polygons[f])
    for(int a = 0; a < 3; ++a) c[a] += soup.points[soup.merged[id]][a] / double(soup.polygons[f].size());
  double best = std::numeric_limits<double>::infinity();
  for(std::size_t t = 0; t < soup.triangles.size(); ++t)
  {
    if(position_of_triangle[t] == std::size_t(-1)) continue;
    double d2 = 0.;
    for(int a = 0; a < 3; ++a)
    {
      const double m = (CGAL::to_double(soup_points[soup.triangles[t][0]][a]) +
                        CGAL::to_double(soup_points[soup.triangles[t][1]][a]) +
                        CGAL::to_double(soup_points[soup.triangles[t][2]][a])) / 3. - c[a];
      d2 += m * m;
    }
    if(d2 < best) { best = d2; donor = position_of_triangle[t]; }
  }
  return donor;
}

// Fills `face_to_input` in the iteration order of faces(tm), and `dropped_faces` with a donor each.
// `triangle_of_point`: the first triangle incident to each merged point.
template <typename TriangleMesh, typename Point>
void record_face_correspondence(
  TriangleMesh& tm, const File_soup& soup, const std::vector<Point>& soup_points,
  const std::vector<std::size_t>& triangle_of_point,
  const std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>& triangle_face,
  IO::Mesh_file_info& info)
{
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor FaceDescriptor;
  auto ftri = get(CGAL::dynamic_face_property_t<std::size_t>(), tm);
  for(std::size_t t = 0; t < soup.triangles.size(); ++t)
    if(triangle_face[t] != boost::graph_traits<TriangleMesh>::null_face()) put(ftri, triangle_face[t], t);
  std::vector<std::size_t> position_of_triangle(soup.triangles.size(), std::size_t(-1));
  for(FaceDescriptor f : faces(tm))
  {
    position_of_triangle[get(ftri, f)] = info.face_to_input.size();
    info.face_to_input.push_back(soup.triangle_to_input[get(ftri, f)]);
  }
  for(std::size_t f : soup.dropped)
    info.dropped_faces.emplace_back(f, donor_of_dropped_face(f, soup, soup_points, triangle_of_point, position_of_triangle));
}

} // namespace internal
/// \endcond

namespace IO {

/*!
\ingroup PkgPartDecompositionIO
reads the file `filename` (OFF, OBJ, PLY, STL; chosen by extension) into the triangle mesh `tm`,
whatever the file holds: polygons are triangulated, vertices with equal coordinates are merged,
the soup is oriented consistently (vertices are duplicated where the surface is non-manifold or
not orientable), and every closed connected component is oriented outward. Open, non-manifold,
self-intersecting meshes and meshes made of many pieces are all accepted. Faces with fewer than
three distinct vertices are left out of `tm` and reported in the returned information.

\tparam TriangleMesh a model of `MutableFaceGraph` whose point type is a \cgal point

\param filename the file
\param tm an empty mesh that receives the triangles

\returns the correspondence between the faces of `tm` and those of the file.

\par Complexity
\f$O(n \log n)\f$ for a file of size \f$n\f$ (the merging of equal vertices), plus the ear clipping of
the polygons, quadratic in the number of vertices of each polygon, and the orientation of the soup
by `CGAL::Polygon_mesh_processing::orient_polygon_soup()`, which is skipped when the triangles
already form a consistently oriented manifold (checked in \f$O(n \log n)\f$).

\throws Invalid_input if the file cannot be opened or parsed (`UNREADABLE_FILE`), holds no face
(`NO_FACES`), has a face with fewer than three vertices or an out-of-range vertex index
(`INVALID_FACE`), or a vertex with a non-finite coordinate (`NON_FINITE_COORDINATES`).
*/
template <typename TriangleMesh>
Mesh_file_info read_triangle_mesh(const std::string& filename, TriangleMesh& tm)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::type VPM;
  typedef typename boost::property_traits<VPM>::value_type Point;

  Mesh_file_info info;
  internal::File_soup soup;
  if(!internal::parse_polygon_soup(filename, soup))
    throw Invalid_input(Input_error::UNREADABLE_FILE,
                        "cannot parse '" + filename + "' as an OFF, OBJ, PLY or STL mesh");
  info.number_of_input_faces = soup.polygons.size();
  info.number_of_input_vertices = soup.file_points.size();
  internal::check_polygon_soup(filename, soup);
  internal::merge_equal_points(soup);
  info.number_of_merged_vertices = soup.file_points.size() - soup.points.size();
  info.number_of_triangulated_faces = internal::triangulate_polygons(soup);
  if(soup.triangles.empty())
    throw Invalid_input(Input_error::NO_FACES, "'" + filename + "' has no face with three distinct vertices");

  // The first triangle incident to each merged point, to give dropped faces a neighbour's result.
  std::vector<std::size_t> triangle_of_point(soup.points.size(), std::size_t(-1));
  for(std::size_t t = 0; t < soup.triangles.size(); ++t)
    for(std::size_t id : soup.triangles[t])
      if(triangle_of_point[id] == std::size_t(-1)) triangle_of_point[id] = t;

  std::vector<Point> soup_points;
  soup_points.reserve(soup.points.size());
  for(const std::array<double, 3>& c : soup.points) soup_points.push_back(Point(c[0], c[1], c[2]));
  if(!internal::is_oriented_manifold_soup(soup.triangles, soup_points.size()))
    CGAL::Polygon_mesh_processing::orient_polygon_soup(soup_points, soup.triangles);
  info.number_of_duplicated_vertices = soup_points.size() - soup.points.size();

  const std::vector<typename GT::face_descriptor> triangle_face = internal::add_triangles(soup_points, soup.triangles, tm);
  internal::drop_faces_of_refused_triangles<TriangleMesh>(triangle_face, soup);
  if(faces(tm).begin() == faces(tm).end())
    throw Invalid_input(Input_error::NO_FACES, "'" + filename + "' gives no valid triangle");
  info.number_of_reversed_components = internal::orient_closed_components_outward(tm);
  internal::record_face_correspondence(tm, soup, soup_points, triangle_of_point, triangle_face, info);
  return info;
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

#endif // CGAL_PART_DECOMPOSITION_IO_READ_MESH_H
