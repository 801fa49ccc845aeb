// sdf_segmentation: CGAL's shape-diameter-function segmentation (Surface_mesh_segmentation, default
// parameters) of a mesh file, for the comparison figure of the manual. Writes one segment id per
// face of the file, in its face order.
//
// usage: sdf_segmentation MESH OUT.seg

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/mesh_segmentation.h>

#include <CGAL/Part_decomposition/IO/read_mesh.h>

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace PD = CGAL::Part_decomposition;

int main(int argc, char** argv)
{
  if(argc < 3)
  {
    std::cerr << "usage: sdf_segmentation MESH OUT.seg\n";
    return EXIT_FAILURE;
  }
  Mesh mesh;
  PD::IO::Mesh_file_info info;
  try
  {
    info = PD::IO::read_triangle_mesh(argv[1], mesh); // closed components oriented outward
  }
  catch(const PD::Invalid_input& e)
  {
    std::cerr << "cannot read " << argv[1] << ": " << e.what() << "\n";
    return EXIT_FAILURE;
  }
  auto sdf = mesh.add_property_map<Mesh::Face_index, double>("f:sdf", 0.).first;
  auto segment = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:segment", 0).first;
  CGAL::sdf_values(mesh, sdf);
  const std::size_t n = CGAL::segmentation_from_sdf_values(mesh, sdf, segment);
  std::vector<std::size_t> labels;
  for(Mesh::Face_index f : faces(mesh)) labels.push_back(segment[f]);
  std::ofstream out(argv[2]);
  for(std::size_t l : PD::IO::labels_in_file_order(info, labels)) out << l << '\n';
  if(!out)
  {
    std::cerr << "cannot write " << argv[2] << "\n";
    return EXIT_FAILURE;
  }
  std::cout << argv[1] << ": " << n << " SDF segments" << std::endl;
  return EXIT_SUCCESS;
}
