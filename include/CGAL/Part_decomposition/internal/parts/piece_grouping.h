// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_PIECE_GROUPING_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_PIECE_GROUPING_H

// Which pieces of an assembly a person names with the piece they sit on: crumbs, and pieces
// repeated in a pattern (keys, buttons, slats, vents); and which plates, side by side, are one.
//
// Inputs: per piece its box (`Part_box`: area, half extents) and number of faces; the pairs of
// pieces whose surfaces touch (a < b).
// Output: per piece the piece it is grouped with (itself if none). Every group is a tree of
// contacts whose root is its largest piece.

#include <CGAL/Part_decomposition/internal/parts/part_merging.h>
#include <CGAL/Part_decomposition/internal/toolbox/toolbox.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

// A crumb: at most this fraction of the surface's area, and the piece it touches at least
// `crumb_host_ratio` times as large.
constexpr double crumb_area_fraction = 0.0002;
constexpr double crumb_host_ratio = 10.;
// A pattern: at least `pattern_count` congruent pieces (same number of faces, areas and box extents
// within `congruence_tolerance`), each at most `pattern_area_fraction` of the surface and touching a
// piece at least `pattern_host_ratio` times as large, its host (the largest such piece). The hosts
// may differ: the slats of several racks are one pattern. The other pieces touching a host that are
// no larger than `pattern_size_ratio` times its members join the pattern (keys of other widths).
constexpr std::size_t pattern_count = 20;
constexpr double congruence_tolerance = 0.05;
constexpr double pattern_area_fraction = 0.005;
constexpr double pattern_host_ratio = 3.;
constexpr double pattern_size_ratio = 2.;

// Tiles: two flat pieces in contact (smallest half extent at most `tile_flatness` times the middle
// one), each at most `tile_area_fraction` of the surface, whose union's box is as thin as the
// thicker of them (within `tile_thickness_slack`) and holds the volume of their two boxes within
// `tile_volume_tolerance`, while at least `tile_side_by_side` times the larger box (neither lies in
// the other's box): the rows of a keyboard, the boards of a panel, laid side by side in one plate.
constexpr double tile_area_fraction = 0.015;
constexpr double tile_volume_tolerance = 0.05;
constexpr double tile_flatness = 0.25;
constexpr double tile_thickness_slack = 1.2;
constexpr double tile_side_by_side = 1.2;

// The half extents of a box, smallest first.
inline std::array<double, 3> sorted_half_extents(const Part_box& b)
{
  std::array<double, 3> h = {{b.half[0], b.half[1], b.half[2]}};
  std::sort(h.begin(), h.end());
  return h;
}

inline bool is_flat(const Part_box& b)
{
  const std::array<double, 3> h = sorted_half_extents(b);
  return h[0] <= tile_flatness * h[1];
}

// Whether pieces `a` and `b`, in contact, tile one plate; `thickness`: the least half extent of a
// box's volume (as in the merge costs).
inline bool tile_one_plate(const Part_box& a, const Part_box& b, double total_area, double thickness)
{
  if(a.area > tile_area_fraction * total_area || b.area > tile_area_fraction * total_area || !is_flat(a) || !is_flat(b))
    return false;
  const Part_box u = merge_boxes(a, b);
  const double va = box_volume(a, thickness), vb = box_volume(b, thickness), vu = box_volume(u, thickness);
  if(std::abs(vu - va - vb) > tile_volume_tolerance * (va + vb) || vu < tile_side_by_side * (std::max)(va, vb))
    return false;
  return u.half.minCoeff() <= tile_thickness_slack * (std::max)(a.half.minCoeff(), b.half.minCoeff());
}

// The classes of congruent pieces: per piece its class, the first piece of the class.
inline std::vector<std::size_t> congruence_classes(const std::vector<Part_box>& box,
                                                   const std::vector<std::size_t>& faces)
{
  const std::size_t n = box.size();
  std::vector<std::size_t> order(n), cls(n);
  for(std::size_t p = 0; p < n; ++p) order[p] = cls[p] = p;
  std::vector<std::array<double, 3> > extent(n);
  for(std::size_t p = 0; p < n; ++p) extent[p] = sorted_half_extents(box[p]);
  // sorted by face count then area: congruent pieces are neighbours in this order
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return faces[a] != faces[b] ? faces[a] < faces[b] : (box[a].area != box[b].area ? box[a].area < box[b].area : a < b);
  });
  auto congruent = [&](std::size_t a, std::size_t b) {
    if(faces[a] != faces[b]) return false;
    const double scale = (std::max)(extent[a][2], extent[b][2]);
    if(std::abs(box[a].area - box[b].area) > congruence_tolerance * (std::max)(box[a].area, box[b].area)) return false;
    for(int d = 0; d < 3; ++d)
      if(std::abs(extent[a][d] - extent[b][d]) > congruence_tolerance * scale) return false;
    return true;
  };
  for(std::size_t i = 1; i < n; ++i)
    if(congruent(order[i - 1], order[i])) cls[order[i]] = cls[order[i - 1]];
  return cls;
}

// The piece each crumb (`crumb_area_fraction`) joins: the smallest of the touching pieces large
// enough, the most local one (a key's plate rather than the case holding it). `none` if none.
inline std::vector<std::size_t> crumb_hosts(const std::vector<Part_box>& box,
                                            const std::vector<std::pair<std::size_t, std::size_t> >& contacts,
                                            double total_area)
{
  const std::size_t none = (std::numeric_limits<std::size_t>::max)();
  std::vector<std::size_t> host(box.size(), none);
  for(const std::pair<std::size_t, std::size_t>& c : contacts)
    for(int side = 0; side < 2; ++side)
    {
      const std::size_t p = side ? c.second : c.first, h = side ? c.first : c.second;
      if(box[p].area > crumb_area_fraction * total_area || box[h].area < crumb_host_ratio * box[p].area) continue;
      if(host[p] == none || box[h].area < box[host[p]].area) host[p] = h;
    }
  return host;
}

// The piece each member of a pattern, or piece of a pattern's size on its host, joins; `none` if
// none.
inline std::vector<std::size_t> pattern_hosts(const std::vector<Part_box>& box, const std::vector<std::size_t>& faces,
                                              const std::vector<std::pair<std::size_t, std::size_t> >& contacts,
                                              double total_area)
{
  const std::size_t none = (std::numeric_limits<std::size_t>::max)(), n = box.size();
  const std::vector<std::size_t> cls = congruence_classes(box, faces);
  // whether p is small enough to join a pattern on h
  auto may_sit_on = [&](std::size_t p, std::size_t h) {
    return box[p].area <= pattern_area_fraction * total_area && box[h].area >= pattern_host_ratio * box[p].area;
  };
  // per small piece, the largest piece it touches that is large enough
  std::vector<std::size_t> candidate(n, none);
  for(const std::pair<std::size_t, std::size_t>& c : contacts)
    for(int side = 0; side < 2; ++side)
    {
      const std::size_t p = side ? c.second : c.first, h = side ? c.first : c.second;
      if(may_sit_on(p, h) && (candidate[p] == none || box[h].area > box[candidate[p]].area)) candidate[p] = h;
    }
  std::vector<std::size_t> members(n, 0); // per class, its members with a candidate host
  for(std::size_t p = 0; p < n; ++p)
    if(candidate[p] != none) ++members[cls[p]];
  std::vector<std::size_t> host(n, none);
  std::vector<double> pattern_area(n, 0.); // per host, its largest pattern member
  for(std::size_t p = 0; p < n; ++p)
    if(candidate[p] != none && members[cls[p]] >= pattern_count)
    {
      host[p] = candidate[p];
      pattern_area[host[p]] = (std::max)(pattern_area[host[p]], box[p].area);
    }
  for(const std::pair<std::size_t, std::size_t>& c : contacts)
    for(int side = 0; side < 2; ++side)
    {
      const std::size_t p = side ? c.second : c.first, h = side ? c.first : c.second;
      if(host[p] == none && pattern_area[p] == 0. && box[p].area <= pattern_size_ratio * pattern_area[h] &&
         may_sit_on(p, h))
        host[p] = h;
    }
  return host;
}

// Per piece, the root of its group (itself if none), its largest piece: patterns join their host,
// crumbs the smallest large enough piece they touch, and tiles one another.
inline std::vector<std::size_t> grouped_pieces(const std::vector<Part_box>& box, const std::vector<std::size_t>& faces,
                                               const std::vector<std::pair<std::size_t, std::size_t> >& contacts,
                                               double thickness)
{
  const std::size_t none = (std::numeric_limits<std::size_t>::max)(), n = box.size();
  double total = 0.;
  for(const Part_box& b : box) total += b.area;
  const std::vector<std::size_t> host = pattern_hosts(box, faces, contacts, total);
  const std::vector<std::size_t> crumb = crumb_hosts(box, contacts, total);
  Index_sets groups(n);
  for(std::size_t p = 0; p < n; ++p)
    if(host[p] != none || crumb[p] != none) groups.unite(p, host[p] != none ? host[p] : crumb[p]);
  for(const std::pair<std::size_t, std::size_t>& c : contacts)
    if(tile_one_plate(box[c.first], box[c.second], total, thickness)) groups.unite(c.first, c.second);
  std::vector<std::size_t> largest(n, none); // per set, by its smallest index
  for(std::size_t p = 0; p < n; ++p)
  {
    std::size_t& r = largest[groups.find(p)];
    if(r == none || box[p].area > box[r].area) r = p;
  }
  std::vector<std::size_t> root(n);
  for(std::size_t p = 0; p < n; ++p) root[p] = largest[groups.find(p)];
  return root;
}

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_PIECE_GROUPING_H
