// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_IO_WRITE_PARTS_GLTF_H
#define CGAL_PART_DECOMPOSITION_IO_WRITE_PARTS_GLTF_H

#include <CGAL/Part_decomposition/Superquadric.h>
#include <CGAL/Part_decomposition/IO/read_mesh_impl.h>
#include <CGAL/Part_decomposition/IO/write_labels_gltf.h>
#include <CGAL/Part_decomposition/internal/io/glb_builder.h>
#include <CGAL/Part_decomposition/internal/io/gltf_part_primitives.h>

#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Part_decomposition {

/// \cond SKIP_IN_MANUAL
namespace internal {

// A distinct, saturated sRGB colour per part (golden-ratio hue steps), as hitops --colored.
inline std::array<double, 3> part_srgb(std::size_t k)
{
  const double h = std::fmod(0.13 + 0.618033988749895 * double(k), 1.) * 6.;
  const double s = (k % 3 == 2) ? 0.55 : 0.8, v = (k % 2) ? 0.8 : 0.95;
  const int i = int(h);
  const double f = h - i, p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
  switch(i % 6)
  {
  case 0: return {{v, t, p}};
  case 1: return {{q, v, p}};
  case 2: return {{p, v, t}};
  case 3: return {{p, q, v}};
  case 4: return {{t, p, v}};
  default: return {{v, p, q}};
  }
}

// glTF colours are linear: the sRGB transfer function undone.
inline double srgb_to_linear(double c)
{
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

// The triangles of one glTF mesh: float positions and uint32 indices.
struct Gltf_triangles
{
  std::string name;
  std::vector<float> positions; // 3 per vertex
  std::vector<std::uint32_t> indices;
  std::size_t material = 0;
};

// The tessellation of a superquadric (see Superquadric::to_triangle_mesh()).
template <typename GeomTraits>
Gltf_triangles superquadric_triangles(const Superquadric<GeomTraits>& q, int resolution)
{
  CGAL::Surface_mesh<typename GeomTraits::Point_3> sq;
  q.to_triangle_mesh(sq, resolution);
  Gltf_triangles t;
  for(auto v : vertices(sq))
    for(double x : {CGAL::to_double(sq.point(v).x()), CGAL::to_double(sq.point(v).y()), CGAL::to_double(sq.point(v).z())})
      t.positions.push_back(float(x));
  for(auto f : faces(sq))
    for(auto v : vertices_around_face(halfedge(f, sq), sq)) t.indices.push_back(std::uint32_t(v));
  return t;
}

// Appends `v` to `bin` as little-endian 32-bit words (glTF's byte order, whatever the host's),
// 4-byte aligned; returns the offset.
template <typename T>
std::size_t append_aligned(std::string& bin, const std::vector<T>& v)
{
  while(bin.size() % 4) bin += '\0';
  const std::size_t offset = bin.size();
  std::vector<unsigned char> bytes(4 * v.size());
  store_le32(v.data(), v.size(), bytes.data());
  bin.append(bytes.begin(), bytes.end());
  return offset;
}

// The JSON of the accessors, views and meshes of `meshes`, and their binary buffer.
inline void gltf_meshes_json(const std::vector<Gltf_triangles>& meshes, std::ostringstream& accessors,
                             std::ostringstream& views, std::ostringstream& out_meshes, std::string& bin)
{
  std::size_t a = 0;
  for(std::size_t m = 0; m < meshes.size(); ++m)
  {
    const Gltf_triangles& t = meshes[m];
    std::array<float, 3> lo, hi;
    lo.fill((std::numeric_limits<float>::max)());
    hi.fill(std::numeric_limits<float>::lowest());
    for(std::size_t i = 0; i < t.positions.size(); ++i)
    {
      lo[i % 3] = (std::min)(lo[i % 3], t.positions[i]);
      hi[i % 3] = (std::max)(hi[i % 3], t.positions[i]);
    }
    const std::size_t p_offset = append_aligned(bin, t.positions), i_offset = append_aligned(bin, t.indices);
    views << (m ? "," : "") << "{\"buffer\":0,\"byteOffset\":" << p_offset << ",\"byteLength\":"
          << 4 * t.positions.size() << ",\"target\":34962},{\"buffer\":0,\"byteOffset\":" << i_offset
          << ",\"byteLength\":" << 4 * t.indices.size() << ",\"target\":34963}";
    accessors << (m ? "," : "") << "{\"bufferView\":" << a << ",\"componentType\":5126,\"type\":\"VEC3\",\"count\":"
              << t.positions.size() / 3 << ",\"min\":[" << lo[0] << ',' << lo[1] << ',' << lo[2] << "],\"max\":["
              << hi[0] << ',' << hi[1] << ',' << hi[2] << "]},{\"bufferView\":" << a + 1
              << ",\"componentType\":5125,\"type\":\"SCALAR\",\"count\":" << t.indices.size() << '}';
    out_meshes << (m ? "," : "") << "{\"name\":\"" << t.name << "\",\"primitives\":[{\"attributes\":{\"POSITION\":" << a
               << "},\"indices\":" << a + 1 << ",\"material\":" << t.material << ",\"mode\":4}]}";
    a += 2;
  }
}

// A GLB of the meshes: material k has colour `colors[k]` (opacity `alpha[k]`), node i holds mesh
// i, and the scene has one group node per entry of `groups` (name, first mesh, end mesh).
inline void write_glb(std::ostream& out, const std::vector<Gltf_triangles>& meshes,
                      const std::vector<std::array<double, 4> >& colors, const std::vector<std::string>& material_names,
                      const std::vector<std::array<std::size_t, 2> >& groups, const std::vector<std::string>& group_names)
{
  std::ostringstream accessors, views, gltf_meshes, nodes, materials, scene;
  for(std::ostringstream* s : {&accessors, &views, &gltf_meshes, &nodes, &materials})
    s->precision(9);
  std::string bin;
  gltf_meshes_json(meshes, accessors, views, gltf_meshes, bin);
  for(std::size_t k = 0; k < colors.size(); ++k)
    materials << (k ? "," : "") << "{\"name\":\"" << material_names[k] << "\",\"pbrMetallicRoughness\":{\"baseColorFactor\":["
              << colors[k][0] << ',' << colors[k][1] << ',' << colors[k][2] << ',' << colors[k][3]
              << "],\"metallicFactor\":0,\"roughnessFactor\":0.8},\"doubleSided\":true"
              << (colors[k][3] < 1. ? ",\"alphaMode\":\"BLEND\"" : "") << '}';
  for(std::size_t m = 0; m < meshes.size(); ++m)
    nodes << (m ? "," : "") << "{\"name\":\"" << meshes[m].name << "\",\"mesh\":" << m << '}';
  for(std::size_t g = 0; g < groups.size(); ++g)
  {
    nodes << ",{\"name\":\"" << group_names[g] << "\",\"children\":[";
    for(std::size_t m = groups[g][0]; m < groups[g][1]; ++m) nodes << (m > groups[g][0] ? "," : "") << m;
    nodes << "]}";
    scene << (g ? "," : "") << meshes.size() + g;
  }
  std::string json = "{\"asset\":{\"version\":\"2.0\",\"generator\":\"CGAL Part_decomposition\"},\"scene\":0,"
                     "\"scenes\":[{\"nodes\":[" + scene.str() + "]}],\"nodes\":[" + nodes.str() + "],\"meshes\":[" +
                     gltf_meshes.str() + "],\"materials\":[" + materials.str() + "],\"accessors\":[" + accessors.str() +
                     "],\"bufferViews\":[" + views.str() + "],\"buffers\":[{\"byteLength\":" + std::to_string(bin.size()) + "}]}";
  write_glb_container(out, json, bin);
}

#ifdef CGAL_PART_DECOMPOSITION_HAS_GLTF
// The flat material of the superquadric of part k: the part's colour, half transparent.
inline Glb_builder::Json superquadric_material(std::size_t k)
{
  const std::array<double, 3> c = part_srgb(k);
  return {{"name", "primitive_" + std::to_string(k)},
          {"pbrMetallicRoughness", {{"baseColorFactor", {srgb_to_linear(c[0]), srgb_to_linear(c[1]), srgb_to_linear(c[2]), 0.5}},
                                    {"metallicFactor", 0}, {"roughnessFactor", 0.8}}},
          {"doubleSided", true}, {"alphaMode", "BLEND"}};
}

// Adds a node `name` whose children are `children` to the scene's roots, if it has any.
inline void add_group_node(const std::string& name, const Glb_builder::Json& children, Glb_builder& out)
{
  if(children.empty()) return;
  const std::size_t node = out.push("nodes", {{"name", name}, {"children", children}});
  out.gltf["scenes"][0]["nodes"].push_back(node);
}

// The document of write_gltf_parts_glb(): the parts of the source with its materials, nodes
// part_k under a node "parts", and the superquadrics, nodes primitive_k under a node "primitives".
inline void gltf_parts_document(const Gltf_source& source, const std::vector<std::size_t>& triangle_part,
                                std::size_t number_of_parts, const std::vector<Gltf_triangles>& superquadrics,
                                Glb_builder& out)
{
  typedef Glb_builder::Json Json;
  out.gltf["asset"] = output_asset(&source);
  out.gltf["scene"] = 0;
  out.gltf["scenes"] = Json::array({Json{{"nodes", Json::array()}}});
  copy_materials(source, true, out);
  const std::vector<Json> parts = part_primitives(source, triangle_part, number_of_parts, out);
  Json children = Json::array();
  for(std::size_t k = 0; k < parts.size(); ++k)
  {
    if(parts[k].empty()) continue; // a glTF mesh has at least one primitive
    const std::string name = "part_" + std::to_string(k);
    const std::size_t mesh = out.push("meshes", {{"name", name}, {"primitives", parts[k]}});
    children.push_back(out.push("nodes", {{"name", name}, {"mesh", mesh}}));
  }
  add_group_node("parts", children, out);
  children = Json::array();
  for(std::size_t k = 0; k < superquadrics.size(); ++k)
  {
    const std::string name = "primitive_" + std::to_string(k);
    Json primitive = {{"attributes", {{"POSITION", out.add_floats(superquadrics[k].positions, 3, true)}}},
                      {"indices", out.add_indices(superquadrics[k].indices)},
                      {"material", out.push("materials", superquadric_material(k))}, {"mode", 4}};
    const std::size_t mesh = out.push("meshes", {{"name", name}, {"primitives", Json::array({primitive})}});
    children.push_back(out.push("nodes", {{"name", name}, {"mesh", mesh}}));
  }
  add_group_node("primitives", children, out);
  declare_extensions(source, out);
}
#endif

} // namespace internal
/// \endcond

namespace IO {

/*!
\ingroup PkgPartDecompositionIO
writes the parts of `tm` as a binary glTF 2.0 file (GLB) to `out`, so that the parts can be picked
one by one in Blender or any glTF viewer: part `k` is the mesh and node `part_k`, with a material
`part_k` of its own colour (the colours of `hitops --colored`), all under a node `parts`. If
`primitives` is not empty, the superquadric of each part is added as a triangle mesh (`resolution`
segments per parameter, see `Superquadric::to_triangle_mesh()`) in node `primitive_k`, with the
colour of its part, half transparent, all under a node `primitives`. Positions are written as
32-bit floats, in the coordinates of `tm`. For a mesh read from a glTF file,
`write_gltf_parts_glb()` keeps the materials, textures and vertex attributes of the file instead.

\tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
\tparam GeomTraits the geometric traits of the superquadrics

\param out the stream, opened in binary mode
\param tm the mesh
\param face_part the part of each face, in the iteration order of `faces(tm)`, in `[0, number_of_parts)`
\param number_of_parts the number of parts
\param primitives the superquadric of each part (`primitives[k]` explains part `k`), or none
\param resolution the tessellation of the superquadrics

\pre `face_part.size() == num_faces(tm)`, and `primitives` is empty or of size `number_of_parts`.
*/
template <typename TriangleMesh, typename GeomTraits>
void write_parts_glb(std::ostream& out, const TriangleMesh& tm, const std::vector<std::size_t>& face_part,
                     std::size_t number_of_parts, const std::vector<Superquadric<GeomTraits> >& primitives,
                     int resolution = 24)
{
  CGAL_precondition(face_part.size() == std::size_t(num_faces(tm)));
  CGAL_precondition(primitives.empty() || primitives.size() == number_of_parts);
  const auto vpm = get(CGAL::vertex_point, tm);
  const auto vim = CGAL::get_initialized_vertex_index_map(tm);
  std::vector<internal::Gltf_triangles> meshes(number_of_parts);
  std::vector<std::array<double, 4> > colors;
  std::vector<std::string> names;
  for(std::size_t k = 0; k < number_of_parts; ++k)
  {
    meshes[k].name = "part_" + std::to_string(k);
    meshes[k].material = k;
    const std::array<double, 3> c = internal::part_srgb(k);
    colors.push_back({{internal::srgb_to_linear(c[0]), internal::srgb_to_linear(c[1]), internal::srgb_to_linear(c[2]), 1.}});
    names.push_back(meshes[k].name);
  }
  // the vertices of each part, numbered in the order the part's triangles reach them
  std::vector<std::uint32_t> local(num_vertices(tm), std::uint32_t(-1));
  std::vector<std::size_t> owner(num_vertices(tm), std::size_t(-1));
  std::size_t i = 0;
  for(auto f : faces(tm))
  {
    const std::size_t k = face_part[i++];
    CGAL_precondition(k < number_of_parts);
    internal::Gltf_triangles& m = meshes[k];
    for(auto v : vertices_around_face(halfedge(f, tm), tm))
    {
      const std::size_t vi = std::size_t(get(vim, v));
      if(owner[vi] != k)
      {
        owner[vi] = k;
        local[vi] = std::uint32_t(m.positions.size() / 3);
        const auto& p = get(vpm, v);
        for(double x : {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}) m.positions.push_back(float(x));
      }
      m.indices.push_back(local[vi]);
    }
  }
  std::vector<std::array<std::size_t, 2> > groups = {{{0, number_of_parts}}};
  std::vector<std::string> group_names = {"parts"};
  for(std::size_t k = 0; k < primitives.size(); ++k)
  {
    internal::Gltf_triangles t = internal::superquadric_triangles(primitives[k], resolution);
    t.name = "primitive_" + std::to_string(k);
    t.material = colors.size();
    std::array<double, 4> c = colors[k];
    c[3] = 0.5;
    colors.push_back(c);
    names.push_back(t.name);
    meshes.push_back(std::move(t));
  }
  if(!primitives.empty())
  {
    groups.push_back({{number_of_parts, meshes.size()}});
    group_names.push_back("primitives");
  }
  internal::write_glb(out, meshes, colors, names, groups, group_names);
}

/*!
\ingroup PkgPartDecompositionIO
writes the parts of the glTF 2.0 file `filename` (`.gltf` or `.glb`) as a binary glTF file (GLB) to
`out`, keeping the look of the source: part `k` is the mesh and node `part_k` (all under a node
`parts`), with one primitive per primitive of the source that has triangles in the part (a
primitive of a mesh instanced by several nodes counts once per node), with the source's material.
The materials, textures, samplers and images of the source are copied with their extensions (e.g.
`KHR_texture_transform`, `KHR_materials_*`); images stored in the source's buffers or in files next
to it are embedded in the output. Each part primitive keeps the vertices its triangles use with
their `POSITION`, `NORMAL`, `TANGENT`, every `TEXCOORD_n` and `COLOR_n` (as 32-bit floats), in the
frame of the scene: a part may span several nodes, so the node transforms are applied, as
`read_triangle_mesh()` does (normals by the inverse transpose, triangles turned over by a
transform that mirrors). Skins, morph targets, points and lines are left out. If `primitives` is
not empty, the superquadrics are added as in `write_parts_glb()`, nodes `primitive_k` under a node
`primitives`.

The triangles of the file are those `read_triangle_mesh()` reads, in the same order: the labels
`labels_in_file_order()` gives for a mesh read from `filename` are the parts to pass.

\tparam GeomTraits the geometric traits of the superquadrics

\param out the stream, opened in binary mode
\param filename the glTF file
\param face_part the part of each face of the file, in the file's order, in `[0, number_of_parts)`
\param number_of_parts the number of parts
\param primitives the superquadric of each part (`primitives[k]` explains part `k`), or none
\param resolution the tessellation of the superquadrics

\pre `primitives` is empty or of size `number_of_parts`.

\throws Invalid_input if the file cannot be read as glTF (`UNREADABLE_FILE`, also when the package
is built without nlohmann/json) or a triangle refers to a vertex that does not exist (`INVALID_FACE`)
\throws std::invalid_argument if `face_part` does not hold one part in `[0, number_of_parts)` per
face of the file
*/
template <typename GeomTraits>
void write_gltf_parts_glb(std::ostream& out, const std::string& filename, const std::vector<std::size_t>& face_part,
                          std::size_t number_of_parts, const std::vector<Superquadric<GeomTraits> >& primitives,
                          int resolution = 24)
{
  CGAL_precondition(primitives.empty() || primitives.size() == number_of_parts);
#ifdef CGAL_PART_DECOMPOSITION_HAS_GLTF
  const std::unique_ptr<internal::Gltf_source> source = internal::read_gltf_source(filename);
  internal::check_file_labels(face_part, source->number_of_triangles, number_of_parts, "write_gltf_parts_glb()");
  std::vector<internal::Gltf_triangles> superquadrics;
  for(const Superquadric<GeomTraits>& q : primitives) superquadrics.push_back(internal::superquadric_triangles(q, resolution));
  internal::Glb_builder builder;
  internal::with_gltf_errors(filename, [&] { internal::gltf_parts_document(*source, face_part, number_of_parts, superquadrics, builder); });
  builder.write(out);
#else
  CGAL_USE(out);
  CGAL_USE(face_part);
  CGAL_USE(number_of_parts);
  CGAL_USE(resolution);
  throw Invalid_input(Input_error::UNREADABLE_FILE,
                      "cannot read '" + filename + "': glTF needs nlohmann/json.hpp (Debian: nlohmann-json3-dev)");
#endif
}

} // namespace IO
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_IO_WRITE_PARTS_GLTF_H
