// Computes the hierarchical Flow/Freeze prior of a mesh and writes the finest grid as a coloured
// point set: Flow voxels in blue, Freeze voxels in red, darker for coarser leaves.
//
// Usage: prior_example [mesh.(off|obj|ply|stl)] [output.ply]
// Without a mesh, a shipped mesh of PD_EXAMPLE_DATA_DIR is used if there is one, otherwise a
// generated shape (two boxes joined by a thin bar).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Part_decomposition/IO/read_mesh.h>
#include <CGAL/Part_decomposition/flow_freeze_prior.h>

#include <array>
#include <chrono>
#include <map>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
namespace PD = CGAL::Part_decomposition;

// Appends the closed box [lo, hi], each side cut into n x n squares of two triangles, outward.
void add_box(Mesh& m, const Point& lo, const Point& hi, int n)
{
  std::map<std::array<double, 3>, Mesh::Vertex_index> index;
  auto vertex = [&](const std::array<double, 3>& c) {
    auto it = index.find(c);
    if(it == index.end()) it = index.emplace(c, m.add_vertex(Point(c[0], c[1], c[2]))).first;
    return it->second;
  };
  const double L[3] = {lo.x(), lo.y(), lo.z()}, H[3] = {hi.x(), hi.y(), hi.z()};
  for(int axis = 0; axis < 3; ++axis)
    for(int side = 0; side < 2; ++side)
    {
      const int u = (axis + 1) % 3, w = (axis + 2) % 3;
      auto V = [&](int i, int j) {
        std::array<double, 3> c;
        c[axis] = side ? H[axis] : L[axis];
        c[u] = L[u] + (H[u] - L[u]) * i / n;
        c[w] = L[w] + (H[w] - L[w]) * j / n;
        return vertex(c);
      };
      for(int i = 0; i < n; ++i)
        for(int j = 0; j < n; ++j)
        {
          const auto a = V(i, j), b = V(i + 1, j), c = V(i + 1, j + 1), d = V(i, j + 1);
          if(side)
          {
            m.add_face(a, b, c);
            m.add_face(a, c, d);
          }
          else
          {
            m.add_face(a, c, b);
            m.add_face(a, d, c);
          }
        }
    }
}

Mesh generated_shape()
{
  Mesh m;
  add_box(m, Point(-1, -0.35, -0.35), Point(-0.3, 0.35, 0.35), 16);
  add_box(m, Point(0.3, -0.35, -0.35), Point(1, 0.35, 0.35), 16);
  add_box(m, Point(-0.3, -0.06, -0.06), Point(0.3, 0.06, 0.06), 8);
  return m;
}

int main(int argc, char** argv)
{
  Mesh mesh;
  std::string input = argc > 1 ? argv[1] : std::string(PD_EXAMPLE_DATA_DIR) + "/dumbbell.off";
  const std::string output = argc > 2 ? argv[2] : "prior.ply";
  try
  {
    if(argc > 1 || std::ifstream(input))
      PD::IO::read_triangle_mesh(input, mesh);
    else
    {
      input = "a generated shape (two boxes joined by a bar)";
      mesh = generated_shape();
    }
  }
  catch(const PD::Invalid_input& e)
  {
    std::cerr << "Cannot read " << input << ": " << e.what() << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "Input: " << input << ", " << num_faces(mesh) << " faces" << std::endl;

  const auto start = std::chrono::steady_clock::now();
  const PD::Hierarchical_prior prior = PD::compute_flow_freeze_prior<CGAL::Parallel_if_available_tag>(mesh);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  std::cout << "Prior computed in " << ms << " ms" << std::endl;

  for(std::size_t l = 0; l < prior.fields.size(); ++l) // the scored resolutions: all, by default
  {
    const PD::Topology_score_field& f = prior.fields[l];
    std::cout << "r = " << prior.resolutions[l] << ": " << f.number_of_active_voxels << " active, "
              << f.number_of_freeze_voxels << " Freeze (threshold " << f.threshold << "); fused leaves: "
              << prior.number_of_flow_leaves[l] << " Flow, " << prior.number_of_freeze_leaves[l] << " Freeze"
              << std::endl;
  }

  // The finest voxels with support, at their centres in input coordinates.
  struct Colored
  {
    std::array<double, 3> p;
    int rgb[3];
  };
  std::vector<Colored> points;
  const int levels = int(prior.resolutions.size());
  for(std::size_t v = 0; v < prior.classes.size(); ++v)
  {
    if(prior.classes[v] == PD::Voxel_class::EMPTY) continue;
    int level = 0;
    while(level < levels && prior.resolutions[std::size_t(level)] != prior.leaf_resolution[v]) ++level;
    const int shade = 100 + (levels > 1 ? 155 * level / (levels - 1) : 155); // coarse = dark
    Colored c;
    c.p = prior.normalization.from_unit(prior.classes.center(v));
    const bool freeze = prior.classes[v] == PD::Voxel_class::FREEZE;
    c.rgb[0] = freeze ? shade : 0;
    c.rgb[1] = freeze ? 0 : shade / 3;
    c.rgb[2] = freeze ? 0 : shade;
    points.push_back(c);
  }
  std::ofstream out(output);
  if(!out)
  {
    std::cerr << "Cannot write " << output << std::endl;
    return EXIT_FAILURE;
  }
  out.precision(10);
  out << "ply\nformat ascii 1.0\ncomment Flow/Freeze prior: blue = Flow, red = Freeze, darker = coarser leaf\n"
      << "element vertex " << points.size() << "\nproperty double x\nproperty double y\nproperty double z\n"
      << "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n";
  for(const Colored& c : points)
    out << c.p[0] << ' ' << c.p[1] << ' ' << c.p[2] << ' ' << c.rgb[0] << ' ' << c.rgb[1] << ' ' << c.rgb[2] << '\n';
  std::cout << "Wrote " << points.size() << " voxel centres to " << output << std::endl;
  return EXIT_SUCCESS;
}
