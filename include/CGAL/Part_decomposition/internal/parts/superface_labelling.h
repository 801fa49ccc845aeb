// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_SUPERFACE_LABELLING_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_SUPERFACE_LABELLING_H

// The final labelling of a mesh whose faces are much smaller than a voxel: the Potts energy of
// `cut_face_labels()` on superfaces, the edge-connected faces whose centroids lie in one cell of a
// grid, each weighed as one point (its faces' area-weighted centroid, their area); then face by
// face on the superfaces next to a cut, the others fixed. Candidates are asked for once per
// superface and once per face of those superfaces, not once per face.
//
// Inputs:  adj, corners, orientation, edge_scale  as for cut_face_labels() (F faces)
//          superfaces     the superfaces of adj (make_superfaces())
//          face_point(i)  Weighted_point: the centroid of face i in the frame of the candidates,
//                         and its area in the unit of their costs
//          candidates_of(points)  Face_candidates: the candidates of each weighted point
// Output:  the label of each face (F values).

#include <CGAL/Part_decomposition/internal/parts/boundary_graph_cut.h>
#include <CGAL/Part_decomposition/internal/parts/potts_alpha_expansion.h>
#include <CGAL/Part_decomposition/internal/toolbox/face_adjacency.h>
#include <CGAL/Part_decomposition/internal/toolbox/toolbox.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

struct Weighted_point
{
  Vec3 point;
  double area;
};

// The cell of the superfaces, in voxels: the data costs of the final labelling vary at the scale
// of a voxel, and the bounding probes reach one voxel away.
constexpr double cluster_cell = 0.5;

// The side of the superfaces' cells in mesh units, for a voxel of `voxel_size` in the normalized
// cube and a normalization of scale `scale`; every stage derives it here, so that they share them.
inline double superface_cell(double voxel_size, double scale)
{
  return cluster_cell * voxel_size / scale;
}

// Whether the superfaces are worth using: at most half as many as the faces.
inline bool superfaces_pay(const Superfaces& sf, std::size_t number_of_faces)
{
  return 2 * sf.size() <= number_of_faces;
}

// The superfaces of cells of side `cell` (mesh units, the frame of adj.centroid).
template <typename ConcurrencyTag>
Superfaces make_superfaces(const Face_adjacency& adj, double cell)
{
  const std::vector<std::array<double, 3> > key = face_cells<ConcurrencyTag>(adj, cell);
  Superfaces sf;
  const std::size_t n = face_components<ConcurrencyTag>(adj, [&](std::size_t i, int k) {
    return key[i] == key[adj.neighbor[3 * i + std::size_t(k)]];
  }, sf.of_face);
  group_indices(adj.number_of_faces, n, [&](std::size_t i) { return sf.of_face[i]; }, [](std::size_t) { return true; },
                sf.start, sf.face);
  return sf;
}

// The superfaces of `plain`, the graph `face_adjacency_of()` of a mesh, in cells of side `cell`;
// when `np` holds the face graphs of `decompose()` (whose `plain` it is), made once for its stages.
template <typename ConcurrencyTag, typename NamedParameters>
std::shared_ptr<const Superfaces> shared_superfaces(const Face_adjacency& plain, double cell, const NamedParameters& np)
{
  const Face_graphs* graphs = face_graphs_of(np);
  if(graphs == nullptr) return std::make_shared<const Superfaces>(make_superfaces<ConcurrencyTag>(plain, cell));
  Face_graphs::Superface_cache& cache = *graphs->superfaces;
  const std::lock_guard<std::mutex> lock(cache.mutex);
  if(!cache.superfaces || cache.cell != cell)
  {
    cache.superfaces = std::make_shared<const Superfaces>(make_superfaces<ConcurrencyTag>(plain, cell));
    cache.cell = cell;
  }
  return cache.superfaces;
}

// Per superface, its faces' area-weighted centroid and their area, summed in face order.
template <typename ConcurrencyTag, typename FacePoint>
std::vector<Weighted_point> superface_points(const Superfaces& sf, const FacePoint& face_point)
{
  std::vector<Weighted_point> out(sf.size());
  for_each_range<ConcurrencyTag>(sf.size(), [&](std::size_t b, std::size_t e) {
    for(std::size_t s = b; s < e; ++s)
    {
      Weighted_point w{{{0., 0., 0.}}, 0.};
      for(std::size_t r = sf.start[s]; r < sf.start[s + 1]; ++r)
      {
        const Weighted_point f = face_point(sf.face[r]);
        for(std::size_t a = 0; a < 3; ++a) w.point[a] += f.area * f.point[a];
        w.area += f.area;
      }
      if(w.area > 0.)
        for(std::size_t a = 0; a < 3; ++a) w.point[a] /= w.area;
      else
        w.point = face_point(sf.face[sf.start[s]]).point;
      out[s] = w;
    }
  }, 256);
  return out;
}

// The problem on all superfaces: a superface may take the candidates of its point and starts with
// the cheapest; a cut between two superfaces costs the cut edges between them.
template <typename ConcurrencyTag>
Label_problem superface_problem(const Face_adjacency& adj, const Face_corners& corners,
                                const std::vector<int>& orientation, double edge_scale, const Superfaces& sf,
                                const Face_candidates& candidates)
{
  Label_problem p;
  p.allocate(sf.size(), [&](std::size_t s) { return std::size_t(candidates.size(s)); });
  for_each_range<ConcurrencyTag>(sf.size(), [&](std::size_t b, std::size_t e) {
    for(std::size_t s = b; s < e; ++s)
    {
      copy_options(candidates, s, p, s);
      p.label[s] = candidates.label[s][0];
      for(std::size_t r = sf.start[s]; r < sf.start[s + 1]; ++r)
        for(int k = 0; k < 3; ++k)
        {
          const std::size_t i = sf.face[r], j = adj.neighbor[3 * i + std::size_t(k)];
          if(j == Face_adjacency::no_face || sf.of_face[j] == s) continue;
          p.links[s].push_back({sf.of_face[j], -1, slot_cut_cost(adj, corners, orientation, i, k, edge_scale)});
        }
      merge_parallel_links(p.links[s]);
    }
  }, 256);
  return p;
}

// The faces of the superfaces with a face next to another label, increasing, and the rank of each
// face among them (Label_problem::fixed for the others).
template <typename ConcurrencyTag>
std::vector<std::size_t> faces_next_to_cuts(const Face_adjacency& adj, const Superfaces& sf,
                                            const std::vector<std::int32_t>& face_label,
                                            std::vector<std::size_t>& rank)
{
  std::vector<std::uint8_t> refine(sf.size(), 0);
  for_each_range<ConcurrencyTag>(sf.size(), [&](std::size_t b, std::size_t e) {
    for(std::size_t s = b; s < e; ++s)
      for(std::size_t r = sf.start[s]; r < sf.start[s + 1] && !refine[s]; ++r)
        for(int k = 0; k < 3; ++k)
        {
          const std::size_t i = sf.face[r], j = adj.neighbor[3 * i + std::size_t(k)];
          if(j != Face_adjacency::no_face && face_label[j] != face_label[i]) refine[s] = 1;
        }
  }, 256);
  std::vector<std::size_t> band;
  rank.assign(adj.number_of_faces, Label_problem::fixed);
  for(std::size_t i = 0; i < adj.number_of_faces; ++i)
    if(refine[sf.of_face[i]])
    {
      rank[i] = band.size();
      band.push_back(i);
    }
  return band;
}

// The edge-connected sets of the faces `band` (`rank`: of each face in it, or fixed): per rank, its
// set, numbered by first rank; returns the number of sets.
inline std::size_t band_sets(const Face_adjacency& adj, const std::vector<std::size_t>& band,
                             const std::vector<std::size_t>& rank, std::vector<std::size_t>& set)
{
  Index_sets sets(band.size());
  for(std::size_t m = 0; m < band.size(); ++m)
    for(int k = 0; k < 3; ++k)
    {
      const std::size_t j = adj.neighbor[3 * band[m] + std::size_t(k)];
      if(j != Face_adjacency::no_face && rank[j] != Label_problem::fixed) sets.unite(m, rank[j]);
    }
  set.resize(band.size());
  for(std::size_t m = 0; m < band.size(); ++m) set[m] = sets.find(m);
  return renumber_by_first_face(set);
}

// Relabels face by face the faces of the superfaces next to a cut, each edge-connected set of them
// on its own, the other faces fixed: each starts with its superface's label if it is one of its own
// candidates, else with its cheapest.
template <typename ConcurrencyTag, typename FacePoint, typename CandidatesOf>
void refine_next_to_cuts(const Face_adjacency& adj, const Face_corners& corners, const std::vector<int>& orientation,
                         double edge_scale, const Superfaces& sf, const FacePoint& face_point,
                         const CandidatesOf& candidates_of, std::vector<std::int32_t>& face_label)
{
  std::vector<std::size_t> rank, set, start, order;
  const std::vector<std::size_t> band = faces_next_to_cuts<ConcurrencyTag>(adj, sf, face_label, rank);
  std::vector<Weighted_point> points(band.size());
  for_each_range<ConcurrencyTag>(band.size(), [&](std::size_t b, std::size_t e) {
    for(std::size_t m = b; m < e; ++m) points[m] = face_point(band[m]);
  }, 1024);
  const Face_candidates candidates = candidates_of(points);
  std::vector<std::int32_t> start_label(band.size());
  for(std::size_t m = 0; m < band.size(); ++m)
  {
    const std::int32_t l = face_label[band[m]];
    start_label[m] = candidates.find(m, l) < 0 ? candidates.label[m][0] : l;
  }
  const std::size_t number_of_sets = band_sets(adj, band, rank, set);
  group_indices(band.size(), number_of_sets, [&](std::size_t m) { return set[m]; }, [](std::size_t) { return true; },
                start, order);
  std::vector<std::size_t> local(band.size()); // the rank of each face of the band in its set
  for(std::size_t r = 0; r < order.size(); ++r) local[order[r]] = r - start[set[order[r]]];
  // the sets write the faces of the band only: the others are read where they are
  const auto label_of = [&](std::size_t j) {
    return rank[j] == Label_problem::fixed ? face_label[j] : start_label[rank[j]];
  };
  const auto label_set = [&](std::size_t c, std::vector<std::size_t>& faces) {
    faces.clear();
    for(std::size_t r = start[c]; r < start[c + 1]; ++r) faces.push_back(band[order[r]]);
    const auto rank_of = [&](std::size_t j) { return rank[j] == Label_problem::fixed ? rank[j] : local[rank[j]]; };
    Label_problem fine = face_problem<CGAL::Sequential_tag>(adj, corners, candidates, orientation, edge_scale, faces,
                                                            rank_of, label_of,
                                                            [&](std::size_t m) { return order[start[c] + m]; });
    minimize_labels(fine);
    for(std::size_t m = 0; m < faces.size(); ++m) face_label[faces[m]] = fine.label[m];
  };
  std::vector<std::size_t> sets(number_of_sets);
  std::iota(sets.begin(), sets.end(), std::size_t(0));
  label_sets_side_by_side<ConcurrencyTag>(sets, [&](std::size_t c) { return start[c + 1] - start[c]; }, label_set);
}

// The label of each face (see the top of this file). The result does not depend on the number of
// threads.
template <typename ConcurrencyTag, typename FacePoint, typename CandidatesOf>
std::vector<std::int32_t> superface_labels(const Face_adjacency& adj, const Face_corners& corners,
                                           const std::vector<int>& orientation, double edge_scale,
                                           const Superfaces& sf, const FacePoint& face_point,
                                           const CandidatesOf& candidates_of)
{
  Label_problem p = superface_problem<ConcurrencyTag>(adj, corners, orientation, edge_scale, sf,
                                                      candidates_of(superface_points<ConcurrencyTag>(sf, face_point)));
  minimize_labels(p);
  std::vector<std::int32_t> face_label(adj.number_of_faces);
  for_each_range<ConcurrencyTag>(adj.number_of_faces, [&](std::size_t b, std::size_t e) {
    for(std::size_t i = b; i < e; ++i) face_label[i] = p.label[sf.of_face[i]];
  }, 4096);
  refine_next_to_cuts<ConcurrencyTag>(adj, corners, orientation, edge_scale, sf, face_point, candidates_of, face_label);
  return face_label;
}

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_SUPERFACE_LABELLING_H
