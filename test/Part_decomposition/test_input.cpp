// Input handling: voxel binning, normalization, the reader on files that real data produce, and
// the glTF writers that copy a file (labels as feature IDs, parts with the file's attributes).
#include <catch2/catch.hpp>

#include <CGAL/Part_decomposition/IO/read_mesh.h>
#include <CGAL/Part_decomposition/IO/write_labels_gltf.h>
#include <CGAL/Part_decomposition/IO/write_parts_gltf.h>
#include <CGAL/Part_decomposition/Voxel_grid.h>
#include <CGAL/Part_decomposition/internal/io/oriented_manifold_soup.h>
#include <CGAL/Part_decomposition/internal/io/oriented_soup_to_mesh.h>
#include <CGAL/Part_decomposition/normalization.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/boost/graph/helpers.h>

#include "sha256.h"
#include "test_shapes.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <iterator>
#include <limits>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace PD = CGAL::Part_decomposition;
using test_shapes::Mesh;
using test_shapes::Point;

namespace {

std::string write_temp(const std::string& name, const std::string& content)
{
  const std::string path = std::string("pd_test_") + name;
  std::ofstream out(path, std::ios::binary);
  out << content;
  return path;
}

PD::Input_error read_error(const std::string& path)
{
  Mesh m;
  try { PD::IO::read_triangle_mesh(path, m); }
  catch(const PD::Invalid_input& e) { return e.error(); }
  FAIL("no exception for " << path);
  return PD::Input_error::INVALID_PARAMETER;
}

} // namespace

TEST_CASE("voxel binning follows floor((p+0.5)r) and clamps p = +0.5", "[grid]")
{
  for(int r : {16, 32, 64})
  {
    CHECK(PD::voxel_coordinate(-0.5, r) == 0);
    CHECK(PD::voxel_coordinate(0.5, r) == r - 1);
    CHECK(PD::voxel_coordinate(0.0, r) == r / 2);                 // on a split plane: upper voxel
    CHECK(PD::voxel_coordinate(-0.5 + 1. / r, r) == 1);
    CHECK(PD::voxel_coordinate(-0.5 + 1. / r - 1e-12, r) == 0);
    CHECK(PD::voxel_coordinate(0.7, r) == r - 1);
    CHECK(PD::voxel_coordinate(-3.0, r) == 0);
  }
  PD::Voxel_grid<int> g(16, 7);
  CHECK(g.size() == 4096u);
  const std::size_t idx = g.index(3, 4, 5);
  CHECK(idx == 3u + 16u * (4u + 16u * 5u));
  const auto c = g.coordinates(idx);
  CHECK((c[0] == 3 && c[1] == 4 && c[2] == 5));
  const auto ctr = g.center(0, 15, 8);
  CHECK(ctr[0] == Approx(-0.5 + 0.5 / 16));
  CHECK(ctr[1] == Approx(0.5 - 0.5 / 16));
  CHECK(ctr[2] == Approx(0.5 / 16));
  const auto loc = g.locate(ctr[0], ctr[1], ctr[2]);
  CHECK((loc[0] == 0 && loc[1] == 15 && loc[2] == 8));
}

TEST_CASE("normalization maps the bounding box into the cube with the margin", "[normalization]")
{
  Mesh m = test_shapes::make_box(Point(1, 2, 3), Point(5, 4, 3.5), 1);
  const PD::Normalization n = PD::compute_normalization(m);
  const double margin = 2. / 64.;
  CHECK(n.scale() == Approx((1. - 2. * margin) / 4.));
  const auto lo = n.to_unit(Point(1, 2, 3)), hi = n.to_unit(Point(5, 4, 3.5));
  CHECK(lo[0] == Approx(-0.5 + margin));
  CHECK(hi[0] == Approx(0.5 - margin));
  CHECK(lo[1] == Approx(-0.25 * (1. - 2. * margin)));
  const auto back = n.from_unit(hi);
  CHECK(back[0] == Approx(5));
  CHECK(back[2] == Approx(3.5));

  // far from the origin, tiny and huge
  for(double s : {1e-8, 1e8})
  {
    Mesh far = test_shapes::make_box(Point(1e6, -1e6, 1e6), Point(1e6 + s, -1e6 + 2 * s, 1e6 + s), 1);
    const PD::Normalization nf = PD::compute_normalization(far);
    const auto a = nf.to_unit(Point(1e6, -1e6, 1e6));
    CHECK(a[1] == Approx(-0.5 + margin).margin(1e-6));
  }
  CHECK_THROWS_AS(PD::compute_normalization(m, PD::parameters::normalization_margin(0.4)), PD::Invalid_input);
}

TEST_CASE("normalization: the default margin equals defaults::normalization_margin given explicitly", "[input]")
{
  const Mesh m = test_shapes::make_box(Point(-2, 1, 0), Point(3, 4, 7), 2);
  const PD::Normalization a = PD::compute_normalization(m);
  const PD::Normalization b =
    PD::compute_normalization(m, PD::parameters::normalization_margin(PD::defaults::normalization_margin));
  CHECK(a.center() == b.center());
  CHECK(a.scale() == b.scale());
  // the longest side (7) goes to 1 - 2 * margin
  CHECK(a.scale() == Approx((1. - 2. * PD::defaults::normalization_margin) / 7.));
  try
  {
    PD::compute_normalization(m, PD::parameters::normalization_margin(-0.1));
    FAIL("no exception");
  }
  catch(const PD::Invalid_input& e)
  {
    CHECK(std::string(e.what()) == "normalization_margin must be in [0, 0.25]");
  }
}

TEST_CASE("the reader keeps the file's face order through a non-manifold soup", "[io]")
{
  // 0: three triangles on one edge (non-manifold), a quad, a degenerate face, an isolated point
  const std::string off =
    "OFF\n8 6 0\n"
    "0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n"
    "2 0 0\n3 0 0\n9 9 9\n"
    "3 0 1 2\n"
    "3 1 0 3\n"
    "3 0 1 4\n"
    "4 1 5 6 4\n"       // quad, triangulated
    "3 5 5 6\n"         // repeated vertex: dropped, takes a neighbour's label
    "3 2 4 3\n";
  const std::string path = write_temp("nonmanifold.off", off);
  Mesh m;
  const PD::IO::Mesh_file_info info = PD::IO::read_triangle_mesh(path, m);
  CHECK(info.number_of_input_faces == 6u);
  CHECK(num_faces(m) == 6u); // 4 triangles + quad as 2, minus the dropped one
  REQUIRE(info.face_to_input.size() == num_faces(m));
  REQUIRE(info.dropped_faces.size() == 1u);
  CHECK(info.dropped_faces[0].first == 4u);
  CHECK(info.number_of_triangulated_faces == 1u);
  CHECK(info.number_of_duplicated_vertices > 0u);
  CHECK(CGAL::is_triangle_mesh(m));

  // label every mesh face by its file face: the round trip gives 0..5 back, in order
  std::vector<std::size_t> labels(info.face_to_input.begin(), info.face_to_input.end());
  const std::vector<std::size_t> in_file = PD::IO::labels_in_file_order(info, labels);
  REQUIRE(in_file.size() == 6u);
  for(std::size_t f : {0u, 1u, 2u, 3u, 5u}) CHECK(in_file[f] == f);
  // the dropped face shares vertices 5 and 6 with the quad only
  CHECK(in_file[4] == 3u);
  std::remove(path.c_str());
}

TEST_CASE("the reader merges STL corners and orients closed pieces outward", "[io]")
{
  // a tetrahedron written inward-facing, as STL (each triangle has its own corners)
  const Point p[4] = {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1)};
  const int tris[4][3] = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}}; // inward
  std::string stl = "solid t\n";
  for(const auto& t : tris)
  {
    stl += " facet normal 0 0 0\n  outer loop\n";
    for(int k = 0; k < 3; ++k)
      stl += "   vertex " + std::to_string(p[t[k]].x()) + " " + std::to_string(p[t[k]].y()) + " " +
             std::to_string(p[t[k]].z()) + "\n";
    stl += "  endloop\n endfacet\n";
  }
  stl += "endsolid t\n";
  const std::string path = write_temp("tet.stl", stl);
  Mesh m;
  const PD::IO::Mesh_file_info info = PD::IO::read_triangle_mesh(path, m);
  CHECK(num_vertices(m) == 4u);
  CHECK(CGAL::is_closed(m));
  CHECK(info.number_of_reversed_components == 1u);
  CHECK(CGAL::Polygon_mesh_processing::volume(m) == Approx(1. / 6.));
  std::remove(path.c_str());
}

TEST_CASE("unreadable or broken files give a clear error", "[io]")
{
  CHECK(read_error("pd_test_does_not_exist.off") == PD::Input_error::UNREADABLE_FILE);
  CHECK(read_error(write_temp("empty.off", "")) == PD::Input_error::UNREADABLE_FILE);
  CHECK(read_error(write_temp("garbage.off", "OFF\nthis is not a mesh\n")) == PD::Input_error::UNREADABLE_FILE);
  CHECK(read_error(write_temp("nofaces.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n")) == PD::Input_error::NO_FACES);
  // CGAL's OFF parser already refuses an out-of-range index
  const PD::Input_error range = read_error(write_temp("range.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n"));
  CHECK((range == PD::Input_error::INVALID_FACE || range == PD::Input_error::UNREADABLE_FILE));
  CHECK(read_error(write_temp("degenerate.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 0 1\n")) ==
        PD::Input_error::NO_FACES);
}

namespace {

// The triangles of a mesh as vertex indices.
std::vector<std::array<std::size_t, 3> > soup_of(const Mesh& m)
{
  std::vector<std::array<std::size_t, 3> > soup;
  for(auto f : faces(m))
  {
    std::array<std::size_t, 3> t;
    int k = 0;
    for(auto v : vertices_around_face(halfedge(f, m), m)) t[std::size_t(k++)] = std::size_t(v);
    soup.push_back(t);
  }
  return soup;
}

} // namespace

TEST_CASE("the oriented-manifold check lets only clean soups skip the orienter", "[io]")
{
  typedef std::vector<std::array<std::size_t, 3> > Triangles;
  // the check the reader runs
  const auto is_oriented_manifold_soup = [](const Triangles& triangles, std::size_t number_of_points) {
    return PD::internal::soup_topology(triangles, number_of_points).oriented_manifold;
  };
  const Mesh box = test_shapes::make_box(Point(0, 0, 0), Point(1, 1, 1), 3);
  const Triangles tris = soup_of(box);
  const std::size_t n = num_vertices(box);
  CHECK(is_oriented_manifold_soup(tris, n));

  Triangles open(tris.begin() + 1, tris.end()); // a hole: still an oriented manifold
  CHECK(is_oriented_manifold_soup(open, n));

  Triangles flipped = tris; // one triangle against its neighbours
  std::swap(flipped[5][0], flipped[5][1]);
  CHECK(!is_oriented_manifold_soup(flipped, n));

  // three triangles on the edge (0, 1)
  CHECK(!is_oriented_manifold_soup(Triangles{{{0, 1, 2}}, {{1, 0, 3}}, {{0, 1, 4}}}, 5));
  // two fans that share only their apex 0 (a bowtie): each edge is fine, the vertex is not
  CHECK(is_oriented_manifold_soup(Triangles{{{0, 1, 2}}, {{0, 2, 3}}}, 7));
  CHECK(!is_oriented_manifold_soup(Triangles{{{0, 1, 2}}, {{0, 2, 3}}, {{0, 4, 5}}, {{0, 5, 6}}}, 7));
  // a closed fan (cycle) around vertex 0 and a cycle with a dangling fan at the same vertex
  CHECK(is_oriented_manifold_soup(Triangles{{{0, 1, 2}}, {{0, 2, 3}}, {{0, 3, 1}}, {{1, 3, 2}}}, 4));
  CHECK(!is_oriented_manifold_soup(Triangles{{{0, 1, 2}}, {{0, 2, 3}}, {{0, 3, 1}}, {{1, 3, 2}}, {{0, 4, 5}}}, 6));
}

namespace {

// The connectivity of every element, in index order: equal lists are equal meshes.
std::vector<std::size_t> connectivity(const Mesh& m)
{
  std::vector<std::size_t> out;
  for(auto h : halfedges(m))
    for(std::size_t x : {std::size_t(next(h, m)), std::size_t(prev(h, m)), std::size_t(target(h, m)),
                         is_border(h, m) ? std::size_t(-1) : std::size_t(face(h, m))})
      out.push_back(x);
  for(auto v : vertices(m)) out.push_back(std::size_t(halfedge(v, m)));
  for(auto f : faces(m)) out.push_back(std::size_t(halfedge(f, m)));
  return out;
}

// Builds `triangles` with the reader's builder for an oriented manifold soup: the general one
// (one element at a time, any mesh) or the one of Surface_mesh (in parallel).
Mesh build_soup(const std::vector<std::array<std::size_t, 3> >& triangles, std::size_t n, bool general)
{
  Mesh m;
  std::vector<Mesh::Vertex_index> vmap;
  for(std::size_t i = 0; i < n; ++i) vmap.push_back(m.add_vertex(Point(double(i), 0, 0)));
  const std::vector<std::size_t> reverse = PD::internal::soup_topology(triangles, n).reverse;
  if(general) PD::internal::add_oriented_manifold_triangles<Mesh>(triangles, vmap, reverse, m);
  else PD::internal::add_oriented_manifold_triangles(triangles, vmap, reverse, m);
  return m;
}

} // namespace

TEST_CASE("the reader's builders make the mesh of add_face() on closed and open soups", "[io]")
{
  typedef std::vector<std::array<std::size_t, 3> > Triangles;
  const Mesh sphere = test_shapes::make_sphere(Point(0, 0, 0), 1., 3);
  const Triangles closed = soup_of(sphere);
  Triangles open; // two holes
  for(std::size_t t = 0; t < closed.size(); ++t)
    if(t != 3 && t != closed.size() / 2) open.push_back(closed[t]);
  const std::size_t n = num_vertices(sphere);
  REQUIRE(PD::internal::soup_topology(open, n).oriented_manifold);
  for(const Triangles* soup : {&closed, static_cast<const Triangles*>(&open)})
  {
    Mesh expected;
    for(std::size_t i = 0; i < n; ++i) expected.add_vertex(Point(double(i), 0, 0));
    for(const auto& t : *soup)
      REQUIRE(CGAL::Euler::add_face(std::array<Mesh::Vertex_index, 3>{{Mesh::Vertex_index(Mesh::size_type(t[0])),
                                                                        Mesh::Vertex_index(Mesh::size_type(t[1])),
                                                                        Mesh::Vertex_index(Mesh::size_type(t[2]))}},
                                    expected) != Mesh::null_face());
    CHECK(connectivity(build_soup(*soup, n, true)) == connectivity(expected));
    CHECK(connectivity(build_soup(*soup, n, false)) == connectivity(expected));
    CHECK(build_soup(*soup, n, false).is_valid(false));
  }
}

// ---- glTF

namespace {

typedef std::array<float, 3> Float3;
typedef std::array<std::uint32_t, 3> Tri;

// The triangles of a test shape, with float coordinates (what a glTF file stores).
void shape_arrays(const Mesh& m, std::vector<Float3>& points, std::vector<Tri>& tris)
{
  for(auto v : vertices(m)) points.push_back({{float(m.point(v).x()), float(m.point(v).y()), float(m.point(v).z())}});
  for(auto f : faces(m))
  {
    Tri t;
    int k = 0;
    for(auto v : vertices_around_face(halfedge(f, m), m)) t[k++] = std::uint32_t(v);
    tris.push_back(t);
  }
}

// Assembles a glTF file: one buffer, one view and accessor per array.
struct Gltf_builder
{
  nlohmann::json j = {{"asset", {{"version", "2.0"}}}, {"bufferViews", nlohmann::json::array()},
                      {"accessors", nlohmann::json::array()}, {"meshes", nlohmann::json::array()},
                      {"nodes", nlohmann::json::array()}};
  std::string bin;

  template <typename T>
  std::size_t accessor(const std::vector<T>& items, int component_type, const char* type, std::size_t count)
  {
    while(bin.size() % 4) bin += '\0';
    j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", items.size() * sizeof(T)}});
    bin.append(reinterpret_cast<const char*>(items.data()), items.size() * sizeof(T));
    j["accessors"].push_back({{"bufferView", j["bufferViews"].size() - 1}, {"componentType", component_type},
                              {"type", type}, {"count", count}});
    return j["accessors"].size() - 1;
  }
  std::size_t positions(const std::vector<Float3>& p) { return accessor(p, 5126, "VEC3", p.size()); }
  template <typename Index>
  std::size_t indices(const std::vector<Tri>& tris)
  {
    std::vector<Index> flat;
    for(const Tri& t : tris)
      for(std::uint32_t i : t) flat.push_back(Index(i));
    return accessor(flat, sizeof(Index) == 2 ? 5123 : 5125, "SCALAR", flat.size());
  }
  std::string json_text(const nlohmann::json& buffer)
  {
    nlohmann::json out = j;
    out["buffers"] = nlohmann::json::array({buffer});
    return out.dump();
  }
  std::string glb()
  {
    std::string text = json_text({{"byteLength", bin.size()}});
    while(text.size() % 4) text += ' ';
    std::string data = bin;
    while(data.size() % 4) data += '\0';
    auto u32 = [](std::uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
    return "glTF" + u32(2) + u32(std::uint32_t(12 + 8 + text.size() + 8 + data.size())) + u32(std::uint32_t(text.size())) +
           "JSON" + text + u32(std::uint32_t(data.size())) + std::string("BIN\0", 4) + data;
  }
  std::string embedded()
  {
    static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string b64;
    for(std::size_t i = 0; i < bin.size(); i += 3)
    {
      const std::size_t n = (std::min)(std::size_t(3), bin.size() - i);
      std::uint32_t v = 0;
      for(std::size_t k = 0; k < 3; ++k) v = (v << 8) | (k < n ? std::uint32_t((unsigned char)bin[i + k]) : 0u);
      b64 += digits[(v >> 18) & 63];
      b64 += digits[(v >> 12) & 63];
      b64 += n > 1 ? digits[(v >> 6) & 63] : '=';
      b64 += n > 2 ? digits[v & 63] : '=';
    }
    return json_text({{"byteLength", bin.size()}, {"uri", "data:application/octet-stream;base64," + b64}});
  }
};

// The scene of the tests: a box (uint16 indices) under a TRS node whose child, with a matrix,
// holds a sphere (uint32 indices) and a non-indexed triangle. The transforms are exact in
// floating point, so the same geometry written as OFF gives the same soup bit for bit.
struct Gltf_scene
{
  Gltf_builder b;
  std::string off; // the same triangles, in the reader's documented order
  std::size_t number_of_triangles = 0;

  Gltf_scene()
  {
    std::vector<Float3> box_points, sphere_points;
    std::vector<Tri> box_tris, sphere_tris;
    shape_arrays(test_shapes::make_box(Point(0, 0, 0), Point(1, 0.5, 0.25), 2), box_points, box_tris);
    shape_arrays(test_shapes::make_sphere(Point(0, 0, 0), 0.5, 2), sphere_points, sphere_tris);
    const std::vector<Float3> loose = {{{0.f, 0.f, 2.f}}, {{1.f, 0.f, 2.f}}, {{0.f, 1.f, 2.f}}};
    const std::size_t box_pos = b.positions(box_points), box_idx = b.indices<std::uint16_t>(box_tris);
    const std::size_t sphere_pos = b.positions(sphere_points), sphere_idx = b.indices<std::uint32_t>(sphere_tris);
    const std::size_t loose_pos = b.positions(loose);
    b.j["meshes"].push_back({{"primitives", {{{"attributes", {{"POSITION", box_pos}}}, {"indices", box_idx}}}}});
    b.j["meshes"].push_back({{"primitives", {{{"attributes", {{"POSITION", sphere_pos}}}, {"indices", sphere_idx}, {"mode", 4}},
                                             {{"attributes", {{"POSITION", loose_pos}}}}}}});
    // parent: scale 2, half a turn about z, then a shift along x
    b.j["nodes"].push_back({{"mesh", 0}, {"children", {1}}, {"translation", {3., 0., 0.}},
                            {"rotation", {0., 0., 1., 0.}}, {"scale", {2., 2., 2.}}});
    // child: (x, y, z) -> (z, x, y) + (0, 5, 0), column-major
    b.j["nodes"].push_back({{"mesh", 1}, {"matrix", {0., 1., 0., 0., 0., 0., 1., 0., 1., 0., 0., 0., 0., 5., 0., 1.}}});
    b.j["scenes"] = {{{"nodes", {0}}}};
    b.j["scene"] = 0;

    auto parent = [](double x, double y, double z) { return std::array<double, 3>{{3. - 2. * x, -2. * y, 2. * z}}; };
    auto world = [&](const Float3& p) { return parent(p[2], double(p[0]) + 5., p[1]); };
    std::vector<std::array<double, 3> > points;
    std::vector<std::array<std::size_t, 3> > tris;
    auto add = [&](const std::vector<Float3>& ps, const std::vector<Tri>& ts, bool child) {
      const std::size_t base = points.size();
      for(const Float3& p : ps) points.push_back(child ? world(p) : parent(p[0], p[1], p[2]));
      for(const Tri& t : ts) tris.push_back({{base + t[0], base + t[1], base + t[2]}});
    };
    add(box_points, box_tris, false);
    add(sphere_points, sphere_tris, true);
    add(loose, {{{0, 1, 2}}}, true);
    std::ostringstream out;
    out.precision(17);
    out << "OFF\n" << points.size() << ' ' << tris.size() << " 0\n";
    for(const auto& p : points) out << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
    for(const auto& t : tris) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
    off = out.str();
    number_of_triangles = tris.size();
  }
};

// The triangles of a mesh, by their corners, in the order of faces(m).
std::vector<std::array<Point, 3> > corners_of(const Mesh& m)
{
  std::vector<std::array<Point, 3> > out;
  for(auto f : faces(m))
  {
    std::array<Point, 3> c;
    int k = 0;
    for(auto v : vertices_around_face(halfedge(f, m), m)) c[k++] = m.point(v);
    out.push_back(c);
  }
  return out;
}

} // namespace

TEST_CASE("glTF: nested node transforms, uint16 and uint32 indices, GLB, embedded and side-by-side buffers", "[io][gltf]")
{
  Gltf_scene scene;
  Mesh from_off;
  const PD::IO::Mesh_file_info off_info = PD::IO::read_triangle_mesh(write_temp("scene.off", scene.off), from_off);
  REQUIRE(off_info.number_of_input_faces == scene.number_of_triangles);

  write_temp("scene.bin", scene.b.bin);
  nlohmann::json side = nlohmann::json::parse(scene.b.json_text({{"byteLength", scene.b.bin.size()}, {"uri", "pd_test_scene.bin"}}));
  for(const std::string& path : {write_temp("scene.glb", scene.b.glb()), write_temp("embedded.gltf", scene.b.embedded()),
                                 write_temp("side.gltf", side.dump())})
  {
    Mesh m;
    const PD::IO::Mesh_file_info info = PD::IO::read_triangle_mesh(path, m);
    // one file face per triangle, and the very mesh of the same triangles written as OFF
    CHECK(info.number_of_input_faces == scene.number_of_triangles);
    CHECK(info.face_to_input == off_info.face_to_input);
    CHECK(corners_of(m) == corners_of(from_off));
    std::vector<std::size_t> labels(info.face_to_input.begin(), info.face_to_input.end());
    CHECK(PD::IO::labels_in_file_order(info, labels).size() == scene.number_of_triangles);
  }
  // the child's sphere lies at x in [2, 4] after both transforms: the matrix was applied, then the TRS
  CGAL::Bbox_3 box;
  for(auto v : vertices(from_off)) box += from_off.point(v).bbox();
  CHECK(box.xmin() == Approx(-1.));
  CHECK(box.xmax() == Approx(4.));
  std::remove("pd_test_scene.bin");
}

TEST_CASE("glTF: broken and hostile files are refused with UNREADABLE_FILE", "[io][gltf]")
{
  Gltf_scene scene;
  const std::string glb = scene.b.glb();
  // truncated anywhere: never a crash, always the documented error
  for(std::size_t n : {std::size_t(0), std::size_t(4), std::size_t(11), std::size_t(20), glb.size() / 3, glb.size() - 200})
    CHECK(read_error(write_temp("truncated.glb", glb.substr(0, n))) == PD::Input_error::UNREADABLE_FILE);

  auto refused = [&](const std::string& name, const std::function<void(nlohmann::json&)>& edit) {
    Gltf_builder b = scene.b;
    edit(b.j);
    return read_error(write_temp(name, b.glb()));
  };
  using J = nlohmann::json;
  CHECK(refused("view.glb", [](J& j) { j["bufferViews"][0]["byteOffset"] = 1u << 30; }) == PD::Input_error::UNREADABLE_FILE);
  CHECK(refused("length.glb", [](J& j) { j["bufferViews"][1]["byteLength"] = 1u << 20; }) == PD::Input_error::UNREADABLE_FILE);
  CHECK(refused("count.glb", [](J& j) { j["accessors"][0]["count"] = 1000000; }) == PD::Input_error::UNREADABLE_FILE);
  CHECK(refused("offset.glb", [](J& j) { j["accessors"][1]["byteOffset"] = 4000000000u; }) == PD::Input_error::UNREADABLE_FILE);
  CHECK(refused("stride.glb", [](J& j) { j["bufferViews"][0]["byteStride"] = 4; }) == PD::Input_error::UNREADABLE_FILE);
  CHECK(refused("negative.glb", [](J& j) { j["accessors"][0]["count"] = -3; }) == PD::Input_error::UNREADABLE_FILE);
  CHECK(refused("type.glb", [](J& j) { j["accessors"][0]["componentType"] = 5130; }) == PD::Input_error::UNREADABLE_FILE);
  CHECK(refused("accessor.glb", [](J& j) { j["meshes"][0]["primitives"][0]["indices"] = 99; }) == PD::Input_error::UNREADABLE_FILE);
  CHECK(refused("cycle.glb", [](J& j) { j["nodes"][1]["children"] = {0}; }) == PD::Input_error::UNREADABLE_FILE);
  CHECK(refused("self.glb", [](J& j) { j["nodes"][0]["children"] = {0}; }) == PD::Input_error::UNREADABLE_FILE);
  CHECK(refused("node.glb", [](J& j) { j["scenes"][0]["nodes"] = {7}; }) == PD::Input_error::UNREADABLE_FILE);
  CHECK(refused("draco.glb", [](J& j) { j["extensionsRequired"] = {"KHR_draco_mesh_compression"}; }) == PD::Input_error::UNREADABLE_FILE);
  CHECK(refused("version.glb", [](J& j) { j["asset"]["version"] = "1.0"; }) == PD::Input_error::UNREADABLE_FILE);
  // a buffer outside the file's folder is never opened
  try
  {
    Mesh m;
    PD::IO::read_triangle_mesh(write_temp("escape.gltf", scene.b.json_text({{"byteLength", 4}, {"uri", "../x.bin"}})), m);
    FAIL("no exception");
  }
  catch(const PD::Invalid_input& e)
  {
    CHECK(std::string(e.what()).find("is not a file next to the glTF file") != std::string::npos);
  }
  for(const char* uri : {"../secret.bin", "/etc/passwd", "file:///etc/passwd", "sub/../../x.bin"})
    CHECK(read_error(write_temp("escape.gltf", scene.b.json_text({{"byteLength", 4}, {"uri", uri}}))) ==
          PD::Input_error::UNREADABLE_FILE);
  CHECK(refused("matrix.glb", [](J& j) { j["nodes"][1]["matrix"] = {1., 2.}; }) == PD::Input_error::UNREADABLE_FILE);
  // an index past the positions is the reader's out-of-range face
  std::string bad = glb;
  const std::size_t at = bad.find("BIN") + 3 + 1 + std::size_t(scene.b.j["bufferViews"][1]["byteOffset"].get<std::size_t>());
  bad[at] = char(0xff);
  bad[at + 1] = char(0xff);
  CHECK(read_error(write_temp("index.glb", bad)) == PD::Input_error::INVALID_FACE);
  CHECK(read_error(write_temp("json.gltf", "{\"asset\": {\"version\": \"2.0\"}, \"nodes\": [")) == PD::Input_error::UNREADABLE_FILE);
  CHECK(read_error(write_temp("base64.gltf", "{\"asset\":{\"version\":\"2.0\"},\"buffers\":[{\"byteLength\":3,\"uri\":\"data:,abc\"}]}")) ==
        PD::Input_error::UNREADABLE_FILE);
  CHECK(read_error(write_temp("nothing.gltf", "{\"asset\":{\"version\":\"2.0\"}}")) == PD::Input_error::NO_FACES);
}

TEST_CASE("the reader welds a seam left open by float32 round-off, in glTF and OFF", "[io][gltf][weld]")
{
  // A sphere cut by the plane x = 0.1 into two meshes; the second stored in the frame of its node,
  // (x, y, z) -> 3 R_z(0.7) (x, y, z) + (10, -4, 7), in float32, as exporters write glTF.
  const Mesh sphere = test_shapes::make_sphere(Point(0, 0, 0), 1., 3);
  std::vector<std::array<double, 3> > points;
  std::vector<std::array<std::size_t, 3> > triangles;
  test_shapes::mesh_soup(sphere, points, triangles);
  const float a = float(3. * std::cos(0.7)), b = float(3. * std::sin(0.7)), s = 3.f;
  const std::array<float, 3> t = {{10.f, -4.f, 7.f}};
  std::vector<Float3> world_points, local_points;
  std::vector<Tri> world_tris, local_tris;
  std::vector<std::uint32_t> world_id(points.size(), ~0u), local_id(points.size(), ~0u);
  for(const auto& tri : triangles)
  {
    double x = 0.;
    for(std::size_t v : tri) x += points[v][0] / 3.;
    const bool local = x >= 0.1;
    Tri out;
    for(int k = 0; k < 3; ++k)
    {
      const std::size_t v = tri[std::size_t(k)];
      std::vector<std::uint32_t>& id = local ? local_id : world_id;
      if(id[v] == ~0u)
      {
        const std::array<double, 3>& p = points[v];
        if(local)
        {
          // the inverse of the node transform, in double, stored as float
          const double qx = p[0] - t[0], qy = p[1] - t[1], qz = p[2] - t[2], d = double(a) * a + double(b) * b;
          local_points.push_back({{float((a * qx + b * qy) / d), float((-b * qx + a * qy) / d), float(qz / s)}});
        }
        else
          world_points.push_back({{float(p[0]), float(p[1]), float(p[2])}});
        id[v] = std::uint32_t((local ? local_points : world_points).size() - 1);
      }
      out[std::size_t(k)] = id[v];
    }
    (local ? local_tris : world_tris).push_back(out);
  }
  Gltf_builder g;
  const std::size_t wp = g.positions(world_points), wi = g.indices<std::uint32_t>(world_tris);
  const std::size_t lp = g.positions(local_points), li = g.indices<std::uint32_t>(local_tris);
  g.j["meshes"].push_back({{"primitives", {{{"attributes", {{"POSITION", wp}}}, {"indices", wi}}}}});
  g.j["meshes"].push_back({{"primitives", {{{"attributes", {{"POSITION", lp}}}, {"indices", li}}}}});
  g.j["nodes"].push_back({{"mesh", 0}});
  g.j["nodes"].push_back({{"mesh", 1}, {"matrix", {a, b, 0.f, 0.f, -b, a, 0.f, 0.f, 0.f, 0.f, s, 0.f, t[0], t[1], t[2], 1.f}}});
  g.j["scenes"] = {{{"nodes", {0, 1}}}};
  g.j["scene"] = 0;
  // the same two meshes in one OFF file, the second brought to the world frame in double
  std::ostringstream off;
  off.precision(17);
  off << "OFF\n" << world_points.size() + local_points.size() << ' ' << world_tris.size() + local_tris.size() << " 0\n";
  for(const Float3& p : world_points) off << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  for(const Float3& p : local_points)
    off << double(a) * p[0] - double(b) * p[1] + t[0] << ' ' << double(b) * p[0] + double(a) * p[1] + t[1] << ' '
        << double(s) * p[2] + t[2] << '\n';
  for(const Tri& tr : world_tris) off << "3 " << tr[0] << ' ' << tr[1] << ' ' << tr[2] << '\n';
  for(const Tri& tr : local_tris)
    off << "3 " << tr[0] + world_points.size() << ' ' << tr[1] + world_points.size() << ' ' << tr[2] + world_points.size() << '\n';

  std::size_t seam = 0;
  for(std::size_t v = 0; v < points.size(); ++v) seam += (world_id[v] != ~0u && local_id[v] != ~0u) ? 1 : 0;
  REQUIRE(seam > 10);
  for(const std::string& path : {write_temp("split.glb", g.glb()), write_temp("split.off", off.str())})
  {
    INFO(path);
    Mesh welded, apart;
    const PD::IO::Mesh_file_info info = PD::IO::read_triangle_mesh(path, welded);
    const PD::IO::Mesh_file_info info_apart = PD::IO::read_triangle_mesh(path, apart, PD::parameters::weld_tolerance(0.));
    // every seam vertex is welded: one closed surface, as the unsplit sphere
    CHECK(info.number_of_welded_vertices + info.number_of_merged_vertices == seam);
    CHECK(info_apart.number_of_welded_vertices == 0);
    CHECK(CGAL::is_closed(welded));
    CHECK(!CGAL::is_closed(apart));
    CHECK(num_vertices(welded) == num_vertices(sphere));
    CHECK(num_faces(welded) == num_faces(sphere));
    CHECK(CGAL::Polygon_mesh_processing::volume(welded) == Approx(CGAL::Polygon_mesh_processing::volume(sphere)).epsilon(1e-5));
  }
  auto refused = [&](double tolerance) {
    Mesh m;
    try { PD::IO::read_triangle_mesh(write_temp("split.off", off.str()), m, PD::parameters::weld_tolerance(tolerance)); }
    catch(const PD::Invalid_input& e) { return e.error() == PD::Input_error::INVALID_PARAMETER; }
    return false;
  };
  CHECK(refused(-1.));
  CHECK(refused(0.5));
  CHECK(refused(std::numeric_limits<double>::quiet_NaN()));
}

TEST_CASE("welding never merges two vertices of one triangle, nor vertices inside a surface", "[io][weld]")
{
  // A strip of two triangles whose shared border has a sliver triangle (an edge of 1e-9) at its
  // end, next to a second strip whose border vertices lie 1e-8 away: the strips are welded, the
  // sliver keeps its three vertices. A vertex inside the first strip lies 1e-8 from a vertex of a
  // third, crossing sheet: inner vertices are not welded.
  const std::vector<std::array<double, 3> > points = {
    {{0, 0, 0}}, {{1, 0, 0}}, {{0, 1, 0}}, {{1, 1, 0}},           // strip A: 0-3
    {{0, 0, 1e-8}}, {{1, 0, 1e-8}}, {{0, -1, 0}}, {{1, -1, 0}},    // strip B: 4-7, its top edge on A's bottom edge
    {{1 + 1e-9, 0, 0}},                                             // 8: the sliver's third corner
    {{0.5, 0.5, 0}}, {{0.5 + 1e-8, 0.5, 1e-8}}, {{0.5, 0.5, 1}}, {{0.5, 0.6, -1}}}; // A's centre 9; sheet C: 10-12
  const std::vector<std::array<std::size_t, 3> > triangles = {
    {{0, 1, 9}}, {{1, 3, 9}}, {{3, 2, 9}}, {{2, 0, 9}},  // strip A, a fan around 9
    {{4, 6, 7}}, {{4, 7, 5}},                          // strip B
    {{1, 8, 3}},                                       // the sliver: 1 and 8 are 1e-9 apart
    {{10, 11, 12}}};                                   // sheet C through A's centre
  Mesh m;
  const PD::IO::Mesh_file_info info = PD::IO::triangle_mesh_from_polygon_soup(points, triangles, m);
  CHECK(num_faces(m) == triangles.size());
  CHECK(info.number_of_welded_vertices == 2); // 4 to 0, 5 to 1
  for(auto f : faces(m))
  {
    std::set<Point> corners;
    for(auto v : vertices_around_face(halfedge(f, m), m)) corners.insert(m.point(v));
    CHECK(corners.size() == 3);
  }
  // 13 points, 2 welded; 8 stays apart from 1, 10 from 9
  CHECK(num_vertices(m) == 11);
}

// ---- glTF writers

namespace {

// A GLB read back: its JSON and its binary chunk.
struct Glb
{
  nlohmann::json j;
  std::string bin;

  explicit Glb(const std::string& bytes)
  {
    std::uint32_t length;
    std::memcpy(&length, bytes.data() + 12, 4);
    j = nlohmann::json::parse(bytes.substr(20, length));
    bin = bytes.substr(28 + length);
  }
  // The elements of accessor i, their components as doubles (unsigned integers or floats).
  std::vector<std::vector<double> > accessor(std::size_t i) const
  {
    const nlohmann::json& a = j["accessors"][i];
    const nlohmann::json& view = j["bufferViews"][a["bufferView"].get<std::size_t>()];
    const int type = a["componentType"];
    const std::size_t size = type == 5121 ? 1 : (type == 5123 ? 2 : 4);
    const std::size_t n = a["type"] == "SCALAR" ? 1 : std::size_t(a["type"].get<std::string>()[3] - '0');
    const std::size_t stride = view.value("byteStride", size * n);
    const std::size_t base = view.value("byteOffset", std::size_t(0)) + a.value("byteOffset", std::size_t(0));
    std::vector<std::vector<double> > out(a["count"].get<std::size_t>(), std::vector<double>(n));
    for(std::size_t e = 0; e < out.size(); ++e)
      for(std::size_t c = 0; c < n; ++c)
      {
        std::uint32_t u = 0;
        std::memcpy(&u, bin.data() + base + e * stride + c * size, size);
        float f;
        std::memcpy(&f, &u, 4);
        out[e][c] = type == 5126 ? double(f) : double(u);
      }
    return out;
  }
};

std::string read_file_bytes(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

std::string glb_of(const std::function<void(std::ostream&)>& write)
{
  std::ostringstream out;
  write(out);
  return out.str();
}

// A quad as a strip of two triangles (sharing two vertices), with normals +z and UVs, instanced
// by a node and by a mirrored node (scale -1 in x).
std::string strip_scene()
{
  Gltf_builder b;
  const std::vector<Float3> p = {{{0.f, 0.f, 0.f}}, {{1.f, 0.f, 0.f}}, {{0.f, 1.f, 0.f}}, {{1.f, 1.f, 0.f}}};
  const std::vector<Float3> n(4, Float3{{0.f, 0.f, 1.f}});
  const std::vector<std::array<float, 2> > uv = {{{0.f, 0.f}}, {{1.f, 0.f}}, {{0.f, 1.f}}, {{1.f, 1.f}}};
  const std::size_t pos = b.positions(p), nor = b.accessor(n, 5126, "VEC3", 4), tex = b.accessor(uv, 5126, "VEC2", 4);
  b.j["meshes"].push_back({{"primitives", {{{"attributes", {{"POSITION", pos}, {"NORMAL", nor}, {"TEXCOORD_0", tex}}},
                                            {"mode", 5}, {"material", 0}}}}});
  b.j["materials"] = {{{"name", "paint"}}};
  b.j["nodes"].push_back({{"mesh", 0}});
  b.j["nodes"].push_back({{"mesh", 0}, {"translation", {5., 0., 0.}}, {"scale", {-1., 1., 1.}}});
  b.j["scenes"] = {{{"nodes", {0, 1}}}};
  return write_temp("strip.glb", b.glb());
}

// The corners of each triangle of a primitive (mode TRIANGLES or TRIANGLE_STRIP).
std::vector<std::array<std::size_t, 3> > primitive_triangles(const Glb& g, const nlohmann::json& p)
{
  std::vector<std::size_t> index;
  if(p.contains("indices"))
    for(const auto& e : g.accessor(p["indices"])) index.push_back(std::size_t(e[0]));
  else
    for(std::size_t i = 0; i < g.j["accessors"][p["attributes"]["POSITION"].get<std::size_t>()]["count"]; ++i) index.push_back(i);
  std::vector<std::array<std::size_t, 3> > out;
  if(p.value("mode", 4) == 4)
    for(std::size_t k = 0; k + 2 < index.size(); k += 3) out.push_back({{index[k], index[k + 1], index[k + 2]}});
  else
    for(std::size_t t = 0; t + 2 < index.size(); ++t) out.push_back({{index[t], index[t + 1 + t % 2], index[t + 2 - t % 2]}});
  return out;
}

} // namespace

TEST_CASE("glTF labels as feature IDs: vertices split on part boundaries, instanced meshes split by labelling",
          "[io][gltf][writer]")
{
  const std::string path = strip_scene();
  // node 0: its two triangles in parts 0 and 1 (a shared vertex gets both); node 1: both in part 1
  const std::vector<std::size_t> labels = {0, 1, 1, 1};
  const Glb g(glb_of([&](std::ostream& out) { PD::IO::write_labels_glb(out, path, labels, 2); }));
  CHECK(g.j["extensionsUsed"] == nlohmann::json::array({"EXT_mesh_features"}));
  REQUIRE(g.j["meshes"].size() == 2);
  CHECK(g.j["nodes"][0]["mesh"] == 0);
  CHECK(g.j["nodes"][1]["mesh"] == 1);
  CHECK(g.j["nodes"][1]["scale"] == nlohmann::json({-1., 1., 1.}));
  const std::vector<std::vector<double> > source_positions = Glb(read_file_bytes(path)).accessor(0);
  std::size_t t = 0;
  for(std::size_t m = 0; m < 2; ++m)
  {
    const nlohmann::json& p = g.j["meshes"][m]["primitives"][0];
    CHECK(p["material"] == 0);
    CHECK(p["extensions"]["EXT_mesh_features"]["featureIds"] == nlohmann::json::array({{{"featureCount", 2}, {"attribute", 0}}}));
    const auto ids = g.accessor(p["attributes"]["_FEATURE_ID_0"]);
    const auto positions = g.accessor(p["attributes"]["POSITION"]);
    CHECK(ids.size() == positions.size());
    CHECK(g.accessor(p["attributes"]["TEXCOORD_0"]).size() == positions.size());
    for(const auto& c : primitive_triangles(g, p))
    {
      INFO("mesh " << m << ", triangle " << t);
      CHECK(ids[c[0]][0] == double(labels[t]));
      CHECK(ids[c[1]][0] == double(labels[t]));
      CHECK(ids[c[2]][0] == double(labels[t]));
      ++t;
    }
    // a duplicated vertex is a copy of a vertex of the source
    for(const auto& q : positions)
      CHECK(std::find(source_positions.begin(), source_positions.end(), q) != source_positions.end());
  }
  CHECK(t == labels.size());
  // the strip with two labels became triangles on six vertices (two duplicated); the other is unchanged
  CHECK(g.j["meshes"][0]["primitives"][0]["mode"] == 4);
  CHECK(g.accessor(g.j["meshes"][0]["primitives"][0]["attributes"]["POSITION"]).size() == 6);
  CHECK(g.j["meshes"][1]["primitives"][0]["mode"] == 5);
  CHECK(!g.j["meshes"][1]["primitives"][0].contains("indices"));

  CHECK_THROWS_AS(glb_of([&](std::ostream& out) { PD::IO::write_labels_glb(out, path, {0, 1, 1}, 2); }), std::invalid_argument);
  CHECK_THROWS_AS(glb_of([&](std::ostream& out) { PD::IO::write_labels_glb(out, path, labels, 1); }), std::invalid_argument);
}

TEST_CASE("glTF parts keep the attributes and material of the file, in the scene's frame", "[io][gltf][writer]")
{
  const std::string path = strip_scene();
  const std::vector<std::size_t> labels = {0, 1, 1, 1};
  const std::vector<PD::Superquadric<test_shapes::K> > none;
  const Glb g(glb_of([&](std::ostream& out) { PD::IO::write_gltf_parts_glb(out, path, labels, 2, none); }));
  REQUIRE(g.j["meshes"].size() == 2);
  CHECK(g.j["materials"] == nlohmann::json::array({{{"name", "paint"}}}));
  // part 1: the second triangle of node 0, then both triangles of the mirrored node 1
  CHECK(g.j["meshes"][0]["primitives"].size() == 1);
  REQUIRE(g.j["meshes"][1]["primitives"].size() == 2);
  std::size_t triangles = 0;
  for(const auto& mesh : g.j["meshes"])
    for(const auto& p : mesh["primitives"])
    {
      CHECK(p["material"] == 0);
      REQUIRE(p["attributes"].contains("NORMAL"));
      REQUIRE(p["attributes"].contains("TEXCOORD_0"));
      const auto positions = g.accessor(p["attributes"]["POSITION"]);
      const auto normals = g.accessor(p["attributes"]["NORMAL"]);
      for(const auto& c : primitive_triangles(g, p))
      {
        // in the scene's frame, and facing the way of the normals (+z), also when mirrored
        const auto& a = positions[c[0]];
        const auto& b = positions[c[1]];
        const auto& d = positions[c[2]];
        const double z = (b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0]);
        CHECK(z > 0.);
        CHECK(normals[c[0]] == std::vector<double>({0., 0., 1.}));
        CHECK(a[0] + b[0] + d[0] <= (triangles < 2 ? 3. : 15.));
        CHECK(a[0] + b[0] + d[0] >= (triangles < 2 ? 0. : 12.));
        ++triangles;
      }
    }
  CHECK(triangles == 4);
}

// ---- files that other mesh libraries read

namespace {

// The corners of a tetrahedron with distinct coordinates, and its faces turned outward.
const double tet_points[4][3] = {{0, 0, 0}, {2, 0, 0}, {0, 3, 0}, {0, 0, 4}};
const int tet_faces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};

// Whether the mesh has a vertex at (x, y, z).
bool has_point(const Mesh& m, double x, double y, double z)
{
  for(auto v : vertices(m))
    if(m.point(v) == Point(x, y, z)) return true;
  return false;
}

// Reads the tetrahedron from `path` and checks that it is the one of tet_points.
void check_tetrahedron(const std::string& path)
{
  INFO(path);
  Mesh m;
  const PD::IO::Mesh_file_info info = PD::IO::read_triangle_mesh(path, m);
  CHECK(info.number_of_input_faces == 4u);
  CHECK(info.number_of_input_vertices == 4u);
  CHECK(num_faces(m) == 4u);
  CHECK(num_vertices(m) == 4u);
  for(const auto& p : tet_points) CHECK(has_point(m, p[0], p[1], p[2]));
  CHECK(CGAL::Polygon_mesh_processing::volume(m) == Approx(2. * 3. * 4. / 6.));
}

// The bytes of `value` in little- or big-endian order.
template <typename T>
std::string bytes_of(T value, bool big_endian)
{
  std::string b(sizeof(T), '\0');
  std::memcpy(&b[0], &value, sizeof(T));
  const std::uint16_t probe = 1;
  const bool host_little = *reinterpret_cast<const unsigned char*>(&probe) == 1;
  if(host_little == big_endian) std::reverse(b.begin(), b.end());
  return b;
}

// The message of the Invalid_input (UNREADABLE_FILE) that reading `path` throws.
std::string read_message(const std::string& path)
{
  Mesh m;
  try { PD::IO::read_triangle_mesh(path, m); }
  catch(const PD::Invalid_input& e)
  {
    CHECK(e.error() == PD::Input_error::UNREADABLE_FILE);
    return e.what();
  }
  FAIL("no exception for " << path);
  return std::string();
}

} // namespace

TEST_CASE("PLY as MeshLab writes it: per-corner texture coordinates and colours after the indices", "[io][ply]")
{
  const std::string header_end = "element vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                                 "element face 4\nproperty list uchar int vertex_indices\n"
                                 "property list uchar float texcoord\nproperty uchar red\nproperty uchar green\n"
                                 "property uchar blue\nproperty uchar alpha\nend_header\n";
  std::ostringstream ascii;
  ascii << "ply\nformat ascii 1.0\ncomment VCGLIB generated\ncomment TextureFile tex.png\n" << header_end;
  for(const auto& p : tet_points) ascii << p[0] << ' ' << p[1] << ' ' << p[2] << " \n";
  for(const auto& f : tet_faces)
    ascii << "3 " << f[0] << ' ' << f[1] << ' ' << f[2] << " 6 0 0 1 0 0.5 1 255 128 0 255 \n";
  check_tetrahedron(write_temp("meshlab.ply", ascii.str()));

  // Some MeshLab files hold more values on a face line than the header declares (here the colour
  // as a list of 9 values after one declared uchar): an element is one line, the rest ignored.
  std::ostringstream longer;
  longer << "ply\nformat ascii 1.0\ncomment VCGLIB generated\n"
         << "element vertex 4\nproperty float x\nproperty float y\nproperty float z\nproperty uchar red\n"
         << "element face 4\nproperty list uchar int vertex_indices\nproperty list uchar float texcoord\n"
         << "property uchar red\nend_header\n";
  for(const auto& p : tet_points) longer << p[0] << ' ' << p[1] << ' ' << p[2] << " 192 \n";
  for(const auto& f : tet_faces)
    longer << "3 " << f[0] << ' ' << f[1] << ' ' << f[2] << " 6 0 0 1 0 0.5 1 9 1 1 1 1 1 1 1 1 1 \n";
  const std::string longer_path = write_temp("meshlab_longer.ply", longer.str());
  check_tetrahedron(longer_path);
  Mesh m;
  CHECK(PD::IO::read_triangle_mesh(longer_path, m).number_of_ignored_values == 4u * 9u);
  CHECK(PD::IO::read_triangle_mesh(write_temp("meshlab_exact.ply", ascii.str()), m).number_of_ignored_values == 0u);
  // a line with fewer values than the header declares is still an error naming it
  const std::string shorter = std::string("ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\n") +
                              "property float y\nproperty float z\nelement face 1\n" +
                              "property list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1\n0 0 1\n3 0 1 2\n";
  const std::string message = read_message(write_temp("meshlab_short.ply", shorter));
  CHECK(message.find("line 12: expected a float 'z' of vertex 3 of 4, got the end of the line") != std::string::npos);

  for(bool big : {false, true})
  {
    std::string binary = std::string("ply\nformat ") + (big ? "binary_big_endian" : "binary_little_endian") +
                         " 1.0\ncomment VCGLIB generated\n" + header_end;
    for(const auto& p : tet_points)
      for(double c : p) binary += bytes_of(float(c), big);
    for(const auto& f : tet_faces)
    {
      binary += '\3';
      for(int i : f) binary += bytes_of(std::int32_t(i), big);
      binary += '\6';
      for(float t : {0.f, 0.f, 1.f, 0.f, 0.5f, 1.f}) binary += bytes_of(t, big);
      binary += std::string("\xff\x80\x00\xff", 4);
    }
    check_tetrahedron(write_temp(big ? "meshlab_be.ply" : "meshlab_le.ply", binary));
  }
}

TEST_CASE("OFF: blanks before the keyword and the first count glued to it", "[io][off]")
{
  // a box (0, 0, 0) - (1, 2, 3) of six quads
  const std::string body = "0 0 0\n1 0 0\n1 2 0\n0 2 0\n0 0 3\n1 0 3\n1 2 3\n0 2 3\n"
                           "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n";
  Mesh m;
  const PD::IO::Mesh_file_info info = PD::IO::read_triangle_mesh(write_temp("glued.off", "   OFF8 6 12 # comment\n" + body), m);
  CHECK(info.number_of_input_vertices == 8u);
  CHECK(info.number_of_input_faces == 6u);
  CHECK(info.number_of_triangulated_faces == 6u);
  CHECK(num_faces(m) == 12u);
  CHECK(has_point(m, 1, 2, 3));
  CHECK(CGAL::Polygon_mesh_processing::volume(m) == Approx(6.));
  // the same with the other variants' letters, and with the counts on the next line
  Mesh n;
  PD::IO::read_triangle_mesh(write_temp("glued_n.off", "NOFF8\n6 12\n" + body), n);
  CHECK(num_faces(n) == 12u);
  // what is not OFF stays refused
  for(const std::string& first : {"OFFx 8 6 12\n", "XOFF 8 6 12\n", "OFF8x 6 12\n", "OF 8 6 12\n", "OFFOFF 8 6 12\n"})
  {
    INFO(first);
    CHECK(read_message(write_temp("not.off", first + body)).find("line 1: expected OFF") != std::string::npos);
  }
}

TEST_CASE("OBJ: every statement but v and f skipped, also a group name holding f", "[io][obj]")
{
  std::ostringstream obj;
  obj << "# exported\nmtllib tet.mtl\no Tetrahedron\n";
  obj << "v " << tet_points[0][0] << ' ' << tet_points[0][1] << ' ' << tet_points[0][2] << '\n';
  obj << "v " << tet_points[1][0] << ' ' << tet_points[1][1] << ' ' << tet_points[1][2] << " 1.0\n"; // weight
  obj << "v " << tet_points[2][0] << ' ' << tet_points[2][1] << ' ' << tet_points[2][2] << " 0.5 0.2 0.9\n"; // colour
  obj << "  v\t" << tet_points[3][0] << ' ' << tet_points[3][1] << ' ' << tet_points[3][2] << "\r\n";
  obj << "vt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\nvp 0.5\ng An f Three Other Things\nusemtl red\ns 1\n";
  const int (&f)[4][3] = tet_faces;
  obj << "f " << f[0][0] + 1 << ' ' << f[0][1] + 1 << ' ' << f[0][2] + 1 << '\n';                         // i
  obj << "f " << f[1][0] + 1 << "/1 " << f[1][1] + 1 << "/2 " << f[1][2] + 1 << "/3 # a comment\n";       // i/t
  obj << "l 1 2\np 3\ncurv 0 1 1 2\nparm u 0 1\nend\n";
  obj << "f " << f[2][0] - 4 << "//1 " << f[2][1] - 4 << "//1 " << f[2][2] - 4 << "//1\n";                 // -i//n
  obj << "fo " << f[3][0] + 1 << "/1/1 " << f[3][1] + 1 << "/2/1 " << f[3][2] + 1 << "/3/1\n";           // i/t/n
  check_tetrahedron(write_temp("groups.obj", obj.str()));

  // polygons are triangulated by the common path: a box of six quads
  const std::string box = "v 0 0 0\nv 1 0 0\nv 1 2 0\nv 0 2 0\nv 0 0 3\nv 1 0 3\nv 1 2 3\nv 0 2 3\n"
                          "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";
  Mesh m;
  const PD::IO::Mesh_file_info info = PD::IO::read_triangle_mesh(write_temp("box.obj", box), m);
  CHECK(info.number_of_input_faces == 6u);
  CHECK(info.number_of_triangulated_faces == 6u);
  CHECK(num_faces(m) == 12u);
  CHECK(CGAL::Polygon_mesh_processing::volume(m) == Approx(6.));
}

TEST_CASE("a UTF-8 byte-order mark before an OFF, OBJ or PLY file is skipped", "[io][off][obj][ply]")
{
  const std::string bom = "\xEF\xBB\xBF";
  std::ostringstream off, obj, ply;
  off << "OFF\n4 4 0\n";
  ply << "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
         "element face 4\nproperty list uchar int vertex_indices\nend_header\n";
  for(const auto& p : tet_points)
  {
    off << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
    obj << "v " << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
    ply << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  }
  for(const auto& f : tet_faces)
  {
    off << "3 " << f[0] << ' ' << f[1] << ' ' << f[2] << '\n';
    obj << "f " << f[0] + 1 << ' ' << f[1] + 1 << ' ' << f[2] + 1 << '\n';
    ply << "3 " << f[0] << ' ' << f[1] << ' ' << f[2] << '\n';
  }
  check_tetrahedron(write_temp("bom.off", bom + off.str()));
  check_tetrahedron(write_temp("bom.obj", bom + obj.str()));
  check_tetrahedron(write_temp("bom.ply", bom + ply.str()));
  // only at the start: a mark in the middle is still an error, with its line
  CHECK(read_message(write_temp("bom_middle.obj", obj.str() + bom + "v 0 0 0\n")).find("line 9") != std::string::npos);
}

TEST_CASE("OBJ: a statement continued on the next line after a backslash", "[io][obj]")
{
  // a box of six quads, as Rhino writes long faces: "f 1 2 \" then "3 4"
  const std::string obj = "v 0 0 0\nv 1 0 0\nv 1 2 0\nv 0 2 0\nv 0 0 3\nv 1 0 3\nv \\\n 1 2 3\nv 0 2 3\n"
                          "f 1 4 \\\n3 2\n"
                          "f 5 6 \\\r\n 7 \\\n 8\n"
                          "f 1 2\\\n 6 5\n"          // glued to the index
                          "f 2 3 7 6 \\  \n"          // blanks after the backslash, then an empty line
                          "\n"
                          "f 3 4 8 7 # a comment ends the statement \\\n"
                          "f 4 1 5 8\n"
                          "g a long \\\n group name\n";
  Mesh m;
  const PD::IO::Mesh_file_info info = PD::IO::read_triangle_mesh(write_temp("continued.obj", obj), m);
  CHECK(info.number_of_input_vertices == 8u);
  CHECK(info.number_of_input_faces == 6u);
  CHECK(num_faces(m) == 12u);
  CHECK(has_point(m, 1, 2, 3));
  CHECK(CGAL::is_closed(m));
  CHECK(CGAL::Polygon_mesh_processing::volume(m) == Approx(6.));
  // a continuation line alone is not a statement
  CHECK(read_message(write_temp("broken.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n3\n")).find("line 5") != std::string::npos);
}

TEST_CASE("OBJ: indices out of range are the out-of-range error, not a parse error", "[io][obj]")
{
  const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  CHECK(read_error(write_temp("zero.obj", tri + "f 0 1 2\n")) == PD::Input_error::INVALID_FACE);
  CHECK(read_error(write_temp("past.obj", tri + "f 1 2 4\n")) == PD::Input_error::INVALID_FACE);
  CHECK(read_error(write_temp("before.obj", tri + "f -1 -2 -4\n")) == PD::Input_error::INVALID_FACE);
  CHECK(read_error(write_temp("huge.obj", tri + "f 1 2 99999999999999999999999\n")) == PD::Input_error::INVALID_FACE);
  CHECK(read_error(write_temp("novertex.obj", "# nothing\n")) == PD::Input_error::NO_FACES);
  // a vertex index may refer to a vertex given later in the file
  Mesh m;
  PD::IO::read_triangle_mesh(write_temp("forward.obj", "v 0 0 0\nf 1 2 3\nv 1 0 0\nv 0 1 0\n"), m);
  CHECK(num_faces(m) == 1u);
}

TEST_CASE("a file that cannot be parsed is refused with its line (or byte) and what was expected", "[io]")
{
  const std::string tri = "0 0 0\n1 0 0\n0 1 0\n";
  struct Case
  {
    std::string name, content, expected;
  };
  const std::string ply = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                          "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  std::string binary_ply = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
                           "property float y\nproperty float z\nend_header\n";
  const std::size_t header = binary_ply.size();
  binary_ply += std::string(20, '\0'); // 5 of the 9 floats
  std::string binary_stl(80, ' ');
  binary_stl += bytes_of(std::uint32_t(3), false) + std::string(70, '\0');
  const std::vector<Case> cases = {
    {"bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n\n# faces\nf 1 2 abc\n",
     "as OBJ: line 6: expected a vertex index after 'f', got 'abc'"},
    {"bad_vertex.obj", "v 0 0 0\nv 1 0 \\\n  x\n", "as OBJ: line 3: expected 3 coordinates after 'v', got 'x'"},
    {"binary.obj", "v 0 0 0\n\x89PNG\r\n", "as OBJ: line 2: expected an OBJ statement"},
    {"bad.off", "OFF\n3 1 0\n0 0 0\n1 abc 0\n0 1 0\n3 0 1 2\n",
     "as OFF: line 4: expected 3 vertex coordinates, got 'abc'"},
    {"short.off", "OFF\n3 2 0\n" + tri + "3 0 1 2\n", "as OFF: line 7: expected face 2 of 2, got the end of the file"},
    {"degree.off", "OFF\n3 1 0\n" + tri + "4 0 1 2\n",
     "as OFF: line 6: expected 4 vertex indices after the face degree, got 3"},
    {"bad.ply", ply + tri + "3 0 1 x\n",
     "as PLY: line 13: expected an integer in list 'vertex_indices' of face 1 of 1, got 'x'"},
    {"type.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty flot x\n", "as PLY: line 4: expected a property type"},
    {"binary.ply", binary_ply, "as PLY: byte " + std::to_string(header + 20) + ": expected a float 'z' of vertex 2 of 3"},
    {"bad.stl",
     "solid t\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 0 0\n  endloop\n endfacet\nendsolid t\n",
     "as STL: line 7: expected 3 vertices in the facet, got 2"},
    {"binary.stl", binary_stl, "as STL: byte 84: expected 3 triangles of 50 bytes, got 70 bytes"},
    {"bad.gltf", "{\"asset\": {\"version\": \"2.0\"},\n \"nodes\": [", "as glTF: invalid JSON"},
    {"mesh.xyz", tri, "cannot parse"}};
  for(const Case& c : cases)
  {
    INFO(c.name);
    const std::string path = write_temp(c.name, c.content);
    const std::string message = read_message(path);
    CHECK(message.rfind("cannot parse '" + path + "'", 0) == 0);
    CHECK(message.find(c.expected) != std::string::npos);
    CHECK(message.find('\n') == std::string::npos);
    std::remove(path.c_str());
  }
  // nlohmann's message names the place of the JSON error
  CHECK(read_message(write_temp("bad.gltf", "{\"asset\": {\"version\": \"2.0\"},\n \"nodes\": [")).find("line 2") !=
        std::string::npos);
}

// ---- SHA-256 of the batch summary (examples/Part_decomposition/include/sha256.h)

TEST_CASE("SHA-256 gives the FIPS 180-4 known answers and the digest of sha256sum", "[sha256]")
{
  using Part_decomposition_tools::sha256_hex;
  CHECK(sha256_hex("abc") == "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  CHECK(sha256_hex("") == "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  CHECK(sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq") ==
        "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  CHECK(sha256_hex(std::string(1000000, 'a')) == "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");

  // a message fed in pieces of every size around the block length gives the same digest
  std::string message;
  for(std::size_t i = 0; i < 300000; ++i) message += char((i * 2654435761u) >> 13);
  const std::string whole = sha256_hex(message);
  for(std::size_t piece : {1u, 55u, 56u, 63u, 64u, 65u, 1000u})
  {
    Part_decomposition_tools::Sha256 h;
    for(std::size_t at = 0; at < message.size(); at += piece)
      h.update(message.data() + at, (std::min)(piece, message.size() - at));
    CHECK(h.hex_digest() == whole);
  }

  // a file read in chunks, against the system's tool
  const std::string path = write_temp("sha256.bin", message);
  std::string digest;
  REQUIRE(Part_decomposition_tools::sha256_of_file(path, digest));
  CHECK(digest == whole);
  std::FILE* tool = popen(("sha256sum " + path).c_str(), "r");
  REQUIRE(tool != nullptr);
  char line[128] = {0};
  const bool got = std::fgets(line, sizeof(line), tool) != nullptr;
  pclose(tool);
  REQUIRE(got);
  CHECK(std::string(line).substr(0, 64) == digest);
  CHECK(!Part_decomposition_tools::sha256_of_file("pd_test_no_such_file", digest));
  std::remove(path.c_str());
}
