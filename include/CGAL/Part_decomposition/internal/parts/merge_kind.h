// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_MERGE_KIND_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_MERGE_KIND_H

// Merge_kind, the kinds of merges of a Part_hierarchy in the order they are made, for the merge
// tree (part_merging.h) and the hierarchy (stage_results.h, which documents it: keep the two lists
// equal).

namespace CGAL {
namespace Part_decomposition {

enum class Merge_kind
{
  NONE,
  SAME_PRIMITIVE,
  SAME_PART,
  ATTACHED,
  SAME_PIECE,
  CONTACT,
  NO_CONTACT
};

namespace internal {

// Whether a merge goes beyond the default parts: it costs at least `maximum_cost` or joins parts
// that do not touch. The hierarchy's cut and its merge order share this rule.
inline bool merge_beyond_default_parts(Merge_kind kind, double cost, double maximum_cost)
{
  if(kind == Merge_kind::ATTACHED) return false; // grouped pieces are one default part
  return cost >= maximum_cost || kind == Merge_kind::NO_CONTACT;
}

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_MERGE_KIND_H
