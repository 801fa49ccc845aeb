// A program that only knows the installed package: decomposes a mesh and writes one part id per
// face. Built twice, against the compiled library and header-only, which must agree.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Part_decomposition/IO/read_mesh.h>
#include <CGAL/Part_decomposition/decompose.h>

#include <cstdlib>
#include <fstream>
#include <iostream>

int main(int argc, char** argv)
{
  namespace PD = CGAL::Part_decomposition;
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  typedef CGAL::Surface_mesh<K::Point_3> Mesh;
  if(argc != 3)
  {
    std::cerr << "usage: " << argv[0] << " MESH OUT.seg" << std::endl;
    return EXIT_FAILURE;
  }
  Mesh mesh;
  PD::IO::read_triangle_mesh(argv[1], mesh);
  auto part = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:part", 0).first;
  const std::size_t n = PD::decompose(mesh, part, PD::parameters::freeze_ratio(0.15f));
  std::ofstream out(argv[2]);
  for(Mesh::Face_index f : faces(mesh)) out << part[f] << '\n';
  std::cout << n << " parts" << std::endl;
  return n > 1 && out ? EXIT_SUCCESS : EXIT_FAILURE;
}
