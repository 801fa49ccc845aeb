// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_ORIENTED_SOUP_TO_MESH_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_ORIENTED_SOUP_TO_MESH_H

#include <CGAL/Part_decomposition/internal/toolbox/toolbox.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/tags.h>

#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

// The corners of a triangle soup: corner c = 3t + k is the directed edge from vertex k of triangle
// t to the next vertex of t.
struct Soup_corners
{
  const std::vector<std::array<std::size_t, 3> >& triangles;

  std::size_t size() const { return 3 * triangles.size(); }
  std::size_t source(std::size_t c) const { return triangles[c / 3][c % 3]; }
  std::size_t target(std::size_t c) const { return triangles[c / 3][(c % 3 + 1) % 3]; }
};

// The reverse of each corner (target(c) -> source(c)), `std::size_t(-1)` if none, of a soup of
// `number_of_points` points. It is found in the row of the corners leaving target(c) (compressed
// rows holding each corner's target, so that a row is scanned without reading the triangles).
inline std::vector<std::size_t> reverse_corners(const Soup_corners& corners, std::size_t number_of_points)
{
  const std::size_t nc = corners.size(), np = number_of_points, none = std::size_t(-1);
  std::vector<std::size_t> start(np + 1, 0), row_corner(nc), row_target(nc);
  for(std::size_t c = 0; c < nc; ++c) ++start[corners.source(c) + 1];
  for(std::size_t p = 0; p < np; ++p) start[p + 1] += start[p];
  {
    std::vector<std::size_t> fill(start.begin(), start.end() - 1);
    for(std::size_t c = 0; c < nc; ++c)
    {
      row_corner[fill[corners.source(c)]] = c;
      row_target[fill[corners.source(c)]++] = corners.target(c);
    }
  }
  // each corner on its own: in parallel when TBB is there (the search misses the cache at
  // every corner)
  std::vector<std::size_t> reverse(nc, none);
  for_each_range<CGAL::Parallel_if_available_tag>(nc, [&](std::size_t first, std::size_t last) {
    for(std::size_t c = first; c < last; ++c)
    {
      const std::size_t a = corners.source(c), b = corners.target(c);
      for(std::size_t k = start[b]; k < start[b + 1]; ++k)
        if(row_target[k] == a) reverse[c] = row_corner[k];
    }
  }, 4096);
  return reverse;
}

// Links the border halfedges, the opposites of the corners without reverse (from target(c) to
// source(c)), to each other and makes each the halfedge of its target, as add_face() does; `h`:
// the halfedge of each corner.
template <typename TriangleMesh>
void link_border_halfedges(const Soup_corners& corners, const std::vector<std::size_t>& reverse,
                           const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& vmap,
                           const std::vector<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor>& h,
                           TriangleMesh& tm)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  const std::size_t nc = corners.size(), none = std::size_t(-1);
  std::vector<typename GT::halfedge_descriptor> border_from(vmap.size(), GT::null_halfedge());
  for(std::size_t c = 0; c < nc; ++c)
    if(reverse[c] == none) border_from[corners.target(c)] = opposite(h[c], tm);
  for(std::size_t c = 0; c < nc; ++c)
    if(reverse[c] == none)
    {
      set_next(opposite(h[c], tm), border_from[corners.source(c)], tm);
      set_halfedge(vmap[corners.source(c)], opposite(h[c], tm), tm);
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
*/
template <typename TriangleMesh>
std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>
add_oriented_manifold_triangles(const std::vector<std::array<std::size_t, 3> >& triangles,
                                const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& vmap,
                                TriangleMesh& tm)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  const Soup_corners corners{triangles};
  const std::size_t nc = corners.size(), np = vmap.size(), none = std::size_t(-1);
  const std::vector<std::size_t> reverse = reverse_corners(corners, np);

  std::vector<halfedge_descriptor> h(nc);
  std::vector<typename GT::face_descriptor> face_of(triangles.size());
  std::vector<std::size_t> last_into(np, none); // the corner into each point of its last triangle
  for(std::size_t t = 0; t < triangles.size(); ++t)
  {
    for(std::size_t c = 3 * t; c < 3 * t + 3; ++c)
    {
      const std::size_t r = reverse[c];
      if(r != none && r < c)
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
      last_into[corners.target(c)] = c;
    }
  }
  for(std::size_t p = 0; p < np; ++p)
    if(last_into[p] != none) set_halfedge(vmap[p], h[last_into[p]], tm);
  link_border_halfedges(corners, reverse, vmap, h, tm);
  return face_of;
}

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_ORIENTED_SOUP_TO_MESH_H
