// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_FACE_ADJACENCY_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_FACE_ADJACENCY_H

#include <CGAL/Part_decomposition/internal/toolbox/toolbox.h>

#include <CGAL/assertions.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/number_utils.h>
#include <CGAL/number_type_config.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <mutex>
#include <vector>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

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
  std::vector<double> normal;        // 3 per face, unit (0 for a degenerate face)
  std::vector<std::uint8_t> degenerate; // per face: zero or non-finite normal
  std::vector<std::uint8_t> junction;   // per slot: glued across a non-manifold edge (empty: none)
  std::vector<std::size_t> twin;        // per face: a face with the same corners, or no_face (empty: none)
};

// The corners of each face as doubles, by face index, in the order of halfedge(f, tm) along next().
struct Face_corners
{
  std::vector<Eigen::Vector3d> point; // per vertex
  std::vector<std::size_t> vertex;    // three per face

  // in parallel when `ConcurrencyTag` is (each element writes its own entries)
  template <typename TriangleMesh, typename FaceIndexMap, typename VertexPointMap,
            typename ConcurrencyTag = CGAL::Sequential_tag>
  Face_corners(const TriangleMesh& tm, const FaceIndexMap& fim, const VertexPointMap& vpm,
               ConcurrencyTag = ConcurrencyTag())
  {
    const auto vim = CGAL::get_initialized_vertex_index_map(tm);
    typedef boost::graph_traits<TriangleMesh> GT;
    const std::vector<typename GT::vertex_descriptor> vs(vertices(tm).begin(), vertices(tm).end());
    point.resize(num_vertices(tm));
    for_each_range<ConcurrencyTag>(vs.size(), [&](std::size_t b, std::size_t e) {
      for(std::size_t r = b; r < e; ++r)
      {
        const auto& p = get(vpm, vs[r]);
        point[std::size_t(get(vim, vs[r]))] =
          Eigen::Vector3d(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
      }
    }, 4096);
    const std::vector<typename GT::face_descriptor> fs(faces(tm).begin(), faces(tm).end());
    vertex.resize(3 * num_faces(tm));
    for_each_range<ConcurrencyTag>(fs.size(), [&](std::size_t b, std::size_t e) {
      for(std::size_t r = b; r < e; ++r)
      {
        std::size_t k = 3 * std::size_t(get(fim, fs[r]));
        for(auto v : vertices_around_face(halfedge(fs[r], tm), tm)) vertex[k++] = std::size_t(get(vim, v));
      }
    }, 4096);
  }

  const Eigen::Vector3d& operator()(std::size_t face, int k) const { return point[vertex[3 * face + std::size_t(k)]]; }
};

// The length of the edge of slot (i, k) of `corners` (a Face_corners, or anything called as one):
// corners are listed from target(halfedge(f)) on, so the edge of slot k joins corners k and k - 1.
template <typename Corners>
double slot_length(const Corners& corners, std::size_t i, int k)
{
  return (corners(i, k) - corners(i, (k + 2) % 3)).norm();
}

// The index of halfedge h in its face, counted from halfedge(face(h), tm).
template <typename TriangleMesh>
int slot_in_face(typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h, const TriangleMesh& tm)
{
  const auto h0 = halfedge(face(h, tm), tm);
  if(h == h0) return 0;
  return h == next(h0, tm) ? 1 : 2;
}

// The face of each face index.
template <typename TriangleMesh, typename FaceIndexMap>
std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>
faces_by_index(const TriangleMesh& tm, const FaceIndexMap& fim)
{
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  const std::size_t nf = num_faces(tm);
  std::vector<face_descriptor> face_of(nf, face_descriptor());
  for(face_descriptor f : faces(tm))
  {
    const std::size_t i = std::size_t(get(fim, f));
    CGAL_precondition(i < nf);
    face_of[i] = f;
  }
  return face_of;
}

// The neighbours, centroid (relative to `origin`), area and degeneracy of each face, and its
// unit normal in `normal` (3 per face, 0 for a degenerate face).
template <typename ConcurrencyTag, typename TriangleMesh, typename FaceIndexMap, typename VertexPointMap,
          typename GeomTraits>
void compute_face_geometry(const TriangleMesh& tm, const FaceIndexMap& fim, const VertexPointMap& vpm,
                           const GeomTraits& gt,
                           const std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>& face_of,
                           const Vec3& origin, Face_adjacency& adj, std::vector<double>& normal)
{
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  const auto vector_3 = gt.construct_vector_3_object();
  const auto cross = gt.construct_cross_product_vector_3_object();
  for_each_range<ConcurrencyTag>(adj.number_of_faces, [&](std::size_t b, std::size_t e) {
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
  }, 1024);
}

// The dihedral angle, in degrees, between faces i and j of `adj` from their normals;
// `degenerate_angle` if one has no normal.
inline double dihedral_angle(const Face_adjacency& adj, std::size_t i, std::size_t j)
{
  if(adj.degenerate[i] || adj.degenerate[j]) return Face_adjacency::degenerate_angle;
  const double* a = &adj.normal[3 * i];
  const double* c = &adj.normal[3 * j];
  const double d = a[0] * c[0] + a[1] * c[1] + a[2] * c[2];
  return std::acos((std::max)(-1., (std::min)(1., d))) * (180. / CGAL_PI);
}

// The dihedral angle of every interior slot. It depends only on the two normals: it is computed
// on the slot of the smaller face index, then copied to the other side (two faces sharing two
// edges get the same value).
template <typename ConcurrencyTag>
void compute_dihedral_angles(Face_adjacency& adj)
{
  const std::size_t nf = adj.number_of_faces;
  for_each_range<ConcurrencyTag>(nf, [&](std::size_t b, std::size_t e) {
    for(std::size_t i = b; i < e; ++i)
      for(int k = 0; k < 3; ++k)
      {
        const std::size_t j = adj.neighbor[3 * i + k];
        if(j == Face_adjacency::no_face || j < i) continue;
        adj.angle[3 * i + k] = dihedral_angle(adj, i, j);
      }
  }, 1024);
  for_each_range<ConcurrencyTag>(nf, [&](std::size_t b, std::size_t e) {
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
  }, 1024);
}

// The face graph of `tm` with its dihedral angles; `face_of` receives the face of each index.
template <typename ConcurrencyTag, typename TriangleMesh, typename FaceIndexMap, typename VertexPointMap,
          typename GeomTraits>
Face_adjacency build_face_adjacency(
    const TriangleMesh& tm, const FaceIndexMap& fim, const VertexPointMap& vpm, const GeomTraits& gt,
    std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>& face_of)
{
  face_of = faces_by_index(tm, fim);
  const std::size_t nf = face_of.size();
  Face_adjacency adj;
  adj.number_of_faces = nf;
  adj.neighbor.assign(3 * nf, Face_adjacency::no_face);
  adj.angle.assign(3 * nf, 0.);
  adj.area.assign(nf, 0.);
  adj.centroid.assign(3 * nf, 0.);
  adj.degenerate.assign(nf, 0);

  // Centroids relative to a vertex of the mesh: moments of far-off meshes stay accurate.
  Vec3 origin = {{0., 0., 0.}};
  if(nf > 0) origin = vec3_of(get(vpm, target(halfedge(face_of[0], tm), tm)));
  adj.normal.assign(3 * nf, 0.);
  compute_face_geometry<ConcurrencyTag>(tm, fim, vpm, gt, face_of, origin, adj, adj.normal);
  compute_dihedral_angles<ConcurrencyTag>(adj);
  return adj;
}

// The face graph of `tm` with the vertex point map and geometric traits of `np` (the graph of
// the over-segmentation, which the thin-sheet merge reuses).
template <typename ConcurrencyTag, typename TriangleMesh, typename FaceIndexMap, typename NamedParameters>
Face_adjacency face_adjacency_of(const TriangleMesh& tm, const FaceIndexMap& fim, const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename GetGeomTraits<TriangleMesh, NamedParameters>::type GT;
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, tm));
  const GT gt = choose_parameter<GT>(get_parameter(np, CGAL::internal_np::geom_traits));
  std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor> face_of;
  return build_face_adjacency<ConcurrencyTag>(tm, fim, vpm, gt, face_of);
}

// The face graphs of one mesh, built once by `decompose()` and read by every stage it runs: a
// graph costs about 0.5 s per million faces (1 s glued), and nine stages read one.
// Superfaces: the edge-connected faces whose centroids lie in one cell of a grid (see
// `make_superfaces()`).
struct Superfaces
{
  std::vector<std::size_t> of_face; // per face index, its superface, numbered by first face
  std::vector<std::size_t> start, face; // superface s: faces face[start[s] .. start[s + 1]), increasing
  std::size_t size() const { return start.empty() ? 0 : start.size() - 1; }
};

struct Face_graphs
{
  // the corners of the faces, made by the first stage that asks (shared_face_corners())
  struct Corners
  {
    std::once_flag made;
    std::shared_ptr<const Face_corners> corners;
  };

  std::shared_ptr<const Face_adjacency> plain;  // face_adjacency_of()
  std::shared_ptr<const Face_adjacency> pieces; // piece_adjacency()
  std::shared_ptr<Corners> corners = std::make_shared<Corners>();
  // the superfaces of `plain`, made by the first stage that asks for their cell (shared_superfaces())
  struct Superface_cache
  {
    std::mutex mutex;
    double cell = 0.;
    std::shared_ptr<const Superfaces> superfaces;
  };
  std::shared_ptr<Superface_cache> superfaces = std::make_shared<Superface_cache>();
};

} // namespace internal

namespace internal_np {
enum face_graphs_t { face_graphs }; // const internal::Face_graphs*, internal to decompose()
} // namespace internal_np

namespace internal {

// The face graphs that `decompose()` passes to its stages in `np`, or null.
template <typename NamedParameters>
const Face_graphs* face_graphs_of(const NamedParameters& np)
{
  return CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np::face_graphs),
                                            static_cast<const Face_graphs*>(nullptr));
}

// The named parameter that hands `graphs` to the stages (null: each stage builds its own).
inline CGAL::Named_function_parameters<const Face_graphs*, internal_np::face_graphs_t>
face_graphs_parameter(const Face_graphs* graphs)
{
  return CGAL::Named_function_parameters<const Face_graphs*, internal_np::face_graphs_t>(graphs);
}

// `face_adjacency_of()`, shared with the other stages of `decompose()`.
template <typename ConcurrencyTag, typename TriangleMesh, typename FaceIndexMap, typename NamedParameters>
std::shared_ptr<const Face_adjacency> shared_face_adjacency(const TriangleMesh& tm, const FaceIndexMap& fim,
                                                            const NamedParameters& np)
{
  const Face_graphs* graphs = face_graphs_of(np);
  if(graphs != nullptr && graphs->plain) return graphs->plain;
  return std::make_shared<const Face_adjacency>(face_adjacency_of<ConcurrencyTag>(tm, fim, np));
}

// The corners of the faces of `tm`, shared with the other stages of `decompose()`. Only the
// stages from the distance field on ask for them: a large mesh's memory peaks while the field is
// computed, without them.
template <typename ConcurrencyTag, typename TriangleMesh, typename FaceIndexMap, typename VertexPointMap,
          typename NamedParameters>
std::shared_ptr<const Face_corners> shared_face_corners(const TriangleMesh& tm, const FaceIndexMap& fim,
                                                        const VertexPointMap& vpm, const NamedParameters& np)
{
  const Face_graphs* graphs = face_graphs_of(np);
  if(graphs == nullptr) return std::make_shared<const Face_corners>(tm, fim, vpm, ConcurrencyTag());
  Face_graphs::Corners& shared = *graphs->corners;
  std::call_once(shared.made, [&] { shared.corners = std::make_shared<const Face_corners>(tm, fim, vpm, ConcurrencyTag()); });
  return shared.corners;
}

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_FACE_ADJACENCY_H
