// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_PIECE_REGIONS_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_PIECE_REGIONS_H

// Pieces (edge-connected components of the face graph, edges with the same end points glued),
// whether each is closed, the regions of each piece between its concave creases, and the parts
// composed from them, on the flat face graph of face_adjacency.h.
//
// Inputs: a Face_adjacency (neighbours, dihedral angles, normals, centroids, areas per face
// index). Outputs: per face index a piece id, a region id and a part id, numbered by first face.

#include <CGAL/Part_decomposition/internal/toolbox/face_adjacency.h>
#include <CGAL/Part_decomposition/internal/parts/patch_operations.h>
#include <CGAL/Part_decomposition/internal/toolbox/toolbox.h>

#include <CGAL/Union_find.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <map>
#include <memory>
#include <utility>
#include <vector>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

// A hash of sorted coordinates that equal coordinates share (-0 and 0 included).
inline std::uint64_t hash_of_points(const double* x, std::size_t n)
{
  std::uint64_t h = 0x9e3779b97f4a7c15ull;
  for(std::size_t i = 0; i < n; ++i)
  {
    const double v = x[i] == 0. ? 0. : x[i];
    std::uint64_t u;
    std::memcpy(&u, &v, 8);
    h ^= u + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
    h = (h ^ (h >> 31)) * 0xbf58476d1ce4e5b9ull;
  }
  return h;
}

// The indices i whose `hash[i]` is also the hash of another index, increasing: the hashes go
// into a table of at least twice as many slots (open addressing, filled by all threads at once).
template <typename ConcurrencyTag>
std::vector<std::size_t> indices_of_repeated_hashes(const std::vector<std::uint64_t>& hash)
{
  const std::size_t n = hash.size();
  std::size_t size = 1;
  while(size < 2 * n) size *= 2;
  std::vector<std::atomic<std::uint64_t> > slot(size);
  std::vector<std::atomic<std::uint8_t> > repeated(size);
  for_each_range<ConcurrencyTag>(size, [&](std::size_t b, std::size_t e) {
    for(std::size_t s = b; s < e; ++s)
    {
      slot[s].store(0, std::memory_order_relaxed);
      repeated[s].store(0, std::memory_order_relaxed);
    }
  }, 4096);
  const auto key = [&](std::size_t i) { return hash[i] == 0 ? std::uint64_t(1) : hash[i]; }; // 0: an empty slot
  // the slot of key k, after storing k there if it is new
  const auto place = [&](std::uint64_t k) {
    for(std::size_t s = std::size_t(k) & (size - 1);; s = (s + 1) & (size - 1))
    {
      std::uint64_t seen = 0;
      if(slot[s].compare_exchange_strong(seen, k, std::memory_order_relaxed) || seen == k) return std::make_pair(s, seen == k);
    }
  };
  for_each_range<ConcurrencyTag>(n, [&](std::size_t b, std::size_t e) {
    for(std::size_t i = b; i < e; ++i)
    {
      const std::pair<std::size_t, bool> p = place(key(i));
      if(p.second) repeated[p.first].store(1, std::memory_order_relaxed);
    }
  }, 4096);
  std::vector<std::uint8_t> flag(n, 0);
  for_each_range<ConcurrencyTag>(n, [&](std::size_t b, std::size_t e) {
    for(std::size_t i = b; i < e; ++i) flag[i] = repeated[place(key(i)).first].load(std::memory_order_relaxed);
  }, 4096);
  std::vector<std::size_t> out;
  for(std::size_t i = 0; i < n; ++i)
    if(flag[i]) out.push_back(i);
  return out;
}

// Faces with the same three corners are twins (`adj.twin`: the first of them; empty if none).
// Faces are grouped by a hash of their sorted corners and compared exactly within a group of two
// or more: sorting the corners of a million faces costs seconds and a hundred bytes per face.
template <typename ConcurrencyTag, typename Corners>
void find_twin_faces(const Corners& corners, Face_adjacency& adj)
{
  typedef std::array<std::array<double, 3>, 3> C;
  const std::size_t nf = adj.number_of_faces;
  auto sorted_corners = [&](std::size_t i) {
    C c = corners(i);
    std::sort(c.begin(), c.end());
    return c;
  };
  std::vector<std::uint64_t> hash(nf);
  for_each_range<ConcurrencyTag>(nf, [&](std::size_t b, std::size_t e) {
    for(std::size_t i = b; i < e; ++i) hash[i] = hash_of_points(sorted_corners(i)[0].data(), 9);
  }, 4096);
  // only the faces whose hash repeats are compared, group by group
  std::vector<std::pair<std::uint64_t, std::size_t> > hashed;
  for(std::size_t i : indices_of_repeated_hashes<ConcurrencyTag>(hash)) hashed.emplace_back(hash[i], i);
  std::sort(hashed.begin(), hashed.end());
  adj.twin.clear(); // allocated at the first twin: empty means none
  std::vector<std::pair<C, std::size_t> > group;
  for(std::size_t s = 0; s < hashed.size();)
  {
    std::size_t e = s + 1;
    while(e < hashed.size() && hashed[e].first == hashed[s].first) ++e;
    group.clear();
    for(std::size_t t = s; t < e; ++t) group.emplace_back(sorted_corners(hashed[t].second), hashed[t].second);
    std::sort(group.begin(), group.end());
    for(std::size_t t = 1; t < group.size(); ++t)
      if(group[t].first == group[t - 1].first)
      {
        if(adj.twin.empty()) adj.twin.assign(nf, Face_adjacency::no_face);
        adj.twin[group[t].second] = adj.twin[group[t - 1].second] != Face_adjacency::no_face
                                      ? adj.twin[group[t - 1].second] : group[t - 1].second;
      }
    s = e;
  }
}

// Gives the border slots of `adj` whose edges have the same two end points as other edges (edges
// the reader split because they are non-manifold or join faces of opposite orientations) a
// neighbour: each such slot is linked to the face of the next slot of its edge in slot order,
// cyclically, so that the faces of one edge are connected. The dihedral angle of a linked slot is
// taken from the two normals; the slots of an edge of three faces or more are marked in
// `adj.junction`. Faces with the same three corners are twins (`find_twin_faces()`).
// Only the edges of border slots are sorted (none on a closed mesh), then every slot on one of
// them (a fin on a plate glues a border edge to an interior one). Returns whether a slot was
// glued or a twin found: if not, the graph reads as the unglued one.
template <typename ConcurrencyTag, typename TriangleMesh, typename FaceIndexMap, typename VertexPointMap>
bool glue_coincident_border_edges(const TriangleMesh& tm, const FaceIndexMap& fim, const VertexPointMap& vpm,
                                  Face_adjacency& adj)
{
  typedef std::array<double, 3> P;
  typedef std::array<P, 2> Edge;
  const auto face_of = faces_by_index(tm, fim);
  auto corners = [&](std::size_t i) {
    auto h = halfedge(face_of[i], tm);
    std::array<P, 3> c;
    for(int k = 0; k < 3; ++k, h = next(h, tm)) c[k] = vec3_of(get(vpm, source(h, tm)));
    return c;
  };
  auto edge = [](const std::array<P, 3>& c, int k) {
    Edge e = {{c[k], c[(k + 1) % 3]}};
    if(e[1] < e[0]) std::swap(e[0], e[1]);
    return e;
  };
  std::vector<Edge> border;
  for(std::size_t i = 0; i < adj.number_of_faces; ++i)
    for(int k = 0; k < 3; ++k)
      if(adj.neighbor[3 * i + std::size_t(k)] == Face_adjacency::no_face) border.push_back(edge(corners(i), k));
  std::sort(border.begin(), border.end());
  border.erase(std::unique(border.begin(), border.end()), border.end());

  std::vector<std::pair<Edge, std::size_t> > edges; // (end points, slot), on a border edge
  for(std::size_t i = 0; i < adj.number_of_faces && !border.empty(); ++i)
  {
    const std::array<P, 3> c = corners(i);
    for(int k = 0; k < 3; ++k)
      if(std::binary_search(border.begin(), border.end(), edge(c, k))) edges.emplace_back(edge(c, k), 3 * i + std::size_t(k));
  }
  std::sort(edges.begin(), edges.end());
  adj.junction.clear(); // allocated at the first junction: empty means none
  bool glued = false;
  for(std::size_t s = 0; s < edges.size();)
  {
    std::size_t e = s + 1;
    while(e < edges.size() && edges[e].first == edges[s].first) ++e;
    for(std::size_t t = s; e - s > 1 && t < e; ++t)
    {
      const std::size_t slot = edges[t].second, i = slot / 3;
      if(adj.neighbor[slot] != Face_adjacency::no_face) continue;
      const std::size_t j = edges[t + 1 < e ? t + 1 : s].second / 3;
      adj.neighbor[slot] = j;
      glued = true;
      if(e - s > 2)
      {
        if(adj.junction.empty()) adj.junction.assign(adj.neighbor.size(), 0);
        adj.junction[slot] = 1;
      }
      adj.angle[slot] = dihedral_angle(adj, i, j);
    }
    s = e;
  }
  find_twin_faces<ConcurrencyTag>(corners, adj);
  return glued || std::any_of(adj.twin.begin(), adj.twin.end(), [](std::size_t t) { return t != Face_adjacency::no_face; });
}

// The face graph of the pieces: the graph of `face_adjacency_of()` with coincident border edges
// glued (`glue_coincident_border_edges()`).
template <typename ConcurrencyTag, typename TriangleMesh, typename FaceIndexMap, typename VertexPointMap,
          typename NamedParameters>
Face_adjacency piece_adjacency(const TriangleMesh& tm, const FaceIndexMap& fim, const VertexPointMap& vpm,
                               const NamedParameters& np)
{
  Face_adjacency adj = face_adjacency_of<ConcurrencyTag>(tm, fim, np);
  glue_coincident_border_edges<ConcurrencyTag>(tm, fim, vpm, adj);
  return adj;
}

// `piece_adjacency()`, shared with the other stages of `decompose()`.
template <typename ConcurrencyTag, typename TriangleMesh, typename FaceIndexMap, typename VertexPointMap,
          typename NamedParameters>
std::shared_ptr<const Face_adjacency> shared_piece_adjacency(const TriangleMesh& tm, const FaceIndexMap& fim,
                                                             const VertexPointMap& vpm, const NamedParameters& np)
{
  const Face_graphs* graphs = face_graphs_of(np);
  if(graphs != nullptr && graphs->pieces) return graphs->pieces;
  return std::make_shared<const Face_adjacency>(piece_adjacency<ConcurrencyTag>(tm, fim, vpm, np));
}

// The two face graphs of `tm` for the stages of `decompose()`: one object when gluing changes
// nothing (a mesh without coincident border edges or twin faces), which saves its memory.
template <typename ConcurrencyTag, typename TriangleMesh, typename FaceIndexMap, typename VertexPointMap,
          typename NamedParameters>
Face_graphs build_face_graphs(const TriangleMesh& tm, const FaceIndexMap& fim, const VertexPointMap& vpm,
                              const NamedParameters& np)
{
  Face_graphs g;
  auto glued = std::make_shared<Face_adjacency>(face_adjacency_of<ConcurrencyTag>(tm, fim, np));
  const bool changed = glue_coincident_border_edges<ConcurrencyTag>(tm, fim, vpm, *glued);
  g.pieces = glued;
  g.plain = changed ? std::make_shared<const Face_adjacency>(face_adjacency_of<ConcurrencyTag>(tm, fim, np)) : g.pieces;
  return g;
}

// Whether slot s of `adj` joins three faces or more (see glue_coincident_border_edges()).
inline bool is_junction(const Face_adjacency& adj, std::size_t s)
{
  return !adj.junction.empty() && adj.junction[s];
}

// Per face index: its connected component across the slots (i, k) with a neighbour for which
// `join(i, k)` holds, faces with the same three corners always together (they are one
// surface), numbered by first face; returns the number of components. `join` is called from
// several threads with `CGAL::Parallel_tag`.
template <typename ConcurrencyTag, typename Join>
std::size_t face_components(const Face_adjacency& adj, const Join& join, std::vector<std::size_t>& label)
{
  const std::size_t nf = adj.number_of_faces;
  Index_sets sets(nf, ConcurrencyTag());
  for_each_range<ConcurrencyTag>(nf, [&](std::size_t b, std::size_t e) {
    for(std::size_t i = b; i < e; ++i)
    {
      for(int k = 0; k < 3; ++k)
      {
        const std::size_t j = adj.neighbor[3 * i + k];
        if(j != Face_adjacency::no_face && join(i, k)) sets.unite(i, j);
      }
      if(i < adj.twin.size() && adj.twin[i] != Face_adjacency::no_face) sets.unite(i, adj.twin[i]);
    }
  }, 4096);
  label.resize(nf);
  for_each_range<ConcurrencyTag>(nf, [&](std::size_t b, std::size_t e) {
    for(std::size_t i = b; i < e; ++i) label[i] = sets.find(i);
  }, 4096);
  return renumber_by_first_face(label);
}

// Per face index: the id of its edge-connected component, numbered by first face; returns the
// number of components.
template <typename ConcurrencyTag>
std::size_t label_pieces(const Face_adjacency& adj, std::vector<std::size_t>& piece)
{
  return face_components<ConcurrencyTag>(adj, [](std::size_t, int) { return true; }, piece);
}

// Per piece: 1 if every edge of its faces has exactly two faces (no border, no junction).
inline std::vector<std::uint8_t> closed_pieces(const Face_adjacency& adj, const std::vector<std::size_t>& piece,
                                               std::size_t number_of_pieces)
{
  std::vector<std::uint8_t> closed(number_of_pieces, 1);
  for(std::size_t i = 0; i < adj.number_of_faces; ++i)
    for(int k = 0; k < 3; ++k)
      if(adj.neighbor[3 * i + k] == Face_adjacency::no_face || is_junction(adj, 3 * i + k)) closed[piece[i]] = 0;
  return closed;
}

// +1 if the edge of slot (i, k) is convex for the orientation of the mesh, -1 if concave: the
// neighbour's centroid lies below or above the plane of face i.
inline int crease_sign(const Face_adjacency& adj, std::size_t i, int k)
{
  const std::size_t j = adj.neighbor[3 * i + k];
  double s = 0.;
  for(int a = 0; a < 3; ++a) s += (adj.centroid[3 * j + a] - adj.centroid[3 * i + a]) * adj.normal[3 * i + a];
  return s > 0. ? -1 : 1;
}

// The dihedral angle, in degrees, from which a concave edge counts fully in the concavity of a
// boundary.
constexpr double full_concavity_angle = 60.;

// The concavity of the edge of slot (i, k) for the orientation (+1 or -1) of its piece:
// min(1, theta / full_concavity_angle) for a concave edge of dihedral angle theta, 0 if convex.
inline double edge_concavity(const Face_adjacency& adj, std::size_t i, int k, int orientation)
{
  return crease_sign(adj, i, k) * orientation < 0 ? (std::min)(1., adj.angle[3 * i + k] / full_concavity_angle) : 0.;
}

// Per piece: -1 if the piece is taken inside out. A closed piece keeps the mesh's orientation
// (the reader orients it outward); an open shell has no outside, so it is oriented to make most
// of its creases (by area of the faces along them) convex: man-made pieces are convex except
// where two parts meet.
inline std::vector<int> piece_orientations(const Face_adjacency& adj, const std::vector<std::size_t>& piece,
                                           const std::vector<std::uint8_t>& closed, double crease_angle)
{
  std::vector<double> vote(closed.size(), 0.);
  for(std::size_t i = 0; i < adj.number_of_faces; ++i)
    for(int k = 0; k < 3 && !closed[piece[i]]; ++k) // a closed piece keeps its orientation
    {
      const std::size_t j = adj.neighbor[3 * i + k];
      if(j == Face_adjacency::no_face || adj.angle[3 * i + k] < crease_angle || is_junction(adj, 3 * i + k)) continue;
      if(adj.degenerate[i] || adj.degenerate[j]) continue;
      vote[piece[i]] += crease_sign(adj, i, k) * (adj.area[i] < adj.area[j] ? adj.area[i] : adj.area[j]);
    }
  std::vector<int> orientation(closed.size(), 1);
  for(std::size_t p = 0; p < closed.size(); ++p)
    if(!closed[p] && vote[p] < 0.) orientation[p] = -1;
  return orientation;
}

// Per face index: the region of its piece between concave creases of at least `crease_angle`
// degrees and junctions of three faces or more (an edge of a face of zero area is never a
// crease), numbered by first face; returns the number of regions.
template <typename ConcurrencyTag>
std::size_t crease_regions(const Face_adjacency& adj, const std::vector<std::size_t>& piece,
                                  const std::vector<int>& orientation, double crease_angle,
                                  std::vector<std::size_t>& region)
{
  return face_components<ConcurrencyTag>(adj, [&](std::size_t i, int k) {
    const std::size_t j = adj.neighbor[3 * i + k];
    // a face of zero area has no normal: no evidence of a crease
    const bool concave = is_junction(adj, 3 * i + k) ||
                         (!adj.degenerate[i] && !adj.degenerate[j] && adj.angle[3 * i + k] >= crease_angle &&
                          crease_sign(adj, i, k) * orientation[piece[i]] < 0);
    return !concave;
  }, region);
}

// The dihedral angle, in degrees, below which a concave edge does not make a piece non-convex:
// the rounding of coplanar or nearly coplanar triangulations.
constexpr double convexity_tolerance = 1.;

// Per piece: 1 if the volumetric stages may split it, if it bounds a volume: it is not convex (an
// edge is concave by at least `convexity_tolerance` degrees as the mesh is oriented) and of area
// at least 2 `min_area` (a smaller piece cannot hold two parts of `min_area`).
inline std::vector<std::uint8_t> splittable_pieces(const Face_adjacency& adj, const std::vector<std::size_t>& piece,
                                                   std::size_t number_of_pieces, double min_area,
                                                   double convexity_tolerance)
{
  std::vector<std::uint8_t> concave(number_of_pieces, 0);
  std::vector<double> area(number_of_pieces, 0.);
  for(std::size_t i = 0; i < adj.number_of_faces; ++i)
  {
    area[piece[i]] += adj.area[i];
    for(int k = 0; k < 3 && !concave[piece[i]]; ++k)
    {
      const std::size_t j = adj.neighbor[3 * i + k];
      if(j != Face_adjacency::no_face && adj.angle[3 * i + k] >= convexity_tolerance && crease_sign(adj, i, k) < 0)
        concave[piece[i]] = 1;
    }
  }
  std::vector<std::uint8_t> splittable(number_of_pieces, 0);
  for(std::size_t p = 0; p < number_of_pieces; ++p) splittable[p] = concave[p] && area[p] >= 2. * min_area;
  return splittable;
}

// Junction edges count only in chains (junction edges joined at common corner points) at least
// this fraction of their piece's bounding-box diagonal long: walls glued along lines form long
// chains, the non-manifold defects of a scan short ones (under 0.035 of the diagonal on a range
// scan; the CAD-style set's chains that decide a verdict are 0.25 to 17 diagonals long).
constexpr double minimum_junction_chain = 0.05;

// The diagonal of the bounding box of each piece's face corners.
template <typename Corners>
std::vector<double> piece_diagonals(const Face_adjacency& adj, const Corners& corners,
                                    const std::vector<std::size_t>& piece, std::size_t number_of_pieces)
{
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<Eigen::Vector3d> lo(number_of_pieces, Eigen::Vector3d::Constant(inf)), hi(number_of_pieces, -lo[0]);
  for(std::size_t i = 0; i < adj.number_of_faces; ++i)
    for(int k = 0; k < 3; ++k)
    {
      const Eigen::Vector3d c = corners(i, k);
      lo[piece[i]] = lo[piece[i]].cwiseMin(c);
      hi[piece[i]] = hi[piece[i]].cwiseMax(c);
    }
  std::vector<double> d(number_of_pieces, 0.);
  for(std::size_t p = 0; p < number_of_pieces; ++p)
    if(lo[p][0] <= hi[p][0]) d[p] = (hi[p] - lo[p]).norm();
  return d;
}

// The chain of each junction slot (3 per face; `none` for other slots): its junction edges
// joined at equal corner points, numbered from 0; and the length of each chain, each edge once.
template <typename Corners>
void junction_chains(const Face_adjacency& adj, const Corners& corners, std::vector<std::size_t>& chain,
                     std::vector<double>& chain_length, std::size_t none)
{
  typedef CGAL::Union_find<std::size_t> Chains;
  Chains chains;
  std::map<std::array<double, 3>, Chains::handle> point;
  auto handle_of = [&](const Eigen::Vector3d& c) {
    const std::array<double, 3> key = {{c[0], c[1], c[2]}};
    auto it = point.find(key);
    if(it == point.end()) it = point.emplace(key, chains.make_set(point.size())).first;
    return it->second;
  };
  std::vector<Chains::handle> first(3 * adj.number_of_faces);
  chain.assign(3 * adj.number_of_faces, none);
  for(std::size_t i = 0; i < adj.number_of_faces; ++i)
    for(int k = 0; k < 3; ++k)
      if(is_junction(adj, 3 * i + std::size_t(k)))
      {
        const Chains::handle a = handle_of(corners(i, k)), b = handle_of(corners(i, (k + 2) % 3));
        chains.unify_sets(a, b);
        first[3 * i + std::size_t(k)] = a;
        chain[3 * i + std::size_t(k)] = 0;
      }
  std::map<std::size_t, std::size_t> number; // root point -> chain
  std::map<std::pair<std::size_t, std::size_t>, double> edge; // by its end points -> length
  chain_length.clear();
  for(std::size_t s = 0; s < chain.size(); ++s)
    if(chain[s] != none)
    {
      chain[s] = number.emplace(*chains.find(first[s]), number.size()).first->second;
      const std::size_t i = s / 3;
      const int k = int(s % 3);
      const std::size_t a = *handle_of(corners(i, k)), b = *handle_of(corners(i, (k + 2) % 3));
      if(!edge.emplace(std::make_pair((std::min)(a, b), (std::max)(a, b)), 0.).second) continue;
      chain_length.resize(number.size(), 0.);
      chain_length[chain[s]] += slot_length(corners, i, k);
    }
  chain_length.resize(number.size(), 0.);
}

// Per piece: the fraction of the length of its face edges that lies on junctions (edges glued to
// two faces or more, see glue_coincident_border_edges()) of chains at least
// `minimum_junction_chain` of its diagonal long, each side of an edge counted once.
template <typename Corners>
std::vector<double> junction_length_fractions(const Face_adjacency& adj, const Corners& corners,
                                              const std::vector<std::size_t>& piece, std::size_t number_of_pieces)
{
  std::vector<double> junction(number_of_pieces, 0.), total(number_of_pieces, 0.);
  if(adj.junction.empty()) return junction;
  const std::size_t none = std::size_t(-1);
  std::vector<std::size_t> chain;
  std::vector<double> chain_length;
  junction_chains(adj, corners, chain, chain_length, none);
  for(std::size_t i = 0; i < adj.number_of_faces; ++i)
    for(int k = 0; k < 3; ++k) total[piece[i]] += slot_length(corners, i, k);
  const std::vector<double> diagonal = piece_diagonals(adj, corners, piece, number_of_pieces);
  for(std::size_t i = 0; i < adj.number_of_faces; ++i)
    for(int k = 0; k < 3; ++k)
    {
      const std::size_t c = chain[3 * i + std::size_t(k)];
      if(c != none && chain_length[c] >= minimum_junction_chain * diagonal[piece[i]])
        junction[piece[i]] += slot_length(corners, i, k);
    }
  for(std::size_t p = 0; p < number_of_pieces; ++p) junction[p] = total[p] > 0. ? junction[p] / total[p] : 0.;
  return junction;
}

// A volumetric part does not cross a concave crease: the faces of part v in a region other than
// v's home (the region holding most of v's area) go to the part whose home is that region and
// which covers most of it, if there is one. `volume_part` holds `none` where the volumetric
// stages did not decompose the face.
inline void keep_volume_parts_in_their_regions(const Face_adjacency& adj, const std::vector<std::size_t>& region,
                                               std::vector<std::size_t>& volume_part, std::size_t none)
{
  std::map<std::pair<std::size_t, std::size_t>, double> area; // (part, region) -> area
  for(std::size_t i = 0; i < volume_part.size(); ++i)
    if(volume_part[i] != none) area[std::make_pair(volume_part[i], region[i])] += adj.area[i];
  std::map<std::size_t, std::pair<double, std::size_t> > home; // part -> (area, region)
  for(const auto& e : area)
  {
    auto it = home.find(e.first.first);
    if(it == home.end() || e.second > it->second.first) home[e.first.first] = std::make_pair(e.second, e.first.second);
  }
  std::map<std::size_t, std::pair<double, std::size_t> > owner; // region -> (area, part)
  for(const auto& e : area)
  {
    if(home[e.first.first].second != e.first.second) continue;
    auto it = owner.find(e.first.second);
    if(it == owner.end() || e.second > it->second.first) owner[e.first.second] = std::make_pair(e.second, e.first.first);
  }
  for(std::size_t i = 0; i < volume_part.size(); ++i)
  {
    if(volume_part[i] == none || home[volume_part[i]].second == region[i]) continue;
    const auto it = owner.find(region[i]);
    if(it != owner.end()) volume_part[i] = it->second.second;
  }
}

// A stretch that one volumetric part covers apart from its largest stretch in the same region is
// a part of its own if its boundary is concave by at least this much on average (a limb ends at a
// concave root, the minima rule; the fingers a coarse grid cannot tell apart); with a smoother
// boundary it is a stray claim and stays with the largest stretch. Tuned on half A of the
// development shapes (see benchmark/Part_decomposition/RESULTS.md).
constexpr double minimum_stretch_concavity = 0.15;

// `stretch`: per face index, its edge-connected set of faces with the same `key`, numbered 0 to
// `n - 1`. Returns, per stretch, the stretch whose part it takes: itself if it is the largest of
// its key (by area; the first on a tie), if its key has no volumetric part (`key.second == 0`), or
// if its boundary is concave on average by `minimum_stretch_concavity` (`edge_concavity()`,
// weighted by length, `corner(i, k)` being the corners of face i); else the largest of its key.
template <typename Corner>
std::vector<std::size_t> stretch_owners(const Face_adjacency& adj, const Corner& corner,
                                        const std::vector<std::pair<std::size_t, std::size_t> >& key,
                                        const std::vector<std::size_t>& stretch, std::size_t n,
                                        const std::vector<std::size_t>& piece, const std::vector<int>& orientation)
{
  std::vector<double> area(n, 0.), length(n, 0.), concave(n, 0.);
  std::vector<std::size_t> first(n, adj.number_of_faces);
  for(std::size_t i = 0; i < adj.number_of_faces; ++i)
  {
    const std::size_t c = stretch[i];
    area[c] += adj.area[i];
    first[c] = (std::min)(first[c], i);
    for(int k = 0; k < 3; ++k)
    {
      const std::size_t j = adj.neighbor[3 * i + k];
      if(j == Face_adjacency::no_face || stretch[j] == c) continue;
      const double l = slot_length(corner, i, k);
      length[c] += l;
      concave[c] += l * edge_concavity(adj, i, k, orientation[piece[i]]);
    }
  }
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> largest; // key -> stretch
  for(std::size_t c = 0; c < n; ++c) // stretches are numbered by first face: the first wins ties
  {
    const auto it = largest.emplace(key[first[c]], c).first;
    if(area[c] > area[it->second]) it->second = c;
  }
  std::vector<std::size_t> owner(n);
  for(std::size_t c = 0; c < n; ++c)
  {
    const std::pair<std::size_t, std::size_t>& k = key[first[c]];
    const bool own = k.second == 0 || concave[c] >= minimum_stretch_concavity * length[c];
    owner[c] = own ? c : largest[k];
  }
  return owner;
}

// The parts of a mesh from its regions (per face index) and, where the volumetric stages ran,
// the volumetric part of each face (`volume_part`: `none` elsewhere; empty if they did not run):
// a face goes to the part of its (region, volumetric part), or of its region alone, except that
// the stretches of one volumetric part apart from its largest in the region are parts of their own
// where their boundary is concave (`stretch_owners()`; `piece` and `orientation` as in
// `Piece_segmentation`, `corner(i, k)` the corners of face i). Parts of area below `min_area` are
// then merged into a neighbour (`merge_small_patches()`), and all are numbered by smallest face
// index. `part` receives the part of each face; returns, per part, the volumetric part covering
// most of its area (smallest id on a tie), or `none`.
template <typename ConcurrencyTag, typename Corner>
std::vector<std::size_t> compose_parts(const Face_adjacency& adj, const Corner& corner,
                                       const std::vector<std::size_t>& region, const std::vector<std::size_t>& piece,
                                       const std::vector<int>& orientation, const std::vector<std::size_t>& volume_part,
                                       double min_area, std::vector<std::size_t>& part, std::size_t none)
{
  const std::size_t nf = adj.number_of_faces;
  const bool volumetric = !volume_part.empty();
  std::vector<std::pair<std::size_t, std::size_t> > key(nf);
  for(std::size_t i = 0; i < nf; ++i)
    key[i] = std::make_pair(region[i], volumetric && volume_part[i] != none ? volume_part[i] + 1 : 0);
  const std::size_t number_of_stretches =
    face_components<ConcurrencyTag>(adj, [&](std::size_t i, int k) { return key[i] == key[adj.neighbor[3 * i + k]]; },
                                    part);
  const std::vector<std::size_t> owner = stretch_owners(adj, corner, key, part, number_of_stretches, piece, orientation);
  for(std::size_t& p : part) p = owner[p];
  merge_small_patches(adj, part, number_of_stretches, min_area);
  const std::size_t count = renumber_by_first_face(part);

  std::vector<std::size_t> source(count, none);
  if(!volumetric) return source;
  std::vector<std::vector<std::pair<std::size_t, double> > > share(count);
  for(std::size_t i = 0; i < nf; ++i)
  {
    if(volume_part[i] == none) continue;
    auto& s = share[part[i]];
    auto it = std::find_if(s.begin(), s.end(), [&](const std::pair<std::size_t, double>& e) {
      return e.first == volume_part[i];
    });
    if(it == s.end()) s.emplace_back(volume_part[i], adj.area[i]);
    else it->second += adj.area[i];
  }
  for(std::size_t k = 0; k < count; ++k)
  {
    double best = -1.;
    for(const auto& e : share[k])
      if(e.second > best || (e.second == best && e.first < source[k])) { best = e.second; source[k] = e.first; }
  }
  return source;
}

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_PIECE_REGIONS_H
