// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_POTTS_ALPHA_EXPANSION_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_POTTS_ALPHA_EXPANSION_H

// Alpha expansion for a Potts energy whose members each have their own few candidate labels.
//
// Input:   a Label_problem: per member m, its options (label, cost), its current label (one of
//          its options) and its links (another member, or a fixed label, and a cost w >= 0)
// Output:  the labels of the members, each among its options, lowering (to a local minimum with
//          respect to expansion moves) sum_m cost_m(label_m) + sum_{links with different labels} w,
//          each link between two members counted once (both list it, with the same w).

#include <CGAL/Part_decomposition/internal/parts/binary_min_cut.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

// A labelling problem on members (faces, or clusters of faces): the candidate labels of each
// member with their costs, its current label, and its links to other members or to fixed labels.
struct Label_problem
{
  struct Link
  {
    std::size_t member; // or `fixed`
    std::int32_t fixed_label;
    double cost;
  };
  static constexpr std::size_t fixed = std::size_t(-1);
  std::vector<std::size_t> first = std::vector<std::size_t>(1, 0); // options of m: [first[m], first[m + 1])
  std::vector<std::int32_t> option;
  std::vector<double> option_cost;
  std::vector<std::int32_t> label;
  std::vector<std::vector<Link> > links;

  std::size_t size() const { return label.size(); }
  // sizes the problem for n members, `count(m)` options for member m (the options, labels and
  // links are then written member by member, by any thread)
  template <typename Count>
  void allocate(std::size_t n, const Count& count)
  {
    first.assign(n + 1, 0);
    for(std::size_t m = 0; m < n; ++m) first[m + 1] = first[m] + count(m);
    option.resize(first[n]);
    option_cost.resize(first[n]);
    label.resize(n);
    links.resize(n);
  }
  // the cost of label l for member m, or -1 if l is not among its options
  double cost(std::size_t m, std::int32_t l) const
  {
    for(std::size_t k = first[m]; k < first[m + 1]; ++k)
      if(option[k] == l) return option_cost[k];
    return -1.;
  }
};

// One expansion move of label `alpha` (Boykov, Veksler, Zabih 2001), solved exactly on the members
// that may take `alpha`, the others fixed: the restriction to the support of `alpha` is what makes
// large sets cheap. Between two members with different labels, keeping both costs w and any change
// w: that is a Potts term of w/2 plus w/2 on keeping each. Returns whether the energy decreased.
// `holders`: the members that have `alpha` among their options; `rank`: all `fixed` on entry and exit.
inline bool expand_label(Label_problem& p, std::int32_t alpha, const std::vector<std::size_t>& holders,
                         std::vector<std::size_t>& rank)
{
  std::vector<std::size_t> support;
  std::vector<std::array<double, 2> > cost; // [keep, alpha] per member of the support
  for(std::size_t m : holders)
    if(p.label[m] != alpha)
    {
      rank[m] = support.size();
      support.push_back(m);
      cost.push_back({p.cost(m, p.label[m]), p.cost(m, alpha)});
    }
  if(support.empty()) return false;
  std::vector<Binary_pair_term> pairs;
  for(std::size_t s = 0; s < support.size(); ++s)
  {
    const std::size_t m = support[s];
    for(const Label_problem::Link& l : p.links[m])
    {
      const std::size_t t = l.member == Label_problem::fixed ? Label_problem::fixed : rank[l.member];
      if(t == Label_problem::fixed)
      {
        const std::int32_t other = l.member == Label_problem::fixed ? l.fixed_label : p.label[l.member];
        if(other != p.label[m]) cost[s][0] += l.cost;
        if(other != alpha) cost[s][1] += l.cost;
      }
      else if(t > s) // each link once
      {
        if(p.label[l.member] == p.label[m])
          pairs.push_back({s, t, l.cost});
        else
        {
          pairs.push_back({s, t, 0.5 * l.cost});
          cost[s][0] += 0.5 * l.cost;
          cost[t][0] += 0.5 * l.cost;
        }
      }
    }
  }
  const std::vector<std::uint8_t> move = minimum_binary_labelling(cost, pairs);
  for(std::size_t m : support) rank[m] = Label_problem::fixed;
  double keep_all = 0., energy = 0.; // the terms that involve the support, before and after
  for(std::size_t s = 0; s < support.size(); ++s)
  {
    keep_all += cost[s][0];
    energy += cost[s][move[s]];
  }
  for(const Binary_pair_term& t : pairs)
    if(move[t.i] != move[t.j]) energy += t.weight;
  if(!(energy < keep_all * (1. - 1e-12))) return false;
  for(std::size_t s = 0; s < support.size(); ++s)
    if(move[s] == 1) p.label[support[s]] = alpha;
  return true;
}

// Alpha expansion: cycles of one move per label, by increasing label, until no move helps.
inline void minimize_labels(Label_problem& p)
{
  constexpr int maximum_cycles = 8;
  std::vector<std::int32_t> labels(p.option);
  std::sort(labels.begin(), labels.end());
  labels.erase(std::unique(labels.begin(), labels.end()), labels.end());
  std::vector<std::vector<std::size_t> > holders(labels.size());
  for(std::size_t m = 0; m < p.size(); ++m)
    for(std::size_t k = p.first[m]; k < p.first[m + 1]; ++k)
      holders[std::size_t(std::lower_bound(labels.begin(), labels.end(), p.option[k]) - labels.begin())].push_back(m);
  std::vector<std::size_t> rank(p.size(), Label_problem::fixed);
  for(int cycle = 0; cycle < maximum_cycles; ++cycle)
  {
    bool decreased = false;
    for(std::size_t a = 0; a < labels.size(); ++a)
      decreased = expand_label(p, labels[a], holders[a], rank) || decreased;
    if(!decreased) break;
  }
}

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_POTTS_ALPHA_EXPANSION_H
