// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_READ_GLTF_SOUP_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_READ_GLTF_SOUP_H

#include <CGAL/Part_decomposition/internal/io/polygon_soup.h>
#include <CGAL/Part_decomposition/internal/io/read_error.h>

// The JSON of glTF is parsed by nlohmann/json (Debian: nlohmann-json3-dev), which throws on any
// malformed text; without it, glTF files are refused with a clear error.
#if __has_include(<nlohmann/json.hpp>)
#include <nlohmann/json.hpp>
#define CGAL_PART_DECOMPOSITION_HAS_GLTF 1
#endif

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

// Why a glTF file cannot be read, for the message of the caller.
struct Gltf_error : Read_error
{
  using Read_error::Read_error;
};

// Bytes of a glTF buffer: a view into the GLB or decoded data owned here.
struct Gltf_buffer
{
  std::vector<unsigned char> owned;
  const unsigned char* data = nullptr;
  std::size_t size = 0; // byteLength, checked against the data
};

// Little-endian unsigned integer of `n` bytes.
inline std::uint64_t little_endian(const unsigned char* p, int n)
{
  std::uint64_t u = 0;
  for(int k = n; k-- > 0;) u = (u << 8) | p[k];
  return u;
}

// Standard base64 (RFC 4648), '=' padding at the end only; throws on any other character.
inline std::vector<unsigned char> decode_base64(const char* first, const char* last)
{
  auto value = [](char c) -> int {
    if(c >= 'A' && c <= 'Z') return c - 'A';
    if(c >= 'a' && c <= 'z') return c - 'a' + 26;
    if(c >= '0' && c <= '9') return c - '0' + 52;
    if(c == '+') return 62;
    if(c == '/') return 63;
    return -1;
  };
  while(last != first && last[-1] == '=') --last;
  std::vector<unsigned char> out;
  out.reserve(std::size_t(last - first) / 4 * 3 + 3);
  std::uint32_t bits = 0;
  int n = 0;
  for(const char* p = first; p != last; ++p)
  {
    const int v = value(*p);
    if(v < 0) throw Gltf_error("invalid base64 data");
    bits = (bits << 6) | std::uint32_t(v);
    if(++n == 4)
    {
      out.push_back((unsigned char)(bits >> 16));
      out.push_back((unsigned char)(bits >> 8));
      out.push_back((unsigned char)bits);
      bits = 0;
      n = 0;
    }
  }
  if(n == 1) throw Gltf_error("invalid base64 data");
  if(n == 2) out.push_back((unsigned char)(bits >> 4));
  if(n == 3)
  {
    out.push_back((unsigned char)(bits >> 10));
    out.push_back((unsigned char)(bits >> 2));
  }
  return out;
}

// A relative URI of a side-by-side file, percent-decoded. Absolute paths, other schemes and ".."
// are refused: a file must not make the reader open files outside its folder.
inline std::string relative_path_of_uri(const std::string& uri)
{
  std::string path;
  for(std::size_t i = 0; i < uri.size(); ++i)
  {
    if(uri[i] == '%' && i + 2 < uri.size() && std::isxdigit((unsigned char)uri[i + 1]) &&
       std::isxdigit((unsigned char)uri[i + 2]))
    {
      path += char(std::stoi(uri.substr(i + 1, 2), nullptr, 16));
      i += 2;
    }
    else
      path += uri[i];
  }
  const bool has_scheme = path.find(':') != std::string::npos;
  const bool escapes = path == ".." || path.compare(0, 3, "../") == 0 || path.find("/../") != std::string::npos ||
                       (path.size() >= 3 && path.compare(path.size() - 3, 3, "/..") == 0);
  if(path.empty() || path[0] == '/' || path[0] == '\\' || has_scheme || escapes || path.find('\0') != std::string::npos)
    throw Gltf_error("buffer URI '" + uri + "' is not a file next to the glTF file");
  return path;
}

#ifdef CGAL_PART_DECOMPOSITION_HAS_GLTF

/*
A reader of the triangles of glTF 2.0 files, .gltf (JSON, buffers as data: URIs or side-by-side
files) and .glb (binary container). Every triangle primitive (TRIANGLES, TRIANGLE_STRIP,
TRIANGLE_FAN) of every mesh instanced by a node of the default scene is read, its positions
transformed by the node's global transform (matrix or translation, rotation, scale, nested), with
or without indices of any integer type. The triangles come in this order: the nodes of the scene
depth first (a node before its children, in the order of the scene's and the node's lists), the
primitives of the node's mesh in their order, the triangles of a primitive in index order. The
writers of glTF files walk the same primitive instances (for_each_primitive_instance()), so that
triangle i of the soup is known as a triangle of a primitive of the file.

Every index into a JSON array, every offset, length, stride and count of a buffer view or an
accessor is checked before any byte is read; a node hierarchy that is not a forest is refused.
*/
class Gltf_soup_reader
{
public:
  typedef nlohmann::json Json;
  typedef std::array<double, 16> Matrix; // column-major, as in glTF

  // The elements of an accessor, bounds-checked: element i starts at data + i * stride.
  struct Accessor
  {
    const unsigned char* data = nullptr; // null: every component is 0
    std::size_t count = 0, stride = 0, components = 0, element_size = 0;
    int component_type = 0;
    bool normalized = false;
  };

  // A triangle primitive of a mesh instanced by a node: the triangles of the soup in their order
  // are those of these instances, one after the other.
  struct Primitive_instance
  {
    std::size_t node = 0, mesh = 0, primitive = 0;
    Matrix world{};        // the node's global transform
    bool mirrored = false; // the transform mirrors: the soup turns the triangles over
    Accessor positions;
    // the corners of each triangle as vertex indices of the primitive (std::uint64_t(-1) or
    // beyond positions.count: no vertex), in the file's winding
    std::vector<std::array<std::uint64_t, 3> > triangles;
  };

  // `directory`: the folder of the .gltf file, for side-by-side buffers (with a final '/', or empty).
  Gltf_soup_reader(const char* begin, const char* end, std::string directory)
    : m_begin(reinterpret_cast<const unsigned char*>(begin)), m_end(reinterpret_cast<const unsigned char*>(end)),
      m_directory(std::move(directory))
  {}

  // Parses the JSON and loads the buffers; throws Gltf_error.
  void load()
  {
    const unsigned char* bin = nullptr;
    std::size_t bin_size = 0;
    const bool glb = m_end - m_begin >= 4 && std::memcmp(m_begin, "glTF", 4) == 0;
    if(glb) parse_glb(bin, bin_size);
    else m_json = parse_json(reinterpret_cast<const char*>(m_begin), reinterpret_cast<const char*>(m_end));
    if(!m_json.is_object()) throw Gltf_error("the JSON is not an object");
    check_asset_and_extensions();
    load_buffers(bin, bin_size);
  }

  // Appends the points and triangles of the default scene to `soup`; throws Gltf_error.
  void read(Polygon_soup_arrays& soup)
  {
    load();
    for_each_primitive_instance([&](const Primitive_instance& p) { add_primitive_instance(p, soup); });
  }

  // Calls f(Primitive_instance) for every triangle primitive of the default scene, in the order
  // of the soup (after load()). The instance passed is reused from call to call.
  template <typename F>
  void for_each_primitive_instance(const F& f) const
  {
    Primitive_instance instance;
    for_each_mesh_instance([&](std::size_t node, std::size_t mesh, const Matrix& world) {
      const Json* primitives = member(element("meshes", mesh), "primitives");
      if(!primitives || !primitives->is_array()) throw Gltf_error("mesh " + std::to_string(mesh) + " has no primitives");
      instance.node = node;
      instance.mesh = mesh;
      instance.world = world;
      // a transform that mirrors turns the triangles over (glTF: clockwise winding)
      instance.mirrored = determinant(world) < 0.;
      for(std::size_t p = 0; p < primitives->size(); ++p)
      {
        instance.primitive = p;
        if(triangles_of_primitive((*primitives)[p], instance)) f(instance);
      }
    });
  }

  const Json& json() const { return m_json; }

  // The folder of the .gltf file, with a final '/', or empty.
  const std::string& directory() const { return m_directory; }

  // The bytes of buffer view `i`, bounds-checked: first, length.
  std::pair<const unsigned char*, std::size_t> buffer_view(std::uint64_t i) const
  {
    const Json& view = element("bufferViews", i);
    const std::uint64_t buffer = unsigned_value(required(view, "buffer"), "bufferView buffer");
    if(buffer >= m_buffers.size()) throw Gltf_error("bufferView refers to a missing buffer");
    const std::uint64_t offset = unsigned_member(view, "byteOffset", 0, "bufferView byteOffset");
    const std::uint64_t length = unsigned_value(required(view, "byteLength"), "bufferView byteLength");
    if(offset + length > m_buffers[buffer].size) throw Gltf_error("bufferView exceeds its buffer");
    return {m_buffers[buffer].data + offset, std::size_t(length)};
  }

  // Accessor `i`, bounds-checked against its buffer view and the view against its buffer.
  Accessor accessor(std::uint64_t i) const
  {
    const Json& a = element("accessors", i);
    if(member(a, "sparse")) throw Gltf_error("sparse accessors are not supported");
    Accessor out;
    out.component_type = int(unsigned_value(required(a, "componentType"), "accessor componentType"));
    out.components = number_of_components(required(a, "type"));
    out.element_size = std::size_t(component_size(out.component_type)) * out.components;
    out.count = std::size_t(unsigned_value(required(a, "count"), "accessor count"));
    const Json* normalized = member(a, "normalized");
    out.normalized = normalized && normalized->is_boolean() && normalized->get<bool>();
    out.stride = out.element_size;
    const Json* view_index = member(a, "bufferView");
    if(!view_index) return out;
    const std::uint64_t v = unsigned_value(*view_index, "accessor bufferView");
    const std::pair<const unsigned char*, std::size_t> view = buffer_view(v);
    out.stride = std::size_t(unsigned_member(element("bufferViews", v), "byteStride", out.element_size, "bufferView byteStride"));
    if(out.stride < out.element_size) throw Gltf_error("bufferView byteStride is smaller than an element");
    const std::uint64_t offset = unsigned_member(a, "byteOffset", 0, "accessor byteOffset");
    if(out.count > 0 && (offset > view.second || (out.count - 1) > (view.second - offset) / out.stride ||
                         std::uint64_t(out.stride) * (out.count - 1) + out.element_size > view.second - offset))
      throw Gltf_error("accessor " + std::to_string(i) + " reads past the end of its bufferView");
    out.data = view.first + offset;
    return out;
  }

  // Component c of element i, as the accessor defines it (normalized integers to [-1, 1] or [0, 1]).
  static double component(const Accessor& a, std::size_t i, std::size_t c)
  {
    if(!a.data) return 0.;
    const int size = component_size(a.component_type);
    const std::uint64_t u = little_endian(a.data + i * a.stride + c * std::size_t(size), size);
    switch(a.component_type)
    {
    case 5120: return a.normalized ? (std::max)(double(std::int8_t(u)) / 127., -1.) : double(std::int8_t(u));
    case 5121: return a.normalized ? double(u) / 255. : double(u);
    case 5122: return a.normalized ? (std::max)(double(std::int16_t(u)) / 32767., -1.) : double(std::int16_t(u));
    case 5123: return a.normalized ? double(u) / 65535. : double(u);
    case 5125: return double(std::uint32_t(u));
    default:
    {
      const std::uint32_t u32 = std::uint32_t(u);
      float f;
      std::memcpy(&f, &u32, 4);
      return double(f);
    }
    }
  }

  // m (x, y, z, h): a point for h = 1, a direction (the linear part alone) for h = 0.
  static std::array<double, 3> apply(const Matrix& m, double x, double y, double z, double h)
  {
    return {{m[0] * x + m[4] * y + m[8] * z + m[12] * h, m[1] * x + m[5] * y + m[9] * z + m[13] * h,
             m[2] * x + m[6] * y + m[10] * z + m[14] * h}};
  }

  // The determinant of the linear part of a transform.
  static double determinant(const Matrix& m)
  {
    return m[0] * (m[5] * m[10] - m[9] * m[6]) - m[4] * (m[1] * m[10] - m[9] * m[2]) + m[8] * (m[1] * m[6] - m[5] * m[2]);
  }

private:
  const unsigned char* m_begin;
  const unsigned char* m_end;
  std::string m_directory;
  Json m_json;
  std::vector<Gltf_buffer> m_buffers;

  static Json parse_json(const char* first, const char* last)
  {
    try
    {
      return Json::parse(first, last);
    }
    catch(const Json::exception& e)
    {
      throw Gltf_error(std::string("invalid JSON: ") + e.what());
    }
  }

  // 12-byte header (magic, version 2, length), then chunks: JSON first, then BIN if any.
  void parse_glb(const unsigned char*& bin, std::size_t& bin_size)
  {
    const std::size_t size = std::size_t(m_end - m_begin);
    if(size < 20) throw Gltf_error("truncated GLB header");
    if(little_endian(m_begin + 4, 4) != 2) throw Gltf_error("GLB version is not 2");
    const std::uint64_t length = little_endian(m_begin + 8, 4);
    if(length > size) throw Gltf_error("GLB length exceeds the file");
    bool has_json = false;
    for(std::uint64_t offset = 12; offset + 8 <= length;)
    {
      const std::uint64_t chunk = little_endian(m_begin + offset, 4), type = little_endian(m_begin + offset + 4, 4);
      if(chunk > length - offset - 8) throw Gltf_error("GLB chunk exceeds the file");
      const unsigned char* data = m_begin + offset + 8;
      if(!has_json)
      {
        if(type != 0x4E4F534Au) throw Gltf_error("the first GLB chunk is not JSON");
        m_json = parse_json(reinterpret_cast<const char*>(data), reinterpret_cast<const char*>(data + chunk));
        has_json = true;
      }
      else if(type == 0x004E4942u && bin == nullptr)
      {
        bin = data;
        bin_size = std::size_t(chunk);
      }
      offset += 8 + chunk;
    }
    if(!has_json) throw Gltf_error("GLB without JSON chunk");
  }

  // A member of an object, or nullptr if absent; throws if `object` is not an object.
  static const Json* member(const Json& object, const char* key)
  {
    if(!object.is_object()) throw Gltf_error(std::string("expected an object holding '") + key + "'");
    const auto it = object.find(key);
    return it == object.end() ? nullptr : &*it;
  }

  static const Json& required(const Json& object, const char* key)
  {
    const Json* v = member(object, key);
    if(!v) throw Gltf_error(std::string("missing '") + key + "'");
    return *v;
  }

  // A non-negative integer of at most 2^48 (offsets, lengths, counts, indices).
  static std::uint64_t unsigned_value(const Json& v, const char* what)
  {
    if(!v.is_number_unsigned() || v.get<std::uint64_t>() > (std::uint64_t(1) << 48))
      throw Gltf_error(std::string(what) + " is not a valid non-negative integer");
    return v.get<std::uint64_t>();
  }

  static std::uint64_t unsigned_member(const Json& object, const char* key, std::uint64_t fallback, const char* what)
  {
    const Json* v = member(object, key);
    return v ? unsigned_value(*v, what) : fallback;
  }

  // The element `i` of the top-level array `name`.
  const Json& element(const char* name, std::uint64_t i) const
  {
    const Json* array = member(m_json, name);
    if(!array || !array->is_array() || i >= array->size())
      throw Gltf_error(std::string(name) + "[" + std::to_string(i) + "] does not exist");
    return (*array)[std::size_t(i)];
  }

  void check_asset_and_extensions() const
  {
    const Json* asset = member(m_json, "asset");
    const Json* version = asset ? member(*asset, "version") : nullptr;
    if(!version || !version->is_string() || version->get<std::string>().compare(0, 2, "2.") != 0)
      throw Gltf_error("not a glTF 2.0 file (asset.version)");
    const Json* required = member(m_json, "extensionsRequired");
    if(!required) return;
    if(!required->is_array()) throw Gltf_error("extensionsRequired is not an array");
    for(const Json& e : *required)
    {
      const std::string name = e.is_string() ? e.get<std::string>() : std::string("?");
      // extensions that change no position or index are harmless
      const bool harmless = name == "KHR_mesh_quantization" || name == "KHR_lights_punctual" ||
                            name.compare(0, 14, "KHR_materials_") == 0 || name.compare(0, 12, "KHR_texture_") == 0;
      if(!harmless) throw Gltf_error("the file requires the unsupported extension '" + name + "'");
    }
  }

  // The data of every buffer: the GLB's BIN chunk, a data: URI or a side-by-side file.
  void load_buffers(const unsigned char* bin, std::size_t bin_size)
  {
    const Json* buffers = member(m_json, "buffers");
    if(!buffers) return;
    if(!buffers->is_array()) throw Gltf_error("buffers is not an array");
    m_buffers.resize(buffers->size());
    std::size_t total = std::size_t(m_end - m_begin);
    for(std::size_t i = 0; i < buffers->size(); ++i)
    {
      const Json& b = (*buffers)[i];
      Gltf_buffer& out = m_buffers[i];
      const std::uint64_t length = unsigned_value(required(b, "byteLength"), "buffer byteLength");
      const Json* uri = member(b, "uri");
      if(!uri)
      {
        if(i != 0 || !bin) throw Gltf_error("buffer " + std::to_string(i) + " has no data");
        out.data = bin;
        out.size = bin_size;
      }
      else
      {
        if(!uri->is_string()) throw Gltf_error("buffer uri is not a string");
        load_uri(uri->get<std::string>(), out);
        out.data = out.owned.data();
        out.size = out.owned.size();
        total += out.size;
      }
      if(length > out.size) throw Gltf_error("buffer " + std::to_string(i) + " is shorter than its byteLength");
      out.size = std::size_t(length);
    }
    // side-by-side buffers count in the input size that bounds the reader's allocations
    read_allocation_limit() = (std::max)(read_allocation_limit(), 64 * total + (std::size_t(1) << 20));
  }

  void load_uri(const std::string& uri, Gltf_buffer& out) const
  {
    if(uri.compare(0, 5, "data:") == 0)
    {
      const std::size_t comma = uri.find(',');
      if(comma == std::string::npos || comma < 7 || uri.compare(comma - 7, 7, ";base64") != 0)
        throw Gltf_error("buffer data URI is not base64");
      out.owned = decode_base64(uri.data() + comma + 1, uri.data() + uri.size());
      return;
    }
    const std::string path = m_directory + relative_path_of_uri(uri);
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    if(!in) throw Gltf_error("cannot open the buffer file '" + path + "'");
    const std::streamoff size = in.tellg();
    if(size < 0) throw Gltf_error("cannot read the buffer file '" + path + "'");
    out.owned.resize(std::size_t(size));
    in.seekg(0, std::ios::beg);
    if(size > 0 && !in.read(reinterpret_cast<char*>(out.owned.data()), size))
      throw Gltf_error("cannot read the buffer file '" + path + "'");
  }

  // ---- accessors

  static int component_size(int type)
  {
    switch(type)
    {
    case 5120: case 5121: return 1;
    case 5122: case 5123: return 2;
    case 5125: case 5126: return 4;
    default: throw Gltf_error("invalid accessor componentType " + std::to_string(type));
    }
  }

  static std::size_t number_of_components(const Json& type)
  {
    const std::string t = type.is_string() ? type.get<std::string>() : std::string();
    if(t == "SCALAR") return 1;
    if(t == "VEC2") return 2;
    if(t == "VEC3") return 3;
    if(t == "VEC4") return 4;
    throw Gltf_error("accessor type '" + t + "' is not SCALAR or VECn");
  }

  // ---- the scene

  static Matrix identity()
  {
    Matrix m{};
    m[0] = m[5] = m[10] = m[15] = 1.;
    return m;
  }

  static Matrix multiply(const Matrix& a, const Matrix& b)
  {
    Matrix m{};
    for(int c = 0; c < 4; ++c)
      for(int r = 0; r < 4; ++r)
        for(int k = 0; k < 4; ++k) m[4 * c + r] += a[4 * k + r] * b[4 * c + k];
    return m;
  }

  static std::vector<double> numbers(const Json* v, std::size_t n, const char* what)
  {
    if(!v->is_array() || v->size() != n) throw Gltf_error(std::string("node ") + what + " must have " + std::to_string(n) + " numbers");
    std::vector<double> out;
    for(const Json& x : *v)
    {
      if(!x.is_number()) throw Gltf_error(std::string("node ") + what + " holds a non-number");
      out.push_back(x.get<double>());
    }
    return out;
  }

  // The local transform of a node: its matrix, or T * R * S.
  static Matrix local_transform(const Json& node)
  {
    if(const Json* m = member(node, "matrix"))
    {
      const std::vector<double> v = numbers(m, 16, "matrix");
      Matrix out{};
      std::copy(v.begin(), v.end(), out.begin());
      return out;
    }
    Matrix out = identity();
    std::vector<double> s = {1., 1., 1.}, q = {0., 0., 0., 1.};
    if(const Json* v = member(node, "scale")) s = numbers(v, 3, "scale");
    if(const Json* v = member(node, "rotation")) q = numbers(v, 4, "rotation");
    const double norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    if(!(norm > 0.) || !std::isfinite(norm)) throw Gltf_error("node rotation is not a quaternion");
    const double x = q[0] / norm, y = q[1] / norm, z = q[2] / norm, w = q[3] / norm;
    const double R[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
                            {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
                            {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}};
    for(int c = 0; c < 3; ++c)
      for(int r = 0; r < 3; ++r) out[4 * c + r] = R[r][c] * s[c];
    if(const Json* v = member(node, "translation"))
    {
      const std::vector<double> t = numbers(v, 3, "translation");
      for(int r = 0; r < 3; ++r) out[12 + r] = t[r];
    }
    return out;
  }

  // The root nodes of the default scene: `scene`, else the first scene, else every node that is
  // no node's child.
  std::vector<std::uint64_t> root_nodes() const
  {
    const Json* scenes = member(m_json, "scenes");
    const Json* nodes = member(m_json, "nodes");
    std::vector<std::uint64_t> roots;
    if(scenes && scenes->is_array() && !scenes->empty())
    {
      const Json& scene = element("scenes", unsigned_member(m_json, "scene", 0, "scene"));
      if(const Json* list = member(scene, "nodes"))
      {
        if(!list->is_array()) throw Gltf_error("scene nodes is not an array");
        for(const Json& n : *list) roots.push_back(unsigned_value(n, "scene node"));
      }
      return roots;
    }
    if(!nodes || !nodes->is_array()) return roots;
    std::vector<char> is_child(nodes->size(), 0);
    for(const Json& n : *nodes)
      if(const Json* children = member(n, "children"))
        for(const Json& c : *children)
          if(c.is_number_unsigned() && c.get<std::uint64_t>() < nodes->size()) is_child[std::size_t(c.get<std::uint64_t>())] = 1;
    for(std::size_t i = 0; i < nodes->size(); ++i)
      if(!is_child[i]) roots.push_back(i);
    return roots;
  }

  // Calls f(node, mesh, global transform) for every node with a mesh, depth first, with an explicit
  // stack (a hostile file may nest nodes deeply); a node reached twice is an error.
  template <typename F>
  void for_each_mesh_instance(const F& f) const
  {
    const Json* nodes = member(m_json, "nodes");
    std::vector<char> visited(nodes && nodes->is_array() ? nodes->size() : 0, 0);
    std::vector<std::pair<std::uint64_t, Matrix> > stack;
    const std::vector<std::uint64_t> roots = root_nodes();
    for(auto it = roots.rbegin(); it != roots.rend(); ++it) stack.emplace_back(*it, identity());
    while(!stack.empty())
    {
      const std::uint64_t n = stack.back().first;
      const Matrix parent = stack.back().second;
      stack.pop_back();
      const Json& node = element("nodes", n);
      if(visited[std::size_t(n)]) throw Gltf_error("node " + std::to_string(n) + " is reached twice: the nodes are not a forest");
      visited[std::size_t(n)] = 1;
      const Matrix world = multiply(parent, local_transform(node));
      if(const Json* mesh = member(node, "mesh")) f(std::size_t(n), std::size_t(unsigned_value(*mesh, "node mesh")), world);
      if(const Json* children = member(node, "children"))
      {
        if(!children->is_array()) throw Gltf_error("node children is not an array");
        for(std::size_t k = children->size(); k-- > 0;)
          stack.emplace_back(unsigned_value((*children)[k], "node child"), world);
      }
    }
  }

  // ---- meshes

  // The positions and the triangles of a primitive of mode TRIANGLES, TRIANGLE_STRIP or
  // TRIANGLE_FAN with a POSITION; false for any other primitive (points and lines have no triangle).
  bool triangles_of_primitive(const Json& primitive, Primitive_instance& out) const
  {
    const std::uint64_t mode = unsigned_member(primitive, "mode", 4, "primitive mode");
    if(mode < 4 || mode > 6) return false;
    const Json* attributes = member(primitive, "attributes");
    const Json* position = attributes ? member(*attributes, "POSITION") : nullptr;
    if(!position) return false;
    out.positions = accessor(unsigned_value(*position, "POSITION"));
    if(out.positions.components != 3) throw Gltf_error("POSITION is not VEC3");
    std::vector<std::uint64_t> index; // empty: the vertices in order
    if(const Json* indices = member(primitive, "indices"))
    {
      const Accessor a = accessor(unsigned_value(*indices, "indices"));
      if(a.components != 1 || a.component_type == 5126) throw Gltf_error("indices are not integers");
      index.resize(a.count);
      for(std::size_t i = 0; i < a.count; ++i)
      {
        const double v = component(a, i, 0);
        index[i] = v < 0. ? std::uint64_t(-1) : std::uint64_t(v);
      }
    }
    const std::size_t n = index.empty() ? out.positions.count : index.size();
    auto vertex = [&](std::size_t k) { return index.empty() ? std::uint64_t(k) : index[k]; };
    const std::size_t triangles = mode == 4 ? n / 3 : (n >= 3 ? n - 2 : 0);
    out.triangles.resize(triangles);
    for(std::size_t t = 0; t < triangles; ++t)
    {
      if(mode == 4) out.triangles[t] = {{vertex(3 * t), vertex(3 * t + 1), vertex(3 * t + 2)}};
      else if(mode == 5) out.triangles[t] = {{vertex(t), vertex(t + 1 + t % 2), vertex(t + 2 - t % 2)}};
      else out.triangles[t] = {{vertex(t + 1), vertex(t + 2), vertex(0)}};
    }
    return true;
  }

  // The positions of the instance in the scene's frame, and its triangles, turned over if the
  // transform mirrors.
  static void add_primitive_instance(const Primitive_instance& p, Polygon_soup_arrays& soup)
  {
    const Matrix& w = p.world;
    const std::size_t base = soup.number_of_points();
    for(std::size_t i = 0; i < p.positions.count; ++i)
    {
      const std::array<double, 3> q =
        apply(w, component(p.positions, i, 0), component(p.positions, i, 1), component(p.positions, i, 2), 1.);
      soup.add_point(q[0], q[1], q[2]);
    }
    for(std::array<std::uint64_t, 3> c : p.triangles)
    {
      if(p.mirrored) std::swap(c[1], c[2]);
      for(std::uint64_t v : c) soup.add_vertex_index(v < p.positions.count ? base + std::size_t(v) : invalid_vertex_index);
      soup.end_polygon();
    }
  }
};

#endif // CGAL_PART_DECOMPOSITION_HAS_GLTF

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_READ_GLTF_SOUP_H
