// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_IO_WRITE_LABELS_GLTF_H
#define CGAL_PART_DECOMPOSITION_IO_WRITE_LABELS_GLTF_H

#include <CGAL/Part_decomposition/IO/read_mesh_impl.h>
#include <CGAL/Part_decomposition/internal/io/glb_builder.h>
#include <CGAL/Part_decomposition/internal/io/gltf_feature_ids.h>
#include <CGAL/Part_decomposition/internal/io/gltf_source.h>

#include <CGAL/use.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace CGAL {
namespace Part_decomposition {

/// \cond SKIP_IN_MANUAL
namespace internal {

#ifdef CGAL_PART_DECOMPOSITION_HAS_GLTF
// The glTF file in memory with its triangle primitives, for the writers that copy it; a broken
// file throws UNREADABLE_FILE with the reason, as when it is read as a mesh.
inline std::unique_ptr<Gltf_source> read_gltf_source(const std::string& filename)
{
  File_contents contents;
  read_file_contents(filename, contents);
  const std::size_t slash = filename.find_last_of('/');
  std::unique_ptr<Gltf_source> source;
  with_gltf_errors(filename, [&] {
    source = std::make_unique<Gltf_source>(std::string(contents.begin(), contents.end()),
                                           slash == std::string::npos ? std::string() : filename.substr(0, slash + 1));
  });
  for(const Gltf_source::Primitive_instance& p : source->instances)
    for(const std::array<std::uint64_t, 3>& t : p.triangles)
      for(std::uint64_t v : t)
        if(v >= p.positions.count)
          throw Invalid_input(Input_error::INVALID_FACE, "'" + filename + "' has a face with an out-of-range vertex index");
  return source;
}

// The document of write_labels_glb() for a file of another format: its polygons, triangulated as
// read_triangle_mesh() does (equal points merged, faces without three distinct points left out),
// as one primitive whose feature ID is the label of the polygon of each triangle.
inline void labelled_soup_document(const std::string& filename, const std::vector<std::size_t>& labels,
                                   std::size_t number_of_labels, Glb_builder& out)
{
  typedef Glb_builder::Json Json;
  File_soup soup;
  parse_polygon_soup(filename, soup.file);
  check_polygon_soup("'" + filename + "'", soup.file);
  check_file_labels(labels, soup.file.number_of_polygons(), number_of_labels, "write_labels_glb()");
  merge_equal_points(soup);
  triangulate_polygons(soup);
  std::vector<std::array<std::uint64_t, 3> > triangles;
  std::vector<std::size_t> triangle_labels;
  for(std::size_t t = 0; t < soup.triangles.size(); ++t)
  {
    triangles.push_back({{soup.triangles[t][0], soup.triangles[t][1], soup.triangles[t][2]}});
    triangle_labels.push_back(labels[soup.triangle_to_input[t]]);
  }
  const Labelled_vertices v = label_vertices(soup.points.size(), triangles, triangle_labels.data());
  std::vector<float> positions;
  for(std::size_t j = 0; j < v.label.size(); ++j)
    for(double x : soup.points[j < soup.points.size() ? j : v.duplicated[j - soup.points.size()]]) positions.push_back(float(x));
  Json primitive = {{"attributes", {{"POSITION", out.add_floats(positions, 3, true)},
                                    {"_FEATURE_ID_0", out.add_feature_ids(v.label, number_of_labels)}}},
                    {"indices", out.add_indices(corner_indices(v))}, {"mode", 4},
                    {"extensions", {{"EXT_mesh_features", {{"featureIds", Json::array({Json{{"featureCount", number_of_labels}, {"attribute", 0}}})}}}}}};
  out.gltf["asset"] = output_asset(nullptr);
  out.gltf["scene"] = 0;
  out.gltf["scenes"] = Json::array({Json{{"nodes", {0}}}});
  out.gltf["nodes"] = Json::array({Json{{"name", "mesh"}, {"mesh", 0}}});
  out.gltf["meshes"] = Json::array({Json{{"name", "mesh"}, {"primitives", Json::array({primitive})}}});
  out.gltf["extensionsUsed"] = Json::array({"EXT_mesh_features"});
}
#endif

} // namespace internal
/// \endcond

namespace IO {

/*!
\ingroup PkgPartDecompositionIO
writes the mesh file `filename` with a label on every face (a part, see `labels_in_file_order()`)
as a binary glTF 2.0 file (GLB) to `out`, the labels as feature IDs of the glTF extension
`EXT_mesh_features`: every primitive gets a vertex attribute `_FEATURE_ID_0` (`_FEATURE_ID_n` if
the file has attributes of the lower numbers already) holding the label of each of its triangles
at its three corners, declared in the primitive as
`"extensions": {"EXT_mesh_features": {"featureIds": [{"featureCount": number_of_labels, "attribute": 0}]}}`.
A vertex shared by triangles with different labels is duplicated, once per extra label.

If `filename` is a glTF file (`.gltf` or `.glb`), the output is its scene unchanged (nodes,
transforms, meshes, materials, textures, every vertex attribute, the extensions), with the buffers
of the file (and images in files next to it) embedded in the GLB's buffer: the feature ID attribute
is added to every triangle primitive of the default scene, the vertex attributes of a primitive
whose vertices are duplicated are extended with the copies (its triangles then written as
`TRIANGLES`), and a mesh instanced by several nodes whose triangles get different labels is
duplicated, one copy per labelling. Otherwise (OFF, OBJ, PLY, STL), the output is one mesh with
one primitive: the polygons of the file triangulated as `read_triangle_mesh()` does (faces with
fewer than three distinct vertices left out), with their positions and the feature IDs.

The faces of the file are those `read_triangle_mesh()` reads, in the same order (a glTF file:
its triangles in the order of the reader).

\param out the stream, opened in binary mode
\param filename the mesh file
\param face_label the label of each face of the file, in the file's order, in `[0, number_of_labels)`
\param number_of_labels the number of labels (the `featureCount`)

\throws Invalid_input if the file cannot be read (`UNREADABLE_FILE`; a glTF file also when the
package is built without nlohmann/json) or has a face with an out-of-range vertex index (`INVALID_FACE`)
\throws std::invalid_argument if `face_label` does not hold one label in `[0, number_of_labels)`
per face of the file
*/
inline void write_labels_glb(std::ostream& out, const std::string& filename, const std::vector<std::size_t>& face_label,
                             std::size_t number_of_labels)
{
#ifdef CGAL_PART_DECOMPOSITION_HAS_GLTF
  internal::Glb_builder builder;
  if(internal::is_gltf_file(filename))
  {
    const std::unique_ptr<internal::Gltf_source> source = internal::read_gltf_source(filename);
    internal::check_file_labels(face_label, source->number_of_triangles, number_of_labels, "write_labels_glb()");
    internal::with_gltf_errors(filename, [&] { internal::labelled_scene_document(*source, face_label, number_of_labels, builder); });
  }
  else
    internal::labelled_soup_document(filename, face_label, number_of_labels, builder);
  builder.write(out);
#else
  CGAL_USE(out);
  CGAL_USE(face_label);
  CGAL_USE(number_of_labels);
  throw Invalid_input(Input_error::UNREADABLE_FILE,
                      "cannot write '" + filename + "' with labels: glTF needs nlohmann/json.hpp (Debian: nlohmann-json3-dev)");
#endif
}

} // namespace IO
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_IO_WRITE_LABELS_GLTF_H
