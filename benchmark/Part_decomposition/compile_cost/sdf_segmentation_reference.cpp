// The reference of the compile-cost measurement: a program of the size of CGAL's own
// Surface_mesh_segmentation example (SDF values, then the segmentation, on a Surface_mesh).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/mesh_segmentation.h>

#include <cstdlib>
#include <fstream>
#include <iostream>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

int main(int argc, char** argv)
{
  Mesh mesh;
  std::ifstream in(argc > 1 ? argv[1] : "data/table.off");
  if(!(in >> mesh) || is_empty(mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "error: cannot read a triangle mesh" << std::endl;
    return EXIT_FAILURE;
  }
  auto sdf = mesh.add_property_map<Mesh::Face_index, double>("f:sdf").first;
  CGAL::sdf_values(mesh, sdf);
  auto segment = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:segment").first;
  const std::size_t n = CGAL::segmentation_from_sdf_values(mesh, sdf, segment);
  std::cout << n << " segments" << std::endl;
  return EXIT_SUCCESS;
}
