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
// Output:  the label of each face, among its candidates, minimizing (approximately)
//          sum_f cost_f(label_f) + edge_scale * sum_{cut edges e} length_e * cut_penalty(e).

#include <CGAL/Part_decomposition/internal/face_adjacency.h>
#include <CGAL/Part_decomposition/internal/piece_regions.h>
#include <CGAL/Part_decomposition/internal/toolbox.h>

#include <CGAL/boost/graph/alpha_expansion_graphcut.h>

#include <boost/graph/adjacency_list.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
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

  void resize(std::size_t n)
  {
    std::array<std::int32_t, capacity> none;
    none.fill(-1);
    label.assign(n, none);
    cost.assign(n, std::array<double, capacity>());
  }
  int size(std::size_t i) const
  {
    int n = 0;
    while(n < capacity && label[i][std::size_t(n)] >= 0) ++n;
    return n;
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

// The length of the edge of slot (i, k): corners are listed from target(halfedge(f)) on.
inline double slot_length(const Face_corners& corners, std::size_t i, int k)
{
  return (corners(i, k) - corners(i, (k + 2) % 3)).norm();
}

// The cost of cutting the edge of slot (i, k), edge_scale included.
inline double slot_cut_cost(const Face_adjacency& adj, const Face_corners& corners,
                            const std::vector<int>& orientation, std::size_t i, int k, double edge_scale)
{
  const bool concave = !adj.degenerate[i] && crease_sign(adj, i, k) * orientation[i] < 0;
  return edge_scale * slot_length(corners, i, k) * cut_penalty(adj.angle[3 * i + std::size_t(k)], concave);
}

// The contested faces of one component, numbered 0..n-1, with their candidates and their
// neighbours: another face of the set, or a fixed label around it.
struct Contested_set
{
  struct Link
  {
    std::size_t face; // in the set, or `fixed`
    std::int32_t fixed_label;
    double cost;
  };
  static constexpr std::size_t fixed = std::size_t(-1);
  std::vector<std::size_t> faces;      // face index of each member
  std::vector<std::int32_t> label;     // current label of each member
  std::vector<std::vector<Link> > links;
  std::vector<std::size_t> member;     // per member: its rank in the support of a move, or `fixed`
};

// One expansion move of label `alpha` (Boykov, Veksler, Zabih 2001), solved exactly on the faces
// that may take `alpha`, the others fixed: CGAL's alpha_expansion_graphcut() cuts the whole graph
// for every label, the restriction to the support of `alpha` is what makes large sets cheap.
// Between two faces with different labels, keeping both costs w and any change w: that is a
// Potts term of w/2 plus w/2 on keeping each. Returns whether the energy decreased.
// `holders`: the members that have `alpha` among their candidates, increasing.
inline bool expand_label(Contested_set& set, const Face_candidates& candidates, std::int32_t alpha,
                         const std::vector<std::size_t>& holders)
{
  typedef boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, boost::no_property,
                                boost::property<boost::edge_weight_t, double> > Graph;
  std::vector<std::size_t>& member = set.member;
  std::vector<std::size_t> support;
  std::vector<std::vector<double> > cost; // [keep, alpha] per member of the support
  for(std::size_t m : holders)
  {
    if(set.label[m] == alpha) continue;
    const std::size_t i = set.faces[m];
    for(int c = 0; c < candidates.size(i); ++c)
      if(candidates.label[i][std::size_t(c)] == alpha)
      {
        member[m] = support.size();
        support.push_back(m);
        cost.push_back({0., candidates.cost[i][std::size_t(c)]});
      }
  }
  if(support.empty()) return false;
  Graph graph(support.size());
  double keep_all = 0.; // the energy of the terms that involve the support, if nothing changes
  for(std::size_t s = 0; s < support.size(); ++s)
  {
    const std::size_t m = support[s];
    const std::size_t i = set.faces[m];
    for(int c = 0; c < candidates.size(i); ++c)
      if(candidates.label[i][std::size_t(c)] == set.label[m]) cost[s][0] = candidates.cost[i][std::size_t(c)];
    for(const Contested_set::Link& l : set.links[m])
    {
      const bool in_support = l.face != Contested_set::fixed && member[l.face] != Contested_set::fixed;
      if(!in_support)
      {
        const std::int32_t other = l.face == Contested_set::fixed ? l.fixed_label : set.label[l.face];
        if(other != set.label[m]) cost[s][0] += l.cost;
        if(other != alpha) cost[s][1] += l.cost;
        continue;
      }
      const std::size_t t = member[l.face];
      if(t < s) continue; // each link once
      if(set.label[l.face] == set.label[m])
        boost::add_edge(s, t, l.cost, graph);
      else
      {
        boost::add_edge(s, t, 0.5 * l.cost, graph);
        cost[s][0] += 0.5 * l.cost;
        cost[t][0] += 0.5 * l.cost;
      }
    }
  }
  for(const std::vector<double>& c : cost) keep_all += c[0];
  std::vector<std::size_t> move(support.size(), 0);
  const double energy = CGAL::alpha_expansion_graphcut(
      graph, boost::get(boost::edge_weight, graph), CGAL::make_property_map(cost), CGAL::make_property_map(move),
      CGAL::parameters::vertex_index_map(boost::get(boost::vertex_index, graph))
        .implementation_tag(CGAL::Alpha_expansion_boost_compressed_sparse_row_tag()));
  for(std::size_t m : support) member[m] = Contested_set::fixed;
  if(!(energy < keep_all * (1. - 1e-12))) return false;
  for(std::size_t s = 0; s < support.size(); ++s)
    if(move[s] == 1) set.label[support[s]] = alpha;
  return true;
}

// Alpha expansion on one connected set of contested faces; the labels of the faces around it
// are fixed (`initial`) and enter as data costs. Writes the labels of `faces` into `face_label`.
inline void cut_contested_component(const Face_adjacency& adj, const Face_corners& corners,
                                    const Face_candidates& candidates, const std::vector<int>& orientation,
                                    double edge_scale, const std::vector<std::size_t>& faces,
                                    const std::vector<std::uint8_t>& contested, const std::vector<std::int32_t>& initial,
                                    std::vector<std::int32_t>& face_label)
{
  constexpr int maximum_cycles = 8; // a cycle without a decrease ends earlier
  Contested_set set;
  set.faces = faces;
  set.links.resize(faces.size());
  std::vector<std::int32_t> labels;
  for(std::size_t m = 0; m < faces.size(); ++m)
  {
    const std::size_t i = faces[m];
    set.label.push_back(initial[i]);
    for(int c = 0; c < candidates.size(i); ++c) labels.push_back(candidates.label[i][std::size_t(c)]);
    for(int k = 0; k < 3; ++k)
    {
      const std::size_t j = adj.neighbor[3 * i + std::size_t(k)];
      if(j == Face_adjacency::no_face || j == i) continue;
      const double w = slot_cut_cost(adj, corners, orientation, i, k, edge_scale);
      if(contested[j])
        set.links[m].push_back({std::size_t(std::lower_bound(faces.begin(), faces.end(), j) - faces.begin()), -1, w});
      else
        set.links[m].push_back({Contested_set::fixed, initial[j], w});
    }
  }
  std::sort(labels.begin(), labels.end());
  labels.erase(std::unique(labels.begin(), labels.end()), labels.end());
  // the members that may take each label: a move visits these only
  std::vector<std::vector<std::size_t> > holders(labels.size());
  for(std::size_t m = 0; m < faces.size(); ++m)
    for(int c = 0; c < candidates.size(faces[m]); ++c)
    {
      const std::int32_t l = candidates.label[faces[m]][std::size_t(c)];
      holders[std::size_t(std::lower_bound(labels.begin(), labels.end(), l) - labels.begin())].push_back(m);
    }
  set.member.assign(faces.size(), Contested_set::fixed);
  for(int cycle = 0; cycle < maximum_cycles; ++cycle)
  {
    bool decreased = false;
    for(std::size_t a = 0; a < labels.size(); ++a)
      decreased = expand_label(set, candidates, labels[a], holders[a]) || decreased;
    if(!decreased) break;
  }
  for(std::size_t m = 0; m < faces.size(); ++m) face_label[faces[m]] = set.label[m];
}

// The final labels: every face starts with its cheapest candidate; the edge-connected sets of
// faces with two candidates or more are relabelled by alpha expansion, each on its own. The
// result does not depend on the number of threads.
template <typename ConcurrencyTag>
std::vector<std::int32_t> cut_face_labels(const Face_adjacency& adj, const Face_corners& corners,
                                          const Face_candidates& candidates, const std::vector<int>& orientation,
                                          double edge_scale)
{
  const std::size_t nf = adj.number_of_faces;
  std::vector<std::int32_t> face_label(nf);
  std::vector<std::uint8_t> contested(nf, 0);
  for(std::size_t i = 0; i < nf; ++i)
  {
    face_label[i] = candidates.label[i][0];
    contested[i] = candidates.size(i) > 1;
  }
  if(edge_scale <= 0.) return face_label;
  std::vector<std::size_t> component;
  const std::size_t nc = face_components(adj, [&](std::size_t i, int k) {
    return contested[i] && contested[adj.neighbor[3 * i + std::size_t(k)]];
  }, component);
  // the contested faces of each component, by increasing face index
  std::vector<std::size_t> start(nc + 1, 0), order;
  for(std::size_t i = 0; i < nf; ++i)
    if(contested[i]) ++start[component[i] + 1];
  for(std::size_t c = 0; c < nc; ++c) start[c + 1] += start[c];
  order.resize(start[nc]);
  {
    std::vector<std::size_t> fill(start.begin(), start.end() - 1);
    for(std::size_t i = 0; i < nf; ++i)
      if(contested[i]) order[fill[component[i]]++] = i;
  }
  std::vector<std::size_t> sets; // the components with contested faces
  for(std::size_t c = 0; c < nc; ++c)
    if(start[c] < start[c + 1]) sets.push_back(c);
  const std::vector<std::int32_t> initial(face_label); // read by all, each component writes its own faces
  for_each_range<ConcurrencyTag>(sets.size(), [&](std::size_t b, std::size_t e) {
    std::vector<std::size_t> faces;
    for(std::size_t s = b; s < e; ++s)
    {
      const std::size_t c = sets[s];
      faces.assign(order.begin() + std::ptrdiff_t(start[c]), order.begin() + std::ptrdiff_t(start[c + 1]));
      cut_contested_component(adj, corners, candidates, orientation, edge_scale, faces, contested, initial,
                              face_label);
    }
  }, 1);
  return face_label;
}

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_BOUNDARY_GRAPH_CUT_H
