// Robustness: every ugly input gets a valid decomposition (one part id per face, finite
// primitives) or a documented error, from the library (Invalid_input) and from the hitops tool
// (one line on stderr, exit status 1, no output file); the same labels for any thread count.
#include <catch2/catch.hpp>

#include <CGAL/Part_decomposition/IO/read_mesh.h>
#include <CGAL/Part_decomposition/Part_decomposer.h>
#include <CGAL/Part_decomposition/decompose.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Random.h>

#include "sha256.h"
#include "method_switches.h"
#include "test_shapes.h"

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <random>
#include <numeric>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

// AddressSanitizer reserves terabytes of address space: no ulimit -v under it.
#if defined(__SANITIZE_ADDRESS__)
#define PD_UNDER_ADDRESS_SANITIZER
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define PD_UNDER_ADDRESS_SANITIZER
#endif
#endif

namespace PD = CGAL::Part_decomposition;
namespace PDP = CGAL::Part_decomposition::parameters;
namespace fs = std::filesystem;
using test_shapes::K;
using test_shapes::Mesh;
using test_shapes::Point;
typedef PD::Superquadric<K> Superquadric;
typedef boost::graph_traits<Mesh>::face_descriptor face_descriptor;

namespace {

const double k_nan = std::numeric_limits<double>::quiet_NaN();
const double k_inf = std::numeric_limits<double>::infinity();

// ---------------------------------------------------------------------------------------------
// Library layer

struct Decomposition
{
  std::size_t parts = 0;
  std::vector<std::size_t> labels; // in the order of faces(mesh)
  std::vector<Superquadric> primitives;
};

bool finite_primitive(const Superquadric& q)
{
  bool ok = std::isfinite(q.center().x()) && std::isfinite(q.center().y()) && std::isfinite(q.center().z()) &&
            std::isfinite(q.epsilon1()) && std::isfinite(q.epsilon2());
  for(double a : q.scales()) ok = ok && std::isfinite(a) && a > 0.;
  for(double r : q.rotation()) ok = ok && std::isfinite(r);
  return ok;
}

// Decomposes `m` and checks what every valid output satisfies: each face gets a part id below
// K, every part has a face, and one finite primitive per part.
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename NP = CGAL::parameters::Default_named_parameters>
Decomposition decompose_checked(const Mesh& m, const NP& np = CGAL::parameters::default_values())
{
  Decomposition d;
  std::vector<std::size_t> part(num_faces(m), std::size_t(-1));
  d.parts = PD::decompose<ConcurrencyTag>(
    m, CGAL::make_property_map(part), PDP::combine(np, PDP::primitive_output_iterator(std::back_inserter(d.primitives))));
  d.labels = part;
  REQUIRE(d.parts >= 1);
  REQUIRE(d.primitives.size() == d.parts);
  std::vector<char> used(d.parts, 0);
  for(std::size_t l : part)
  {
    REQUIRE(l < d.parts);
    used[l] = 1;
  }
  CHECK(std::count(used.begin(), used.end(), 1) == std::ptrdiff_t(d.parts));
  for(const Superquadric& q : d.primitives) CHECK(finite_primitive(q));
  return d;
}

template <typename F>
PD::Input_error error_of(F&& f)
{
  try { f(); }
  catch(const PD::Invalid_input& e)
  {
    CHECK(std::string(e.what()).find('\n') == std::string::npos);
    return e.error();
  }
  FAIL("no Invalid_input");
  return PD::Input_error::UNREADABLE_FILE;
}

template <typename NP>
PD::Input_error decompose_error(const Mesh& m, const NP& np)
{
  return error_of([&] {
    std::vector<std::size_t> part(num_faces(m));
    PD::decompose<CGAL::Sequential_tag>(m, CGAL::make_property_map(part), np);
  });
}

PD::Input_error decompose_error(const Mesh& m)
{
  return decompose_error(m, CGAL::parameters::default_values());
}

Mesh transformed(const Mesh& in, double scale, double offset)
{
  Mesh m = in;
  for(auto v : vertices(m))
  {
    const Point p = m.point(v);
    m.point(v) = Point(p.x() * scale + offset, p.y() * scale + offset, p.z() * scale - offset);
  }
  return m;
}

// A ball with a cylinder through it: two overlapping closed pieces (self-intersecting union).
Mesh ball_and_bar()
{
  Mesh m = test_shapes::make_sphere(Point(0, 0, 0), 1., 2);
  Mesh bar = test_shapes::make_cylinder(Point(0, 0, 1.5), 0.3, 2., 12, 6);
  test_shapes::append(m, bar);
  return m;
}

// The faces of `in` whose centroid satisfies `keep`, as a new mesh.
template <typename Keep>
Mesh filtered(const Mesh& in, Keep keep)
{
  test_shapes::Soup s;
  for(face_descriptor f : faces(in))
  {
    std::vector<Point> p;
    for(auto v : vertices_around_face(halfedge(f, in), in)) p.push_back(in.point(v));
    if(keep(CGAL::centroid(p[0], p[1], p[2]))) s.triangle(p[0], p[1], p[2]);
  }
  return s.mesh();
}

// The component of every face.
std::vector<std::size_t> components(const Mesh& m)
{
  std::vector<std::size_t> c(num_faces(m));
  CGAL::Polygon_mesh_processing::connected_components(m, CGAL::make_property_map(c));
  return c;
}

// Whether no part holds faces of two components.
bool parts_within_components(const std::vector<std::size_t>& labels, const std::vector<std::size_t>& comp)
{
  std::map<std::size_t, std::size_t> component_of_part;
  for(std::size_t i = 0; i < labels.size(); ++i)
  {
    auto r = component_of_part.emplace(labels[i], comp[i]);
    if(r.first->second != comp[i]) return false;
  }
  return true;
}

// Whether `a` and `b` group the faces alike, whatever the part ids.
bool same_partition(const std::vector<std::size_t>& a, const std::vector<std::size_t>& b)
{
  if(a.size() != b.size()) return false;
  std::map<std::size_t, std::size_t> a_to_b, b_to_a;
  for(std::size_t i = 0; i < a.size(); ++i)
    if(a_to_b.emplace(a[i], b[i]).first->second != b[i] || b_to_a.emplace(b[i], a[i]).first->second != a[i])
      return false;
  return true;
}

double agreement(const std::vector<std::size_t>& a, const std::vector<std::size_t>& b)
{
  std::size_t same = 0;
  for(std::size_t i = 0; i < a.size(); ++i) same += a[i] == b[i];
  return double(same) / double(a.size());
}

// ---------------------------------------------------------------------------------------------
// Tool layer: files on disk through hitops

// A fresh folder per test case, removed at the end.
struct Temp_dir
{
  fs::path path;
  Temp_dir()
  {
    static int counter = 0;
    path = fs::temp_directory_path() / ("pd_robustness_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~Temp_dir()
  {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
  std::string file(const std::string& name, const std::string& content) const
  {
    const fs::path p = path / name;
    std::ofstream out(p, std::ios::binary);
    out << content;
    return p.string();
  }
  std::string operator/(const std::string& name) const { return (path / name).string(); }
  std::set<std::string> listing() const
  {
    std::set<std::string> names;
    for(const auto& e : fs::directory_iterator(path)) names.insert(e.path().filename().string());
    return names;
  }
};

std::string read_text(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string quoted(const std::string& s) { return "'" + s + "'"; }

struct Run
{
  int status = -1;
  std::string out, err;
};

#ifdef PD_HITOPS_PATH
// Runs hitops with `args`, capturing its exit status, stdout and stderr.
Run hitops(const Temp_dir& dir, const std::string& args)
{
  const std::string out = dir / "stdout.txt", err = dir / "stderr.txt";
  std::string command = quoted(PD_HITOPS_PATH) + " " + args + " > " + quoted(out) + " 2> " + quoted(err);
#if !defined(PD_UNDER_ADDRESS_SANITIZER)
  // a regression that allocates from a lying header must fail here, not take the machine down
  command = "ulimit -v 4000000; " + command;
#endif
  const int raw = std::system(command.c_str());
  Run r;
  r.status = (raw != -1 && WIFEXITED(raw)) ? WEXITSTATUS(raw) : -1;
  r.out = read_text(out);
  r.err = read_text(err);
  fs::remove(out);
  fs::remove(err);
  return r;
}
#endif

// ---------------------------------------------------------------------------------------------
// OFF text of raw polygons, so that files can hold what no mesh data structure does.

struct Off
{
  std::vector<std::array<double, 3> > points;
  std::vector<std::vector<long long> > faces;

  std::size_t point(double x, double y, double z)
  {
    points.push_back({{x, y, z}});
    return points.size() - 1;
  }
  void face(std::initializer_list<long long> f) { faces.emplace_back(f); }
  // appends a triangle mesh
  void add(const Mesh& m, bool reversed = false)
  {
    const std::size_t base = points.size();
    std::map<Mesh::Vertex_index, std::size_t> id;
    for(auto v : vertices(m))
    {
      id[v] = points.size() - base;
      points.push_back({{m.point(v).x(), m.point(v).y(), m.point(v).z()}});
    }
    for(face_descriptor f : faces_of(m))
    {
      std::vector<long long> poly;
      for(auto v : vertices_around_face(halfedge(f, m), m)) poly.push_back((long long)(base + id[v]));
      if(reversed) std::reverse(poly.begin(), poly.end());
      faces.push_back(poly);
    }
  }
  static CGAL::Iterator_range<Mesh::Face_iterator> faces_of(const Mesh& m) { return CGAL::faces(m); }
  std::string text() const
  {
    std::ostringstream out;
    out.precision(17);
    out << "OFF\n" << points.size() << ' ' << faces.size() << " 0\n";
    for(const auto& p : points) out << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
    for(const auto& f : faces)
    {
      out << f.size();
      for(long long i : f) out << ' ' << i;
      out << '\n';
    }
    return out.str();
  }
};

Off off_of(const Mesh& m)
{
  Off o;
  o.add(m);
  return o;
}

} // namespace

// =============================================================================================
// Library: meshes built to be ugly

TEST_CASE("a single triangle, a flat sheet and an open mesh are decomposed", "[robustness][library]")
{
  SECTION("single triangle")
  {
    test_shapes::Soup s;
    s.triangle(Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0));
    const Decomposition d = decompose_checked(s.mesh());
    CHECK(d.parts == 1);
  }
  SECTION("flat sheet: no volume, flat primitives in its plane")
  {
    test_shapes::Soup s;
    const int n = 12;
    for(int i = 0; i < n; ++i)
      for(int j = 0; j < n; ++j)
      {
        const double x = double(i) / n, y = double(j) / n, h = 1. / n;
        s.triangle(Point(x, y, 0), Point(x + h, y, 0), Point(x + h, y + h, 0));
        s.triangle(Point(x, y, 0), Point(x + h, y + h, 0), Point(x, y + h, 0));
      }
    const Decomposition d = decompose_checked(s.mesh());
    for(const Superquadric& q : d.primitives)
    {
      const std::array<double, 3> a = q.scales();
      CHECK(*std::min_element(a.begin(), a.end()) < 0.02); // at most a voxel thick
      CHECK(std::abs(q.center().z()) < 0.02);
    }
  }
  SECTION("open mesh: a sphere with its top cut off")
  {
    const Mesh m = filtered(test_shapes::make_sphere(Point(0, 0, 0), 1., 3), [](const Point& c) { return c.z() < 0.5; });
    REQUIRE(!CGAL::is_closed(m));
    decompose_checked(m);
  }
}

TEST_CASE("many components, a flipped one and needles keep parts within their piece", "[robustness][library]")
{
  SECTION("343 separate boxes")
  {
    Mesh m;
    for(int i = 0; i < 7; ++i)
      for(int j = 0; j < 7; ++j)
        for(int k = 0; k < 7; ++k)
          test_shapes::append(m, test_shapes::make_box(Point(i, j, k), Point(i + 0.5, j + 0.4, k + 0.3), 1));
    REQUIRE(num_faces(m) == 343u * 12u);
    // more boxes than the default cap of 256 primitives: raised
    const Decomposition d = decompose_checked(m, PDP::maximum_number_of_primitives(std::size_t(400)));
    const std::vector<std::size_t> comp = components(m);
    std::vector<std::set<std::size_t> > labels_of_box(343), boxes_of_part(d.parts);
    for(std::size_t i = 0; i < comp.size(); ++i)
    {
      labels_of_box[comp[i]].insert(d.labels[i]);
      boxes_of_part[d.labels[i]].insert(comp[i]);
    }
    const std::size_t whole_boxes = std::size_t(std::count_if(
      labels_of_box.begin(), labels_of_box.end(), [](const std::set<std::size_t>& s) { return s.size() == 1; }));
    const std::size_t parts_in_one_box = std::size_t(std::count_if(
      boxes_of_part.begin(), boxes_of_part.end(), [](const std::set<std::size_t>& s) { return s.size() == 1; }));
    CAPTURE(d.parts, whole_boxes, parts_in_one_box);
    // Not every box: the fit stops at its coverage target, and the faces of a box left without a
    // primitive vote for those of its neighbours (one part over two boxes, a box over two parts).
    CHECK(whole_boxes >= 343 * 9 / 10);
    CHECK(parts_in_one_box >= d.parts * 9 / 10);
  }
  SECTION("two balls, one of them inward-facing")
  {
    Mesh a = test_shapes::make_sphere(Point(0, 0, 0), 1., 2);
    Mesh b = test_shapes::make_sphere(Point(3, 0, 0), 1., 2);
    Mesh outward = a;
    test_shapes::append(outward, b);
    CGAL::Polygon_mesh_processing::reverse_face_orientations(b);
    test_shapes::append(a, b);
    const Decomposition d = decompose_checked(a);
    CHECK(parts_within_components(d.labels, components(a)));
    // the orientation of a piece does not change its parts
    CHECK(same_partition(d.labels, decompose_checked(outward).labels));
  }
  SECTION("a needle 1/200 of the shape thick through a box")
  {
    Mesh m = test_shapes::make_box(Point(-1, -1, -1), Point(1, 1, 1), 4);
    test_shapes::append(m, test_shapes::make_cylinder(Point(0, 0, 2), 0.01, 4., 6, 20));
    decompose_checked(m);
  }
}

TEST_CASE("degenerate faces and coincident vertices give finite results", "[robustness][library]")
{
  // collapse a vertex of a sphere onto its neighbour: two faces become segments of zero area,
  // and two vertices share their position
  Mesh m = test_shapes::make_sphere(Point(0, 0, 0), 1., 2);
  const auto v = *vertices(m).begin();
  const auto u = target(halfedge(v, m), m) == v ? source(halfedge(v, m), m) : target(halfedge(v, m), m);
  m.point(v) = m.point(u);
  // and a sliver: a vertex moved onto the segment of two others
  const auto h = halfedge(*std::next(faces(m).begin(), 40), m);
  const Point a = m.point(source(h, m)), b = m.point(target(h, m));
  m.point(target(next(h, m), m)) = CGAL::midpoint(a, b);
  decompose_checked(m);

  // every face of zero area: the vertices lie on one line
  test_shapes::Soup s;
  s.triangle(Point(0, 0, 0), Point(1, 0, 0), Point(2, 0, 0));
  s.triangle(Point(1, 0, 0), Point(3, 0, 0), Point(2, 0, 0));
  CHECK(decompose_checked(s.mesh()).parts == 1);
}

TEST_CASE("coordinates around 1e8, 1e-8 and far from the origin give the same parts", "[robustness][library]")
{
  const Mesh m = ball_and_bar();
  const Decomposition ref = decompose_checked(m);
  CHECK(ref.parts >= 2);
  // Powers of two scale every coordinate exactly, and the pipeline works in normalized units.
  for(double s : {std::ldexp(1., 27), std::ldexp(1., -27), std::ldexp(1., 90), std::ldexp(1., -90)})
  {
    CAPTURE(s);
    const Decomposition d = decompose_checked(transformed(m, s, 0.));
    CHECK(d.labels == ref.labels);
  }
  // 1e6 away from the origin: about 30 bits are left for the shape, which is not exact.
  const Decomposition far = decompose_checked(transformed(m, 1., 1e6));
  CHECK(far.parts == ref.parts);
  CHECK(agreement(far.labels, ref.labels) > 0.97);
  for(const Superquadric& q : far.primitives) CHECK(q.center().x() == Approx(1e6).margin(3.));
}

TEST_CASE("the OFF reader reads the Geomview variants, ASCII and binary, alike", "[robustness][library][io]")
{
  auto big_endian = [](std::uint32_t u) {
    std::string b(4, '\0');
    for(int k = 0; k < 4; ++k) b[k] = char((u >> (24 - 8 * k)) & 0xff);
    return b;
  };
  auto i32 = [&](std::int32_t i) { return big_endian(std::uint32_t(i)); };
  auto f32 = [&](float f) {
    std::uint32_t u;
    std::memcpy(&u, &f, 4);
    return big_endian(u);
  };
  // a tetrahedron, with normals after the coordinates and one face colour in the binary file
  const double p[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const int f[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  std::string ascii = "NOFF\n4 4 0\n", binary = "NOFF BINARY\n" + i32(4) + i32(4) + i32(0);
  for(const auto& v : p)
  {
    ascii += std::to_string(v[0]) + " " + std::to_string(v[1]) + " " + std::to_string(v[2]) + " 0 0 1\n";
    binary += f32(float(v[0])) + f32(float(v[1])) + f32(float(v[2])) + f32(0.f) + f32(0.f) + f32(1.f);
  }
  for(const auto& t : f)
  {
    ascii += "3 " + std::to_string(t[0]) + " " + std::to_string(t[1]) + " " + std::to_string(t[2]) + "\n";
    binary += i32(3) + i32(t[0]) + i32(t[1]) + i32(t[2]) + i32(1) + f32(0.5f);
  }
  Temp_dir dir;
  for(const std::string& content : {ascii, binary})
  {
    Mesh m;
    const PD::IO::Mesh_file_info info = PD::IO::read_triangle_mesh(dir.file("tet.off", content), m);
    CHECK(info.number_of_input_faces == 4u);
    CHECK(num_vertices(m) == 4u);
    CHECK(CGAL::is_closed(m));
    CHECK(CGAL::Polygon_mesh_processing::is_outward_oriented(m));
  }
  // truncated binary files and negative counts are refused
  Mesh m;
  CHECK(error_of([&] { PD::IO::read_triangle_mesh(dir.file("cut.off", binary.substr(0, binary.size() - 6)), m); }) ==
        PD::Input_error::UNREADABLE_FILE);
  CHECK(error_of([&] { PD::IO::read_triangle_mesh(dir.file("neg.off", "OFF BINARY\n" + i32(-3) + i32(1) + i32(0)), m); }) ==
        PD::Input_error::UNREADABLE_FILE);
}

TEST_CASE("meshes that cannot be decomposed give the documented error", "[robustness][library]")
{
  using E = PD::Input_error;
  CHECK(decompose_error(Mesh()) == E::NO_FACES);

  Mesh quad;
  std::vector<Mesh::Vertex_index> vs = {quad.add_vertex(Point(0, 0, 0)), quad.add_vertex(Point(1, 0, 0)),
                                        quad.add_vertex(Point(1, 1, 0)), quad.add_vertex(Point(0, 1, 0))};
  quad.add_face(vs);
  CHECK(decompose_error(quad) == E::NOT_TRIANGLE_MESH);

  Mesh same;
  same.add_face(same.add_vertex(Point(1, 2, 3)), same.add_vertex(Point(1, 2, 3)), same.add_vertex(Point(1, 2, 3)));
  CHECK(decompose_error(same) == E::DEGENERATE_EXTENT);

  const Mesh box = test_shapes::make_box(Point(0, 0, 0), Point(1, 1, 1), 2);
  for(double bad : {k_nan, k_inf, -k_inf})
  {
    Mesh m = box;
    m.point(*std::next(vertices(m).begin(), 5)) = Point(0.5, bad, 0.5);
    CHECK(decompose_error(m) == E::NON_FINITE_COORDINATES);
  }
  // squared lengths would overflow or underflow: outside the documented range
  CHECK(decompose_error(transformed(box, 1e31, 0.)) == E::COORDINATES_OUT_OF_RANGE);
  CHECK(decompose_error(transformed(box, 1e29, 2e30)) == E::COORDINATES_OUT_OF_RANGE);
  CHECK(decompose_error(transformed(box, 1., 2e30)) == E::DEGENERATE_EXTENT); // 1 is lost next to 2e30
  CHECK(decompose_error(transformed(box, 1e-31, 0.)) == E::COORDINATES_OUT_OF_RANGE);
  CHECK(decompose_error(transformed(box, 1e-300, 0.)) == E::COORDINATES_OUT_OF_RANGE);
  CHECK_NOTHROW(decompose_checked(transformed(box, 1e29, 0.)));
  CHECK_NOTHROW(decompose_checked(transformed(box, 1e-29, 0.)));

  // a Surface_mesh with removed faces and no collect_garbage(): its indices have holes
  Mesh holes = box;
  CGAL::Euler::remove_face(halfedge(*faces(holes).begin(), holes), holes);
  REQUIRE(holes.has_garbage());
  CHECK(decompose_error(holes) == E::INVALID_PARAMETER);
  holes.collect_garbage();
  decompose_checked(holes);
}

TEST_CASE("out-of-range named parameters give INVALID_PARAMETER before any work", "[robustness][library][parameters]")
{
  const Mesh m = test_shapes::make_box(Point(0, 0, 0), Point(1, 2, 3), 2);
  auto bad = [&](const auto& np) { return decompose_error(m, np) == PD::Input_error::INVALID_PARAMETER; };
  for(const std::vector<int>& r : std::vector<std::vector<int> >{
        {}, {0}, {1}, {-16}, {3}, {16, 48}, {16, 64}, {64, 32}, {256, 512}, {1 << 30},
        {std::numeric_limits<int>::min()}})
    CHECK(bad(PDP::voxel_resolutions(r)));
  // the coarsest grids the rule allows still give a valid decomposition ({1} alone fails on the
  // default truncation of 8 voxels, which must be at most 4 voxels of the finest grid)
  decompose_checked(m, PDP::voxel_resolutions(std::vector<int>{1, 2, 4}));
  for(unsigned int n : {0u, 35u, 4000000000u}) CHECK(bad(CGAL::parameters::number_of_points_per_face(n)));
  CHECK(bad(PDP::number_of_neighbors(0)));
  for(double p : {-1., 100.5, k_nan}) CHECK(bad(PDP::curvature_percentile(p)));
  CHECK(bad(PDP::cue_weights(std::array<double, 4>{{1., k_nan, 1., 1.}})));
  CHECK(bad(PDP::cue_weights(std::array<double, 4>{{1., k_inf, 1., 1.}})));
  CHECK(bad(PDP::cue_weights(std::vector<double>{1., 1.})));
  for(double a : {0., 1., -0.5, k_nan}) CHECK(bad(PDP::freeze_ratio(a)));
  for(double g : {-0.01, 0.3, k_nan, k_inf}) CHECK(bad(PDP::normalization_margin(g)));
  for(double t : {0., -1., k_nan, k_inf, 1e9}) CHECK(bad(PDP::tsdf_truncation(t)));
  for(double t : {-1., k_nan, k_inf}) CHECK(bad(PDP::flow_zone_tolerance(t)));
  CHECK(bad(PDP::trust_region_scales(std::vector<double>{})));
  CHECK(bad(PDP::trust_region_scales(std::vector<double>{1., 0.})));
  CHECK(bad(PDP::trust_region_scales(std::vector<double>{k_nan})));
  for(double t : {0., -1., k_nan, k_inf}) CHECK(bad(PDP::body_seed_threshold(t)));
  for(double v : {-1., k_nan, k_inf}) CHECK(bad(PDP::minimum_body_volume(v)));
  for(double v : {-1., k_nan, k_inf}) CHECK(bad(PDP::minimum_surface_volume(v)));
  for(double v : {-1., k_nan, k_inf}) CHECK(bad(PDP::exterior_penalty(v)));
  for(double c : {0., 1.5, k_nan}) CHECK(bad(PDP::coverage_target(c)));
  for(double r : {0., -2., k_nan, k_inf}) CHECK(bad(PDP::roi_radius(r)));
  CHECK(bad(PDP::maximum_number_of_primitives(std::size_t(0))));
  for(double q : {-1., 101., k_nan}) CHECK(bad(PDP::dihedral_percentile(q)));
  for(double s : {-0.1, 2., k_nan}) CHECK(bad(PDP::minimum_patch_size(s)));
  for(double s : {0., 2., k_nan}) CHECK(bad(PDP::patch_split_size(s)));
  CHECK(bad(PDP::smoothing_iterations(-1)));
  for(double t : {0., -1., k_nan, k_inf}) CHECK(bad(PDP::vote_temperature(t)));
  // the finest leaves: a power of two, at most 256
  for(int g : {0, -128, 96, 512})
  {
    CAPTURE(g);
    CHECK(bad(PDP::grid_resolution(g)));
  }
}

TEST_CASE("extreme but valid named parameters give a valid decomposition", "[robustness][library][parameters]")
{
  const Mesh m = ball_and_bar();
  auto valid = [&](const char* what, const auto& np) {
    INFO(what);
    CHECK_NOTHROW(decompose_checked(m, np));
  };
  valid("one coarse grid", PDP::voxel_resolutions(std::vector<int>{4}));
  valid("two coarse grids", PDP::voxel_resolutions(std::vector<int>{2, 4}));
  valid("one sample per face", CGAL::parameters::number_of_points_per_face(1u));
  valid("more neighbours than faces", PDP::number_of_neighbors(100000));
  valid("lowest percentiles", PDP::combine(PDP::curvature_percentile(0.), PDP::dihedral_percentile(0.)));
  valid("highest percentiles", PDP::combine(PDP::curvature_percentile(100.), PDP::dihedral_percentile(100.)));
  valid("zero cue weights", PDP::cue_weights(std::array<double, 4>{{0., 0., 0., 0.}}));
  valid("huge cue weights", PDP::cue_weights(std::array<double, 4>{{1e300, 1e300, 1e300, 1e300}}));
  valid("tiny freeze ratio, no margin", PDP::combine(PDP::freeze_ratio(1e-9), PDP::normalization_margin(0.)));
  valid("huge freeze ratio, widest margin", PDP::combine(PDP::freeze_ratio(1. - 1e-9), PDP::normalization_margin(0.25)));
  valid("tiny truncation, no Flow dilation", PDP::combine(PDP::tsdf_truncation(1e-9), PDP::flow_zone_tolerance(0.)));
  valid("widest truncation, huge dilation", PDP::combine(PDP::tsdf_truncation(256.), PDP::flow_zone_tolerance(1e300)));
  valid("extreme trust regions", PDP::trust_region_scales(std::vector<double>{1e-300, 1e300}));
  valid("no body seed, no surface seed volume",
        PDP::combine(PDP::body_seed_threshold(1e300), PDP::minimum_surface_volume(1e300)));
  valid("every seed a body seed of any volume",
        PDP::combine(PDP::body_seed_threshold(1e-300), PDP::minimum_body_volume(0.), PDP::minimum_surface_volume(0.)));
  valid("huge penalty and ROI", PDP::combine(PDP::exterior_penalty(1e300), PDP::roi_radius(1e300)));
  valid("no penalty, tiny ROI and coverage",
        PDP::combine(PDP::exterior_penalty(0.), PDP::roi_radius(1e-300), PDP::coverage_target(1e-300)));
  valid("one primitive", PDP::combine(PDP::maximum_number_of_primitives(std::size_t(1)), PDP::coverage_target(1.)));
  valid("one patch", PDP::combine(PDP::minimum_patch_size(1.), PDP::patch_split_size(1.)));
  valid("tiny patches, long smoothing",
        PDP::combine(PDP::minimum_patch_size(0.), PDP::patch_split_size(1e-300), PDP::smoothing_iterations(50)));
  valid("tiny vote temperature", PDP::vote_temperature(1e-300));
  valid("huge vote temperature", PDP::vote_temperature(1e300));
  valid("the dense grid of the paper", switches(&Variant::adaptive_grid, false));
  valid("finest leaves at the finest voxel resolution", PDP::grid_resolution(64));
  valid("finest leaves at 256", PDP::grid_resolution(256));
  valid("coarse voxels, finest leaves at 256",
        PDP::combine(PDP::voxel_resolutions(std::vector<int>{2, 4}), PDP::grid_resolution(256)));
}

TEST_CASE("stage functions check their inputs at run time", "[robustness][library]")
{
  using E = PD::Input_error;
  const Mesh m = ball_and_bar();
  PD::Part_decomposer<Mesh> pd(m);
  std::vector<std::size_t> part(num_faces(m));
  // a stage computes the stages it needs: no order to follow
  CHECK(pd.compose_parts(CGAL::make_property_map(part), switches(&Variant::use_pieces, false)) >= 1u);
  CHECK_FALSE(pd.fitting().primitives.empty());
  // results that do not match are refused: the grid of the field follows the prior
  pd.compute_prior(PDP::voxel_resolutions(std::vector<int>{16, 32}));
  CHECK(error_of([&] { pd.compute_distance_field(); }) == E::INVALID_PARAMETER); // 32^3 prior, 64^3 field
  CHECK(error_of([&] { pd.fit_primitives(); }) == E::INVALID_PARAMETER);
  CHECK(error_of([&] { pd.compute_fitting_zones(); }) == E::INVALID_PARAMETER);
  pd.compute_distance_field(PDP::voxel_resolutions(std::vector<int>{16, 32}));
  CHECK(pd.compute_fitting_zones().flow_zone.count(16) == 1); // r_fit of {16, 32}: 16 only
  // a refused stage leaves the results of {16, 32}, which fit
  CHECK(error_of([&] { pd.compute_distance_field(); }) == E::INVALID_PARAMETER);
  CHECK(pd.distance_field().voxel_size == 1. / 32.);
  CHECK(pd.fit_primitives().labels.size() == pd.distance_field().grid.number_of_leaves());

  // the free functions on results that do not match
  const PD::Hierarchical_prior prior = PD::compute_flow_freeze_prior(m);
  const PD::Truncated_signed_distance_field tsdf32 =
    PD::compute_tsdf(m, PDP::voxel_resolutions(std::vector<int>{32}));
  CHECK(error_of([&] { PD::fit_superquadrics(PD::Hierarchical_prior(), PD::Truncated_signed_distance_field()); }) ==
        E::INVALID_PARAMETER);
  CHECK(error_of([&] { PD::compute_tsdf(Mesh()); }) == E::NO_FACES);
  CHECK(error_of([&] { PD::compute_flow_freeze_prior(Mesh()); }) == E::NO_FACES);
  const PD::Truncated_signed_distance_field tsdf = PD::compute_tsdf(m);
  CHECK(error_of([&] { PD::compute_fitting_zones(prior, tsdf, std::vector<int>{0}); }) == E::INVALID_PARAMETER);
  // a grid coarser than the prior's finest resolution
  const PD::Truncated_signed_distance_field dense32 =
    PD::compute_tsdf(m, PDP::combine(PDP::voxel_resolutions(std::vector<int>{32}), switches(&Variant::adaptive_grid, false)));
  REQUIRE(dense32.grid.finest_resolution() == 32);
  CHECK(error_of([&] { PD::compute_fitting_zones(prior, dense32, std::vector<int>{16}); }) == E::INVALID_PARAMETER);
  CHECK(error_of([&] { PD::fit_superquadrics(prior, dense32); }) == E::INVALID_PARAMETER);
  CHECK(error_of([&] { PD::compute_tsdf(m, prior, PDP::voxel_resolutions(std::vector<int>{32})); }) == E::INVALID_PARAMETER);

  // a normalization that is not a map into the cube
  for(double s : {0., -1., k_nan, k_inf})
    CHECK(error_of([&] { PD::Normalization({{0., 0., 0.}}, s); }) == E::INVALID_PARAMETER);
  CHECK(error_of([&] { PD::Normalization({{k_nan, 0., 0.}}, 1.); }) == E::INVALID_PARAMETER);

  // an empty mesh has no patch; no claimed leaf gives one part; labels of another grid are refused
  std::vector<std::size_t> none;
  CHECK(PD::over_segment(Mesh(), CGAL::make_property_map(none)) == 0u);
  std::vector<std::size_t> patch(num_faces(m), 7);
  std::vector<std::int32_t> unclaimed(tsdf.grid.number_of_leaves(), -1);
  const std::vector<std::size_t> parts =
    PD::assign_parts(m, CGAL::make_property_map(patch), unclaimed, tsdf, CGAL::make_property_map(part));
  CHECK(parts.size() == 1u);
  CHECK(std::all_of(part.begin(), part.end(), [](std::size_t p) { return p == 0; }));
  REQUIRE(tsdf32.grid.number_of_leaves() != tsdf.grid.number_of_leaves());
  unclaimed.assign(tsdf32.grid.number_of_leaves(), 0);
  CHECK(error_of([&] {
          PD::assign_parts(m, CGAL::make_property_map(patch), unclaimed, tsdf, CGAL::make_property_map(part));
        }) == E::INVALID_PARAMETER);
  CHECK(error_of([&] {
          PD::assign_parts(m, CGAL::make_property_map(patch), unclaimed, PD::Truncated_signed_distance_field(),
                           CGAL::make_property_map(part));
        }) == E::INVALID_PARAMETER);
}

TEST_CASE("the fit refuses a distance field of other voxel resolutions than the prior's",
          "[robustness][library]")
{
  const Mesh m = ball_and_bar();
  const PD::Hierarchical_prior prior = PD::compute_flow_freeze_prior(m);
  const PD::Truncated_signed_distance_field tsdf32 =
    PD::compute_tsdf(m, PDP::voxel_resolutions(std::vector<int>{32}));
  CHECK(error_of([&] { PD::fit_superquadrics(prior, tsdf32); }) == PD::Input_error::INVALID_PARAMETER);
}

TEST_CASE("sets joined by several threads at once are the connected components, rooted at their smallest index",
          "[robustness][determinism]")
{
  // 97 chains over shuffled indices: chain c holds the indices i with i % 97 == c; each link is
  // given twice, in both directions, so that threads race on the same roots
  const std::size_t n = 200000, chains = 97;
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t(0));
  CGAL::Random rng(5);
  std::shuffle(order.begin(), order.end(), std::mt19937(rng.get_int(0, 1 << 30)));
  std::vector<std::pair<std::size_t, std::size_t> > links;
  std::vector<std::size_t> last(chains, n);
  for(std::size_t i : order)
  {
    if(last[i % chains] != n)
    {
      links.emplace_back(i, last[i % chains]);
      links.emplace_back(last[i % chains], i);
    }
    last[i % chains] = i;
  }
  const auto check = [&](auto tag) {
    CGAL::Part_decomposition::internal::Index_sets sets(n, tag);
    CGAL::Part_decomposition::internal::for_each_range<decltype(tag)>(links.size(), [&](std::size_t b, std::size_t e) {
      for(std::size_t k = b; k < e; ++k) sets.unite(links[k].first, links[k].second);
    }, 64);
    std::size_t wrong = 0;
    for(std::size_t i = 0; i < n; ++i) wrong += sets.find(i) != i % chains;
    CHECK(wrong == 0u);
  };
  check(CGAL::Sequential_tag());
  // joined by one thread, a union returns the root of the joined set
  CGAL::Part_decomposition::internal::Index_sets small(4);
  CHECK(small.unite(3, 1) == 1u);
  CHECK(small.unite(2, 3) == 1u);
  CHECK(small.unite(0, 2) == 0u);
  CHECK(small.find(3) == 0u);
#ifdef CGAL_LINKED_WITH_TBB
  for(std::size_t threads : {2, 3})
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    CAPTURE(threads);
    check(CGAL::Parallel_tag());
  }
#endif
}

TEST_CASE("the labels are the same run after run and for any number of threads", "[robustness][determinism][data]")
{
  Mesh m;
  const PD::IO::Mesh_file_info info = PD::IO::read_triangle_mesh(std::string(PD_EXAMPLE_DATA_DIR) + "/animal.off", m);
  REQUIRE(info.number_of_input_faces == num_faces(m));
  const Decomposition ref = decompose_checked<CGAL::Sequential_tag>(m);
  CHECK(ref.parts >= 3);
  CHECK(decompose_checked<CGAL::Sequential_tag>(m).labels == ref.labels);
#ifdef CGAL_LINKED_WITH_TBB
  for(std::size_t threads : {1, 2, 3})
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    CAPTURE(threads);
    const Decomposition d = decompose_checked<CGAL::Parallel_tag>(m);
    CHECK(d.labels == ref.labels);
    CHECK(d.parts == ref.parts);
    for(std::size_t k = 0; k < d.parts; ++k)
    {
      CHECK(d.primitives[k].scales() == ref.primitives[k].scales());
      CHECK(d.primitives[k].center() == ref.primitives[k].center());
    }
  }
#endif
}

// =============================================================================================
// The hitops tool on files from the wild

#ifdef PD_HITOPS_PATH

namespace {

// A file hitops must refuse: exit status 1, one line on stderr naming the problem, nothing on
// stdout, no output file (and an existing one untouched).
void check_refused(const std::string& name, const std::string& content, const std::string& reason)
{
  CAPTURE(name, reason);
  Temp_dir dir;
  const std::string input = dir.file(name, content);
  const std::string kept = dir.file("kept.seg", "old\n");
  const Run r = hitops(dir, quoted(input) + " --labels " + quoted(dir / "out.seg") + " --primitives " +
                                quoted(dir / "out.json") + " --colored " + quoted(kept));
  CHECK(r.status == 1);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  CHECK(r.err.rfind("hitops: error: ", 0) == 0);
  CHECK(r.err.find(reason) != std::string::npos);
  CHECK(r.out.empty());
  CHECK(dir.listing() == std::set<std::string>{name, "kept.seg"});
  CHECK(read_text(kept) == "old\n");
}

// A file hitops must decompose: exit status 0, one label per face of the file, each a part of
// the JSON, whose numbers are all finite; no temporary file left.
std::vector<std::size_t> check_decomposed(const std::string& name, const std::string& content,
                                          std::size_t file_faces, const std::string& options = "")
{
  CAPTURE(name);
  Temp_dir dir;
  const std::string input = dir.file(name, content);
  const Run r = hitops(dir, quoted(input) + " --labels " + quoted(dir / "out.seg") + " --primitives " +
                                quoted(dir / "out.json") + " --colored " + quoted(dir / "out.ply") + " " + options);
  CHECK(r.status == 0);
  CHECK(r.err.empty());
  CHECK(dir.listing() == std::set<std::string>{name, "out.seg", "out.json", "out.ply"});
  std::vector<std::size_t> labels;
  {
    std::istringstream in(read_text(dir / "out.seg"));
    for(std::string line; std::getline(in, line);)
    {
      REQUIRE(!line.empty());
      REQUIRE(line.find_first_not_of("0123456789") == std::string::npos);
      labels.push_back(std::stoul(line));
    }
  }
  CHECK(labels.size() == file_faces);
  std::string json = read_text(dir / "out.json");
  std::transform(json.begin(), json.end(), json.begin(), [](char c) { return char(std::tolower(c)); });
  CHECK(json.find("nan") == std::string::npos);
  CHECK(json.find("inf") == std::string::npos);
  std::size_t parts = 0;
  for(std::size_t p = json.find("\"part\""); p != std::string::npos; p = json.find("\"part\"", p + 1)) ++parts;
  CHECK(parts >= 1);
  for(std::size_t l : labels) CHECK(l < parts);
  std::string ply = read_text(dir / "out.ply");
  std::transform(ply.begin(), ply.end(), ply.begin(), [](char c) { return char(std::tolower(c)); });
  CHECK(ply.find("nan") == std::string::npos);
  return labels;
}

std::string box_off(double scale = 1., double offset = 0.)
{
  return off_of(transformed(test_shapes::make_box(Point(0, 0, 0), Point(1, 2, 3), 2), scale, offset)).text();
}

} // namespace

TEST_CASE("hitops refuses broken files with one line and exit status 1", "[robustness][hitops]")
{
  const std::string tri = "0 0 0\n1 0 0\n0 1 0\n";
  check_refused("empty.off", "", "cannot parse");
  check_refused("header_only.off", "OFF\n", "cannot parse");
  check_refused("counts_only.off", "OFF\n3 1 0\n", "cannot parse");
  check_refused("garbage.off", "OFF\nthis is not a mesh\n", "cannot parse");
  check_refused("binary_garbage.off", std::string("\x00\xff\x13OFF\x01\x02", 8), "cannot parse");
  check_refused("nan.off", "OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n", "");
  check_refused("inf.off", "OFF\n3 1 0\n0 0 0\n1e999 0 0\n0 1 0\n3 0 1 2\n", "");
  check_refused("out_of_range.off", "OFF\n3 1 0\n" + tri + "3 0 1 7\n", "");
  check_refused("negative_index.off", "OFF\n3 1 0\n" + tri + "3 0 -1 2\n", "");
  check_refused("two_vertex_face.off", "OFF\n3 1 0\n" + tri + "2 0 1\n", "");
  check_refused("no_faces.off", "OFF\n3 0 0\n" + tri, "no face");
  check_refused("only_degenerate.off", "OFF\n3 2 0\n" + tri + "3 0 0 1\n3 2 2 2\n", "no face");
  check_refused("coincident.off", "OFF\n3 1 0\n1 1 1\n1 1 1\n1 1 1\n3 0 1 2\n", "no face");
  // headers that promise more than the file holds must not allocate for it
  check_refused("lying_faces.off", "OFF\n3 1000000000 0\n" + tri + "3 0 1 2\n", "cannot parse");
  check_refused("lying_vertices.off", "OFF\n1000000000 1 0\n" + tri + "3 0 1 2\n", "cannot parse");
  check_refused("lying_degree.off", "OFF\n3 1 0\n" + tri + "1000000000 0 1 2\n", "cannot parse");
  check_refused("lying.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                             "property float z\nelement face 1000000000\nproperty list uchar int vertex_indices\n"
                             "end_header\n" + tri + "3 0 1 2\n", "cannot parse");
  check_refused("mesh.xyz", tri, "cannot parse");
  // found by fuzz_decompose: CGAL's parsers had undefined behaviour on these (a property before
  // any element indexed an empty vector; an index of 2^64 or more was cast from a double, and
  // read as vertex 0 in practice)
  check_refused("property_first.ply", "ply\nformat ascii 1.0\nproperty float x\nelement vertex 3\n"
                                      "property float y\nproperty float z\nend_header\n" + tri, "cannot parse");
  const std::string ply_header = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                 "property float z\nelement face 1\nproperty list uint int vertex_indices\n";
  // a list length of 2^32 - 1 in a few bytes, a negative element count (2^64 - 5 items of an
  // element without properties: an endless loop in CGAL's reader), a non-integer list length
  check_refused("lying_length.ply", ply_header + "end_header\n" + tri + "4294967295 0 1 2\n", "cannot parse");
  check_refused("negative_count.ply", ply_header + "element junk -5\nend_header\n" + tri + "3 0 1 2\n", "cannot parse");
  check_refused("fractional_length.ply", ply_header + "end_header\n" + tri + "2.5 0 1 2\n", "cannot parse");
  check_refused("huge_index.off", "OFF\n3 1 0\n" + tri + "3 0 1 333333333333333333336\n", "out-of-range");
  check_refused("huge_degree.off", "OFF\n3 1 0\n" + tri + "1e20 0 1 2\n", "cannot parse");
  check_refused("fractional_index.off", "OFF\n3 1 0\n" + tri + "3 0 1 1.5\n", "cannot parse");
  check_refused("zero_weight.off", "4OFF\n3 1 0\n0 0 0 1\n1 0 0 0\n0 1 0 1\n3 0 1 2\n", "non-finite");
  check_refused("huge.off", box_off(1e31), "range");
  check_refused("tiny.off", box_off(1e-31), "range");

  Temp_dir dir;
  Run r = hitops(dir, quoted(dir / "missing.off"));
  CHECK(r.status == 1);
  CHECK(r.err.find("cannot open") != std::string::npos);
  r = hitops(dir, quoted(dir.path.string()) + " --labels " + quoted(dir / "x.seg"));
  CHECK(r.status == 1);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  // an output that cannot be written: an error, and no partial file next to it
  const std::string box = dir.file("box.off", box_off());
  r = hitops(dir, quoted(box) + " --labels " + quoted(dir / "missing_dir/out.seg") + " --primitives " +
                    quoted(dir / "out.json"));
  CHECK(r.status == 1);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  CHECK(dir.listing() == std::set<std::string>{"box.off"});
  r = hitops(dir, quoted(box) + " --resolutions 16,48");
  CHECK(r.status == 1);
  CHECK(r.err.find("voxel_resolutions") != std::string::npos);
}

TEST_CASE("hitops reads ugly but meaningful file variants, one label per file face", "[robustness][hitops]")
{
  SECTION("single triangle")
  {
    CHECK(check_decomposed("triangle.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", 1) ==
          std::vector<std::size_t>{0});
  }
  SECTION("OFF variants whose colour and texture entries are ignored")
  {
    // a colour index far outside any colour map, a texture line too short, normals, weights
    const std::string faces = "3 0 1 2 1e10\n3 0 2 3\n3 0 3 1\n3 1 3 2\n";
    check_decomposed("colors.off", "COFF\n4 4 0\n0 0 0 1e300\n1 0 0 -7\n0 1 0\n0 0 1 1 2 3 4 5\n" + faces, 4);
    check_decomposed("texture.off", "STOFF\n4 4 0\n0 0 0\n1 0 0 1\n0 1 0\n0 0 1\n" + faces, 4);
    check_decomposed("normals.off", "NOFF 4 4 0\n0 0 0 0 0 -1\n1 0 0 1 0 0\n0 1 0 0 1 0\n0 0 1 0 0 1\n" + faces, 4);
    check_decomposed("weights.off", "4OFF\n4 4 0\n0 0 0 2\n2 0 0 2\n0 2 0 2\n0 0 2 2\n" + faces, 4);
  }
  SECTION("PLY: binary big endian, elements without properties, faces before vertices")
  {
    auto be32 = [](std::uint32_t u) {
      std::string b(4, '\0');
      for(int k = 0; k < 4; ++k) b[k] = char((u >> (24 - 8 * k)) & 0xff);
      return b;
    };
    auto f32 = [&](float f) {
      std::uint32_t u;
      std::memcpy(&u, &f, 4);
      return be32(u);
    };
    std::string ply = "ply\nformat binary_big_endian 1.0\nelement nothing 1000000000000\nelement face 4\n"
                      "property list uchar uint vertex_indices\nelement vertex 4\nproperty float x\n"
                      "property float y\nproperty float z\nend_header\n";
    for(const auto& t : {std::array<std::uint32_t, 3>{{0, 2, 1}}, std::array<std::uint32_t, 3>{{0, 1, 3}},
                         std::array<std::uint32_t, 3>{{0, 3, 2}}, std::array<std::uint32_t, 3>{{1, 2, 3}}})
      ply += std::string(1, '\3') + be32(t[0]) + be32(t[1]) + be32(t[2]);
    for(const auto& v : {std::array<float, 3>{{0, 0, 0}}, std::array<float, 3>{{1, 0, 0}}, std::array<float, 3>{{0, 1, 0}},
                         std::array<float, 3>{{0, 0, 1}}})
      ply += f32(v[0]) + f32(v[1]) + f32(v[2]);
    check_decomposed("tet.ply", ply, 4);
  }
  SECTION("quads and n-gons: an octagonal prism")
  {
    Off o;
    const double pi = std::acos(-1.);
    for(int z = 0; z < 2; ++z)
      for(int i = 0; i < 8; ++i) o.point(std::cos(pi * i / 4), std::sin(pi * i / 4), 2. * z);
    o.face({7, 6, 5, 4, 3, 2, 1, 0});
    o.face({8, 9, 10, 11, 12, 13, 14, 15});
    for(long long i = 0; i < 8; ++i) o.face({i, (i + 1) % 8, 8 + (i + 1) % 8, 8 + i});
    check_decomposed("prism.off", o.text(), 10);
  }
}

TEST_CASE("hitops decomposes degenerate, non-manifold and extreme geometry, one label per file face",
          "[robustness][hitops]")
{
  SECTION("zero-area and repeated-vertex faces, duplicated faces")
  {
    Off o = off_of(test_shapes::make_box(Point(0, 0, 0), Point(1, 1, 1), 2));
    const std::size_t n = o.faces.size();
    o.face({0, 0, 1});                          // repeated vertex
    o.face({2, 2, 2});                          // one vertex three times
    const long long c = (long long)o.point(0.5, 0, 0), a = (long long)o.point(0, 0, 0),
                    b = (long long)o.point(1, 0, 0);
    o.face({a, c, b});                          // collinear: zero area
    o.faces.push_back(o.faces[0]);              // duplicated face
    std::vector<long long> flipped = o.faces[1];
    std::reverse(flipped.begin(), flipped.end());
    o.faces.push_back(flipped);                 // duplicated with the opposite orientation
    const std::vector<std::size_t> labels = check_decomposed("degenerate.off", o.text(), n + 5);
    REQUIRE(labels.size() == n + 5);
    CHECK(labels[n + 3] == labels[0]);          // the duplicate takes the label of its twin
  }
  SECTION("non-manifold edges and vertices")
  {
    Off o = off_of(test_shapes::make_box(Point(0, 0, 0), Point(1, 1, 1), 1));
    // two more triangles on an edge of the box, a second box touching it at a corner only
    const long long p = (long long)o.point(0.5, -1, 0.5), q = (long long)o.point(0.5, -1, -0.5);
    o.face({0, 1, p});
    o.face({1, 0, q});
    Off other = off_of(test_shapes::make_box(Point(1, 1, 1), Point(2, 2, 2), 1));
    const long long base = (long long)o.points.size();
    for(const auto& pt : other.points) o.points.push_back(pt);
    for(auto f : other.faces)
    {
      for(long long& i : f) i += base;
      o.faces.push_back(f);
    }
    check_decomposed("nonmanifold.off", o.text(), o.faces.size());
  }
  SECTION("open mesh, many components, an inward-facing component")
  {
    const Mesh open = filtered(test_shapes::make_sphere(Point(0, 0, 0), 1., 2), [](const Point& c) { return c.z() < 0.3; });
    check_decomposed("open.off", off_of(open).text(), num_faces(open));
    Off many;
    for(int i = 0; i < 150; ++i)
      many.add(test_shapes::make_box(Point(2 * (i % 10), 2 * (i / 10 % 5), 2 * (i / 50)),
                                     Point(2 * (i % 10) + 1, 2 * (i / 10 % 5) + 1, 2 * (i / 50) + 1), 1),
               i % 7 == 3 /* some inward-facing */);
    check_decomposed("many.off", many.text(), many.faces.size(), "--resolutions 16,32");
    Off flipped;
    flipped.add(test_shapes::make_sphere(Point(0, 0, 0), 1., 2));
    flipped.add(test_shapes::make_sphere(Point(3, 0, 0), 1., 2), true);
    const std::vector<std::size_t> labels = check_decomposed("flipped.off", flipped.text(), flipped.faces.size());
    const std::size_t half = flipped.faces.size() / 2;
    CHECK(std::set<std::size_t>(labels.begin(), labels.begin() + half).size() == 1u);
    CHECK(std::set<std::size_t>(labels.begin() + half, labels.end()).size() == 1u);
    CHECK(labels.front() != labels.back());
  }
  SECTION("flat sheet, needle, 1e8, 1e-8, far from the origin")
  {
    Off sheet;
    for(int i = 0; i <= 6; ++i)
      for(int j = 0; j <= 6; ++j) sheet.point(i, j, 0);
    for(long long i = 0; i < 6; ++i)
      for(long long j = 0; j < 6; ++j) sheet.face({7 * i + j, 7 * (i + 1) + j, 7 * (i + 1) + j + 1, 7 * i + j + 1});
    CHECK(check_decomposed("sheet.off", sheet.text(), 36) == std::vector<std::size_t>(36, 0));
    Mesh needle = test_shapes::make_box(Point(-1, -1, -1), Point(1, 1, 1), 3);
    test_shapes::append(needle, test_shapes::make_cylinder(Point(0, 0, 3), 0.002, 4., 5, 10));
    check_decomposed("needle.off", off_of(needle).text(), num_faces(needle));
    const Mesh shape = ball_and_bar();
    const std::vector<std::size_t> ref = check_decomposed("shape.off", off_of(shape).text(), num_faces(shape));
    CHECK(check_decomposed("large.off", off_of(transformed(shape, std::ldexp(1., 27), 0.)).text(), num_faces(shape)) == ref);
    CHECK(check_decomposed("small.off", off_of(transformed(shape, std::ldexp(1., -27), 0.)).text(), num_faces(shape)) == ref);
    check_decomposed("far.off", off_of(transformed(shape, 1., 1e6)).text(), num_faces(shape));
    check_decomposed("1e8.off", box_off(1e8, 3e8), 48);
    check_decomposed("1e-8.off", box_off(1e-8, -5e-8), 48);
  }
}

TEST_CASE("hitops batch: failures are reported per mesh, outputs of the others are complete", "[robustness][hitops]")
{
  Temp_dir dir;
  const std::string good = dir.file("good.off", box_off());
  const std::string bad = dir.file("bad.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 9\n");
  const std::string list = dir.file("list.txt", "# meshes\n" + good + "\n" + bad + "\n" + (dir / "missing.off") + "\n");
  fs::create_directories(dir.path / "out");
  // --quiet: no line per mesh, only the errors
  const Run r = hitops(dir, "--batch " + quoted(list) + " --out " + quoted(dir / "out") + " --threads 1 --quiet");
  CHECK(r.status == 1);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 2); // one line per failed mesh
  std::set<std::string> out;
  for(const auto& e : fs::directory_iterator(dir.path / "out")) out.insert(e.path().filename().string());
  CHECK(out == std::set<std::string>{"good.seg", "good.json", "summary.tsv"});
  const std::string summary = read_text(dir / "out/summary.tsv");
  CHECK(summary.find("good\t" + good + "\tok\t48\t") != std::string::npos);
  CHECK(summary.find("bad\t" + bad + "\tfailed\t") != std::string::npos);
  CHECK(summary.find("missing\t") != std::string::npos);
  CHECK(std::count(summary.begin(), summary.end(), '\n') == 4);
}

namespace {

// The rows of a summary.tsv, each as its columns by the names of the header.
std::vector<std::map<std::string, std::string> > summary_rows(const std::string& path)
{
  std::istringstream in(read_text(path));
  std::vector<std::string> header;
  std::vector<std::map<std::string, std::string> > rows;
  for(std::string line; std::getline(in, line);)
  {
    std::vector<std::string> cells;
    std::istringstream cells_in(line);
    for(std::string cell; std::getline(cells_in, cell, '\t');) cells.push_back(cell);
    if(!line.empty() && line.back() == '\t') cells.push_back(std::string());
    if(header.empty())
    {
      header = cells;
      continue;
    }
    REQUIRE(cells.size() == header.size());
    std::map<std::string, std::string> row;
    for(std::size_t k = 0; k < cells.size(); ++k) row[header[k]] = cells[k];
    rows.push_back(row);
  }
  return rows;
}

// The digest `sha256sum` gives for the file.
std::string sha256sum(const std::string& path)
{
  std::FILE* tool = popen(("sha256sum " + quoted(path)).c_str(), "r");
  REQUIRE(tool != nullptr);
  char line[128] = {0};
  const bool got = std::fgets(line, sizeof(line), tool) != nullptr;
  pclose(tool);
  REQUIRE(got);
  return std::string(line).substr(0, 64);
}

} // namespace

TEST_CASE("hitops batch: the summary gives the SHA-256 of every input that can be read", "[robustness][hitops]")
{
  Temp_dir dir;
  const std::string good = std::string(PD_EXAMPLE_DATA_DIR) + "/dumbbell.off";
  const std::string bad = dir.file("bad.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 x\n");
  const std::string list = dir.file("list.txt", good + "\n" + bad + "\n" + (dir / "missing.off") + "\n");
  std::string good_digest, bad_digest;
  REQUIRE(Part_decomposition_tools::sha256_of_file(good, good_digest));
  REQUIRE(Part_decomposition_tools::sha256_of_file(bad, bad_digest));
  CHECK(good_digest == sha256sum(good));
  CHECK(bad_digest == sha256sum(bad));
  for(const std::string run : {"decomposed", "skipped"})
  {
    INFO(run);
    hitops(dir, "--batch " + quoted(list) + " --out " + quoted(dir / "out") + " --threads 1");
    const auto rows = summary_rows(dir / "out/summary.tsv");
    REQUIRE(rows.size() == 3);
    CHECK(rows[0].at("status") == (run == "decomposed" ? "ok" : "skipped"));
    CHECK(rows[0].at("sha256") == good_digest);
    CHECK(rows[1].at("status") == "failed");
    CHECK(rows[1].at("sha256") == bad_digest);
    CHECK(rows[1].at("message").find("line 6") != std::string::npos);
    CHECK(rows[2].at("status") == "failed");
    CHECK(rows[2].at("sha256").empty());
  }
}

TEST_CASE("hitops batch: a mesh over --mesh-timeout is stopped, and the batch goes on", "[robustness][hitops]")
{
  Temp_dir dir;
  const std::string table = std::string(PD_EXAMPLE_DATA_DIR) + "/table.off";
  const std::string dumbbell = std::string(PD_EXAMPLE_DATA_DIR) + "/dumbbell.off";
  const std::string list = dir.file("list.txt", table + "\n" + dumbbell + "\n");
  // these decompositions take far more than a millisecond: each mesh times out, in order
  Run r = hitops(dir, "--batch " + quoted(list) + " --out " + quoted(dir / "out") + " --mesh-timeout 0.001");
  CHECK(r.status == 1);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 2);
  auto rows = summary_rows(dir / "out/summary.tsv");
  REQUIRE(rows.size() == 2);
  CHECK(rows[0].at("status") == "timeout");
  CHECK(rows[0].at("message").find("--mesh-timeout") != std::string::npos);
  CHECK(rows[1].at("name") == "dumbbell");
  CHECK(rows[1].at("status") == "timeout");
  CHECK(rows[1].at("sha256") == sha256sum(dumbbell));
  // a killed mesh leaves nothing, not even a temporary file
  std::set<std::string> out;
  for(const auto& e : fs::directory_iterator(dir.path / "out")) out.insert(e.path().filename().string());
  CHECK(out == std::set<std::string>{"summary.tsv"});

  // within the limit, the child process gives the outputs and the summary of the batch without one
  const std::string box = dir.file("box.off", box_off());
  const std::string short_list = dir.file("short.txt", box + "\n" + (dir / "missing.off") + "\n");
  r = hitops(dir, "--batch " + quoted(short_list) + " --out " + quoted(dir / "limited") + " --threads 1 --mesh-timeout 600");
  CHECK(r.status == 1); // the missing file
  r = hitops(dir, "--batch " + quoted(short_list) + " --out " + quoted(dir / "unlimited") + " --threads 1");
  rows = summary_rows(dir / "limited/summary.tsv");
  const auto unlimited = summary_rows(dir / "unlimited/summary.tsv");
  REQUIRE(rows.size() == 2);
  REQUIRE(unlimited.size() == 2);
  CHECK(rows[0].at("status") == "ok");
  for(const char* column : {"status", "faces", "parts", "sha256"}) CHECK(rows[0].at(column) == unlimited[0].at(column));
  CHECK(read_text(dir / "limited/box.seg") == read_text(dir / "unlimited/box.seg"));
  CHECK(read_text(dir / "limited/box.json") == read_text(dir / "unlimited/box.json"));
  CHECK(rows[1].at("status") == "failed");
  CHECK(rows[1].at("message") == unlimited[1].at("message"));
}

TEST_CASE("hitops gives the same labels for 1 and 2 threads", "[robustness][hitops][determinism][data]")
{
  Temp_dir dir;
  const std::string input = std::string(PD_EXAMPLE_DATA_DIR) + "/table.off";
  REQUIRE(hitops(dir, quoted(input) + " --threads 1 --labels " + quoted(dir / "a.seg")).status == 0);
  REQUIRE(hitops(dir, quoted(input) + " --threads 2 --labels " + quoted(dir / "b.seg")).status == 0);
  const std::string a = read_text(dir / "a.seg");
  CHECK(std::count(a.begin(), a.end(), '\n') == 8714);
  CHECK(a == read_text(dir / "b.seg"));
}

#endif // PD_HITOPS_PATH
