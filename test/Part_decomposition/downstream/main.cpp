// A program that only knows the installed package.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/generators.h>
#include <CGAL/Part_decomposition/normalization.h>

#include <cmath>
#include <iostream>

int main()
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  CGAL::Surface_mesh<K::Point_3> mesh;
  CGAL::make_tetrahedron(K::Point_3(0, 0, 0), K::Point_3(2, 0, 0), K::Point_3(0, 2, 0), K::Point_3(0, 0, 2), mesh);
  const CGAL::Part_decomposition::Normalization n = CGAL::Part_decomposition::compute_normalization(mesh);
  std::cout << "scale " << n.scale() << std::endl;
  return std::abs(n.scale() * 2. - (1. - 2. * 2. / 64.)) < 1e-12 ? 0 : 1;
}
