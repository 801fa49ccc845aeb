// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_GLTF_SOURCE_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_GLTF_SOURCE_H

#include <CGAL/Part_decomposition/internal/io/glb_builder.h>
#include <CGAL/Part_decomposition/internal/io/read_gltf_soup.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

#ifdef CGAL_PART_DECOMPOSITION_HAS_GLTF

typedef Gltf_soup_reader::Json Gltf_json;

/*
A glTF file kept in memory for the writers that copy it, with its triangle primitive instances in
the reader's order: triangle i of the mesh file (what a label in the file's order refers to) is
triangle i - first_triangle[k] of instances[k], for the k with first_triangle[k] <= i <
first_triangle[k + 1].
*/
class Gltf_source
{
public:
  typedef Gltf_soup_reader::Json Json;
  typedef Gltf_soup_reader::Primitive_instance Primitive_instance;

  // `bytes`: the file; `directory`: its folder, with a final '/', or empty. Throws Gltf_error.
  Gltf_source(std::string bytes, std::string directory)
    : m_bytes(std::move(bytes)), m_reader(m_bytes.data(), m_bytes.data() + m_bytes.size(), std::move(directory))
  {
    m_reader.load();
    m_reader.for_each_primitive_instance([&](const Primitive_instance& p) {
      first_triangle.push_back(number_of_triangles);
      number_of_triangles += p.triangles.size();
      instances.push_back(p);
    });
  }

  Gltf_source(const Gltf_source&) = delete;
  Gltf_source& operator=(const Gltf_source&) = delete;

  const Gltf_soup_reader& reader() const { return m_reader; }
  const Json& json() const { return m_reader.json(); }

  std::vector<Primitive_instance> instances;
  std::vector<std::size_t> first_triangle;
  std::size_t number_of_triangles = 0;

private:
  std::string m_bytes; // the reader's buffers point into it
  Gltf_soup_reader m_reader;
};

// The MIME type of an image from its first bytes, or empty if not a format glTF knows.
inline std::string image_mime_type(const std::string& bytes)
{
  if(bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0) return "image/png";
  if(bytes.compare(0, 3, "\xff\xd8\xff") == 0) return "image/jpeg";
  if(bytes.size() >= 12 && bytes.compare(0, 4, "RIFF") == 0 && bytes.compare(8, 4, "WEBP") == 0) return "image/webp";
  if(bytes.compare(0, 8, "\xabKTX 20\xbb") == 0) return "image/ktx2";
  return std::string();
}

// The image `image` of the source in the output: its bytes embedded in the output's buffer if they
// are in a buffer view (copied when `copy_views`, else the views keep their indices) or in a file
// next to the source of a known format; a data: URI or a file that cannot be read stays a URI.
inline Gltf_json copied_image(const Gltf_source& source, const Gltf_json& image, bool copy_views, Glb_builder& out)
{
  Gltf_json copy = image;
  std::string bytes;
  const auto view = image.find("bufferView");
  const auto uri = image.find("uri");
  if(view != image.end() && view->is_number_unsigned())
  {
    if(!copy_views) return copy;
    const std::pair<const unsigned char*, std::size_t> b = source.reader().buffer_view(view->get<std::uint64_t>());
    bytes.assign(reinterpret_cast<const char*>(b.first), b.second);
  }
  else if(uri != image.end() && uri->is_string() && uri->get<std::string>().compare(0, 5, "data:") != 0)
  {
    try
    {
      std::ifstream in(source.reader().directory() + relative_path_of_uri(uri->get<std::string>()), std::ios::binary);
      bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    catch(const Gltf_error&)
    {
      return copy; // not a file next to the source
    }
    if(image_mime_type(bytes).empty()) return copy;
    copy.erase("uri");
  }
  else
    return copy;
  const std::string mime = image_mime_type(bytes); // an unknown format keeps the declared type
  if(!mime.empty()) copy["mimeType"] = mime;
  const std::size_t offset = out.append(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size());
  copy["bufferView"] = out.add_view(offset, bytes.size());
  return copy;
}

// Copies the top-level array `name` of the source into the output unchanged (same indices).
inline void copy_array(const Gltf_source& source, const char* name, Glb_builder& out)
{
  const auto it = source.json().find(name);
  if(it != source.json().end() && it->is_array() && !it->empty()) out.gltf[name] = *it;
}

// The materials, textures, samplers and images of the source in the output, with the same indices.
inline void copy_materials(const Gltf_source& source, bool copy_image_views, Glb_builder& out)
{
  for(const char* name : {"materials", "textures", "samplers"}) copy_array(source, name, out);
  const auto images = source.json().find("images");
  if(images == source.json().end() || !images->is_array()) return;
  Gltf_json copies = Gltf_json::array();
  for(const Gltf_json& image : *images) copies.push_back(copied_image(source, image, copy_image_views, out));
  if(!copies.empty()) out.gltf["images"] = std::move(copies);
}

// The names of the extensions used in `value` (keys of its "extensions" objects, "extras" left out).
inline void collect_extensions(const Gltf_json& value, std::set<std::string>& names)
{
  if(value.is_array())
    for(const Gltf_json& v : value) collect_extensions(v, names);
  if(!value.is_object()) return;
  for(auto it = value.begin(); it != value.end(); ++it)
  {
    if(it.key() == "extras") continue;
    if(it.key() == "extensions" && it->is_object())
      for(auto e = it->begin(); e != it->end(); ++e) names.insert(e.key());
    collect_extensions(*it, names);
  }
}

// Declares the extensions the output uses: extensionsUsed, and extensionsRequired where the
// source requires them; the source's top-level extension objects (e.g. the variants of
// KHR_materials_variants) come along.
inline void declare_extensions(const Gltf_source& source, Glb_builder& out)
{
  const Gltf_json& in = source.json();
  std::set<std::string> used;
  out.gltf.erase("extensionsUsed");
  out.gltf.erase("extensionsRequired");
  out.gltf.erase("extensions");
  collect_extensions(out.gltf, used);
  const auto root = in.find("extensions");
  if(root != in.end() && root->is_object())
    for(auto e = root->begin(); e != root->end(); ++e)
      if(used.count(e.key())) out.gltf["extensions"][e.key()] = e.value();
  if(used.empty()) return;
  out.gltf["extensionsUsed"] = used;
  const auto required = in.find("extensionsRequired");
  Gltf_json kept = Gltf_json::array();
  if(required != in.end() && required->is_array())
    for(const Gltf_json& name : *required)
      if(name.is_string() && used.count(name.get<std::string>())) kept.push_back(name);
  if(!kept.empty()) out.gltf["extensionsRequired"] = std::move(kept);
}

// The asset of the output: glTF 2.0 by this package, with the copyright of the source.
inline Gltf_json output_asset(const Gltf_source* source)
{
  Gltf_json asset = {{"version", "2.0"}, {"generator", "CGAL Part_decomposition"}};
  if(!source) return asset;
  const auto in = source->json().find("asset");
  if(in != source->json().end() && in->is_object() && in->contains("copyright")) asset["copyright"] = (*in)["copyright"];
  return asset;
}

#endif // CGAL_PART_DECOMPOSITION_HAS_GLTF

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_GLTF_SOURCE_H
