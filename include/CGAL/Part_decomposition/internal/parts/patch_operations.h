// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_PATCH_OPERATIONS_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_PATCH_OPERATIONS_H

#include <CGAL/Part_decomposition/internal/toolbox/face_adjacency.h>
#include <CGAL/Part_decomposition/internal/toolbox/toolbox.h>

#include <boost/container_hash/hash.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>
#include <queue>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

// The dihedral angles of the interior edges between two faces of non-zero area, once per edge.
inline std::vector<double> interior_edge_angles(const Face_adjacency& adj)
{
  std::vector<double> values;
  values.reserve(3 * adj.number_of_faces / 2 + 1);
  for(std::size_t i = 0; i < adj.number_of_faces; ++i)
  {
    if(adj.degenerate[i]) continue;
    for(int k = 0; k < 3; ++k)
    {
      const std::size_t j = adj.neighbor[3 * i + k];
      if(j != Face_adjacency::no_face && j > i && !adj.degenerate[j])
        values.push_back(adj.angle[3 * i + k]);
    }
  }
  return values;
}

// Renumbers the labels to 0..A-1 by increasing smallest face index; returns A. `old_label`, if
// given, receives the former label of each new one.
inline std::size_t renumber_by_first_face(std::vector<std::size_t>& label,
                                          std::vector<std::size_t>* old_label = nullptr)
{
  const std::size_t none = Face_adjacency::no_face;
  std::size_t max_label = 0;
  for(std::size_t l : label) max_label = (std::max)(max_label, l);
  std::vector<std::size_t> new_id(label.empty() ? 0 : max_label + 1, none);
  std::size_t count = 0;
  if(old_label) old_label->clear();
  for(std::size_t& l : label)
  {
    if(new_id[l] == none)
    {
      new_id[l] = count++;
      if(old_label) old_label->push_back(l);
    }
    l = new_id[l];
  }
  return count;
}

// The uncut interior edges of the patches marked `large`, as sort keys in increasing order: the
// angle as a float (its bits order like the value for angles >= 0), then the slot, then whether
// the edge is flat (angle <= `flat_angle`). Every key is unique and equal floats fall back to
// the slot order, so any sort gives the same order.
template <typename ConcurrencyTag>
std::vector<std::uint64_t> uncut_edges_by_angle(const Face_adjacency& adj, const std::vector<std::uint8_t>& cut,
                                                const std::vector<std::size_t>& label,
                                                const std::vector<std::uint8_t>& large, double flat_angle)
{
  const std::size_t nf = adj.number_of_faces;
  CGAL_precondition(3 * nf < (std::size_t(1) << 31));
  std::vector<std::uint64_t> edges;
  edges.reserve(3 * nf / 2);
  for(std::size_t i = 0; i < nf; ++i)
  {
    if(!large[label[i]]) continue;
    for(int k = 0; k < 3; ++k)
    {
      const std::size_t j = adj.neighbor[3 * i + k];
      if(j != Face_adjacency::no_face && j > i && !cut[3 * i + k])
      {
        const double angle = adj.angle[3 * i + k];
        const float a = float(angle);
        std::uint32_t bits;
        std::memcpy(&bits, &a, sizeof bits);
        edges.push_back((std::uint64_t(bits) << 32) | (std::uint64_t(3 * i + k) << 1) |
                        std::uint64_t(angle <= flat_angle ? 1 : 0));
      }
    }
  }
  sort_values<ConcurrencyTag>(edges.begin(), edges.end());
  return edges;
}

// Splits every patch of area above `max_area` by an ordered flood fill: its uncut edges are
// crossed by increasing dihedral angle (ties: slot order), joining the two sides unless the
// joined piece would have an area above `max_area` or a squared radius of gyration (area-weighted,
// of the face centroids) above `gyration_ratio * max_area` (Kruskal with a size and shape cap),
// so that compact pieces meet along the locally sharpest edges. Without the shape cap, pieces
// follow the directions of least curvature and grow into long strips. Flat edges (angle <=
// `flat_angle`) are always crossed: a planar region is never split. Patches not above `max_area`
// are unchanged. On output the labels are renumbered by first face; returns their number.
template <typename ConcurrencyTag>
std::size_t split_large_patches(const Face_adjacency& adj, const std::vector<std::uint8_t>& cut,
                                       std::vector<std::size_t>& label, std::size_t number_of_patches,
                                       double max_area, double gyration_ratio, double flat_angle)
{
  const std::size_t nf = adj.number_of_faces;
  std::vector<double> patch_area(number_of_patches, 0.);
  for(std::size_t i = 0; i < nf; ++i) patch_area[label[i]] += adj.area[i];
  std::vector<std::uint8_t> large(number_of_patches, 0);
  bool any = false;
  for(std::size_t p = 0; p < number_of_patches; ++p)
    if(patch_area[p] > max_area) large[p] = 1, any = true;
  if(!any) return renumber_by_first_face(label);

  const std::vector<std::uint64_t> edges = uncut_edges_by_angle<ConcurrencyTag>(adj, cut, label, large, flat_angle);

  // Disjoint sets of faces; the piece of each root: its area, the area-weighted first and second
  // moments of its face centroids, and its smallest face index.
  struct Piece { double area, mx, my, mz, m2; std::size_t first; };
  Index_sets sets(nf);
  std::vector<Piece> piece(nf);
  for(std::size_t i = 0; i < nf; ++i)
  {
    const double* c = &adj.centroid[3 * i];
    const double a = adj.area[i];
    piece[i] = Piece{a, a * c[0], a * c[1], a * c[2], a * (c[0] * c[0] + c[1] * c[1] + c[2] * c[2]), i};
  }
  const double max_gyration = gyration_ratio * max_area;
  const auto slot_of = [&](std::size_t e) { return std::size_t((edges[e] >> 1) & 0x7fffffffu); };
  constexpr std::size_t ahead = 16; // edges whose faces are fetched before their turn
  for(std::size_t e = 0; e < edges.size(); ++e)
  {
    if(e + 2 * ahead < edges.size()) prefetch_address(&adj.neighbor[slot_of(e + 2 * ahead)]);
    if(e + ahead < edges.size())
    {
      const std::size_t s = slot_of(e + ahead), f = s / 3, g = adj.neighbor[s];
      sets.prefetch(f);
      sets.prefetch(g);
      prefetch_address(&piece[f]);
      prefetch_address(&piece[g]);
    }
    const std::uint64_t key = edges[e];
    const std::size_t slot = slot_of(e);
    const bool flat = (key & 1u) != 0;
    const std::size_t a = sets.find(slot / 3), b = sets.find(adj.neighbor[slot]);
    if(a == b) continue;
    const Piece& pa = piece[a];
    const Piece& pb = piece[b];
    const Piece m{pa.area + pb.area, pa.mx + pb.mx, pa.my + pb.my, pa.mz + pb.mz, pa.m2 + pb.m2,
                  (std::min)(pa.first, pb.first)};
    if(!flat)
    {
      if(m.area > max_area) continue;
      if(m.area > 0.)
      {
        const double g = m.m2 / m.area - (m.mx * m.mx + m.my * m.my + m.mz * m.mz) / (m.area * m.area);
        if(g > max_gyration) continue;
      }
    }
    piece[sets.unite(a, b)] = m;
  }
  // Pieces of split patches get ids after the unchanged ones; renumbering orders them all.
  for(std::size_t i = 0; i < nf; ++i)
    if(large[label[i]]) label[i] = number_of_patches + piece[sets.find(i)].first;
  return renumber_by_first_face(label);
}

// The rank of each key among the distinct keys (`index`) and the rank of its first
// `prefix_length` entries among the distinct prefixes (`prefix_index`), in lexicographic order. The
// keys repeat over many faces: only the distinct ones are sorted (each block of keys is reduced
// to its distinct ones in parallel), and each key finds its ranks in a hash table.
template <typename ConcurrencyTag, typename T, std::size_t N>
void index_of_keys(const std::vector<std::array<T, N> >& key, std::size_t prefix_length,
                   std::vector<std::size_t>& index, std::vector<std::size_t>& prefix_index)
{
  typedef std::array<T, N> Key;
  typedef std::unordered_map<Key, std::pair<std::size_t, std::size_t>, boost::hash<Key> > Rank_table;
  constexpr std::size_t block = std::size_t(1) << 16;
  std::vector<std::vector<Key> > found((key.size() + block - 1) / block);
  for_each_block<ConcurrencyTag>(key.size(), block, [&](std::size_t b, std::size_t e) {
    const std::unordered_set<Key, boost::hash<Key> > seen(key.begin() + std::ptrdiff_t(b), key.begin() + std::ptrdiff_t(e));
    found[b / block].assign(seen.begin(), seen.end());
  });
  std::vector<Key> distinct;
  for(const std::vector<Key>& f : found) distinct.insert(distinct.end(), f.begin(), f.end());
  std::sort(distinct.begin(), distinct.end());
  distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
  Rank_table rank(distinct.size());
  std::size_t prefix_rank = 0;
  for(std::size_t r = 0; r < distinct.size(); ++r)
  {
    if(r > 0 && !std::equal(distinct[r].begin(), distinct[r].begin() + prefix_length, distinct[r - 1].begin()))
      ++prefix_rank;
    rank.emplace(distinct[r], std::make_pair(r, prefix_rank));
  }
  index.resize(key.size());
  prefix_index.resize(key.size());
  for_each_range<ConcurrencyTag>(key.size(), [&](std::size_t b, std::size_t e) {
    for(std::size_t i = b; i < e; ++i)
    {
      const std::pair<std::size_t, std::size_t>& r = rank.find(key[i])->second;
      index[i] = r.first;
      prefix_index[i] = r.second;
    }
  }, 4096);
}

// Merges every patch whose area is below `min_area` into the neighbouring patch across its
// weakest shared edge (smallest dihedral angle; ties: the smaller neighbour, then the smaller
// id, so that equal fragments pair up rather than pile onto one), smallest patch first,
// until every patch reaches `min_area` or has no neighbour. `label` holds ids in
// [0, number_of_patches) on input, and the ids of the surviving patches (not renumbered) on output.
inline void merge_small_patches(const Face_adjacency& adj, std::vector<std::size_t>& label,
                                std::size_t number_of_patches, double min_area)
{
  const std::size_t nf = adj.number_of_faces;
  const std::size_t np = number_of_patches;
  std::vector<double> patch_area(np, 0.);
  for(std::size_t i = 0; i < nf; ++i) patch_area[label[i]] += adj.area[i];

  // Adjacency lists may hold stale ids and repeats; they are resolved through `find`.
  struct Link { std::size_t patch; double angle; };
  std::vector<std::vector<Link> > links(np);
  for(std::size_t i = 0; i < nf; ++i)
    for(int k = 0; k < 3; ++k)
    {
      const std::size_t j = adj.neighbor[3 * i + k];
      if(j == Face_adjacency::no_face || label[j] == label[i]) continue;
      links[label[i]].push_back(Link{label[j], adj.angle[3 * i + k]});
    }

  // Not CGAL::Union_find: the root must be the patch merged into, whose id breaks the ties.
  std::vector<std::size_t> parent(np);
  for(std::size_t p = 0; p < np; ++p) parent[p] = p;
  auto find = [&](std::size_t p) {
    std::size_t r = p;
    while(parent[r] != r) r = parent[r];
    while(parent[p] != r) { const std::size_t n = parent[p]; parent[p] = r; p = n; }
    return r;
  };

  typedef std::pair<double, std::size_t> Entry; // (area, patch): smallest first
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry> > queue;
  for(std::size_t p = 0; p < np; ++p)
    if(patch_area[p] < min_area) queue.push(Entry(patch_area[p], p));

  while(!queue.empty())
  {
    const Entry e = queue.top();
    queue.pop();
    const std::size_t p = e.second;
    if(parent[p] != p || patch_area[p] != e.first) continue; // merged away or stale
    std::size_t best = np;
    double best_angle = 0.;
    std::vector<Link>& lp = links[p];
    std::size_t kept = 0;
    for(std::size_t l = 0; l < lp.size(); ++l)
    {
      const std::size_t q = find(lp[l].patch);
      if(q == p) continue;
      lp[kept++] = Link{q, lp[l].angle};
      if(best == np || lp[l].angle < best_angle ||
         (lp[l].angle == best_angle &&
          (patch_area[q] < patch_area[best] || (patch_area[q] == patch_area[best] && q < best))))
      {
        best = q;
        best_angle = lp[l].angle;
      }
    }
    lp.resize(kept);
    if(best == np) continue; // an isolated piece of the mesh: nothing to merge with
    parent[p] = best;
    patch_area[best] += patch_area[p];
    std::vector<Link>& lb = links[best];
    lb.insert(lb.end(), lp.begin(), lp.end());
    std::vector<Link>().swap(lp);
    if(patch_area[best] < min_area) queue.push(Entry(patch_area[best], best));
  }
  for(std::size_t i = 0; i < nf; ++i) label[i] = find(label[i]);
}

// One pass of boundary smoothing: a face moves to the patch Q that holds at least two of its
// three neighbours, counting only neighbours that do not move themselves in this pass. A moving
// face has at most one neighbour in its own patch, so every patch stays edge-connected; a patch
// may vanish. Decisions read the labels before the pass (order independent). Returns the number
// of faces moved.
template <typename ConcurrencyTag>
std::size_t smooth_patch_boundaries(const Face_adjacency& adj, std::vector<std::size_t>& label)
{
  const std::size_t nf = adj.number_of_faces;
  const std::size_t none = Face_adjacency::no_face;
  // target[i]: the patch holding two or more neighbours of i (none if no such patch).
  std::vector<std::size_t> target(nf, none);
  for_each_range<ConcurrencyTag>(nf, [&](std::size_t b, std::size_t e) {
    for(std::size_t i = b; i < e; ++i)
    {
      const std::size_t* nb = &adj.neighbor[3 * i];
      std::size_t l[3];
      for(int k = 0; k < 3; ++k) l[k] = nb[k] == none ? none : label[nb[k]];
      for(int k = 0; k < 3; ++k)
        if(l[k] != none && l[k] != label[i] && (l[k] == l[(k + 1) % 3] || l[k] == l[(k + 2) % 3]))
        {
          target[i] = l[k];
          break;
        }
    }
  }, 1024);
  std::vector<std::size_t> next_label(label);
  std::vector<std::uint8_t> moved(nf, 0);
  for_each_range<ConcurrencyTag>(nf, [&](std::size_t b, std::size_t e) {
    for(std::size_t i = b; i < e; ++i)
    {
      if(target[i] == none) continue;
      int stable = 0;
      for(int k = 0; k < 3; ++k)
      {
        const std::size_t j = adj.neighbor[3 * i + k];
        if(j != none && label[j] == target[i] && target[j] == none) ++stable;
      }
      if(stable >= 2) { next_label[i] = target[i]; moved[i] = 1; }
    }
  }, 1024);
  label.swap(next_label);
  std::size_t count = 0;
  for(std::uint8_t m : moved) count += m;
  return count;
}

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_PATCH_OPERATIONS_H
