// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_PART_MERGING_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_PART_MERGING_H

// The agglomerative merge tree of `build_part_hierarchy()`: boxes on principal axes, the contacts
// between parts, and the greedy merges.

#include <CGAL/Part_decomposition/internal/toolbox/face_adjacency.h>
#include <CGAL/Part_decomposition/internal/parts/merge_kind.h>

#include <CGAL/hilbert_sort.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/property_map.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <queue>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

// The box of a set of triangles on the principal axes of their area moments: what one box-like
// superquadric of them covers. Moments are taken relative to a common origin, so that they add.
struct Part_box
{
  double area = 0.;
  Eigen::Vector3d first = Eigen::Vector3d::Zero();  // integral of x over the surface
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero(); // integral of x x^T over the surface
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  Eigen::Vector3d half = Eigen::Vector3d::Zero();
};

// Adds the moments of triangle (a, b, c), corners relative to the box's origin.
inline void add_triangle_moments(Part_box& box, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                 const Eigen::Vector3d& c)
{
  const double area = 0.5 * (b - a).cross(c - a).norm();
  const Eigen::Vector3d s = a + b + c;
  box.area += area;
  box.first += area / 3. * s;
  box.second += area / 12. * (a * a.transpose() + b * b.transpose() + c * c.transpose() + s * s.transpose());
}

// The principal axes (a rotation) and mean of the moments; the identity and `fallback` for a
// surface of zero area.
inline void principal_axes(const Part_box& box, const Eigen::Vector3d& fallback, Eigen::Matrix3d& axes,
                           Eigen::Vector3d& mean)
{
  mean = fallback;
  Eigen::Matrix3d cov = Eigen::Matrix3d::Identity();
  if(box.area > 0.)
  {
    mean = box.first / box.area;
    cov = box.second / box.area - mean * mean.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  axes = eig.eigenvectors();
  if(axes.determinant() < 0) axes.col(0) = -axes.col(0);
}

// The centre and half extents of `points` on each of `axes` (through `mean`), in one pass over
// the points.
inline void extents_on_axes(const std::vector<Eigen::Matrix3d>& axes, const Eigen::Vector3d& mean,
                            const std::vector<Eigen::Vector3d>& points, std::vector<Eigen::Vector3d>& center,
                            std::vector<Eigen::Vector3d>& half)
{
  const std::size_t n = axes.size();
  std::vector<Eigen::Vector3d> lo(n, Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity()));
  std::vector<Eigen::Vector3d> hi(n, Eigen::Vector3d::Constant(-std::numeric_limits<double>::infinity()));
  for(const Eigen::Vector3d& p : points)
    for(std::size_t c = 0; c < n; ++c)
    {
      const Eigen::Vector3d l = axes[c].transpose() * (p - mean);
      lo[c] = lo[c].cwiseMin(l);
      hi[c] = hi[c].cwiseMax(l);
    }
  center.resize(n);
  half.resize(n);
  for(std::size_t c = 0; c < n; ++c)
  {
    if(points.empty()) lo[c] = hi[c] = Eigen::Vector3d::Zero();
    half[c] = (hi[c] - lo[c]) / 2.;
    center[c] = mean + axes[c] * ((hi[c] + lo[c]) / 2.);
  }
}

// Sets the axes and extents of `box` to the smallest box of `points` on the principal axes of its
// moments, on the coordinate axes, or on one of `more_axes`: principal axes are arbitrary where
// moments are equal (a square section), and man-made parts are often aligned.
inline void fit_box_to_points(Part_box& box, const std::vector<Eigen::Vector3d>& points,
                              const std::vector<Eigen::Matrix3d>& more_axes = std::vector<Eigen::Matrix3d>())
{
  // the mean of the points stands for the centroid of a surface of zero area only
  Eigen::Vector3d fallback = Eigen::Vector3d::Zero();
  if(!(box.area > 0.))
    for(const Eigen::Vector3d& p : points) fallback += p / double(points.size());
  Eigen::Vector3d mean;
  Eigen::Matrix3d principal;
  principal_axes(box, fallback, principal, mean);
  std::vector<Eigen::Matrix3d> candidates(1, principal);
  candidates.push_back(Eigen::Matrix3d::Identity());
  candidates.insert(candidates.end(), more_axes.begin(), more_axes.end());
  std::vector<Eigen::Vector3d> center, half;
  extents_on_axes(candidates, mean, points, center, half);
  double best = std::numeric_limits<double>::infinity();
  for(std::size_t c = 0; c < candidates.size(); ++c)
  {
    // a flat box still has a size: its two largest extents break the tie
    const double floor = 1e-6 * half[c].maxCoeff();
    const double volume = (half[c][0] + floor) * (half[c][1] + floor) * (half[c][2] + floor);
    if(volume < best * (1. - 1e-9))
    {
      best = volume;
      box.axes = candidates[c];
      box.center = center[c];
      box.half = half[c];
    }
  }
}

inline std::array<Eigen::Vector3d, 8> box_corners(const Part_box& b)
{
  std::array<Eigen::Vector3d, 8> c;
  for(int k = 0; k < 8; ++k)
    c[k] = b.center + b.axes * Eigen::Vector3d((k & 1) ? b.half[0] : -b.half[0], (k & 2) ? b.half[1] : -b.half[1],
                                               (k & 4) ? b.half[2] : -b.half[2]);
  return c;
}

// The box of the union of two boxes' surfaces: summed moments, extents over the 16 corners (a box
// that contains both children, tight when the children are boxes of the same axes).
inline Part_box merge_boxes(const Part_box& a, const Part_box& b)
{
  Part_box u;
  u.area = a.area + b.area;
  u.first = a.first + b.first;
  u.second = a.second + b.second;
  std::vector<Eigen::Vector3d> corners;
  corners.reserve(16);
  for(const Eigen::Vector3d& c : box_corners(a)) corners.push_back(c);
  for(const Eigen::Vector3d& c : box_corners(b)) corners.push_back(c);
  fit_box_to_points(u, corners, {a.axes, b.axes});
  return u;
}

// The volume of a box whose half extents are at least `floor` (a flat part still has a volume).
inline double box_volume(const Part_box& b, double floor)
{
  double v = 1.;
  for(int i = 0; i < 3; ++i) v *= 2. * (std::max)(b.half[i], floor);
  return v;
}

// The parameters of the merge order.
struct Merge_parameters
{
  double contact_distance = 0.; // surfaces of two pieces closer than this touch
  double thickness = 0.;        // the smallest half extent of a box's volume
  double crease_weight = 0.;    // weight of the concavity of the common boundary in the cost
  // From the first merge between parts that costs at least `attachment_from` (the default parts'
  // maximum_merge_cost) on, merges between parts add `attachment_weight` times the area fraction
  // of the smaller part: above the default parts, small parts join the part they are attached to
  // before large parts merge, and the merges below keep their order.
  double attachment_from = std::numeric_limits<double>::infinity();
  double attachment_weight = 0.;
  // Above the default parts, a merge within a piece that costs at least this much waits with the
  // contacts: two large parts of one piece (a lid and its base joined by a hinge) are not a part
  // attached to another.
  double within_piece_limit = std::numeric_limits<double>::infinity();
};

// The pairs of leaves of different pieces whose surfaces come within about `distance` of each
// other: points are spread over every face at most `distance` apart and hashed into cells of
// that size; leaves in the same or adjacent cells touch. Returns sorted unique pairs (a < b).
template <typename Corner>
std::vector<std::pair<std::size_t, std::size_t> >
touching_leaves(std::size_t number_of_faces, const Corner& corner, const std::vector<std::size_t>& leaf,
                const std::vector<std::size_t>& piece, double distance)
{
  std::vector<std::pair<std::uint64_t, std::size_t> > cells; // (cell key, leaf)
  const Eigen::Vector3d origin = corner(0, 0);
  auto key = [&](const Eigen::Vector3d& p) {
    std::uint64_t k = 0;
    for(int d = 0; d < 3; ++d)
    {
      const double c = std::floor((p[d] - origin[d]) / distance) + double(1 << 20);
      k = (k << 21) | std::uint64_t((std::min)((std::max)(c, 0.), double((1 << 21) - 1)));
    }
    return k;
  };
  std::vector<std::uint64_t> face_cells;
  for(std::size_t i = 0; i < number_of_faces; ++i)
  {
    const Eigen::Vector3d a = corner(i, 0), b = corner(i, 1), c = corner(i, 2);
    const double longest = (std::max)({(b - a).norm(), (c - b).norm(), (a - c).norm()});
    // at most 64 steps per edge: larger faces are rare and their corners and centre still count
    const int n = int((std::min)(64., std::ceil(longest / distance)));
    face_cells.clear();
    for(int u = 0; u <= n; ++u)
      for(int v = 0; u + v <= n; ++v)
      {
        const double s = n > 0 ? double(u) / n : 1. / 3., t = n > 0 ? double(v) / n : 1. / 3.;
        face_cells.push_back(key(a + s * (b - a) + t * (c - a)));
      }
    // a face's samples share cells: fewer entries to sort below
    std::sort(face_cells.begin(), face_cells.end());
    face_cells.erase(std::unique(face_cells.begin(), face_cells.end()), face_cells.end());
    for(std::uint64_t k : face_cells) cells.emplace_back(k, leaf[i]);
  }
  std::sort(cells.begin(), cells.end());
  cells.erase(std::unique(cells.begin(), cells.end()), cells.end());

  // the first entry of each cell, by key
  std::unordered_map<std::uint64_t, std::size_t> first;
  first.reserve(cells.size());
  for(std::size_t c = 0; c < cells.size(); ++c) first.emplace(cells[c].first, c);
  auto leaves_of = [&](std::size_t c) {
    std::size_t e = c;
    while(e < cells.size() && cells[e].first == cells[c].first) ++e;
    return std::make_pair(c, e);
  };
  std::vector<std::pair<std::size_t, std::size_t> > pairs;
  const std::uint64_t mask = (std::uint64_t(1) << 21) - 1;
  for(std::size_t c = 0; c < cells.size();)
  {
    const std::uint64_t k = cells[c].first;
    const std::pair<std::size_t, std::size_t> here = leaves_of(c);
    c = here.second;
    for(int dx = -1; dx <= 1; ++dx)
      for(int dy = -1; dy <= 1; ++dy)
        for(int dz = -1; dz <= 1; ++dz)
        {
          const std::uint64_t x = ((k >> 42) & mask) + dx, y = ((k >> 21) & mask) + dy, z = (k & mask) + dz;
          if(x > mask || y > mask || z > mask) continue;
          const std::uint64_t nk = (x << 42) | (y << 21) | z;
          if(nk < k) continue; // each pair of cells once
          const auto it = first.find(nk);
          if(it == first.end()) continue;
          const std::pair<std::size_t, std::size_t> there = leaves_of(it->second);
          for(std::size_t i = here.first; i < here.second; ++i)
            for(std::size_t j = there.first; j < there.second; ++j)
            {
              const std::size_t a = cells[i].second, b = cells[j].second;
              if(a != b && piece[a] != piece[b]) pairs.emplace_back((std::min)(a, b), (std::max)(a, b));
            }
        }
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

// Greedy agglomeration of the leaves into a binary tree, by kind of merge (same subgroup, same
// group, attached, same piece, contact, none) then by cost. `subgroup` (nested in `group`), `group`
// and `piece` are per leaf (`none`: none); `attached` flags the leaves of pieces grouped with a
// larger piece, whose `piece` is that of the larger piece. `link()` joins the leaves that share an
// edge or touch.
class Part_agglomeration
{
public:
  static constexpr std::size_t none = (std::numeric_limits<std::size_t>::max)();

  Part_agglomeration(std::vector<Part_box> boxes, std::vector<std::size_t> subgroup, std::vector<std::size_t> group,
                     std::vector<std::size_t> piece, std::vector<std::uint8_t> attached, const Merge_parameters& p,
                     double total_volume)
    : m_box(std::move(boxes)), m_subgroup(std::move(subgroup)), m_group(std::move(group)), m_piece(std::move(piece)),
      m_attached(std::move(attached)), m_p(p), m_volume((std::max)(total_volume, std::numeric_limits<double>::min()))
  {
    const std::size_t n = m_box.size();
    m_links.resize(n);
    m_alive.assign(n, 1);
    m_children.assign(n, {{none, none}});
    m_kind.assign(n, Merge_kind::NONE);
    m_cost.assign(n, 0.);
    double area = 0.;
    for(const Part_box& b : m_box) area += b.area;
    m_area = (std::max)(area, std::numeric_limits<double>::min());
  }

  // `length`: of the common boundary; `concave`: its length weighted by concavity (0 to 1).
  void link(std::size_t a, std::size_t b, bool contact, double length = 0., double concave = 0.)
  {
    add_link(a, Link{b, contact, length, concave});
    add_link(b, Link{a, contact, length, concave});
  }

  // Merges down to one node; returns the number of nodes.
  std::size_t run()
  {
    for(std::size_t a = 0; a < m_links.size(); ++a)
      for(const Link& l : m_links[a])
        if(a < l.node) push(a, l);
    std::size_t alive = m_box.size();
    Merge_kind phase = Merge_kind::SAME_PRIMITIVE;
    while(alive > 1)
    {
      while(!m_queue.empty() && (!m_alive[m_queue.top().a] || !m_alive[m_queue.top().b])) m_queue.pop();
      if(m_queue.empty() || m_queue.top().rank > phase)
      {
        complete(phase);
        if(phase != Merge_kind::NO_CONTACT) phase = Merge_kind(int(phase) + 1);
        continue;
      }
      if(!m_above_default && ends_default_parts(m_queue.top()))
      {
        m_above_default = true;
        recost_queue();
        continue;
      }
      const Entry e = m_queue.top();
      m_queue.pop();
      merge(e);
      --alive;
    }
    return m_box.size();
  }

  const std::vector<Part_box>& boxes() const { return m_box; }
  const std::vector<std::array<std::size_t, 2> >& children() const { return m_children; }
  const std::vector<Merge_kind>& kinds() const { return m_kind; }
  const std::vector<double>& costs() const { return m_cost; }
  const std::vector<std::size_t>& groups() const { return m_group; }

private:
  struct Link
  {
    std::size_t node;
    bool contact;
    double length, concave; // of the common boundary
  };
  struct Entry
  {
    Merge_kind kind;
    double cost;
    std::size_t a, b;
    Merge_kind rank; // the kind of merge it waits with
    bool operator>(const Entry& o) const
    {
      if(rank != o.rank) return rank > o.rank;
      if(cost != o.cost) return cost > o.cost;
      if(a != o.a) return a > o.a;
      return b > o.b;
    }
  };

  void add_link(std::size_t a, const Link& link)
  {
    for(Link& l : m_links[a])
      if(l.node == link.node)
      {
        l.contact = l.contact || link.contact;
        l.length += link.length;
        l.concave += link.concave;
        return;
      }
    m_links[a].push_back(link);
  }

  Merge_kind kind_of(std::size_t a, std::size_t b, bool contact) const
  {
    if(m_subgroup[a] != none && m_subgroup[a] == m_subgroup[b]) return Merge_kind::SAME_PRIMITIVE;
    if(m_group[a] != none && m_group[a] == m_group[b]) return Merge_kind::SAME_PART;
    if(m_piece[a] != none && m_piece[a] == m_piece[b])
      return m_attached[a] || m_attached[b] ? Merge_kind::ATTACHED : Merge_kind::SAME_PIECE;
    return contact ? Merge_kind::CONTACT : Merge_kind::NO_CONTACT;
  }

  // The empty volume one box of the union adds to the two boxes, plus the concavity of the
  // common boundary, plus the size of the smaller part for a merge of `kind` (between parts) that
  // costs at least Merge_parameters::attachment_from or comes above the default parts.
  double cost(std::size_t a, const Link& l, Merge_kind kind) const
  {
    const std::size_t b = l.node;
    const Part_box u = merge_boxes(m_box[a], m_box[b]);
    const double added = box_volume(u, m_p.thickness) - box_volume(m_box[a], m_p.thickness) -
                         box_volume(m_box[b], m_p.thickness);
    const double crease = l.length > 0. ? l.concave / l.length : 0.;
    const double c = (std::max)(added, 0.) / m_volume + m_p.crease_weight * crease;
    if(int(kind) < int(Merge_kind::SAME_PIECE) || (c < m_p.attachment_from && !m_above_default)) return c;
    return c + m_p.attachment_weight * (std::min)(m_box[a].area, m_box[b].area) / m_area;
  }

  // Whether merge `e` is the first above the default parts: between parts, not within one, and
  // where Part_hierarchy::level_below_cost() stops.
  bool ends_default_parts(const Entry& e) const
  {
    return e.kind >= Merge_kind::SAME_PIECE && merge_beyond_default_parts(e.kind, e.cost, m_p.attachment_from);
  }

  // The merges waiting when the default parts are reached, with the costs of the merges above them.
  void recost_queue()
  {
    std::vector<Entry> entries;
    for(; !m_queue.empty(); m_queue.pop())
      if(m_alive[m_queue.top().a] && m_alive[m_queue.top().b]) entries.push_back(m_queue.top());
    for(Entry& e : entries)
    {
      for(const Link& l : m_links[e.a])
        if(l.node == e.b) e.cost = cost(e.a, l, e.kind);
      e.rank = rank_of(e.kind, e.cost);
      m_queue.push(e);
    }
  }

  Merge_kind rank_of(Merge_kind kind, double cost) const
  {
    const bool waits = m_above_default && kind == Merge_kind::SAME_PIECE && cost >= m_p.within_piece_limit;
    return waits ? Merge_kind::CONTACT : kind;
  }

  void push(std::size_t a, const Link& l)
  {
    const Merge_kind kind = kind_of(a, l.node, l.contact);
    const double c = cost(a, l, kind);
    m_queue.push(Entry{kind, c, (std::min)(a, l.node), (std::max)(a, l.node), rank_of(kind, c)});
  }

  // Links the living nodes that must merge before the merges of the next kind but are not
  // linked: those of one subgroup, of one group, of one piece, or all (`NO_CONTACT`).
  void complete(Merge_kind phase)
  {
    // contacts are found, never completed; attached pieces are linked to their host by contacts
    if(phase == Merge_kind::CONTACT || phase == Merge_kind::ATTACHED) return;
    std::vector<std::pair<std::size_t, std::size_t> > members; // (set, node)
    for(std::size_t n = 0; n < m_box.size(); ++n)
    {
      if(!m_alive[n]) continue;
      const std::size_t set = phase == Merge_kind::SAME_PRIMITIVE ? m_subgroup[n]
                              : phase == Merge_kind::SAME_PART ? m_group[n]
                              : phase == Merge_kind::SAME_PIECE ? m_piece[n] : 0;
      if(set != none) members.emplace_back(set, n);
    }
    std::sort(members.begin(), members.end());
    for(std::size_t i = 0; i < members.size();)
    {
      std::size_t j = i;
      std::vector<std::size_t> set;
      for(; j < members.size() && members[j].first == members[i].first; ++j) set.push_back(members[j].second);
      link_set(set);
      i = j;
    }
  }

  // Links a set of nodes along their Hilbert order (all pairs if few), so that it is connected.
  void link_set(std::vector<std::size_t>& set)
  {
    if(set.size() < 2) return;
    constexpr std::size_t all_pairs = 32, window = 4;
    if(set.size() > all_pairs)
    {
      typedef CGAL::Simple_cartesian<double>::Point_3 P;
      std::vector<P> centers;
      for(std::size_t n : set) centers.emplace_back(m_box[n].center[0], m_box[n].center[1], m_box[n].center[2]);
      std::vector<std::size_t> order(set.size());
      for(std::size_t i = 0; i < order.size(); ++i) order[i] = i;
      typedef CGAL::Pointer_property_map<P>::type Map;
      CGAL::hilbert_sort(order.begin(), order.end(),
                         CGAL::Spatial_sort_traits_adapter_3<CGAL::Simple_cartesian<double>, Map>(
                           CGAL::make_property_map(centers)));
      std::vector<std::size_t> sorted;
      for(std::size_t i : order) sorted.push_back(set[i]);
      set.swap(sorted);
    }
    for(std::size_t i = 0; i < set.size(); ++i)
      for(std::size_t j = i + 1; j < set.size() && (set.size() <= all_pairs || j <= i + window); ++j)
      {
        bool linked = false;
        for(const Link& l : m_links[set[i]]) linked = linked || l.node == set[j];
        if(linked) continue;
        link(set[i], set[j], false);
        push(set[i], m_links[set[i]].back());
      }
  }

  void merge(const Entry& e)
  {
    const std::size_t m = m_box.size();
    m_box.push_back(merge_boxes(m_box[e.a], m_box[e.b]));
    m_subgroup.push_back(m_subgroup[e.a] == m_subgroup[e.b] ? m_subgroup[e.a] : none);
    m_group.push_back(m_group[e.a] == m_group[e.b] ? m_group[e.a] : none);
    m_piece.push_back(m_piece[e.a] == m_piece[e.b] ? m_piece[e.a] : none);
    m_attached.push_back(m_attached[e.a] && m_attached[e.b]);
    m_children.push_back({{e.a, e.b}});
    m_kind.push_back(e.kind);
    // above the default parts a merge costs at least their maximum, whatever its place in the order
    m_cost.push_back(m_above_default && std::isfinite(m_p.attachment_from) ? (std::max)(e.cost, m_p.attachment_from)
                                                                           : e.cost);
    m_alive[e.a] = m_alive[e.b] = 0;
    m_alive.push_back(1);
    m_links.emplace_back();
    for(std::size_t c : {e.a, e.b})
    {
      for(const Link& l : m_links[c])
      {
        if(l.node == e.a || l.node == e.b) continue;
        add_link(m, l);
        std::vector<Link>& back = m_links[l.node];
        back.erase(std::remove_if(back.begin(), back.end(),
                                  [&](const Link& x) { return x.node == e.a || x.node == e.b; }),
                   back.end());
      }
      std::vector<Link>().swap(m_links[c]);
    }
    for(const Link& l : m_links[m])
    {
      add_link(l.node, Link{m, l.contact, l.length, l.concave});
      push(m, l);
    }
  }

  std::vector<Part_box> m_box;
  std::vector<std::size_t> m_subgroup, m_group, m_piece;
  std::vector<std::uint8_t> m_attached;
  Merge_parameters m_p;
  double m_volume, m_area; // of the bounding box of the mesh, of its surface
  std::vector<std::vector<Link> > m_links;
  std::vector<std::uint8_t> m_alive;
  std::vector<std::array<std::size_t, 2> > m_children;
  std::vector<Merge_kind> m_kind;
  std::vector<double> m_cost;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry> > m_queue;
  bool m_above_default = false; // once the merges of the default parts are done
};

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_PART_MERGING_H
