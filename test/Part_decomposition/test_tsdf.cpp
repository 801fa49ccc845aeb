// Tests of the TSDF, the grid morphology and the fitter's zones, against analytic shapes,
// hand-made grids and brute-force references.
#include <catch2/catch.hpp>

#include "test_shapes.h"

#include <CGAL/Part_decomposition/fitting_zones.h>
#include <CGAL/Part_decomposition/flow_freeze_prior.h>
#include <CGAL/Part_decomposition/internal/grid_morphology.h>
#include <CGAL/Part_decomposition/internal/mesh_voxelization.h>
#include <CGAL/Part_decomposition/internal/triangle_distance.h>
#include <CGAL/Part_decomposition/internal/triangle_soup_aabb_tree.h>
#include <CGAL/Part_decomposition/internal/winding_number.h>
#include <CGAL/Part_decomposition/tsdf.h>

#include <CGAL/Bbox_3.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Random.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace PD = CGAL::Part_decomposition;
namespace PDI = CGAL::Part_decomposition::internal;
using test_shapes::K;
using test_shapes::Mesh;
using test_shapes::Point;
typedef PD::Voxel_grid<std::uint8_t> Mask;

namespace {

Mask random_mask(int r, double density, CGAL::Random& rng)
{
  Mask m(r, 0);
  for(std::size_t i = 0; i < m.size(); ++i) m[i] = rng.get_double() < density ? 1 : 0;
  return m;
}

// Brute-force squared EDT, optionally with the layer outside the grid as feature.
PD::Voxel_grid<double> brute_force_edt(const Mask& feature, bool border)
{
  const int r = feature.resolution();
  PD::Voxel_grid<double> out(r, std::numeric_limits<double>::infinity());
  for(std::size_t v = 0; v < out.size(); ++v)
  {
    const std::array<int, 3> p = out.coordinates(v);
    double best = std::numeric_limits<double>::infinity();
    for(std::size_t f = 0; f < feature.size(); ++f)
      if(feature[f])
      {
        const std::array<int, 3> q = feature.coordinates(f);
        double d = 0.;
        for(int a = 0; a < 3; ++a) d += double(p[a] - q[a]) * double(p[a] - q[a]);
        best = std::min(best, d);
      }
    if(border)
      for(int a = 0; a < 3; ++a)
      {
        const double s = std::min(p[a] + 1, r - p[a]);
        best = std::min(best, s * s);
      }
    out[v] = best;
  }
  return out;
}

// Mesh made of the given triangles, no vertex shared between triangles: every edge is a border
// edge, the geometry is unchanged.
Mesh unshared_copy(const Mesh& m)
{
  std::vector<Point> points;
  std::vector<std::vector<std::size_t> > polygons;
  for(auto f : faces(m))
  {
    std::vector<std::size_t> poly;
    for(auto v : vertices_around_face(halfedge(f, m), m))
    {
      poly.push_back(points.size());
      points.push_back(m.point(v));
    }
    polygons.push_back(poly);
  }
  Mesh out;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, out);
  return out;
}

Mesh reversed(const Mesh& m)
{
  Mesh out = m;
  CGAL::Polygon_mesh_processing::reverse_face_orientations(out);
  return out;
}

Mesh without_first_face(const Mesh& m)
{
  Mesh out = m;
  CGAL::Euler::remove_face(halfedge(*faces(out).begin(), out), out);
  out.collect_garbage();
  return out;
}

double sd_sphere(const std::array<double, 3>& p, const std::array<double, 3>& c, double R)
{
  return std::sqrt((p[0] - c[0]) * (p[0] - c[0]) + (p[1] - c[1]) * (p[1] - c[1]) + (p[2] - c[2]) * (p[2] - c[2])) - R;
}

double sd_box(const std::array<double, 3>& p, const std::array<double, 3>& lo, const std::array<double, 3>& hi)
{
  double outside = 0., inside = -std::numeric_limits<double>::infinity();
  for(int a = 0; a < 3; ++a)
  {
    const double d = std::max(lo[a] - p[a], p[a] - hi[a]);
    outside += std::max(d, 0.) * std::max(d, 0.);
    inside = std::max(inside, d);
  }
  return outside > 0. ? std::sqrt(outside) : inside;
}

std::array<double, 3> unit(const PD::Normalization& n, double x, double y, double z) { return n.to_unit(x, y, z); }

// Checks the sign of every voxel whose analytic signed distance (normalized units) exceeds `margin`
// in magnitude and which `where` accepts; returns the number of voxels checked.
std::size_t check_signs(const PD::Truncated_signed_distance_field& tsdf,
                        const std::function<double(const std::array<double, 3>&)>& sd, double margin,
                        const std::function<bool(const std::array<double, 3>&)>& where = nullptr)
{
  std::size_t checked = 0, wrong = 0;
  for(std::size_t i = 0; i < tsdf.values.size(); ++i)
  {
    const std::array<double, 3> c = tsdf.values.center(i);
    const double s = sd(c);
    if(std::abs(s) <= margin || (where && !where(c))) continue;
    ++checked;
    if((s < 0.) != (tsdf.values[i] < 0.))
    {
      if(wrong < 5)
      {
        const std::array<int, 3> v = tsdf.values.coordinates(i);
        WARN("wrong sign at voxel " << v[0] << " " << v[1] << " " << v[2] << ": exact " << s * tsdf.values.resolution()
             << " voxels, got " << tsdf.values[i] * tsdf.values.resolution() << " (method " << int(tsdf.sign_method) << ")");
      }
      ++wrong;
    }
  }
  CHECK(wrong == 0);
  return checked;
}

// Checks |tsdf - clamp(sd)| <= tolerance everywhere; returns the largest error.
double check_values(const PD::Truncated_signed_distance_field& tsdf,
                    const std::function<double(const std::array<double, 3>&)>& sd, double tolerance)
{
  double worst = 0.;
  for(std::size_t i = 0; i < tsdf.values.size(); ++i)
  {
    const double s = std::max(-tsdf.truncation, std::min(tsdf.truncation, sd(tsdf.values.center(i))));
    worst = std::max(worst, std::abs(tsdf.values[i] - s));
  }
  CHECK(worst <= tolerance);
  return worst;
}

} // namespace

// ------------------------------------------------------------------------------------ morphology

TEST_CASE("EDT equals a brute-force EDT on random masks, empty and full ones", "[tsdf][morphology]")
{
  CGAL::Random rng(7);
  for(int r : {1, 2, 3, 5, 8, 11})
    for(double density : {0., 0.02, 0.2, 0.7, 1.})
      for(bool border : {false, true})
      {
        const Mask m = random_mask(r, density, rng);
        PD::Voxel_grid<std::size_t> nearest;
        const PD::Voxel_grid<double> d = PDI::squared_distance_transform(m, border, &nearest);
        const PD::Voxel_grid<double> ref = brute_force_edt(m, border);
        REQUIRE(d == ref);
        CHECK(PDI::squared_distance_transform<CGAL::Parallel_if_available_tag>(m, border) == ref);
        for(std::size_t v = 0; v < d.size(); ++v)
        {
          if(nearest[v] == PDI::outside_grid_feature() || nearest[v] == PDI::outside_grid_feature() - 1)
          {
            // Border feature, or no feature at all.
            CHECK((border || d[v] == PDI::no_feature_distance()));
            continue;
          }
          REQUIRE(m[nearest[v]] != 0);
          const std::array<int, 3> p = d.coordinates(v), q = d.coordinates(nearest[v]);
          double e = 0.;
          for(int a = 0; a < 3; ++a) e += double(p[a] - q[a]) * double(p[a] - q[a]);
          CHECK(e == d[v]);
        }
      }
}

TEST_CASE("EDT without features is infinite, with one feature exact", "[tsdf][morphology]")
{
  Mask m(6, 0);
  const PD::Voxel_grid<double> none = PDI::squared_distance_transform(m);
  CHECK(std::all_of(none.values().begin(), none.values().end(), [](double v) { return std::isinf(v); }));
  m(1, 2, 3) = 1;
  const PD::Voxel_grid<double> one = PDI::squared_distance_transform(m);
  CHECK(one(5, 5, 5) == 16. + 9. + 4.);
  CHECK(one(1, 2, 3) == 0.);
}

TEST_CASE("Adding features updates the EDT exactly", "[tsdf][morphology]")
{
  CGAL::Random rng(11);
  for(int trial = 0; trial < 20; ++trial)
  {
    const int r = 4 + trial % 9;
    Mask m = random_mask(r, 0.03 + 0.01 * (trial % 4), rng);
    m[rng.get_int(0, int(m.size()))] = 1;
    PD::Voxel_grid<double> d = PDI::squared_distance_transform(m);
    std::vector<std::size_t> added;
    const int count = 1 + trial % 5;
    for(int k = 0; k < count; ++k)
    {
      const std::size_t v = std::size_t(rng.get_int(0, int(m.size())));
      added.push_back(v);
      m[v] = 1;
    }
    PDI::add_features_to_squared_distance_transform(d, added);
    CHECK(d == PDI::squared_distance_transform(m));
  }
}

TEST_CASE("Hole filling matches hand-made grids", "[tsdf][morphology]")
{
  // A closed shell [2,6]^3 in a 9^3 grid: its inside [3,5]^3 gets filled.
  Mask shell(9, 0);
  for(int k = 2; k <= 6; ++k)
    for(int j = 2; j <= 6; ++j)
      for(int i = 2; i <= 6; ++i)
        if(i == 2 || i == 6 || j == 2 || j == 6 || k == 2 || k == 6) shell(i, j, k) = 1;
  const Mask filled = PDI::fill_holes(shell);
  for(int k = 0; k < 9; ++k)
    for(int j = 0; j < 9; ++j)
      for(int i = 0; i < 9; ++i)
      {
        const bool in_box = i >= 2 && i <= 6 && j >= 2 && j <= 6 && k >= 2 && k <= 6;
        CHECK(filled(i, j, k) == (in_box ? 1 : 0));
      }
  // One voxel removed from a face: the inside is joined to the outside and stays empty.
  Mask open_shell = shell;
  open_shell(4, 4, 2) = 0;
  CHECK(PDI::fill_holes(open_shell) == open_shell);
  // A diagonal gap does not connect in 6-connectivity: a shell missing an edge voxel but with the
  // gap closed face-wise stays closed.
  Mask edge = shell;
  edge(2, 2, 4) = 0; // edge voxel: its 6-neighbours inside the box are shell voxels
  Mask expected = filled;
  expected(2, 2, 4) = 0;
  CHECK(PDI::fill_holes(edge) == expected);
  // A mask touching the border: border voxels outside the mask are exterior.
  Mask border(4, 0);
  border(0, 0, 0) = 1;
  CHECK(PDI::fill_holes(border) == border);
}

TEST_CASE("Dilation matches hand-made grids and a brute force", "[tsdf][morphology]")
{
  Mask one(7, 0);
  one(3, 3, 3) = 1;
  auto count = [](const Mask& m) { return std::size_t(std::count(m.values().begin(), m.values().end(), 1)); };
  CHECK(PDI::dilate(one, 0.) == one);
  CHECK(count(PDI::dilate(one, 0.99)) == 1);
  CHECK(count(PDI::dilate(one, 1.)) == 7);
  CHECK(count(PDI::dilate(one, std::sqrt(2.))) == 19);
  CHECK(count(PDI::dilate(one, std::sqrt(3.))) == 27);
  CHECK(count(PDI::dilate(one, 2.)) == 33);
  const Mask r1 = PDI::dilate(one, 1.);
  CHECK(r1(3, 3, 4) == 1);
  CHECK(r1(4, 4, 3) == 0);

  CGAL::Random rng(3);
  for(double radius : {0.5, 1.5, 2.2, 3.})
  {
    const Mask m = random_mask(9, 0.02, rng);
    const PD::Voxel_grid<double> ref = brute_force_edt(m, false);
    const Mask d = PDI::dilate(m, radius);
    for(std::size_t v = 0; v < d.size(); ++v) CHECK(d[v] == (ref[v] <= radius * radius ? 1 : 0));
  }
}

TEST_CASE("Connected components on a hand-made grid", "[tsdf][morphology]")
{
  Mask m(4, 0);
  m(0, 0, 0) = m(1, 0, 0) = m(1, 1, 0) = 1; // component 0 (first voxel index 0)
  m(3, 0, 0) = 1;                           // component 1 (index 3)
  m(2, 1, 1) = 1;                           // component 2: only edge-adjacent to (1,1,0)
  m(3, 3, 3) = m(3, 3, 2) = 1;              // component 3
  const PDI::Grid_components cc = PDI::connected_components(m);
  REQUIRE(cc.size() == 4);
  CHECK(cc.sizes == std::vector<std::size_t>{3, 1, 1, 2});
  CHECK(cc.labels(0, 0, 0) == 0);
  CHECK(cc.labels(1, 1, 0) == 0);
  CHECK(cc.labels(3, 0, 0) == 1);
  CHECK(cc.labels(2, 1, 1) == 2);
  CHECK(cc.labels(3, 3, 2) == 3);
  CHECK(cc.labels(2, 2, 2) == -1);
  CHECK(cc.centroids[0][0] == Approx(2. / 3.));
  CHECK(cc.centroids[0][1] == Approx(1. / 3.));
  CHECK(cc.centroids[0][2] == 0.);
  CHECK(cc.centroids[3][2] == 2.5);
  CHECK(PDI::connected_components(Mask(3, 0)).size() == 0);
  CHECK(PDI::connected_components(Mask(3, 1)).sizes == std::vector<std::size_t>{27});
}

// ------------------------------------------------------------------------------- geometry pieces

TEST_CASE("Point-triangle distance and the AABB-tree closest-triangle search match brute force", "[tsdf][distance]")
{
  CGAL::Random rng(5);
  auto rnd = [&](double s) { return PDI::Vec3{{rng.get_double(-s, s), rng.get_double(-s, s), rng.get_double(-s, s)}}; };
  std::vector<PDI::Triangle_points> tris;
  for(int i = 0; i < 400; ++i)
  {
    const PDI::Vec3 c = rnd(0.4);
    PDI::Triangle_points t;
    for(auto& p : t)
    {
      const PDI::Vec3 d = rnd(0.03);
      p = {{c[0] + d[0], c[1] + d[1], c[2] + d[2]}};
    }
    if(i % 40 == 1) t[2] = t[1];                                                             // repeated vertex
    if(i % 40 == 2) t[2] = {{2 * t[1][0] - t[0][0], 2 * t[1][1] - t[0][1], 2 * t[1][2] - t[0][2]}}; // collinear
    if(i % 40 == 3) t[1] = t[2] = t[0];                                                      // a point
    tris.push_back(t);
  }
  // The triangle routine against CGAL's kernel.
  for(int i = 0; i < 2000; ++i)
  {
    const PDI::Triangle_points& t = tris[std::size_t(i) % tris.size()];
    const PDI::Vec3 p = rnd(0.5);
    if(i % 40 < 4) continue; // CGAL wants non-degenerate triangles
    const K::Triangle_3 T(Point(t[0][0], t[0][1], t[0][2]), Point(t[1][0], t[1][1], t[1][2]), Point(t[2][0], t[2][1], t[2][2]));
    const double ref = CGAL::to_double(CGAL::squared_distance(Point(p[0], p[1], p[2]), T));
    CHECK(PDI::squared_distance_to_triangle(p, t[0], t[1], t[2]) == Approx(ref).epsilon(1e-9).margin(1e-18));
  }
  const PDI::Triangle_soup_aabb_tree tree(tris);
  for(int i = 0; i < 3000; ++i)
  {
    const PDI::Vec3 p = rnd(0.6);
    double best = std::numeric_limits<double>::infinity();
    for(const auto& t : tris) best = std::min(best, PDI::squared_distance_to_triangle(p, t[0], t[1], t[2]));
    const std::pair<std::uint32_t, double> got = tree.closest(p);
    CHECK(std::abs(std::sqrt(got.second) - std::sqrt(best)) <= 1e-12);
    const auto& t = tris[got.first];
    CHECK(PDI::squared_distance_to_triangle(p, t[0], t[1], t[2]) == got.second);
    // A bound reached by a given triangle does not change the answer.
    const std::uint32_t hint = std::uint32_t(i) % std::uint32_t(tris.size());
    const auto& h = tris[hint];
    const std::pair<std::uint32_t, double> hinted = tree.closest(p, PDI::squared_distance_to_triangle(p, h[0], h[1], h[2]), hint);
    CHECK(std::abs(std::sqrt(hinted.second) - std::sqrt(best)) <= 1e-12);
    // A bound below every triangle comes back unchanged.
    const std::pair<std::uint32_t, double> below = tree.closest(p, 0.5 * best, 7u);
    CHECK(below.first == 7u);
    CHECK(below.second == 0.5 * best);
  }
  // One triangle (a tree without nodes) and three.
  for(std::size_t n : {std::size_t(1), std::size_t(3)})
  {
    const std::vector<PDI::Triangle_points> few(tris.begin() + 4, tris.begin() + 4 + std::ptrdiff_t(n));
    const PDI::Triangle_soup_aabb_tree small(few);
    const PDI::Vec3 p = {{0.1, 0.2, 0.3}};
    double best = std::numeric_limits<double>::infinity();
    for(const auto& t : few) best = std::min(best, PDI::squared_distance_to_triangle(p, t[0], t[1], t[2]));
    CHECK(small.closest(p).second == best);
  }
}

TEST_CASE("TSDF band distances equal the distances of CGAL's AABB tree", "[tsdf][distance]")
{
  // A jittered sphere (irregular triangles) overlapping a box: two components, many near ties.
  Mesh m = test_shapes::make_sphere(Point(0.2, 0.1, 0.), 0.7, 3);
  CGAL::Random rng(17);
  for(auto v : vertices(m))
  {
    const Point& q = m.point(v);
    m.point(v) = Point(q.x() + rng.get_double(-0.03, 0.03), q.y() + rng.get_double(-0.03, 0.03), q.z() + rng.get_double(-0.03, 0.03));
  }
  test_shapes::append(m, test_shapes::make_box(Point(-0.9, -0.4, -0.3), Point(0.1, 0.3, 0.35), 4));
  for(int r : {32, 64})
  {
    const PD::Truncated_signed_distance_field tsdf = PD::compute_tsdf<CGAL::Parallel_if_available_tag>(
      m, PD::parameters::voxel_resolutions(std::vector<int>{r}));
    const std::vector<PDI::Triangle_points> tris = PDI::normalized_triangles(m, get(CGAL::vertex_point, m), tsdf.normalization);
    // CGAL's plain distance query on the same normalized triangles.
    typedef PDI::Aabb_kernel SC;
    std::vector<SC::Triangle_3> triangles;
    for(const auto& t : tris)
      triangles.emplace_back(SC::Point_3(t[0][0], t[0][1], t[0][2]), SC::Point_3(t[1][0], t[1][1], t[1][2]),
                             SC::Point_3(t[2][0], t[2][1], t[2][2]));
    PDI::Aabb_triangle_tree tree(triangles.begin(), triangles.end());
    tree.accelerate_distance_queries();
    std::vector<std::size_t> band;
    for(std::size_t i = 0; i < tsdf.values.size(); ++i)
      if(std::abs(tsdf.values[i]) < tsdf.truncation) band.push_back(i);
    REQUIRE(band.size() > 1000);
    CGAL::Random pick(3);
    double worst = 0.;
    for(int s = 0; s < 400; ++s)
    {
      const std::size_t i = band[std::size_t(pick.get_int(0, int(band.size())))];
      const PDI::Vec3 c = tsdf.values.center(i);
      const double d = std::sqrt(CGAL::to_double(tree.squared_distance(SC::Point_3(c[0], c[1], c[2]))));
      worst = std::max(worst, std::abs(std::abs(tsdf.values[i]) - d));
    }
    CHECK(worst <= 1e-12);
    // Outside the band CGAL finds nothing closer than the truncation.
    for(int s = 0; s < 400; ++s)
    {
      const std::size_t i = std::size_t(pick.get_int(0, int(tsdf.values.size())));
      if(std::abs(tsdf.values[i]) < tsdf.truncation) continue;
      const PDI::Vec3 c = tsdf.values.center(i);
      CHECK(std::sqrt(CGAL::to_double(tree.squared_distance(SC::Point_3(c[0], c[1], c[2])))) >= tsdf.truncation - 1e-12);
    }
  }
}

TEST_CASE("The band distances by the tree and by sweeping the triangles are the same", "[tsdf][distance]")
{
  // Large triangles (a box of 12, a tilted plate), small ones (a jittered sphere), an open sheet.
  Mesh plates = test_shapes::make_box(Point(-0.4, -0.3, -0.2), Point(0.3, 0.1, 0.25), 1);
  Mesh tilted;
  const auto a = tilted.add_vertex(Point(-0.45, -0.4, -0.3)), b = tilted.add_vertex(Point(0.4, -0.1, 0.3)),
             c = tilted.add_vertex(Point(-0.2, 0.45, 0.1));
  tilted.add_face(a, b, c);
  test_shapes::append(plates, tilted);
  Mesh sphere = test_shapes::make_sphere(Point(0.1, 0., 0.05), 0.4, 3);
  CGAL::Random rng(5);
  for(auto v : vertices(sphere))
  {
    const Point& q = sphere.point(v);
    sphere.point(v) = Point(q.x() + rng.get_double(-0.02, 0.02), q.y(), q.z() + rng.get_double(-0.02, 0.02));
  }
  const Mesh sheet = test_shapes::make_wavy_sheet(12, 0.1);
  for(const Mesh* m : std::vector<const Mesh*>{&plates, &sphere, &sheet})
    for(int r : {16, 32})
      for(double tau_voxels : {1.5, 8.})
      {
        const std::vector<PDI::Triangle_points> tris =
          PDI::normalized_triangles(*m, get(CGAL::vertex_point, *m), PD::compute_normalization(*m));
        const PDI::Surface_voxels sv = PDI::surface_voxels<CGAL::Sequential_tag>(tris, r);
        const double tau = tau_voxels / r;
        const PD::Voxel_grid<double> tree = PDI::clipped_unsigned_distance<CGAL::Parallel_if_available_tag>(
          tris, sv, r, tau, nullptr, PDI::Band_distance_method::TREE);
        const PD::Voxel_grid<double> sweep = PDI::clipped_unsigned_distance<CGAL::Parallel_if_available_tag>(
          tris, sv, r, tau, nullptr, PDI::Band_distance_method::SWEEP);
        std::size_t differ = 0, band = 0;
        for(std::size_t i = 0; i < tree.size(); ++i)
        {
          differ += tree[i] != sweep[i] ? 1 : 0;
          band += tree[i] < tau ? 1 : 0;
        }
        CHECK(band > 100);
        CHECK(differ == 0);
      }
}

TEST_CASE("Surface voxels are the voxels the triangles touch", "[tsdf][voxelization]")
{
  CGAL::Random rng(9);
  const int r = 12;
  const double h = 1. / r;
  for(int trial = 0; trial < 30; ++trial)
  {
    PDI::Triangle_points t;
    for(auto& p : t)
      for(auto& x : p) x = rng.get_double(-0.45, 0.45);
    if(trial % 3 == 0) // on voxel faces and through voxel centres
      for(auto& p : t) p[2] = -0.5 + 4 * h;
    const std::vector<PDI::Triangle_points> tris(1, t);
    const PDI::Surface_voxels sv = PDI::surface_voxels<CGAL::Sequential_tag>(tris, r);
    const K::Triangle_3 T(Point(t[0][0], t[0][1], t[0][2]), Point(t[1][0], t[1][1], t[1][2]), Point(t[2][0], t[2][1], t[2][2]));
    for(std::size_t v = 0; v < sv.mask.size(); ++v)
    {
      const std::array<double, 3> c = sv.mask.center(v);
      auto box = [&](double half) {
        return CGAL::Bbox_3(c[0] - half, c[1] - half, c[2] - half, c[0] + half, c[1] + half, c[2] + half);
      };
      if(CGAL::do_intersect(T, box(0.5 * h))) CHECK(sv.mask[v] == 1);    // every touched voxel
      if(!CGAL::do_intersect(T, box(0.5 * h * (1 + 1e-6)))) CHECK(sv.mask[v] == 0); // and no other
      CHECK(sv.offsets[v + 1] - sv.offsets[v] == std::size_t(sv.mask[v]));
    }
  }
}

TEST_CASE("Winding numbers: exact solid angles and the hierarchical approximation", "[tsdf][winding]")
{
  const Mesh sphere = test_shapes::make_sphere(Point(0, 0, 0), 0.4, 3);
  const std::vector<PDI::Triangle_points> tris =
    PDI::normalized_triangles(sphere, get(CGAL::vertex_point, sphere), PD::Normalization());
  const PDI::Fast_winding_number wn(tris);
  CHECK(wn.exact({{0., 0., 0.}}) == Approx(1.).margin(1e-9));
  CHECK(wn.exact({{0.1, 0.2, -0.1}}) == Approx(1.).margin(1e-9));
  CHECK(wn.exact({{0.5, 0.1, 0.}}) == Approx(0.).margin(1e-9));
  CGAL::Random rng(2);
  double worst = 0.;
  for(int i = 0; i < 500; ++i)
  {
    const PDI::Vec3 p = {{rng.get_double(-0.5, 0.5), rng.get_double(-0.5, 0.5), rng.get_double(-0.5, 0.5)}};
    worst = std::max(worst, std::abs(wn(p) - wn.exact(p)));
  }
  CHECK(worst < 0.05);
  // Open surface: a hemisphere-like cap seen from its centre has |w| close to 1/2.
  const Mesh holed = without_first_face(sphere);
  const std::vector<PDI::Triangle_points> tris2 =
    PDI::normalized_triangles(holed, get(CGAL::vertex_point, holed), PD::Normalization());
  const PDI::Fast_winding_number wn2(tris2);
  CHECK(wn2({{0., 0., 0.}}) > 0.9);
  CHECK(std::abs(wn2({{0., 0., 0.}}) - wn2.exact({{0., 0., 0.}})) < 0.05);
}

TEST_CASE("Row crossings count a closed box exactly when rows run through its edges and faces", "[tsdf][rows]")
{
  const int r = 64;
  auto c = [&](int j) { return -0.5 + (j + 0.5) / r; };
  // Box vertices land on voxel centres: rows pass through vertices, along edges and inside faces.
  const Mesh box = test_shapes::make_box(Point(c(10), c(12), c(8)), Point(c(50), c(44), c(52)), 40);
  const std::vector<PDI::Triangle_points> tris =
    PDI::normalized_triangles(box, get(CGAL::vertex_point, box), PD::Normalization());
  const PDI::Row_crossings rows = PDI::row_crossings<CGAL::Sequential_tag>(tris, r);
  for(std::size_t row = 0; row < std::size_t(r) * r; ++row)
  {
    int sum = 0;
    for(std::size_t k = rows.offsets[row]; k < rows.offsets[row + 1]; ++k) sum += rows.sign[k];
    CHECK(sum == 0); // a closed surface is entered as often as it is left
  }
  for(bool parity : {false, true})
  {
    const std::vector<std::uint8_t> inside = PDI::inside_from_rows(rows, r, parity);
    std::size_t wrong = 0;
    for(int k = 0; k < r; ++k)
      for(int j = 0; j < r; ++j)
        for(int i = 0; i < r; ++i)
        {
          const bool strictly_in = i > 10 && i < 50 && j > 12 && j < 44 && k > 8 && k < 52;
          const bool strictly_out = i < 10 || i > 50 || j < 12 || j > 44 || k < 8 || k > 52;
          const bool in = inside[std::size_t(i) + r * (std::size_t(j) + r * std::size_t(k))] != 0;
          if((strictly_in && !in) || (strictly_out && in)) ++wrong;
        }
    CHECK(wrong == 0);
  }
}

// -------------------------------------------------------------------------------------- the TSDF

TEST_CASE("TSDF of a sphere: within half a voxel of the exact signed distance, clipped", "[tsdf]")
{
  const Mesh sphere = test_shapes::make_sphere(Point(0.3, -0.2, 0.1), 1.0, 4);
  for(PD::Tsdf_sign_method method : {PD::Tsdf_sign_method::AUTOMATIC, PD::Tsdf_sign_method::INSIDE_TEST,
                                     PD::Tsdf_sign_method::FLOOD_FILL})
  {
    const PD::Truncated_signed_distance_field tsdf = PD::compute_tsdf(sphere, PD::parameters::tsdf_sign_method(method));
    REQUIRE(tsdf.values.resolution() == 64);
    CHECK(tsdf.truncation == Approx(8. / 64.));
    CHECK(tsdf.sign_method == (method == PD::Tsdf_sign_method::AUTOMATIC ? PD::Tsdf_sign_method::RAY_VOTES : method));
    const std::array<double, 3> c = unit(tsdf.normalization, 0.3, -0.2, 0.1);
    const double R = 1.0 * tsdf.normalization.scale();
    auto sd = [&](const std::array<double, 3>& p) { return sd_sphere(p, c, R); };
    check_values(tsdf, sd, 0.5 / 64.);
    check_signs(tsdf, sd, 0.05 / 64.);
    // Deep inside and far outside: exactly -tau and +tau.
    const std::array<int, 3> centre = tsdf.values.locate(c[0], c[1], c[2]);
    CHECK(tsdf.values(centre[0], centre[1], centre[2]) == -tsdf.truncation);
    CHECK(tsdf.values(0, 0, 0) == tsdf.truncation);
    const double lo = *std::min_element(tsdf.values.values().begin(), tsdf.values.values().end());
    const double hi = *std::max_element(tsdf.values.values().begin(), tsdf.values.values().end());
    CHECK(lo == -tsdf.truncation);
    CHECK(hi == tsdf.truncation);
  }
}

TEST_CASE("TSDF of a box equals the exact signed distance", "[tsdf]")
{
  const Mesh box = test_shapes::make_box(Point(-1, -0.6, -0.4), Point(1, 0.6, 0.4), 3);
  const PD::Truncated_signed_distance_field tsdf =
    PD::compute_tsdf(box, PD::parameters::combine(PD::parameters::voxel_resolutions(std::vector<int>{32, 64}),
                                                  PD::parameters::tsdf_truncation(5.)));
  REQUIRE(tsdf.values.resolution() == 64);
  CHECK(tsdf.truncation == Approx(5. / 64.));
  const std::array<double, 3> lo = unit(tsdf.normalization, -1, -0.6, -0.4), hi = unit(tsdf.normalization, 1, 0.6, 0.4);
  auto sd = [&](const std::array<double, 3>& p) { return sd_box(p, lo, hi); };
  check_values(tsdf, sd, 1e-4 / 64.);
  check_signs(tsdf, sd, 1e-9);
}

TEST_CASE("TSDF sign of a closed sphere with one small hole", "[tsdf][sign]")
{
  const Mesh sphere = test_shapes::make_sphere(Point(0, 0, 0), 1.0, 3);
  const Mesh holed = without_first_face(sphere);
  REQUIRE(num_faces(holed) + 1 == num_faces(sphere));
  std::array<double, 3> hole = {{0., 0., 0.}};
  {
    const auto f = *faces(sphere).begin();
    for(auto v : vertices_around_face(halfedge(f, sphere), sphere))
      for(int a = 0; a < 3; ++a) hole[a] += CGAL::to_double(sphere.point(v)[a]) / 3.;
  }
  const PD::Truncated_signed_distance_field tsdf = PD::compute_tsdf(holed);
  CHECK(tsdf.sign_method == PD::Tsdf_sign_method::RAY_VOTES);
  const std::array<double, 3> c = unit(tsdf.normalization, 0, 0, 0), h = unit(tsdf.normalization, hole[0], hole[1], hole[2]);
  const double R = tsdf.normalization.scale();
  auto sd = [&](const std::array<double, 3>& p) { return sd_sphere(p, c, R); };
  auto away_from_hole = [&](const std::array<double, 3>& p) { return sd_sphere(p, h, 4. / 64.) > 0.; };
  CHECK(check_signs(tsdf, sd, 1.5 / 64., away_from_hole) > 200000);
  // Probes: the centre, just inside and just outside the surface opposite to the hole.
  auto value_at = [&](const std::array<double, 3>& p) {
    const std::array<int, 3> v = tsdf.values.locate(p[0], p[1], p[2]);
    return tsdf.values(v[0], v[1], v[2]);
  };
  CHECK(value_at(c) == -tsdf.truncation);
  const std::array<double, 3> dir = {{c[0] - h[0], c[1] - h[1], c[2] - h[2]}};
  const double n = std::sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
  auto along = [&](double t) { return std::array<double, 3>{{c[0] + dir[0] / n * t, c[1] + dir[1] / n * t, c[2] + dir[2] / n * t}}; };
  CHECK(value_at(along(R - 3. / 64.)) < 0.);
  CHECK(value_at(along(R + 3. / 64.)) > 0.);
  // The same probes near the hole: 2 voxels inside and outside the missing face.
  const std::array<double, 3> hd = {{h[0] - c[0], h[1] - c[1], h[2] - c[2]}};
  const double hn = std::sqrt(hd[0] * hd[0] + hd[1] * hd[1] + hd[2] * hd[2]);
  auto near_hole = [&](double t) { return std::array<double, 3>{{c[0] + hd[0] / hn * t, c[1] + hd[1] / hn * t, c[2] + hd[2] / hn * t}}; };
  CHECK(value_at(near_hole(hn - 3. / 64.)) < 0.);
  CHECK(value_at(near_hole(hn + 3. / 64.)) > 0.);

  // Flood fill seals a hole smaller than a voxel (here on the 16^3 grid).
  const PD::Truncated_signed_distance_field coarse = PD::compute_tsdf(
    without_first_face(test_shapes::make_sphere(Point(0, 0, 0), 1.0, 4)),
    PD::parameters::combine(PD::parameters::voxel_resolutions(std::vector<int>{16}),
                            PD::parameters::tsdf_sign_method(PD::Tsdf_sign_method::FLOOD_FILL)));
  CHECK(coarse.sign_method == PD::Tsdf_sign_method::FLOOD_FILL);
  check_signs(coarse, sd, 0.5 / 16.);
}

TEST_CASE("TSDF sign of two separate closed pieces", "[tsdf][sign]")
{
  Mesh m = test_shapes::make_sphere(Point(-0.5, 0, 0), 0.4, 3);
  test_shapes::append(m, test_shapes::make_box(Point(0.2, -0.3, -0.3), Point(0.8, 0.3, 0.3), 2));
  for(const Mesh& mesh : {m, unshared_copy(m)}) // closed, then the same triangles with no shared vertex
  {
    const PD::Truncated_signed_distance_field tsdf = PD::compute_tsdf(mesh);
    CHECK(tsdf.sign_method == PD::Tsdf_sign_method::RAY_VOTES);
    const PD::Normalization& N = tsdf.normalization;
    const std::array<double, 3> c = unit(N, -0.5, 0, 0), lo = unit(N, 0.2, -0.3, -0.3), hi = unit(N, 0.8, 0.3, 0.3);
    const double R = 0.4 * N.scale();
    auto sd = [&](const std::array<double, 3>& p) { return std::min(sd_sphere(p, c, R), sd_box(p, lo, hi)); };
    check_signs(tsdf, sd, 0.1 / 64.);
    check_values(tsdf, sd, 0.5 / 64.);
  }
}

TEST_CASE("TSDF sign of a mesh with an inward-oriented component", "[tsdf][sign]")
{
  Mesh m = test_shapes::make_sphere(Point(-0.5, 0, 0), 0.4, 3);
  test_shapes::append(m, reversed(test_shapes::make_box(Point(0.2, -0.3, -0.3), Point(0.8, 0.3, 0.3), 2)));
  for(const Mesh& mesh : {m, unshared_copy(m)}) // exact winding numbers, then ray votes or hierarchical ones
    for(PD::Tsdf_sign_method method : {PD::Tsdf_sign_method::AUTOMATIC, PD::Tsdf_sign_method::WINDING_NUMBER,
                                       PD::Tsdf_sign_method::FLOOD_FILL})
    {
      const PD::Truncated_signed_distance_field tsdf = PD::compute_tsdf(mesh, PD::parameters::tsdf_sign_method(method));
      const PD::Normalization& N = tsdf.normalization;
      const std::array<double, 3> c = unit(N, -0.5, 0, 0), lo = unit(N, 0.2, -0.3, -0.3), hi = unit(N, 0.8, 0.3, 0.3);
      const double R = 0.4 * N.scale();
      auto sd = [&](const std::array<double, 3>& p) { return std::min(sd_sphere(p, c, R), sd_box(p, lo, hi)); };
      check_signs(tsdf, sd, 0.1 / 64.);
      const std::array<int, 3> in_box = tsdf.values.locate(0.5 * (lo[0] + hi[0]), 0., 0.);
      CHECK(tsdf.values(in_box[0], in_box[1], in_box[2]) == -tsdf.truncation);
    }
}

TEST_CASE("TSDF sign of a self-intersecting union of two boxes", "[tsdf][sign]")
{
  Mesh m = test_shapes::make_box(Point(-0.6, -0.3, -0.3), Point(0.2, 0.3, 0.3), 3);
  test_shapes::append(m, test_shapes::make_box(Point(-0.2, -0.5, -0.2), Point(0.6, 0.1, 0.2), 3));
  auto sd_for = [](const PD::Normalization& N) {
    const std::array<double, 3> a0 = unit(N, -0.6, -0.3, -0.3), a1 = unit(N, 0.2, 0.3, 0.3);
    const std::array<double, 3> b0 = unit(N, -0.2, -0.5, -0.2), b1 = unit(N, 0.6, 0.1, 0.2);
    return [=](const std::array<double, 3>& p) { return std::min(sd_box(p, a0, a1), sd_box(p, b0, b1)); };
  };
  for(const Mesh& mesh : {m, unshared_copy(m)})
  {
    const PD::Truncated_signed_distance_field tsdf = PD::compute_tsdf(mesh);
    CHECK(check_signs(tsdf, sd_for(tsdf.normalization), 0.1 / 64.) > 200000);
    // The overlap, covered twice, is inside.
    const std::array<double, 3> o = unit(tsdf.normalization, 0., -0.1, 0.);
    const std::array<int, 3> v = tsdf.values.locate(o[0], o[1], o[2]);
    CHECK(tsdf.values(v[0], v[1], v[2]) < 0.);
  }
  // Flood fill agrees; ray parity counts the overlap as outside (documented limitation).
  const PD::Truncated_signed_distance_field flood =
    PD::compute_tsdf(m, PD::parameters::tsdf_sign_method(PD::Tsdf_sign_method::FLOOD_FILL));
  check_signs(flood, sd_for(flood.normalization), 0.1 / 64.);
  const PD::Truncated_signed_distance_field parity =
    PD::compute_tsdf(m, PD::parameters::tsdf_sign_method(PD::Tsdf_sign_method::INSIDE_TEST));
  const std::array<double, 3> o = unit(parity.normalization, 0., -0.1, 0.);
  const std::array<int, 3> v = parity.values.locate(o[0], o[1], o[2]);
  CHECK(parity.values(v[0], v[1], v[2]) > 0.);
}

TEST_CASE("TSDF is deterministic, reads the vertex point map and the normalization", "[tsdf]")
{
  Mesh m = test_shapes::make_sphere(Point(-0.5, 0, 0), 0.4, 3);
  test_shapes::append(m, test_shapes::make_cylinder(Point(0.3, 0, 0), 0.2, 0.9, 24, 6));
  const Mesh open = without_first_face(m);
  for(const Mesh* mesh : std::vector<const Mesh*>{&m, &open})
    for(PD::Tsdf_sign_method method : {PD::Tsdf_sign_method::AUTOMATIC, PD::Tsdf_sign_method::WINDING_NUMBER,
                                       PD::Tsdf_sign_method::FLOOD_FILL})
    {
      const auto np = PD::parameters::tsdf_sign_method(method);
      const PD::Truncated_signed_distance_field seq = PD::compute_tsdf<CGAL::Sequential_tag>(*mesh, np);
      const PD::Truncated_signed_distance_field par = PD::compute_tsdf<CGAL::Parallel_if_available_tag>(*mesh, np);
      CHECK(seq.values == par.values);
    }

  // A vertex point map holding the points moved by (10, 20, 30): same field, moved normalization.
  auto moved = get(CGAL::dynamic_vertex_property_t<Point>(), m);
  for(auto v : vertices(m)) put(moved, v, m.point(v) + K::Vector_3(10, 20, 30));
  const PD::Truncated_signed_distance_field base = PD::compute_tsdf(m);
  const PD::Truncated_signed_distance_field shifted = PD::compute_tsdf(m, CGAL::parameters::vertex_point_map(moved));
  CHECK(shifted.normalization.center()[0] == Approx(base.normalization.center()[0] + 10));
  double worst = 0.;
  for(std::size_t i = 0; i < base.values.size(); ++i) worst = std::max(worst, std::abs(base.values[i] - shifted.values[i]));
  CHECK(worst < 1e-9);

  // A given normalization is used as is.
  const PD::Normalization half({{0., 0., 0.}}, 0.5);
  const PD::Truncated_signed_distance_field given = PD::compute_tsdf(m, PD::parameters::normalization(half));
  CHECK(given.normalization.scale() == 0.5);
  // 0.05 inside the sphere of radius 0.2 (normalized) centred at (-0.25, 0, 0).
  const std::array<int, 3> v = given.values.locate(-0.1, 0., 0.);
  const std::array<double, 3> c = given.values.center(v[0], v[1], v[2]);
  CHECK(given.values(v[0], v[1], v[2]) == Approx(sd_sphere(c, {{-0.25, 0., 0.}}, 0.2)).margin(0.5 / 64));
}

TEST_CASE("TSDF of an open sheet: all outside, distances to the triangles", "[tsdf]")
{
  // Two triangles making a slanted square: no inside at all.
  Mesh m;
  const auto a = m.add_vertex(Point(0, 0, 0)), b = m.add_vertex(Point(1, 0, 0.3)), c = m.add_vertex(Point(1, 1, 0.5)),
             d = m.add_vertex(Point(0, 1, 0.2));
  m.add_face(a, b, c);
  m.add_face(a, c, d);
  for(PD::Tsdf_sign_method method : {PD::Tsdf_sign_method::AUTOMATIC, PD::Tsdf_sign_method::FLOOD_FILL})
    for(int r : {2, 16})
    {
      const PD::Truncated_signed_distance_field tsdf = PD::compute_tsdf(
        m, PD::parameters::combine(PD::parameters::tsdf_sign_method(method),
                                   PD::parameters::voxel_resolutions(std::vector<int>{r})));
      const std::vector<PDI::Triangle_points> tris = PDI::normalized_triangles(m, get(CGAL::vertex_point, m), tsdf.normalization);
      for(std::size_t i = 0; i < tsdf.values.size(); ++i)
      {
        const PDI::Vec3 p = tsdf.values.center(i);
        double d2 = std::numeric_limits<double>::infinity();
        for(const auto& t : tris) d2 = std::min(d2, PDI::squared_distance_to_triangle(p, t[0], t[1], t[2]));
        CHECK(tsdf.values[i] == Approx(std::min(std::sqrt(d2), tsdf.truncation)).margin(1e-9));
      }
    }
}

TEST_CASE("TSDF parameters are validated", "[tsdf]")
{
  const Mesh m = test_shapes::make_box(Point(0, 0, 0), Point(1, 1, 1), 1);
  auto throws = [&](const auto& np) {
    try
    {
      PD::compute_tsdf(m, np);
    }
    catch(const PD::Invalid_input& e)
    {
      return e.error() == PD::Input_error::INVALID_PARAMETER;
    }
    return false;
  };
  CHECK(throws(PD::parameters::tsdf_truncation(0.)));
  CHECK(throws(PD::parameters::tsdf_truncation(-1.)));
  CHECK(throws(PD::parameters::voxel_resolutions(std::vector<int>{})));
  CHECK(throws(PD::parameters::voxel_resolutions(std::vector<int>{16, 0})));
  CHECK(throws(PD::parameters::voxel_resolutions(std::vector<int>{4096})));
  // the one rule of voxel_resolutions: powers of two up to 256, each twice the previous
  CHECK(throws(PD::parameters::voxel_resolutions(std::vector<int>{512})));
  CHECK(throws(PD::parameters::voxel_resolutions(std::vector<int>{48})));
  CHECK(throws(PD::parameters::voxel_resolutions(std::vector<int>{64, 32})));
  CHECK(!throws(PD::parameters::voxel_resolutions(std::vector<int>{256})));
  Mesh empty;
  CHECK_THROWS_AS(PD::compute_tsdf(empty), PD::Invalid_input);
}

TEST_CASE("TSDF: the defaults equal every default given explicitly", "[tsdf][parameters]")
{
  const Mesh box = test_shapes::make_box(Point(-1, -0.6, -0.4), Point(1, 0.6, 0.4), 3);
  const PD::Truncated_signed_distance_field a = PD::compute_tsdf(box);
  const PD::Truncated_signed_distance_field b = PD::compute_tsdf(
    box, PD::parameters::combine(PD::parameters::voxel_resolutions(PD::defaults::voxel_resolutions()),
                                 PD::parameters::tsdf_truncation(PD::defaults::tsdf_truncation),
                                 PD::parameters::tsdf_sign_method(PD::Tsdf_sign_method::AUTOMATIC),
                                 PD::parameters::normalization_margin(PD::defaults::normalization_margin)));
  CHECK(a.values.resolution() == PD::defaults::voxel_resolutions().back());
  CHECK(a.values == b.values);
  CHECK(a.truncation == b.truncation);
  CHECK(a.sign_method == b.sign_method);
  CHECK(a.normalization.scale() == b.normalization.scale());
  CHECK(a.normalization.center() == b.normalization.center());
}

TEST_CASE("voxel_resolutions: one rule and one message for the prior, the TSDF and the score", "[tsdf][parameters]")
{
  const Mesh box = test_shapes::make_box(Point(-1, -0.6, -0.4), Point(1, 0.6, 0.4), 2);
  auto message = [](const auto& run) -> std::string {
    try
    {
      run();
    }
    catch(const PD::Invalid_input& e)
    {
      return e.error() == PD::Input_error::INVALID_PARAMETER ? std::string(e.what()) : std::string("other error");
    }
    return "no error";
  };
  std::vector<double> zero(num_faces(box), 0.);
  for(const std::vector<int>& bad : {std::vector<int>{}, std::vector<int>{16, 48}, std::vector<int>{512},
                                     std::vector<int>{32, 16}, std::vector<int>{16, 64}})
  {
    const std::string prior =
      message([&] { PD::compute_flow_freeze_prior(box, PD::parameters::voxel_resolutions(bad)); });
    const std::string tsdf = message([&] { PD::compute_tsdf(box, PD::parameters::voxel_resolutions(bad)); });
    CHECK(prior.find("voxel_resolutions must be") == 0);
    CHECK(tsdf == prior);
  }
  // a single resolution of the score is checked as the list of that one resolution
  const std::string score = message([&] {
    PD::compute_topology_score(box, CGAL::make_property_map(zero), CGAL::make_property_map(zero), 48);
  });
  CHECK(score == message([&] { PD::compute_tsdf(box, PD::parameters::voxel_resolutions(std::vector<int>{48})); }));
  CHECK(message([&] { PD::fuse_flow_freeze({PD::Voxel_grid<PD::Voxel_class>(48)}); }) == score);
}

// -------------------------------------------------------------------------------- fitting zones

TEST_CASE("Fitting zones of a hand-made prior", "[tsdf][zones]")
{
  // A shell of Flow voxels [4,11]^3 in a 16^3 grid, its z = 4 face Freeze, with a hole of 2 x 2
  // voxels in its z = 11 face; the distance field puts the cube inside, the rest outside.
  const int r = 16;
  PD::Voxel_grid<PD::Voxel_class> classes(r, PD::Voxel_class::EMPTY);
  PD::Truncated_signed_distance_field tsdf;
  tsdf.values = PD::Voxel_grid<double>(r, 1.);
  tsdf.truncation = 1.;
  for(int k = 4; k <= 11; ++k)
    for(int j = 4; j <= 11; ++j)
      for(int i = 4; i <= 11; ++i)
      {
        tsdf.values(i, j, k) = -1.;
        const bool hole = k == 11 && (i == 7 || i == 8) && (j == 7 || j == 8);
        if((i == 4 || i == 11 || j == 4 || j == 11 || k == 4 || k == 11) && !hole)
          classes(i, j, k) = k == 4 ? PD::Voxel_class::FREEZE : PD::Voxel_class::FLOW;
      }
  const PD::Fitting_zones z = PD::compute_fitting_zones(classes, tsdf, std::vector<int>{8, 4, 8});
  CHECK(z.flow_zone.size() == 2);
  CHECK(z.flow_zone_distance.size() == 2);
  Mask hull(r, 0);
  for(int k = 0; k < r; ++k)
    for(int j = 0; j < r; ++j)
      for(int i = 0; i < r; ++i)
      {
        const bool in_cube = i >= 4 && i <= 11 && j >= 4 && j <= 11 && k >= 4 && k <= 11;
        const bool hole = k == 11 && (i == 7 || i == 8) && (j == 7 || j == 8);
        const bool shell = in_cube && !hole && (i == 4 || i == 11 || j == 4 || j == 11 || k == 4 || k == 11);
        hull(i, j, k) = in_cube ? 1 : 0;
        CHECK(z.occupied(i, j, k) == (shell ? 1 : 0));
        // the hole does not let the outside in: the exterior is the field's
        CHECK(z.exterior(i, j, k) == (in_cube ? 0 : 1));
        CHECK(z.freeze_zone(i, j, k) == ((!in_cube || (shell && k == 4)) ? 1 : 0));
      }
  const PD::Voxel_grid<double> to_hull = brute_force_edt(hull, false);
  for(int r_fit : {4, 8})
  {
    const double radius = 2. * r / r_fit; // 8 and 4 voxels of the 16^3 grid
    const Mask& flow = z.flow_zone.at(r_fit);
    Mask outside(r, 0);
    for(std::size_t v = 0; v < flow.size(); ++v)
    {
      CHECK(flow[v] == (to_hull[v] <= radius * radius ? 1 : 0));
      outside[v] = flow[v] ? 0 : 1;
    }
    const PD::Voxel_grid<double> to_outside = brute_force_edt(outside, true);
    for(std::size_t v = 0; v < flow.size(); ++v)
      CHECK(z.flow_zone_distance.at(r_fit)[v] == Approx(flow[v] ? std::sqrt(to_outside[v]) / r : 0.));
  }
  // The centre of the cube is 4 voxels from the outside of the r_fit = 8 zone ([0,15]^3 clipped by
  // the grid: the zone reaches the border, whose outside layer counts).
  CHECK(z.flow_zone_distance.at(8)(8, 8, 8) == Approx(8. / 16.));

  const PD::Fitting_zones no_freeze =
    PD::compute_fitting_zones(classes, tsdf, std::vector<int>{8}, PD::parameters::use_freeze_zone(false));
  CHECK(no_freeze.freeze_zone == no_freeze.exterior);
  const PD::Fitting_zones tight = PD::compute_fitting_zones<CGAL::Parallel_if_available_tag>(
    classes, tsdf, std::vector<int>{8}, PD::parameters::flow_zone_tolerance(0.));
  CHECK(tight.flow_zone.at(8) == hull);
  CHECK_THROWS_AS(PD::compute_fitting_zones(classes, tsdf, std::vector<int>{0}), PD::Invalid_input);
  CHECK_THROWS_AS(PD::compute_fitting_zones(classes, tsdf, std::vector<int>{8}, PD::parameters::flow_zone_tolerance(-1.)),
                  PD::Invalid_input);
  PD::Truncated_signed_distance_field coarse;
  coarse.values = PD::Voxel_grid<double>(8, 1.);
  CHECK_THROWS_AS(PD::compute_fitting_zones(classes, coarse, std::vector<int>{8}), PD::Invalid_input);
}

TEST_CASE("an open sheet has no inside, a sphere with a hole of a tenth of its area keeps its inside", "[tsdf][zones][open]")
{
  // A flat square: the winding number is below 1/2 on both sides. A gently wavy sheet: above 1/2
  // only in a layer of at most one voxel on the concave side of its dips, where the sheet covers
  // a little more than half of the directions; it holds no volume.
  for(double amplitude : {0., 0.05})
  {
    const PD::Truncated_signed_distance_field tsdf = PD::compute_tsdf(test_shapes::make_wavy_sheet(20, amplitude));
    const double deepest = *std::min_element(tsdf.values.values().begin(), tsdf.values.values().end());
    if(amplitude == 0.) CHECK(deepest >= 0.);
    CHECK(deepest > -1. / 64.);
  }

  // the unit sphere without its cap z > 0.8 (a tenth of its area): a hole 0.6 wide
  const Mesh sphere = test_shapes::make_sphere(Point(0, 0, 0), 1., 4);
  test_shapes::Soup open_soup;
  for(auto f : faces(sphere))
  {
    std::array<Point, 3> c;
    int k = 0;
    for(auto v : vertices_around_face(halfedge(f, sphere), sphere)) c[std::size_t(k++)] = sphere.point(v);
    if((c[0].z() + c[1].z() + c[2].z()) / 3. <= 0.8) open_soup.triangle(c[0], c[1], c[2]);
  }
  const Mesh open = open_soup.mesh();
  REQUIRE(!CGAL::is_closed(open));
  // the same normalization for both, so that their voxels match
  const PD::Normalization frame = PD::compute_normalization(sphere);
  auto inside = [](const PD::Truncated_signed_distance_field& t) {
    return std::count_if(t.values.values().begin(), t.values.values().end(), [](double d) { return d < 0.; });
  };
  const PD::Truncated_signed_distance_field closed_field = PD::compute_tsdf(sphere, PD::parameters::normalization(frame));
  const PD::Truncated_signed_distance_field open_field = PD::compute_tsdf(open, PD::parameters::normalization(frame));
  const PD::Truncated_signed_distance_field filled = PD::compute_tsdf(
    open, PD::parameters::combine(PD::parameters::normalization(frame), PD::parameters::tsdf_sign_method(PD::Tsdf_sign_method::FLOOD_FILL)));
  INFO("inside voxels: closed " << inside(closed_field) << ", open " << inside(open_field) << ", open by flood fill "
                                << inside(filled));
  // the segment of the ball under the missing cap (2.8% of its volume) may go either way
  CHECK(inside(open_field) >= 0.96 * double(inside(closed_field)));
  CHECK(inside(open_field) <= inside(closed_field));
  CHECK(inside(filled) < 0.05 * double(inside(closed_field))); // the paper's fill leaks through the hole

  // the zones take their exterior from the field: the ball stays open to the fitter
  const PD::Hierarchical_prior prior = PD::compute_flow_freeze_prior(open, PD::parameters::normalization(frame));
  const PD::Fitting_zones zones = PD::compute_fitting_zones(prior.classes, open_field, PD::fitting_resolutions(prior.resolutions));
  std::size_t exterior_in_ball = 0;
  for(std::size_t v = 0; v < zones.exterior.size(); ++v)
  {
    const std::array<double, 3> c = zones.exterior.center(v);
    const double radius = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]) / frame.scale();
    if(radius < 0.7 && zones.exterior[v]) ++exterior_in_ball;
  }
  CHECK(exterior_in_ball == 0);
}
