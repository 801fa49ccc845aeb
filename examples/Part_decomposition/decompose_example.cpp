// Decomposes a mesh into parts and prints, for each part, its size and its superquadric.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Part_decomposition/IO/read_mesh.h>
#include <CGAL/Part_decomposition/decompose.h>

#include <cstdlib>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace PD = CGAL::Part_decomposition;

int main(int argc, char** argv)
{
  const std::string filename = argc > 1 ? argv[1] : PD_EXAMPLE_DATA_DIR "/table.off";
  Mesh mesh;
  try
  {
    PD::IO::read_triangle_mesh(filename, mesh);
  }
  catch(const PD::Invalid_input& e)
  {
    std::cerr << "error: " << e.what() << std::endl;
    return EXIT_FAILURE;
  }

  // one part id per face, one superquadric per part
  Mesh::Property_map<Mesh::Face_index, std::size_t> part =
    mesh.add_property_map<Mesh::Face_index, std::size_t>("f:part", 0).first;
  std::vector<PD::Superquadric<K> > primitives;
  PD::Stage_timings timings;
  const std::size_t K_parts = PD::decompose(
    mesh, part,
    PD::parameters::combine(PD::parameters::primitive_output_iterator(std::back_inserter(primitives)),
                            PD::parameters::stage_timings(&timings)));

  std::vector<std::size_t> faces_of_part(K_parts, 0);
  for(Mesh::Face_index f : faces(mesh)) ++faces_of_part[part[f]];
  std::cout << filename << ": " << num_faces(mesh) << " faces, " << K_parts << " parts in "
            << timings.total << " s" << std::endl;
  for(std::size_t k = 0; k < K_parts; ++k)
  {
    const auto a = primitives[k].scales();
    std::cout << "  part " << k << ": " << faces_of_part[k] << " faces, superquadric at ("
              << primitives[k].center() << "), semi-axes " << a[0] << " " << a[1] << " " << a[2]
              << ", exponents " << primitives[k].epsilon1() << " " << primitives[k].epsilon2() << std::endl;
  }
  return EXIT_SUCCESS;
}
