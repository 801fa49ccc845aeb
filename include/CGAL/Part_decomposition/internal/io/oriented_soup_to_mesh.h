// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_ORIENTED_SOUP_TO_MESH_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_ORIENTED_SOUP_TO_MESH_H

#include <CGAL/Part_decomposition/internal/io/oriented_manifold_soup.h>
#include <CGAL/Part_decomposition/internal/toolbox/toolbox.h>

#include <CGAL/Surface_mesh/Surface_mesh_fwd.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

constexpr std::size_t no_corner = std::size_t(-1);

// The reverse of each corner (target(c) -> source(c)), `no_corner` if none: the last one in the
// row of target(c).
inline std::vector<std::size_t> reverse_corners(const Soup_corners& corners, const Corner_rows& rows)
{
  // each corner on its own: in parallel when TBB is there (the search misses the cache at
  // every corner)
  std::vector<std::size_t> reverse(corners.size(), no_corner);
  for_each_range<CGAL::Parallel_if_available_tag>(corners.size(), [&](std::size_t first, std::size_t last) {
    for(std::size_t c = first; c < last; ++c)
    {
      const std::size_t a = corners.source(c), b = corners.target(c);
      for(std::size_t k = rows.start[b]; k < rows.start[b + 1]; ++k)
        if(rows.target[k] == a) reverse[c] = rows.corner[k];
    }
  }, 4096);
  return reverse;
}

// Whether an edge of the soup belongs to one triangle only: a corner with no reverse and no other
// corner in its direction. If not, the soup has no border point to weld.
inline bool has_edge_of_one_triangle(const Soup_corners& corners, const Corner_rows& rows,
                                     const std::vector<std::size_t>& reverse)
{
  for(std::size_t c = 0; c < corners.size(); ++c)
  {
    if(reverse[c] != no_corner) continue;
    const std::size_t a = corners.source(c), b = corners.target(c);
    bool twin = false;
    for(std::size_t k = rows.start[a]; k < rows.start[a + 1] && !twin; ++k)
      twin = rows.target[k] == b && rows.corner[k] != c;
    if(!twin) return true;
  }
  return false;
}

// What the reader needs to know of a soup's corners: their reverses (`reverse_corners()`), whether
// an edge belongs to one triangle only (then border points may need a weld) and whether the
// triangles form an oriented manifold (`is_oriented_manifold_soup()`).
struct Soup_topology
{
  std::vector<std::size_t> reverse;
  bool has_edge_of_one_triangle = false;
  bool oriented_manifold = false;
};

inline Soup_topology soup_topology(const std::vector<std::array<std::size_t, 3> >& triangles,
                                   std::size_t number_of_points)
{
  const Soup_corners corners{triangles};
  const Corner_rows rows(corners, number_of_points);
  Soup_topology t;
  t.reverse = reverse_corners(corners, rows);
  t.has_edge_of_one_triangle = has_edge_of_one_triangle(corners, rows, t.reverse);
  t.oriented_manifold = is_oriented_manifold_soup<CGAL::Parallel_if_available_tag>(corners, rows);
  return t;
}

// Makes the halfedge of each point's vertex that of the last corner into the point, as add_face()
// leaves an inner vertex (link_border_halfedges() then gives border vertices theirs); `h(c)`: the
// halfedge of corner c.
template <typename TriangleMesh, typename HalfedgeOfCorner>
void set_vertex_halfedges(const Soup_corners& corners,
                          const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& vmap,
                          const HalfedgeOfCorner& h, TriangleMesh& tm)
{
  std::vector<std::size_t> last_into(vmap.size(), no_corner);
  for(std::size_t c = 0; c < corners.size(); ++c) last_into[corners.target(c)] = c;
  for(std::size_t p = 0; p < vmap.size(); ++p)
    if(last_into[p] != no_corner) set_halfedge(vmap[p], h(last_into[p]), tm);
}

// Links the border halfedges, the opposites of the corners without reverse (from target(c) to
// source(c)), to each other and makes each the halfedge of its target, as add_face() does;
// `h(c)`: the halfedge of corner c.
template <typename TriangleMesh, typename HalfedgeOfCorner>
void link_border_halfedges(const Soup_corners& corners, const std::vector<std::size_t>& reverse,
                           const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& vmap,
                           const HalfedgeOfCorner& h, TriangleMesh& tm)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  if(std::find(reverse.begin(), reverse.end(), no_corner) == reverse.end()) return; // closed
  const std::size_t nc = corners.size();
  std::vector<typename GT::halfedge_descriptor> border_from(vmap.size(), GT::null_halfedge());
  for(std::size_t c = 0; c < nc; ++c)
    if(reverse[c] == no_corner) border_from[corners.target(c)] = opposite(h(c), tm);
  for(std::size_t c = 0; c < nc; ++c)
    if(reverse[c] == no_corner)
    {
      set_next(opposite(h(c), tm), border_from[corners.source(c)], tm);
      set_halfedge(vmap[corners.source(c)], opposite(h(c), tm), tm);
    }
}

/*
Adds the triangles of a consistently oriented manifold soup (`is_oriented_manifold_soup()`) to
`tm`, whose vertex of point i is `vmap[i]`, and returns the face of each triangle: the very
halfedge structure that CGAL::Euler::add_face() builds when the triangles are added one by one,
without its search around a vertex for every edge (half the time of reading a large mesh).

What add_face() leaves, triangle t = (v0, v1, v2) being face t:
- the edge of {a, b} is created by the first triangle holding a -> b or b -> a, in the order of the
  triangles and of their edges v0 v1, v1 v2, v2 v0; its first halfedge goes as in that triangle;
- halfedge(face t) is its halfedge v2 -> v0; the next of an inner halfedge is the following one
  in its triangle;
- each border vertex has one incoming and one outgoing border halfedge: the next of the one is
  the other, and halfedge(v) is the incoming one (add_face() always makes it so);
- halfedge(v) of an inner vertex is the halfedge into v of the last triangle holding v: before
  that triangle closed the fan of v, halfedge(v) was the border halfedge it covers, and add_face()
  keeps it when no border halfedge is left around v.
`reverse`: the reverse of each corner (`reverse_corners()`).
*/
template <typename TriangleMesh>
std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>
add_oriented_manifold_triangles(const std::vector<std::array<std::size_t, 3> >& triangles,
                                const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& vmap,
                                const std::vector<std::size_t>& reverse, TriangleMesh& tm)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  const Soup_corners corners{triangles};
  std::vector<halfedge_descriptor> h(corners.size());
  std::vector<typename GT::face_descriptor> face_of(triangles.size());
  for(std::size_t t = 0; t < triangles.size(); ++t)
  {
    for(std::size_t c = 3 * t; c < 3 * t + 3; ++c)
    {
      const std::size_t r = reverse[c];
      if(r != no_corner && r < c)
      {
        h[c] = opposite(h[r], tm);
        continue;
      }
      h[c] = halfedge(add_edge(tm), tm);
      set_target(h[c], vmap[corners.target(c)], tm);
      set_target(opposite(h[c], tm), vmap[corners.source(c)], tm);
      set_face(opposite(h[c], tm), GT::null_face(), tm);
    }
    const auto f = add_face(tm);
    face_of[t] = f;
    set_halfedge(f, h[3 * t + 2], tm);
    for(std::size_t c = 3 * t; c < 3 * t + 3; ++c)
    {
      set_face(h[c], f, tm);
      set_next(h[c], h[c + 1 < 3 * t + 3 ? c + 1 : 3 * t], tm);
    }
  }
  const auto halfedge_of = [&](std::size_t c) { return h[c]; };
  set_vertex_halfedges(corners, vmap, halfedge_of, tm);
  link_border_halfedges(corners, reverse, vmap, halfedge_of, tm);
  return face_of;
}

// The same structure in a `Surface_mesh` without faces or edges, written in parallel: its elements
// are indices, so edge e (numbered by the corner that creates it) is halfedges 2e and 2e + 1 and
// face t is triangle t, and each corner writes its own halfedges (a third of the time of reading
// a large mesh, one by one).
template <typename P>
std::vector<typename Surface_mesh<P>::Face_index>
add_oriented_manifold_triangles(const std::vector<std::array<std::size_t, 3> >& triangles,
                                const std::vector<typename Surface_mesh<P>::Vertex_index>& vmap,
                                const std::vector<std::size_t>& reverse, Surface_mesh<P>& tm)
{
  typedef Surface_mesh<P> Mesh;
  typedef typename Mesh::Halfedge_index Halfedge_index;
  typedef typename Mesh::Face_index Face_index;
  if(tm.number_of_edges() != 0 || tm.number_of_faces() != 0 || tm.has_garbage())
    return add_oriented_manifold_triangles<Mesh>(triangles, vmap, reverse, tm);
  const Soup_corners corners{triangles};
  const std::size_t nc = corners.size(), nt = triangles.size();
  const auto creates_edge = [&](std::size_t c) { return reverse[c] == no_corner || reverse[c] > c; };
  std::vector<std::size_t> edge(nc);
  std::size_t ne = 0;
  for(std::size_t c = 0; c < nc; ++c) edge[c] = creates_edge(c) ? ne++ : edge[reverse[c]];
  const auto halfedge_of = [&](std::size_t c) {
    return Halfedge_index(typename Mesh::size_type(2 * edge[c] + (creates_edge(c) ? 0 : 1)));
  };
  tm.resize(tm.number_of_vertices(), typename Mesh::size_type(ne), typename Mesh::size_type(nt));
  std::vector<Face_index> face_of(nt);
  for_each_range<CGAL::Parallel_if_available_tag>(nt, [&](std::size_t first, std::size_t last) {
    for(std::size_t t = first; t < last; ++t)
    {
      face_of[t] = Face_index(typename Mesh::size_type(t));
      tm.set_halfedge(face_of[t], halfedge_of(3 * t + 2));
      for(std::size_t c = 3 * t; c < 3 * t + 3; ++c)
      {
        const Halfedge_index h = halfedge_of(c);
        tm.set_target(h, vmap[corners.target(c)]);
        tm.set_face(h, face_of[t]);
        tm.set_next(h, halfedge_of(c + 1 < 3 * t + 3 ? c + 1 : 3 * t));
        if(reverse[c] == no_corner)
        {
          tm.set_target(tm.opposite(h), vmap[corners.source(c)]);
          tm.set_face(tm.opposite(h), Mesh::null_face());
        }
      }
    }
  }, 4096);
  set_vertex_halfedges(corners, vmap, halfedge_of, tm);
  link_border_halfedges(corners, reverse, vmap, halfedge_of, tm);
  return face_of;
}

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_ORIENTED_SOUP_TO_MESH_H
