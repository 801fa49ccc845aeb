// The prior: geometric cues, topology score, Flow/Freeze cut and the octree fusion.
#include <catch2/catch.hpp>

#include <CGAL/Part_decomposition/flow_freeze_prior.h>
#include <CGAL/Part_decomposition/geometric_cues.h>
#include <CGAL/Part_decomposition/topology_score.h>

#include <CGAL/Polygon_mesh_processing/orientation.h>

#include "shipped_shapes.h"
#include "method_switches.h"
#include "test_shapes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

namespace PD = CGAL::Part_decomposition;
using test_shapes::Mesh;
using test_shapes::Point;
typedef boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
typedef boost::graph_traits<Mesh>::face_descriptor face_descriptor;
typedef PD::Voxel_class VC;

namespace {

// Flat n x n grid of squares (two triangles each) over [0,1]^2 at z = 0: an open mesh.
Mesh make_sheet(int n)
{
  test_shapes::Soup s;
  auto P = [&](int i, int j) { return Point(double(i) / n, double(j) / n, 0.); };
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < n; ++j)
    {
      s.triangle(P(i, j), P(i + 1, j), P(i + 1, j + 1));
      s.triangle(P(i, j), P(i + 1, j + 1), P(i, j + 1));
    }
  return s.mesh();
}

std::vector<double> vertex_curvatures(const Mesh& m)
{
  std::vector<double> k(num_vertices(m), -1.);
  PD::compute_vertex_mean_curvature(m, CGAL::make_property_map(k));
  return k;
}

struct Face_cues
{
  std::vector<double> c, phi;
};

template <typename ConcurrencyTag = CGAL::Sequential_tag, typename NamedParameters = CGAL::parameters::Default_named_parameters>
Face_cues face_cues(const Mesh& m, const NamedParameters& np = CGAL::parameters::default_values())
{
  Face_cues cues;
  cues.c.assign(num_faces(m), -1.);
  cues.phi.assign(num_faces(m), -1.);
  PD::compute_geometric_cues<ConcurrencyTag>(m, CGAL::make_property_map(cues.c), CGAL::make_property_map(cues.phi), np);
  return cues;
}

// The torus of major radius R and tube radius r, n x n quads split in two, oriented outward; `tube`
// receives the cosine of the tube angle at each face's centre (-1: the inner equator).
Mesh make_torus(double R, double r, int n, std::vector<double>& tube)
{
  const double pi = std::acos(-1.);
  auto P = [&](int i, int j) { // i around the axis, j around the tube; indices taken modulo n
    const double phi = 2 * pi * ((i % n + n) % n) / n, theta = 2 * pi * ((j % n + n) % n) / n;
    return Point((R + r * std::cos(theta)) * std::cos(phi), (R + r * std::cos(theta)) * std::sin(phi), r * std::sin(theta));
  };
  test_shapes::Soup s;
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < n; ++j)
    {
      // (i, j) -> (i + 1, j) -> (i + 1, j + 1) turns around the outward normal
      s.triangle(P(i, j), P(i + 1, j), P(i + 1, j + 1));
      s.triangle(P(i, j), P(i + 1, j + 1), P(i, j + 1));
      tube.push_back(std::cos(2 * pi * (j + 0.5) / n));
      tube.push_back(std::cos(2 * pi * (j + 0.5) / n));
    }
  return s.mesh();
}

Point centroid(const Mesh& m, face_descriptor f)
{
  double x = 0, y = 0, z = 0;
  for(auto v : vertices_around_face(halfedge(f, m), m))
  {
    x += m.point(v).x() / 3;
    y += m.point(v).y() / 3;
    z += m.point(v).z() / 3;
  }
  return Point(x, y, z);
}

// Two boxes joined by a thin bar along x.
Mesh make_dumbbell()
{
  Mesh m = test_shapes::make_box(Point(-1, -0.35, -0.35), Point(-0.3, 0.35, 0.35), 12);
  test_shapes::append(m, test_shapes::make_box(Point(0.3, -0.35, -0.35), Point(1, 0.35, 0.35), 12));
  test_shapes::append(m, test_shapes::make_box(Point(-0.3, -0.06, -0.06), Point(0.3, 0.06, 0.06), 6));
  return m;
}

// A 2-level hand-made pair of grids: parents at resolution r, children at 2r.
struct Levels
{
  std::vector<PD::Voxel_grid<VC> > grids;
  explicit Levels(std::vector<int> res)
  {
    for(int r : res) grids.emplace_back(r, VC::EMPTY);
  }
  // Sets the 8 children of coarse voxel (i,j,k) of level l (child c: bit0 = x, bit1 = y, bit2 = z).
  void children(std::size_t l, int i, int j, int k, const std::array<VC, 8>& cls)
  {
    for(int c = 0; c < 8; ++c)
      grids[l + 1](2 * i + (c & 1), 2 * j + ((c >> 1) & 1), 2 * k + ((c >> 2) & 1)) = cls[std::size_t(c)];
  }
};

const VC E = VC::EMPTY, F = VC::FLOW, Z = VC::FREEZE;

// The voxels outside `mask` that a 6-connected flood fill from the grid border reaches through
// voxels outside it (the library's dense fill went with the dense grid).
PD::Voxel_grid<std::uint8_t> border_connected_complement(const PD::Voxel_grid<std::uint8_t>& mask)
{
  const int r = mask.resolution();
  PD::Voxel_grid<std::uint8_t> reached(r, 0);
  std::vector<std::array<int, 3> > queue;
  auto push = [&](int i, int j, int k) {
    if(!mask.contains(i, j, k) || mask(i, j, k) != 0 || reached(i, j, k) != 0) return;
    reached(i, j, k) = 1;
    queue.push_back({{i, j, k}});
  };
  for(int k = 0; k < r; ++k)
    for(int j = 0; j < r; ++j)
      for(int i = 0; i < r; ++i)
        if(i == 0 || j == 0 || k == 0 || i == r - 1 || j == r - 1 || k == r - 1) push(i, j, k);
  for(std::size_t head = 0; head < queue.size(); ++head)
  {
    const std::array<int, 3> v = queue[head];
    for(int a = 0; a < 3; ++a)
      for(int s : {-1, 1})
      {
        std::array<int, 3> w = v;
        w[std::size_t(a)] += s;
        push(w[0], w[1], w[2]);
      }
  }
  return reached;
}


} // namespace

// ---------------------------------------------------------------------------------------------
// Curvature

TEST_CASE("Meyer mixed Voronoi areas sum to the triangle area", "[cues]")
{
  const std::vector<std::array<PD::internal::Vec3, 3> > triangles = {
    {{{{0, 0, 0}}, {{1, 0, 0}}, {{0.4, 0.9, 0}}}},     // acute
    {{{{0, 0, 0}}, {{1, 0, 0}}, {{0, 1, 0}}}},         // right angle at a
    {{{{0, 0, 0}}, {{1, 0, 0}}, {{0.5, 0.1, 0.2}}}},   // obtuse at c
    {{{{0.5, 0.05, 0}}, {{0, 0, 0}}, {{1, 0, 0.1}}}},  // obtuse at a
    {{{{3, 1, 2}}, {{-1, 0.5, 1}}, {{0.2, 7, -3}}}}};
  for(const auto& t : triangles)
  {
    const PD::internal::Vec3 n = PD::internal::cross3(PD::internal::sub3(t[1], t[0]), PD::internal::sub3(t[2], t[0]));
    const double area = 0.5 * std::sqrt(PD::internal::dot3(n, n));
    const std::array<double, 3> a = PD::internal::mixed_voronoi_areas(t[0], t[1], t[2]);
    CHECK(a[0] + a[1] + a[2] == Approx(area).epsilon(1e-12));
    for(double x : a) CHECK(x > 0.);
  }
  // Obtuse at c: c gets half, the others a quarter each.
  const std::array<double, 3> a = PD::internal::mixed_voronoi_areas({{0, 0, 0}}, {{1, 0, 0}}, {{0.5, 0.1, 0.}});
  CHECK(a[2] == Approx(0.025));
  CHECK(a[0] == Approx(0.0125));
  CHECK(a[1] == Approx(0.0125));
  // Equilateral: a third each.
  const std::array<double, 3> e = PD::internal::mixed_voronoi_areas({{0, 0, 0}}, {{1, 0, 0}}, {{0.5, std::sqrt(3.) / 2, 0.}});
  CHECK(e[0] == Approx(std::sqrt(3.) / 12));
  CHECK(e[1] == Approx(std::sqrt(3.) / 12));
}

TEST_CASE("mean curvature of a fine sphere is 1/R", "[cues]")
{
  const double R = 2.5;
  const Mesh m = test_shapes::make_sphere(Point(1, -2, 0.5), R, 5);
  const std::vector<double> k = vertex_curvatures(m);
  for(auto v : vertices(m)) REQUIRE(k[v.idx()] == Approx(1. / R).epsilon(0.02));
}

TEST_CASE("mean curvature of a cylinder side is 1/(2R)", "[cues]")
{
  const double R = 0.8, h = 4.;
  const int na = 96, nz = 76; // square-ish cells: 2 pi R / na ~ h / nz
  const Mesh m = test_shapes::make_cylinder(Point(0, 0, 0), R, h, na, nz);
  const std::vector<double> k = vertex_curvatures(m);
  std::size_t checked = 0;
  for(auto v : vertices(m))
  {
    const Point& p = m.point(v);
    const double r = std::sqrt(p.x() * p.x() + p.y() * p.y());
    if(std::abs(r - R) > 1e-9 || std::abs(p.z()) > h / 2 - 3 * h / nz) continue;
    ++checked;
    CHECK(k[v.idx()] == Approx(1. / (2 * R)).epsilon(0.03));
  }
  CHECK(checked > std::size_t(na * (nz - 8)));
}

TEST_CASE("mean curvature is 0 on a flat sheet, 1/R on the border of an open sphere cap", "[cues]")
{
  const Mesh m = make_sheet(10);
  const std::vector<double> k = vertex_curvatures(m);
  for(auto v : vertices(m))
  {
    REQUIRE(std::isfinite(k[v.idx()]));
    CHECK(k[v.idx()] < 1e-12); // also on the rim: only the normal component counts there
  }
  // An open hemisphere-like cap: finite on the border too.
  Mesh s = test_shapes::make_sphere(Point(0, 0, 0), 1., 3);
  std::vector<face_descriptor> remove;
  for(auto f : faces(s))
    if(centroid(s, f).z() > 0.3) remove.push_back(f);
  for(auto f : remove) CGAL::Euler::remove_face(halfedge(f, s), s);
  s.collect_garbage();
  const std::vector<double> ks = vertex_curvatures(s);
  std::size_t border = 0;
  for(auto v : vertices(s))
  {
    REQUIRE(std::isfinite(ks[v.idx()]));
    border += is_border(v, s) ? 1 : 0;
    if(is_border(v, s))
      CHECK(ks[v.idx()] <= 1.1); // the normal component only: no rim curvature added
    else
      CHECK(ks[v.idx()] == Approx(1.).epsilon(0.05));
  }
  CHECK(border > 0);
}

TEST_CASE("a zero-area face and an isolated vertex give finite cues", "[cues]")
{
  // A(0,0) M(0.5,0) B(1,0) collinear: face (A,B,M) has zero area; C above, D a tip out of plane.
  Mesh m;
  const auto A = m.add_vertex(Point(0, 0, 0)), B = m.add_vertex(Point(1, 0, 0)), M = m.add_vertex(Point(0.5, 0, 0));
  const auto C = m.add_vertex(Point(0.5, 1, 0)), D = m.add_vertex(Point(0.5, 0.4, 0.7));
  m.add_vertex(Point(5, 5, 5)); // isolated
  REQUIRE(m.add_face(A, M, D) != Mesh::null_face());
  REQUIRE(m.add_face(M, B, D) != Mesh::null_face());
  REQUIRE(m.add_face(B, C, D) != Mesh::null_face());
  REQUIRE(m.add_face(C, A, D) != Mesh::null_face());
  REQUIRE(m.add_face(A, B, M) != Mesh::null_face()); // degenerate
  const std::vector<double> k = vertex_curvatures(m);
  for(double x : k) CHECK(std::isfinite(x));
  CHECK(k[5] == 0.); // isolated
  const Face_cues cues = face_cues(m);
  for(double x : cues.c) CHECK((std::isfinite(x) && x >= 0. && x <= 1.));
  for(double x : cues.phi) CHECK((std::isfinite(x) && x >= 0. && x <= 2.));
  const PD::Hierarchical_prior prior = PD::compute_flow_freeze_prior(m);
  for(double s : prior.fields.back().score.values()) CHECK(std::isfinite(s));
}

TEST_CASE("face curvature cue is clipped and normalized to [0,1]", "[cues]")
{
  Mesh m = test_shapes::make_sphere(Point(0, 0, 0), 1., 3);
  test_shapes::append(m, test_shapes::make_sphere(Point(3, 0, 0), 0.25, 3)); // 4x the curvature
  // the paper's cue: convex spheres have no concave vertex
  const Face_cues cues = face_cues(m, switches(&Variant::use_concave_curvature, false));
  double cmax = 0.;
  for(double x : cues.c)
  {
    CHECK(x >= 0.);
    CHECK(x <= 1.);
    cmax = (std::max)(cmax, x);
  }
  CHECK(cmax == Approx(1.));
  // The large sphere has a quarter of the curvature of the small one.
  const std::size_t n_big = num_faces(test_shapes::make_sphere(Point(0, 0, 0), 1., 3));
  CHECK(cues.c[0] == Approx(0.25).epsilon(0.02));
  CHECK(cues.c[n_big] == Approx(1.).epsilon(0.001));
  // A flat sheet: the maximum is 0, every cue is 0.
  const Face_cues flat = face_cues(make_sheet(6));
  for(double x : flat.c) CHECK(x == 0.);
}

TEST_CASE("the curvature cue counts the concave vertices only: none on a sphere, the inner side of a torus",
          "[cues]")
{
  const Mesh sphere = test_shapes::make_sphere(Point(0, 0, 0), 1., 3);
  for(double x : face_cues(sphere).c) CHECK(x == 0.);
  for(double x : face_cues(sphere, switches(&Variant::use_concave_curvature, false)).c) CHECK(x > 0.5);
  // Taken inside out, every vertex of the sphere is concave.
  Mesh inverted = sphere;
  CGAL::Polygon_mesh_processing::reverse_face_orientations(inverted);
  for(double x : face_cues(inverted).c) CHECK(x > 0.5);

  // R = 1.5, r = 1: the mean curvature (R + 2 r cos t) / (2 r (R + r cos t)) is negative where the
  // cosine of the tube angle t is below -R / 2r = -0.75.
  std::vector<double> tube;
  const Mesh torus = make_torus(1.5, 1., 48, tube);
  const Face_cues cues = face_cues(torus), paper = face_cues(torus, switches(&Variant::use_concave_curvature, false));
  std::size_t concave = 0, convex = 0;
  for(std::size_t f = 0; f < tube.size(); ++f)
  {
    CHECK(paper.c[f] > 0.);
    if(tube[f] < -0.85) { CHECK(cues.c[f] > 0.); ++concave; }
    if(tube[f] > -0.65) { CHECK(cues.c[f] == 0.); ++convex; }
  }
  CHECK(concave > 0);
  CHECK(convex > concave);
}

// ---------------------------------------------------------------------------------------------
// Normal deviation

TEST_CASE("normal deviation is 0 on a flat sheet and high on a cube's edges", "[cues]")
{
  const Face_cues flat = face_cues(make_sheet(8));
  for(double x : flat.phi) CHECK(x < 1e-6);

  const int n = 8;
  const Mesh cube = test_shapes::make_box(Point(-1, -1, -1), Point(1, 1, 1), n);
  const Face_cues cues = face_cues(cube);
  double edge_min = 10., centre_max = 0.;
  for(auto f : faces(cube))
  {
    const Point c = centroid(cube, f);
    const double a[3] = {std::abs(c.x()), std::abs(c.y()), std::abs(c.z())};
    std::array<double, 3> s = {{a[0], a[1], a[2]}};
    std::sort(s.begin(), s.end());
    // s[2] = 1 on the face; s[1] = distance to the nearest edge's axis.
    if(s[1] > 1. - 1. / n) edge_min = (std::min)(edge_min, cues.phi[f.idx()]);
    if(s[1] < 0.5) centre_max = (std::max)(centre_max, cues.phi[f.idx()]);
  }
  CHECK(centre_max < 1e-6);
  CHECK(edge_min > 0.2); // at least ~2 of 8 neighbours across a right angle
}

// ---------------------------------------------------------------------------------------------
// Sampling, binning, score

TEST_CASE("barycentric sample grid: n^2 points strictly inside, summing to 1", "[score]")
{
  for(std::size_t n : {1, 2, 3, 6, 7})
  {
    const auto s = PD::barycentric_sample_grid(n * n);
    REQUIRE(s.size() == n * n);
    double mean[3] = {0, 0, 0};
    for(const auto& w : s)
    {
      CHECK(w[0] + w[1] + w[2] == Approx(1.).epsilon(1e-14));
      for(int i = 0; i < 3; ++i)
      {
        CHECK(w[i] > 0.);
        mean[i] += w[i] / double(s.size());
      }
    }
    for(int i = 0; i < 3; ++i) CHECK(mean[i] == Approx(1. / 3.)); // evenly spread
    for(std::size_t a = 0; a < s.size(); ++a)
      for(std::size_t b = a + 1; b < s.size(); ++b)
        CHECK(std::abs(s[a][0] - s[b][0]) + std::abs(s[a][1] - s[b][1]) > 1e-9);
  }
  CHECK_THROWS_AS(PD::barycentric_sample_grid(35), PD::Invalid_input);
  CHECK_THROWS_AS(PD::barycentric_sample_grid(0), PD::Invalid_input);
}

TEST_CASE("binning p = +0.5 goes to the last voxel", "[score]")
{
  for(int r : {1, 16, 32, 64, 256}) CHECK(PD::voxel_coordinate(0.5, r) == r - 1);
  // A box whose +x face is mapped exactly onto x = +0.5.
  const Mesh box = test_shapes::make_box(Point(-1, -1, -1), Point(1, 1, 1), 2);
  const PD::Normalization nz({{0., 0., 0.}}, 0.5);
  std::vector<double> zero(num_faces(box), 0.);
  const PD::Topology_score_field field = PD::compute_topology_score(
    box, CGAL::make_property_map(zero), CGAL::make_property_map(zero), 16, PD::parameters::normalization(nz));
  std::size_t last = 0;
  for(int k = 0; k < 16; ++k)
    for(int j = 0; j < 16; ++j) last += field.sample_count(15, j, k);
  CHECK(last >= 36u * 8u); // the 8 triangles of the +x face at least
}

TEST_CASE("exactly N samples per face, counts summing to N*F at every resolution, as binned one by one", "[score]")
{
  const Mesh m = make_dumbbell();
  const Face_cues cues = face_cues(m);
  const PD::Normalization nz = PD::compute_normalization(m);
  // up to 32: at 64 the bar's long triangles exceed sqrt(N)/2 voxels and are cut (next test)
  const std::vector<int> res = {8, 16, 32};
  for(std::size_t N : {36, 49})
  {
    const auto bary = PD::barycentric_sample_grid(N);
    // Brute force: every sample binned at every resolution with voxel_coordinate().
    std::vector<std::vector<double> > count(res.size()), sum(res.size());
    for(std::size_t l = 0; l < res.size(); ++l)
    {
      count[l].assign(std::size_t(res[l] * res[l] * res[l]), 0.);
      sum[l].assign(count[l].size(), 0.);
    }
    for(auto f : faces(m))
    {
      std::array<std::array<double, 3>, 3> u;
      int c = 0;
      for(auto v : vertices_around_face(halfedge(f, m), m)) u[c++] = nz.to_unit(m.point(v));
      for(const auto& w : bary)
      {
        double p[3];
        for(int a = 0; a < 3; ++a) p[a] = w[0] * u[0][a] + w[1] * u[1][a] + w[2] * u[2][a];
        for(std::size_t l = 0; l < res.size(); ++l)
        {
          const int r = res[l];
          const std::size_t idx = std::size_t(PD::voxel_coordinate(p[0], r) +
                                              r * (PD::voxel_coordinate(p[1], r) + r * PD::voxel_coordinate(p[2], r)));
          count[l][idx] += 1;
          sum[l][idx] += cues.c[f.idx()];
        }
      }
    }
    for(std::size_t l = 0; l < res.size(); ++l)
    {
      const PD::Topology_score_field field = PD::compute_topology_score(
        m, CGAL::make_property_map(cues.c), CGAL::make_property_map(cues.phi), res[l],
        PD::parameters::combine(CGAL::parameters::number_of_points_per_face(N), PD::parameters::normalization(nz)));
      REQUIRE(field.resolution == res[l]);
      std::size_t total = 0, active = 0;
      bool same = true;
      for(std::size_t v = 0; v < field.sample_count.size(); ++v)
      {
        total += field.sample_count[v];
        active += field.sample_count[v] > 0 ? 1 : 0;
        same = same && double(field.sample_count[v]) == count[l][v];
        if(field.sample_count[v] > 0)
          same = same && std::abs(field.curvature_mean[v] - sum[l][v] / count[l][v]) < 1e-12;
        else
          same = same && field.score[v] == 0. && field.classes[v] == VC::EMPTY;
      }
      CHECK(same);
      CHECK(total == N * num_faces(m));
      CHECK(active == field.number_of_active_voxels);
    }
  }
}

TEST_CASE("large triangles are sampled densely enough to leave no hole in the active set", "[score]")
{
  // The same cube as 12 triangles (edges of about 60 voxels at 64^3) and as 24 x 24 squares per side.
  const Mesh coarse = test_shapes::make_box(Point(-1, -1, -1), Point(1, 1, 1), 1);
  const Mesh fine = test_shapes::make_box(Point(-1, -1, -1), Point(1, 1, 1), 24);
  const PD::Normalization nz({{0.0123, 0.0371, -0.0219}}, 0.41); // no face on a voxel boundary
  auto field_of = [&](const Mesh& m) {
    std::vector<double> zero(num_faces(m), 0.);
    return PD::compute_topology_score(m, CGAL::make_property_map(zero), CGAL::make_property_map(zero), 64,
                                      PD::parameters::normalization(nz));
  };
  const PD::Topology_score_field c = field_of(coarse), f = field_of(fine);
  auto occupied = [](const PD::Topology_score_field& field) {
    PD::Voxel_grid<std::uint8_t> m(field.resolution, 0);
    for(std::size_t v = 0; v < m.size(); ++v) m[v] = field.sample_count[v] > 0 ? 1 : 0;
    return m;
  };
  const PD::Voxel_grid<std::uint8_t> oc = occupied(c), of = occupied(f);
  // the surface voxels of the fine cube are all reached by the 12 triangles, and few more
  std::size_t missed = 0, extra = 0;
  for(std::size_t v = 0; v < oc.size(); ++v)
  {
    missed += (of[v] && !oc[v]) ? 1 : 0;
    extra += (oc[v] && !of[v]) ? 1 : 0;
  }
  CHECK(missed == 0u);
  CHECK(extra <= f.number_of_active_voxels / 50);
  // no hole: the flood fill from the grid border stays outside, as for the fine cube
  const PD::Voxel_grid<std::uint8_t> ec = border_connected_complement(oc), ef = border_connected_complement(of);
  CHECK(ec(32, 32, 32) == 0);
  CHECK(ec.values() == ef.values());
  // each face still counts about N samples: its weights are rounded per voxel, at least 1, so
  // it adds at most one per voxel it reaches (a voxel on an edge of the cube is reached by up to 4)
  std::size_t total = 0;
  for(std::size_t v = 0; v < c.sample_count.size(); ++v) total += c.sample_count[v];
  CHECK(total >= 36u * 12u);
  CHECK(total <= 36u * 12u + 4u * c.number_of_active_voxels);
}

TEST_CASE("score terms on a hand-checked configuration", "[score]")
{
  // Two faces in one voxel of a 1-grid with c = 0 and 1: mu = 1/2, sigma = 1/2, Delta = 0 (r = 1),
  // phi mean = (0.2 + 0.6)/2; S = (mu + sigma + 0 + 0.4) * sqrt(72).
  Mesh m;
  const auto a = m.add_vertex(Point(0, 0, 0)), b = m.add_vertex(Point(1, 0, 0));
  const auto c = m.add_vertex(Point(0, 1, 0)), d = m.add_vertex(Point(1, 1, 0.5));
  m.add_face(a, b, c);
  m.add_face(b, d, c);
  std::vector<double> cv = {0., 1.}, pv = {0.2, 0.6};
  const PD::Topology_score_field f = PD::compute_topology_score(
    m, CGAL::make_property_map(cv), CGAL::make_property_map(pv), 1,
    PD::parameters::cue_weights(std::array<double, 4>{{1., 1., 1., 1.}}));
  CHECK(f.sample_count[0] == 72u);
  CHECK(f.curvature_mean[0] == Approx(0.5));
  CHECK(f.curvature_deviation[0] == Approx(0.5));
  CHECK(f.curvature_gradient[0] == 0.);
  CHECK(f.normal_deviation[0] == Approx(0.4));
  CHECK(f.score[0] == Approx(1.4 * std::sqrt(72.)));
  const PD::Topology_score_field g = PD::compute_topology_score(
    m, CGAL::make_property_map(cv), CGAL::make_property_map(pv), 1,
    PD::parameters::cue_weights(std::vector<double>{2., 0., 0., 0.5}));
  CHECK(g.score[0] == Approx((2 * 0.5 + 0.5 * 0.4) * std::sqrt(72.)));
}

TEST_CASE("curvature gradient: central differences inside, one-sided at the border", "[score]")
{
  PD::internal::Voxel_sums vs;
  vs.r = 4;
  vs.n.assign(64, 1);
  vs.s1.assign(64, 0.);
  vs.s2.assign(64, 0.);
  vs.sphi.assign(64, 0.);
  // mu = i^2 along x, plus 3 k along z
  for(int k = 0; k < 4; ++k)
    for(int j = 0; j < 4; ++j)
      for(int i = 0; i < 4; ++i) vs.s1[std::size_t(i + 4 * (j + 4 * k))] = double(i * i) + 3. * k;
  PD::Topology_score_field f;
  PD::internal::make_score_field(vs, {{0., 0., 1., 0.}}, true, f);
  auto expect = [](int i) { return i == 0 ? 1. : i == 3 ? 5. : 2. * i; }; // d(i^2)/di
  for(int k = 0; k < 4; ++k)
    for(int i = 0; i < 4; ++i)
      CHECK(f.curvature_gradient(i, 2, k) == Approx(std::sqrt(expect(i) * expect(i) + 9.)));
}

TEST_CASE("the top-alpha cut freezes alpha of the active voxels", "[score]")
{
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U(0., 10.);
  for(int trial = 0; trial < 30; ++trial)
  {
    const int r = 8 + (trial % 3) * 4;
    PD::Topology_score_field field;
    field.sample_count = PD::Voxel_grid<std::uint32_t>(r, 0);
    field.score = PD::Voxel_grid<double>(r, 0.);
    std::size_t m = 0;
    for(std::size_t v = 0; v < field.score.size(); ++v)
      if(U(rng) < 3.)
      {
        field.sample_count[v] = 1 + std::uint32_t(U(rng));
        field.score[v] = U(rng);
        ++m;
      }
    for(double alpha : {0.01, 0.15, 0.5, 0.9})
    {
      PD::apply_flow_freeze_cut(field, alpha);
      CHECK(field.number_of_active_voxels == m);
      std::size_t freeze = 0, flow = 0;
      for(std::size_t v = 0; v < field.score.size(); ++v)
      {
        if(field.sample_count[v] == 0) CHECK(field.classes[v] == VC::EMPTY);
        freeze += field.classes[v] == VC::FREEZE ? 1 : 0;
        flow += field.classes[v] == VC::FLOW ? 1 : 0;
        if(field.classes[v] == VC::FREEZE) CHECK(field.score[v] >= field.threshold);
        if(field.classes[v] == VC::FLOW) CHECK(field.score[v] < field.threshold);
      }
      CHECK(freeze == field.number_of_freeze_voxels);
      CHECK(freeze + flow == m);
      CHECK(std::abs(double(freeze) - alpha * double(m)) <= 1.);
    }
  }
  // Ties: all equal scores are all Freeze.
  PD::Topology_score_field tied;
  tied.sample_count = PD::Voxel_grid<std::uint32_t>(4, 1);
  tied.score = PD::Voxel_grid<double>(4, 2.);
  PD::apply_flow_freeze_cut(tied, 0.15);
  CHECK(tied.number_of_freeze_voxels == 64u);
  // ... except a zero score, which is no evidence at all: 90% zeros, alpha = 0.15.
  for(std::size_t v = 0; v < 64; ++v) tied.score[v] = v < 58 ? 0. : 1. + double(v);
  PD::apply_flow_freeze_cut(tied, 0.15);
  CHECK(tied.threshold == 0.);
  CHECK(tied.number_of_freeze_voxels == 6u);
  CHECK_THROWS_AS(PD::apply_flow_freeze_cut(tied, 0.), PD::Invalid_input);
  CHECK_THROWS_AS(PD::apply_flow_freeze_cut(tied, 1.), PD::Invalid_input);
}

// ---------------------------------------------------------------------------------------------
// Fusion

TEST_CASE("fusion rules on two levels", "[fusion]")
{
  Levels L({2, 4});
  auto& P = L.grids[0];
  // (0,0,0) rule (i): Flow parent, 4 Flow children -> one Flow leaf at 2.
  P(0, 0, 0) = F;
  L.children(0, 0, 0, 0, {{F, F, F, F, E, E, E, E}});
  // (1,0,0) rule (ii): Flow parent, one Freeze child -> split.
  P(1, 0, 0) = F;
  L.children(0, 1, 0, 0, {{F, F, F, Z, E, E, E, E}});
  // (0,1,0) rule (iii): Freeze parent, 1 of 4 children Flow (1/4 < 0.5) -> one Freeze leaf.
  P(0, 1, 0) = Z;
  L.children(0, 0, 1, 0, {{Z, Z, Z, F, E, E, E, E}});
  // (1,1,0) rule (iv): Freeze parent, 2 of 4 children Flow (2/4 >= 0.5) -> split.
  P(1, 1, 0) = Z;
  L.children(0, 1, 1, 0, {{Z, Z, F, F, E, E, E, E}});
  // (0,0,1) sparse support: Flow parent with 2 Flow children -> split anyway.
  P(0, 0, 1) = F;
  L.children(0, 0, 0, 1, {{F, E, E, E, E, E, E, F}});
  // (1,0,1) sparse support: Freeze parent with 1 Freeze child -> split.
  P(1, 0, 1) = Z;
  L.children(0, 1, 0, 1, {{E, E, E, E, E, E, Z, E}});
  // (0,1,1) Freeze parent, 5 Freeze and 3 Flow children (3/8 < 0.5) -> Freeze leaf.
  P(0, 1, 1) = Z;
  L.children(0, 0, 1, 1, {{Z, F, Z, F, Z, F, Z, Z}});

  const PD::Hierarchical_prior prior = PD::fuse_flow_freeze(L.grids);
  REQUIRE(prior.classes.resolution() == 4);
  REQUIRE(prior.resolutions == std::vector<int>({2, 4}));
  const auto& fine = L.grids[1];
  auto check_block = [&](int i, int j, int k, bool leaf, VC leaf_class) {
    for(int c = 0; c < 8; ++c)
    {
      const int x = 2 * i + (c & 1), y = 2 * j + ((c >> 1) & 1), z = 2 * k + ((c >> 2) & 1);
      INFO("parent " << i << j << k << " child " << c);
      if(fine(x, y, z) == E)
      {
        CHECK(prior.classes(x, y, z) == E);
        CHECK(prior.leaf_resolution(x, y, z) == 0);
      }
      else if(leaf)
      {
        CHECK(prior.classes(x, y, z) == leaf_class);
        CHECK(prior.leaf_resolution(x, y, z) == 2);
      }
      else
      {
        CHECK(prior.classes(x, y, z) == fine(x, y, z));
        CHECK(prior.leaf_resolution(x, y, z) == 4);
      }
    }
  };
  check_block(0, 0, 0, true, F);
  check_block(1, 0, 0, false, E);
  check_block(0, 1, 0, true, Z);
  check_block(1, 1, 0, false, E);
  check_block(0, 0, 1, false, E);
  check_block(1, 0, 1, false, E);
  check_block(0, 1, 1, true, Z);
  check_block(1, 1, 1, false, E); // empty everywhere
  CHECK(prior.number_of_flow_leaves == std::vector<std::size_t>({1, 3 + 2 + 2}));
  CHECK(prior.number_of_freeze_leaves == std::vector<std::size_t>({2, 1 + 2 + 1}));
  CHECK(prior.fields.empty());
}

TEST_CASE("fusion on three levels: backward consistency and inheritance", "[fusion]")
{
  Levels L({2, 4, 8});
  auto& P = L.grids[0];
  // Parent A (0,0,0), Freeze, keeps its children mostly Freeze (rule iii): it would stay a leaf...
  P(0, 0, 0) = Z;
  L.children(0, 0, 0, 0, {{Z, Z, Z, F, E, E, E, E}});
  // ...but its child (1,0,0) (Freeze) relaxes (iv) at 8: 3 of 4 grandchildren Flow -> splits,
  // which forces A to split. Child (1,1,0) is Flow with Flow grandchildren: it stays a leaf and
  // inherits A's class Freeze; children (0,0,0) and (0,1,0) stay Freeze leaves at 4.
  L.children(1, 1, 0, 0, {{F, F, F, Z, E, E, E, E}});
  L.children(1, 0, 0, 0, {{Z, Z, Z, Z, E, E, E, E}});
  L.children(1, 0, 1, 0, {{Z, Z, Z, F, E, E, E, E}});
  L.children(1, 1, 1, 0, {{F, F, F, F, E, E, E, E}});
  // Parent B (1,0,0), Flow, all children Flow with Flow grandchildren: one Flow leaf at 2.
  P(1, 0, 0) = F;
  L.children(0, 1, 0, 0, {{F, F, F, F, E, E, E, E}});
  for(int c : {0, 1, 2, 3})
    L.children(1, 2 + (c & 1), (c >> 1) & 1, 0, {{F, F, F, F, F, F, F, F}});
  // Parent C (0,1,0) empty at 2 but with children at 4 (inconsistent grids): it splits and its
  // children carry their own classes; child (0,2,0) Flow with one Freeze grandchild splits.
  L.children(0, 0, 1, 0, {{F, F, F, E, E, E, E, E}});
  L.children(1, 0, 2, 0, {{F, F, Z, F, E, E, E, E}});
  L.children(1, 1, 2, 0, {{F, F, F, F, E, E, E, E}});
  L.children(1, 0, 3, 0, {{F, F, F, F, E, E, E, E}});

  const PD::Hierarchical_prior prior = PD::fuse_flow_freeze(L.grids);
  const auto& fine = L.grids[2];
  auto block = [&](int l, int i, int j, int k, VC cls, int res) {
    const int s = 2 - l;
    for(int z = k << s; z < (k + 1) << s; ++z)
      for(int y = j << s; y < (j + 1) << s; ++y)
        for(int x = i << s; x < (i + 1) << s; ++x)
        {
          INFO("level " << l << " cell " << i << j << k << " voxel " << x << y << z);
          if(fine(x, y, z) == E)
          {
            CHECK(prior.classes(x, y, z) == E);
            CHECK(prior.leaf_resolution(x, y, z) == 0);
          }
          else
          {
            CHECK(prior.classes(x, y, z) == (cls == E ? fine(x, y, z) : cls));
            CHECK(prior.leaf_resolution(x, y, z) == res);
          }
        }
  };
  // A: forced split; (1,0,0) split at 8 (own classes), the others leaves at 4 carrying Freeze.
  block(1, 1, 0, 0, E, 8);
  block(1, 0, 0, 0, Z, 4);
  block(1, 0, 1, 0, Z, 4);
  block(1, 1, 1, 0, Z, 4); // Flow at 4 but inherits A's Freeze
  // B: one Flow leaf at 2.
  block(0, 1, 0, 0, F, 2);
  // C: (0,2,0) split at 8; (1,2,0) and (0,3,0) Flow leaves at 4.
  block(1, 0, 2, 0, E, 8);
  block(1, 1, 2, 0, F, 4);
  block(1, 0, 3, 0, F, 4);

  CHECK(prior.number_of_flow_leaves == std::vector<std::size_t>({1, 2, 3 + 3}));
  CHECK(prior.number_of_freeze_leaves == std::vector<std::size_t>({0, 3, 1 + 1}));
}

TEST_CASE("fusion of a single level is the identity", "[fusion]")
{
  PD::Voxel_grid<VC> g(4, E);
  g(0, 0, 0) = F;
  g(3, 2, 1) = Z;
  g(1, 1, 1) = F;
  const PD::Hierarchical_prior prior = PD::fuse_flow_freeze({g});
  CHECK(prior.classes == g);
  CHECK(prior.leaf_resolution(3, 2, 1) == 4);
  CHECK(prior.leaf_resolution(2, 2, 2) == 0);
  CHECK(prior.number_of_flow_leaves == std::vector<std::size_t>({2}));
  CHECK(prior.number_of_freeze_leaves == std::vector<std::size_t>({1}));
  CHECK_THROWS_AS(PD::fuse_flow_freeze({}), PD::Invalid_input);
  CHECK_THROWS_AS(PD::fuse_flow_freeze({PD::Voxel_grid<VC>(4), PD::Voxel_grid<VC>(16)}), PD::Invalid_input);
  CHECK_THROWS_AS(PD::fuse_flow_freeze({PD::Voxel_grid<VC>(3), PD::Voxel_grid<VC>(6)}), PD::Invalid_input);
}

// ---------------------------------------------------------------------------------------------
// The whole prior

namespace {

// The shipped dumbbell: one closed surface whose bells are welded to its bar, so that the
// junctions are concave (the three boxes of make_dumbbell() are convex pieces).
Mesh welded_dumbbell()
{
  Mesh m;
  test_shapes::read_shipped_shape("dumbbell", m);
  return m;
}

// Per face of `m`, the class of the finest voxel that holds its centroid.
std::vector<VC> face_classes(const Mesh& m, const PD::Hierarchical_prior& prior)
{
  std::vector<VC> result;
  for(auto f : faces(m))
  {
    const auto h = halfedge(f, m);
    const Point c = CGAL::centroid(m.point(source(h, m)), m.point(target(h, m)), m.point(target(next(h, m), m)));
    const auto u = prior.normalization.to_unit(c.x(), c.y(), c.z());
    const auto g = prior.classes.locate(u[0], u[1], u[2]);
    result.push_back(prior.classes(g[0], g[1], g[2]));
  }
  return result;
}

} // namespace

TEST_CASE("the prior of a dumbbell freezes its junctions, not its bar", "[prior]")
{
  // The shipped dumbbell: one closed surface, two bells (parts 0 and 2) welded to a bar (part 1).
  Mesh m;
  const std::vector<std::size_t> truth = test_shapes::read_shipped_shape("dumbbell", m);
  const PD::Hierarchical_prior prior = PD::compute_flow_freeze_prior(m);
  REQUIRE(prior.resolutions == std::vector<int>({16, 32, 64}));
  REQUIRE(prior.fields.size() == 3);
  for(const auto& f : prior.fields)
  {
    // The voxels at or above the threshold with a positive score are Freeze: within one voxel of
    // alpha * active (up to the voxels tied at the threshold), fewer if fewer have any evidence.
    std::size_t above = 0, tied = 0;
    for(std::size_t v = 0; v < f.score.size(); ++v)
      if(f.sample_count[v] > 0 && f.score[v] > 0.)
      {
        above += f.score[v] > f.threshold;
        tied += f.score[v] == f.threshold;
      }
    const double target = 0.15 * double(f.number_of_active_voxels);
    CHECK(double(above) <= target + 1.);
    if(f.threshold > 0.) CHECK(double(above + tied) >= target - 1.);
    CHECK(f.number_of_freeze_voxels == above + tied);
    CHECK(f.number_of_freeze_voxels > 0u);
  }
  // Every finest voxel with support has a class and a leaf resolution; the others none.
  for(std::size_t v = 0; v < prior.classes.size(); ++v)
  {
    const bool support = prior.fields[2].sample_count[v] > 0;
    CHECK((prior.classes[v] != VC::EMPTY) == support);
    CHECK((prior.leaf_resolution[v] != 0) == support);
    if(prior.fields[2].classes[v] == VC::FREEZE) CHECK(prior.classes[v] == VC::FREEZE);
  }
  // The faces along a true cut (the concave roots of the bar) are Freeze; most of the bar and of
  // the bells is Flow.
  auto fractions_frozen = [&](const PD::Hierarchical_prior& p) {
    const std::vector<VC> cls = face_classes(m, p);
    std::array<double, 3> frozen{{0., 0., 0.}}, count{{0., 0., 0.}}; // bells, bar, cut
    for(auto f : faces(m))
    {
      bool on_cut = false;
      for(auto h : halfedges_around_face(halfedge(f, m), m)) on_cut = on_cut || truth[face(opposite(h, m), m)] != truth[f];
      const std::size_t group = on_cut ? 2 : truth[f] == 1 ? 1 : 0;
      count[group] += 1.;
      frozen[group] += cls[std::size_t(f)] == VC::FREEZE ? 1. : 0.;
    }
    for(std::size_t g = 0; g < 3; ++g) frozen[g] /= count[g];
    return frozen;
  };
  const std::array<double, 3> frozen = fractions_frozen(prior);
  CHECK(frozen[2] >= 0.9);
  CHECK(frozen[1] <= 0.2);
  CHECK(frozen[0] <= 0.1);
  // With the paper's cues (|H| at every vertex, the normal deviation), the thin bar's convex
  // curvature freezes it end to end, and no primitive would be seeded in it.
  const std::array<double, 3> paper = fractions_frozen(PD::compute_flow_freeze_prior(
    m, PD::parameters::combine(switches(&Variant::use_concave_curvature, false),
                                 PD::parameters::cue_weights(std::array<double, 4>{{1., 1., 1., 1.}}))));
  CHECK(paper[1] >= 0.8);
}

TEST_CASE("the prior is the same with any number of threads and validates its parameters", "[prior]")
{
  const Mesh m = make_dumbbell();
  const PD::Hierarchical_prior a = PD::compute_flow_freeze_prior<CGAL::Sequential_tag>(m);
#ifdef CGAL_LINKED_WITH_TBB
  const PD::Hierarchical_prior b = PD::compute_flow_freeze_prior<CGAL::Parallel_tag>(m);
  CHECK(a.classes == b.classes);
  CHECK(a.leaf_resolution == b.leaf_resolution);
  for(std::size_t l = 0; l < a.fields.size(); ++l)
  {
    CHECK(a.fields[l].score == b.fields[l].score);
    CHECK(a.fields[l].threshold == b.fields[l].threshold);
  }
  const Face_cues ca = face_cues<CGAL::Sequential_tag>(m), cb = face_cues<CGAL::Parallel_tag>(m);
  CHECK(ca.c == cb.c);
  CHECK(ca.phi == cb.phi);
#endif
  CHECK(a.number_of_flow_leaves.size() == 3);
  const PD::Hierarchical_prior c = PD::compute_flow_freeze_prior(
    m, PD::parameters::voxel_resolutions(std::vector<int>{32}));
  CHECK(c.classes == c.fields[0].classes);
  using PD::parameters::voxel_resolutions;
  CHECK_THROWS_AS(PD::compute_flow_freeze_prior(m, voxel_resolutions(std::vector<int>{})), PD::Invalid_input);
  CHECK_THROWS_AS(PD::compute_flow_freeze_prior(m, voxel_resolutions(std::vector<int>{16, 48})), PD::Invalid_input);
  CHECK_THROWS_AS(PD::compute_flow_freeze_prior(m, voxel_resolutions(std::vector<int>{16, 64})), PD::Invalid_input);
  CHECK_THROWS_AS(PD::compute_flow_freeze_prior(m, voxel_resolutions(std::vector<int>{256, 512})), PD::Invalid_input);
  CHECK_THROWS_AS(PD::compute_flow_freeze_prior(m, PD::parameters::freeze_ratio(0.)), PD::Invalid_input);
  CHECK_THROWS_AS(PD::compute_flow_freeze_prior(m, PD::parameters::freeze_ratio(1.)), PD::Invalid_input);
  CHECK_THROWS_AS(PD::compute_flow_freeze_prior(m, CGAL::parameters::number_of_points_per_face(35)), PD::Invalid_input);
  CHECK_THROWS_AS(PD::compute_flow_freeze_prior(m, PD::parameters::number_of_neighbors(0)), PD::Invalid_input);
  CHECK_THROWS_AS(PD::compute_flow_freeze_prior(m, PD::parameters::curvature_percentile(101.)), PD::Invalid_input);
  CHECK_THROWS_AS(PD::compute_flow_freeze_prior(m, PD::parameters::cue_weights(std::vector<double>{1, 1, 1})),
                  PD::Invalid_input);
}

// ----------------------------------------------------------------- one parameter layer

namespace {

// Every default of the cues, the score and the prior, given explicitly.
auto explicit_defaults()
{
  return PD::parameters::combine(
    CGAL::parameters::number_of_points_per_face(PD::defaults::number_of_points_per_face),
    PD::parameters::voxel_resolutions(PD::defaults::voxel_resolutions),
    PD::parameters::number_of_neighbors(PD::defaults::number_of_neighbors),
    PD::parameters::curvature_percentile(PD::defaults::curvature_percentile),
    PD::parameters::cue_weights(PD::defaults::cue_weights), PD::parameters::freeze_ratio(PD::defaults::freeze_ratio),
    PD::parameters::normalization_margin(PD::defaults::normalization_margin));
}

bool same_field(const PD::Topology_score_field& a, const PD::Topology_score_field& b)
{
  return a.resolution == b.resolution && a.sample_count == b.sample_count && a.curvature_mean == b.curvature_mean &&
         a.curvature_deviation == b.curvature_deviation && a.curvature_gradient == b.curvature_gradient &&
         a.normal_deviation == b.normal_deviation && a.score == b.score && a.classes == b.classes &&
         a.threshold == b.threshold && a.number_of_active_voxels == b.number_of_active_voxels &&
         a.number_of_freeze_voxels == b.number_of_freeze_voxels;
}

} // namespace

TEST_CASE("cues, score and prior: the defaults equal every default given explicitly", "[parameters]")
{
  const Mesh m = make_dumbbell();
  const Face_cues a = face_cues(m);
  Face_cues b;
  b.c.assign(num_faces(m), -1.);
  b.phi.assign(num_faces(m), -1.);
  PD::compute_geometric_cues(m, CGAL::make_property_map(b.c), CGAL::make_property_map(b.phi), explicit_defaults());
  CHECK(a.c == b.c);
  CHECK(a.phi == b.phi);
  std::vector<double> c1(num_faces(m)), c2(num_faces(m)), p1(num_faces(m)), p2(num_faces(m));
  PD::compute_face_curvature_cue(m, CGAL::make_property_map(c1));
  PD::compute_face_curvature_cue(m, CGAL::make_property_map(c2), explicit_defaults());
  PD::compute_face_normal_deviation(m, CGAL::make_property_map(p1));
  PD::compute_face_normal_deviation(m, CGAL::make_property_map(p2), explicit_defaults());
  CHECK((c1 == c2 && c1 == a.c));
  CHECK((p1 == p2 && p1 == a.phi));

  CHECK(PD::compute_normalization(m).scale() == PD::compute_normalization(m, explicit_defaults()).scale());
  CHECK(PD::compute_normalization(m).center() == PD::compute_normalization(m, explicit_defaults()).center());

  const auto cmap = CGAL::make_property_map(a.c);
  const auto pmap = CGAL::make_property_map(a.phi);
  CHECK(same_field(PD::compute_topology_score(m, cmap, pmap, 32),
                   PD::compute_topology_score(m, cmap, pmap, 32, explicit_defaults())));
  CHECK(same_field(PD::compute_topology_score(m, cmap, pmap, 16, 64),
                   PD::compute_topology_score(m, cmap, pmap, 16, 64, explicit_defaults())));

  const PD::Hierarchical_prior x = PD::compute_flow_freeze_prior(m);
  const PD::Hierarchical_prior y = PD::compute_flow_freeze_prior(m, explicit_defaults());
  REQUIRE(x.fields.size() == y.fields.size());
  for(std::size_t l = 0; l < x.fields.size(); ++l) CHECK(same_field(x.fields[l], y.fields[l]));
  CHECK(x.classes == y.classes);
  CHECK(x.leaf_resolution == y.leaf_resolution);
}

TEST_CASE("the prior's field at r is compute_topology_score at r with the samples binned at the finest r",
          "[parameters][score]")
{
  // The 12-triangle cube: its faces are cut relative to the finest grid in the prior, so binning
  // at r itself gives other fields.
  // With lambda_4 = 0 (the default) the prior does not compute the normal deviation: its grids are 0.
  const Mesh cube = test_shapes::make_box(Point(-1, -1, -1), Point(1, 1, 1), 1);
  const Mesh dumbbell = make_dumbbell(), welded = welded_dumbbell();
  for(const Mesh* m : {&cube, &dumbbell, &welded})
  {
    const Face_cues cues = face_cues(*m);
    const std::vector<double> no_phi(cues.phi.size(), 0.);
    const auto cmap = CGAL::make_property_map(cues.c);
    for(const std::array<double, 4> weights : {PD::defaults::cue_weights, std::array<double, 4>{{1., 1., 1., 1.}}})
      for(bool density : {true, false})
      {
        const auto np = PD::parameters::combine(switches(&Variant::use_density, density), PD::parameters::cue_weights(weights));
        const PD::Hierarchical_prior prior = PD::compute_flow_freeze_prior(*m, np);
        REQUIRE(prior.fields.size() == 3);
        const auto pmap = CGAL::make_property_map(weights[3] == 0. ? no_phi : cues.phi);
        for(std::size_t l = 0; l < 3; ++l)
          CHECK(same_field(prior.fields[l], PD::compute_topology_score(*m, cmap, pmap, prior.resolutions[l], 64, np)));
      }
  }
  const Face_cues cues = face_cues(cube);
  const PD::Topology_score_field at_16 = PD::compute_topology_score(
    cube, CGAL::make_property_map(cues.c), CGAL::make_property_map(cues.phi), 16);
  CHECK(!same_field(PD::compute_flow_freeze_prior(cube).fields[0], at_16));
  CHECK(same_field(at_16, PD::compute_topology_score(cube, CGAL::make_property_map(cues.c),
                                                     CGAL::make_property_map(cues.phi), 16, 16)));
  CHECK_THROWS_AS(PD::compute_topology_score(cube, CGAL::make_property_map(cues.c),
                                             CGAL::make_property_map(cues.phi), 32, 16), PD::Invalid_input);
  CHECK_THROWS_AS(PD::compute_topology_score(cube, CGAL::make_property_map(cues.c),
                                             CGAL::make_property_map(cues.phi), 16, 48), PD::Invalid_input);
}

TEST_CASE("use_density(false) drops the density factor sqrt(n) of every active voxel", "[parameters][score]")
{
  const Mesh m = welded_dumbbell();
  const Face_cues cues = face_cues(m);
  const auto cmap = CGAL::make_property_map(cues.c);
  const auto pmap = CGAL::make_property_map(cues.phi);
  for(int r : {8, 32})
  {
    const PD::Topology_score_field with = PD::compute_topology_score(m, cmap, pmap, r);
    const PD::Topology_score_field without =
      PD::compute_topology_score(m, cmap, pmap, r, switches(&Variant::use_density, false));
    REQUIRE(with.sample_count == without.sample_count);
    std::size_t checked = 0, positive = 0, wrong = 0;
    for(std::size_t v = 0; v < with.score.size(); ++v)
    {
      if(with.sample_count[v] == 0)
      {
        wrong += without.score[v] == 0. ? 0 : 1;
        continue;
      }
      // equal up to the rounding of the product and the quotient
      const double expected = with.score[v] / std::sqrt(double(with.sample_count[v]));
      wrong += std::abs(without.score[v] - expected) <= 1e-12 * std::abs(expected) ? 0 : 1;
      ++checked;
      positive += without.score[v] > 0. ? 1 : 0;
    }
    CHECK(wrong == 0u);
    CHECK(checked == with.number_of_active_voxels);
    CHECK(positive > 0u);
  }
  // the prior passes it on
  const PD::Hierarchical_prior p = PD::compute_flow_freeze_prior(m, switches(&Variant::use_density, false));
  const PD::Hierarchical_prior q = PD::compute_flow_freeze_prior(m);
  const std::size_t v = std::size_t(std::max_element(q.fields[2].sample_count.values().begin(),
                                                     q.fields[2].sample_count.values().end()) -
                                    q.fields[2].sample_count.values().begin());
  CHECK(p.fields[2].score[v] == Approx(q.fields[2].score[v] / std::sqrt(double(q.fields[2].sample_count[v]))));
}
