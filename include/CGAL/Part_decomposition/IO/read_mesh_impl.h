// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_IO_READ_MESH_IMPL_H
#define CGAL_PART_DECOMPOSITION_IO_READ_MESH_IMPL_H

// The reader of `IO/read_mesh.h`: the parsers and the building of the mesh.
#include <CGAL/Part_decomposition/IO/read_mesh.h>
#include <CGAL/Part_decomposition/input_validation.h>
#include <CGAL/Part_decomposition/parameters.h>
#include <CGAL/Part_decomposition/internal/io/polygon_soup.h>
#include <CGAL/Part_decomposition/internal/io/read_error.h>
#include <CGAL/Part_decomposition/internal/io/read_gltf_soup.h>
#include <CGAL/Part_decomposition/internal/io/read_obj_soup.h>
#include <CGAL/Part_decomposition/internal/io/read_off_soup.h>
#include <CGAL/Part_decomposition/internal/io/read_ply_soup.h>
#include <CGAL/Part_decomposition/internal/io/read_stl_soup.h>
#include <CGAL/Part_decomposition/internal/io/oriented_manifold_soup.h>
#include <CGAL/Part_decomposition/internal/io/oriented_soup_to_mesh.h>
#include <CGAL/Part_decomposition/internal/io/triangulate_polygon.h>
#include <CGAL/Part_decomposition/internal/io/weld_border_points.h>
#include <CGAL/Part_decomposition/internal/toolbox/toolbox.h>

#include <CGAL/IO/helpers.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/use.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Dynamic_property_map.h>

#include <cstring>

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

/// \cond SKIP_IN_MANUAL
namespace internal {

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
  sort_values<CGAL::Parallel_if_available_tag>(order.begin(), order.end(), less);
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
// (disjoint sets of the face indices: CGAL's connected_components() is several times slower on
// a million faces). Returns their number.
template <typename TriangleMesh, typename FaceIndexMap>
std::size_t face_components(const TriangleMesh& tm, const FaceIndexMap& index, std::vector<std::size_t>& component)
{
  const std::size_t n = component.size();
  Index_sets sets(n);
  for(auto f : faces(tm))
  {
    auto h = halfedge(f, tm);
    for(int k = 0; k < 3; ++k, h = next(h, tm))
    {
      const auto g = face(opposite(h, tm), tm);
      if(g != boost::graph_traits<TriangleMesh>::null_face()) sets.unite(get(index, f), get(index, g));
    }
  }
  std::size_t count = 0;
  std::vector<std::size_t> id_of_root(n, std::size_t(-1));
  for(auto f : faces(tm))
  {
    const std::size_t r = sets.find(get(index, f));
    if(id_of_root[r] == std::size_t(-1)) id_of_root[r] = count++;
    component[get(index, f)] = id_of_root[r];
  }
  return count;
}

// The components of the triangles of an oriented manifold soup (what orient_polygon_soup()
// returns, or a soup that needed no orientation), each triangle added as a face: triangles that
// share a point share an edge, since the triangles around each point form one fan. Disjoint sets
// of the points, fewer and read in a more local order than the faces of the mesh. `fcc` is indexed
// by the index of the face of each triangle.
template <typename FaceIndexMap, typename FaceDescriptor>
std::size_t soup_components(const std::vector<std::array<std::size_t, 3> >& triangles, std::size_t number_of_points,
                            const std::vector<FaceDescriptor>& triangle_face, const FaceIndexMap& findex,
                            std::vector<std::size_t>& fcc)
{
  Index_sets sets(number_of_points);
  for(const std::array<std::size_t, 3>& t : triangles)
    for(int k = 1; k < 3; ++k) sets.unite(t[0], t[k]);
  std::size_t count = 0;
  std::vector<std::size_t> id_of_root(number_of_points, std::size_t(-1));
  for(std::size_t t = 0; t < triangles.size(); ++t)
  {
    const std::size_t r = sets.find(triangles[t][0]);
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
  const auto vpm = get(CGAL::vertex_point, tm);
  const std::vector<face_descriptor> face_list(faces(tm).begin(), faces(tm).end());
  // per face, six times the signed volume of its tetrahedron with the origin, and whether it has a
  // border edge
  std::vector<double> det(face_list.size());
  std::vector<char> on_border(face_list.size(), 0);
  for_each_range<CGAL::Parallel_if_available_tag>(face_list.size(), [&](std::size_t b, std::size_t e) {
    for(std::size_t i = b; i < e; ++i)
    {
      std::array<std::array<double, 3>, 3> p;
      auto h = halfedge(face_list[i], tm);
      for(int k = 0; k < 3; ++k, h = next(h, tm))
      {
        const Point& q = get(vpm, target(h, tm));
        p[k] = {{CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z())}};
        if(is_border(opposite(h, tm), tm)) on_border[i] = 1;
      }
      det[i] = p[0][0] * (p[1][1] * p[2][2] - p[1][2] * p[2][1]) - p[0][1] * (p[1][0] * p[2][2] - p[1][2] * p[2][0]) +
               p[0][2] * (p[1][0] * p[2][1] - p[1][1] * p[2][0]);
    }
  }, 4096);
  // the sums in face order, whatever the number of threads
  std::vector<double> volume(ncc, 0.);
  std::vector<char> closed(ncc, 1);
  for(std::size_t i = 0; i < face_list.size(); ++i)
  {
    const std::size_t c = fcc[get(findex, face_list[i])];
    if(on_border[i]) closed[c] = 0;
    volume[c] += det[i];
  }
  std::vector<face_descriptor> to_reverse;
  for(face_descriptor f : face_list)
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
  // a soup whose every edge has two triangles has no border point to weld
  Soup_topology topology = soup_topology(soup.triangles, soup.points.size());
  info.number_of_welded_vertices = topology.has_edge_of_one_triangle ? weld_soup_points(soup, weld_tolerance) : 0;
  if(info.number_of_welded_vertices > 0) topology = soup_topology(soup.triangles, soup.points.size());

  // The first triangle incident to each merged point, to give dropped faces a neighbour's result.
  std::vector<std::size_t> triangle_of_point(soup.points.size(), std::size_t(-1));
  for(std::size_t t = 0; t < soup.triangles.size(); ++t)
    for(std::size_t id : soup.triangles[t])
      if(triangle_of_point[id] == std::size_t(-1)) triangle_of_point[id] = t;

  std::vector<Point> soup_points;
  soup_points.reserve(soup.points.size());
  for(const std::array<double, 3>& c : soup.points) soup_points.push_back(Point(c[0], c[1], c[2]));
  if(!topology.oriented_manifold)
  {
    CGAL::Polygon_mesh_processing::orient_polygon_soup(soup_points, soup.triangles);
    topology = soup_topology(soup.triangles, soup_points.size());
  }
  info.number_of_duplicated_vertices = soup_points.size() - soup.points.size();

  reserve(tm, typename boost::graph_traits<TriangleMesh>::vertices_size_type(soup_points.size()),
          typename boost::graph_traits<TriangleMesh>::edges_size_type(3 * soup.triangles.size() / 2 + 3),
          typename boost::graph_traits<TriangleMesh>::faces_size_type(soup.triangles.size()));
  const auto vmap = add_used_points(soup_points, soup.triangles, tm);
  // the mesh add_face() would build, without its searches, when the soup is a clean one
  const std::vector<typename GT::face_descriptor> triangle_face =
    topology.oriented_manifold ? add_oriented_manifold_triangles(soup.triangles, vmap, topology.reverse, tm)
                               : add_triangles(soup.triangles, vmap, tm);
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

template <typename TriangleMesh>
IO::Mesh_file_info read_mesh_file(const std::string& filename, double weld_tolerance, TriangleMesh& tm)
{
  File_soup soup;
  parse_polygon_soup(filename, soup.file);
  IO::Mesh_file_info info = build_triangle_mesh(soup, "'" + filename + "'", weld_tolerance, tm);
  if(CGAL::IO::internal::get_file_extension(filename) == "stl")
  {
    // the distinct corners are the file's vertices
    info.number_of_input_vertices -= info.number_of_merged_vertices;
    info.number_of_merged_vertices = 0;
  }
  return info;
}

} // namespace internal
/// \endcond

} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_IO_READ_MESH_IMPL_H
