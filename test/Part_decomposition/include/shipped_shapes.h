// The shapes shipped with the examples (examples/Part_decomposition/data), with their true parts.
#ifndef PART_DECOMPOSITION_TEST_SHIPPED_SHAPES_H
#define PART_DECOMPOSITION_TEST_SHIPPED_SHAPES_H

#include "test_shapes.h"

#include <CGAL/Part_decomposition/IO/read_mesh.h>

#include <catch2/catch.hpp>

#include <fstream>
#include <string>
#include <vector>

namespace test_shapes {

// A shipped example mesh (examples/Part_decomposition/data/NAME.off) and its true part per face.
inline std::vector<std::size_t> read_shipped_shape(const std::string& name, Mesh& m)
{
  const std::string base = std::string(PD_EXAMPLE_DATA_DIR) + "/" + name;
  CGAL::Part_decomposition::IO::read_triangle_mesh(base + ".off", m);
  std::ifstream in(base + ".seg");
  std::vector<std::size_t> truth;
  std::size_t l;
  while(in >> l) truth.push_back(l);
  REQUIRE(truth.size() == num_faces(m));
  return truth;
}

} // namespace test_shapes

#endif // PART_DECOMPOSITION_TEST_SHIPPED_SHAPES_H
