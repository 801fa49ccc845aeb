// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_PART_HIERARCHY_H
#define CGAL_PART_DECOMPOSITION_PART_HIERARCHY_H

#include <CGAL/Part_decomposition/input_validation.h>
#include <CGAL/Part_decomposition/parameters.h>
#include <CGAL/Part_decomposition/stage_results.h>
#include <CGAL/Part_decomposition/internal/toolbox/face_adjacency.h>
#include <CGAL/Part_decomposition/internal/parts/part_merging.h>
#include <CGAL/Part_decomposition/internal/parts/piece_grouping.h>
#include <CGAL/Part_decomposition/internal/parts/piece_regions.h>
#include <CGAL/Part_decomposition/piece_segmentation.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

// The package parameters of the hierarchy and of the cut at a number of parts.
struct Hierarchy_parameters
{
  bool has_number_of_parts = false;
  std::size_t number_of_parts = 0;
  double maximum_merge_cost = 0.;
};

template <typename NamedParameters>
Hierarchy_parameters read_hierarchy_parameters(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  namespace inp = Part_decomposition::internal_np;
  Hierarchy_parameters p;
  const std::optional<std::size_t> k = optional_parameter<std::size_t>(np, inp::number_of_parts);
  p.has_number_of_parts = k.has_value();
  p.number_of_parts = k.value_or(0);
  if(p.has_number_of_parts) check_parameter(p.number_of_parts >= 1, "number_of_parts");
  p.maximum_merge_cost = choose_parameter(get_parameter(np, inp::maximum_merge_cost), defaults::maximum_merge_cost);
  check_non_negative(p.maximum_merge_cost, "maximum_merge_cost");
  return p;
}

// Surfaces of two pieces closer than this fraction of the bounding box diagonal touch; a box is
// at least twice as thick (about one voxel of the default 64^3 grid).
constexpr double contact_fraction = 0.01;
// The weight of the concavity of the common boundary: parts meet along concave creases.
constexpr double merge_crease_weight = 0.05;
// Above the default parts, the weight of the smaller part's area fraction in the cost: large
// enough that size orders these merges (tuned on half A of the development and CAD-style sets
// told their part counts: 3 and 10 equal, 1 and 0.3 below; see the archive of RESULTS.md).
constexpr double merge_attachment_weight = 10.;
// Above the default parts, the cost from which a merge within a piece waits with the contacts: the
// size term of a part of 30% of the surface (tuned on half A of the CAD-style set told its coarse
// part counts: 2.5 to 3.5 equal, 2 and 4 below; see the archive of RESULTS.md).
constexpr double merge_within_piece_limit = 3.;

// The leaf boxes: the corners of each leaf's faces, boxed by `fit_box_to_points()`, leaf by leaf.
template <typename ConcurrencyTag, typename Corner>
std::vector<Part_box> leaf_boxes(std::size_t number_of_faces, const Corner& corner, const std::vector<std::size_t>& leaf,
                                 std::size_t number_of_leaves, const Eigen::Vector3d& origin)
{
  std::vector<Part_box> box(number_of_leaves);
  // the faces of each leaf in increasing order
  std::vector<std::size_t> start, order;
  group_indices(number_of_faces, number_of_leaves, [&](std::size_t i) { return leaf[i]; },
                [](std::size_t) { return true; }, start, order);
  for_each_range<ConcurrencyTag>(number_of_leaves, [&](std::size_t first, std::size_t last) {
    std::vector<Eigen::Vector3d> points;
    for(std::size_t l = first; l < last; ++l)
    {
      points.clear();
      for(std::size_t s = start[l]; s < start[l + 1]; ++s)
      {
        const std::size_t i = order[s];
        add_triangle_moments(box[l], corner(i, 0) - origin, corner(i, 1) - origin, corner(i, 2) - origin);
        for(int k = 0; k < 3; ++k) points.push_back(corner(i, k) - origin);
      }
      fit_box_to_points(box[l], points);
    }
  });
  return box;
}

// The value of a per-face label on each leaf, `none` if the leaf's faces disagree.
inline std::vector<std::size_t> label_of_leaves(const std::vector<std::size_t>& face_label, const std::vector<std::size_t>& leaf,
                                                std::size_t number_of_leaves, std::size_t none)
{
  std::vector<std::size_t> result(number_of_leaves, none);
  std::vector<std::uint8_t> seen(number_of_leaves, 0);
  for(std::size_t i = 0; i < leaf.size(); ++i)
  {
    std::size_t& r = result[leaf[i]];
    if(!seen[leaf[i]]) { seen[leaf[i]] = 1; r = face_label[i]; }
    else if(r != face_label[i]) r = none;
  }
  return result;
}

// Groups crumbs, repeated pieces and tiles (`grouped_pieces()`; `thickness` as in the merge costs):
// `leaf_piece` (per leaf its piece, `none` if several) becomes the piece of the group's root, and
// `attached` flags the leaves of grouped pieces that are not roots. `touching`: the touching leaves.
template <typename ConcurrencyTag, typename Corner>
void group_attached_leaves(std::size_t number_of_faces, const Corner& corner, const std::vector<std::size_t>& piece,
                           const std::vector<std::pair<std::size_t, std::size_t> >& touching, const Eigen::Vector3d& origin,
                           double thickness, std::vector<std::size_t>& leaf_piece, std::vector<std::uint8_t>& attached)
{
  if(touching.empty()) return;
  const std::size_t none = (std::numeric_limits<std::size_t>::max)(); // a leaf of several pieces
  const std::size_t number_of_pieces = *std::max_element(piece.begin(), piece.end()) + 1;
  std::vector<std::size_t> faces(number_of_pieces, 0);
  for(std::size_t i = 0; i < number_of_faces; ++i) ++faces[piece[i]];
  std::vector<std::pair<std::size_t, std::size_t> > contacts;
  for(const auto& e : touching)
  {
    const std::size_t a = leaf_piece[e.first], b = leaf_piece[e.second];
    if(a != none && b != none && a != b) contacts.emplace_back((std::min)(a, b), (std::max)(a, b));
  }
  std::sort(contacts.begin(), contacts.end());
  contacts.erase(std::unique(contacts.begin(), contacts.end()), contacts.end());
  const std::vector<std::size_t> root =
    grouped_pieces(leaf_boxes<ConcurrencyTag>(number_of_faces, corner, piece, number_of_pieces, origin), faces, contacts,
                   thickness);
  for(std::size_t l = 0; l < leaf_piece.size(); ++l)
    if(leaf_piece[l] != none && root[leaf_piece[l]] != leaf_piece[l])
    {
      leaf_piece[l] = root[leaf_piece[l]];
      attached[l] = 1;
    }
}

// The merge parameters at the scale of a mesh whose bounding box has corners `lo` and `hi`;
// `total_volume` becomes the volume of that box, each side at least twice the thickness.
inline Merge_parameters hierarchy_merge_parameters(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                                                   double maximum_merge_cost, double& total_volume)
{
  const double diagonal = (std::max)((hi - lo).norm(), std::numeric_limits<double>::min());
  Merge_parameters p;
  p.contact_distance = contact_fraction * diagonal;
  p.thickness = contact_fraction * diagonal;
  p.crease_weight = merge_crease_weight;
  p.attachment_from = maximum_merge_cost;
  p.attachment_weight = merge_attachment_weight;
  p.within_piece_limit = merge_within_piece_limit;
  total_volume = 1.;
  for(int d = 0; d < 3; ++d) total_volume *= (std::max)(hi[d] - lo[d], 2. * p.thickness);
  return p;
}

// Links the leaves that share an edge, once per pair, with the length of their common boundary and
// that length weighted by its concavity.
template <typename ConcurrencyTag, typename Corner>
void link_leaves_sharing_edges(const Face_adjacency& adj, const Corner& corner, const std::vector<std::size_t>& leaf,
                               const std::vector<std::size_t>& piece, const std::vector<int>& orientation,
                               Part_agglomeration& agglomeration)
{
  typedef std::pair<std::pair<std::size_t, std::size_t>, std::array<double, 2> > Shared_edge;
  constexpr std::size_t block = std::size_t(1) << 16;
  std::vector<std::vector<Shared_edge> > found((adj.number_of_faces + block - 1) / block);
  for_each_block<ConcurrencyTag>(adj.number_of_faces, block, [&](std::size_t b, std::size_t e) {
    for(std::size_t i = b; i < e; ++i)
      for(int k = 0; k < 3; ++k)
      {
        const std::size_t j = adj.neighbor[3 * i + k];
        if(j == Face_adjacency::no_face || leaf[j] <= leaf[i]) continue; // each edge once, from one side
        const double length = slot_length(corner, i, k);
        const double weight = edge_concavity(adj, i, k, orientation[piece[i]]);
        found[b / block].push_back({{leaf[i], leaf[j]}, {{length, length * weight}}});
      }
  });
  std::vector<Shared_edge> shared;
  for(const std::vector<Shared_edge>& f : found) shared.insert(shared.end(), f.begin(), f.end());
  // sorted, the edges of a pair of leaves follow each other and are summed in a fixed order
  std::sort(shared.begin(), shared.end());
  for(std::size_t e = 0; e < shared.size();)
  {
    std::size_t f = e;
    std::array<double, 2> sum = {{0., 0.}};
    for(; f < shared.size() && shared[f].first == shared[e].first; ++f)
    {
      sum[0] += shared[f].second[0];
      sum[1] += shared[f].second[1];
    }
    agglomeration.link(shared[e].first.first, shared[e].first.second, false, sum[0], sum[1]);
    e = f;
  }
}

// The leaf nodes of `h`: their faces, first face and area.
template <typename GeomTraits>
void fill_leaf_nodes(const Face_adjacency& adj, const std::vector<std::size_t>& leaf, Part_hierarchy<GeomTraits>& h)
{
  for(std::size_t i = 0; i < adj.number_of_faces; ++i)
  {
    Part_hierarchy_node<GeomTraits>& n = h.nodes[leaf[i]];
    if(n.number_of_faces == 0) n.first_face = i;
    ++n.number_of_faces;
    n.area += adj.area[i];
  }
}

// The number of faces of each group among the faces `0` to `number_of_faces - 1` (none if `group`
// is empty).
inline std::vector<std::size_t> faces_of_groups(const std::vector<std::size_t>& group, std::size_t number_of_faces)
{
  std::vector<std::size_t> group_faces;
  if(group.empty()) return group_faces;
  for(std::size_t i = 0; i < number_of_faces; ++i)
  {
    if(group[i] >= group_faces.size()) group_faces.resize(group[i] + 1, 0);
    ++group_faces[group[i]];
  }
  return group_faces;
}

// Every node of `h` from the merges of `agglomeration`, whose leaves `fill_leaf_nodes()` filled. A
// node with all the faces of its group (`group_faces`: per group) keeps the group's primitive, the
// others get their box.
template <typename GeomTraits>
void fill_merged_nodes(const Part_agglomeration& agglomeration, const std::vector<std::size_t>& group_faces,
                       const std::vector<Superquadric<GeomTraits> >& group_primitive, const Eigen::Vector3d& origin,
                       Part_hierarchy<GeomTraits>& h)
{
  typedef Part_hierarchy_node<GeomTraits> Node;
  const std::size_t none = Node::no_node;
  for(std::size_t m = 0; m < h.nodes.size(); ++m)
  {
    Node& n = h.nodes[m];
    n.children = agglomeration.children()[m];
    n.kind = agglomeration.kinds()[m];
    n.merge_cost = agglomeration.costs()[m];
    if(n.children[0] != none)
    {
      const Node &a = h.nodes[n.children[0]], &b = h.nodes[n.children[1]];
      n.area = a.area + b.area;
      n.number_of_faces = a.number_of_faces + b.number_of_faces;
      n.first_face = (std::min)(a.first_face, b.first_face);
      h.nodes[n.children[0]].parent = h.nodes[n.children[1]].parent = m;
    }
    const std::size_t g = agglomeration.groups()[m];
    if(g != none && g < group_primitive.size() && g < group_faces.size() && group_faces[g] == n.number_of_faces)
      n.primitive = group_primitive[g];
    else
      n.primitive = box_superquadric<GeomTraits>(agglomeration.boxes()[m], origin);
  }
}

// The hierarchy of the leaves of a mesh given by its face graph `adj` and the corners of its faces
// (`corner(i, k)`, input coordinates). `group` (per face, may be empty) is a coarser partition
// whose parts are unions of leaves, each explained by `group_primitive`; `piece` is per face;
// merges from `maximum_merge_cost` on are ordered by size first.
template <typename ConcurrencyTag, typename GeomTraits, typename Corner>
Part_hierarchy<GeomTraits> hierarchy_of_leaves(const Face_adjacency& adj, const Corner& corner,
                                               const std::vector<std::size_t>& leaf, std::size_t number_of_leaves,
                                               const std::vector<std::size_t>& subgroup,
                                               const std::vector<std::size_t>& group,
                                               const std::vector<Superquadric<GeomTraits> >& group_primitive,
                                               const std::vector<std::size_t>& piece,
                                               const std::vector<int>& orientation, double maximum_merge_cost)
{
  const std::size_t none = Part_hierarchy_node<GeomTraits>::no_node, nf = adj.number_of_faces;
  Part_hierarchy<GeomTraits> h;
  h.leaf = leaf;
  h.default_number_of_parts = group_primitive.size();
  if(nf == 0 || number_of_leaves == 0) return h;

  // the scale: the bounding box of the corners
  const Eigen::Vector3d origin = corner(0, 0);
  constexpr std::size_t block = std::size_t(1) << 16;
  std::vector<std::array<Eigen::Vector3d, 2> > block_box((nf + block - 1) / block, {{origin, origin}});
  for_each_block<ConcurrencyTag>(nf, block, [&](std::size_t b, std::size_t e) {
    std::array<Eigen::Vector3d, 2>& box = block_box[b / block];
    for(std::size_t i = b; i < e; ++i)
      for(int k = 0; k < 3; ++k) { box[0] = box[0].cwiseMin(corner(i, k)); box[1] = box[1].cwiseMax(corner(i, k)); }
  });
  Eigen::Vector3d lo = origin, hi = origin;
  for(const std::array<Eigen::Vector3d, 2>& box : block_box) { lo = lo.cwiseMin(box[0]); hi = hi.cwiseMax(box[1]); }
  double total_volume = 1.;
  const Merge_parameters p = hierarchy_merge_parameters(lo, hi, maximum_merge_cost, total_volume);

  const std::vector<std::size_t> leaf_group = group.empty() ? std::vector<std::size_t>(number_of_leaves, none)
                                                            : label_of_leaves(group, leaf, number_of_leaves, none);
  const std::vector<std::size_t> leaf_subgroup = subgroup.empty() ? std::vector<std::size_t>(number_of_leaves, none)
                                                                  : label_of_leaves(subgroup, leaf, number_of_leaves, none);
  const std::vector<std::size_t> leaf_piece = label_of_leaves(piece, leaf, number_of_leaves, none);
  std::vector<std::pair<std::size_t, std::size_t> > touching;
  if(std::any_of(leaf_piece.begin(), leaf_piece.end(), [&](std::size_t q) { return q != leaf_piece[0]; }))
    touching = touching_leaves(nf, corner, leaf, leaf_piece, p.contact_distance);
  std::vector<std::size_t> host_piece = leaf_piece;
  std::vector<std::uint8_t> attached(number_of_leaves, 0);
  group_attached_leaves<ConcurrencyTag>(nf, corner, piece, touching, origin, p.thickness, host_piece, attached);
  Part_agglomeration agglomeration(leaf_boxes<ConcurrencyTag>(nf, corner, leaf, number_of_leaves, origin), leaf_subgroup, leaf_group,
                                   host_piece, attached, p, total_volume);

  // links: leaves sharing an edge, and leaves of different pieces whose surfaces touch
  link_leaves_sharing_edges<ConcurrencyTag>(adj, corner, leaf, piece, orientation, agglomeration);
  // a grouped piece touches its group alone: screws do not glue a leg to the panel they hold
  for(const auto& e : touching)
    if(host_piece[e.first] == host_piece[e.second] || !(attached[e.first] || attached[e.second]))
      agglomeration.link(e.first, e.second, true);
  h.nodes.resize(agglomeration.run());
  fill_leaf_nodes(adj, leaf, h);
  fill_merged_nodes(agglomeration, faces_of_groups(group, nf), group_primitive, origin, h);
  return h;
}

} // namespace internal

/*!
\ingroup PkgPartDecompositionRef
builds the part hierarchy of a mesh from its finest parts, given by `face_part_map`: a binary merge
tree whose leaves are these parts and whose root is the whole mesh.

The parts are merged two at a time, greedily. Two parts may merge if they share an edge, if they
belong to different pieces (edge-connected components) whose surfaces come within 1% of the
bounding box diagonal of each other (a contact), or, once no such pair is left, if they are
neighbours in the Hilbert order of their centres (parts in separate places). Before the parts of a
piece merge, the pieces a person names with the piece they sit on join it (`Merge_kind::ATTACHED`):
a crumb, a piece of at most 0.02% of the surface's area touching a piece at least 10 times as
large (the smallest such piece), and a pattern, at least 20 congruent pieces (the same number of
faces, areas and box extents within 5%), each at most 0.5% of the surface and touching a piece at
least 3 times as large (the largest such piece, its host; the hosts may differ, as the frames of
several racks), with the pieces of at most twice their size that touch a host too (the keys of a
keyboard, of several widths). Tiles join one another the same way, their largest piece being the
root: flat pieces in contact (the smallest side of the box at most a quarter of the next), each at
most 1.5% of the surface, whose common box is as thin as they are and holds the volume of their two
boxes within 5% (the rows of a keyboard, side by side). A grouped piece keeps only its contacts
within its group. These merges are always below the default parts, so the pieces of a group are
one part by default and separate nodes of the tree. The other pairs
are taken by kind first, parts of one piece before parts in contact before the others, so that
the pieces of the mesh, with their groups, are a level of the tree, and within a kind by
increasing cost
\f[ c(a, b) = \frac{\max(0,\ V(a \cup b) - V(a) - V(b))}{V(M)} + 0.05\,\frac{C(a, b)}{L(a, b)}, \f]
where \f$V\f$ is the volume of the box, on the principal axes of the area moments of a part's
surface, that holds the part (its box-like superquadric), with a thickness of at least 1% of the
diagonal, \f$V(M)\f$ that of the bounding box of the mesh, \f$L(a, b)\f$ the length of the
common boundary of the two parts (0: the term is 0) and \f$C(a, b)\f$ that length weighted by
concavity (an edge counts with \f$\min(1, \theta / 60^\circ)\f$ if it is concave with dihedral angle
\f$\theta\f$, 0 if convex; open pieces are oriented as in `segment_pieces()`): two parts merge
early when one box explains their union about as well as their two boxes (two halves of one
plate, a knob on a door, the two parts of a limb that is straight), late when the union would
leave much space empty (a leg and the seat, two perpendicular plates). The box of a merged node
holds the boxes of its two children.

The merges go on in this order until the next one costs at least `maximum_merge_cost` or joins
parts that do not touch: these are the default parts (`Part_hierarchy::level_below_cost()`).
From there on, every merge that is not between parts of one assigned part costs
\f$c(a, b) + 10\,\min(A(a), A(b)) / A(M)\f$ instead (and at least `maximum_merge_cost`), with
\f$A\f$ the area of a part's surface and \f$A(M)\f$ that of the mesh: above the default parts, a
small part joins the part it is attached to (a handle its door, a pin its plate, the keys their
keyboard) before large parts merge. A merge within a piece that then costs at least 3 waits with
the merges between pieces in contact: two large parts of one piece (a lid and its base joined by a
hinge) are not one part attached to the other. The merges below keep their order, and with them the
default parts.

`build_part_hierarchy(tm, pieces, parts, np)` builds the hierarchy of a decomposition, whose default parts
are a level of the tree.

\tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph` whose faces are triangles
\tparam FacePartMap a model of `ReadablePropertyMap` with
`boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and `std::size_t` as value type
\tparam NamedParameters a sequence of named parameters

\param tm the mesh
\param face_part_map the finest part of each face, from `0` to `K - 1`
\param np an optional sequence of named parameters; this function reads `vertex_point_map`,
`face_index_map`, `geom_traits` (\ref PD_MeshParameters) and `maximum_merge_cost`
(\ref PD_ParameterTable)

\pre `CGAL::is_triangle_mesh(tm)` and the values of `face_part_map` are `0` to `K - 1`, each used.

\returns the hierarchy: `K` leaves, leaf `k` being part `k`, and `K - 1` merges. Every node's
primitive is its box-like superquadric. The result does not depend on the number of threads.

\par Complexity
\f$O(F \log F)\f$ for \f$F\f$ faces, plus \f$O(E \log E)\f$ for the \f$E\f$ pairs of parts that
are linked.

\throws Invalid_input (`INVALID_PARAMETER`) if a part id is not below the number of faces or
`maximum_merge_cost` is out of its range.
*/
template <typename TriangleMesh, typename FacePartMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Part_hierarchy<typename GetGeomTraits<TriangleMesh, NamedParameters>::type>
build_part_hierarchy(const TriangleMesh& tm, FacePartMap face_part_map,
                     const NamedParameters& np = CGAL::parameters::default_values())
{
  typedef typename GetGeomTraits<TriangleMesh, NamedParameters>::type GT;
  CGAL_precondition(CGAL::is_triangle_mesh(tm));
  const auto fim = CGAL::get_initialized_face_index_map(tm, np);
  const auto vpm = CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                                      get_const_property_map(CGAL::vertex_point, tm));
  const auto graph = internal::shared_piece_adjacency<CGAL::Sequential_tag>(tm, fim, vpm, np);
  const internal::Face_adjacency& adj = *graph;
  const Piece_segmentation pieces = internal::segment_pieces_of_graph<CGAL::Sequential_tag>(adj, internal::Piece_parameters());
  std::vector<std::size_t> leaf(adj.number_of_faces, 0);
  std::size_t number_of_leaves = 0;
  for(auto f : faces(tm))
  {
    const std::size_t k = std::size_t(get(face_part_map, f));
    internal::check_parameter(k < adj.number_of_faces, "face_part_map", "part ids below the number of faces");
    leaf[std::size_t(get(fim, f))] = k;
    number_of_leaves = (std::max)(number_of_leaves, k + 1);
  }
  const internal::Face_corners corners(tm, fim, vpm);
  return internal::hierarchy_of_leaves<CGAL::Sequential_tag, GT>(adj, corners, leaf, number_of_leaves, std::vector<std::size_t>(),
                                           std::vector<std::size_t>(), std::vector<Superquadric<GT> >(), pieces.piece,
                                           pieces.orientation, internal::read_hierarchy_parameters(np).maximum_merge_cost);
}

} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_PART_HIERARCHY_H
