// Computes the truncated signed distance field of a mesh on the adaptive grid that its Flow/Freeze
// prior asks for, and reports the grid (its leaves per depth, against the dense grid of its finest
// leaves) and the field (its range, the leaves inside and in the truncation band, the volume
// inside, the value at the centre of the bounding box).
//
// usage: tsdf_example [mesh.off|obj|ply|stl]
// Without a mesh, a torus pierced by a box (two overlapping closed parts) is generated.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Part_decomposition/IO/read_mesh.h>
#include <CGAL/Part_decomposition/flow_freeze_prior.h>
#include <CGAL/Part_decomposition/tsdf.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
namespace PD = CGAL::Part_decomposition;

// A closed torus around the z axis and a closed box through its tube: a self-intersecting mesh.
static Mesh generated_mesh()
{
  Mesh m;
  const int nu = 48, nv = 24;
  const double R = 1.0, r = 0.35, pi = std::acos(-1.);
  std::vector<Mesh::Vertex_index> v;
  for(int i = 0; i < nu; ++i)
    for(int j = 0; j < nv; ++j)
    {
      const double u = 2 * pi * i / nu, w = 2 * pi * j / nv;
      v.push_back(m.add_vertex(Point((R + r * std::cos(w)) * std::cos(u), (R + r * std::cos(w)) * std::sin(u), r * std::sin(w))));
    }
  auto at = [&](int i, int j) { return v[std::size_t(((i + nu) % nu) * nv + (j + nv) % nv)]; };
  for(int i = 0; i < nu; ++i)
    for(int j = 0; j < nv; ++j)
    {
      m.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      m.add_face(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  // Box [0.6, 1.6] x [-0.2, 0.2] x [-0.5, 0.5], two triangles per side, outward.
  const double lo[3] = {0.6, -0.2, -0.5}, hi[3] = {1.6, 0.2, 0.5};
  Mesh::Vertex_index c[8];
  for(int k = 0; k < 8; ++k) c[k] = m.add_vertex(Point(k & 1 ? hi[0] : lo[0], k & 2 ? hi[1] : lo[1], k & 4 ? hi[2] : lo[2]));
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for(const auto& q : quads)
  {
    m.add_face(c[q[0]], c[q[1]], c[q[2]]);
    m.add_face(c[q[0]], c[q[2]], c[q[3]]);
  }
  return m;
}

static const char* name(PD::Tsdf_sign_method m)
{
  switch(m)
  {
  case PD::Tsdf_sign_method::INSIDE_TEST: return "INSIDE_TEST (ray parity)";
  case PD::Tsdf_sign_method::WINDING_NUMBER: return "WINDING_NUMBER";
  case PD::Tsdf_sign_method::FLOOD_FILL: return "FLOOD_FILL";
  case PD::Tsdf_sign_method::RAY_VOTES: return "RAY_VOTES";
  default: return "AUTOMATIC";
  }
}

int main(int argc, char** argv)
{
  Mesh mesh;
  if(argc > 1)
  {
    try
    {
      PD::IO::read_triangle_mesh(argv[1], mesh);
    }
    catch(const std::exception& e)
    {
      std::cerr << "cannot read " << argv[1] << ": " << e.what() << "\n";
      return EXIT_FAILURE;
    }
  }
  else
    mesh = generated_mesh();

  // The prior tells how fine the grid must be along the surface: coarse on smooth Flow regions,
  // fine at the Freeze boundaries (and down to grid_resolution where the shape is thin).
  const auto t0 = std::chrono::steady_clock::now();
  const PD::Hierarchical_prior prior = PD::compute_flow_freeze_prior<CGAL::Parallel_if_available_tag>(mesh);
  const PD::Truncated_signed_distance_field tsdf = PD::compute_tsdf<CGAL::Parallel_if_available_tag>(mesh, prior);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();

  const PD::Adaptive_grid& grid = tsdf.grid;
  const int R = grid.finest_resolution(), r = int(std::lround(1. / tsdf.voxel_size)); // 128 and 64 by default
  std::cout << num_faces(mesh) << " faces, closed: " << (CGAL::is_closed(mesh) ? "yes" : "no")
            << "; prior and field computed in " << ms << " ms\n"
            << "grid of finest resolution " << R << ": " << grid.number_of_leaves() << " leaves (a dense " << r
            << "^3 grid has " << std::size_t(r) * r * r << " voxels)\n";
  for(int d = 0; (1 << d) <= R; ++d)
    if(grid.number_of_leaves_of_depth(d) > 0)
      std::cout << "  depth " << d << " (side 1/" << (1 << d) << "): " << grid.number_of_leaves_of_depth(d) << " leaves\n";

  // One value per leaf, at its centre; a leaf's volume weighs it.
  double lo = tsdf.values.front(), hi = lo, inside_volume = 0.;
  std::size_t inside = 0, band = 0;
  for(std::size_t l = 0; l < grid.number_of_leaves(); ++l)
  {
    const double v = tsdf.values[l];
    lo = std::min(lo, v);
    hi = std::max(hi, v);
    band += std::abs(v) < tsdf.truncation;
    if(v < 0.)
    {
      ++inside;
      inside_volume += grid.volume(l);
    }
  }
  const double scale = tsdf.normalization.scale(); // input lengths to normalized ones
  std::cout << "field in [" << lo << ", " << hi << "], truncation " << tsdf.truncation << " (normalized units, "
            << tsdf.truncation / tsdf.voxel_size << " voxels of " << r << "^3), sign method "
            << name(tsdf.sign_method) << "\n"
            << inside << " leaves inside, " << band << " in the band; volume inside "
            << inside_volume / (scale * scale * scale) << " (input units)\n";

  // Any point of the cube lies in one leaf: here the centre of the bounding box, the origin of the
  // normalized cube.
  const std::size_t c = grid.locate(0., 0., 0.);
  std::cout << "centre of the bounding box: leaf " << c << " of depth " << grid.depth(c) << ", value "
            << tsdf.values[c] << "\n";
  return EXIT_SUCCESS;
}
