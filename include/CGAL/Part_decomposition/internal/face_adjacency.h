// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_FACE_ADJACENCY_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_FACE_ADJACENCY_H

#include <CGAL/assertions.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>
#include <CGAL/tags.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#endif

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

// Calls f(begin, end) on chunks of [0, n): one call when sequential, TBB chunks otherwise.
// Callers write only to slots they own, so the result does not depend on the chunking.
template <typename ConcurrencyTag, typename F>
void chunked_for(std::size_t n, const F& f)
{
#ifdef CGAL_LINKED_WITH_TBB
  if(std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value && n > 2048)
  {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 1024),
                      [&](const tbb::blocked_range<std::size_t>& r) { f(r.begin(), r.end()); });
    return;
  }
#endif
  f(std::size_t(0), n);
}

// The face graph of a triangle mesh in flat arrays indexed by the face index map. Slot 3*i+k is
// the k-th halfedge of face i, counted from halfedge(f, tm) along next().
struct Face_adjacency
{
  static constexpr std::size_t no_face = (std::numeric_limits<std::size_t>::max)();
  // The dihedral angle given to an edge with a zero-area face: it is always cut.
  static constexpr double degenerate_angle = 180.;

  std::size_t number_of_faces = 0;
  std::vector<std::size_t> neighbor; // face across each slot, no_face on a border
  std::vector<double> angle;         // dihedral angle (degrees) across each slot, 0 on a border
  std::vector<double> area;          // per face
  std::vector<double> centroid;      // 3 per face, relative to a vertex of the mesh
  std::vector<std::uint8_t> degenerate; // per face: zero or non-finite normal
};

// The index of halfedge h in its face, counted from halfedge(face(h), tm).
template <typename TriangleMesh>
int slot_in_face(typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h, const TriangleMesh& tm)
{
  const auto h0 = halfedge(face(h, tm), tm);
  if(h == h0) return 0;
  return h == next(h0, tm) ? 1 : 2;
}

template <typename ConcurrencyTag, typename TriangleMesh, typename FaceIndexMap, typename VertexPointMap,
          typename GeomTraits>
Face_adjacency build_face_adjacency(
    const TriangleMesh& tm, const FaceIndexMap& fim, const VertexPointMap& vpm, const GeomTraits& gt,
    std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>& face_of)
{
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;

  Face_adjacency adj;
  const std::size_t nf = num_faces(tm);
  adj.number_of_faces = nf;
  face_of.assign(nf, face_descriptor());
  for(face_descriptor f : faces(tm))
  {
    const std::size_t i = std::size_t(get(fim, f));
    CGAL_precondition(i < nf);
    face_of[i] = f;
  }
  adj.neighbor.assign(3 * nf, Face_adjacency::no_face);
  adj.angle.assign(3 * nf, 0.);
  adj.area.assign(nf, 0.);
  adj.centroid.assign(3 * nf, 0.);
  adj.degenerate.assign(nf, 0);
  std::vector<double> normal(3 * nf, 0.);

  // Centroids relative to a vertex of the mesh: moments of far-off meshes stay accurate.
  double origin[3] = {0., 0., 0.};
  if(nf > 0)
  {
    const auto& p = get(vpm, target(halfedge(face_of[0], tm), tm));
    origin[0] = CGAL::to_double(p.x());
    origin[1] = CGAL::to_double(p.y());
    origin[2] = CGAL::to_double(p.z());
  }
  const auto vector_3 = gt.construct_vector_3_object();
  const auto cross = gt.construct_cross_product_vector_3_object();
  chunked_for<ConcurrencyTag>(nf, [&](std::size_t b, std::size_t e) {
    for(std::size_t i = b; i < e; ++i)
    {
      const face_descriptor f = face_of[i];
      halfedge_descriptor h = halfedge(f, tm);
      CGAL_precondition(next(next(next(h, tm), tm), tm) == h);
      const auto& p0 = get(vpm, source(h, tm));
      const auto& p1 = get(vpm, target(h, tm));
      const auto& p2 = get(vpm, target(next(h, tm), tm));
      adj.centroid[3 * i + 0] = (CGAL::to_double(p0.x()) + CGAL::to_double(p1.x()) + CGAL::to_double(p2.x())) / 3. - origin[0];
      adj.centroid[3 * i + 1] = (CGAL::to_double(p0.y()) + CGAL::to_double(p1.y()) + CGAL::to_double(p2.y())) / 3. - origin[1];
      adj.centroid[3 * i + 2] = (CGAL::to_double(p0.z()) + CGAL::to_double(p1.z()) + CGAL::to_double(p2.z())) / 3. - origin[2];
      const auto n = cross(vector_3(p0, p1), vector_3(p0, p2));
      const double c[3] = {CGAL::to_double(n.x()), CGAL::to_double(n.y()), CGAL::to_double(n.z())};
      const double len = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
      if(len > 0. && std::isfinite(len))
      {
        for(int a = 0; a < 3; ++a) normal[3 * i + a] = c[a] / len;
        adj.area[i] = 0.5 * len;
      }
      else
        adj.degenerate[i] = 1;
      for(int k = 0; k < 3; ++k, h = next(h, tm))
      {
        const face_descriptor g = face(opposite(h, tm), tm);
        if(g != boost::graph_traits<TriangleMesh>::null_face())
          adj.neighbor[3 * i + k] = std::size_t(get(fim, g));
      }
    }
  });

  // The angle depends only on the two normals: compute it on the slot of the smaller face
  // index, then copy it to the other side (two faces sharing two edges get the same value).
  chunked_for<ConcurrencyTag>(nf, [&](std::size_t b, std::size_t e) {
    for(std::size_t i = b; i < e; ++i)
      for(int k = 0; k < 3; ++k)
      {
        const std::size_t j = adj.neighbor[3 * i + k];
        if(j == Face_adjacency::no_face || j < i) continue;
        if(adj.degenerate[i] || adj.degenerate[j])
        {
          adj.angle[3 * i + k] = Face_adjacency::degenerate_angle;
          continue;
        }
        const double* a = &normal[3 * i];
        const double* c = &normal[3 * j];
        const double d = a[0] * c[0] + a[1] * c[1] + a[2] * c[2];
        adj.angle[3 * i + k] = std::acos((std::max)(-1., (std::min)(1., d))) * (180. / CGAL_PI);
      }
  });
  chunked_for<ConcurrencyTag>(nf, [&](std::size_t b, std::size_t e) {
    for(std::size_t i = b; i < e; ++i)
      for(int k = 0; k < 3; ++k)
      {
        const std::size_t j = adj.neighbor[3 * i + k];
        if(j == Face_adjacency::no_face || j >= i) continue;
        for(int l = 0; l < 3; ++l)
          if(adj.neighbor[3 * j + l] == i)
          {
            adj.angle[3 * i + k] = adj.angle[3 * j + l];
            break;
          }
      }
  });
  return adj;
}

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_FACE_ADJACENCY_H
