// Computes the truncated signed distance field of a mesh and writes its three middle slices as
// images: tsdf_x.ppm, tsdf_y.ppm, tsdf_z.ppm (blue inside, red outside, white on the surface,
// lighter inside the truncation band, black on the zero crossings).
//
// usage: tsdf_example [mesh.off|obj|ply|stl] [output_prefix]
// Without a mesh, a torus pierced by a box (two overlapping closed parts) is generated.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Part_decomposition/IO/read_mesh.h>
#include <CGAL/Part_decomposition/tsdf.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
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

// Writes the slice `index` across `axis` as a PPM image, `scale` pixels per voxel.
static bool write_slice(const PD::Truncated_signed_distance_field& tsdf, int axis, int index, const std::string& file)
{
  const int r = tsdf.values.resolution(), scale = std::max(1, 512 / r);
  auto value = [&](int a, int b) {
    int ijk[3];
    ijk[axis] = index;
    ijk[(axis + 1) % 3] = a;
    ijk[(axis + 2) % 3] = b;
    return tsdf.values(ijk[0], ijk[1], ijk[2]);
  };
  std::ofstream out(file, std::ios::binary);
  if(!out) return false;
  out << "P6\n" << r * scale << " " << r * scale << "\n255\n";
  for(int y = r * scale - 1; y >= 0; --y) // image rows top to bottom
    for(int x = 0; x < r * scale; ++x)
    {
      const int a = x / scale, b = y / scale;
      const double v = value(a, b), t = std::min(1., std::abs(v) / tsdf.truncation);
      // Diverging map: white at 0, towards blue (inside) or red (outside); the clipped region is
      // drawn darker than the band so that the band is visible.
      double s = 0.25 + 0.6 * t;
      if(t >= 1.) s = 1.;
      unsigned char rgb[3];
      const double hi = 255 * (1. - 0.15 * (t >= 1.)), lo = 255 * (1. - s);
      if(v < 0.)
      {
        rgb[0] = static_cast<unsigned char>(lo);
        rgb[1] = static_cast<unsigned char>(lo + 0.3 * (hi - lo));
        rgb[2] = static_cast<unsigned char>(hi);
      }
      else
      {
        rgb[0] = static_cast<unsigned char>(hi);
        rgb[1] = static_cast<unsigned char>(lo);
        rgb[2] = static_cast<unsigned char>(lo);
      }
      // Zero crossing: a sign change towards the next voxel, drawn on the shared pixel border.
      const bool edge_a = a + 1 < r && (x % scale == scale - 1) && ((value(a + 1, b) < 0.) != (v < 0.));
      const bool edge_b = b + 1 < r && (y % scale == scale - 1) && ((value(a, b + 1) < 0.) != (v < 0.));
      if(edge_a || edge_b) rgb[0] = rgb[1] = rgb[2] = 0;
      out.write(reinterpret_cast<const char*>(rgb), 3);
    }
  return bool(out);
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
  const std::string prefix = argc > 2 ? argv[2] : "tsdf";

  const auto t0 = std::chrono::steady_clock::now();
  const PD::Truncated_signed_distance_field tsdf = PD::compute_tsdf<CGAL::Parallel_if_available_tag>(mesh);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();

  const int r = tsdf.values.resolution();
  std::size_t inside = 0, band = 0;
  for(double v : tsdf.values.values())
  {
    inside += v < 0.;
    band += std::abs(v) < tsdf.truncation;
  }
  std::cout << num_faces(mesh) << " faces, closed: " << (CGAL::is_closed(mesh) ? "yes" : "no") << "\n"
            << "TSDF " << r << "^3, truncation " << tsdf.truncation << " (normalized units), sign method "
            << name(tsdf.sign_method) << "\n"
            << inside << " voxels inside, " << band << " in the band, computed in " << ms << " ms\n";
  for(int axis = 0; axis < 3; ++axis)
  {
    const std::string file = prefix + "_" + "xyz"[axis] + ".ppm";
    if(!write_slice(tsdf, axis, r / 2, file))
    {
      std::cerr << "cannot write " << file << "\n";
      return EXIT_FAILURE;
    }
    std::cout << "wrote " << file << " (slice " << r / 2 << " across " << "xyz"[axis] << ")\n";
  }
  return EXIT_SUCCESS;
}
