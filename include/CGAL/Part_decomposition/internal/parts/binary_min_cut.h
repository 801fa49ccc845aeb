// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_BINARY_MIN_CUT_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_BINARY_MIN_CUT_H

// The exact minimum of a binary energy with non-negative pairwise terms, by one minimum s-t cut.
//
// Inputs:  cost   per node i (n nodes), cost[i][x]: the cost of giving node i the label x in {0, 1}
//          pairs  (i, j, w), w >= 0: w is paid when i and j get different labels
// Output:  per node, its label (0 or 1) in a labelling of least total cost.
//
// CGAL's alpha_expansion_graphcut() lacks this: it loops over every label until no move helps
// (three max-flows or more for two labels), and its compressed-row graph finds the reverse of each
// edge by a scan of the source's and sink's n edges, quadratic in n. Here the graph is built in
// linear time with the reverse edges known, then cut once by boost's Boykov-Kolmogorov max-flow.

#include <CGAL/Part_decomposition/internal/toolbox/toolbox.h>

#include <boost/graph/boykov_kolmogorov_max_flow.hpp>
#include <boost/graph/compressed_sparse_row_graph.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

struct Binary_pair_term
{
  std::size_t i, j;
  double weight;
};

inline std::vector<std::uint8_t> minimum_binary_labelling(const std::vector<std::array<double, 2> >& cost,
                                                          const std::vector<Binary_pair_term>& pairs)
{
  typedef boost::compressed_sparse_row_graph<boost::directedS> Graph;
  typedef boost::graph_traits<Graph>::edge_descriptor Edge;
  const std::size_t n = cost.size(), source = n, sink = n + 1;
  // Directed arcs in pairs (2k, 2k + 1), each the reverse of the other. A node on the source side
  // takes label 0 and cuts its arc to the sink, which carries cost[i][0] (less the common part).
  struct Arc { std::size_t from, to; double capacity; };
  std::vector<Arc> arc;
  arc.reserve(2 * (n + pairs.size()));
  for(std::size_t i = 0; i < n; ++i)
  {
    const double common = (std::min)(cost[i][0], cost[i][1]);
    if(cost[i][0] > common) { arc.push_back({i, sink, cost[i][0] - common}); arc.push_back({sink, i, 0.}); }
    else if(cost[i][1] > common) { arc.push_back({source, i, cost[i][1] - common}); arc.push_back({i, source, 0.}); }
  }
  for(const Binary_pair_term& p : pairs)
    if(p.weight > 0. && p.i != p.j)
    {
      arc.push_back({p.i, p.j, p.weight});
      arc.push_back({p.j, p.i, p.weight});
    }
  // arcs sorted by their tail: the graph keeps this order, so position = edge index
  std::vector<std::size_t> start, order;
  group_indices(arc.size(), n + 2, [&](std::size_t k) { return arc[k].from; }, [](std::size_t) { return true; },
                start, order);
  std::vector<std::size_t> position(arc.size());
  std::vector<std::pair<std::size_t, std::size_t> > sorted(arc.size());
  for(std::size_t e = 0; e < order.size(); ++e)
  {
    position[order[e]] = e;
    sorted[e] = std::make_pair(arc[order[e]].from, arc[order[e]].to);
  }
  const Graph graph(boost::edges_are_sorted, sorted.begin(), sorted.end(), n + 2);
  std::vector<double> capacity(arc.size()), residual(arc.size());
  std::vector<Edge> reverse(arc.size());
  for(std::size_t k = 0; k < arc.size(); ++k)
  {
    capacity[position[k]] = arc[k].capacity;
    reverse[position[k]] = Edge(arc[k ^ 1].from, position[k ^ 1]);
  }
  const auto edge_index = boost::get(boost::edge_index, graph);
  const auto vertex_index = boost::get(boost::vertex_index, graph);
  std::vector<boost::default_color_type> color(n + 2);
  std::vector<double> distance(n + 2);
  std::vector<Edge> predecessor(n + 2);
  boost::boykov_kolmogorov_max_flow(graph, boost::make_iterator_property_map(capacity.begin(), edge_index),
                                    boost::make_iterator_property_map(residual.begin(), edge_index),
                                    boost::make_iterator_property_map(reverse.begin(), edge_index),
                                    boost::make_iterator_property_map(predecessor.begin(), vertex_index),
                                    boost::make_iterator_property_map(color.begin(), vertex_index),
                                    boost::make_iterator_property_map(distance.begin(), vertex_index),
                                    vertex_index, source, sink);
  // the sink's search tree is white: those nodes are cut off from the source, label 1
  typedef boost::color_traits<boost::default_color_type> Colors;
  std::vector<std::uint8_t> label(n);
  for(std::size_t i = 0; i < n; ++i) label[i] = color[i] == Colors::white() ? 1 : 0;
  return label;
}

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_BINARY_MIN_CUT_H
