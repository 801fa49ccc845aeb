// Checks of the benchmark's SDF peer (sdf_peer.h) on the inputs on which CGAL 5.5.1's SDF
// segmentation fails unguarded. Run by ctest with the test suite; it tests the benchmark, not the
// package, so it lives here.
#include "sdf_peer.h"
#include "test_shapes.h"

#include <CGAL/Polygon_mesh_processing/orientation.h>

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <string>

namespace {

int passed = 0, failed = 0;

void check(bool ok, const char* what, int line)
{
  if(ok) ++passed;
  else
  {
    ++failed;
    std::cerr << "check_sdf_peer.cpp:" << line << ": failed: " << what << std::endl;
  }
}
#define PD_CHECK(x) check((x), #x, __LINE__)

using test_shapes::Mesh;
using test_shapes::Point;

bool has(const std::string& note, const char* word) { return note.find(word) != std::string::npos; }

void tetrahedron() // fewer faces, hence SDF values, than clusters
{
  test_shapes::Soup soup;
  const Point a(1, 1, 1), b(1, -1, -1), c(-1, 1, -1), d(-1, -1, 1);
  soup.triangle(a, b, c);
  soup.triangle(a, c, d);
  soup.triangle(a, d, b);
  soup.triangle(b, d, c);
  const pd_benchmark::Sdf_peer_result r = pd_benchmark::segment_with_sdf(soup.mesh());
  PD_CHECK(r.labels.size() == 4);
  PD_CHECK(r.distinct_sdf_values <= 4);
  PD_CHECK(r.number_of_clusters == (std::min<std::size_t>)(4, r.distinct_sdf_values));
  PD_CHECK(r.number_of_segments >= 1);
  PD_CHECK(has(r.note, "cluster") || has(r.note, "single segment"));
}

void octahedron() // eight faces, three distinct SDF values: CGAL 5.5.1's k-means++ loops forever
{
  test_shapes::Soup soup;
  const Point px(1, 0, 0), nx(-1, 0, 0), py(0, 1, 0), ny(0, -1, 0), pz(0, 0, 1), nz(0, 0, -1);
  soup.triangle(px, py, pz);
  soup.triangle(py, nx, pz);
  soup.triangle(nx, ny, pz);
  soup.triangle(ny, px, pz);
  soup.triangle(py, px, nz);
  soup.triangle(nx, py, nz);
  soup.triangle(ny, nx, nz);
  soup.triangle(px, ny, nz);
  const pd_benchmark::Sdf_peer_result r = pd_benchmark::segment_with_sdf(soup.mesh());
  PD_CHECK(r.labels.size() == 8);
  PD_CHECK(r.distinct_sdf_values < 5);
  PD_CHECK(r.number_of_clusters == (std::max<std::size_t>)(1, r.distinct_sdf_values));
  PD_CHECK(has(r.note, "clusters 5->") || has(r.note, "single segment"));
}

void inward_sphere()
{
  Mesh m = test_shapes::make_sphere(Point(0, 0, 0), 1., 2);
  CGAL::Polygon_mesh_processing::reverse_face_orientations(m);
  const pd_benchmark::Sdf_peer_result r = pd_benchmark::segment_with_sdf(m);
  PD_CHECK(r.reversed_components == 1);
  PD_CHECK(has(r.note, "reoriented 1"));
  PD_CHECK(r.labels.size() == num_faces(m));
  PD_CHECK(r.distinct_sdf_values > 5); // rays now hit the far side
  PD_CHECK(r.number_of_clusters == 5);
}

void twelve_triangle_cube()
{
  const Mesh m = test_shapes::make_box(Point(0, 0, 0), Point(1, 1, 1), 1);
  const pd_benchmark::Sdf_peer_result r = pd_benchmark::segment_with_sdf(m);
  PD_CHECK(r.labels.size() == 12);
  PD_CHECK(r.reversed_components == 0);
  PD_CHECK(r.number_of_clusters == (std::min<std::size_t>)(5, r.distinct_sdf_values));
  for(std::size_t l : r.labels) PD_CHECK(l < r.number_of_segments);
}

} // namespace

int main()
{
  tetrahedron();
  octahedron();
  inward_sphere();
  twelve_triangle_cube();
  std::cout << passed << " passed, " << failed << " failed" << std::endl;
  return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
