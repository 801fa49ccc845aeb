// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_GLB_BUILDER_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_GLB_BUILDER_H

#if __has_include(<nlohmann/json.hpp>)
#include <nlohmann/json.hpp>
#endif

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

// 32-bit values (floats or integers) as little-endian bytes, glTF's byte order whatever the host's.
template <typename T>
void store_le32(const T* v, std::size_t n, unsigned char* out)
{
  static_assert(sizeof(T) == 4, "32-bit values");
  for(std::size_t i = 0; i < n; ++i)
  {
    std::uint32_t u;
    std::memcpy(&u, v + i, 4);
    for(int k = 0; k < 4; ++k) out[4 * i + std::size_t(k)] = (unsigned char)((u >> (8 * k)) & 0xff);
  }
}

// A GLB file: the header, the JSON chunk (padded with spaces) and the BIN chunk (padded with
// zeros, left out if empty), little-endian whatever the host's byte order.
inline void write_glb_container(std::ostream& out, std::string json, std::string bin)
{
  while(json.size() % 4) json += ' ';
  while(bin.size() % 4) bin += '\0';
  auto u32 = [&out](std::size_t v) {
    const unsigned char b[4] = {(unsigned char)(v & 0xff), (unsigned char)((v >> 8) & 0xff),
                                (unsigned char)((v >> 16) & 0xff), (unsigned char)((v >> 24) & 0xff)};
    out.write(reinterpret_cast<const char*>(b), 4);
  };
  out.write("glTF", 4);
  u32(2);
  u32(12 + 8 + json.size() + (bin.empty() ? 0 : 8 + bin.size()));
  u32(json.size());
  out.write("JSON", 4);
  out.write(json.data(), std::streamsize(json.size()));
  if(bin.empty()) return;
  u32(bin.size());
  out.write("BIN\0", 4);
  out.write(bin.data(), std::streamsize(bin.size()));
}

#if __has_include(<nlohmann/json.hpp>)

/*
The document and the binary buffer of a GLB under construction: the buffer views and accessors
added here all lie in buffer 0, the BIN chunk. Vertex attributes are stored with 4-byte aligned
elements, as glTF requires.
*/
class Glb_builder
{
public:
  typedef nlohmann::json Json;

  Json gltf = Json::object();

  // Appends `size` bytes at an offset equal to `remainder` modulo 4 (the alignment the bytes had
  // in their source buffer, so that the accessors into them stay aligned); returns the offset.
  std::size_t append(const unsigned char* data, std::size_t size, std::size_t remainder = 0)
  {
    while(m_bin.size() % 4 != remainder % 4) m_bin += '\0';
    const std::size_t offset = m_bin.size();
    m_bin.append(reinterpret_cast<const char*>(data), size);
    return offset;
  }

  // A buffer view of `length` bytes at `offset` of the buffer; `target` 0 for none.
  std::size_t add_view(std::size_t offset, std::size_t length, int target = 0, std::size_t stride = 0)
  {
    Json view = {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", length}};
    if(stride) view["byteStride"] = stride;
    if(target) view["target"] = target;
    return push("bufferViews", std::move(view));
  }

  // A vertex attribute of `count` elements of `element_size` bytes each, written by
  // `element(i, destination)`, in a view of its own; returns the accessor, described by `accessor`
  // (componentType, type, ...) without bufferView, byteOffset and count.
  template <typename ElementWriter>
  std::size_t add_vertex_attribute(Json accessor, std::size_t count, std::size_t element_size, const ElementWriter& element)
  {
    const std::size_t stride = (element_size + 3) / 4 * 4;
    std::vector<unsigned char> bytes(count * stride, 0);
    for(std::size_t i = 0; i < count; ++i) element(i, bytes.data() + i * stride);
    const std::size_t offset = append(bytes.data(), bytes.size());
    accessor["bufferView"] = add_view(offset, bytes.size(), 34962, stride == element_size ? 0 : stride);
    accessor["count"] = count;
    return push("accessors", std::move(accessor));
  }

  // float32 vectors of `components` components; with the bounds (required for POSITION) if asked.
  std::size_t add_floats(const std::vector<float>& v, std::size_t components, bool bounds)
  {
    static const char* const types[] = {"", "SCALAR", "VEC2", "VEC3", "VEC4"};
    Json accessor = {{"componentType", 5126}, {"type", types[components]}};
    if(bounds && !v.empty())
    {
      std::vector<float> lo(v.begin(), v.begin() + std::ptrdiff_t(components)), hi = lo;
      for(std::size_t i = 0; i < v.size(); ++i)
      {
        lo[i % components] = (std::min)(lo[i % components], v[i]);
        hi[i % components] = (std::max)(hi[i % components], v[i]);
      }
      accessor["min"] = lo;
      accessor["max"] = hi;
    }
    return add_vertex_attribute(std::move(accessor), v.size() / components, 4 * components,
                                [&](std::size_t i, unsigned char* out) { store_le32(v.data() + i * components, components, out); });
  }

  // Triangle indices, as 16-bit unsigned integers if they fit (half the bytes), else 32-bit.
  std::size_t add_indices(const std::vector<std::uint32_t>& indices)
  {
    const bool short_ = std::all_of(indices.begin(), indices.end(), [](std::uint32_t i) { return i < 65535; });
    const std::size_t size = short_ ? 2 : 4;
    std::vector<unsigned char> bytes(size * indices.size());
    for(std::size_t i = 0; i < indices.size(); ++i)
      for(std::size_t k = 0; k < size; ++k) bytes[size * i + k] = (unsigned char)((indices[i] >> (8 * k)) & 0xff);
    const std::size_t offset = append(bytes.data(), bytes.size());
    return push("accessors", Json{{"bufferView", add_view(offset, bytes.size(), 34963)}, {"componentType", short_ ? 5123 : 5125},
                                  {"type", "SCALAR"}, {"count", indices.size()}});
  }

  // Feature IDs (EXT_mesh_features): the smallest unsigned type that holds `number_of_features`
  // values, float32 beyond 16 bits (exact up to 2^24; glTF has no 32-bit integer attribute).
  std::size_t add_feature_ids(const std::vector<std::uint32_t>& ids, std::size_t number_of_features)
  {
    const int type = number_of_features <= 256 ? 5121 : (number_of_features <= 65536 ? 5123 : 5126);
    const std::size_t size = type == 5121 ? 1 : (type == 5123 ? 2 : 4);
    return add_vertex_attribute(Json{{"componentType", type}, {"type", "SCALAR"}}, ids.size(), size,
                                [&](std::size_t i, unsigned char* out) {
                                  if(type == 5126)
                                  {
                                    const float f = float(ids[i]);
                                    store_le32(&f, 1, out);
                                  }
                                  else
                                    for(std::size_t k = 0; k < size; ++k) out[k] = (unsigned char)((ids[i] >> (8 * k)) & 0xff);
                                });
  }

  // Appends `value` to the top-level array `name`; returns its index.
  std::size_t push(const char* name, Json value)
  {
    Json& array = gltf[name];
    if(!array.is_array()) array = Json::array();
    array.push_back(std::move(value));
    return array.size() - 1;
  }

  // Writes the GLB: the buffer is declared, the document serialized.
  void write(std::ostream& out)
  {
    if(!m_bin.empty()) gltf["buffers"] = Json::array({Json{{"byteLength", m_bin.size()}}});
    write_glb_container(out, gltf.dump(), m_bin);
  }

private:
  std::string m_bin;
};

#endif // __has_include(<nlohmann/json.hpp>)

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_GLB_BUILDER_H
