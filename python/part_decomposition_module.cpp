// The compiled core part_decomposition._core of the Python package part_decomposition: decompose()
// on numpy arrays and decompose_file() on a mesh file, with every named parameter of
// CGAL::Part_decomposition::decompose() as a keyword, and the parts at every level of the hierarchy.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Part_decomposition/IO/read_mesh.h>
#include <CGAL/Part_decomposition/IO/write_labels_gltf.h>
#include <CGAL/Part_decomposition/decompose.h>

#include "decomposition_settings.h"
#include "part_palette.h"
#include "part_renderer.h"

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/task_arena.h>
#endif

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace py = pybind11;

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef CGAL::Part_decomposition::Superquadric<K> Superquadric;
namespace PD = CGAL::Part_decomposition;
namespace PDP = CGAL::Part_decomposition::parameters;

// The keywords, at the library's defaults: decompose()'s named parameters, then the module's own.
struct Parameters : Part_decomposition_tools::Decomposition_settings
{
  int threads = 0;                            // 0: all cores
};

// A Python value of the type of the field; a TypeError that names the keyword otherwise.
template <typename T>
T cast(const std::string& keyword, py::handle value, const char* expected)
{
  try
  {
    return value.cast<T>();
  }
  catch(const py::cast_error&)
  {
    throw py::type_error("keyword '" + keyword + "' expects " + expected + ", got " +
                         std::string(py::str(py::type::handle_of(value).attr("__name__"))));
  }
}

// A value from its text, as hitops reads it: an enumerator from its lower-case name (or the short
// name of hitops), the switches of the method.
template <typename E>
E from_text(const std::string& keyword, py::handle value)
{
  E e{};
  const std::string s = cast<std::string>(keyword, value, "a string");
  try
  {
    Part_decomposition_tools::parse_value(s, e);
  }
  catch(const std::invalid_argument& error)
  {
    throw py::value_error("keyword '" + keyword + "' expects " + error.what() + ", got '" + s + "'");
  }
  return e;
}

typedef std::function<void(Parameters&, const std::string&, py::handle)> Setter;
typedef std::function<py::object(const Parameters&)> Getter;
struct Keyword
{
  Setter set;
  Getter get;
};

template <typename T, typename Owner>
Keyword field(T Owner::*member, const char* expected)
{
  return {[member, expected](Parameters& p, const std::string& k, py::handle v) { p.*member = cast<T>(k, v, expected); },
          [member](const Parameters& p) { return py::cast(p.*member); }};
}

// Enumerations as their lower-case names, the switches of the method as hitops writes them.
template <typename E>
constexpr bool has_text_form = std::is_enum<E>::value || std::is_same<E, PD::Method_variant>::value;

template <typename E, typename Owner>
std::enable_if_t<has_text_form<E>, Keyword> keyword_of(E Owner::*member)
{
  return {[member](Parameters& p, const std::string& k, py::handle v) { p.*member = from_text<E>(k, v); },
          [member](const Parameters& p) { return py::cast(Part_decomposition_tools::format_value(p.*member)); }};
}

// The other settings as the Python value of their type.
template <typename T, typename Owner>
std::enable_if_t<!has_text_form<T>, Keyword> keyword_of(T Owner::*member)
{
  if(std::is_same<T, std::optional<std::size_t> >::value) return field(member, "None or a positive int");
  if(std::is_same<T, bool>::value) return field(member, "a bool");
  if(std::is_same<T, double>::value) return field(member, "a float");
  if(std::is_unsigned<T>::value) return field(member, "a non-negative int");
  if(std::is_integral<T>::value) return field(member, "an int");
  if(std::is_same<T, std::vector<int> >::value) return field(member, "a sequence of int");
  if(std::is_same<T, std::vector<double> >::value) return field(member, "a sequence of float");
  return field(member, "a sequence of 4 floats");
}

// Every keyword, with how it is read and its default (for DEFAULTS and the documentation): the
// settings of decompose(), then the module's own.
const std::map<std::string, Keyword>& keywords()
{
  static const std::map<std::string, Keyword> table = [] {
    std::map<std::string, Keyword> t;
    Part_decomposition_tools::for_each_setting([&](const char* name, auto member) { t.emplace(name, keyword_of(member)); });
    t.emplace("threads", field(&Parameters::threads, "None or a positive int"));
    return t;
  }();
  return table;
}

Parameters parameters_from(const py::kwargs& kwargs)
{
  Parameters p;
  for(const auto& item : kwargs)
  {
    const std::string k = py::str(item.first);
    const auto it = keywords().find(k);
    if(it == keywords().end())
      throw py::type_error("unexpected keyword argument '" + k + "' (part_decomposition.DEFAULTS lists them)");
    // None keeps the default: the spelling of an absent number_of_parts or threads
    if(!item.second.is_none()) it->second.set(p, k, item.second);
  }
  if(p.number_of_parts && *p.number_of_parts == 0) throw py::value_error("number_of_parts must be at least 1");
  if(p.threads < 0) throw py::value_error("threads must be at least 1");
  return p;
}

py::dict default_parameters()
{
  const Parameters p;
  py::dict d;
  for(const auto& k : keywords()) d[py::str(k.first)] = k.second.get(p);
  d["threads"] = py::none();
  return d;
}

// One superquadric in the input's coordinates.
struct Primitive
{
  std::array<double, 3> center, scales;
  std::array<double, 9> rotation; // row by row; column j is the local axis j
  std::array<double, 2> exponents;
};

struct Result
{
  std::vector<std::size_t> labels; // one per input face
  std::size_t number_of_parts = 0;
  std::vector<Primitive> primitives;
  PD::Stage_timings timings;
  double read_seconds = 0.;
  PD::Part_hierarchy<K> hierarchy; // the levels of labels_at()
  PD::IO::Mesh_file_info info; // mesh faces to input faces
};

// decompose() with the parameters; labels per mesh face, in the order of faces(mesh).
std::vector<std::size_t> run(const Mesh& mesh, const Parameters& p, Result& r)
{
  std::vector<std::size_t> part(num_faces(mesh), 0);
  std::vector<Superquadric> primitives;
  auto np = PDP::combine(Part_decomposition_tools::named_parameters(p),
                         PDP::primitive_output_iterator(std::back_inserter(primitives)),
                         PDP::stage_timings(&r.timings), PDP::part_hierarchy(&r.hierarchy));
#ifdef CGAL_LINKED_WITH_TBB
  // an arena of `threads` threads: the caller's other TBB work and global settings are untouched
  tbb::task_arena arena(p.threads > 0 ? p.threads : tbb::task_arena::automatic);
  arena.execute([&] { r.number_of_parts = PD::decompose(mesh, CGAL::make_property_map(part), np); });
#else
  r.number_of_parts = PD::decompose(mesh, CGAL::make_property_map(part), np);
#endif
  for(const Superquadric& q : primitives)
  {
    const K::Point_3 c = q.center();
    r.primitives.push_back(Primitive{{{c.x(), c.y(), c.z()}}, q.scales(), q.rotation(), {{q.epsilon1(), q.epsilon2()}}});
  }
  return part;
}

py::array_t<double> vector_array(const double* data, std::vector<py::ssize_t> shape)
{
  py::array_t<double> a(shape);
  std::copy(data, data + a.size(), a.mutable_data());
  return a;
}

py::array_t<std::int64_t> index_array(const std::vector<std::size_t>& v)
{
  py::array_t<std::int64_t> a(py::ssize_t(v.size()));
  std::copy(v.begin(), v.end(), a.mutable_data());
  return a;
}

// The input faces of each part, in increasing order.
py::list parts_list(const Result& r)
{
  std::vector<std::vector<std::size_t> > faces(r.number_of_parts);
  for(std::size_t i = 0; i < r.labels.size(); ++i) faces[r.labels[i]].push_back(i);
  py::list out;
  for(const auto& f : faces) out.append(index_array(f));
  return out;
}

py::array_t<std::int64_t> part_faces(const Result& r, py::ssize_t k)
{
  if(k < 0 || std::size_t(k) >= r.number_of_parts)
    throw py::index_error("part " + std::to_string(k) + " out of range: there are " + std::to_string(r.number_of_parts) +
                          " parts");
  std::vector<std::size_t> faces;
  for(std::size_t i = 0; i < r.labels.size(); ++i)
    if(r.labels[i] == std::size_t(k)) faces.push_back(i);
  return index_array(faces);
}

std::size_t number_of_levels(const Result& r) { return r.hierarchy.number_of_leaves(); }

// The labels of level k of the hierarchy, numbered as decompose(number_of_parts=k) numbers them.
py::array_t<std::int64_t> labels_at(const Result& r, py::ssize_t k)
{
  const std::size_t levels = number_of_levels(r);
  if(k < 1 || std::size_t(k) > levels)
    throw py::value_error("labels_at(" + std::to_string(k) + "): the levels are 1 to " + std::to_string(levels));
  return index_array(PD::IO::labels_in_file_order(r.info, r.hierarchy.labels(std::size_t(k))));
}

py::dict timings_dict(const Result& r)
{
  py::dict d;
  d["read"] = r.read_seconds;
  d["pieces"] = r.timings.pieces;
  d["prior"] = r.timings.prior;
  d["tsdf"] = r.timings.tsdf;
  d["fitting"] = r.timings.fitting;
  d["fitting_zones"] = r.timings.fitting_zones;
  d["over_segmentation"] = r.timings.over_segmentation;
  d["assignment"] = r.timings.assignment;
  d["hierarchy"] = r.timings.hierarchy;
  d["total"] = r.timings.total;
  d["overlapping"] = r.timings.overlapping;
  return d;
}

// (n, 3) finite coordinates, as doubles.
std::vector<std::array<double, 3> > read_vertices(py::handle object)
{
  const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(object);
  if(!a) throw py::value_error("vertices must be an (n, 3) array of floats");
  if(a.ndim() != 2 || a.shape(1) != 3)
    throw py::value_error("vertices must be an (n, 3) array of floats, got shape " + std::string(py::str(a.attr("shape"))));
  std::vector<std::array<double, 3> > out(std::size_t(a.shape(0)));
  const double* d = a.data();
  for(std::size_t i = 0; i < out.size(); ++i)
    for(int k = 0; k < 3; ++k)
    {
      out[i][k] = d[3 * i + std::size_t(k)];
      if(!std::isfinite(out[i][k]))
        throw py::value_error("vertices[" + std::to_string(i) + "] has a non-finite coordinate");
    }
  return out;
}

// (m, 3) integers in [0, n).
std::vector<std::array<std::int64_t, 3> > read_faces(py::handle object, std::size_t n)
{
  const py::array any = py::array::ensure(object);
  if(!any) throw py::value_error("faces must be an (m, 3) array of integers");
  const char kind = any.dtype().kind();
  if(kind != 'i' && kind != 'u')
    throw py::value_error("faces must be an (m, 3) array of integers, got dtype " + std::string(py::str(any.dtype())));
  if(any.ndim() != 2 || any.shape(1) != 3)
    throw py::value_error("faces must be an (m, 3) array of integers, got shape " + std::string(py::str(any.attr("shape"))));
  // an unsigned index beyond the int64 range is out of range anyway
  const auto a = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(any);
  std::vector<std::array<std::int64_t, 3> > out(std::size_t(a.shape(0)));
  const std::int64_t* d = a.data();
  const bool wrapped = kind == 'u' && any.dtype().itemsize() == 8;
  for(std::size_t i = 0; i < out.size(); ++i)
    for(int k = 0; k < 3; ++k)
    {
      const std::int64_t id = d[3 * i + std::size_t(k)];
      out[i][k] = id;
      if(id < 0 || std::uint64_t(id) >= n)
        throw py::value_error("faces[" + std::to_string(i) + ", " + std::to_string(k) + "] = " +
                              (wrapped && id < 0 ? std::to_string(std::uint64_t(id)) : std::to_string(id)) +
                              " is not a vertex index: vertices has " + std::to_string(n) + " rows");
    }
  return out;
}

Result decompose_arrays(py::handle vertices, py::handle faces, const py::kwargs& kwargs)
{
  const Parameters p = parameters_from(kwargs);
  const std::vector<std::array<double, 3> > points = read_vertices(vertices);
  const std::vector<std::array<std::int64_t, 3> > triangles = read_faces(faces, points.size());
  Result r;
  py::gil_scoped_release release;
  const auto t0 = std::chrono::steady_clock::now();
  Mesh mesh;
  // the reader's own construction: welded, oriented, one label per row of `faces`
  const PD::IO::Mesh_file_info info =
    PD::IO::triangle_mesh_from_polygon_soup(points, triangles, mesh, PD::parameters::weld_tolerance(p.weld_tolerance));
  r.read_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.labels = PD::IO::labels_in_file_order(info, run(mesh, p, r));
  r.info = info;
  return r;
}

Result decompose_path(py::object path_like, const py::kwargs& kwargs)
{
  const std::string path = py::str(py::module_::import("os").attr("fspath")(path_like));
  const Parameters p = parameters_from(kwargs);
  Result r;
  py::gil_scoped_release release;
  const auto t0 = std::chrono::steady_clock::now();
  Mesh mesh;
  const PD::IO::Mesh_file_info info = PD::IO::read_triangle_mesh(path, mesh, PD::parameters::weld_tolerance(p.weld_tolerance));
  r.read_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.labels = PD::IO::labels_in_file_order(info, run(mesh, p, r));
  r.info = info;
  return r;
}

// One line per keyword: its default and, for a named parameter, what it means.
std::string keyword_documentation()
{
  std::string doc;
  const py::dict d = default_parameters();
  for(const auto& item : d)
  {
    const std::string name = py::str(item.first);
    doc += "    " + name + "=" + std::string(py::repr(item.second));
    if(const PD::Parameter_description* p = PD::internal::find_parameter(name.c_str()))
      doc += std::string(": ") + p->meaning;
    else if(name == "threads")
      doc += ": the number of threads; None: all cores";
    doc += "\n";
  }
  return doc;
}

namespace render = Part_decomposition_tools::render;

// (m,) non-negative integer labels.
std::vector<std::size_t> read_labels(py::handle object)
{
  const auto a = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(object);
  if(!a || a.ndim() != 1) throw py::value_error("labels must be a one-dimensional array of integers");
  std::vector<std::size_t> labels(std::size_t(a.shape(0)));
  for(std::size_t i = 0; i < labels.size(); ++i)
  {
    if(a.data()[i] < 0) throw py::value_error("labels must not be negative");
    labels[i] = std::size_t(a.data()[i]);
  }
  return labels;
}

render::Picture_options picture_options(const std::pair<int, int>& size)
{
  if(size.first < 2 || size.second < 2 || size.first > 4096 || size.second > 4096)
    throw py::value_error("size must be (width, height), each from 2 to 4096");
  render::Picture_options o;
  o.width = size.first;
  o.height = size.second;
  return o;
}

// The PNG of the triangles beside their parts, one label per triangle.
template <typename TriangleRange>
py::bytes picture_png(const std::vector<std::array<double, 3> >& points, const TriangleRange& triangles,
                      const std::vector<std::size_t>& labels, const render::Picture_options& options)
{
  std::vector<render::Rgb> colours;
  for(std::size_t l : labels) colours.push_back(Part_decomposition_tools::part_rgb(l));
  std::vector<std::uint8_t> png;
  {
    py::gil_scoped_release release;
    png = render::encode_png(render::render_input_and_parts(points, triangles, colours, options));
  }
  return py::bytes(reinterpret_cast<const char*>(png.data()), png.size());
}

// render_parts() on arrays: one label per row of faces.
py::bytes render_arrays_png(py::handle vertices, py::handle faces, py::handle labels, std::pair<int, int> size)
{
  const render::Picture_options options = picture_options(size);
  const std::vector<std::array<double, 3> > points = read_vertices(vertices);
  const std::vector<std::array<std::int64_t, 3> > triangles = read_faces(faces, points.size());
  const std::vector<std::size_t> l = read_labels(labels);
  if(l.size() != triangles.size())
    throw py::value_error("labels has " + std::to_string(l.size()) + " entries, faces " + std::to_string(triangles.size()) +
                          " rows");
  return picture_png(points, triangles, l, options);
}

// render_parts() on a mesh file: one label per face of the file, in its order (decompose_file()).
py::bytes render_file_png(py::object path_like, py::handle labels, std::pair<int, int> size)
{
  const render::Picture_options options = picture_options(size);
  const std::string path = py::str(py::module_::import("os").attr("fspath")(path_like));
  const std::vector<std::size_t> l = read_labels(labels);
  Mesh mesh;
  const PD::IO::Mesh_file_info info = PD::IO::read_triangle_mesh(path, mesh);
  if(l.size() != info.number_of_input_faces)
    throw py::value_error("labels has " + std::to_string(l.size()) + " entries, the file " +
                          std::to_string(info.number_of_input_faces) + " faces");
  std::vector<std::array<double, 3> > points;
  std::vector<std::array<std::size_t, 3> > triangles;
  render::surface_mesh_arrays(mesh, points, triangles);
  std::vector<std::size_t> face_labels;
  for(std::size_t i = 0; i < triangles.size(); ++i) face_labels.push_back(l[info.face_to_input[i]]);
  return picture_png(points, triangles, face_labels, options);
}

} // namespace

// write_labels_glb(output, input, labels, number_of_labels): the library's writer, labels in the
// input file's face order (those of decompose_file()).
void write_labels_glb_file(const std::string& output, const std::string& input,
                           const py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>& labels,
                           std::optional<std::size_t> number_of_labels)
{
  if(labels.ndim() != 1) throw std::invalid_argument("labels must be a one-dimensional array");
  std::vector<std::size_t> face_label(std::size_t(labels.shape(0)));
  std::size_t largest = 0;
  for(std::size_t i = 0; i < face_label.size(); ++i)
  {
    const std::int64_t l = labels.at(py::ssize_t(i));
    if(l < 0) throw std::invalid_argument("labels must not be negative");
    face_label[i] = std::size_t(l);
    largest = (std::max)(largest, face_label[i] + 1);
  }
  const std::size_t n = number_of_labels ? *number_of_labels : largest;
  std::ostringstream glb;
  {
    py::gil_scoped_release release;
    PD::IO::write_labels_glb(glb, input, face_label, n);
  }
  std::ofstream out(output, std::ios::binary);
  out << glb.str();
  out.close();
  if(!out) throw std::invalid_argument("cannot write '" + output + "'");
}

PYBIND11_MODULE(_core, m)
{
  m.doc() = "The compiled core of part_decomposition: import part_decomposition instead.";
  m.attr("__version__") = PART_DECOMPOSITION_VERSION;

  // a ValueError, so that `except ValueError` catches every refused input
  py::register_exception<PD::Invalid_input>(m, "InvalidInput", PyExc_ValueError);

  py::class_<Primitive>(m, "Primitive", "The superquadric of one part, in the input's coordinates.")
    .def_property_readonly("center", [](const Primitive& q) { return vector_array(q.center.data(), {3}); },
                           "(3,) the centre")
    .def_property_readonly("rotation", [](const Primitive& q) { return vector_array(q.rotation.data(), {3, 3}); },
                           "(3, 3) the rotation, local to world: column j is the local axis j")
    .def_property_readonly("scales", [](const Primitive& q) { return vector_array(q.scales.data(), {3}); },
                           "(3,) the semi-axes along the local axes")
    .def_property_readonly("exponents", [](const Primitive& q) { return vector_array(q.exponents.data(), {2}); },
                           "(2,) epsilon1 (along the local z axis) and epsilon2 (in the local xy plane)")
    .def("__repr__", [](const Primitive& q) {
      return "Primitive(center=[" + std::to_string(q.center[0]) + ", " + std::to_string(q.center[1]) + ", " +
             std::to_string(q.center[2]) + "], scales=[" + std::to_string(q.scales[0]) + ", " +
             std::to_string(q.scales[1]) + ", " + std::to_string(q.scales[2]) + "])";
    });

  py::class_<Result>(m, "Decomposition", "The parts of a mesh.")
    .def_property_readonly("labels", [](const Result& r) { return index_array(r.labels); },
                           "(m,) int64: the part of each input face, in [0, number_of_parts)")
    .def_readonly("number_of_parts", &Result::number_of_parts, "the number of parts")
    .def_readonly("primitives", &Result::primitives, "one Primitive per part, part k explained by primitives[k]")
    .def_property_readonly("timings", &timings_dict,
                           "wall-clock seconds: read (the mesh from the file or arrays) and each stage of decompose()")
    .def("parts", &parts_list, "one int64 array per part: the input faces of part k, increasing")
    .def("part_faces", &part_faces, py::arg("k"), "(n_k,) int64: the input faces of part k, increasing")
    .def_property_readonly("levels", [](const Result& r) {
        return py::module_::import("builtins").attr("range")(1, number_of_levels(r) + 1);
      }, "the numbers of parts labels_at() accepts: range(1, leaves + 1)")
    .def("labels_at", &labels_at, py::arg("k"),
         "(m,) int64: the part of each input face at level k of this result's part hierarchy (k parts, "
         "those of decompose(number_of_parts=k))")
    .def("__repr__", [](const Result& r) {
      return "Decomposition(" + std::to_string(r.labels.size()) + " faces, " + std::to_string(r.number_of_parts) + " parts)";
    });

  // static: pybind11 keeps the pointers
  static const std::string decompose_doc = std::string("decompose(vertices, faces, **parameters) -> Decomposition\n\n"
         "Decomposes the triangle mesh given by vertices, an (n, 3) float array, and faces, an (m, 3)\n"
         "integer array of vertex indices. The mesh is built as the package's reader builds it from a\n"
         "file (equal vertices merged, border vertices within weld_tolerance of the bounding box\n"
         "diagonal welded, the soup oriented, closed pieces outward); labels has one part\n"
         "per row of faces. Runs with the GIL released, on `threads` threads (default: all cores;\n"
         "the labels do not depend on it). Raises ValueError (InvalidInput for the library's checks)\n"
         "for a bad array or a parameter out of its range, TypeError for an unknown keyword.\n\n"
         "Keywords (the named parameters of CGAL::Part_decomposition::decompose(), and of the reader\n"
         "for weld_tolerance), with defaults:\n") +
    keyword_documentation();
  m.attr("_keyword_documentation") = keyword_documentation();
  m.def("decompose", &decompose_arrays, py::arg("vertices"), py::arg("faces"), decompose_doc.c_str());
  m.def("decompose_file", &decompose_path, py::arg("path"),
        "decompose_file(path, **parameters) -> Decomposition\n\n"
         "Reads the mesh file (OFF, OBJ, PLY, STL, glTF .gltf/.glb) with the package's reader and\n"
         "decomposes it: the labels are in the file's face order, as written by hitops --labels.\n"
         "Same keywords as decompose().\n");
  m.def("write_labels_glb", &write_labels_glb_file, py::arg("output"), py::arg("input"), py::arg("labels"),
        py::arg("number_of_labels") = py::none(),
        "write_labels_glb(output, input, labels, number_of_labels=None)\n\n"
        "Writes the mesh file input (any format of decompose_file()) as a binary glTF file output, with\n"
        "the label of every face as an EXT_mesh_features feature ID (vertex attribute _FEATURE_ID_0);\n"
        "a glTF input keeps its scene, materials and textures. labels: one per face in the file's\n"
        "order, as decompose_file() gives them; number_of_labels (the featureCount) defaults to\n"
        "max(labels) + 1. ValueError for labels that do not fit the file.\n");
  m.def("_render_arrays_png", &render_arrays_png, py::arg("vertices"), py::arg("faces"), py::arg("labels"),
        py::arg("size"), "The PNG of render_parts() on arrays, as bytes: use render_parts().");
  m.def("_render_file_png", &render_file_png, py::arg("path"), py::arg("labels"), py::arg("size"),
        "The PNG of render_parts() on a mesh file, as bytes: use render_parts().");
  m.attr("DEFAULTS") = default_parameters();
}
