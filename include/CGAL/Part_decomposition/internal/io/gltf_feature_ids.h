// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_GLTF_FEATURE_IDS_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_GLTF_FEATURE_IDS_H

#include <CGAL/Part_decomposition/internal/io/gltf_source.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

// The vertices of triangles with one label each, so that the three corners of every triangle
// carry its label: a vertex whose triangles have several labels is duplicated once per extra label.
struct Labelled_vertices
{
  std::vector<std::uint32_t> label;               // of the vertices, then of the duplicates (0 if unused)
  std::vector<std::size_t> duplicated;            // the vertex each duplicate copies
  std::vector<std::array<std::size_t, 3> > corners; // of each triangle, duplicates included
};

// `labels[t]` is the label of triangle t; every corner is below `number_of_vertices`.
inline Labelled_vertices label_vertices(std::size_t number_of_vertices,
                                        const std::vector<std::array<std::uint64_t, 3> >& triangles,
                                        const std::size_t* labels)
{
  const std::uint32_t none = std::uint32_t(-1);
  Labelled_vertices out;
  out.label.assign(number_of_vertices, none);
  out.corners.resize(triangles.size());
  std::map<std::pair<std::size_t, std::uint32_t>, std::size_t> copies;
  for(std::size_t t = 0; t < triangles.size(); ++t)
  {
    const std::uint32_t l = std::uint32_t(labels[t]);
    for(int c = 0; c < 3; ++c)
    {
      const std::size_t v = std::size_t(triangles[t][c]);
      if(out.label[v] == none) out.label[v] = l;
      if(out.label[v] == l)
      {
        out.corners[t][c] = v;
        continue;
      }
      const auto it = copies.emplace(std::make_pair(v, l), out.label.size());
      if(it.second)
      {
        out.label.push_back(l);
        out.duplicated.push_back(v);
      }
      out.corners[t][c] = it.first->second;
    }
  }
  for(std::uint32_t& l : out.label)
    if(l == none) l = 0;
  return out;
}

// The corners of the triangles of `v`, three per triangle, as glTF indices.
inline std::vector<std::uint32_t> corner_indices(const Labelled_vertices& v)
{
  std::vector<std::uint32_t> indices;
  indices.reserve(3 * v.corners.size());
  for(const std::array<std::size_t, 3>& c : v.corners)
    for(std::size_t k : c) indices.push_back(std::uint32_t(k));
  return indices;
}

#ifdef CGAL_PART_DECOMPOSITION_HAS_GLTF

// Accessor `i` of the source extended to the vertices and duplicates of `v`, in a buffer view of
// the output: the same elements, bytes and bounds.
inline std::size_t extended_accessor(const Gltf_source& source, std::uint64_t i, std::size_t number_of_vertices,
                                     const Labelled_vertices& v, Glb_builder& out)
{
  const Gltf_soup_reader::Accessor a = source.reader().accessor(i);
  if(a.count < number_of_vertices) throw Gltf_error("a vertex attribute has fewer elements than POSITION");
  Glb_builder::Json accessor = source.json().at("accessors").at(std::size_t(i));
  for(const char* key : {"bufferView", "byteOffset", "count"}) accessor.erase(key);
  return out.add_vertex_attribute(std::move(accessor), v.label.size(), a.element_size,
                                  [&](std::size_t j, unsigned char* element) {
                                    const std::size_t from = j < number_of_vertices ? j : v.duplicated[j - number_of_vertices];
                                    if(a.data) std::memcpy(element, a.data + from * a.stride, a.element_size);
                                  });
}

// Extends every vertex attribute and morph target of `primitive` to the duplicates of `v`, and
// makes its triangles TRIANGLES on them (a strip or a fan cannot give a vertex two labels).
inline void add_duplicated_vertices(const Gltf_source& source, std::size_t number_of_vertices, const Labelled_vertices& v,
                                    Glb_builder::Json& primitive, Glb_builder& out)
{
  auto extend = [&](Glb_builder::Json& attributes) {
    for(auto it = attributes.begin(); it != attributes.end(); ++it)
      if(it->is_number_unsigned()) *it = extended_accessor(source, it->get<std::uint64_t>(), number_of_vertices, v, out);
  };
  extend(primitive["attributes"]);
  if(primitive.contains("targets") && primitive["targets"].is_array())
    for(Glb_builder::Json& target : primitive["targets"]) extend(target);
  primitive["indices"] = out.add_indices(corner_indices(v));
  primitive["mode"] = 4;
}

// Gives the triangles of `primitive` (those of `instance`) their labels as an EXT_mesh_features
// feature ID attribute _FEATURE_ID_n, n the first one free.
inline void add_feature_ids(const Gltf_source& source, const Gltf_source::Primitive_instance& instance,
                            const std::size_t* labels, std::size_t number_of_labels, Glb_builder::Json& primitive,
                            Glb_builder& out)
{
  const Labelled_vertices v = label_vertices(instance.positions.count, instance.triangles, labels);
  if(!v.duplicated.empty()) add_duplicated_vertices(source, instance.positions.count, v, primitive, out);
  std::size_t n = 0;
  while(primitive["attributes"].contains("_FEATURE_ID_" + std::to_string(n))) ++n;
  primitive["attributes"]["_FEATURE_ID_" + std::to_string(n)] = out.add_feature_ids(v.label, number_of_labels);
  Glb_builder::Json& ids = primitive["extensions"]["EXT_mesh_features"]["featureIds"];
  if(!ids.is_array()) ids = Glb_builder::Json::array();
  ids.push_back({{"featureCount", number_of_labels}, {"attribute", n}});
}

// Copies every buffer view of the source into the output's buffer, with the same indices.
inline void copy_buffer_views(const Gltf_source& source, Glb_builder& out)
{
  const auto views = source.json().find("bufferViews");
  out.gltf.erase("bufferViews");
  out.gltf.erase("buffers");
  if(views == source.json().end() || !views->is_array()) return;
  for(std::size_t i = 0; i < views->size(); ++i)
  {
    const std::pair<const unsigned char*, std::size_t> bytes = source.reader().buffer_view(i);
    Glb_builder::Json view = (*views)[i];
    const std::size_t offset = view.value("byteOffset", std::size_t(0));
    view["buffer"] = 0;
    view["byteOffset"] = out.append(bytes.first, bytes.second, offset % 4);
    out.push("bufferViews", std::move(view));
  }
}

// The output mesh of each node of the default scene with a mesh: the source's, or a copy of it if
// another node instances it with other labels. Calls f(mesh, first instance, end instance) once
// per output mesh to label, the instances being those of one node that gets that mesh.
template <typename F>
void assign_labelled_meshes(const Gltf_source& source, const std::vector<std::size_t>& labels, Glb_builder& out, const F& f)
{
  const std::vector<Gltf_source::Primitive_instance>& instances = source.instances;
  // per source mesh: the labelled copies made so far, as (output mesh, first instance, end instance)
  std::map<std::size_t, std::vector<std::array<std::size_t, 3> > > copies;
  auto triangles_of = [&](std::size_t first, std::size_t end) {
    const std::size_t begin = source.first_triangle[first];
    const std::size_t last = source.first_triangle[end - 1] + instances[end - 1].triangles.size();
    return std::make_pair(labels.begin() + std::ptrdiff_t(begin), labels.begin() + std::ptrdiff_t(last));
  };
  for(std::size_t first = 0, end = 0; first < instances.size(); first = end)
  {
    while(end < instances.size() && instances[end].node == instances[first].node) ++end;
    const std::size_t mesh = instances[first].mesh;
    const auto mine = triangles_of(first, end);
    std::vector<std::array<std::size_t, 3> >& made = copies[mesh];
    const auto same = std::find_if(made.begin(), made.end(), [&](const std::array<std::size_t, 3>& c) {
      const auto theirs = triangles_of(c[1], c[2]);
      return std::equal(mine.first, mine.second, theirs.first, theirs.second);
    });
    std::size_t output_mesh = mesh;
    if(same != made.end()) output_mesh = (*same)[0];
    else if(!made.empty()) output_mesh = out.push("meshes", source.json().at("meshes").at(mesh));
    out.gltf["nodes"][instances[first].node]["mesh"] = output_mesh;
    if(same != made.end()) continue;
    made.push_back({{output_mesh, first, end}});
    f(output_mesh, first, end);
  }
}

// The document of write_labels_glb() for a glTF source: the source unchanged (its buffers made
// the output's one buffer, images in files embedded), with the label of every triangle (in the
// reader's order) as a feature ID.
inline void labelled_scene_document(const Gltf_source& source, const std::vector<std::size_t>& labels,
                                    std::size_t number_of_labels, Glb_builder& out)
{
  out.gltf = source.json();
  copy_buffer_views(source, out);
  if(out.gltf.contains("images") && out.gltf["images"].is_array())
    for(Glb_builder::Json& image : out.gltf["images"]) image = copied_image(source, image, false, out);
  assign_labelled_meshes(source, labels, out, [&](std::size_t mesh, std::size_t first, std::size_t end) {
    for(std::size_t k = first; k < end; ++k)
    {
      const Gltf_source::Primitive_instance& instance = source.instances[k];
      add_feature_ids(source, instance, labels.data() + source.first_triangle[k], number_of_labels,
                      out.gltf["meshes"][mesh]["primitives"][instance.primitive], out);
    }
  });
  Glb_builder::Json& used = out.gltf["extensionsUsed"];
  if(!used.is_array()) used = Glb_builder::Json::array();
  if(std::find(used.begin(), used.end(), "EXT_mesh_features") == used.end()) used.push_back("EXT_mesh_features");
}

#endif // CGAL_PART_DECOMPOSITION_HAS_GLTF

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_GLTF_FEATURE_IDS_H
