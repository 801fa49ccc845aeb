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
#include <CGAL/Part_decomposition/internal/polygon_soup.h>
#include <CGAL/Part_decomposition/internal/read_error.h>
#include <CGAL/Part_decomposition/internal/read_gltf_soup.h>
#include <CGAL/Part_decomposition/internal/read_obj_soup.h>
#include <CGAL/Part_decomposition/internal/read_off_soup.h>
#include <CGAL/Part_decomposition/internal/read_ply_soup.h>
#include <CGAL/Part_decomposition/internal/read_stl_soup.h>
#include <CGAL/Part_decomposition/internal/oriented_manifold_soup.h>
#include <CGAL/Part_decomposition/internal/oriented_soup_to_mesh.h>
#include <CGAL/Part_decomposition/internal/triangulate_polygon.h>
#include <CGAL/Part_decomposition/internal/weld_border_points.h>

#include <CGAL/IO/helpers.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/use.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Dynamic_property_map.h>

#include <cstring>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/parallel_sort.h>
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <new>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

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

// The bytes of a file, read at once: parsing in memory is several times faster than a stream.
struct File_contents
{
  std::unique_ptr<char[]> data;
  std::size_t size = 0;
  const char* begin() const { return data.get(); }
  const char* end() const { return data.get() + size; }
};

// Throws UNREADABLE_FILE if the file cannot be opened or read.
inline void read_file_contents(const std::string& filename, File_contents& contents)
{
  std::ifstream in(filename, std::ios::binary | std::ios::ate);
  if(!in)
    throw Invalid_input(Input_error::UNREADABLE_FILE, "cannot open '" + filename + "'");
  const std::streamoff end = in.tellg();
  if(end < 0) throw Invalid_input(Input_error::UNREADABLE_FILE, "cannot read '" + filename + "'");
  contents.size = std::size_t(end);
  contents.data.reset(new char[contents.size + 1]);
  in.seekg(0, std::ios::beg);
  if(contents.size != 0 && !in.read(contents.data.get(), std::streamsize(contents.size)))
    throw Invalid_input(Input_error::UNREADABLE_FILE, "cannot read '" + filename + "'");
}

// glTF (.gltf, .glb): a broken file throws Gltf_error with the reason.
inline void read_gltf_soup(const std::string& filename, const File_contents& contents, Polygon_soup_arrays& soup)
{
#ifdef CGAL_PART_DECOMPOSITION_HAS_GLTF
  const std::size_t slash = filename.find_last_of('/');
  Gltf_soup_reader(contents.begin(), contents.end(), slash == std::string::npos ? std::string() : filename.substr(0, slash + 1))
    .read(soup);
#else
  CGAL_USE(contents);
  CGAL_USE(soup);
  throw Invalid_input(Input_error::UNREADABLE_FILE,
                      "cannot read '" + filename + "': glTF needs nlohmann/json.hpp (Debian: nlohmann-json3-dev)");
#endif
}

// The format of a file extension, as the messages name it; empty if the package reads none.
inline std::string format_of_extension(const std::string& extension)
{
  if(extension == "off" || extension == "obj" || extension == "ply" || extension == "stl")
  {
    std::string name = extension;
    for(char& c : name) c = char(c - 'a' + 'A');
    return name;
  }
  return extension == "gltf" || extension == "glb" ? "glTF" : std::string();
}

// Whether the file is read as glTF.
inline bool is_gltf_file(const std::string& filename)
{
  return format_of_extension(CGAL::IO::internal::get_file_extension(filename)) == "glTF";
}

#ifdef CGAL_PART_DECOMPOSITION_HAS_GLTF
// Runs f(); an error of a glTF file (broken JSON, accessor, index) becomes UNREADABLE_FILE with
// the reason.
template <typename F>
void with_gltf_errors(const std::string& filename, const F& f)
{
  try
  {
    f();
  }
  catch(const Gltf_error& e)
  {
    throw Invalid_input(Input_error::UNREADABLE_FILE, "cannot parse '" + filename + "' as glTF: " + e.what());
  }
  catch(const nlohmann::json::exception& e)
  {
    throw Invalid_input(Input_error::UNREADABLE_FILE, "cannot parse '" + filename + "' as glTF: " + e.what());
  }
}

#endif

// Throws std::invalid_argument for `what` unless `labels` holds one label in [0, number_of_labels)
// per face of the file.
inline void check_file_labels(const std::vector<std::size_t>& labels, std::size_t number_of_faces,
                              std::size_t number_of_labels, const char* what)
{
  if(labels.size() != number_of_faces)
    throw std::invalid_argument(std::string(what) + ": " + std::to_string(labels.size()) + " labels for " +
                                std::to_string(number_of_faces) + " faces of the file");
  for(std::size_t k : labels)
    if(k >= number_of_labels)
      throw std::invalid_argument(std::string(what) + ": label " + std::to_string(k) + " is not below the number of labels, " +
                                  std::to_string(number_of_labels));
}

// Parses the file into `soup`; throws UNREADABLE_FILE, saying where and why, if it cannot.
inline void parse_polygon_soup(const std::string& filename, Polygon_soup_arrays& soup)
{
  // only these formats: CGAL's reader of every format costs a user seconds of compilation
  const std::string extension = CGAL::IO::internal::get_file_extension(filename);
  const std::string format = format_of_extension(extension);
  if(format.empty())
    throw Invalid_input(Input_error::UNREADABLE_FILE, "cannot parse '" + filename +
                                                        "': the extension is none of .off, .obj, .ply, .stl, .gltf, .glb");
  File_contents contents;
  read_file_contents(filename, contents);
  const std::string cannot = "cannot parse '" + filename + "' as " + format + ": ";
  try
  {
    // A header may promise more than the file holds (an OFF count or face degree of 10^9 in a
    // few bytes): no single allocation of the parser may exceed a multiple of the file size.
    Read_allocation_limit limit(64 * contents.size + (std::size_t(1) << 20));
    // CGAL's OFF and PLY parsers have undefined behaviour or allocate without bound on some
    // broken files, its STL reader looks every corner up in a std::map, and its OBJ reader
    // refuses valid files and reads a stream: every format is read by our own parsers.
    // Windows tools may start a text file with a UTF-8 byte-order mark (not STL: its binary
    // header is any 80 bytes; JSON skips it itself)
    const char* text = contents.begin();
    if(contents.size >= 3 && std::memcmp(text, "\xEF\xBB\xBF", 3) == 0) text += 3;
    if(extension == "off") Off_soup_reader(text, contents.end()).read(soup);
    else if(extension == "obj") Obj_soup_reader(text, contents.end()).read(soup);
    else if(extension == "ply") Ply_soup_reader(text, contents.end()).read(soup);
    else if(extension == "stl") Stl_soup_reader(contents.begin(), contents.end()).read(soup);
    else read_gltf_soup(filename, contents, soup);
  }
  catch(const Invalid_input&)
  {
    throw;
  }
  catch(const Read_error& e)
  {
    throw Invalid_input(Input_error::UNREADABLE_FILE, cannot + e.what());
  }
  catch(const std::bad_alloc&)
  {
    throw Invalid_input(Input_error::UNREADABLE_FILE, cannot + "out of memory");
  }
  catch(const std::exception& e)
  {
    throw Invalid_input(Input_error::UNREADABLE_FILE, cannot + e.what());
  }
}

// `name` is the file name in quotes, or what the soup is.
inline void check_polygon_soup(const std::string& name, const Polygon_soup_arrays& soup)
{
  if(soup.number_of_polygons() == 0)
    throw Invalid_input(Input_error::NO_FACES, name + " has no face");
  for(const std::array<double, 3>& p : soup.points)
    if(!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      throw Invalid_input(Input_error::NON_FINITE_COORDINATES, name + " has a vertex with a non-finite coordinate");
  const std::size_t n = soup.number_of_points();
  for(std::size_t f = 0; f < soup.number_of_polygons(); ++f)
  {
    if(soup.polygon_size(f) < 3)
      throw Invalid_input(Input_error::INVALID_FACE, name + " has a face with fewer than 3 vertices");
    for(const std::size_t* id = soup.polygon_begin(f); id != soup.polygon_end(f); ++id)
      if(*id >= n)
        throw Invalid_input(Input_error::INVALID_FACE, name + " has a face with an out-of-range vertex index");
  }
}

// Merges points with equal coordinates (STL stores each triangle's corners separately); the
// merged points keep the order of their first occurrence. A sort of (coordinates, index) records,
// not a std::map: no allocation per point, and the comparisons read memory in order.
inline void merge_equal_points(File_soup& soup)
{
  const auto& p = soup.file.points;
  const std::size_t n = p.size();
  struct Record
  {
    std::array<double, 3> c;
    std::size_t i;
  };
  std::vector<Record> order(n);
  for(std::size_t i = 0; i < n; ++i) order[i] = Record{p[i], i};
  // equal points in a row, the first occurrence first (-0 and 0 are equal, as for std::map); the
  // indices make every record distinct, so a parallel sort gives the same order
  const auto less = [](const Record& a, const Record& b) {
    for(int k = 0; k < 3; ++k)
    {
      if(a.c[k] < b.c[k]) return true;
      if(b.c[k] < a.c[k]) return false;
    }
    return a.i < b.i;
  };
#ifdef CGAL_LINKED_WITH_TBB
  tbb::parallel_sort(order.begin(), order.end(), less);
#else
  std::sort(order.begin(), order.end(), less);
#endif
  std::vector<std::size_t> first(n);
  for(std::size_t i = 0; i < n; ++i)
    first[order[i].i] = (i > 0 && order[i].c == order[i - 1].c) ? first[order[i - 1].i] : order[i].i;
  std::vector<Record>().swap(order);
  soup.merged.resize(n);
  soup.points.clear();
  for(std::size_t i = 0; i < n; ++i)
  {
    if(first[i] != i)
    {
      soup.merged[i] = soup.merged[first[i]];
      continue;
    }
    soup.merged[i] = soup.points.size();
    soup.points.push_back(p[i]);
  }
}

// Triangulates every polygon on the merged points; returns the number of polygons with more than
// three vertices after merging.
inline std::size_t triangulate_polygons(File_soup& soup)
{
  std::size_t triangulated = 0;
  auto xyz = [&](std::size_t i) { return soup.points[i]; };
  std::vector<std::array<std::size_t, 3> > tris;
  std::vector<std::size_t> poly;
  const std::size_t nf = soup.file.number_of_polygons();
  soup.triangles.reserve(nf);
  soup.triangle_to_input.reserve(nf);
  for(std::size_t f = 0; f < nf; ++f)
  {
    const std::size_t* first = soup.file.polygon_begin(f);
    const std::size_t* last = soup.file.polygon_end(f);
    if(last - first == 3)
    {
      // the common case; a triangle with a repeated point gives none
      const std::array<std::size_t, 3> t = {{soup.merged[first[0]], soup.merged[first[1]], soup.merged[first[2]]}};
      if(t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) soup.dropped.push_back(f);
      else
      {
        soup.triangles.push_back(t);
        soup.triangle_to_input.push_back(f);
      }
      continue;
    }
    poly.clear();
    for(const std::size_t* id = first; id != last; ++id)
      if(poly.empty() || poly.back() != soup.merged[*id]) poly.push_back(soup.merged[*id]);
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
      soup.triangles.push_back(t);
      soup.triangle_to_input.push_back(f);
      any = true;
    }
    if(!any) soup.dropped.push_back(f);
  }
  return triangulated;
}

// The weld tolerance of `np`, checked: a fraction of the bounding box diagonal.
template <typename NamedParameters>
double read_weld_tolerance(const NamedParameters& np)
{
  const double t = CGAL::parameters::choose_parameter(
    CGAL::parameters::get_parameter(np, internal_np::weld_tolerance), defaults::weld_tolerance);
  check_parameter(t >= 0. && t <= 0.01, "weld_tolerance");
  return t;
}

// Welds the border points of the triangles within `relative_tolerance` of the diagonal of their
// bounding box (`weld_border_points()`); the file points follow their points. Returns the number
// of points welded.
inline std::size_t weld_soup_points(File_soup& soup, double relative_tolerance)
{
  std::array<double, 3> lo = soup.points[soup.triangles.front()[0]], hi = lo;
  for(const std::array<std::size_t, 3>& t : soup.triangles)
    for(std::size_t id : t)
      for(int a = 0; a < 3; ++a)
      {
        lo[a] = (std::min)(lo[a], soup.points[id][a]);
        hi[a] = (std::max)(hi[a], soup.points[id][a]);
      }
  const double diagonal =
    std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) + (hi[2] - lo[2]) * (hi[2] - lo[2]));
  // below this the cells of the search would not fit in 64-bit integers; no double is that close
  if(!(relative_tolerance > 1e-15) || !(diagonal > 0.) || !std::isfinite(diagonal)) return 0;
  std::size_t welded = 0;
  const std::vector<std::size_t> target = weld_border_points(soup.points, soup.triangles, relative_tolerance * diagonal, welded);
  for(std::size_t& m : soup.merged) m = target[m];
  return welded;
}

// Adds the points the triangles use to `tm`, in the order the triangles reach them; returns the
// vertex of each point (null if unused).
template <typename TriangleMesh, typename Point>
std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>
add_used_points(const std::vector<Point>& soup_points, const std::vector<std::array<std::size_t, 3> >& triangles,
                TriangleMesh& tm)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  std::vector<typename GT::vertex_descriptor> vmap(soup_points.size(), GT::null_vertex());
  auto vpm = get(CGAL::vertex_point, tm);
  for(const std::array<std::size_t, 3>& t : triangles)
    for(std::size_t id : t)
      if(vmap[id] == GT::null_vertex())
      {
        vmap[id] = add_vertex(tm);
        put(vpm, vmap[id], soup_points[id]);
      }
  return vmap;
}

// Adds the triangles to `tm` one by one, so that a face refused by add_face cannot shift the
// order. Returns the face of each triangle (null if refused).
template <typename TriangleMesh>
std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>
add_triangles(const std::vector<std::array<std::size_t, 3> >& triangles,
              const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& vmap, TriangleMesh& tm)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  std::vector<typename GT::face_descriptor> triangle_face(triangles.size(), GT::null_face());
  std::array<typename GT::vertex_descriptor, 3> corners;
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
  std::vector<char> input_has_face(soup.file.number_of_polygons(), 0);
  for(std::size_t t = 0; t < triangle_face.size(); ++t)
    if(triangle_face[t] != null_face) input_has_face[soup.triangle_to_input[t]] = 1;
  for(std::size_t t = 0; t < triangle_face.size(); ++t)
    if(triangle_face[t] == null_face && !input_has_face[soup.triangle_to_input[t]])
    {
      input_has_face[soup.triangle_to_input[t]] = 2; // mark once
      soup.dropped.push_back(soup.triangle_to_input[t]);
    }
}

// The edge-connected components of the triangles of `tm`, numbered in the order of faces(tm)
// (a union-find over the face indices: CGAL's connected_components() is several times slower on
// a million faces). Returns their number.
template <typename TriangleMesh, typename FaceIndexMap>
std::size_t face_components(const TriangleMesh& tm, const FaceIndexMap& index, std::vector<std::size_t>& component)
{
  const std::size_t n = component.size();
  std::vector<std::size_t> parent(n);
  for(std::size_t i = 0; i < n; ++i) parent[i] = i;
  auto root = [&](std::size_t i) {
    while(parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for(auto f : faces(tm))
  {
    auto h = halfedge(f, tm);
    for(int k = 0; k < 3; ++k, h = next(h, tm))
    {
      const auto g = face(opposite(h, tm), tm);
      if(g == boost::graph_traits<TriangleMesh>::null_face()) continue;
      const std::size_t a = root(get(index, f)), b = root(get(index, g));
      if(a != b) parent[(std::max)(a, b)] = (std::min)(a, b);
    }
  }
  std::size_t count = 0;
  std::vector<std::size_t> id_of_root(n, std::size_t(-1));
  for(auto f : faces(tm))
  {
    const std::size_t r = root(get(index, f));
    if(id_of_root[r] == std::size_t(-1)) id_of_root[r] = count++;
    component[get(index, f)] = id_of_root[r];
  }
  return count;
}

// The components of the triangles of an oriented manifold soup (what orient_polygon_soup()
// returns, or a soup that needed no orientation), each triangle added as a face: triangles that
// share a point share an edge, since the triangles around each point form one fan. A union-find
// over the points, whose array is smaller and read in a more local order than the faces of the
// mesh. `fcc` is indexed by the index of the face of each triangle.
template <typename FaceIndexMap, typename FaceDescriptor>
std::size_t soup_components(const std::vector<std::array<std::size_t, 3> >& triangles, std::size_t number_of_points,
                            const std::vector<FaceDescriptor>& triangle_face, const FaceIndexMap& findex,
                            std::vector<std::size_t>& fcc)
{
  std::vector<std::size_t> parent(number_of_points);
  for(std::size_t i = 0; i < number_of_points; ++i) parent[i] = i;
  auto root = [&](std::size_t i) {
    while(parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for(const std::array<std::size_t, 3>& t : triangles)
    for(int k = 1; k < 3; ++k)
    {
      const std::size_t a = root(t[0]), b = root(t[k]);
      if(a != b) parent[(std::max)(a, b)] = (std::min)(a, b);
    }
  std::size_t count = 0;
  std::vector<std::size_t> id_of_root(number_of_points, std::size_t(-1));
  for(std::size_t t = 0; t < triangles.size(); ++t)
  {
    const std::size_t r = root(triangles[t][0]);
    if(id_of_root[r] == std::size_t(-1)) id_of_root[r] = count++;
    fcc[get(findex, triangle_face[t])] = id_of_root[r];
  }
  return count;
}

// Orients every closed connected component outward (positive enclosed volume); returns how many
// were reversed. Closedness is per component here, so not CGAL::is_closed().
// `fcc` and `ncc`: the component of each face (by its index in `findex`) and their number.
template <typename TriangleMesh, typename FaceIndexMap>
std::size_t orient_closed_components_outward(TriangleMesh& tm, const FaceIndexMap& findex,
                                             const std::vector<std::size_t>& fcc, std::size_t ncc)
{
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  typedef typename boost::property_traits<typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::type>::value_type Point;
  std::vector<double> volume(ncc, 0.);
  std::vector<char> closed(ncc, 1);
  const auto vpm = get(CGAL::vertex_point, tm);
  for(face_descriptor f : faces(tm))
  {
    const std::size_t c = fcc[get(findex, f)];
    std::array<std::array<double, 3>, 3> p;
    auto h = halfedge(f, tm);
    for(int k = 0; k < 3; ++k, h = next(h, tm))
    {
      const Point& q = get(vpm, target(h, tm));
      p[k] = {{CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z())}};
      if(is_border(opposite(h, tm), tm)) closed[c] = 0;
    }
    volume[c] += p[0][0] * (p[1][1] * p[2][2] - p[1][2] * p[2][1])
               - p[0][1] * (p[1][0] * p[2][2] - p[1][2] * p[2][0])
               + p[0][2] * (p[1][0] * p[2][1] - p[1][1] * p[2][0]);
  }
  std::vector<face_descriptor> to_reverse;
  for(face_descriptor f : faces(tm))
    if(closed[fcc[get(findex, f)]] && volume[fcc[get(findex, f)]] < 0.) to_reverse.push_back(f);
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
  const std::size_t* first = soup.file.polygon_begin(f);
  const std::size_t* last = soup.file.polygon_end(f);
  for(const std::size_t* id = first; id != last; ++id)
  {
    const std::size_t t = triangle_of_point[soup.merged[*id]];
    if(t != std::size_t(-1) && position_of_triangle[t] != std::size_t(-1)) return position_of_triangle[t];
  }
  // isolated degenerate face: the mesh face with the nearest centroid
  std::size_t donor = std::size_t(-1);
  std::array<double, 3> c = {{0., 0., 0.}};
  for(const std::size_t* id = first; id != last; ++id)
    for(int a = 0; a < 3; ++a) c[a] += soup.points[soup.merged[*id]][a] / double(last - first);
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
                                       TriangleMesh& tm)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::type VPM;
  typedef typename boost::property_traits<VPM>::value_type Point;

  IO::Mesh_file_info info;
  info.number_of_input_faces = soup.file.number_of_polygons();
  info.number_of_input_vertices = soup.file.number_of_points();
  info.number_of_ignored_values = soup.file.ignored_values;
  check_polygon_soup(name, soup.file);
  merge_equal_points(soup);
  info.number_of_merged_vertices = soup.file.number_of_points() - soup.points.size();
  info.number_of_triangulated_faces = triangulate_polygons(soup);
  if(soup.triangles.empty())
    throw Invalid_input(Input_error::NO_FACES, name + " has no face with three distinct vertices");
  info.number_of_welded_vertices = weld_soup_points(soup, weld_tolerance);

  // The first triangle incident to each merged point, to give dropped faces a neighbour's result.
  std::vector<std::size_t> triangle_of_point(soup.points.size(), std::size_t(-1));
  for(std::size_t t = 0; t < soup.triangles.size(); ++t)
    for(std::size_t id : soup.triangles[t])
      if(triangle_of_point[id] == std::size_t(-1)) triangle_of_point[id] = t;

  std::vector<Point> soup_points;
  soup_points.reserve(soup.points.size());
  for(const std::array<double, 3>& c : soup.points) soup_points.push_back(Point(c[0], c[1], c[2]));
  bool oriented_manifold = is_oriented_manifold_soup(soup.triangles, soup_points.size());
  if(!oriented_manifold)
  {
    CGAL::Polygon_mesh_processing::orient_polygon_soup(soup_points, soup.triangles);
    oriented_manifold = is_oriented_manifold_soup(soup.triangles, soup_points.size());
  }
  info.number_of_duplicated_vertices = soup_points.size() - soup.points.size();

  reserve(tm, typename boost::graph_traits<TriangleMesh>::vertices_size_type(soup_points.size()),
          typename boost::graph_traits<TriangleMesh>::edges_size_type(3 * soup.triangles.size() / 2 + 3),
          typename boost::graph_traits<TriangleMesh>::faces_size_type(soup.triangles.size()));
  const auto vmap = add_used_points(soup_points, soup.triangles, tm);
  // the mesh add_face() would build, without its searches, when the soup is a clean one
  const std::vector<typename GT::face_descriptor> triangle_face =
    oriented_manifold ? add_oriented_manifold_triangles(soup.triangles, vmap, tm) : add_triangles(soup.triangles, vmap, tm);
  drop_faces_of_refused_triangles<TriangleMesh>(triangle_face, soup);
  if(faces(tm).begin() == faces(tm).end())
    throw Invalid_input(Input_error::NO_FACES, name + " gives no valid triangle");
  const auto findex = CGAL::get_initialized_face_index_map(tm);
  std::vector<std::size_t> fcc(num_faces(tm));
  // a refused triangle may join two components through its points: then the mesh decides
  const std::size_t ncc =
    std::find(triangle_face.begin(), triangle_face.end(), GT::null_face()) == triangle_face.end()
      ? soup_components(soup.triangles, soup_points.size(), triangle_face, findex, fcc)
      : face_components(tm, findex, fcc);
  info.number_of_reversed_components = orient_closed_components_outward(tm, findex, fcc, ncc);
  record_face_correspondence(tm, soup, soup_points, triangle_of_point, triangle_face, info);
  return info;
}

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

The file is read into memory at once and parsed in place by the package's own parsers (see the
user manual for what each reads). An STL file stores the corners of each triangle apart: its vertices are
the distinct corners, so that `Mesh_file_info::number_of_input_vertices` counts them and
`Mesh_file_info::number_of_merged_vertices` is 0.

\tparam TriangleMesh a model of `MutableFaceGraph` whose point type is a \cgal point
\tparam NamedParameters a sequence of named parameters

\param filename the file
\param tm an empty mesh that receives the triangles
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{weld_tolerance}
    \cgalParamDescription{the distance, as a fraction of the diagonal of the bounding box of the
                          triangles, within which vertices on a border are welded; 0 welds nothing}
    \cgalParamType{`double`, in `[0, 0.01]`}
    \cgalParamDefault{`5e-6`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the correspondence between the faces of `tm` and those of the file.

\par Complexity
\f$O(n \log n)\f$ for a file of size \f$n\f$ (the merging of equal vertices, a sort, and the
search of the border vertices to weld), plus the ear
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
  const double weld_tolerance = internal::read_weld_tolerance(np);
  internal::File_soup soup;
  internal::parse_polygon_soup(filename, soup.file);
  Mesh_file_info info = internal::build_triangle_mesh(soup, "'" + filename + "'", weld_tolerance, tm);
  if(CGAL::IO::internal::get_file_extension(filename) == "stl")
  {
    // the distinct corners are the file's vertices
    info.number_of_input_vertices -= info.number_of_merged_vertices;
    info.number_of_merged_vertices = 0;
  }
  return info;
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
\param np an optional sequence of named parameters: `weld_tolerance` (see `read_triangle_mesh()`)

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

#endif // CGAL_PART_DECOMPOSITION_IO_READ_MESH_H
