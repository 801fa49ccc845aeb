// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_GLTF_PART_PRIMITIVES_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_GLTF_PART_PRIMITIVES_H

#include <CGAL/Part_decomposition/internal/io/gltf_source.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

#ifdef CGAL_PART_DECOMPOSITION_HAS_GLTF

// The vertex attributes a part keeps, each with the number of components it may have.
enum class Part_attribute { POSITION, NORMAL, TANGENT, TEXCOORD, COLOR, NONE };

inline Part_attribute part_attribute(const std::string& name, std::size_t components)
{
  if(name == "POSITION" && components == 3) return Part_attribute::POSITION;
  if(name == "NORMAL" && components == 3) return Part_attribute::NORMAL;
  if(name == "TANGENT" && components == 4) return Part_attribute::TANGENT;
  if(name.compare(0, 9, "TEXCOORD_") == 0 && components == 2) return Part_attribute::TEXCOORD;
  if(name.compare(0, 6, "COLOR_") == 0 && (components == 3 || components == 4)) return Part_attribute::COLOR;
  // joints and weights would need the skin, which the scene's frame leaves behind
  return Part_attribute::NONE;
}

// The values of an attribute at `vertices` in the scene's frame, as float32: positions by the
// transform `w`, normals by the inverse transpose of its linear part, tangent directions by the
// linear part (their handedness flips with a mirror), the others unchanged.
inline std::vector<float> world_attribute(Part_attribute kind, const Gltf_soup_reader::Accessor& a,
                                          const std::vector<std::size_t>& vertices, const Gltf_soup_reader::Matrix& w)
{
  typedef Gltf_soup_reader R;
  const double det = R::determinant(w);
  // the columns of the inverse transpose, times det: the cross products of the columns
  auto column = [&](int j) { return std::array<double, 3>{{w[4 * j], w[4 * j + 1], w[4 * j + 2]}}; };
  auto cross = [](const std::array<double, 3>& u, const std::array<double, 3>& v) {
    return std::array<double, 3>{{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]}};
  };
  const std::array<std::array<double, 3>, 3> cof = {{cross(column(1), column(2)), cross(column(2), column(0)), cross(column(0), column(1))}};
  std::vector<float> out;
  out.reserve(vertices.size() * a.components);
  for(std::size_t v : vertices)
  {
    std::array<double, 4> x = {{0., 0., 0., 0.}};
    for(std::size_t c = 0; c < a.components; ++c) x[c] = R::component(a, v, c);
    std::array<double, 4> y = x;
    if(kind == Part_attribute::POSITION || kind == Part_attribute::TANGENT)
    {
      const std::array<double, 3> q = R::apply(w, x[0], x[1], x[2], kind == Part_attribute::POSITION ? 1. : 0.);
      std::copy(q.begin(), q.end(), y.begin());
    }
    if(kind == Part_attribute::NORMAL && det != 0.)
      for(int r = 0; r < 3; ++r) y[r] = (cof[0][r] * x[0] + cof[1][r] * x[1] + cof[2][r] * x[2]) * (det < 0. ? -1. : 1.);
    if(kind == Part_attribute::NORMAL || kind == Part_attribute::TANGENT)
    {
      // unit length, as glTF requires
      const double n = std::sqrt(y[0] * y[0] + y[1] * y[1] + y[2] * y[2]);
      if(n > 0.)
        for(int r = 0; r < 3; ++r) y[r] /= n;
      if(kind == Part_attribute::TANGENT && det < 0.) y[3] = -y[3];
    }
    for(std::size_t c = 0; c < a.components; ++c) out.push_back(float(y[c]));
  }
  return out;
}

// The triangles `selected` (indices into instance.triangles) of a primitive instance of `source`
// as a primitive of `out`, in the scene's frame: the vertices they use, with their positions,
// normals, tangents, texture coordinates and colours, the source's material, mode TRIANGLES.
inline Gltf_soup_reader::Json part_primitive(const Gltf_source& source, const Gltf_source::Primitive_instance& instance,
                                             const std::vector<std::size_t>& selected, Glb_builder& out)
{
  typedef Gltf_soup_reader::Json Json;
  const Json& primitive = source.json().at("meshes").at(instance.mesh).at("primitives").at(instance.primitive);
  // the vertices, numbered in the order the triangles reach them
  std::vector<std::uint32_t> local(instance.positions.count, std::uint32_t(-1));
  std::vector<std::size_t> vertices;
  std::vector<std::uint32_t> indices;
  indices.reserve(3 * selected.size());
  for(std::size_t t : selected)
  {
    std::array<std::uint64_t, 3> c = instance.triangles[t];
    if(instance.mirrored) std::swap(c[1], c[2]); // the soup's winding, front faces kept
    for(std::uint64_t v : c)
    {
      if(local[std::size_t(v)] == std::uint32_t(-1))
      {
        local[std::size_t(v)] = std::uint32_t(vertices.size());
        vertices.push_back(std::size_t(v));
      }
      indices.push_back(local[std::size_t(v)]);
    }
  }
  Json attributes = Json::object();
  for(auto it = primitive.at("attributes").begin(); it != primitive.at("attributes").end(); ++it)
  {
    if(!it->is_number_unsigned()) continue;
    const Gltf_soup_reader::Accessor a = source.reader().accessor(it->get<std::uint64_t>());
    const Part_attribute kind = part_attribute(it.key(), a.components);
    if(kind == Part_attribute::NONE || a.count < instance.positions.count) continue;
    attributes[it.key()] = out.add_floats(world_attribute(kind, a, vertices, instance.world), a.components,
                                          kind == Part_attribute::POSITION);
  }
  Json part = {{"attributes", std::move(attributes)}, {"indices", out.add_indices(indices)}, {"mode", 4}};
  const auto material = primitive.find("material");
  const auto materials = source.json().find("materials");
  if(material != primitive.end() && material->is_number_unsigned() && materials != source.json().end() &&
     materials->is_array() && material->get<std::uint64_t>() < materials->size())
    part["material"] = *material;
  return part;
}

// For each part, the primitives of its triangles: one per primitive instance of the source with
// triangles in the part, in the order of the instances. `triangle_part`: the part of each
// triangle of the source, in the reader's order.
inline std::vector<Gltf_soup_reader::Json> part_primitives(const Gltf_source& source,
                                                           const std::vector<std::size_t>& triangle_part,
                                                           std::size_t number_of_parts, Glb_builder& out)
{
  std::vector<Gltf_soup_reader::Json> parts(number_of_parts, Gltf_soup_reader::Json::array());
  std::vector<std::vector<std::size_t> > selected(number_of_parts);
  std::vector<std::size_t> touched;
  for(std::size_t k = 0; k < source.instances.size(); ++k)
  {
    const Gltf_source::Primitive_instance& instance = source.instances[k];
    for(std::size_t t = 0; t < instance.triangles.size(); ++t)
    {
      const std::size_t part = triangle_part[source.first_triangle[k] + t];
      if(selected[part].empty()) touched.push_back(part);
      selected[part].push_back(t);
    }
    for(std::size_t part : touched)
    {
      parts[part].push_back(part_primitive(source, instance, selected[part], out));
      selected[part].clear();
    }
    touched.clear();
  }
  return parts;
}

#endif // CGAL_PART_DECOMPOSITION_HAS_GLTF

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_GLTF_PART_PRIMITIVES_H
