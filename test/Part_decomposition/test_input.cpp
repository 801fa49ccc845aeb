// Input handling: voxel binning, normalization, and the reader on files that real data produce.
#include <catch2/catch.hpp>

#include <CGAL/Part_decomposition/IO/read_mesh.h>
#include <CGAL/Part_decomposition/Voxel_grid.h>
#include <CGAL/Part_decomposition/internal/oriented_manifold_soup.h>
#include <CGAL/Part_decomposition/normalization.h>
#include <CGAL/Polygon_mesh_processing/measure.h>

#include "test_shapes.h"

#include <array>
#include <cstdio>
#include <fstream>
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

TEST_CASE("the oriented-manifold check lets only clean soups skip the orienter", "[io]")
{
  using PD::internal::is_oriented_manifold_soup;
  typedef std::vector<std::array<std::size_t, 3> > Triangles;
  const Mesh box = test_shapes::make_box(Point(0, 0, 0), Point(1, 1, 1), 3);
  Triangles tris;
  for(auto f : faces(box))
  {
    std::array<std::size_t, 3> t;
    int k = 0;
    for(auto v : vertices_around_face(halfedge(f, box), box)) t[k++] = std::size_t(v);
    tris.push_back(t);
  }
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
