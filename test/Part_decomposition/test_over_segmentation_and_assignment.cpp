// The mesh side of the assignment (paper App. E.3, E.4): the curvature-aware over-segmentation
// into patches, and the distance-weighted vote (Eq. 9) that turns patches into parts.
#include <catch2/catch.hpp>

#include <CGAL/Part_decomposition/Adaptive_grid.h>
#include <CGAL/Part_decomposition/flow_freeze_prior.h>
#include <CGAL/Part_decomposition/over_segmentation.h>
#include <CGAL/Part_decomposition/primitive_assignment.h>
#include <CGAL/Part_decomposition/tsdf.h>
#include <CGAL/Part_decomposition/internal/fitting/claimed_leaf_search.h>
#include <CGAL/Part_decomposition/internal/toolbox/toolbox.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Aff_transformation_3.h>
#include <CGAL/Random.h>
#include <CGAL/boost/graph/helpers.h>

#include "shipped_shapes.h"
#include "method_switches.h"
#include "test_shapes.h"

#include <cmath>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace PD = CGAL::Part_decomposition;
namespace PDP = CGAL::Part_decomposition::parameters;
namespace PMP = CGAL::Polygon_mesh_processing;
using test_shapes::K;
using test_shapes::Mesh;
using test_shapes::Point;
typedef Mesh::Face_index face_descriptor;

namespace {

std::vector<std::size_t> patches_of(Mesh& m, std::size_t& count, double quantile = 90.,
                                    double min_size = 0.001, double max_size = 0.003, int smoothing = 1)
{
  auto map = m.add_property_map<face_descriptor, std::size_t>("f:test_patch", 0).first;
  count = PD::over_segment(m, map,
                           PD::parameters::combine(PD::parameters::dihedral_percentile(quantile),
                                                   PD::parameters::minimum_patch_size(min_size),
                                                   PD::parameters::patch_split_size(max_size),
                                                   PD::parameters::smoothing_iterations(smoothing)));
  std::vector<std::size_t> out;
  for(face_descriptor f : faces(m)) out.push_back(map[f]);
  m.remove_property_map(map);
  return out;
}

// Patch ids are 0..A-1, each used, numbered by first face, and each patch is edge-connected.
void check_patch_structure(Mesh& m, const std::vector<std::size_t>& patch, std::size_t count)
{
  REQUIRE(test_shapes::count_if_numbered_by_first_face(patch) == count);
  // Flood fill inside each patch only: one component per patch.
  Mesh& mm = m;
  auto comp = mm.add_property_map<face_descriptor, std::size_t>("f:test_comp", 0).first;
  auto is_border_of_patch = mm.add_property_map<Mesh::Edge_index, bool>("e:test_cut", false).first;
  for(auto e : edges(m))
  {
    const auto h = halfedge(e, m);
    if(is_border(e, m)) continue;
    is_border_of_patch[e] = patch[face(h, m)] != patch[face(opposite(h, m), m)];
  }
  const std::size_t n = PMP::connected_components(m, comp, CGAL::parameters::edge_is_constrained_map(is_border_of_patch));
  mm.remove_property_map(comp);
  mm.remove_property_map(is_border_of_patch);
  CHECK(n == count);
}

Mesh rotated(const Mesh& m)
{
  Mesh r = m;
  const double a = 0.7, b = 0.4;
  const CGAL::Aff_transformation_3<K> rz(std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a), 0, 0, 0, 1);
  const CGAL::Aff_transformation_3<K> rx(1, 0, 0, 0, std::cos(b), -std::sin(b), 0, std::sin(b), std::cos(b));
  for(auto v : vertices(r)) r.point(v) = (rx * rz).transform(r.point(v)) + K::Vector_3(3, -1, 2);
  return r;
}

// A flat strip of 2n triangles along x at height z in [x0, x0 + n*w]: faces 2i, 2i+1 in square i.
Mesh make_strip(double x0, double w, int n, double y0, double h, double z)
{
  test_shapes::Soup s;
  for(int i = 0; i < n; ++i)
  {
    const Point a(x0 + i * w, y0, z), b(x0 + (i + 1) * w, y0, z), c(x0 + (i + 1) * w, y0 + h, z),
        d(x0 + i * w, y0 + h, z);
    s.triangle(a, b, c);
    s.triangle(a, c, d);
  }
  return s.mesh();
}

// Claims as assign_parts() reads them: one label per leaf of the grid of a distance field, whose
// normalization and voxel size are the frame and the unit of lengths.
struct Claims
{
  PD::Truncated_signed_distance_field tsdf;
  std::vector<std::int32_t> labels;
};

// The claims of a dense grid on the uniform grid of its voxels (leaf index == voxel index), in the
// identity frame, lengths in its voxels.
Claims uniform_claims(const PD::Voxel_grid<std::int32_t>& claimed)
{
  Claims c;
  c.tsdf.grid = PD::Adaptive_grid::uniform(claimed.resolution());
  c.tsdf.values.assign(c.tsdf.grid.number_of_leaves(), 0.);
  c.tsdf.voxel_size = claimed.voxel_size();
  c.labels = claimed.values();
  return c;
}

std::vector<std::size_t> assign(Mesh& m, const std::vector<std::size_t>& patch, const Claims& claimed,
                                std::vector<std::size_t>& part, double temperature = 1.0, double smoothness = 0.)
{
  Mesh& mm = m;
  auto pmap = mm.add_property_map<face_descriptor, std::size_t>("f:test_in", 0).first;
  auto qmap = mm.add_property_map<face_descriptor, std::size_t>("f:test_out", 0).first;
  for(face_descriptor f : faces(m)) pmap[f] = patch[f];
  const std::vector<std::size_t> prim =
      PD::assign_parts(m, pmap, claimed.labels, claimed.tsdf, qmap,
                       PDP::combine(PDP::vote_temperature(temperature), PDP::boundary_smoothness(smoothness)));
  part.clear();
  for(face_descriptor f : faces(m)) part.push_back(qmap[f]);
  mm.remove_property_map(pmap);
  mm.remove_property_map(qmap);
  return prim;
}

double distance3(const std::array<double, 3>& a, const std::array<double, 3>& b)
{
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

// The nearest claimed leaf of a point u of the cube as specified, by brute force: the leaf of u if
// it is claimed, else the nearest centre of the claimed leaves with an unclaimed face neighbour
// (on a uniform grid, the nearest claimed centre).
PD::internal::Claimed_leaf_search<PD::Adaptive_grid>::Result specified_nearest(const PD::Adaptive_grid& grid,
                                                            const std::vector<std::int32_t>& labels,
                                                            const std::array<double, 3>& u)
{
  PD::internal::Claimed_leaf_search<PD::Adaptive_grid>::Result r;
  const std::size_t own = grid.locate(u[0], u[1], u[2]);
  if(labels[own] >= 0)
  {
    r.label = labels[own];
    r.distance = distance3(u, grid.center(own));
    return r;
  }
  r.distance = 1e30;
  for(std::size_t l = 0; l < grid.number_of_leaves(); ++l)
  {
    if(labels[l] < 0) continue;
    bool boundary = false;
    grid.for_each_neighbor(l, [&](std::size_t n) { boundary = boundary || labels[n] < 0; });
    if(!boundary) continue;
    const double d = distance3(u, grid.center(l));
    if(d < r.distance) r.distance = d, r.label = labels[l];
  }
  return r;
}

// Brute-force Eq. 9: the specified nearest claimed leaf of each face centroid, weights, argmax.
std::vector<std::int32_t> brute_force_votes(const Mesh& m, const std::vector<std::size_t>& patch,
                                            const Claims& claimed, double temperature)
{
  std::map<std::size_t, std::map<std::int32_t, double> > votes;
  const double tau = temperature * claimed.tsdf.voxel_size;
  for(face_descriptor f : faces(m))
  {
    const Point c = CGAL::centroid(m.point(source(halfedge(f, m), m)), m.point(target(halfedge(f, m), m)),
                                   m.point(target(next(halfedge(f, m), m), m)));
    const PD::internal::Claimed_leaf_search<PD::Adaptive_grid>::Result r =
      specified_nearest(claimed.tsdf.grid, claimed.labels, claimed.tsdf.normalization.to_unit(c.x(), c.y(), c.z()));
    votes[patch[f]][r.label] += std::exp(-r.distance / tau);
  }
  std::vector<std::int32_t> out;
  for(const auto& pv : votes)
  {
    std::int32_t arg = -1;
    double w = -1.;
    for(const auto& kv : pv.second)
      if(kv.second > w) w = kv.second, arg = kv.first;
    out.push_back(arg);
  }
  return out;
}

// Three primitives claiming slabs of the ball of radius 0.3: 9 for x < -0.1, 5 for
// -0.1 <= x < 0.15, 2 above; on the leaves of `grid` whose centre lies in the ball.
std::vector<std::int32_t> three_slab_labels(const PD::Adaptive_grid& grid)
{
  std::vector<std::int32_t> labels(grid.number_of_leaves(), -1);
  for(std::size_t l = 0; l < labels.size(); ++l)
  {
    const auto c = grid.center(l);
    if(c[0] * c[0] + c[1] * c[1] + c[2] * c[2] > 0.3 * 0.3) continue;
    labels[l] = c[0] < -0.1 ? 9 : (c[0] < 0.15 ? 5 : 2);
  }
  return labels;
}

// The three slabs on the voxels of the 16^3 grid.
Claims three_slab_claims()
{
  Claims c = uniform_claims(PD::Voxel_grid<std::int32_t>(16, -1));
  c.labels = three_slab_labels(c.tsdf.grid);
  return c;
}

} // namespace

TEST_CASE("the dihedral threshold interpolates linearly between the closest ranks", "[over_segmentation]")
{
  std::vector<double> v = {30., 0., 20., 10.};
  CHECK(PD::internal::percentile(v, 50.) == Approx(15.));
  v = {30., 0., 20., 10.};
  CHECK(PD::internal::percentile(v, 90.) == Approx(27.));
  v = {30., 0., 20., 10.};
  CHECK(PD::internal::percentile(v, 100.) == 30.);
  v = {30., 0., 20., 10.};
  CHECK(PD::internal::percentile(v, 0.) == 0.);
  v = {5.};
  CHECK(PD::internal::percentile(v, 90.) == 5.);
}

TEST_CASE("a cube gives its 6 sides, whatever the tessellation and placement", "[over_segmentation]")
{
  for(int n : {1, 2, 3, 8})
    for(bool rotate : {false, true})
    {
      INFO("n = " << n << " rotated = " << rotate);
      Mesh m = test_shapes::make_box(Point(0, 0, 0), Point(1, 2, 1.5), n);
      if(rotate) m = rotated(m);
      std::size_t count = 0;
      const std::vector<std::size_t> patch = patches_of(m, count);
      REQUIRE(count == 6);
      check_patch_structure(m, patch, count);
      // each patch is exactly one side: its faces share one normal, and it holds 2 n^2 faces
      std::map<std::size_t, std::vector<K::Vector_3> > normals;
      for(face_descriptor f : faces(m)) normals[patch[f]].push_back(PMP::compute_face_normal(f, m));
      for(const auto& pn : normals)
      {
        CHECK(pn.second.size() == std::size_t(2 * n * n));
        for(const auto& v : pn.second) CHECK(v * pn.second.front() > 1. - 1e-9);
      }
    }
}

TEST_CASE("a smooth sphere gives a few hundred compact patches", "[over_segmentation]")
{
  Mesh m = test_shapes::make_sphere(Point(0, 0, 0), 1., 4); // 5120 faces
  std::size_t count = 0;
  const std::vector<std::size_t> patch = patches_of(m, count);
  check_patch_structure(m, patch, count);
  // every patch is below patch_split_size + minimum_patch_size of the area (up to a face)
  // and the clean-up leaves none below minimum_patch_size after smoothing by more than a face
  std::map<std::size_t, double> area;
  double total = 0.;
  for(face_descriptor f : faces(m))
  {
    area[patch[f]] += PMP::face_area(f, m);
    total += PMP::face_area(f, m);
  }
  const double face_area = total / 5120.;
  for(const auto& pa : area)
  {
    CHECK(pa.second <= (0.003 + 0.001) * total + 3 * face_area);
    CHECK(pa.second >= 0.001 * total - 3 * face_area);
  }
  CHECK(count >= 250);
  CHECK(count <= 1000);

  // Without the size cap the paper's flood fill alone leaks through the sparse cuts of a smooth
  // surface: far fewer patches.
  std::size_t uncapped = 0;
  patches_of(m, uncapped, 90., 0.001, 1.0);
  CHECK(uncapped < count / 4);
}

TEST_CASE("the result does not depend on the number of threads", "[over_segmentation]")
{
  Mesh m = test_shapes::make_sphere(Point(0, 0, 0), 1., 5); // 20480 faces
  auto a = m.add_property_map<face_descriptor, std::size_t>("f:a", 0).first;
  auto b = m.add_property_map<face_descriptor, std::size_t>("f:b", 0).first;
  const std::size_t na = PD::over_segment<CGAL::Sequential_tag>(m, a);
  const std::size_t nb = PD::over_segment<CGAL::Parallel_if_available_tag>(m, b);
  CHECK(na == nb);
  std::size_t differ = 0;
  for(face_descriptor f : faces(m)) differ += a[f] != b[f];
  CHECK(differ == 0);
}

TEST_CASE("the clean-up merges fragments across their weakest edge, smallest first", "[over_segmentation]")
{
  // Hand-made face graph: patch 0 = faces {0, 1}, fragment {2}, patch 2 = faces {3, 4}.
  // Face 2 touches face 1 across a 40 degree edge and face 3 across a 25 degree edge.
  PD::internal::Face_adjacency adj;
  const std::size_t no = PD::internal::Face_adjacency::no_face;
  adj.number_of_faces = 5;
  adj.neighbor = {1, no, no, /**/ 0, 2, no, /**/ 1, 3, no, /**/ 2, 4, no, /**/ 3, no, no};
  adj.angle = {5, 0, 0, /**/ 5, 40, 0, /**/ 40, 25, 0, /**/ 25, 5, 0, /**/ 5, 0, 0};
  adj.area = {1., 1., 0.05, 1., 1.};
  adj.degenerate.assign(5, 0);
  std::vector<std::size_t> label = {0, 0, 1, 2, 2};
  PD::internal::merge_small_patches(adj, label, 3, 0.5);
  CHECK(label == std::vector<std::size_t>({0, 0, 2, 2, 2}));

  // A chain of two fragments: the smaller one (face 2) goes first, into face 1 (10 < 30 degrees),
  // then the merged piece (area 0.3) is still small and follows its weakest remaining edge.
  adj.angle = {5, 0, 0, /**/ 5, 10, 0, /**/ 10, 30, 0, /**/ 30, 20, 0, /**/ 20, 0, 0};
  adj.area = {1., 0.2, 0.1, 0.2, 1.};
  label = {0, 1, 2, 3, 4};
  PD::internal::merge_small_patches(adj, label, 5, 0.35);
  // face 2 -> face 1 (area 0.3, still small) -> merges across its weakest edge: 5 deg to face 0;
  // face 3 (0.2) -> weakest edge 20 deg to face 4.
  CHECK(label == std::vector<std::size_t>({0, 0, 0, 4, 4}));

  // Through the public function: with minimum_patch_size above 1/6 every side of a two-triangle
  // cube is a fragment. All edges are 90 degrees: ties go to the smaller neighbour, so sides pair
  // up first and the last two join the pairs: two patches of three sides.
  Mesh cube = test_shapes::make_box(Point(0, 0, 0), Point(1, 1, 1), 1);
  std::size_t count = 0;
  const std::vector<std::size_t> patch = patches_of(cube, count, 90., 0.2);
  CHECK(count == 2);
  check_patch_structure(cube, patch, count);
  std::map<std::size_t, int> sizes;
  for(std::size_t p : patch) ++sizes[p];
  for(const auto& s : sizes) CHECK(s.second == 6);
}

TEST_CASE("boundary smoothing moves a face to the patch of two of its neighbours", "[over_segmentation]")
{
  // Face 0 (patch 0) has neighbours 1, 2 in patch 1 and 3 in patch 0: it moves to patch 1.
  // Face 4 (patch 2) has neighbours 5, 6 in patch 3, but face 5 would move itself (two of its
  // neighbours are in patch 2): neither counts the other, both keep their patch.
  PD::internal::Face_adjacency adj;
  const std::size_t no = PD::internal::Face_adjacency::no_face;
  adj.number_of_faces = 9;
  adj.neighbor = {1, 2, 3, /*1*/ 0, no, no, /*2*/ 0, no, no, /*3*/ 0, no, no,
                  /*4*/ 5, 6, 7, /*5*/ 4, 8, no, /*6*/ 4, no, no, /*7*/ 4, no, no, /*8*/ 5, no, no};
  adj.angle.assign(27, 10.);
  adj.area.assign(9, 1.);
  adj.degenerate.assign(9, 0);
  std::vector<std::size_t> label = {0, 1, 1, 0, 2, 3, 3, 2, 2};
  const std::size_t moved = PD::internal::smooth_patch_boundaries<CGAL::Sequential_tag>(adj, label);
  CHECK(moved == 1);
  CHECK(label == std::vector<std::size_t>({1, 1, 1, 0, 2, 3, 3, 2, 2}));
}

TEST_CASE("zero-area faces and open meshes give valid patches", "[over_segmentation]")
{
  // a strip with a zero-area triangle glued on its border edge
  test_shapes::Soup s;
  s.triangle(Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0));
  s.triangle(Point(0, 0, 0), Point(1, 1, 0), Point(0, 1, 0));
  s.triangle(Point(1, 0, 0), Point(0, 0, 0), Point(0.5, 0, 0)); // collinear: zero area
  Mesh m = s.mesh();
  REQUIRE(num_faces(m) == 3);
  std::size_t count = 0;
  const std::vector<std::size_t> patch = patches_of(m, count, 90., 0.0);
  CHECK(count == 2); // the flat square, and the degenerate face on its own
  check_patch_structure(m, patch, count);
  patches_of(m, count); // clean-up on: the zero-area face is merged
  CHECK(count == 1);
}

TEST_CASE("invalid over-segmentation parameters throw", "[over_segmentation]")
{
  Mesh m = test_shapes::make_box(Point(0, 0, 0), Point(1, 1, 1), 1);
  auto map = m.add_property_map<face_descriptor, std::size_t>("f:x", 0).first;
  CHECK_THROWS_AS(PD::over_segment(m, map, PD::parameters::dihedral_percentile(101.)), PD::Invalid_input);
  CHECK_THROWS_AS(PD::over_segment(m, map, PD::parameters::minimum_patch_size(-0.1)), PD::Invalid_input);
  CHECK_THROWS_AS(PD::over_segment(m, map, PD::parameters::patch_split_size(0.)), PD::Invalid_input);
  CHECK_THROWS_AS(PD::over_segment(m, map, PD::parameters::smoothing_iterations(-1)), PD::Invalid_input);
}

TEST_CASE("over_segment with every default given explicitly gives the default patches", "[over_segmentation][defaults]")
{
  Mesh m = test_shapes::make_sphere(Point(0, 0, 0), 1., 4); // 5120 faces
  std::vector<std::size_t> a(num_faces(m)), b(num_faces(m));
  const std::size_t na = PD::over_segment(m, CGAL::make_property_map(a));
  const std::size_t nb = PD::over_segment(
      m, CGAL::make_property_map(b),
      PDP::combine(CGAL::parameters::vertex_point_map(get(CGAL::vertex_point, m))
                       .face_index_map(get(CGAL::face_index, m))
                       .geom_traits(K()),
                   PDP::dihedral_percentile(PD::defaults::dihedral_percentile),
                   PDP::minimum_patch_size(PD::defaults::minimum_patch_size),
                   PDP::patch_split_size(PD::defaults::patch_split_size),
                   PDP::smoothing_iterations(PD::defaults::smoothing_iterations)));
  CHECK(na == nb);
  CHECK(a == b);
  // patches of 0.1 to 0.2 percent of the area
  CHECK(na >= 400);
  CHECK(na <= 1000);
}

TEST_CASE("dihedral_percentile and patch_split_size reach the over-segmentation", "[over_segmentation]")
{
  Mesh m = test_shapes::make_sphere(Point(0, 0, 0), 1., 4);
  std::vector<std::size_t> given(num_faces(m)), by_default(num_faces(m));
  const auto np = PDP::combine(PDP::dihedral_percentile(80.), PDP::patch_split_size(0.01));
  // a cap twenty times the default gives fewer patches
  CHECK(PD::over_segment(m, CGAL::make_property_map(given), np) < PD::over_segment(m, CGAL::make_property_map(by_default)));
}

TEST_CASE("the nearest claimed leaf of a uniform grid is exact, near and far from the claims", "[assignment]")
{
  const int r = 16;
  PD::Voxel_grid<std::int32_t> claimed(r, -1);
  CGAL::Random rng(7);
  for(std::size_t idx = 0; idx < claimed.size(); ++idx)
    if(rng.get_double() < 0.03) claimed[idx] = rng.get_int(0, 5);
  // a solid block too, so that the kd-tree skips interior leaves
  for(int k = 2; k < 7; ++k)
    for(int j = 2; j < 7; ++j)
      for(int i = 2; i < 7; ++i) claimed(i, j, k) = 9;
  const PD::Adaptive_grid grid = PD::Adaptive_grid::uniform(r);
  const std::vector<std::int32_t>& labels = claimed.values();
  PD::internal::Claimed_leaf_search<PD::Adaptive_grid> search;
  search.build<CGAL::Sequential_tag>(grid, labels);
  REQUIRE(search.any());
  std::size_t claimed_count = 0;
  for(std::int32_t l : labels) claimed_count += l >= 0;
  CHECK(search.tree_size() <= claimed_count - 27); // the 3x3x3 core of the block is left out
  for(int n = 0; n < 3000; ++n)
  {
    const std::array<double, 3> u = {{rng.get_double(-0.8, 0.8), rng.get_double(-0.8, 0.8), rng.get_double(-0.8, 0.8)}};
    double best = 1e30;
    std::int32_t label = -1;
    for(std::size_t l = 0; l < grid.number_of_leaves(); ++l)
    {
      if(labels[l] < 0) continue;
      const double d = distance3(u, grid.center(l));
      if(d < best) best = d, label = labels[l];
    }
    const PD::internal::Claimed_leaf_search<PD::Adaptive_grid>::Result res = search.nearest(u);
    CHECK(res.distance == Approx(best).epsilon(1e-12));
    CHECK(res.label == label);
  }
  // nothing claimed
  PD::internal::Claimed_leaf_search<PD::Adaptive_grid> none;
  none.build<CGAL::Sequential_tag>(grid, std::vector<std::int32_t>(grid.number_of_leaves(), -1));
  CHECK_FALSE(none.any());
}

namespace {

// A random octree of the cube down to resolution 32: the cube and its children always split,
// deeper cells with probability one half.
PD::Adaptive_grid random_octree(CGAL::Random& rng)
{
  std::vector<PD::Adaptive_grid::Cell> cells;
  std::vector<PD::Adaptive_grid::Cell> stack(1, PD::Adaptive_grid::Cell{0, {{0, 0, 0}}});
  while(!stack.empty())
  {
    const PD::Adaptive_grid::Cell c = stack.back();
    stack.pop_back();
    if(c.depth == 5 || (c.depth >= 2 && rng.get_double() < 0.5))
    {
      cells.push_back(c);
      continue;
    }
    for(std::uint32_t child = 0; child < 8; ++child)
      stack.push_back(PD::Adaptive_grid::Cell{
        c.depth + 1, {{2 * c.position[0] + (child & 1), 2 * c.position[1] + ((child >> 1) & 1), 2 * c.position[2] + (child >> 2)}}});
  }
  return PD::Adaptive_grid(32, cells);
}

} // namespace

TEST_CASE("the nearest claimed leaf of an adaptive grid: its own leaf, else the nearest claimed boundary leaf", "[assignment]")
{
  CGAL::Random rng(11);
  for(int trial = 0; trial < 3; ++trial)
  {
    CAPTURE(trial);
    const PD::Adaptive_grid grid = random_octree(rng);
    // leaves of several sizes, the test means something
    REQUIRE(grid.number_of_leaves_of_depth(5) > 0);
    REQUIRE(grid.number_of_leaves_of_depth(3) > 0);
    std::vector<std::int32_t> labels(grid.number_of_leaves(), -1);
    for(std::size_t l = 0; l < labels.size(); ++l)
    {
      const auto c = grid.center(l);
      if(c[0] > -0.3 && c[0] < 0. && c[1] > -0.3 && c[1] < 0. && c[2] > -0.3 && c[2] < 0.) labels[l] = 9; // a solid block
      else if(rng.get_double() < 0.1) labels[l] = rng.get_int(0, 5);
    }
    PD::internal::Claimed_leaf_search<PD::Adaptive_grid> search;
    search.build<CGAL::Sequential_tag>(grid, labels);
    REQUIRE(search.any());
    std::size_t inner = 0; // claimed leaves with every neighbour claimed: not in the tree
    for(std::size_t l = 0; l < grid.number_of_leaves(); ++l)
    {
      bool boundary = false;
      grid.for_each_neighbor(l, [&](std::size_t n) { boundary = boundary || labels[n] < 0; });
      inner += labels[l] >= 0 && !boundary;
    }
    REQUIRE(inner > 0);
    std::size_t claimed_count = 0;
    for(std::int32_t l : labels) claimed_count += l >= 0;
    CHECK(search.tree_size() == claimed_count - inner);
    std::size_t own = 0;
    for(int n = 0; n < 2000; ++n)
    {
      const std::array<double, 3> u = {{rng.get_double(-0.5, 0.5), rng.get_double(-0.5, 0.5), rng.get_double(-0.5, 0.5)}};
      const PD::internal::Claimed_leaf_search<PD::Adaptive_grid>::Result expected = specified_nearest(grid, labels, u);
      const PD::internal::Claimed_leaf_search<PD::Adaptive_grid>::Result res = search.nearest(u);
      own += labels[grid.locate(u[0], u[1], u[2])] >= 0;
      CHECK(res.distance == Approx(expected.distance).epsilon(1e-12));
      CHECK(res.label == expected.label);
    }
    // both branches of the specification were exercised
    CHECK(own > 100);
    CHECK(own < 1900);
  }
}

TEST_CASE("a patch takes the distance-weighted majority of its faces", "[assignment]")
{
  // Grid r = 8 (voxel 0.125) over the identity normalization. The strip lies at z = 0.01 along x
  // in [-0.5, 0.5), y in [0, 0.1): 16 squares, 32 faces, in voxels of row (j = 4, k = 4).
  Mesh m = make_strip(-0.5, 1. / 16., 16, 0., 0.1, 0.01);
  const int r = 8;
  PD::Voxel_grid<std::int32_t> voxels(r, -1);
  // Primitive 7 claims the first voxel along the strip (faces 0..3 lie inside it): faces 0..11
  // are nearest to it, at 0.5 to 2.3 voxels. Primitive 3 claims the voxels two rows above the
  // rest of the strip: faces 12..31 are nearest to it, each about 2.4 voxels away. The near
  // minority outweighs the far majority.
  voxels(0, 4, 4) = 7;
  for(int i = 2; i < 8; ++i) voxels(i, 4, 6) = 3;
  const Claims claimed = uniform_claims(voxels);
  // all faces in one patch
  std::vector<std::size_t> patch(num_faces(m), 0), part;
  std::vector<std::size_t> prim = assign(m, patch, claimed, part);
  REQUIRE(prim.size() == 1);
  CHECK(prim[0] == 7); // 12 near faces outweigh 20 far ones
  {
    // the plain count favours primitive 3
    std::vector<std::size_t> singletons(patch.size());
    for(std::size_t i = 0; i < singletons.size(); ++i) singletons[i] = i;
    const std::vector<std::int32_t> nearest = brute_force_votes(m, singletons, claimed, 1.0);
    std::size_t n3 = 0, n7 = 0;
    for(std::int32_t l : nearest) (l == 3 ? n3 : n7) += 1;
    CHECK(n3 == 20);
    CHECK(n7 == 12);
  }
  CHECK(brute_force_votes(m, patch, claimed, 1.0) == std::vector<std::int32_t>({7}));
  for(std::size_t p : part) CHECK(p == 0);

  // With a very high temperature every face weighs the same: the plain majority wins.
  prim = assign(m, patch, claimed, part, 1e6);
  REQUIRE(prim.size() == 1);
  CHECK(prim[0] == 3);

  // Two patches: the first 4 squares (all near primitive 7) and the rest, where the 4 faces
  // nearest to 7 (about 2 voxels away) lose to the 20 faces nearest to 3.
  for(std::size_t i = 0; i < patch.size(); ++i) patch[i] = i < 8 ? 0 : 1;
  prim = assign(m, patch, claimed, part);
  CHECK(prim == std::vector<std::size_t>({3, 7})); // parts by increasing primitive index
  for(std::size_t i = 0; i < part.size(); ++i) CHECK(part[i] == (i < 8 ? 1u : 0u));
  CHECK(brute_force_votes(m, patch, claimed, 1.0) == std::vector<std::int32_t>({7, 3}));
}

namespace {

// The three slabs on the adaptive grid of the distance field of `m` in the identity frame: the
// surface at 64^3, larger leaves inside.
Claims adaptive_three_slab_claims(const Mesh& m)
{
  Claims c;
  c.tsdf = PD::compute_tsdf(m, PDP::normalization(PD::Normalization()));
  c.labels = three_slab_labels(c.tsdf.grid);
  return c;
}

} // namespace

TEST_CASE("parts merge the patches of one primitive and follow a brute-force reference", "[assignment]")
{
  Mesh m = test_shapes::make_sphere(Point(0, 0, 0), 0.4, 3); // 1280 faces
  for(bool adaptive : {false, true})
  {
    CAPTURE(adaptive);
    const Claims claimed = adaptive ? adaptive_three_slab_claims(m) : three_slab_claims();
    if(adaptive)
    {
      // claimed leaves of several sizes
      std::set<std::uint32_t> widths;
      for(std::size_t l = 0; l < claimed.labels.size(); ++l)
        if(claimed.labels[l] >= 0) widths.insert(claimed.tsdf.grid.width(l));
      REQUIRE(widths.size() >= 2);
    }
    std::size_t count = 0;
    const std::vector<std::size_t> patch = patches_of(m, count);
    REQUIRE(count > 20);
    std::vector<std::size_t> part;
    const std::vector<std::size_t> prim = assign(m, patch, claimed, part);
    CHECK(prim == std::vector<std::size_t>({2, 5, 9}));
    const std::vector<std::int32_t> reference = brute_force_votes(m, patch, claimed, 1.0);
    REQUIRE(reference.size() == count);
    for(face_descriptor f : faces(m))
    {
      REQUIRE(part[f] < prim.size());
      CHECK(prim[part[f]] == std::size_t(reference[patch[f]]));
    }
    // Faces far on the x < -0.2 side are in primitive 9's part, on the x > 0.25 side in 2's.
    for(face_descriptor f : faces(m))
    {
      const double x = m.point(source(halfedge(f, m), m)).x();
      if(x < -0.3) CHECK(prim[part[f]] == 9);
      if(x > 0.3) CHECK(prim[part[f]] == 2);
    }

    // Same answer with threads and with patch ids that are not consecutive.
    std::vector<std::size_t> sparse(patch);
    for(std::size_t& p : sparse) p = p * 1000003 + 17;
    std::vector<std::size_t> part2;
    CHECK(assign(m, sparse, claimed, part2) == prim);
    CHECK(part2 == part);
    Mesh& mm = m;
    auto pmap = mm.add_property_map<face_descriptor, std::size_t>("f:p", 0).first;
    auto qmap = mm.add_property_map<face_descriptor, std::size_t>("f:q", 0).first;
    for(face_descriptor f : faces(m)) pmap[f] = patch[f];
    CHECK(PD::assign_parts<CGAL::Parallel_if_available_tag>(m, pmap, claimed.labels, claimed.tsdf, qmap,
                                                            PDP::boundary_smoothness(0.)) == prim);
    for(face_descriptor f : faces(m)) CHECK(qmap[f] == part[f]);
    mm.remove_property_map(pmap);
    mm.remove_property_map(qmap);
  }
}

// The energy of the final labelling (internal/boundary_graph_cut.h), computed face by face.
double labelling_energy(const PD::internal::Face_adjacency& adj, const PD::internal::Face_corners& corners,
                        const PD::internal::Face_candidates& c, const std::vector<std::int32_t>& label, double scale)
{
  const std::vector<int> outward(adj.number_of_faces, 1);
  double e = 0.;
  for(std::size_t i = 0; i < adj.number_of_faces; ++i)
  {
    bool found = false;
    for(int k = 0; k < c.size(i); ++k)
      if(c.label[i][std::size_t(k)] == label[i]) e += c.cost[i][std::size_t(k)], found = true;
    if(!found) return 1e300; // not a candidate
    for(int k = 0; k < 3; ++k)
    {
      const std::size_t j = adj.neighbor[3 * i + std::size_t(k)];
      if(j != PD::internal::Face_adjacency::no_face && j > i && label[j] != label[i])
        e += PD::internal::slot_cut_cost(adj, corners, outward, i, k, scale);
    }
  }
  return e;
}

TEST_CASE("the final labelling reaches the least energy of two labels and a local minimum of three", "[assignment]")
{
  // A folded strip: 8 squares along x, the last 4 bent down by 60 degrees (a convex crease).
  Mesh m = make_strip(0., 0.125, 8, 0., 0.125, 0.);
  for(auto v : vertices(m))
  {
    const Point p = m.point(v);
    if(p.x() > 0.5) m.point(v) = Point(0.5 + (p.x() - 0.5) * 0.5, p.y(), -(p.x() - 0.5) * std::sqrt(0.75));
  }
  const std::size_t nf = num_faces(m);
  const PD::internal::Face_adjacency adj =
    PD::internal::face_adjacency_of<CGAL::Sequential_tag>(m, get(CGAL::face_index, m), CGAL::parameters::default_values());
  const PD::internal::Face_corners corners(m, get(CGAL::face_index, m), get(CGAL::vertex_point, m));
  CGAL::Random rng(7);
  for(int trial = 0; trial < 20; ++trial)
  {
    const int labels = trial < 12 ? 2 : 3;
    PD::internal::Face_candidates c;
    c.resize(nf);
    for(std::size_t i = 0; i < nf; ++i)
    {
      // every face may take every label; the cheapest first, at cost 0
      std::vector<std::pair<double, std::int32_t> > costs;
      for(int l = 0; l < labels; ++l) costs.emplace_back(rng.get_double(0., 0.02), l);
      std::sort(costs.begin(), costs.end());
      for(int l = 0; l < labels; ++l)
      {
        c.label[i][std::size_t(l)] = costs[std::size_t(l)].second;
        c.cost[i][std::size_t(l)] = costs[std::size_t(l)].first - costs[0].first;
      }
    }
    const double scale = rng.get_double(0.001, 0.05);
    const std::vector<std::int32_t> cut = PD::internal::cut_face_labels<CGAL::Sequential_tag>(
      adj, corners, c, std::vector<int>(nf, 1), scale, 0.);
    const double e = labelling_energy(adj, corners, c, cut, scale);
    std::vector<std::int32_t> initial(nf);
    for(std::size_t i = 0; i < nf; ++i) initial[i] = c.label[i][0];
    CHECK(e <= labelling_energy(adj, corners, c, initial, scale) + 1e-12);
    CHECK(PD::internal::cut_face_labels<CGAL::Parallel_if_available_tag>(adj, corners, c, std::vector<int>(nf, 1),
                                                                           scale, 0.) == cut);
    if(labels == 2)
    {
      // one expansion is exact on two labels: the least energy over all 2^16 labellings
      double least = 1e300;
      std::vector<std::int32_t> l(nf);
      for(std::size_t bits = 0; bits < (std::size_t(1) << nf); ++bits)
      {
        for(std::size_t i = 0; i < nf; ++i) l[i] = std::int32_t((bits >> i) & 1);
        least = (std::min)(least, labelling_energy(adj, corners, c, l, scale));
      }
      CHECK(e == Approx(least).epsilon(1e-9));
    }
    else
    {
      // no face alone can lower the energy
      std::vector<std::int32_t> l(cut);
      for(std::size_t i = 0; i < nf; ++i)
        for(std::int32_t x = 0; x < labels; ++x)
        {
          l[i] = x;
          CHECK(labelling_energy(adj, corners, c, l, scale) >= e - 1e-12);
          l[i] = cut[i];
        }
    }
  }
}

namespace {

// A 40 x 8 grid of squares of 0.025 along x in [0, 1], the part beyond x = `fold_crease` folded up
// by 90 degrees (a concave crease for the upward normals).
constexpr double fold_crease = 0.55;
Mesh folded_strip()
{
  test_shapes::Soup soup;
  const double w = 0.025;
  const auto fold = [&](double x, double y) {
    return x <= fold_crease ? Point(x, y, 0.) : Point(fold_crease, y, x - fold_crease);
  };
  for(int i = 0; i < 40; ++i)
    for(int j = 0; j < 8; ++j)
    {
      const Point a = fold(i * w, j * w), b = fold((i + 1) * w, j * w), c = fold((i + 1) * w, (j + 1) * w),
                  d = fold(i * w, (j + 1) * w);
      soup.triangle(a, b, c);
      soup.triangle(a, c, d);
    }
  return soup.mesh();
}

// Candidates that prefer a cut at x = 0.45 (unfolded), on flat surface: label 0 before, 1 after,
// the other at the area times the distance to x = 0.45.
void add_fold_candidates(const PD::internal::Weighted_point& u, PD::internal::Face_candidates& c, std::size_t i)
{
  const double x = u.point[2] > 1e-9 ? fold_crease + u.point[2] : u.point[0]; // unfolded abscissa
  const std::int32_t near = x < 0.45 ? 0 : 1;
  c.label[i] = {{near, 1 - near, -1, -1}};
  c.cost[i] = {{0., u.area * std::abs(x - 0.45), 0., 0.}};
  c.excluded[i] = u.area;
}

} // namespace

TEST_CASE("the two-level final labelling finds the concave crease of a fine mesh", "[assignment]")
{
  // The cut is far cheaper along the crease than where the data prefer it, so the least energy
  // cuts there: face by face, in two levels and on superfaces.
  Mesh m = folded_strip();
  const std::size_t nf = num_faces(m);
  const PD::internal::Face_adjacency adj =
    PD::internal::face_adjacency_of<CGAL::Sequential_tag>(m, get(CGAL::face_index, m), CGAL::parameters::default_values());
  const PD::internal::Face_corners corners(m, get(CGAL::face_index, m), get(CGAL::vertex_point, m));
  const auto face_point = [&](std::size_t i) {
    const Eigen::Vector3d g = (corners(i, 0) + corners(i, 1) + corners(i, 2)) / 3.;
    return PD::internal::Weighted_point{
      {{g.x(), g.y(), g.z()}}, 0.5 * (corners(i, 1) - corners(i, 0)).cross(corners(i, 2) - corners(i, 0)).norm()};
  };
  PD::internal::Face_candidates c;
  c.resize(nf);
  for(std::size_t i = 0; i < nf; ++i) add_fold_candidates(face_point(i), c, i);
  const std::vector<int> up(nf, 1);
  const double edge_scale = 0.01;
  const std::vector<std::int32_t> one_level =
    PD::internal::cut_face_labels<CGAL::Sequential_tag>(adj, corners, c, up, edge_scale, 0.);
  // cells of 0.1: 32 faces per cluster, the crease inside a cell
  const std::vector<std::int32_t> two_levels =
    PD::internal::cut_face_labels<CGAL::Sequential_tag>(adj, corners, c, up, edge_scale, 0.1);
  for(std::size_t i = 0; i < nf; ++i)
  {
    const bool folded = corners(i, 0).z() > 1e-9 || corners(i, 1).z() > 1e-9 || corners(i, 2).z() > 1e-9;
    CHECK(one_level[i] == (folded ? 1 : 0));
  }
  CHECK(two_levels == one_level);
  CHECK(PD::internal::cut_face_labels<CGAL::Parallel_if_available_tag>(adj, corners, c, up, edge_scale, 0.1) ==
        two_levels);
  // superfaces of 0.1: each is one point, whose data cost puts the cut at x = 0.45; the faces of
  // the superfaces next to that cut move it to the crease
  const PD::internal::Superfaces sf = PD::internal::make_superfaces<CGAL::Sequential_tag>(adj, 0.1);
  CHECK(8 * sf.size() <= nf);
  const auto candidates_of = [](const std::vector<PD::internal::Weighted_point>& points) {
    PD::internal::Face_candidates out;
    out.resize(points.size());
    for(std::size_t i = 0; i < points.size(); ++i) add_fold_candidates(points[i], out, i);
    return out;
  };
  CHECK(PD::internal::superface_labels<CGAL::Sequential_tag>(adj, corners, up, edge_scale, sf, face_point,
                                                             candidates_of) == one_level);
  CHECK(PD::internal::superface_labels<CGAL::Parallel_if_available_tag>(adj, corners, up, edge_scale, sf, face_point,
                                                                        candidates_of) == one_level);
}

TEST_CASE("with the final labelling the parts do not depend on the patches", "[assignment]")
{
  Mesh m = test_shapes::make_sphere(Point(0, 0, 0), 0.4, 3);
  const Claims claimed = three_slab_claims();
  std::size_t count = 0;
  const std::vector<std::size_t> patch = patches_of(m, count);
  std::vector<std::size_t> one(num_faces(m), 0), own(num_faces(m)), part_a, part_b, part_c;
  for(std::size_t i = 0; i < own.size(); ++i) own[i] = i;
  const std::vector<std::size_t> prim = assign(m, patch, claimed, part_a, 1., 1.);
  CHECK(prim == std::vector<std::size_t>({2, 5, 9}));
  CHECK(assign(m, one, claimed, part_b, 1., 1.) == prim);
  CHECK(assign(m, own, claimed, part_c, 1., 1.) == prim);
  CHECK(part_b == part_a);
  CHECK(part_c == part_a);
  // the patch vote gives a single patch a single part
  CHECK(assign(m, one, claimed, part_b, 1., 0.).size() == 1);
  // the parts are the slabs: the cuts, on smooth surface, move at most by the candidate margin
  // (3 voxels of 0.0625) from the planes x = -0.1 and x = 0.15, towards shorter circles
  for(face_descriptor f : faces(m))
  {
    const double x = m.point(source(halfedge(f, m), m)).x();
    if(x < -0.1 - 0.1875 - 0.07) CHECK(prim[part_a[f]] == 9);
    if(x > 0. && x < 0.05) CHECK(prim[part_a[f]] == 5);
    if(x > 0.15 + 0.1875 + 0.07) CHECK(prim[part_a[f]] == 2);
  }
}

TEST_CASE("on faces much smaller than a voxel the final labelling runs on superfaces and finds the slabs", "[assignment]")
{
  Mesh m = test_shapes::make_sphere(Point(0, 0, 0), 0.4, 5); // 20480 faces, edges of about 0.02
  const Claims claimed = three_slab_claims();
  const PD::internal::Face_adjacency adj =
    PD::internal::face_adjacency_of<CGAL::Sequential_tag>(m, get(CGAL::face_index, m), CGAL::parameters::default_values());
  // cells of half a voxel of 1/16: at most half as many superfaces as faces, the switch to them
  CHECK(2 * PD::internal::make_superfaces<CGAL::Sequential_tag>(adj, 0.5 / 16.).size() <= num_faces(m));
  std::vector<std::size_t> one(num_faces(m), 0), part, part_parallel;
  const std::vector<std::size_t> prim = assign(m, one, claimed, part, 1., 1.);
  CHECK(prim == std::vector<std::size_t>({2, 5, 9}));
  std::size_t wrong = 0;
  for(face_descriptor f : faces(m))
  {
    const double x = m.point(source(halfedge(f, m), m)).x();
    wrong += (x < -0.1 - 0.1875 - 0.07 && prim[part[f]] != 9) || (x > 0. && x < 0.05 && prim[part[f]] != 5) ||
             (x > 0.15 + 0.1875 + 0.07 && prim[part[f]] != 2);
  }
  CHECK(wrong == 0);
  auto qmap = m.add_property_map<face_descriptor, std::size_t>("f:parallel", 0).first;
  auto pmap = m.add_property_map<face_descriptor, std::size_t>("f:one", 0).first;
  CHECK(PD::assign_parts<CGAL::Parallel_if_available_tag>(
          m, pmap, claimed.labels, claimed.tsdf, qmap,
          PDP::combine(PDP::vote_temperature(1.), PDP::boundary_smoothness(1.))) == prim);
  std::size_t differ = 0;
  for(face_descriptor f : faces(m)) differ += qmap[f] != part[f];
  CHECK(differ == 0);
}

TEST_CASE("without claimed leaves all faces form one part", "[assignment]")
{
  Mesh m = test_shapes::make_box(Point(-0.2, -0.2, -0.2), Point(0.2, 0.2, 0.2), 2);
  std::vector<std::size_t> patch(num_faces(m)), part;
  for(std::size_t i = 0; i < patch.size(); ++i) patch[i] = i % 5;
  Claims claimed = uniform_claims(PD::Voxel_grid<std::int32_t>(8, -1));
  const std::vector<std::size_t> prim = assign(m, patch, claimed, part);
  CHECK(prim == std::vector<std::size_t>({PD::no_primitive}));
  for(std::size_t p : part) CHECK(p == 0);
  // a point outside the cube still finds the claimed leaf through the kd-tree
  claimed.labels[0] = 4; // the voxel (0, 0, 0)
  Mesh far = test_shapes::make_box(Point(2, 2, 2), Point(3, 3, 3), 1);
  std::vector<std::size_t> one(num_faces(far), 0);
  CHECK(assign(far, one, claimed, part) == std::vector<std::size_t>({4}));
  Mesh any = test_shapes::make_box(Point(0, 0, 0), Point(1, 1, 1), 1);
  Mesh& ma = any;
  auto pmap = ma.add_property_map<face_descriptor, std::size_t>("f:p", 0).first;
  CHECK_THROWS_AS(PD::assign_parts(any, pmap, claimed.labels, claimed.tsdf, pmap, PD::parameters::vote_temperature(0.)),
                  PD::Invalid_input);
  // labels of another grid
  const std::vector<std::int32_t> too_few(claimed.labels.begin(), claimed.labels.end() - 1);
  CHECK_THROWS_AS(PD::assign_parts(any, pmap, too_few, claimed.tsdf, pmap), PD::Invalid_input);
}

TEST_CASE("exact primitive supports give back the true parts of the dumbbell", "[assignment][data]")
{
  // The dumbbell is the union of two balls (radius 0.3 at x = -0.7 and 0.7) and a bar (capsule of
  // radius 0.1 between them); its .seg holds the true part of each face (0, 1, 2 from left).
  Mesh m;
  const std::vector<std::size_t> truth = test_shapes::read_shipped_shape("dumbbell", m);

  // Claimed leaves: those whose centre lies inside a primitive (the balls win over the bar), on
  // the dense 64^3 grid and on the adaptive grid of the pipeline (coarse inside the balls, fine
  // on the surface and in the bar).
  const PD::Hierarchical_prior prior = PD::compute_flow_freeze_prior(m);
  auto patch = m.add_property_map<face_descriptor, std::size_t>("f:patch", 0).first;
  auto part = m.add_property_map<face_descriptor, std::size_t>("f:part", 0).first;
  const std::size_t count = PD::over_segment(m, patch);
  check_patch_structure(m, std::vector<std::size_t>(patch.begin(), patch.end()), count);
  CHECK(count >= 200);
  CHECK(count <= 800);
  for(bool adaptive : {false, true})
  {
    CAPTURE(adaptive);
    const PD::Truncated_signed_distance_field tsdf = PD::compute_tsdf(m, prior, switches(&Variant::adaptive_grid, adaptive));
    const PD::Adaptive_grid& grid = tsdf.grid;
    if(adaptive) CHECK(grid.number_of_leaves() < 64u * 64u * 64u / 4u);
    else CHECK(grid == PD::Adaptive_grid::uniform(64));
    std::vector<std::int32_t> claimed(grid.number_of_leaves(), -1);
    for(std::size_t l = 0; l < claimed.size(); ++l)
    {
      const auto p = tsdf.normalization.from_unit(grid.center(l));
      const double yz = p[1] * p[1] + p[2] * p[2];
      if((p[0] + 0.7) * (p[0] + 0.7) + yz < 0.09) claimed[l] = 10;
      else if((p[0] - 0.7) * (p[0] - 0.7) + yz < 0.09) claimed[l] = 30;
      else if(std::abs(p[0]) < 0.7 && yz < 0.01) claimed[l] = 20;
    }
    for(double smoothness : {0., PD::defaults::boundary_smoothness})
    {
      CAPTURE(smoothness);
      const std::vector<std::size_t> prim =
        PD::assign_parts(m, patch, claimed, tsdf, part, PDP::boundary_smoothness(smoothness));
      CHECK(prim == std::vector<std::size_t>({10, 20, 30}));
      std::size_t correct = 0;
      for(face_descriptor f : faces(m)) correct += part[f] == truth[std::size_t(f)];
      CHECK(double(correct) / double(num_faces(m)) > 0.97);
    }
  }
}

TEST_CASE("assign_parts with every default given explicitly gives the default parts", "[assignment][defaults]")
{
  Mesh m = test_shapes::make_sphere(Point(0, 0, 0), 0.4, 3);
  const Claims claimed = three_slab_claims();
  std::vector<std::size_t> patch(num_faces(m)), a(num_faces(m)), b(num_faces(m));
  PD::over_segment(m, CGAL::make_property_map(patch));
  const std::vector<std::size_t> prim_a =
      PD::assign_parts(m, CGAL::make_property_map(patch), claimed.labels, claimed.tsdf, CGAL::make_property_map(a));
  const std::vector<std::size_t> prim_b = PD::assign_parts(
      m, CGAL::make_property_map(patch), claimed.labels, claimed.tsdf, CGAL::make_property_map(b),
      PDP::combine(CGAL::parameters::vertex_point_map(get(CGAL::vertex_point, m)).face_index_map(get(CGAL::face_index, m)),
                   PDP::vote_temperature(PD::defaults::vote_temperature),
                   PDP::boundary_smoothness(PD::defaults::boundary_smoothness)));
  CHECK(prim_a == std::vector<std::size_t>({2, 5, 9}));
  CHECK(prim_b == prim_a);
  CHECK(b == a);
}
