// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_BOUNDARY_GRAPH_CUT_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_BOUNDARY_GRAPH_CUT_H

// The final labelling of the faces: a Potts energy on the face graph, minimized by alpha
// expansion on the contested faces only.
//
// Inputs:  adj        the face graph with dihedral angles (F faces)
//          corners    the corners of each face (edge lengths)
//          candidates per face, its candidate labels and their data costs (see Face_candidates)
//          orientation per face, +1 or -1: the side of the surface that is outside
//          edge_scale the cost of cutting one unit of length across a smooth convex edge is
//                     edge_scale * cut_penalty(0, convex)
//          cluster_cell  the cell size (mesh units) of the clusters of the two-level labelling
// Output:  the label of each face, among its candidates, minimizing (approximately)
//          sum_f cost_f(label_f) + edge_scale * sum_{cut edges e} length_e * cut_penalty(e).

#include <CGAL/Part_decomposition/internal/toolbox/face_adjacency.h>
#include <CGAL/Part_decomposition/internal/parts/piece_regions.h>
#include <CGAL/Part_decomposition/internal/parts/potts_alpha_expansion.h>
#include <CGAL/Part_decomposition/internal/toolbox/toolbox.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

// Per face, up to `capacity` candidate labels by increasing cost; the first is the cheapest.
struct Face_candidates
{
  static constexpr int capacity = 4;
  std::vector<std::array<std::int32_t, capacity> > label; // -1 past the last candidate
  std::vector<std::array<double, capacity> > cost;
  std::vector<double> excluded; // the least cost of a label that is not a candidate

  void resize(std::size_t n)
  {
    std::array<std::int32_t, capacity> none;
    none.fill(-1);
    label.assign(n, none);
    cost.assign(n, std::array<double, capacity>());
    excluded.assign(n, 0.);
  }
  int size(std::size_t i) const
  {
    int n = 0;
    while(n < capacity && label[i][std::size_t(n)] >= 0) ++n;
    return n;
  }
  // the rank of label l among the candidates of face i, or -1
  int find(std::size_t i, std::int32_t l) const
  {
    for(int k = 0; k < capacity && label[i][std::size_t(k)] >= 0; ++k)
      if(label[i][std::size_t(k)] == l) return k;
    return -1;
  }
};

// The cost factor of cutting across an edge of dihedral angle `degrees`, in the form of the
// Surface_mesh_segmentation package: -log of the angle as a fraction of pi, scaled down on a
// convex edge, so that concave creases are cheap and smooth or convex surface is expensive.
inline double cut_penalty(double degrees, bool concave)
{
  constexpr double convex_factor = 0.08, smallest = 1e-3; // smallest: a flat edge costs -log(1e-3)
  const double t = (std::min)(1., (std::max)(0., degrees / 180.)) * (concave ? 1. : convex_factor);
  return -std::log((std::max)(t, smallest));
}

// The cost of cutting the edge of slot (i, k), edge_scale included.
inline double slot_cut_cost(const Face_adjacency& adj, const Face_corners& corners,
                            const std::vector<int>& orientation, std::size_t i, int k, double edge_scale)
{
  const bool concave = !adj.degenerate[i] && crease_sign(adj, i, k) * orientation[i] < 0;
  return edge_scale * slot_length(corners, i, k) * cut_penalty(adj.angle[3 * i + std::size_t(k)], concave);
}

// The rank of a face in its contested set (the set's faces by increasing index), or
// Label_problem::fixed for a face outside the set `set`: an array lookup, where a binary search
// per link was a fifth of the labelling of a large mesh.
struct Set_ranks
{
  const std::vector<std::size_t>& set_of; // per face, its set (read for contested faces only)
  const std::vector<std::uint8_t>& contested;
  const std::vector<std::size_t>& rank; // per contested face, its rank in its set
  std::size_t set;

  std::size_t operator()(std::size_t j) const
  {
    return contested[j] && set_of[j] == set ? rank[j] : Label_problem::fixed;
  }
};

// Writes the candidates of row r of `candidates` as the options of member m of `p` (allocated).
inline void copy_options(const Face_candidates& candidates, std::size_t r, Label_problem& p, std::size_t m)
{
  for(int c = 0; c < candidates.size(r); ++c)
  {
    p.option[p.first[m] + std::size_t(c)] = candidates.label[r][std::size_t(c)];
    p.option_cost[p.first[m] + std::size_t(c)] = candidates.cost[r][std::size_t(c)];
  }
}

// The problem on the faces `faces` (increasing; `rank_of(j)`: the rank of j in `faces`, or
// Label_problem::fixed), each starting with label_of(i), a candidate; the other faces around them
// are fixed at label_of(j). The candidates of faces[m] are row `row(m)` of `candidates`.
template <typename ConcurrencyTag, typename RankOf, typename LabelOf, typename Row>
Label_problem face_problem(const Face_adjacency& adj, const Face_corners& corners, const Face_candidates& candidates,
                           const std::vector<int>& orientation, double edge_scale,
                           const std::vector<std::size_t>& faces, const RankOf& rank_of, const LabelOf& label_of,
                           const Row& row)
{
  const std::size_t n = faces.size();
  Label_problem p;
  p.allocate(n, [&](std::size_t m) { return std::size_t(candidates.size(row(m))); });
  for_each_range<ConcurrencyTag>(n, [&](std::size_t b, std::size_t e) {
    for(std::size_t m = b; m < e; ++m)
    {
      const std::size_t i = faces[m];
      copy_options(candidates, row(m), p, m);
      p.label[m] = label_of(i);
      for(int k = 0; k < 3; ++k)
      {
        const std::size_t j = adj.neighbor[3 * i + std::size_t(k)];
        if(j == Face_adjacency::no_face || j == i) continue;
        const double w = slot_cut_cost(adj, corners, orientation, i, k, edge_scale);
        const std::size_t r = rank_of(j);
        p.links[m].push_back({r, r == Label_problem::fixed ? label_of(j) : -1, w});
      }
    }
  }, 1024);
  return p;
}

// Per face index, the cell of a grid of spacing `cell` (mesh units) that holds its centroid.
template <typename ConcurrencyTag>
std::vector<std::array<double, 3> > face_cells(const Face_adjacency& adj, double cell)
{
  std::vector<std::array<double, 3> > key(adj.number_of_faces);
  for_each_range<ConcurrencyTag>(adj.number_of_faces, [&](std::size_t b, std::size_t e) {
    for(std::size_t i = b; i < e; ++i)
      for(std::size_t a = 0; a < 3; ++a) key[i][a] = std::floor(adj.centroid[3 * i + a] / cell);
  }, 4096);
  return key;
}

// Per face index: its cluster, the faces of `contested` that are edge-connected within one cell of
// a grid of spacing `cell` (a face elsewhere is alone).
template <typename ConcurrencyTag>
std::vector<std::size_t> face_clusters(const Face_adjacency& adj, const std::vector<std::uint8_t>& contested,
                                              double cell)
{
  const std::vector<std::array<double, 3> > key = face_cells<ConcurrencyTag>(adj, cell);
  std::vector<std::size_t> cluster;
  face_components<ConcurrencyTag>(adj, [&](std::size_t i, int k) {
    const std::size_t j = adj.neighbor[3 * i + std::size_t(k)];
    return contested[i] && contested[j] && key[i] == key[j];
  }, cluster);
  return cluster;
}

// Sums the links to the same member or fixed label into one.
inline void merge_parallel_links(std::vector<Label_problem::Link>& links)
{
  const auto key = [](const Label_problem::Link& l) { return std::make_pair(l.member, l.fixed_label); };
  std::sort(links.begin(), links.end(),
            [&](const Label_problem::Link& a, const Label_problem::Link& b) { return key(a) < key(b); });
  std::size_t n = 0;
  for(std::size_t k = 0; k < links.size(); ++k)
    if(n > 0 && key(links[n - 1]) == key(links[k])) links[n - 1].cost += links[k].cost;
    else links[n++] = links[k];
  links.resize(n);
}

// The cluster of each face of `faces` numbered 0..C-1 in increasing cluster id; returns C.
template <typename ConcurrencyTag>
std::size_t local_clusters(const std::vector<std::size_t>& faces, const std::vector<std::size_t>& cluster,
                           std::vector<std::size_t>& local)
{
  std::vector<std::size_t> ids(faces.size());
  for_each_range<ConcurrencyTag>(faces.size(), [&](std::size_t b, std::size_t e) {
    for(std::size_t m = b; m < e; ++m) ids[m] = cluster[faces[m]];
  }, 4096);
  sort_values<ConcurrencyTag>(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  local.resize(faces.size());
  for_each_range<ConcurrencyTag>(faces.size(), [&](std::size_t b, std::size_t e) {
    for(std::size_t m = b; m < e; ++m)
      local[m] = std::size_t(std::lower_bound(ids.begin(), ids.end(), cluster[faces[m]]) - ids.begin());
  }, 4096);
  return ids.size();
}

// The links of cluster c of `faces` (its members: faces[member[start[c] .. start[c + 1])],
// increasing): its cut edges to other clusters and to fixed faces, those to one cluster or one
// fixed label summed.
template <typename LabelOf>
void cluster_links(const Face_adjacency& adj, const Face_corners& corners, const std::vector<int>& orientation,
                   double edge_scale, const std::vector<std::size_t>& faces, const Set_ranks& rank_of,
                   const std::vector<std::size_t>& local, const LabelOf& label_of, const std::vector<std::size_t>& start,
                   const std::vector<std::size_t>& member, std::size_t c, std::vector<Label_problem::Link>& links)
{
  for(std::size_t s = start[c]; s < start[c + 1]; ++s)
    for(int k = 0; k < 3; ++k)
    {
      const std::size_t m = member[s], i = faces[m], j = adj.neighbor[3 * i + std::size_t(k)];
      if(j == Face_adjacency::no_face || j == i) continue;
      const std::size_t r = rank_of(j);
      if(r != Label_problem::fixed && local[r] == c) continue;
      const double w = slot_cut_cost(adj, corners, orientation, i, k, edge_scale);
      links.push_back(r == Label_problem::fixed ? Label_problem::Link{r, label_of(j), w}
                                                : Label_problem::Link{local[r], -1, w});
    }
  merge_parallel_links(links);
}

// The problem on the C clusters of `faces` (increasing), `local` the cluster of each face: a
// cluster may take any candidate of its faces, at the sum of their costs (a face without that
// candidate adds its `excluded` cost), and starts with its cheapest; a cut between two clusters
// costs the cut edges between them.
template <typename ConcurrencyTag, typename LabelOf>
Label_problem cluster_problem(const Face_adjacency& adj, const Face_corners& corners, const Face_candidates& candidates,
                              const std::vector<int>& orientation, double edge_scale,
                              const std::vector<std::size_t>& faces, const Set_ranks& rank_of,
                              const std::vector<std::size_t>& local, std::size_t number_of_clusters,
                              const LabelOf& label_of)
{
  const std::size_t C = number_of_clusters;
  std::vector<std::size_t> start, member; // the members of cluster c: faces[member[start[c] .. start[c + 1])]
  group_indices(faces.size(), C, [&](std::size_t m) { return local[m]; }, [](std::size_t) { return true; }, start,
                member);
  // the candidates of the faces of cluster c, sorted, without repeats
  const auto cluster_labels = [&](std::size_t c, std::vector<std::int32_t>& labels) {
    labels.clear();
    for(std::size_t s = start[c]; s < start[c + 1]; ++s)
    {
      const std::size_t i = faces[member[s]];
      for(int k = 0; k < candidates.size(i); ++k) labels.push_back(candidates.label[i][std::size_t(k)]);
    }
    std::sort(labels.begin(), labels.end());
    labels.erase(std::unique(labels.begin(), labels.end()), labels.end());
  };
  std::vector<std::size_t> count(C);
  for_each_range<ConcurrencyTag>(C, [&](std::size_t b, std::size_t e) {
    std::vector<std::int32_t> labels;
    for(std::size_t c = b; c < e; ++c)
    {
      cluster_labels(c, labels);
      count[c] = labels.size();
    }
  }, 256);
  Label_problem p;
  p.allocate(C, [&](std::size_t c) { return count[c]; });
  for_each_range<ConcurrencyTag>(C, [&](std::size_t b, std::size_t e) {
    std::vector<std::int32_t> labels;
    for(std::size_t c = b; c < e; ++c)
    {
      cluster_labels(c, labels);
      double least = std::numeric_limits<double>::infinity();
      p.label[c] = labels.front();
      for(std::size_t o = 0; o < labels.size(); ++o)
      {
        double sum = 0.;
        for(std::size_t s = start[c]; s < start[c + 1]; ++s)
        {
          const std::size_t i = faces[member[s]];
          const int k = candidates.find(i, labels[o]);
          sum += k < 0 ? candidates.excluded[i] : candidates.cost[i][std::size_t(k)];
        }
        p.option[p.first[c] + o] = labels[o];
        p.option_cost[p.first[c] + o] = sum;
        if(sum < least) { least = sum; p.label[c] = labels[o]; }
      }
      cluster_links(adj, corners, orientation, edge_scale, faces, rank_of, local, label_of, start, member, c,
                    p.links[c]);
    }
  }, 256);
  return p;
}

// Labels one edge-connected set of contested faces (increasing), the faces around it fixed at
// `initial`. A set with far fewer clusters than faces is labelled in two levels, because a max-flow
// on a fine mesh follows paths across the whole set: its clusters first, then again face by face,
// the clusters next to a cut only (the cut moves within them), the rest fixed at its cluster's label.
template <typename ConcurrencyTag>
void label_contested_set(const Face_adjacency& adj, const Face_corners& corners,
                                const Face_candidates& candidates, const std::vector<int>& orientation,
                                double edge_scale, const std::vector<std::size_t>& faces, const Set_ranks& rank_of,
                                const std::vector<std::size_t>& cluster, const std::vector<std::int32_t>& initial,
                                std::vector<std::int32_t>& face_label)
{
  const auto initial_label = [&](std::size_t j) { return initial[j]; };
  std::vector<std::size_t> local;
  const std::size_t number_of_clusters = cluster.empty() ? faces.size() : local_clusters<ConcurrencyTag>(faces, cluster, local);
  if(2 * number_of_clusters > faces.size())
  {
    Label_problem p = face_problem<ConcurrencyTag>(adj, corners, candidates, orientation, edge_scale, faces, rank_of,
                                                   initial_label, [&](std::size_t m) { return faces[m]; });
    minimize_labels(p);
    for(std::size_t m = 0; m < faces.size(); ++m) face_label[faces[m]] = p.label[m];
    return;
  }
  Label_problem coarse = cluster_problem<ConcurrencyTag>(adj, corners, candidates, orientation, edge_scale, faces,
                                                         rank_of, local, number_of_clusters, initial_label);
  minimize_labels(coarse);
  // each face takes its cluster's label, or its cheapest candidate if that is not one of its own
  std::vector<std::int32_t> projected(faces.size());
  for_each_range<ConcurrencyTag>(faces.size(), [&](std::size_t b, std::size_t e) {
    for(std::size_t m = b; m < e; ++m)
    {
      const std::size_t i = faces[m];
      const std::int32_t l = coarse.label[local[m]];
      projected[m] = candidates.find(i, l) < 0 ? candidates.label[i][0] : l;
    }
  }, 4096);
  const auto label_of = [&](std::size_t j) {
    const std::size_t r = rank_of(j);
    return r == Label_problem::fixed ? initial[j] : projected[r];
  };
  // the clusters with a face next to another label
  std::vector<std::uint8_t> next_to_cut(faces.size(), 0), refine(coarse.size(), 0);
  for_each_range<ConcurrencyTag>(faces.size(), [&](std::size_t b, std::size_t e) {
    for(std::size_t m = b; m < e; ++m)
      for(int k = 0; k < 3; ++k)
      {
        const std::size_t j = adj.neighbor[3 * faces[m] + std::size_t(k)];
        if(j != Face_adjacency::no_face && label_of(j) != projected[m]) next_to_cut[m] = 1;
      }
  }, 4096);
  for(std::size_t m = 0; m < faces.size(); ++m)
    if(next_to_cut[m]) refine[local[m]] = 1;
  std::vector<std::size_t> band, band_rank(faces.size(), Label_problem::fixed);
  for(std::size_t m = 0; m < faces.size(); ++m)
    if(refine[local[m]])
    {
      band_rank[m] = band.size();
      band.push_back(faces[m]);
    }
  const auto rank_in_band = [&](std::size_t j) {
    const std::size_t r = rank_of(j);
    return r == Label_problem::fixed ? r : band_rank[r];
  };
  Label_problem fine =
    face_problem<ConcurrencyTag>(adj, corners, candidates, orientation, edge_scale, band, rank_in_band, label_of,
                                 [&](std::size_t m) { return band[m]; });
  minimize_labels(fine);
  for(std::size_t m = 0; m < faces.size(); ++m) face_label[faces[m]] = projected[m];
  for(std::size_t b = 0; b < band.size(); ++b) face_label[band[b]] = fine.label[b];
}

// Calls label_set(c, faces) for each set c of `sets` (`faces` is scratch), the largest beside all
// the others: its minimum cuts run on one thread.
template <typename ConcurrencyTag, typename SizeOf, typename LabelSet>
void label_sets_side_by_side(const std::vector<std::size_t>& sets, const SizeOf& size_of, const LabelSet& label_set)
{
  if(sets.empty()) return;
  const std::size_t largest = *std::max_element(sets.begin(), sets.end(),
                                                [&](std::size_t a, std::size_t b) { return size_of(a) < size_of(b); });
  run_side_by_side<ConcurrencyTag>([&] {
    std::vector<std::size_t> faces;
    label_set(largest, faces);
  }, [&] {
    for_each_range<ConcurrencyTag>(sets.size(), [&](std::size_t b, std::size_t e) {
      std::vector<std::size_t> faces;
      for(std::size_t s = b; s < e; ++s)
        if(sets[s] != largest) label_set(sets[s], faces);
    }, 1);
  });
}

// The final labels: every face starts with its cheapest candidate; the edge-connected sets of
// faces with two candidates or more are relabelled by alpha expansion, each on its own, in two
// levels where the faces are much smaller than `cluster_cell` (0: never). The result does not
// depend on the number of threads.
template <typename ConcurrencyTag>
std::vector<std::int32_t> cut_face_labels(const Face_adjacency& adj, const Face_corners& corners,
                                          const Face_candidates& candidates, const std::vector<int>& orientation,
                                          double edge_scale, double cluster_cell)
{
  const std::size_t nf = adj.number_of_faces;
  std::vector<std::int32_t> face_label(nf);
  std::vector<std::uint8_t> contested(nf, 0);
  for_each_range<ConcurrencyTag>(nf, [&](std::size_t b, std::size_t e) {
    for(std::size_t i = b; i < e; ++i)
    {
      face_label[i] = candidates.label[i][0];
      contested[i] = candidates.size(i) > 1;
    }
  }, 4096);
  if(edge_scale <= 0.) return face_label;
  // the contested sets, then the clusters of the two-level labelling (one after the other: this
  // step holds the peak memory of a large mesh)
  std::vector<std::size_t> component;
  const std::size_t nc = face_components<ConcurrencyTag>(adj, [&](std::size_t i, int k) {
    return contested[i] && contested[adj.neighbor[3 * i + std::size_t(k)]];
  }, component);
  const std::vector<std::size_t> cluster =
    cluster_cell > 0. ? face_clusters<ConcurrencyTag>(adj, contested, cluster_cell) : std::vector<std::size_t>();
  // the contested faces of each component, by increasing face index
  std::vector<std::size_t> start, order;
  group_indices(nf, nc, [&](std::size_t i) { return component[i]; }, [&](std::size_t i) { return contested[i] != 0; },
                start, order);
  std::vector<std::size_t> sets; // the components with contested faces
  for(std::size_t c = 0; c < nc; ++c)
    if(start[c] < start[c + 1]) sets.push_back(c);
  std::vector<std::size_t> rank(nf, 0); // of each contested face in its set
  for_each_range<ConcurrencyTag>(order.size(), [&](std::size_t b, std::size_t e) {
    for(std::size_t s = b; s < e; ++s) rank[order[s]] = s - start[component[order[s]]];
  }, 4096);
  const std::vector<std::int32_t> initial(face_label); // read by all, each set writes its own faces
  const auto label_set = [&](std::size_t c, std::vector<std::size_t>& faces) {
    faces.assign(order.begin() + std::ptrdiff_t(start[c]), order.begin() + std::ptrdiff_t(start[c + 1]));
    const Set_ranks rank_of{component, contested, rank, c};
    label_contested_set<ConcurrencyTag>(adj, corners, candidates, orientation, edge_scale, faces, rank_of, cluster,
                                        initial, face_label);
  };
  label_sets_side_by_side<ConcurrencyTag>(sets, [&](std::size_t c) { return start[c + 1] - start[c]; }, label_set);
  return face_label;
}

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_BOUNDARY_GRAPH_CUT_H
