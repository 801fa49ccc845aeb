// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

// The comparison peer: CGAL's shape-diameter-function segmentation (Surface_mesh_segmentation)
// with its default parameters, guarded against the two inputs on which CGAL 5.5.1 aborts or
// loops, so that a benchmark run always finishes.

#ifndef PART_DECOMPOSITION_BENCHMARK_SDF_PEER_H
#define PART_DECOMPOSITION_BENCHMARK_SDF_PEER_H

#include <CGAL/Surface_mesh.h>
#include <CGAL/mesh_segmentation.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace pd_benchmark {

// CGAL 5.5.1 defaults (CGAL/mesh_segmentation.h).
constexpr double sdf_default_cone_angle = 2.0 / 3.0 * CGAL_PI;
constexpr std::size_t sdf_default_number_of_rays = 25;
constexpr std::size_t sdf_default_number_of_clusters = 5;
constexpr double sdf_default_smoothing_lambda = 0.26;
// CGAL_NORMALIZATION_ALPHA of Surface_mesh_segmentation/internal/Surface_mesh_segmentation.h
// (#undef'd at its end): the log normalization applied before the clustering.
constexpr double sdf_log_normalization_alpha = 5.0;

struct Sdf_peer_result
{
  std::vector<std::size_t> labels;     // segment id of each face, in the iteration order of faces()
  std::size_t number_of_segments = 0;
  std::size_t number_of_clusters = 0;  // the cluster count actually passed to CGAL
  std::size_t distinct_sdf_values = 0; // after CGAL's log normalization
  std::size_t reversed_components = 0; // closed components turned outward before the SDF
  std::size_t open_components = 0;
  double sdf_seconds = 0.;
  double segmentation_seconds = 0.;
  std::string note;                    // every guard that fired, "; "-separated
};

namespace internal {

inline void add_note(std::string& note, const std::string& text)
{
  if(!note.empty()) note += "; ";
  note += text;
}

inline double seconds_since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Reverses every closed connected component of negative signed volume; returns how many; counts
// the open components (their orientation is left as is: there is no inside to point away from).
template <typename Point>
std::size_t orient_closed_components_outward(CGAL::Surface_mesh<Point>& mesh, std::size_t& open_components)
{
  typedef CGAL::Surface_mesh<Point> Mesh;
  typedef typename Mesh::Face_index Face;
  auto fcc = mesh.template add_property_map<Face, std::size_t>("f:pd_sdf_peer_cc", 0).first;
  const std::size_t ncc = CGAL::Polygon_mesh_processing::connected_components(mesh, fcc);
  std::vector<double> volume(ncc, 0.);
  std::vector<char> closed(ncc, 1);
  for(Face f : faces(mesh))
  {
    std::array<std::array<double, 3>, 3> p;
    int k = 0;
    for(auto h : halfedges_around_face(halfedge(f, mesh), mesh))
    {
      const Point& q = mesh.point(target(h, mesh));
      p[k++] = {{CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z())}};
      if(is_border(opposite(h, mesh), mesh)) closed[fcc[f]] = 0;
    }
    volume[fcc[f]] += p[0][0] * (p[1][1] * p[2][2] - p[1][2] * p[2][1])
                    - p[0][1] * (p[1][0] * p[2][2] - p[1][2] * p[2][0])
                    + p[0][2] * (p[1][0] * p[2][1] - p[1][1] * p[2][0]);
  }
  std::vector<Face> to_reverse;
  for(Face f : faces(mesh))
    if(closed[fcc[f]] && volume[fcc[f]] < 0.) to_reverse.push_back(f);
  std::size_t reversed = 0;
  open_components = 0;
  for(std::size_t c = 0; c < ncc; ++c)
  {
    if(!closed[c]) ++open_components;
    else if(volume[c] < 0.) ++reversed;
  }
  mesh.remove_property_map(fcc);
  if(!to_reverse.empty())
    CGAL::Polygon_mesh_processing::reverse_face_orientations(to_reverse, mesh);
  return reversed;
}

} // namespace internal

// Runs CGAL::sdf_values() and CGAL::segmentation_from_sdf_values() with their default parameters
// on a copy of `input` (face indices are kept, so labels[i] belongs to the i-th face of `input`).
// Guards:
// - closed components whose faces point inward cast their rays outward and get no SDF value at
//   all (CGAL then crashes in the clustering): they are reoriented first. Our reader already
//   orients closed components outward, so on its meshes this guard should never fire.
// - k-means++ in CGAL 5.5.1 loops or reads out of bounds when the faces carry fewer distinct
//   (log-normalized) SDF values than clusters (a tetrahedron, a regular octahedron): the cluster count is
//   lowered to that number, and a mesh with a single value is one segment.
// `clusters`: the number of clusters asked of CGAL (its default, or the oracle count).
template <typename Point>
Sdf_peer_result segment_with_sdf(const CGAL::Surface_mesh<Point>& input,
                                 std::size_t clusters = sdf_default_number_of_clusters)
{
  typedef CGAL::Surface_mesh<Point> Mesh;
  typedef typename Mesh::Face_index Face;
  Sdf_peer_result r;
  CGAL_precondition(!input.has_garbage()); // the copy must keep the face order
  Mesh mesh(input);
  r.reversed_components = internal::orient_closed_components_outward(mesh, r.open_components);
  if(r.reversed_components > 0)
    internal::add_note(r.note, "reoriented " + std::to_string(r.reversed_components) +
                               " inward closed component(s)");

  auto sdf = mesh.template add_property_map<Face, double>("f:pd_sdf", 0.).first;
  auto segment = mesh.template add_property_map<Face, std::size_t>("f:pd_segment", 0).first;

  auto t0 = std::chrono::steady_clock::now();
  CGAL::sdf_values(mesh, sdf, sdf_default_cone_angle, sdf_default_number_of_rays, true);
  r.sdf_seconds = internal::seconds_since(t0);

  // The values CGAL clusters: log(5 v + 1) / log(6) of the [0,1]-normalized SDF.
  std::vector<double> values;
  values.reserve(num_faces(mesh));
  std::size_t no_hit = 0;
  for(Face f : faces(mesh))
  {
    const double v = sdf[f];
    if(!(v >= 0. && v <= 1.)) ++no_hit; // CGAL leaves DBL_MAX where no ray hit anything
    values.push_back(std::log(v * sdf_log_normalization_alpha + 1) / std::log(sdf_log_normalization_alpha + 1));
  }
  if(no_hit > 0)
    internal::add_note(r.note, std::to_string(no_hit) + " face(s) without SDF value");
  std::sort(values.begin(), values.end());
  r.distinct_sdf_values = std::size_t(std::unique(values.begin(), values.end()) - values.begin());
  r.number_of_clusters = (std::min)(clusters, r.distinct_sdf_values);

  t0 = std::chrono::steady_clock::now();
  if(no_hit == num_faces(mesh) || r.number_of_clusters <= 1)
  {
    internal::add_note(r.note, "single segment (" + std::to_string(r.distinct_sdf_values) +
                               " distinct SDF value)");
    for(Face f : faces(mesh)) segment[f] = 0;
    r.number_of_segments = 1;
  }
  else
  {
    if(r.number_of_clusters < clusters)
      internal::add_note(r.note, "clusters " + std::to_string(clusters) + "->" +
                                 std::to_string(r.number_of_clusters) + " (" +
                                 std::to_string(r.distinct_sdf_values) + " distinct SDF values)");
    r.number_of_segments = CGAL::segmentation_from_sdf_values(mesh, sdf, segment, r.number_of_clusters,
                                                              sdf_default_smoothing_lambda);
  }
  r.segmentation_seconds = internal::seconds_since(t0);

  r.labels.reserve(num_faces(mesh));
  for(Face f : faces(mesh)) r.labels.push_back(segment[f]);
  return r;
}

} // namespace pd_benchmark

#endif // PART_DECOMPOSITION_BENCHMARK_SDF_PEER_H
