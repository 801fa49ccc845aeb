// libFuzzer target: mutated mesh files through IO::read_triangle_mesh() and the whole pipeline.
// A file may be refused with Invalid_input (the documented error); anything else, a crash, a
// sanitizer report, a label without a part or a non-finite primitive is a finding.
// Build and run: see README.md in this folder.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Part_decomposition/IO/read_mesh.h>
#include <CGAL/Part_decomposition/decompose.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace PD = CGAL::Part_decomposition;

void require(bool ok, const char* what)
{
  if(ok) return;
  std::fprintf(stderr, "fuzz_decompose: %s\n", what);
  std::abort();
}

bool starts_with(const std::uint8_t* data, std::size_t size, const char* prefix)
{
  const std::size_t n = std::strlen(prefix);
  return size >= n && std::memcmp(data, prefix, n) == 0;
}

// The reader chooses the format by extension: guess it from the content, so that mutations of
// every seed keep reaching their parser.
std::string extension_of(const std::uint8_t* data, std::size_t size)
{
  if(starts_with(data, size, "glTF")) return ".glb";
  if(starts_with(data, size, "{")) return ".gltf";
  if(starts_with(data, size, "ply")) return ".ply";
  if(starts_with(data, size, "solid")) return ".stl";
  if(starts_with(data, size, "v ") || starts_with(data, size, "o ") || starts_with(data, size, "# obj")) return ".obj";
  return ".off";
}

bool finite(const PD::Superquadric<K>& q)
{
  bool ok = std::isfinite(q.center().x()) && std::isfinite(q.center().y()) && std::isfinite(q.center().z());
  for(double a : q.scales()) ok = ok && std::isfinite(a) && a > 0.;
  for(double r : q.rotation()) ok = ok && std::isfinite(r);
  return ok;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  static const std::string stem = "/tmp/pd_fuzz_" + std::to_string(::getpid());
  const std::string path = stem + extension_of(data, size);
  {
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
  }
  try
  {
    Mesh mesh;
    const PD::IO::Mesh_file_info info = PD::IO::read_triangle_mesh(path, mesh);
    require(num_faces(mesh) > 0 && info.face_to_input.size() == num_faces(mesh), "face correspondence size");
    for(std::size_t f : info.face_to_input) require(f < info.number_of_input_faces, "face correspondence range");
    for(const auto& d : info.dropped_faces)
      require(d.first < info.number_of_input_faces && d.second < num_faces(mesh), "dropped face");

    // Coarse grids keep an iteration in milliseconds; the code paths are those of 64^3.
    std::vector<std::size_t> part(num_faces(mesh), std::size_t(-1));
    std::vector<PD::Superquadric<K> > primitives;
    const std::size_t parts = PD::decompose<CGAL::Sequential_tag>(
      mesh, CGAL::make_property_map(part),
      PD::parameters::combine(CGAL::parameters::number_of_points_per_face(9u),
                              PD::parameters::voxel_resolutions(std::vector<int>{8, 16}),
                              PD::parameters::primitive_output_iterator(std::back_inserter(primitives))));
    require(parts >= 1 && primitives.size() == parts, "number of parts");
    for(std::size_t p : part) require(p < parts, "label without a part");
    for(const auto& q : primitives) require(finite(q), "non-finite primitive");
    const std::vector<std::size_t> in_file = PD::IO::labels_in_file_order(info, part);
    require(in_file.size() == info.number_of_input_faces, "labels in file order");
    for(std::size_t p : in_file) require(p < parts, "file label without a part");
  }
  catch(const PD::Invalid_input&)
  {
    // the documented refusal
  }
  std::remove(path.c_str());
  return 0;
}
