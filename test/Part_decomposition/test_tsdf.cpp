// Tests of the adaptive grid, the distances and signs of its leaves, the TSDF on its leaves and
// the fitter's zones, against analytic shapes, hand-made grids and brute-force references.
#include <catch2/catch.hpp>

#include "method_switches.h"
#include "test_shapes.h"

#include <CGAL/Part_decomposition/Adaptive_grid.h>
#include <CGAL/Part_decomposition/fitting_zones.h>
#include <CGAL/Part_decomposition/flow_freeze_prior.h>
#include <CGAL/Part_decomposition/internal/grid/adaptive_grid_builder.h>
#include <CGAL/Part_decomposition/internal/grid/leaf_distance.h>
#include <CGAL/Part_decomposition/internal/grid/leaf_signs.h>
#include <CGAL/Part_decomposition/internal/grid/mesh_voxelization.h>
#include <CGAL/Part_decomposition/internal/grid/triangle_distance.h>
#include <CGAL/Part_decomposition/internal/grid/triangle_soup_aabb_tree.h>
#include <CGAL/Part_decomposition/internal/grid/winding_number.h>
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
#include <numeric>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

namespace PD = CGAL::Part_decomposition;
namespace PDI = CGAL::Part_decomposition::internal;
using test_shapes::K;
using test_shapes::Mesh;
using test_shapes::Point;
typedef PD::Adaptive_grid Grid;
typedef std::vector<std::uint8_t> Flags;

namespace {

const double k_inf = std::numeric_limits<double>::infinity();

Grid::Cell cell(int d, std::uint32_t i, std::uint32_t j, std::uint32_t k) { return Grid::Cell{d, {{i, j, k}}}; }

// The faces of `m` whose centroid lies at or below height `z`: a closed mesh with its cap cut off.
Mesh without_cap(const Mesh& m, double z)
{
  test_shapes::Soup soup;
  for(auto f : faces(m))
  {
    std::array<Point, 3> c;
    int k = 0;
    for(auto v : vertices_around_face(halfedge(f, m), m)) c[std::size_t(k++)] = m.point(v);
    if((c[0].z() + c[1].z() + c[2].z()) / 3. <= z) soup.triangle(c[0], c[1], c[2]);
  }
  return soup.mesh();
}

// The 8^d cells of depth d.
std::vector<Grid::Cell> cells_of_depth(int d)
{
  std::vector<Grid::Cell> cells;
  const std::uint32_t r = 1u << d;
  for(std::uint32_t k = 0; k < r; ++k)
    for(std::uint32_t j = 0; j < r; ++j)
      for(std::uint32_t i = 0; i < r; ++i) cells.push_back(cell(d, i, j, k));
  return cells;
}

// A grid of finest resolution 2^D whose cells below `min_depth` are split and the others with
// probability `split`, handed to the constructor in a shuffled order.
Grid random_grid(int D, double split, CGAL::Random& rng, int min_depth = 1)
{
  std::vector<Grid::Cell> cells, stack(1, cell(0, 0, 0, 0));
  while(!stack.empty())
  {
    const Grid::Cell c = stack.back();
    stack.pop_back();
    if(c.depth < D && (c.depth < min_depth || rng.get_double() < split))
    {
      for(std::uint32_t s = 0; s < 8; ++s)
        stack.push_back(cell(c.depth + 1, 2 * c.position[0] + (s & 1), 2 * c.position[1] + ((s >> 1) & 1),
                             2 * c.position[2] + ((s >> 2) & 1)));
      continue;
    }
    cells.push_back(c);
  }
  for(std::size_t i = cells.size(); i > 1; --i) std::swap(cells[i - 1], cells[std::size_t(rng.get_int(0, int(i)))]);
  return Grid(1 << D, cells);
}

// Whether leaf b shares a piece of face of positive area with leaf a, from their boxes; `direction`
// receives the side of a it lies on (0: -x, 1: +x, ..., 5: +z).
bool face_neighbors(const Grid& g, std::size_t a, std::size_t b, int* direction = nullptr)
{
  const Grid::Voxel &ca = g.corner(a), &cb = g.corner(b);
  const std::uint32_t wa = g.width(a), wb = g.width(b);
  int touching = 0, overlapping = 0, side = -1;
  for(int x = 0; x < 3; ++x)
  {
    if(ca[x] + wa == cb[x]) ++touching, side = 2 * x + 1;
    else if(cb[x] + wb == ca[x]) ++touching, side = 2 * x;
    else if(std::max(ca[x], cb[x]) < std::min(ca[x] + wa, cb[x] + wb)) ++overlapping;
  }
  if(direction) *direction = side;
  return touching == 1 && overlapping == 2;
}

// The brute-force face adjacency of all leaves.
std::vector<std::vector<std::size_t> > brute_force_neighbors(const Grid& g)
{
  std::vector<std::vector<std::size_t> > out(g.number_of_leaves());
  for(std::size_t a = 0; a < g.number_of_leaves(); ++a)
    for(std::size_t b = 0; b < g.number_of_leaves(); ++b)
      if(a != b && face_neighbors(g, a, b)) out[a].push_back(b);
  return out;
}

double squared_distance(const std::array<double, 3>& p, const std::array<double, 3>& q)
{
  return (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]);
}

// The squared distance from p to the nearest centre of `features`, and with `border` to the
// centres of the finest voxels just outside the cube.
double brute_force_squared_distance(const Grid& g, const std::array<double, 3>& p,
                                    const std::vector<std::size_t>& features, bool border)
{
  double best = k_inf;
  for(std::size_t f : features) best = std::min(best, squared_distance(p, g.center(f)));
  if(border)
  {
    const double h = 0.5 / g.finest_resolution();
    for(int a = 0; a < 3; ++a)
      best = std::min({best, (p[a] + 0.5 + h) * (p[a] + 0.5 + h), (0.5 - p[a] + h) * (0.5 - p[a] + h)});
  }
  return best;
}

// The centre of the finest voxel in the middle of leaf l, where its sign is decided.
std::array<double, 3> sign_point_of(const Grid& g, std::size_t l)
{
  const double h = 1. / g.finest_resolution();
  std::array<double, 3> p;
  for(int a = 0; a < 3; ++a) p[a] = -0.5 + (double(g.corner(l)[a] + g.width(l) / 2) + 0.5) * h;
  return p;
}

CGAL::Bbox_3 leaf_box(const Grid& g, std::size_t l, double grow = 0.)
{
  const double h = 1. / g.finest_resolution(), s = g.size(l);
  const Grid::Voxel& c = g.corner(l);
  const double x = -0.5 + c[0] * h, y = -0.5 + c[1] * h, z = -0.5 + c[2] * h;
  return CGAL::Bbox_3(x - grow, y - grow, z - grow, x + s + grow, y + s + grow, z + s + grow);
}

double half_diagonal(const Grid& g, std::size_t l) { return 0.5 * std::sqrt(3.) * g.size(l); }

double unsigned_distance(const std::vector<PDI::Triangle_points>& tris, const PDI::Vec3& p)
{
  double d2 = k_inf;
  for(const auto& t : tris) d2 = std::min(d2, PDI::squared_distance_to_triangle(p, t[0], t[1], t[2]));
  return std::sqrt(d2);
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

// The centroid of the first face of m (the hole of without_first_face(m)).
std::array<double, 3> first_face_centroid(const Mesh& m)
{
  std::array<double, 3> c = {{0., 0., 0.}};
  for(auto v : vertices_around_face(halfedge(*faces(m).begin(), m), m))
    for(int a = 0; a < 3; ++a) c[a] += CGAL::to_double(m.point(v)[a]) / 3.;
  return c;
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

// Checks the sign of every leaf whose analytic signed distance (normalized units) at its sign
// point exceeds `margin` in magnitude and which `where` accepts there; returns the volume of the
// leaves checked.
double check_signs(const PD::Truncated_signed_distance_field& tsdf,
                   const std::function<double(const std::array<double, 3>&)>& sd, double margin,
                   const std::function<bool(const std::array<double, 3>&)>& where = nullptr)
{
  REQUIRE(tsdf.values.size() == tsdf.grid.number_of_leaves());
  std::size_t wrong = 0;
  double checked = 0.;
  for(std::size_t l = 0; l < tsdf.values.size(); ++l)
  {
    const std::array<double, 3> p = sign_point_of(tsdf.grid, l);
    const double s = sd(p);
    if(std::abs(s) <= margin || (where && !where(p))) continue;
    checked += tsdf.grid.volume(l);
    if((s < 0.) != (tsdf.values[l] < 0.))
    {
      if(wrong < 5)
        WARN("wrong sign at leaf " << l << " of width " << tsdf.grid.width(l) << ": exact " << s / tsdf.voxel_size
             << " voxels, got " << tsdf.values[l] / tsdf.voxel_size << " (method " << int(tsdf.sign_method) << ")");
      ++wrong;
    }
  }
  CHECK(wrong == 0);
  return checked;
}

// Checks ||tsdf| - min(|sd|, tau)| <= tolerance at every leaf centre (the magnitude is the
// distance of the centre, the sign that of the sign point); returns the largest error.
double check_values(const PD::Truncated_signed_distance_field& tsdf,
                    const std::function<double(const std::array<double, 3>&)>& sd, double tolerance)
{
  REQUIRE(tsdf.values.size() == tsdf.grid.number_of_leaves());
  double worst = 0.;
  for(std::size_t l = 0; l < tsdf.values.size(); ++l)
  {
    const double s = std::min(tsdf.truncation, std::abs(sd(tsdf.grid.center(l))));
    worst = std::max(worst, std::abs(std::abs(tsdf.values[l]) - s));
    CHECK(std::abs(tsdf.values[l]) <= tsdf.truncation);
  }
  CHECK(worst <= tolerance);
  return worst;
}

// The leaf that holds the point p of the normalized cube, and its value.
double value_at(const PD::Truncated_signed_distance_field& tsdf, const std::array<double, 3>& p)
{
  return tsdf.values[tsdf.grid.locate(p[0], p[1], p[2])];
}

double inside_volume(const PD::Truncated_signed_distance_field& tsdf)
{
  double v = 0.;
  for(std::size_t l = 0; l < tsdf.values.size(); ++l)
    if(tsdf.values[l] < 0.) v += tsdf.grid.volume(l);
  return v;
}

} // namespace

// --------------------------------------------------------------------------------- adaptive grid

TEST_CASE("Adaptive_grid: cells that do not tile the cube are refused", "[tsdf][grid]")
{
  typedef std::vector<Grid::Cell> Cells;
  auto refused = [](int r, const Cells& cells) {
    try
    {
      Grid g(r, cells);
    }
    catch(const std::invalid_argument&)
    {
      return true;
    }
    return false;
  };
  const Cells octants = cells_of_depth(1);
  CHECK(!refused(4, octants));
  CHECK(!refused(1, Cells{cell(0, 0, 0, 0)}));
  CHECK(!refused(2, octants));
  CHECK(refused(4, Cells{}));
  Cells missing = octants;
  missing.pop_back();
  CHECK(refused(4, missing));
  Cells twice = octants;
  twice.push_back(octants[3]);
  CHECK(refused(4, twice));
  Cells child_on_top = octants; // a child of octant 0 over it
  child_on_top.push_back(cell(2, 1, 0, 1));
  CHECK(refused(4, child_on_top));
  // the volume of the cube, an overlap and a gap: octant 7 replaced by the children of octant 0
  Cells moved(octants.begin(), octants.end() - 1);
  for(std::uint32_t s = 0; s < 8; ++s) moved.push_back(cell(2, s & 1, (s >> 1) & 1, (s >> 2) & 1));
  CHECK(refused(4, moved));
  Cells outside = octants;
  outside.back() = cell(1, 2, 1, 1);
  CHECK(refused(4, outside));
  CHECK(refused(2, cells_of_depth(2))); // deeper than the finest resolution
  CHECK(refused(4, Cells{cell(-1, 0, 0, 0)}));
  CHECK(refused(3, Cells{cell(0, 0, 0, 0)}));
  CHECK(refused(0, Cells{cell(0, 0, 0, 0)}));
  CHECK(refused(2048, Cells{cell(0, 0, 0, 0)}));
  CHECK_THROWS_AS(Grid::uniform(6), std::invalid_argument);
  CHECK_THROWS_AS(Grid::uniform(0), std::invalid_argument);
}

TEST_CASE("Adaptive_grid: a uniform grid is numbered like Voxel_grid, with its six neighbours in order", "[tsdf][grid]")
{
  for(int r : {1, 2, 4, 8})
  {
    const Grid g = Grid::uniform(r);
    const PD::Voxel_grid<int> v(r);
    REQUIRE(g.number_of_leaves() == v.size());
    CHECK(g.finest_resolution() == r);
    CHECK(g.number_of_leaves_of_depth(Grid::depth_of(r)) == v.size());
    CHECK(Grid::depth_of(r) == int(std::log2(r)));
    for(std::size_t l = 0; l < g.number_of_leaves(); ++l)
    {
      const std::array<int, 3> c = v.coordinates(l);
      CHECK(g.corner(l) == Grid::Voxel{{std::uint32_t(c[0]), std::uint32_t(c[1]), std::uint32_t(c[2])}});
      CHECK(g.center(l) == v.center(l));
      CHECK(g.width(l) == 1u);
      CHECK(g.resolution(l) == r);
      CHECK(g.size(l) == 1. / r);
      CHECK(g.leaf_of_voxel(std::uint32_t(c[0]), std::uint32_t(c[1]), std::uint32_t(c[2])) == l);
      // -x, +x, -y, +y, -z, +z, those inside the grid
      std::vector<std::size_t> expected;
      for(int a = 0; a < 3; ++a)
        for(int s : {-1, 1})
        {
          std::array<int, 3> n = c;
          n[std::size_t(a)] += s;
          if(v.contains(n[0], n[1], n[2])) expected.push_back(v.index(n[0], n[1], n[2]));
        }
      CHECK(std::vector<std::size_t>(g.neighbors_begin(l), g.neighbors_end(l)) == expected);
      CHECK(g.number_of_neighbors(l) == expected.size());
    }
  }
  CHECK(Grid::uniform(4) == Grid(4, cells_of_depth(2)));
  CHECK(Grid::uniform(4) != Grid(8, cells_of_depth(2)));
}

TEST_CASE("Adaptive_grid: numbering, neighbours, location and volume match a brute force on random grids", "[tsdf][grid]")
{
  CGAL::Random rng(23);
  for(int trial = 0; trial < 8; ++trial)
  {
    const int D = 2 + trial % 3, R = 1 << D;
    const Grid g = random_grid(D, 0.3 + 0.05 * trial, rng);
    const std::size_t n = g.number_of_leaves();
    REQUIRE(g.finest_resolution() == R);
    INFO("trial " << trial << ", " << n << " leaves");
    // numbered by smallest corner, z first; geometry of each leaf
    double volume = 0.;
    std::vector<std::size_t> per_depth(std::size_t(D) + 1, 0);
    for(std::size_t l = 0; l < n; ++l)
    {
      const Grid::Voxel& c = g.corner(l);
      if(l > 0)
      {
        const Grid::Voxel& p = g.corner(l - 1);
        CHECK(std::make_tuple(p[2], p[1], p[0]) < std::make_tuple(c[2], c[1], c[0]));
      }
      CHECK(g.resolution(l) == 1 << g.depth(l));
      CHECK(g.width(l) == std::uint32_t(R / g.resolution(l)));
      for(int a = 0; a < 3; ++a)
      {
        CHECK(c[a] % g.width(l) == 0u);
        CHECK(g.center(l)[a] == -0.5 + (c[a] + 0.5 * g.width(l)) / R);
      }
      volume += g.volume(l);
      ++per_depth[std::size_t(g.depth(l))];
      // the centre locates its leaf
      CHECK(g.locate(g.center(l)[0], g.center(l)[1], g.center(l)[2]) == l);
    }
    CHECK(volume == 1.);
    for(int d = 0; d <= D; ++d) CHECK(g.number_of_leaves_of_depth(d) == per_depth[std::size_t(d)]);
    // every finest voxel lies in the leaf leaf_of_voxel() gives
    for(std::uint32_t k = 0; k < std::uint32_t(R); ++k)
      for(std::uint32_t j = 0; j < std::uint32_t(R); ++j)
        for(std::uint32_t i = 0; i < std::uint32_t(R); ++i)
        {
          const std::size_t l = g.leaf_of_voxel(i, j, k);
          const Grid::Voxel& c = g.corner(l);
          const std::uint32_t w = g.width(l);
          CHECK((i >= c[0] && i < c[0] + w && j >= c[1] && j < c[1] + w && k >= c[2] && k < c[2] + w));
        }
    // neighbours: the leaves sharing a piece of face, in the order of the faces, symmetric
    const std::vector<std::vector<std::size_t> > brute = brute_force_neighbors(g);
    for(std::size_t l = 0; l < n; ++l)
    {
      std::vector<std::size_t> got(g.neighbors_begin(l), g.neighbors_end(l));
      int previous = -1;
      for(std::size_t m : got)
      {
        int direction = -1;
        CHECK(face_neighbors(g, l, m, &direction));
        CHECK(direction >= previous);
        previous = direction;
        CHECK(std::count(g.neighbors_begin(m), g.neighbors_end(m), std::uint32_t(l)) == 1);
      }
      std::vector<std::size_t> visited;
      g.for_each_neighbor(l, [&](std::size_t m) { visited.push_back(m); });
      CHECK(visited == got);
      std::sort(got.begin(), got.end());
      CHECK(got == brute[l]);
    }
    // points: the leaf whose box holds them; outside the cube, clamped
    for(int s = 0; s < 200; ++s)
    {
      const std::array<double, 3> p = {{rng.get_double(-0.7, 0.7), rng.get_double(-0.7, 0.7), rng.get_double(-0.7, 0.7)}};
      const std::size_t l = g.locate(p[0], p[1], p[2]);
      const CGAL::Bbox_3 b = leaf_box(g, l);
      for(int a = 0; a < 3; ++a)
      {
        const double q = std::min(std::max(p[a], -0.5), 0.5);
        CHECK((q >= b.min(a) && q <= b.max(a)));
      }
    }
  }
}

TEST_CASE("Adaptive_grid: the box queries give each leaf meeting the box once, by brute force", "[tsdf][grid]")
{
  CGAL::Random rng(29);
  for(int trial = 0; trial < 6; ++trial)
  {
    const int D = 3 + trial % 2, R = 1 << D;
    const Grid g = random_grid(D, 0.4, rng);
    for(int s = 0; s < 150; ++s)
    {
      // boxes of the normalized cube, some beyond it (clamped), some empty
      std::array<double, 3> lo, hi;
      for(int a = 0; a < 3; ++a)
      {
        lo[a] = rng.get_double(-0.7, 0.6);
        hi[a] = lo[a] + rng.get_double(s % 10 == 0 ? -0.1 : 0., 0.5);
      }
      std::vector<std::size_t> got;
      g.for_each_leaf_in_box(lo, hi, [&](std::size_t l) { got.push_back(l); });
      std::vector<std::size_t> expected;
      const bool empty = lo[0] > hi[0] || lo[1] > hi[1] || lo[2] > hi[2];
      for(std::size_t l = 0; l < g.number_of_leaves() && !empty; ++l)
      {
        const CGAL::Bbox_3 b = leaf_box(g, l);
        bool meets = true;
        for(int a = 0; a < 3; ++a)
        {
          const double l0 = std::min(std::max(lo[a], -0.5), 0.5), h0 = std::min(std::max(hi[a], -0.5), 0.5);
          meets = meets && b.min(a) <= h0 && l0 <= b.max(a);
        }
        if(meets) expected.push_back(l);
      }
      std::sort(got.begin(), got.end());
      CHECK(std::adjacent_find(got.begin(), got.end()) == got.end());
      CHECK(got == expected);
    }
    // boxes in finest voxels, inclusive, clamped to the grid
    for(int s = 0; s < 150; ++s)
    {
      Grid::Voxel lo, hi;
      for(int a = 0; a < 3; ++a)
      {
        lo[a] = std::uint32_t(rng.get_int(0, R + 2));
        hi[a] = std::uint32_t(rng.get_int(0, R + 2));
        if(s % 10 != 0 && lo[a] > hi[a]) std::swap(lo[a], hi[a]);
      }
      std::vector<std::size_t> got;
      g.for_each_leaf_in_voxel_box(lo, hi, [&](std::size_t l) { got.push_back(l); });
      std::vector<std::size_t> expected;
      for(std::size_t l = 0; l < g.number_of_leaves(); ++l)
      {
        bool meets = true;
        for(int a = 0; a < 3; ++a)
        {
          const std::uint32_t top = std::uint32_t(R - 1), a0 = std::min(lo[a], top), b0 = std::min(hi[a], top);
          meets = meets && a0 <= b0 && g.corner(l)[a] <= b0 && a0 < g.corner(l)[a] + g.width(l);
        }
        if(meets) expected.push_back(l);
      }
      std::sort(got.begin(), got.end());
      CHECK(std::adjacent_find(got.begin(), got.end()) == got.end());
      CHECK(got == expected);
    }
  }
}

// ------------------------------------------------------------------------- distances of leaves

TEST_CASE("Leaf distances on a uniform grid equal a brute force over voxel centres", "[tsdf][leaf_distance]")
{
  CGAL::Random rng(7);
  for(int r : {1, 2, 4, 8, 16})
  {
    const Grid g = Grid::uniform(r);
    for(double density : {0., 0.02, 0.2, 0.7, 1.})
      for(bool border : {false, true})
      {
        Flags feature(g.number_of_leaves(), 0);
        std::vector<std::size_t> features;
        for(std::size_t l = 0; l < feature.size(); ++l)
          if(rng.get_double() < density) feature[l] = 1, features.push_back(l);
        auto is_feature = [&](std::size_t l) { return feature[l] != 0; };
        const std::vector<double> d2 =
          PDI::leaf_squared_distances<CGAL::Sequential_tag>(g, is_feature, [](std::size_t) { return true; }, border);
        std::vector<double> expected(g.number_of_leaves());
        for(std::size_t l = 0; l < expected.size(); ++l)
          expected[l] = feature[l] ? 0. : brute_force_squared_distance(g, g.center(l), features, border);
        REQUIRE(d2 == expected);
        CHECK(PDI::leaf_squared_distances<CGAL::Parallel_if_available_tag>(g, is_feature, [](std::size_t) { return true; },
                                                                           border) == expected);
        // only the wanted leaves are measured
        const std::vector<double> odd = PDI::leaf_squared_distances<CGAL::Sequential_tag>(
          g, is_feature, [](std::size_t l) { return l % 2 == 1; }, border);
        for(std::size_t l = 0; l < odd.size(); ++l) CHECK(odd[l] == (feature[l] || l % 2 == 1 ? expected[l] : k_inf));
        // the nearest feature is a feature at that distance, or the border layer
        // only the features with a face neighbour outside the set or on the cube's border are kept
        std::size_t boundary = 0;
        for(std::size_t l : features)
        {
          const auto o = g.corner(l);
          bool next_to_outside = false;
          for(int a = 0; a < 3; ++a) next_to_outside = next_to_outside || o[a] == 0 || int(o[a]) + 1 == r;
          g.for_each_neighbor(l, [&](std::size_t m) { next_to_outside = next_to_outside || !feature[m]; });
          boundary += next_to_outside ? 1 : 0;
        }
        PDI::Leaf_feature_search<Grid> search;
        search.build<CGAL::Sequential_tag>(g, is_feature, border);
        CHECK(search.size() == boundary);
        CHECK(search.empty() == (boundary == 0 && !border));
        for(std::size_t l = 0; l < g.number_of_leaves(); ++l)
        {
          if(feature[l]) continue;
          const std::pair<std::size_t, double> nn = search.nearest(g.center(l));
          CHECK(nn.second == expected[l]);
          if(nn.first == PDI::Leaf_feature_search<Grid>::no_leaf) CHECK((border || features.empty()));
          else
          {
            REQUIRE(nn.first < feature.size());
            CHECK(feature[nn.first] == 1);
            CHECK(squared_distance(g.center(l), g.center(nn.first)) == nn.second);
          }
          CHECK(search.squared_distance(l) == expected[l]);
        }
      }
  }
  // known answers on the 8^3 grid
  const Grid g = Grid::uniform(8);
  const std::size_t one = g.leaf_of_voxel(1, 2, 3), far = g.leaf_of_voxel(5, 5, 5);
  auto only = [&](std::size_t l) { return l == one; };
  auto all = [](std::size_t) { return true; };
  CHECK(PDI::leaf_squared_distances<CGAL::Sequential_tag>(g, only, all)[far] == (16. + 9. + 4.) / 64.);
  const std::vector<double> none = PDI::leaf_squared_distances<CGAL::Sequential_tag>(g, [](std::size_t) { return false; }, all);
  CHECK(std::all_of(none.begin(), none.end(), [](double v) { return std::isinf(v); }));
  // the border layer alone: one voxel from the border voxels, four from the middle ones
  const std::vector<double> border =
    PDI::leaf_squared_distances<CGAL::Sequential_tag>(g, [](std::size_t) { return false; }, all, true);
  CHECK(border[g.leaf_of_voxel(0, 4, 4)] == 1. / 64.);
  CHECK(border[g.leaf_of_voxel(3, 4, 4)] == 16. / 64.);
}

TEST_CASE("Leaf distances on an adaptive grid: to the nearest boundary feature, to listed features exactly", "[tsdf][leaf_distance]")
{
  CGAL::Random rng(11);
  for(int trial = 0; trial < 12; ++trial)
  {
    const Grid g = random_grid(3 + trial % 2, 0.45, rng);
    const std::vector<std::vector<std::size_t> > adjacency = brute_force_neighbors(g);
    const double density = 0.05 + 0.1 * (trial % 4);
    const bool border = trial % 3 == 0;
    Flags feature(g.number_of_leaves(), 0);
    for(std::size_t l = 0; l < feature.size(); ++l) feature[l] = rng.get_double() < density ? 1 : 0;
    // the features with a face neighbour outside the set, the only ones searched
    std::vector<std::size_t> features, boundary;
    for(std::size_t l = 0; l < feature.size(); ++l)
    {
      if(!feature[l]) continue;
      features.push_back(l);
      if(std::any_of(adjacency[l].begin(), adjacency[l].end(), [&](std::size_t m) { return !feature[m]; }))
        boundary.push_back(l);
    }
    auto is_feature = [&](std::size_t l) { return feature[l] != 0; };
    const std::vector<double> d2 =
      PDI::leaf_squared_distances<CGAL::Parallel_if_available_tag>(g, is_feature, [](std::size_t) { return true; }, border);
    std::size_t approximate = 0;
    for(std::size_t l = 0; l < g.number_of_leaves(); ++l)
    {
      if(feature[l])
      {
        CHECK(d2[l] == 0.);
        continue;
      }
      CHECK(d2[l] == brute_force_squared_distance(g, g.center(l), boundary, border));
      // never nearer than the nearest feature of all
      const double exact = brute_force_squared_distance(g, g.center(l), features, border);
      CHECK(d2[l] >= exact);
      approximate += d2[l] > exact ? 1 : 0;
    }
    INFO("leaves farther from the boundary features than from all: " << approximate);

    // listed features are all kept: the exact nearest of them
    std::vector<std::size_t> listed;
    for(std::size_t l = 0; l < g.number_of_leaves(); ++l)
      if(rng.get_double() < 0.1) listed.push_back(l);
    PDI::Leaf_feature_search<Grid> search;
    search.build_on<CGAL::Sequential_tag>(g, listed);
    CHECK(search.size() == listed.size());
    for(int s = 0; s < 100; ++s)
    {
      const std::array<double, 3> p = {{rng.get_double(-0.5, 0.5), rng.get_double(-0.5, 0.5), rng.get_double(-0.5, 0.5)}};
      const std::pair<std::size_t, double> nn = search.nearest(p);
      CHECK(nn.second == brute_force_squared_distance(g, p, listed, false));
      if(!listed.empty())
      {
        CHECK(std::count(listed.begin(), listed.end(), nn.first) == 1);
        CHECK(squared_distance(p, g.center(nn.first)) == nn.second);
      }
    }
  }
}

TEST_CASE("Leaf distances on a hand-made adaptive grid: an inner feature nearer than every boundary one is not seen", "[tsdf][leaf_distance]")
{
  // Finest resolution 4: octants of side 2, octants 0 and 7 split into leaves of side 1. The
  // features: octant 0 and the three octants next to it across its +x, +y, +z faces. Leaf (1,1,1)
  // of octant 0 has features all around: only the three big octants are boundary features. The
  // leaf (2,2,2) of octant 7, across the corner, is sqrt(3) voxels from (1,1,1) and sqrt(4.75)
  // from the centres (3,1,1), (1,3,1), (1,1,3): the search gives the nearest boundary feature
  // (leaf_distance.h), not the nearest feature.
  std::vector<Grid::Cell> cells;
  for(std::uint32_t s = 1; s < 7; ++s) cells.push_back(cell(1, s & 1, (s >> 1) & 1, (s >> 2) & 1));
  for(std::uint32_t s = 0; s < 8; ++s)
  {
    cells.push_back(cell(2, s & 1, (s >> 1) & 1, (s >> 2) & 1));
    cells.push_back(cell(2, 2 + (s & 1), 2 + ((s >> 1) & 1), 2 + ((s >> 2) & 1)));
  }
  const Grid g(4, cells);
  Flags feature(g.number_of_leaves(), 0);
  for(std::size_t l = 0; l < g.number_of_leaves(); ++l)
  {
    const Grid::Voxel& c = g.corner(l);
    feature[l] = (c[0] < 2 && c[1] < 2 && c[2] < 2) || (g.width(l) == 2 && c[0] + c[1] + c[2] == 2) ? 1 : 0;
  }
  const std::size_t p = g.leaf_of_voxel(2, 2, 2);
  const std::vector<double> d2 = PDI::leaf_squared_distances<CGAL::Sequential_tag>(
    g, [&](std::size_t l) { return feature[l] != 0; }, [](std::size_t) { return true; });
  CHECK(d2[p] == 4.75 / 16.);
  std::vector<std::size_t> features;
  for(std::size_t l = 0; l < g.number_of_leaves(); ++l)
    if(feature[l]) features.push_back(l);
  CHECK(brute_force_squared_distance(g, g.center(p), features, false) == 3. / 16.);
  // listed, the inner leaf is found
  PDI::Leaf_feature_search<Grid> all;
  all.build_on<CGAL::Sequential_tag>(g, features);
  CHECK(all.nearest(g.center(p)) == std::make_pair(g.leaf_of_voxel(1, 1, 1), 3. / 16.));
}

TEST_CASE("Leaf distances: features added later by a search on the list give the distances of the union", "[tsdf][leaf_distance]")
{
  CGAL::Random rng(13);
  for(int trial = 0; trial < 20; ++trial)
  {
    const Grid g = Grid::uniform(4 << (trial % 2));
    Flags feature(g.number_of_leaves(), 0);
    for(std::size_t l = 0; l < feature.size(); ++l) feature[l] = rng.get_double() < 0.03 ? 1 : 0;
    feature[std::size_t(rng.get_int(0, int(feature.size())))] = 1;
    auto all = [](std::size_t) { return true; };
    const std::vector<double> before =
      PDI::leaf_squared_distances<CGAL::Sequential_tag>(g, [&](std::size_t l) { return feature[l] != 0; }, all);
    std::vector<std::size_t> added;
    for(int k = 0; k < 1 + trial % 5; ++k)
    {
      const std::size_t l = std::size_t(rng.get_int(0, int(feature.size())));
      added.push_back(l);
      feature[l] = 1;
    }
    PDI::Leaf_feature_search<Grid> search;
    search.build_on<CGAL::Sequential_tag>(g, added);
    std::vector<double> updated(before);
    for(std::size_t l = 0; l < updated.size(); ++l) updated[l] = std::min(updated[l], search.squared_distance(l));
    CHECK(updated == PDI::leaf_squared_distances<CGAL::Sequential_tag>(g, [&](std::size_t l) { return feature[l] != 0; }, all));
  }
}

TEST_CASE("Leaf components on a hand-made grid: labels, volumes, volume-weighted centroids", "[tsdf][leaf_distance]")
{
  // Finest resolution 4: octant (0,0,0) split into its 8 children, the other octants whole.
  std::vector<Grid::Cell> cells;
  for(std::uint32_t s = 1; s < 8; ++s) cells.push_back(cell(1, s & 1, (s >> 1) & 1, (s >> 2) & 1));
  for(std::uint32_t s = 0; s < 8; ++s) cells.push_back(cell(2, s & 1, (s >> 1) & 1, (s >> 2) & 1));
  const Grid g(4, cells);
  REQUIRE(g.number_of_leaves() == 15);
  auto at = [&](std::uint32_t i, std::uint32_t j, std::uint32_t k) { return g.leaf_of_voxel(i, j, k); };
  const std::size_t small0 = at(0, 0, 0), small1 = at(1, 0, 0), octant_x = at(2, 0, 0), small011 = at(0, 1, 1),
                    octant_xyz = at(2, 2, 2);
  CHECK(g.width(small0) == 1u);
  CHECK(g.width(octant_x) == 2u);
  // two small leaves and the +x octant across a face of the second (component 0); a small leaf
  // and an octant meeting the others along edges only (components 1 and 2)
  Flags in(g.number_of_leaves(), 0);
  for(std::size_t l : {small0, small1, octant_x, small011, octant_xyz}) in[l] = 1;
  const PDI::Leaf_components cc = PDI::leaf_components(g, [&](std::size_t l) { return in[l] != 0; });
  REQUIRE(cc.size() == 3);
  CHECK(cc.labels[small0] == 0);
  CHECK(cc.labels[small1] == 0);
  CHECK(cc.labels[octant_x] == 0);
  CHECK(cc.labels[small011] == 1);
  CHECK(cc.labels[octant_xyz] == 2);
  for(std::size_t l = 0; l < g.number_of_leaves(); ++l)
    if(!in[l]) CHECK(cc.labels[l] == -1);
  CHECK(cc.volumes[0] == Approx(10. / 64.));
  CHECK(cc.volumes[1] == Approx(1. / 64.));
  CHECK(cc.volumes[2] == Approx(8. / 64.));
  // (1 * (-0.375) + 1 * (-0.125) + 8 * 0.25) / 10 along x, (2 * (-0.375) + 8 * (-0.25)) / 10 along y, z
  CHECK(cc.centroids[0][0] == Approx(0.15));
  CHECK(cc.centroids[0][1] == Approx(-0.275));
  CHECK(cc.centroids[0][2] == Approx(-0.275));
  CHECK(cc.centroids[1] == std::array<double, 3>{{-0.375, -0.125, -0.125}});
  CHECK(cc.centroids[2] == std::array<double, 3>{{0.25, 0.25, 0.25}});
  // grown from seeds only, in their order
  const std::vector<std::size_t> seeds = {octant_xyz, small1, octant_x};
  const PDI::Leaf_components seeded = PDI::leaf_components(g, [&](std::size_t l) { return in[l] != 0; }, &seeds);
  REQUIRE(seeded.size() == 2);
  CHECK(seeded.labels[octant_xyz] == 0);
  CHECK(seeded.labels[small0] == 1);
  CHECK(seeded.labels[small011] == -1);
  CHECK(seeded.volumes[1] == Approx(10. / 64.));
  // nothing and everything
  CHECK(PDI::leaf_components(g, [](std::size_t) { return false; }).size() == 0);
  const PDI::Leaf_components whole = PDI::leaf_components(g, [](std::size_t) { return true; });
  REQUIRE(whole.size() == 1);
  CHECK(whole.volumes[0] == 1.);
  CHECK(whole.centroids[0][0] == Approx(0.).margin(1e-15));
}

TEST_CASE("Leaf components on random grids equal a brute-force union of face-adjacent leaves", "[tsdf][leaf_distance]")
{
  CGAL::Random rng(19);
  for(int trial = 0; trial < 10; ++trial)
  {
    const Grid g = random_grid(3 + trial % 2, 0.4, rng);
    const std::size_t n = g.number_of_leaves();
    const std::vector<std::vector<std::size_t> > adjacency = brute_force_neighbors(g);
    Flags in(n, 0);
    for(std::size_t l = 0; l < n; ++l) in[l] = rng.get_double() < 0.3 + 0.05 * (trial % 5) ? 1 : 0;
    // union-find over the brute-force adjacency
    std::vector<std::size_t> parent(n);
    std::iota(parent.begin(), parent.end(), std::size_t(0));
    std::function<std::size_t(std::size_t)> root = [&](std::size_t l) { return parent[l] == l ? l : parent[l] = root(parent[l]); };
    for(std::size_t l = 0; l < n; ++l)
      for(std::size_t m : adjacency[l])
        if(in[l] && in[m]) parent[root(l)] = root(m);
    const PDI::Leaf_components cc = PDI::leaf_components(g, [&](std::size_t l) { return in[l] != 0; });
    // components numbered by their smallest leaf
    std::vector<std::size_t> first_of_component;
    std::vector<double> volume;
    std::vector<std::array<double, 3> > moment;
    std::vector<std::int32_t> expected(n, -1);
    for(std::size_t l = 0; l < n; ++l)
    {
      if(!in[l]) continue;
      const std::size_t r = root(l);
      auto it = std::find(first_of_component.begin(), first_of_component.end(), r);
      if(it == first_of_component.end())
      {
        first_of_component.push_back(r);
        volume.push_back(0.);
        moment.push_back({{0., 0., 0.}});
        it = first_of_component.end() - 1;
      }
      const std::size_t c = std::size_t(it - first_of_component.begin());
      expected[l] = std::int32_t(c);
      volume[c] += g.volume(l);
      for(int a = 0; a < 3; ++a) moment[c][a] += g.volume(l) * g.center(l)[a];
    }
    CHECK(cc.labels == expected);
    REQUIRE(cc.size() == volume.size());
    for(std::size_t c = 0; c < volume.size(); ++c)
    {
      CHECK(cc.volumes[c] == Approx(volume[c]).epsilon(1e-12));
      for(int a = 0; a < 3; ++a) CHECK(cc.centroids[c][a] == Approx(moment[c][a] / volume[c]).epsilon(1e-12).margin(1e-14));
    }
  }
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
  // the squared distance from p to the nearest triangle of a soup, triangle by triangle
  const auto brute_force = [](const std::vector<PDI::Triangle_points>& soup, const PDI::Vec3& p) {
    double best = std::numeric_limits<double>::infinity();
    for(const auto& t : soup) best = std::min(best, PDI::squared_distance_to_triangle(p, t[0], t[1], t[2]));
    return best;
  };
  const PDI::Triangle_soup_aabb_tree tree(tris);
  for(int i = 0; i < 3000; ++i)
  {
    const PDI::Vec3 p = rnd(0.6);
    const double best = brute_force(tris, p);
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
    CHECK(small.closest(p).second == brute_force(few, p));
  }
  // A soup large enough to be held in two trees (each triangle 4 times or more): the nearest of both.
  std::vector<PDI::Triangle_points> many;
  for(std::size_t i = 0; many.size() < (std::size_t(1) << 17); ++i) many.push_back(tris[i % tris.size()]);
  // built on one thread and, as compute_tsdf() builds it, on several: the same answers
  const PDI::Triangle_soup_aabb_tree large(many);
  const PDI::Triangle_soup_aabb_tree large_parallel(many, CGAL::Parallel_if_available_tag());
  for(int i = 0; i < 300; ++i)
  {
    const PDI::Vec3 p = rnd(0.6);
    const double best = brute_force(tris, p);
    const std::pair<std::uint32_t, double> got = large.closest(p);
    CHECK(got.second == best);
    const auto& t = many[got.first];
    CHECK(PDI::squared_distance_to_triangle(p, t[0], t[1], t[2]) == got.second);
    CHECK(large_parallel.closest(p) == got);
  }
}

TEST_CASE("The grid builder splits a cell while its centre is nearer the surface than its side, down to the surface's depth", "[tsdf][grid]")
{
  CGAL::Random rng(9);
  for(int trial = 0; trial < 12; ++trial)
  {
    // one triangle: it faces no other sheet, so nothing is finer than the depth the surface asks
    PDI::Triangle_points t;
    for(auto& p : t)
      for(auto& x : p) x = rng.get_double(-0.45, 0.45);
    if(trial % 3 == 0) // on cell faces and through cell centres
      for(auto& p : t) p[2] = -0.5 + 4. / 16.;
    const std::vector<PDI::Triangle_points> tris(1, t);
    const PDI::Triangle_soup_aabb_tree tree(tris);
    PDI::Grid_refinement_rule rule;
    rule.base_depth = 4;
    rule.finest_depth = 6;
    rule.band = 0.1;
    std::vector<PDI::Grid_leaf> leaves = PDI::adaptive_grid_leaves<CGAL::Sequential_tag>(tree, rule);
    std::vector<Grid::Cell> cells;
    for(const PDI::Grid_leaf& l : leaves) cells.push_back(Grid::Cell{l.depth, l.position});
    const Grid g(64, cells); // the leaves tile the cube
    const K::Triangle_3 T(Point(t[0][0], t[0][1], t[0][2]), Point(t[1][0], t[1][1], t[1][2]), Point(t[2][0], t[2][1], t[2][2]));
    std::size_t touched = 0;
    for(const PDI::Grid_leaf& leaf : leaves)
    {
      const std::size_t l = g.leaf_of_voxel(leaf.position[0] << (6 - leaf.depth), leaf.position[1] << (6 - leaf.depth),
                                            leaf.position[2] << (6 - leaf.depth));
      REQUIRE(g.depth(l) == leaf.depth);
      // the distance of the centre: exact below the band, the band beyond
      const double d = unsigned_distance(tris, g.center(l));
      CHECK(std::abs(leaf.distance - std::min(d, rule.band)) <= 1e-15);
      CHECK(g.depth(l) <= rule.base_depth);
      // not split: its centre is at least its side away, or it has the surface's depth
      if(g.depth(l) < rule.base_depth) CHECK(d >= g.size(l));
      // split parent: its centre is nearer than its side
      if(g.depth(l) > 0)
      {
        const double s = 2. * g.size(l);
        std::array<double, 3> parent;
        for(int a = 0; a < 3; ++a) parent[a] = -0.5 + (std::floor((g.center(l)[a] + 0.5) / s) + 0.5) * s;
        CHECK(unsigned_distance(tris, parent) < s);
      }
      // the leaves the triangle touches (the former surface voxels) have the surface's depth
      if(CGAL::do_intersect(T, leaf_box(g, l)))
      {
        ++touched;
        CHECK(g.depth(l) == rule.base_depth);
      }
    }
    CHECK(touched > 0);
  }

  // The depth the surface asks for: 3 where x < 0, 5 where x >= 0 (a resolution-2 map).
  const PDI::Triangle_points t = {{{{-0.41, -0.37, 0.11}}, {{0.43, -0.29, 0.09}}, {{0.03, 0.42, 0.12}}}};
  const std::vector<PDI::Triangle_points> tris(1, t);
  const PDI::Triangle_soup_aabb_tree tree(tris);
  PDI::Grid_refinement_rule rule;
  rule.base_depth = 3;
  rule.finest_depth = 6;
  rule.surface.resolution = 2;
  rule.surface.depth.assign(8, 0);
  for(std::size_t v = 0; v < 8; ++v) rule.surface.depth[v] = v % 2 == 0 ? 3 : 5;
  std::vector<Grid::Cell> cells;
  for(const PDI::Grid_leaf& l : PDI::adaptive_grid_leaves<CGAL::Parallel_if_available_tag>(tree, rule))
    cells.push_back(Grid::Cell{l.depth, l.position});
  const Grid g(64, cells);
  const K::Triangle_3 T(Point(t[0][0], t[0][1], t[0][2]), Point(t[1][0], t[1][1], t[1][2]), Point(t[2][0], t[2][1], t[2][2]));
  std::size_t left = 0, right = 0;
  for(std::size_t l = 0; l < g.number_of_leaves(); ++l)
  {
    CHECK(g.depth(l) <= 5);
    if(!CGAL::do_intersect(T, leaf_box(g, l))) continue;
    const double x = g.center(l)[0];
    if(x < -0.2)
    {
      ++left;
      CHECK(g.depth(l) == 3);
    }
    if(x > 0.2)
    {
      ++right;
      CHECK(g.depth(l) == 5);
    }
  }
  CHECK(left > 0);
  CHECK(right > 0);

  // A uniform rule: the dense grid, every distance exact below the band.
  rule.uniform = true;
  rule.finest_depth = 4;
  rule.surface = PDI::Surface_depths();
  std::vector<double> distance;
  cells.clear();
  for(const PDI::Grid_leaf& l : PDI::adaptive_grid_leaves<CGAL::Sequential_tag>(tree, rule))
  {
    cells.push_back(Grid::Cell{l.depth, l.position});
    distance.push_back(l.distance);
  }
  const Grid u(16, cells);
  CHECK(u == Grid::uniform(16));
  for(std::size_t i = 0; i < cells.size(); ++i)
  {
    const std::size_t l = u.leaf_of_voxel(cells[i].position[0], cells[i].position[1], cells[i].position[2]);
    CHECK(std::abs(distance[i] - std::min(unsigned_distance(tris, u.center(l)), rule.band)) <= 1e-15);
  }
}

TEST_CASE("The grid builder refines two close facing sheets to the finest depth", "[tsdf][grid]")
{
  // Two parallel squares, oppositely oriented, 0.6 finest voxels of 64 apart: the faces of a slab.
  const double z0 = 0.0371, gap = 0.6 / 64.;
  auto square = [](double z, bool up) {
    const PDI::Vec3 a = {{-0.3, -0.3, z}}, b = {{0.3, -0.3, z}}, c = {{0.3, 0.3, z}}, d = {{-0.3, 0.3, z}};
    return up ? std::vector<PDI::Triangle_points>{{{a, b, c}}, {{a, c, d}}}
              : std::vector<PDI::Triangle_points>{{{a, c, b}}, {{a, d, c}}};
  };
  std::vector<PDI::Triangle_points> tris = square(z0 + gap, true), lower = square(z0, false);
  tris.insert(tris.end(), lower.begin(), lower.end());
  const PDI::Triangle_soup_aabb_tree tree(tris);
  PDI::Grid_refinement_rule rule;
  rule.base_depth = 4;
  rule.finest_depth = 6;
  rule.band = 0.1;
  std::vector<Grid::Cell> cells;
  for(const PDI::Grid_leaf& l : PDI::adaptive_grid_leaves<CGAL::Sequential_tag>(tree, rule))
    cells.push_back(Grid::Cell{l.depth, l.position});
  const Grid g(64, cells);
  std::size_t crossed = 0;
  for(std::size_t l = 0; l < g.number_of_leaves(); ++l)
  {
    const std::array<double, 3> c = g.center(l);
    // the leaves the squares cross away from their rims
    if(std::abs(c[0]) > 0.25 || std::abs(c[1]) > 0.25 || unsigned_distance(tris, c) > half_diagonal(g, l)) continue;
    ++crossed;
    CHECK(g.depth(l) == 6);
  }
  CHECK(crossed > 500);
  // one square alone stays at the surface's depth
  const PDI::Triangle_soup_aabb_tree single(lower);
  std::size_t finest = 0;
  for(const PDI::Grid_leaf& l : PDI::adaptive_grid_leaves<CGAL::Sequential_tag>(single, rule)) finest += l.depth > 4 ? 1 : 0;
  CHECK(finest == 0);
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
  // The leaves are inside where their sign voxel is: on the dense grid and on an adaptive one.
  CGAL::Random rng(31);
  for(const Grid& g : {Grid::uniform(r), random_grid(6, 0.5, rng, 3)})
    for(bool parity : {false, true})
    {
      const Flags inside = PDI::leaf_inside_from_rows<CGAL::Sequential_tag>(tris, g, parity);
      REQUIRE(inside.size() == g.number_of_leaves());
      std::size_t wrong = 0, in_count = 0;
      for(std::size_t l = 0; l < g.number_of_leaves(); ++l)
      {
        const Grid::Voxel v = PDI::sign_voxel(g, l);
        CHECK(PDI::sign_point(g, l) == sign_point_of(g, l));
        const int i = int(v[0]), j = int(v[1]), k = int(v[2]);
        const bool strictly_in = i > 10 && i < 50 && j > 12 && j < 44 && k > 8 && k < 52;
        const bool strictly_out = i < 10 || i > 50 || j < 12 || j > 44 || k < 8 || k > 52;
        if((strictly_in && !inside[l]) || (strictly_out && inside[l])) ++wrong;
        in_count += inside[l];
      }
      CHECK(wrong == 0);
      CHECK(in_count > 0);
    }
}


TEST_CASE("Leaf signs by rows, ray votes and winding numbers on a closed and a holed sphere", "[tsdf][sign]")
{
  // The triangles in the cube as they are; the polyhedron is within 0.002 of the sphere.
  const double R = 0.35;
  const Mesh sphere = test_shapes::make_sphere(Point(0.013, -0.021, 0.007), R, 3);
  const std::array<double, 3> c = {{0.013, -0.021, 0.007}};
  // without its cap x > 0.8 R: the rows along +x from inside leave through the hole
  test_shapes::Soup soup;
  for(auto f : faces(sphere))
  {
    std::array<Point, 3> p;
    int k = 0;
    for(auto v : vertices_around_face(halfedge(f, sphere), sphere)) p[std::size_t(k++)] = sphere.point(v);
    if((p[0].x() + p[1].x() + p[2].x()) / 3. <= c[0] + 0.8 * R) soup.triangle(p[0], p[1], p[2]);
  }
  const Mesh holed = soup.mesh();
  REQUIRE(num_faces(holed) < num_faces(sphere));
  auto triangles = [](const Mesh& m) { return PDI::normalized_triangles(m, get(CGAL::vertex_point, m), PD::Normalization()); };
  const std::vector<PDI::Triangle_points> closed_tris = triangles(sphere), holed_tris = triangles(holed);
  const double margin = 0.005;
  CGAL::Random rng(37);
  for(const Grid& g : {Grid::uniform(32), random_grid(6, 0.45, rng, 2)})
  {
    INFO(g.number_of_leaves() << " leaves of finest resolution " << g.finest_resolution());
    // the exact answer at each sign point, away from the surface (and from the hole)
    std::vector<int> expected(g.number_of_leaves(), -1);
    std::size_t decided = 0;
    for(std::size_t l = 0; l < g.number_of_leaves(); ++l)
    {
      const double s = sd_sphere(sign_point_of(g, l), c, R);
      if(std::abs(s) > margin) expected[l] = s < 0. ? 1 : 0, ++decided;
    }
    REQUIRE(decided > g.number_of_leaves() / 2);
    auto wrong = [&](const Flags& inside, bool near_hole_too) {
      REQUIRE(inside.size() == g.number_of_leaves());
      std::size_t w = 0;
      for(std::size_t l = 0; l < inside.size(); ++l)
        if(expected[l] >= 0 && (near_hole_too || sign_point_of(g, l)[0] < c[0] + 0.6 * R) && inside[l] != expected[l]) ++w;
      return w;
    };
    CHECK(wrong(PDI::leaf_inside_from_rows<CGAL::Sequential_tag>(closed_tris, g, false), true) == 0);
    CHECK(wrong(PDI::leaf_inside_from_rows<CGAL::Parallel_if_available_tag>(closed_tris, g, true), true) == 0);
    CHECK(wrong(PDI::leaf_inside_by_ray_votes<CGAL::Sequential_tag>(closed_tris, g), true) == 0);
    Flags by_winding(g.number_of_leaves(), 0);
    PDI::leaf_inside_by_winding_number<CGAL::Sequential_tag>(closed_tris, g, {}, by_winding);
    CHECK(wrong(by_winding, true) == 0);
    // a listed subset only
    std::vector<std::size_t> some;
    for(std::size_t l = 0; l < g.number_of_leaves(); l += 3) some.push_back(l);
    Flags partial(g.number_of_leaves(), 2);
    PDI::leaf_inside_by_winding_number<CGAL::Parallel_if_available_tag>(closed_tris, g, some, partial);
    for(std::size_t l = 0; l < g.number_of_leaves(); ++l)
      CHECK(partial[l] == (l % 3 == 0 ? by_winding[l] : 2));

    // The cap missing: the votes of the six rays (and the winding number where one leaves through
    // the hole) keep the inside away from the hole; a single row does not.
    CHECK(wrong(PDI::leaf_inside_by_ray_votes<CGAL::Parallel_if_available_tag>(holed_tris, g), false) == 0);
    CHECK(wrong(PDI::leaf_inside_from_rows<CGAL::Sequential_tag>(holed_tris, g, false), false) > 0);
  }
}

TEST_CASE("Leaf signs by flood fill on hand-made shells", "[tsdf][sign]")
{
  // A shell of surface leaves on the border of [2,6]^3 in the 16^3 grid: its inside [3,5]^3 is
  // sealed; every shell leaf touches the outside, so it is outside.
  const Grid g = Grid::uniform(16);
  auto in_box = [](const Grid::Voxel& v, std::uint32_t lo, std::uint32_t hi) {
    return v[0] >= lo && v[0] <= hi && v[1] >= lo && v[1] <= hi && v[2] >= lo && v[2] <= hi;
  };
  Flags shell(g.number_of_leaves(), 0);
  for(std::size_t l = 0; l < g.number_of_leaves(); ++l)
    if(in_box(g.corner(l), 2, 6) && !in_box(g.corner(l), 3, 5)) shell[l] = 1;
  auto expected = [&](bool sealed) {
    Flags out(g.number_of_leaves(), 0);
    for(std::size_t l = 0; l < out.size(); ++l) out[l] = std::uint8_t(sealed && in_box(g.corner(l), 3, 5));
    return out;
  };
  CHECK(PDI::leaf_inside_by_flood_fill(g, shell) == expected(true));
  // an edge leaf of the shell open: its face neighbours inside the box are shell leaves, the
  // inside stays sealed (6-connectivity)
  Flags edge = shell;
  edge[g.leaf_of_voxel(2, 2, 4)] = 0;
  CHECK(PDI::leaf_inside_by_flood_fill(g, edge) == expected(true));
  // a face leaf open: the inside joins the outside
  Flags open = shell;
  open[g.leaf_of_voxel(4, 4, 2)] = 0;
  CHECK(PDI::leaf_inside_by_flood_fill(g, open) == expected(false));
  // a thick wall: the surface leaves of its inner layer see no outside leaf and are inside
  Flags thick = shell;
  for(std::size_t l = 0; l < g.number_of_leaves(); ++l)
    if(in_box(g.corner(l), 3, 5) && !in_box(g.corner(l), 4, 4)) thick[l] = 1;
  const Flags thick_inside = PDI::leaf_inside_by_flood_fill(g, thick);
  CHECK(thick_inside[g.leaf_of_voxel(3, 4, 4)] == 1);
  CHECK(thick_inside[g.leaf_of_voxel(4, 4, 4)] == 1);
  CHECK(thick_inside[g.leaf_of_voxel(2, 4, 4)] == 0);

  // On an adaptive grid: a closed sphere of surface leaves (centre within half a diagonal of the
  // sphere) seals its inside, through leaves of any size; the surface leaves are outside where
  // they touch an outside leaf.
  CGAL::Random rng(41);
  const Grid a = random_grid(5, 0.4, rng, 2);
  const std::array<double, 3> c = {{0.02, 0., -0.03}};
  Flags crossed(a.number_of_leaves(), 0);
  for(std::size_t l = 0; l < a.number_of_leaves(); ++l)
    crossed[l] = std::abs(sd_sphere(a.center(l), c, 0.3)) <= half_diagonal(a, l) * (1. + 1e-9) ? 1 : 0;
  const Flags inside = PDI::leaf_inside_by_flood_fill(a, crossed);
  std::size_t wrong = 0;
  for(std::size_t l = 0; l < a.number_of_leaves(); ++l)
  {
    bool expect = sd_sphere(a.center(l), c, 0.3) < 0.;
    if(crossed[l])
    {
      expect = true;
      a.for_each_neighbor(l, [&](std::size_t m) { expect = expect && (crossed[m] || sd_sphere(a.center(m), c, 0.3) < 0.); });
    }
    wrong += inside[l] != std::uint8_t(expect) ? 1 : 0;
  }
  CHECK(wrong == 0);
}

// -------------------------------------------------------------------------------------- the TSDF

TEST_CASE("TSDF distances below the truncation equal the distances of CGAL's AABB tree", "[tsdf][distance]")
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
    for(int mode = 0; mode < 3; ++mode) // the dense grid, the adaptive grid without and with the prior
    {
      const auto np = PD::parameters::combine(PD::parameters::voxel_resolutions(std::vector<int>{r / 2, r}),
                                              switches(&Variant::adaptive_grid, mode != 0));
      const PD::Truncated_signed_distance_field tsdf =
        mode == 2 ? PD::compute_tsdf<CGAL::Parallel_if_available_tag>(m, PD::compute_flow_freeze_prior(m, np), np)
                  : PD::compute_tsdf<CGAL::Parallel_if_available_tag>(m, np);
      INFO("resolution " << r << ", mode " << mode << ", " << tsdf.grid.number_of_leaves() << " leaves");
      const std::vector<PDI::Triangle_points> tris = PDI::normalized_triangles(m, get(CGAL::vertex_point, m), tsdf.normalization);
      // CGAL's plain distance query on the same normalized triangles.
      typedef PDI::Aabb_kernel SC;
      std::vector<SC::Triangle_3> triangles;
      for(const auto& t : tris)
        triangles.emplace_back(SC::Point_3(t[0][0], t[0][1], t[0][2]), SC::Point_3(t[1][0], t[1][1], t[1][2]),
                               SC::Point_3(t[2][0], t[2][1], t[2][2]));
      PDI::Aabb_triangle_tree tree(triangles.begin(), triangles.end());
      tree.accelerate_distance_queries();
      std::size_t band = 0;
      double worst = 0.;
      for(std::size_t l = 0; l < tsdf.values.size(); ++l)
      {
        const PDI::Vec3 c = tsdf.grid.center(l);
        const double d = std::sqrt(CGAL::to_double(tree.squared_distance(SC::Point_3(c[0], c[1], c[2]))));
        if(std::abs(tsdf.values[l]) < tsdf.truncation)
        {
          ++band;
          worst = std::max(worst, std::abs(std::abs(tsdf.values[l]) - d));
        }
        else // CGAL finds nothing closer than the truncation
          CHECK(d >= tsdf.truncation - 1e-12);
      }
      CHECK(band > 1000);
      CHECK(worst <= 1e-12);
    }
}

TEST_CASE("TSDF of a sphere: within half a voxel of the exact signed distance, clipped", "[tsdf]")
{
  const Mesh sphere = test_shapes::make_sphere(Point(0.3, -0.2, 0.1), 1.0, 4);
  for(PD::Tsdf_sign_method method : {PD::Tsdf_sign_method::AUTOMATIC, PD::Tsdf_sign_method::INSIDE_TEST,
                                     PD::Tsdf_sign_method::FLOOD_FILL})
  {
    const PD::Truncated_signed_distance_field tsdf = PD::compute_tsdf(sphere, PD::parameters::tsdf_sign_method(method));
    REQUIRE(tsdf.voxel_size == 1. / 64.);
    REQUIRE(tsdf.grid.finest_resolution() == 128);
    REQUIRE(tsdf.values.size() == tsdf.grid.number_of_leaves());
    CHECK(tsdf.truncation == Approx(8. / 64.));
    CHECK(tsdf.sign_method == (method == PD::Tsdf_sign_method::AUTOMATIC ? PD::Tsdf_sign_method::RAY_VOTES : method));
    const std::array<double, 3> c = unit(tsdf.normalization, 0.3, -0.2, 0.1);
    const double R = 1.0 * tsdf.normalization.scale();
    auto sd = [&](const std::array<double, 3>& p) { return sd_sphere(p, c, R); };
    check_values(tsdf, sd, 0.5 / 64.);
    CHECK(check_signs(tsdf, sd, 0.05 / 64.) > 0.99);
    // Deep inside and far outside: exactly -tau and +tau.
    CHECK(value_at(tsdf, c) == -tsdf.truncation);
    CHECK(value_at(tsdf, {{-0.5, -0.5, -0.5}}) == tsdf.truncation);
    CHECK(*std::min_element(tsdf.values.begin(), tsdf.values.end()) == -tsdf.truncation);
    CHECK(*std::max_element(tsdf.values.begin(), tsdf.values.end()) == tsdf.truncation);
  }
}

TEST_CASE("TSDF of a box equals the exact signed distance", "[tsdf]")
{
  const Mesh box = test_shapes::make_box(Point(-1, -0.6, -0.4), Point(1, 0.6, 0.4), 3);
  for(bool adaptive : {true, false})
  {
    const PD::Truncated_signed_distance_field tsdf =
      PD::compute_tsdf(box, PD::parameters::combine(PD::parameters::voxel_resolutions(std::vector<int>{32, 64}),
                                                    PD::parameters::tsdf_truncation(5.), switches(&Variant::adaptive_grid, adaptive)));
    REQUIRE(tsdf.voxel_size == 1. / 64.);
    CHECK(tsdf.truncation == Approx(5. / 64.));
    const std::array<double, 3> lo = unit(tsdf.normalization, -1, -0.6, -0.4), hi = unit(tsdf.normalization, 1, 0.6, 0.4);
    auto sd = [&](const std::array<double, 3>& p) { return sd_box(p, lo, hi); };
    check_values(tsdf, sd, 1e-4 / 64.);
    CHECK(check_signs(tsdf, sd, 1e-9) > 0.999);
  }
}

TEST_CASE("TSDF sign of a closed sphere with one small hole", "[tsdf][sign]")
{
  const Mesh sphere = test_shapes::make_sphere(Point(0, 0, 0), 1.0, 3);
  const Mesh holed = without_first_face(sphere);
  REQUIRE(num_faces(holed) + 1 == num_faces(sphere));
  const std::array<double, 3> hole = first_face_centroid(sphere);
  const PD::Truncated_signed_distance_field tsdf = PD::compute_tsdf(holed);
  CHECK(tsdf.sign_method == PD::Tsdf_sign_method::RAY_VOTES);
  const std::array<double, 3> c = unit(tsdf.normalization, 0, 0, 0), h = unit(tsdf.normalization, hole[0], hole[1], hole[2]);
  const double R = tsdf.normalization.scale();
  auto sd = [&](const std::array<double, 3>& p) { return sd_sphere(p, c, R); };
  auto away_from_hole = [&](const std::array<double, 3>& p) { return sd_sphere(p, h, 4. / 64.) > 0.; };
  CHECK(check_signs(tsdf, sd, 1.5 / 64., away_from_hole) > 0.8); // a shell 3/64 thick left out
  // Probes: the centre, just inside and just outside the surface opposite to the hole.
  CHECK(value_at(tsdf, c) == -tsdf.truncation);
  const std::array<double, 3> dir = {{c[0] - h[0], c[1] - h[1], c[2] - h[2]}};
  const double n = std::sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
  auto along = [&](double t) { return std::array<double, 3>{{c[0] + dir[0] / n * t, c[1] + dir[1] / n * t, c[2] + dir[2] / n * t}}; };
  CHECK(value_at(tsdf, along(R - 3. / 64.)) < 0.);
  CHECK(value_at(tsdf, along(R + 3. / 64.)) > 0.);
  // The same probes near the hole: 3 voxels inside and outside the missing face.
  const std::array<double, 3> hd = {{h[0] - c[0], h[1] - c[1], h[2] - c[2]}};
  const double hn = std::sqrt(hd[0] * hd[0] + hd[1] * hd[1] + hd[2] * hd[2]);
  auto near_hole = [&](double t) { return std::array<double, 3>{{c[0] + hd[0] / hn * t, c[1] + hd[1] / hn * t, c[2] + hd[2] / hn * t}}; };
  CHECK(value_at(tsdf, near_hole(hn - 3. / 64.)) < 0.);
  CHECK(value_at(tsdf, near_hole(hn + 3. / 64.)) > 0.);

  // Flood fill seals a hole smaller than a voxel (here on the 16^3 grid).
  const PD::Truncated_signed_distance_field coarse = PD::compute_tsdf(
    without_first_face(test_shapes::make_sphere(Point(0, 0, 0), 1.0, 4)),
    PD::parameters::combine(PD::parameters::voxel_resolutions(std::vector<int>{16}),
                            PD::parameters::tsdf_sign_method(PD::Tsdf_sign_method::FLOOD_FILL)));
  CHECK(coarse.sign_method == PD::Tsdf_sign_method::FLOOD_FILL);
  CHECK(check_signs(coarse, sd, 0.5 / 16.) > 0.75);
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
    CHECK(check_signs(tsdf, sd, 0.1 / 64.) > 0.99);
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
      CHECK(check_signs(tsdf, sd, 0.1 / 64.) > 0.99);
      CHECK(value_at(tsdf, {{0.5 * (lo[0] + hi[0]), 0., 0.}}) == -tsdf.truncation);
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
    CHECK(check_signs(tsdf, sd_for(tsdf.normalization), 0.1 / 64.) > 0.99);
    // The overlap, covered twice, is inside.
    CHECK(value_at(tsdf, unit(tsdf.normalization, 0., -0.1, 0.)) < 0.);
  }
  // Flood fill agrees; ray parity counts the overlap as outside (documented limitation).
  const PD::Truncated_signed_distance_field flood =
    PD::compute_tsdf(m, PD::parameters::tsdf_sign_method(PD::Tsdf_sign_method::FLOOD_FILL));
  CHECK(check_signs(flood, sd_for(flood.normalization), 0.1 / 64.) > 0.99);
  const PD::Truncated_signed_distance_field parity =
    PD::compute_tsdf(m, PD::parameters::tsdf_sign_method(PD::Tsdf_sign_method::INSIDE_TEST));
  CHECK(value_at(parity, unit(parity.normalization, 0., -0.1, 0.)) > 0.);
}

TEST_CASE("TSDF is deterministic, reads the vertex point map and the normalization", "[tsdf]")
{
  Mesh m = test_shapes::make_sphere(Point(-0.5, 0, 0), 0.4, 3);
  test_shapes::append(m, test_shapes::make_cylinder(Point(0.3, 0, 0), 0.2, 0.9, 24, 6));
  const Mesh open = without_first_face(m);
  const PD::Hierarchical_prior prior = PD::compute_flow_freeze_prior(m);
  for(const Mesh* mesh : std::vector<const Mesh*>{&m, &open})
    for(PD::Tsdf_sign_method method : {PD::Tsdf_sign_method::AUTOMATIC, PD::Tsdf_sign_method::WINDING_NUMBER,
                                       PD::Tsdf_sign_method::FLOOD_FILL})
    {
      const auto np = PD::parameters::tsdf_sign_method(method);
      const PD::Truncated_signed_distance_field seq = PD::compute_tsdf<CGAL::Sequential_tag>(*mesh, np);
      const PD::Truncated_signed_distance_field par = PD::compute_tsdf<CGAL::Parallel_if_available_tag>(*mesh, np);
      CHECK(seq.grid == par.grid);
      CHECK(seq.values == par.values);
      const PD::Truncated_signed_distance_field seq_prior = PD::compute_tsdf<CGAL::Sequential_tag>(*mesh, prior, np);
      const PD::Truncated_signed_distance_field par_prior = PD::compute_tsdf<CGAL::Parallel_if_available_tag>(*mesh, prior, np);
      CHECK(seq_prior.grid == par_prior.grid);
      CHECK(seq_prior.values == par_prior.values);
    }

  // A vertex point map holding the points moved by (10, 20, 30): same field, moved normalization.
  auto moved = get(CGAL::dynamic_vertex_property_t<Point>(), m);
  for(auto v : vertices(m)) put(moved, v, m.point(v) + K::Vector_3(10, 20, 30));
  const PD::Truncated_signed_distance_field base = PD::compute_tsdf(m);
  const PD::Truncated_signed_distance_field shifted = PD::compute_tsdf(m, CGAL::parameters::vertex_point_map(moved));
  CHECK(shifted.normalization.center()[0] == Approx(base.normalization.center()[0] + 10));
  REQUIRE(shifted.grid == base.grid);
  double worst = 0.;
  for(std::size_t i = 0; i < base.values.size(); ++i) worst = std::max(worst, std::abs(base.values[i] - shifted.values[i]));
  CHECK(worst < 1e-9);

  // A given normalization is used as is.
  const PD::Normalization half({{0., 0., 0.}}, 0.5);
  const PD::Truncated_signed_distance_field given = PD::compute_tsdf(m, PD::parameters::normalization(half));
  CHECK(given.normalization.scale() == 0.5);
  // 0.05 inside the sphere of radius 0.2 (normalized) centred at (-0.25, 0, 0).
  const std::size_t l = given.grid.locate(-0.1, 0., 0.);
  CHECK(given.values[l] == Approx(sd_sphere(given.grid.center(l), {{-0.25, 0., 0.}}, 0.2)).margin(0.5 / 64));
  CHECK(given.values[l] < 0.);
}

TEST_CASE("TSDF of an open sheet: all outside, distances to the triangles", "[tsdf]")
{
  // Two triangles making a slanted square: no inside at all.
  Mesh m;
  const auto a = m.add_vertex(Point(0, 0, 0)), b = m.add_vertex(Point(1, 0, 0.3)), c = m.add_vertex(Point(1, 1, 0.5)),
             d = m.add_vertex(Point(0, 1, 0.2));
  m.add_face(a, b, c);
  m.add_face(a, c, d);
  // (FLOOD_FILL: see the test of its known failure on an open sheet below)
  for(PD::Tsdf_sign_method method : {PD::Tsdf_sign_method::AUTOMATIC, PD::Tsdf_sign_method::WINDING_NUMBER})
    for(int r : {2, 16})
      for(bool adaptive : {true, false})
      {
        const PD::Truncated_signed_distance_field tsdf = PD::compute_tsdf(
          m, PD::parameters::combine(PD::parameters::tsdf_sign_method(method),
                                     PD::parameters::voxel_resolutions(std::vector<int>{r}),
                                     switches(&Variant::adaptive_grid, adaptive)));
        if(!adaptive) CHECK(tsdf.grid == Grid::uniform(r));
        const std::vector<PDI::Triangle_points> tris = PDI::normalized_triangles(m, get(CGAL::vertex_point, m), tsdf.normalization);
        for(std::size_t l = 0; l < tsdf.values.size(); ++l)
          CHECK(tsdf.values[l] == Approx(std::min(unsigned_distance(tris, tsdf.grid.center(l)), tsdf.truncation)).margin(1e-9));
      }
}

// --------------------------------------------------------------------------- the grid of the TSDF

TEST_CASE("TSDF with adaptive_grid(false): the dense grid, the exact clipped signed distance at the voxel centres", "[tsdf][grid]")
{
  const Mesh box = test_shapes::make_box(Point(-1, -0.6, -0.4), Point(1, 0.6, 0.4), 3);
  const PD::Hierarchical_prior prior = PD::compute_flow_freeze_prior(box);
  for(int variant = 0; variant < 3; ++variant)
  {
    const auto dense = switches(&Variant::adaptive_grid, false);
    const PD::Truncated_signed_distance_field tsdf =
      variant == 0 ? PD::compute_tsdf(box, dense)
                   : variant == 1 ? PD::compute_tsdf(box, prior, dense)
                                  : PD::compute_tsdf(box, PD::parameters::combine(dense, PD::parameters::grid_resolution(256)));
    REQUIRE(tsdf.grid == Grid::uniform(64));
    const std::array<double, 3> lo = unit(tsdf.normalization, -1, -0.6, -0.4), hi = unit(tsdf.normalization, 1, 0.6, 0.4);
    const PD::Voxel_grid<double> voxels(64);
    double worst = 0.;
    std::size_t wrong_sign = 0;
    for(std::size_t v = 0; v < voxels.size(); ++v)
    {
      const double s = sd_box(voxels.center(v), lo, hi);
      worst = std::max(worst, std::abs(tsdf.values[v] - std::max(-tsdf.truncation, std::min(tsdf.truncation, s))));
      wrong_sign += std::abs(s) > 1e-12 && (s < 0.) != (tsdf.values[v] < 0.) ? 1 : 0;
    }
    CHECK(worst <= 1e-12);
    CHECK(wrong_sign == 0);
  }
  // the dense grid of the finest voxel resolution, whatever the grid resolution
  const PD::Truncated_signed_distance_field coarse = PD::compute_tsdf(
    box, PD::parameters::combine(PD::parameters::voxel_resolutions(std::vector<int>{16, 32}),
                                 switches(&Variant::adaptive_grid, false), PD::parameters::grid_resolution(64)));
  CHECK(coarse.grid == Grid::uniform(32));
  CHECK(coarse.voxel_size == 1. / 32.);
}

TEST_CASE("TSDF grid: a thin plate gets the finest leaves on its surface", "[tsdf][grid]")
{
  // 2 x 2 x 0.02: 0.6 voxels of 64 thick once normalized, well under the 4/64 the rule sees.
  const Mesh plate = test_shapes::make_box(Point(-1, -1, -0.01), Point(1, 1, 0.01), 4);
  const PD::Hierarchical_prior prior = PD::compute_flow_freeze_prior(plate);
  for(int variant = 0; variant < 3; ++variant)
  {
    const PD::Truncated_signed_distance_field tsdf =
      variant == 0 ? PD::compute_tsdf(plate, prior)
                   : variant == 1 ? PD::compute_tsdf(plate) : PD::compute_tsdf(plate, prior, PD::parameters::grid_resolution(64));
    const int finest = variant == 2 ? 64 : 128;
    REQUIRE(tsdf.grid.finest_resolution() == finest);
    const std::array<double, 3> lo = unit(tsdf.normalization, -1, -1, -0.01), hi = unit(tsdf.normalization, 1, 1, 0.01);
    REQUIRE(hi[2] - lo[2] < 1. / 64.);
    auto sd = [&](const std::array<double, 3>& p) { return sd_box(p, lo, hi); };
    // the leaves the big faces cross, away from the rim
    std::size_t crossed = 0, wrong = 0;
    for(std::size_t l = 0; l < tsdf.grid.number_of_leaves(); ++l)
    {
      const std::array<double, 3> c = tsdf.grid.center(l);
      if(std::abs(c[0]) > 0.8 * hi[0] || std::abs(c[1]) > 0.8 * hi[1] || std::abs(sd(c)) > half_diagonal(tsdf.grid, l)) continue;
      ++crossed;
      wrong += tsdf.grid.width(l) != 1u ? 1 : 0;
    }
    INFO("variant " << variant << ": " << tsdf.grid.number_of_leaves() << " leaves, " << crossed << " crossed");
    CHECK(crossed > 2000);
    CHECK(wrong == 0);
    // the values stay exact, the sign points within the plate inside
    check_values(tsdf, sd, 1e-12);
    CHECK(check_signs(tsdf, sd, 1e-9) > 0.999);
  }
}

TEST_CASE("TSDF grid: a big box gets no finest leaf, few leaves, large ones far from its surface", "[tsdf][grid]")
{
  const Mesh box = test_shapes::make_box(Point(-1, -0.6, -0.4), Point(1, 0.6, 0.4), 3);
  const PD::Hierarchical_prior prior = PD::compute_flow_freeze_prior(box);
  for(bool with_prior : {true, false})
  {
    const PD::Truncated_signed_distance_field tsdf = with_prior ? PD::compute_tsdf(box, prior) : PD::compute_tsdf(box);
    const Grid& g = tsdf.grid;
    INFO((with_prior ? "with" : "without") << " the prior: " << g.number_of_leaves() << " leaves");
    REQUIRE(g.finest_resolution() == 128);
    CHECK(g.number_of_leaves_of_depth(7) == 0);
    // the dense grid has 64^3 leaves; the surface alone at 64 asks for a few layers of 64^2
    CHECK(g.number_of_leaves() < std::size_t(64 * 64 * 64) / (with_prior ? 8 : 4));
    const std::array<double, 3> lo = unit(tsdf.normalization, -1, -0.6, -0.4), hi = unit(tsdf.normalization, 1, 0.6, 0.4);
    const double grading = 2. + 0.5 * std::sqrt(3.); // a child's centre is within this many of its sides of the surface
    std::size_t crossed = 0;
    for(std::size_t l = 0; l < g.number_of_leaves(); ++l)
    {
      const double d = std::abs(sd_box(g.center(l), lo, hi));
      // its parent was split: its centre nearer than its side, the child's centre at most half
      // the parent's half diagonal farther
      CHECK(d < grading * g.size(l) + 1e-12);
      // coarser than the surface ever asks: it was not split, its centre at least its side away
      if(g.resolution(l) < 16) CHECK(d >= g.size(l) - 1e-12);
      if(d <= half_diagonal(g, l))
      {
        ++crossed;
        // at least the prior's coarsest resolution; without the prior the finest voxel resolution
        CHECK(g.resolution(l) >= (with_prior ? 16 : 64));
      }
    }
    CHECK(crossed > 0);
    // the leaf at the centre, 0.19 from the surface, is large
    CHECK(g.size(g.locate(0., 0., 0.)) >= 1. / 8.);
  }
}

TEST_CASE("TSDF grid: with the prior, a coarsening of the grid without it, the values still exact", "[tsdf][grid]")
{
  // The prior asks for its fused resolution (16, 32 or 64) where the grid without it asks for 64:
  // every cell split with the prior is split without it.
  const Mesh sphere = test_shapes::make_sphere(Point(0, 0, 0), 1., 4);
  const PD::Hierarchical_prior prior = PD::compute_flow_freeze_prior(sphere);
  const PD::Truncated_signed_distance_field with = PD::compute_tsdf(sphere, prior), without = PD::compute_tsdf(sphere);
  INFO("leaves with the prior " << with.grid.number_of_leaves() << ", without " << without.grid.number_of_leaves());
  CHECK(with.grid.number_of_leaves() < without.grid.number_of_leaves());
  std::size_t finer = 0;
  for(std::size_t l = 0; l < without.grid.number_of_leaves(); ++l)
  {
    const Grid::Voxel& c = without.grid.corner(l);
    finer += with.grid.depth(with.grid.leaf_of_voxel(c[0], c[1], c[2])) > without.grid.depth(l) ? 1 : 0;
  }
  CHECK(finer == 0);
  // the smooth sphere is crossed by leaves coarser than the finest voxel resolution
  std::size_t coarse = 0;
  for(std::size_t l = 0; l < with.grid.number_of_leaves(); ++l)
    if(std::abs(with.values[l]) <= half_diagonal(with.grid, l) && with.grid.resolution(l) < 64) ++coarse;
  CHECK(coarse > 0);
  // the values stay exact wherever the grid is coarse
  const std::vector<PDI::Triangle_points> tris = PDI::normalized_triangles(sphere, get(CGAL::vertex_point, sphere), with.normalization);
  CGAL::Random rng(43);
  for(int s = 0; s < 300; ++s)
  {
    const std::size_t l = std::size_t(rng.get_int(0, int(with.grid.number_of_leaves())));
    CHECK(std::abs(with.values[l]) == Approx(std::min(unsigned_distance(tris, with.grid.center(l)), with.truncation)).margin(1e-12));
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
  CHECK(!throws(PD::parameters::combine(PD::parameters::voxel_resolutions(std::vector<int>{256}), PD::parameters::grid_resolution(256))));
  // grid_resolution: a power of two up to 256, raised to the finest voxel resolution
  CHECK(PD::compute_tsdf(m, PD::parameters::grid_resolution(32)).grid.finest_resolution() == 64);
  CHECK(PD::compute_tsdf(m, PD::parameters::combine(PD::parameters::voxel_resolutions(std::vector<int>{16}),
                                                    PD::parameters::grid_resolution(8))).grid.finest_resolution() == 16);
  CHECK(throws(PD::parameters::grid_resolution(96)));
  CHECK(throws(PD::parameters::grid_resolution(512)));
  CHECK(throws(PD::parameters::grid_resolution(0)));
  CHECK(!throws(PD::parameters::grid_resolution(64)));
  CHECK(!throws(PD::parameters::combine(PD::parameters::voxel_resolutions(std::vector<int>{16}), PD::parameters::grid_resolution(16))));
  // a prior of other resolutions
  const PD::Hierarchical_prior prior = PD::compute_flow_freeze_prior(m, PD::parameters::voxel_resolutions(std::vector<int>{16, 32}));
  CHECK_THROWS_AS(PD::compute_tsdf(m, prior), PD::Invalid_input);
  CHECK_NOTHROW(PD::compute_tsdf(m, prior, PD::parameters::voxel_resolutions(std::vector<int>{16, 32})));
  Mesh empty;
  CHECK_THROWS_AS(PD::compute_tsdf(empty), PD::Invalid_input);
}

TEST_CASE("TSDF: the defaults equal every default given explicitly", "[tsdf][parameters]")
{
  const Mesh box = test_shapes::make_box(Point(-1, -0.6, -0.4), Point(1, 0.6, 0.4), 3);
  const PD::Truncated_signed_distance_field a = PD::compute_tsdf(box);
  const PD::Truncated_signed_distance_field b = PD::compute_tsdf(
    box, PD::parameters::combine(PD::parameters::voxel_resolutions(PD::defaults::voxel_resolutions),
                                 PD::parameters::tsdf_truncation(PD::defaults::tsdf_truncation),
                                 PD::parameters::tsdf_sign_method(PD::Tsdf_sign_method::AUTOMATIC),
                                 PD::parameters::normalization_margin(PD::defaults::normalization_margin),
                                 PD::parameters::grid_resolution(PD::defaults::grid_resolution)));
  CHECK(a.voxel_size == 1. / PD::defaults::voxel_resolutions.back());
  CHECK(a.grid.finest_resolution() == PD::defaults::grid_resolution);
  CHECK(a.grid == b.grid);
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

namespace {

// The Flow zones of `fitting_resolutions`: the leaves whose centre lies within tolerance / r_fit of
// the centre of a non-exterior leaf, by brute force over the leaf centres (and the bound of the
// library on the rounding of the radius).
void check_flow_zones(const Grid& g, const PD::Fitting_zones& z, const std::vector<int>& fitting_resolutions,
                      double tolerance, double voxel)
{
  std::vector<std::size_t> hull;
  for(std::size_t l = 0; l < g.number_of_leaves(); ++l)
    if(!z.exterior[l]) hull.push_back(l);
  std::vector<double> to_hull(g.number_of_leaves());
  for(std::size_t l = 0; l < g.number_of_leaves(); ++l)
    to_hull[l] = z.exterior[l] ? brute_force_squared_distance(g, g.center(l), hull, false) : 0.;
  for(int r_fit : fitting_resolutions)
  {
    REQUIRE(z.flow_zone.count(r_fit) == 1);
    const Flags& flow = z.flow_zone.at(r_fit);
    REQUIRE(flow.size() == g.number_of_leaves());
    const double radius = tolerance / r_fit, limit = radius * radius * (1. + 1e-12) + 1e-9 * voxel * voxel;
    std::size_t wrong = 0, inside = 0;
    for(std::size_t l = 0; l < g.number_of_leaves(); ++l)
    {
      const bool expected = to_hull[l] <= limit;
      if(flow[l] != (expected ? 1 : 0))
      {
        if(wrong < 5)
          WARN("r_fit " << r_fit << ": leaf " << l << " of width " << g.width(l) << " at " << std::sqrt(to_hull[l]) / radius
               << " radii from the hull, in the zone: " << int(flow[l]));
        ++wrong;
      }
      inside += expected && z.exterior[l] ? 1 : 0;
    }
    INFO("r_fit " << r_fit << ": " << inside << " exterior leaves in the zone");
    CHECK(wrong == 0);
    CHECK(inside > 0);
  }
}

} // namespace

TEST_CASE("Fitting zones of a hand-made prior on the dense grid", "[tsdf][zones]")
{
  // A shell of Flow voxels [4,11]^3 in a 16^3 grid, its z = 4 face Freeze, with a hole of 2 x 2
  // voxels in its z = 11 face. The distance field is that of the cube [4,12)^3 of voxels, on whose
  // surface the occupied voxels lie (what the zones assume of a field and a prior).
  const int r = 16;
  PD::Hierarchical_prior prior;
  prior.resolutions = {r};
  prior.classes = PD::Voxel_grid<PD::Voxel_class>(r, PD::Voxel_class::EMPTY);
  prior.leaf_resolution = PD::Voxel_grid<std::uint16_t>(r, 0);
  auto in_cube = [](const std::array<int, 3>& v) {
    return v[0] >= 4 && v[0] <= 11 && v[1] >= 4 && v[1] <= 11 && v[2] >= 4 && v[2] <= 11;
  };
  auto in_shell = [&](const std::array<int, 3>& v) {
    const bool hole = v[2] == 11 && (v[0] == 7 || v[0] == 8) && (v[1] == 7 || v[1] == 8);
    return in_cube(v) && !hole && (v[0] == 4 || v[0] == 11 || v[1] == 4 || v[1] == 11 || v[2] == 4 || v[2] == 11);
  };
  for(std::size_t v = 0; v < prior.classes.size(); ++v)
  {
    const std::array<int, 3> c = prior.classes.coordinates(v);
    if(!in_shell(c)) continue;
    prior.classes[v] = c[2] == 4 ? PD::Voxel_class::FREEZE : PD::Voxel_class::FLOW;
    prior.leaf_resolution[v] = c[2] == 4 ? 16 : 8;
  }
  for(double truncation : {0.3, 1.})
  {
    PD::Truncated_signed_distance_field tsdf;
    tsdf.grid = Grid::uniform(r);
    tsdf.truncation = truncation;
    tsdf.voxel_size = 1. / r;
    for(std::size_t l = 0; l < tsdf.grid.number_of_leaves(); ++l)
      tsdf.values.push_back(std::max(-truncation, std::min(truncation, sd_box(tsdf.grid.center(l), {{-0.25, -0.25, -0.25}}, {{0.25, 0.25, 0.25}}))));
    const PD::Fitting_zones z = PD::compute_fitting_zones(prior, tsdf, std::vector<int>{8, 4, 8});
    CHECK(z.flow_zone.size() == 2);
    for(std::size_t v = 0; v < prior.classes.size(); ++v)
    {
      const std::array<int, 3> c = prior.classes.coordinates(v);
      const bool cube = in_cube(c), shell = in_shell(c);
      CHECK(z.classes[v] == prior.classes[v]);
      CHECK(z.leaf_resolution[v] == prior.leaf_resolution[v]);
      CHECK(z.occupied[v] == (shell ? 1 : 0));
      // the hole does not let the outside in: the exterior is the field's
      CHECK(z.exterior[v] == (cube ? 0 : 1));
      CHECK(z.freeze_zone[v] == ((!cube || (shell && c[2] == 4)) ? 1 : 0));
    }
    check_flow_zones(tsdf.grid, z, {4, 8}, 2., 1. / r);
    // the r_fit = 8 zone is the cube grown by 4 voxels between centres: [0,15]^3 along the axes
    CHECK(z.flow_zone.at(8)[tsdf.grid.leaf_of_voxel(0, 8, 8)] == 1);
    CHECK(z.flow_zone.at(8)[tsdf.grid.leaf_of_voxel(0, 0, 8)] == 0);

    const PD::Fitting_zones no_freeze = PD::compute_fitting_zones(prior, tsdf, std::vector<int>{8}, switches(&Variant::use_freeze_zone, false));
    CHECK(no_freeze.freeze_zone == no_freeze.exterior);
    const PD::Fitting_zones tight = PD::compute_fitting_zones<CGAL::Parallel_if_available_tag>(
      prior, tsdf, std::vector<int>{8}, PD::parameters::flow_zone_tolerance(0.));
    for(std::size_t v = 0; v < tight.exterior.size(); ++v) CHECK(tight.flow_zone.at(8)[v] == 1 - tight.exterior[v]);
    CHECK(PD::compute_fitting_zones<CGAL::Parallel_if_available_tag>(prior, tsdf, std::vector<int>{8, 4}).flow_zone == z.flow_zone);
  }

  // On leaves finer than the prior's voxels, a Flow voxel carries the surface only in the leaves it
  // may cross, a Freeze voxel is Freeze whole; both give their resolution.
  PD::Truncated_signed_distance_field fine;
  fine.grid = Grid::uniform(2 * r);
  fine.truncation = 1.;
  for(std::size_t l = 0; l < fine.grid.number_of_leaves(); ++l)
    fine.values.push_back(l % 3 == 0 ? 0.5 / (2 * r) : 0.5);
  const PD::Fitting_zones split = PD::compute_fitting_zones(prior, fine, std::vector<int>{8});
  for(std::size_t l = 0; l < fine.grid.number_of_leaves(); ++l)
  {
    const Grid::Voxel& c = fine.grid.corner(l);
    const std::size_t v = prior.classes.index(int(c[0] / 2), int(c[1] / 2), int(c[2] / 2));
    const bool crossed = l % 3 == 0;
    CHECK(split.classes[l] == (prior.classes[v] == PD::Voxel_class::FLOW && !crossed ? PD::Voxel_class::EMPTY : prior.classes[v]));
    CHECK(split.leaf_resolution[l] == prior.leaf_resolution[v]);
  }

  PD::Truncated_signed_distance_field tsdf;
  tsdf.grid = Grid::uniform(r);
  tsdf.values.assign(tsdf.grid.number_of_leaves(), 1.);
  CHECK_THROWS_AS(PD::compute_fitting_zones(prior, tsdf, std::vector<int>{0}), PD::Invalid_input);
  CHECK_THROWS_AS(PD::compute_fitting_zones(prior, tsdf, std::vector<int>{8}, PD::parameters::flow_zone_tolerance(-1.)),
                  PD::Invalid_input);
  PD::Truncated_signed_distance_field coarse;
  coarse.grid = Grid::uniform(8);
  coarse.values.assign(coarse.grid.number_of_leaves(), 1.);
  CHECK_THROWS_AS(PD::compute_fitting_zones(prior, coarse, std::vector<int>{8}), PD::Invalid_input);
  PD::Truncated_signed_distance_field short_values = tsdf;
  short_values.values.pop_back();
  CHECK_THROWS_AS(PD::compute_fitting_zones(prior, short_values, std::vector<int>{8}), PD::Invalid_input);
  CHECK_THROWS_AS(PD::compute_fitting_zones(PD::Hierarchical_prior(), tsdf, std::vector<int>{8}), PD::Invalid_input);
}

TEST_CASE("Fitting zones on the adaptive grid of a generated shape, by brute force over the leaves", "[tsdf][zones]")
{
  // An L of two plates 0.03 thick, with a junction (Freeze) and plates thin enough for the finest
  // leaves; a grid of finest resolution 64 over a prior at 16 and 32: leaves coarser and finer than
  // the prior's voxels.
  const Mesh m = test_shapes::make_l_bracket(1., 1., 0.03, 0.8, 0.1);
  const auto np = PD::parameters::combine(PD::parameters::voxel_resolutions(std::vector<int>{16, 32}),
                                          PD::parameters::grid_resolution(64));
  const PD::Hierarchical_prior prior = PD::compute_flow_freeze_prior(m, np);
  const PD::Truncated_signed_distance_field tsdf = PD::compute_tsdf(m, prior, np);
  const Grid& g = tsdf.grid;
  REQUIRE(g.finest_resolution() == 64);
  REQUIRE(prior.classes.resolution() == 32);
  const std::vector<int> fitting = {4, 8, 16};
  const PD::Fitting_zones z = PD::compute_fitting_zones(prior, tsdf, fitting);
  const std::size_t n = g.number_of_leaves();
  REQUIRE(z.classes.size() == n);
  INFO(n << " leaves");
  // the prior on the leaves, from the prior voxels each leaf holds or lies in
  std::size_t finer = 0, coarser = 0, freeze = 0, flow = 0;
  for(std::size_t l = 0; l < n; ++l)
  {
    const bool crossed = std::abs(tsdf.values[l]) <= half_diagonal(g, l) * (1. + 1e-9);
    const Grid::Voxel& c = g.corner(l);
    PD::Voxel_class cls = PD::Voxel_class::EMPTY;
    std::uint16_t res = 0;
    if(g.width(l) < 2) // half a prior voxel: the class of the voxel it lies in
    {
      ++finer;
      const std::size_t v = prior.classes.index(int(c[0] / 2), int(c[1] / 2), int(c[2] / 2));
      res = prior.leaf_resolution[v];
      if(prior.classes[v] == PD::Voxel_class::FREEZE || (prior.classes[v] == PD::Voxel_class::FLOW && crossed))
        cls = prior.classes[v];
    }
    else if(crossed) // Freeze if one of its prior voxels is, the finest of their resolutions
    {
      ++coarser;
      const int w = int(g.width(l) / 2);
      for(int k = int(c[2] / 2); k < int(c[2] / 2) + w; ++k)
        for(int j = int(c[1] / 2); j < int(c[1] / 2) + w; ++j)
          for(int i = int(c[0] / 2); i < int(c[0] / 2) + w; ++i)
          {
            const PD::Voxel_class p = prior.classes(i, j, k);
            if(p == PD::Voxel_class::EMPTY) continue;
            if(cls != PD::Voxel_class::FREEZE) cls = p;
            res = std::max(res, prior.leaf_resolution(i, j, k));
          }
    }
    CHECK(z.classes[l] == cls);
    CHECK(z.leaf_resolution[l] == res);
    const bool occupied = cls != PD::Voxel_class::EMPTY, exterior = !occupied && !std::signbit(tsdf.values[l]);
    CHECK(z.occupied[l] == (occupied ? 1 : 0));
    CHECK(z.exterior[l] == (exterior ? 1 : 0));
    CHECK(z.freeze_zone[l] == ((exterior || cls == PD::Voxel_class::FREEZE) ? 1 : 0));
    freeze += cls == PD::Voxel_class::FREEZE ? 1 : 0;
    flow += cls == PD::Voxel_class::FLOW ? 1 : 0;
  }
  CHECK(finer > 0);
  CHECK(coarser > 0);
  CHECK(freeze > 0);
  CHECK(flow > 0);
  check_flow_zones(g, z, fitting, 2., 1. / 32.);
  // the inside of a plate is not exterior
  const std::array<double, 3> in_plate = tsdf.normalization.to_unit(0.5, 0.015, 0.4);
  CHECK(z.exterior[g.locate(in_plate[0], in_plate[1], in_plate[2])] == 0);
}

TEST_CASE("an open sheet has no inside, a sphere with a hole of a tenth of its area keeps its inside", "[tsdf][zones][open]")
{
  // A flat square: the winding number is below 1/2 on both sides. A gently wavy sheet: above 1/2
  // only in a layer of at most one voxel on the concave side of its dips, where the sheet covers
  // a little more than half of the directions; it holds no volume.
  for(double amplitude : {0., 0.05})
  {
    const PD::Truncated_signed_distance_field tsdf = PD::compute_tsdf(test_shapes::make_wavy_sheet(20, amplitude));
    const double deepest = *std::min_element(tsdf.values.begin(), tsdf.values.end());
    if(amplitude == 0.) CHECK(deepest >= 0.);
    CHECK(deepest > -1. / 64.);
  }

  // the unit sphere without its cap z > 0.8 (a tenth of its area): a hole 0.6 wide
  const Mesh sphere = test_shapes::make_sphere(Point(0, 0, 0), 1., 4);
  const Mesh open = without_cap(sphere, 0.8);
  REQUIRE(!CGAL::is_closed(open));
  // the same normalization for both, so that their leaves compare
  const PD::Normalization frame = PD::compute_normalization(sphere);
  const PD::Truncated_signed_distance_field closed_field = PD::compute_tsdf(sphere, PD::parameters::normalization(frame));
  const PD::Truncated_signed_distance_field open_field = PD::compute_tsdf(open, PD::parameters::normalization(frame));
  // the dense grid: on the adaptive one the fill is blocked by large leaves (known failure below)
  const PD::Truncated_signed_distance_field filled = PD::compute_tsdf(
    open, PD::parameters::combine(PD::parameters::normalization(frame), switches(&Variant::adaptive_grid, false),
                                  PD::parameters::tsdf_sign_method(PD::Tsdf_sign_method::FLOOD_FILL)));
  const double closed_volume = inside_volume(closed_field), open_volume = inside_volume(open_field);
  INFO("inside volume: closed " << closed_volume << ", open " << open_volume << ", open by flood fill " << inside_volume(filled));
  // the ball of radius 0.47 (0.43 of the cube)
  CHECK(closed_volume == Approx(4. / 3. * std::acos(-1.) * std::pow(frame.scale(), 3)).epsilon(0.02));
  // the segment of the ball under the missing cap (2.8% of its volume) may go either way
  CHECK(open_volume >= 0.96 * closed_volume);
  CHECK(open_volume <= closed_volume * (1. + 1e-3));
  // the paper's fill leaks through the hole: the ball is outside but for the leaves the surface
  // may cross
  std::size_t deep_inside = 0;
  for(std::size_t l = 0; l < filled.values.size(); ++l)
  {
    const std::array<double, 3> c = filled.grid.center(l);
    deep_inside += std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]) < 0.9 * frame.scale() && filled.values[l] < 0. ? 1 : 0;
  }
  CHECK(deep_inside == 0);

  // the zones take their exterior from the field: the ball stays open to the fitter
  const PD::Hierarchical_prior prior = PD::compute_flow_freeze_prior(open, PD::parameters::normalization(frame));
  const PD::Truncated_signed_distance_field open_on_prior = PD::compute_tsdf(open, prior, PD::parameters::normalization(frame));
  for(const PD::Truncated_signed_distance_field* field : {&open_field, &open_on_prior})
  {
    const PD::Fitting_zones zones = PD::compute_fitting_zones(prior, *field, PD::fitting_resolutions(prior.resolutions));
    std::size_t exterior_in_ball = 0;
    for(std::size_t l = 0; l < zones.exterior.size(); ++l)
    {
      const std::array<double, 3> c = field->grid.center(l);
      const double radius = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]) / frame.scale();
      if(radius + half_diagonal(field->grid, l) / frame.scale() < 0.7 && zones.exterior[l]) ++exterior_in_ball;
    }
    CHECK(exterior_in_ball == 0);
  }
}

// ------------------------------------------------------------------- the paper's flood fill

// FLOOD_FILL gives a leaf the surface may meet the side of its neighbours the surface does not
// meet: an open sheet bounds nothing, on the adaptive and the dense grid.
TEST_CASE("FLOOD_FILL leaves an open sheet outside", "[tsdf][sign]")
{
  Mesh m;
  const auto a = m.add_vertex(Point(0, 0, 0)), b = m.add_vertex(Point(1, 0, 0.3)), c = m.add_vertex(Point(1, 1, 0.5)),
             d = m.add_vertex(Point(0, 1, 0.2));
  m.add_face(a, b, c);
  m.add_face(a, c, d);
  for(bool adaptive : {true, false})
  {
    const PD::Truncated_signed_distance_field tsdf = PD::compute_tsdf(
      m, PD::parameters::combine(PD::parameters::tsdf_sign_method(PD::Tsdf_sign_method::FLOOD_FILL),
                                 PD::parameters::voxel_resolutions(std::vector<int>{16}), switches(&Variant::adaptive_grid, adaptive)));
    const std::size_t negative = std::size_t(std::count_if(tsdf.values.begin(), tsdf.values.end(), [](double v) { return v < 0.; }));
    INFO((adaptive ? "adaptive" : "dense") << " grid: " << negative << " leaves of " << tsdf.values.size() << " inside");
    CHECK(negative == 0);
  }
}

// Whether the surface meets a leaf comes from the unclipped distance of its centre: a leaf whose
// half diagonal exceeds the truncation is no surface leaf unless the surface is near it, so the
// signs do not depend on the truncation, which does not change the grid.
TEST_CASE("the FLOOD_FILL sign of large leaves does not depend on the truncation", "[tsdf][sign]")
{
  const Mesh sphere = test_shapes::make_sphere(Point(0, 0, 0), 1., 4);
  const Mesh open = without_cap(sphere, 0.8);
  auto field = [&](double tau) {
    return PD::compute_tsdf(open, PD::parameters::combine(PD::parameters::tsdf_truncation(tau),
                                                          PD::parameters::tsdf_sign_method(PD::Tsdf_sign_method::FLOOD_FILL)));
  };
  const PD::Truncated_signed_distance_field tight = field(8.), loose = field(32.);
  REQUIRE(tight.grid == loose.grid);
  std::size_t large = 0, differ = 0;
  for(std::size_t l = 0; l < tight.values.size(); ++l)
  {
    large += half_diagonal(tight.grid, l) >= tight.truncation ? 1 : 0;
    differ += (tight.values[l] < 0.) != (loose.values[l] < 0.) ? 1 : 0;
  }
  INFO(large << " leaves with a half diagonal beyond the truncation; inside volume " << inside_volume(tight) << " at tau = 8, "
             << inside_volume(loose) << " at tau = 32");
  CHECK(differ == 0);
  // the fill leaks through the hole into the ball, as on the dense grid
  CHECK(value_at(tight, {{0., 0., 0.}}) > 0.);
}
