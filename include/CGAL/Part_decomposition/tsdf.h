// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_TSDF_H
#define CGAL_PART_DECOMPOSITION_TSDF_H

#include <CGAL/Part_decomposition/stage_results.h>
#include <CGAL/Part_decomposition/Voxel_grid.h>
#include <CGAL/Part_decomposition/input_validation.h>
#include <CGAL/Part_decomposition/normalization.h>
#include <CGAL/Part_decomposition/parameters.h>
#include <CGAL/Part_decomposition/internal/grid_morphology.h>
#include <CGAL/Part_decomposition/internal/mesh_voxelization.h>
#include <CGAL/Part_decomposition/internal/parameter_checks.h>
#include <CGAL/Part_decomposition/internal/toolbox.h>
#include <CGAL/Part_decomposition/internal/triangle_distance.h>
#include <CGAL/Part_decomposition/internal/triangle_soup_aabb_tree.h>
#include <CGAL/Part_decomposition/internal/winding_number.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

namespace CGAL {
namespace Part_decomposition {



namespace internal {

// Gives undecided surface voxels the flag of a 6-adjacent decided voxel whose centre they see
// without crossing a triangle, in `rounds` rounds (a voxel decided in one round passes its flag on
// in the next); the voxels just outside the grid count as decided outside voxels. Exact for a
// closed surface: an uncrossed segment joins two points of the same side.
// A segment between adjacent centres lies in the two voxels: only their triangles are tested.
// Neighbours are tried in a fixed order and rounds are synchronous: the result is deterministic.
template <typename ConcurrencyTag>
void spread_to_surface_voxels(const std::vector<Triangle_points>& tris, const Surface_voxels& sv, int r,
                              int rounds, std::vector<std::uint8_t>& inside, std::vector<std::uint8_t>& decided)
{
  const std::size_t R = std::size_t(r), size = R * R * R;
  const Voxel_grid<std::uint8_t>& S = sv.mask;
  typedef CGAL::Epick::Point_3 P;
  auto point = [](const Vec3& p) { return P(p[0], p[1], p[2]); };
  auto meets_triangles_of = [&](const CGAL::Epick::Segment_3& seg, std::size_t voxel) {
    for(std::size_t t = sv.offsets[voxel]; t < sv.offsets[voxel + 1]; ++t)
    {
      const Triangle_points& T = tris[sv.triangles[t]];
      const CGAL::Epick::Triangle_3 triangle(point(T[0]), point(T[1]), point(T[2]));
      // a zero-area triangle separates nothing (and do_intersect() requires a proper one)
      if(!triangle.is_degenerate() && CGAL::do_intersect(seg, triangle)) return true;
    }
    return false;
  };
  std::vector<std::size_t> pending;
  for(std::size_t idx = 0; idx < size; ++idx)
    if(S[idx] != 0 && decided[idx] == 0) pending.push_back(idx);
  for(int round = 0; round < rounds && !pending.empty(); ++round)
  {
    std::vector<std::uint8_t> next_inside = inside, next_decided = decided;
    for_each_range<ConcurrencyTag>(pending.size(), [&](std::size_t b, std::size_t e) {
      for(std::size_t n = b; n < e; ++n)
      {
        const std::size_t idx = pending[n];
        const std::array<int, 3> ijk = S.coordinates(idx);
        const P c = point(S.center(idx));
        // not for_each_face_neighbor(): the neighbours outside the grid count here
        for(int dir = 0; dir < 6; ++dir)
        {
          std::array<int, 3> q = ijk;
          q[dir / 2] += (dir % 2) ? 1 : -1;
          // The layer around the grid is outside (the mesh lies in the cube) and holds no triangle.
          const bool in_grid = S.contains(q[0], q[1], q[2]);
          const std::size_t nb = in_grid ? S.index(q[0], q[1], q[2]) : size;
          if(in_grid && decided[nb] == 0) continue;
          const double h = 1. / double(r);
          const P other(-0.5 + (q[0] + 0.5) * h, -0.5 + (q[1] + 0.5) * h, -0.5 + (q[2] + 0.5) * h);
          const CGAL::Epick::Segment_3 seg(c, other);
          if(meets_triangles_of(seg, idx) || (in_grid && S[nb] != 0 && meets_triangles_of(seg, nb))) continue;
          next_inside[idx] = in_grid ? inside[nb] : 0;
          next_decided[idx] = 1;
          break;
        }
      }
    });
    inside.swap(next_inside);
    decided.swap(next_decided);
    std::vector<std::size_t> still;
    for(std::size_t idx : pending)
      if(decided[idx] == 0) still.push_back(idx);
    pending.swap(still);
  }
}

// Inside flags by the generalized winding number: evaluated at the centres of the non-surface
// voxels next to the surface voxels, spread by a breadth-first flood fill through non-surface
// voxels (from the evaluated voxels, in linear-index order), then passed on to the surface voxels
// by uncrossed segments; the surface voxels left get their own evaluation.
template <typename ConcurrencyTag>
std::vector<std::uint8_t> inside_by_winding_number(const std::vector<Triangle_points>& tris,
                                                   const Surface_voxels& sv, int r)
{
  const std::size_t R = std::size_t(r), size = R * R * R;
  const Voxel_grid<std::uint8_t>& S = sv.mask;
  std::vector<std::uint8_t> inside(size, 0), decided(size, 0);
  std::vector<std::size_t> shell;
  for(std::size_t idx = 0; idx < size; ++idx)
  {
    if(S[idx] != 0) continue;
    bool next_to_surface = false;
    for_each_face_neighbor(idx, R, [&](std::size_t n) { next_to_surface = next_to_surface || S[n] != 0; });
    if(next_to_surface) shell.push_back(idx);
  }
  const Fast_winding_number wn(tris);
  auto evaluate = [&](const std::vector<std::size_t>& voxels) {
    for_each_range<ConcurrencyTag>(voxels.size(), [&](std::size_t b, std::size_t e) {
      for(std::size_t n = b; n < e; ++n)
      {
        const std::size_t idx = voxels[n];
        inside[idx] = std::abs(wn(S.center(idx))) > 0.5 ? 1 : 0;
        decided[idx] = 1;
      }
    });
  };
  evaluate(shell);
  std::vector<std::size_t> queue(shell);
  queue.reserve(size);
  for(std::size_t head = 0; head < queue.size(); ++head)
  {
    const std::size_t idx = queue[head];
    for_each_face_neighbor(idx, R, [&](std::size_t n) {
      if(decided[n] == 0 && S[n] == 0)
      {
        decided[n] = 1;
        inside[n] = inside[idx];
        queue.push_back(n);
      }
    });
  }
  spread_to_surface_voxels<ConcurrencyTag>(tris, sv, r, 3, inside, decided);
  std::vector<std::size_t> left;
  for(std::size_t idx = 0; idx < size; ++idx)
    if(decided[idx] == 0) left.push_back(idx);
  evaluate(left);
  return inside;
}

// Inside flags by ray votes (`ray_votes()`): inside if the six axis rays see a non-zero winding
// number, outside if at most three do; in between (the rays that leave through a hole, or the dips
// of a wavy sheet, which four or five rays cross) the generalized winding number at the centre
// decides, |w| > 1/2.
template <typename ConcurrencyTag>
std::vector<std::uint8_t> inside_by_ray_votes(const std::vector<Triangle_points>& tris, int r)
{
  std::vector<std::uint8_t> inside = ray_votes<ConcurrencyTag>(tris, r);
  std::vector<std::size_t> undecided;
  for(std::size_t v = 0; v < inside.size(); ++v)
    if(inside[v] == 4 || inside[v] == 5) undecided.push_back(v);
    else inside[v] = inside[v] == 6 ? 1 : 0;
  if(undecided.empty()) return inside;
  const Fast_winding_number wn(tris);
  const Voxel_grid<std::uint8_t> frame(r, 0); // voxel centres
  for_each_range<ConcurrencyTag>(undecided.size(), [&](std::size_t b, std::size_t e) {
    for(std::size_t n = b; n < e; ++n)
      inside[undecided[n]] = std::abs(wn(frame.center(undecided[n]))) > 0.5 ? 1 : 0;
  });
  return inside;
}

// Inside flags by flood fill: the non-surface voxels connected to the border are outside, the
// other non-surface voxels inside; surface voxels take the flag of a voxel they see without
// crossing a triangle (at most three steps away, so that a hole smaller than a voxel cannot leak
// the outside far along the surface) and are inside otherwise.
template <typename ConcurrencyTag>
std::vector<std::uint8_t> inside_by_flood_fill(const std::vector<Triangle_points>& tris,
                                               const Surface_voxels& sv, int r)
{
  const std::size_t size = sv.mask.size();
  const Voxel_grid<std::uint8_t> exterior = border_connected_complement(sv.mask);
  std::vector<std::uint8_t> inside(size, 0), decided(size, 0);
  for(std::size_t idx = 0; idx < size; ++idx)
  {
    decided[idx] = sv.mask[idx] == 0 ? 1 : 0;
    inside[idx] = (sv.mask[idx] == 0 && exterior[idx] == 0) ? 1 : 0;
  }
  spread_to_surface_voxels<ConcurrencyTag>(tris, sv, r, 3, inside, decided);
  for(std::size_t idx = 0; idx < size; ++idx)
    if(decided[idx] == 0) inside[idx] = 1;
  return inside;
}

// The band of the distances, for both ways of computing them: a voxel centre can be closer than
// `tau` to the surface only if its squared distance, in voxels, to the nearest surface-voxel centre
// is below this (tau plus half a voxel diagonal).
inline double squared_band_reach(int r, double tau)
{
  const double reach = tau * double(r) + 0.5 * std::sqrt(3.) + 1e-6;
  return reach * reach;
}

// The voxels whose centres lie within `tau` of each triangle's box, `{i0, i1, j0, j1, k0, k1}`
// (inclusive, one voxel wider for the roundings), and the number of those voxels over all triangles.
inline std::pair<std::vector<std::array<int, 6> >, double>
voxels_near_triangle_boxes(const std::vector<Triangle_points>& tris, int r, double tau)
{
  const double h = 1. / double(r);
  std::vector<std::array<int, 6> > boxes(tris.size());
  double count = 0.;
  for(std::size_t t = 0; t < tris.size(); ++t)
  {
    double n = 1.;
    for(int a = 0; a < 3; ++a)
    {
      const double lo = (std::min)({tris[t][0][a], tris[t][1][a], tris[t][2][a]}) - tau;
      const double hi = (std::max)({tris[t][0][a], tris[t][1][a], tris[t][2][a]}) + tau;
      // centre of voxel i: -0.5 + (i + 0.5) h
      const int i0 = (std::max)(0, int(std::floor((lo + 0.5) / h - 0.5)) - 1);
      const int i1 = (std::min)(r - 1, int(std::ceil((hi + 0.5) / h - 0.5)) + 1);
      boxes[t][2 * a] = i0;
      boxes[t][2 * a + 1] = i1;
      n *= double((std::max)(i1 - i0 + 1, 0));
    }
    count += n;
  }
  return std::make_pair(std::move(boxes), count);
}

// The squared distance to the closest triangle, capped at tau^2, at every voxel centre, each
// triangle swept over the voxels of its box widened by tau (`voxels_near_triangle_boxes()`): the
// minimum over a set of triangles that holds the closest one wherever it is closer than tau, with
// the distance function of the tree's queries, so the same values. One thread per z-layer: the
// result does not depend on the thread count.
template <typename ConcurrencyTag>
Voxel_grid<double> swept_squared_distances(const std::vector<Triangle_points>& tris,
                                           const std::vector<std::array<int, 6> >& boxes, int r, double tau)
{
  const std::size_t R = std::size_t(r);
  // the triangles of each z-layer, in triangle order
  std::vector<std::size_t> first(R + 1, 0);
  for(const std::array<int, 6>& b : boxes)
    for(int k = b[4]; k <= b[5]; ++k) ++first[std::size_t(k) + 1];
  for(std::size_t k = 0; k < R; ++k) first[k + 1] += first[k];
  std::vector<std::uint32_t> layer_triangles(first[R]);
  std::vector<std::size_t> next(first.begin(), first.end() - 1);
  for(std::size_t t = 0; t < boxes.size(); ++t)
    for(int k = boxes[t][4]; k <= boxes[t][5]; ++k) layer_triangles[next[std::size_t(k)]++] = std::uint32_t(t);

  Voxel_grid<double> out(r, tau * tau);
  for_each_range<ConcurrencyTag>(R, [&](std::size_t kb, std::size_t ke) {
    for(std::size_t k = kb; k < ke; ++k)
      for(std::size_t n = first[k]; n < first[k + 1]; ++n)
      {
        const std::uint32_t t = layer_triangles[n];
        const Triangle_points& T = tris[t];
        for(int j = boxes[t][2]; j <= boxes[t][3]; ++j)
          for(int i = boxes[t][0]; i <= boxes[t][1]; ++i)
          {
            const std::size_t idx = std::size_t(i) + R * (std::size_t(j) + R * k);
            const double d = squared_distance_to_triangle(out.center(idx), T[0], T[1], T[2]);
            if(d < out[idx]) out[idx] = d;
          }
      }
  });
  return out;
}

// Unsigned distances (normalized units, clipped to `tau`) at the voxel centres that can be closer
// than `tau` to the surface, `tau` elsewhere. The distance from a centre to the surface is at least
// its distance to the nearest surface-voxel centre minus half a voxel diagonal: beyond
// tau + sqrt(3)/2 voxels nothing is queried. Each query is an exact closest-triangle search in
// CGAL's AABB tree of the triangles, nearest child first, whose initial bound is the distance to
// the closest triangle of the previous voxel of the row, or to the triangles of the nearest surface
// voxel, capped at tau. The tree is built before the parallel loop; rows are processed whole by
// one thread, so the result does not depend on the thread count. The tree keeps its own copy of
// the triangles: `release`, if given, is `&tris`, emptied once the tree is built (a hundred
// megabytes on a million faces, while the queries run).
template <typename ConcurrencyTag>
Voxel_grid<double> clipped_distance_by_tree(const std::vector<Triangle_points>& tris, const Surface_voxels& sv, int r,
                                            double tau, std::vector<Triangle_points>* release)
{
  const std::size_t R = std::size_t(r);
  const double reach2 = squared_band_reach(r, tau);
  Voxel_grid<std::size_t> nearest;
  Voxel_grid<double> d2;
  std::unique_ptr<const Triangle_soup_aabb_tree> tree_holder;
  // CGAL builds the tree sequentially: next to the surface-voxel EDT when threads are available.
  run_side_by_side<ConcurrencyTag>([&] { tree_holder.reset(new Triangle_soup_aabb_tree(tris)); },
                                   [&] { d2 = squared_distance_transform<ConcurrencyTag>(sv.mask, false, &nearest); });
  const Triangle_soup_aabb_tree& tree = *tree_holder;
  if(release) std::vector<Triangle_points>().swap(*release);

  Voxel_grid<double> out(r, tau);
  const double tau2 = tau * tau;
  for_each_range<ConcurrencyTag>(R * R, [&](std::size_t b, std::size_t e) {
    for(std::size_t row = b; row < e; ++row)
    {
      bool has_previous = false;
      std::uint32_t previous = 0;
      for(std::size_t i = 0; i < R; ++i)
      {
        const std::size_t idx = i + R * row;
        if(!(d2[idx] < reach2))
        {
          has_previous = false;
          continue;
        }
        const Vec3 c = out.center(idx);
        double bound2 = std::numeric_limits<double>::infinity();
        std::uint32_t bound_triangle = 0;
        auto try_triangle = [&](std::uint32_t t) {
          const Triangle_points tri = tree.triangle(t);
          const double d = squared_distance_to_triangle(c, tri[0], tri[1], tri[2]);
          if(d < bound2 || (d == bound2 && t < bound_triangle))
          {
            bound2 = d;
            bound_triangle = t;
          }
        };
        if(has_previous)
          try_triangle(previous);
        else
        {
          const std::size_t v = nearest[idx];
          for(std::size_t k = sv.offsets[v]; k < sv.offsets[v + 1]; ++k) try_triangle(sv.triangles[k]);
        }
        // Nothing beyond tau matters: the search is cut there.
        const bool capped = !(bound2 < tau2);
        if(capped) bound2 = tau2;
        const std::pair<std::uint32_t, double> best = tree.closest(c, bound2, bound_triangle);
        has_previous = best.second < tau2 || !capped;
        previous = best.first;
        out[idx] = (std::min)(std::sqrt(best.second), tau);
      }
    }
  });
  return out;
}

// clipped_distance_by_tree()'s values by sweeping each triangle over the voxels near its box
// (`boxes`, from voxels_near_triangle_boxes()): the band is that of the distance transform.
template <typename ConcurrencyTag>
Voxel_grid<double> clipped_distance_by_sweep(const std::vector<Triangle_points>& tris, const Surface_voxels& sv,
                                             const std::vector<std::array<int, 6> >& boxes, int r, double tau)
{
  const double reach2 = squared_band_reach(r, tau);
  Voxel_grid<double> d2, swept;
  run_side_by_side<ConcurrencyTag>([&] { swept = swept_squared_distances<ConcurrencyTag>(tris, boxes, r, tau); },
                                   [&] { d2 = squared_distance_transform<ConcurrencyTag>(sv.mask, false); });
  Voxel_grid<double> out(r, tau);
  for(std::size_t i = 0; i < out.size(); ++i)
    if(d2[i] < reach2) out[i] = (std::min)(std::sqrt(swept[i]), tau);
  return out;
}

// How clipped_unsigned_distance() finds the closest triangles.
enum class Band_distance_method
{
  AUTOMATIC, // the sweep if it evaluates fewer than `sweep_limit` distances per voxel of the band
  TREE,
  SWEEP
};

// The sweep evaluates every triangle at every voxel of its widened box; the tree about one triangle
// per query on small triangles, tens on large overlapping ones, at several times the cost of one
// sweep evaluation. On the CAD-style objects the sweep is faster below 10 evaluations per voxel of
// the band (surface voxels times 2 tau + 1 voxels), slower from 19 on; the two give the same values.
constexpr double sweep_limit = 10.;

// Unsigned distances (normalized units, clipped to `tau`) at the voxel centres that can be closer
// than `tau` to the surface, `tau` elsewhere: clipped_distance_by_tree() or, for a few large
// triangles (an assembly of plates), clipped_distance_by_sweep(), which give the same values.
// `release`, if given, is `&tris`, emptied once it is no longer needed.
template <typename ConcurrencyTag>
Voxel_grid<double> clipped_unsigned_distance(const std::vector<Triangle_points>& tris, const Surface_voxels& sv, int r,
                                             double tau, std::vector<Triangle_points>* release = nullptr,
                                             Band_distance_method method = Band_distance_method::AUTOMATIC)
{
  if(method != Band_distance_method::TREE)
  {
    const std::pair<std::vector<std::array<int, 6> >, double> boxes = voxels_near_triangle_boxes(tris, r, tau);
    std::size_t surface = 0;
    for(std::size_t i = 0; i < sv.mask.size(); ++i) surface += sv.mask[i] != 0 ? 1 : 0;
    const double band = double(surface) * (2. * tau * double(r) + 1.);
    if(method == Band_distance_method::SWEEP || boxes.second < sweep_limit * band)
    {
      Voxel_grid<double> out = clipped_distance_by_sweep<ConcurrencyTag>(tris, sv, boxes.first, r, tau);
      if(release) std::vector<Triangle_points>().swap(*release);
      return out;
    }
  }
  return clipped_distance_by_tree<ConcurrencyTag>(tris, sv, r, tau, release);
}

// The named parameters of compute_tsdf(): the finest resolution, tau in voxels, the sign method.
struct Tsdf_parameters
{
  int resolution;
  double truncation_voxels;
  Tsdf_sign_method sign_method;
};

template <typename NamedParameters>
Tsdf_parameters read_tsdf_parameters(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  Tsdf_parameters p;
  p.resolution = read_voxel_resolutions(np).back();
  p.truncation_voxels = double(choose_parameter(get_parameter(np, internal_np::tsdf_truncation), defaults::tsdf_truncation));
  check_parameter(p.truncation_voxels > 0. && p.truncation_voxels <= 4. * p.resolution, "tsdf_truncation");
  p.sign_method = choose_parameter(get_parameter(np, internal_np::tsdf_sign_method), defaults::tsdf_sign_method);
  if(p.sign_method == Tsdf_sign_method::AUTOMATIC) p.sign_method = Tsdf_sign_method::RAY_VOTES;
  return p;
}

// Inside flags of the voxel centres by `method` (never AUTOMATIC).
template <typename ConcurrencyTag>
std::vector<std::uint8_t> inside_flags(const std::vector<Triangle_points>& tris, bool closed,
                                       Tsdf_sign_method method, const Surface_voxels& sv, int r)
{
  switch(method)
  {
  case Tsdf_sign_method::INSIDE_TEST:
    return inside_from_rows(row_crossings<ConcurrencyTag>(tris, r), r, true);
  case Tsdf_sign_method::FLOOD_FILL:
    return inside_by_flood_fill<ConcurrencyTag>(tris, sv, r);
  case Tsdf_sign_method::RAY_VOTES:
    if(closed) return inside_from_rows(row_crossings<ConcurrencyTag>(tris, r), r, false);
    return inside_by_ray_votes<ConcurrencyTag>(tris, r);
  default:
    if(closed) return inside_from_rows(row_crossings<ConcurrencyTag>(tris, r), r, false);
    return inside_by_winding_number<ConcurrencyTag>(tris, sv, r);
  }
}

// compute_tsdf() on a mesh that check_input() accepted (Part_decomposer checks its mesh once).
template <typename ConcurrencyTag, typename TriangleMesh, typename NamedParameters>
Truncated_signed_distance_field compute_tsdf_of_checked_mesh(const TriangleMesh& tm, const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  static_check_concurrency_tag<ConcurrencyTag>();
  typedef typename GetVertexPointMap<TriangleMesh, NamedParameters>::const_type VPM;
  const VPM vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                   get_const_property_map(CGAL::vertex_point, tm));
  const Tsdf_parameters parameters = read_tsdf_parameters(np);
  const int r = parameters.resolution;
  const Tsdf_sign_method method = parameters.sign_method;

  Truncated_signed_distance_field out;
  out.normalization = read_normalization(tm, np);
  out.truncation = parameters.truncation_voxels / double(r);
  out.sign_method = method;

  std::vector<Triangle_points> tris = normalized_triangles(tm, vpm, out.normalization);
  const bool closed = faces_form_closed_surface(tm);
  const Surface_voxels sv = surface_voxels<ConcurrencyTag>(tris, r);
  const std::vector<std::uint8_t> inside = inside_flags<ConcurrencyTag>(tris, closed, method, sv, r);
  out.values = clipped_unsigned_distance<ConcurrencyTag>(tris, sv, r, out.truncation, &tris);
  for(std::size_t i = 0; i < out.values.size(); ++i)
    if(inside[i]) out.values[i] = -out.values[i];
  return out;
}

} // namespace internal

/*!
\ingroup PkgPartDecompositionRef
computes the truncated signed distance field \f$d_\mathcal{M}\f$ of `tm` (paper App.\ E.2) at the
voxel centres of the finest grid of the method, in the normalized cube: the Euclidean distance to
the surface, negative inside and positive outside, clipped to \f$\pm\tau\f$.

Distances are exact, up to rounding, wherever they can be below \f$\tau\f$: the distance to the
closest triangle, found in a `CGAL::AABB_tree` of the normalized triangles by a nearest-first
traversal (nearest child box first, boxes farther than the best triangle so far pruned, exact
point-triangle distances at the leaves), bounded from the start by the triangle found for the
previous voxel of the row and by \f$\tau\f$. These distances equal those of the tree's own
`squared_distance()` query up to rounding (\f$10^{-14}\f$ voxel on the development meshes),
which is several times slower on the band. A mesh of a few large triangles (a CAD assembly of
plates) is done the other way round, with the same values: each triangle is swept over the voxels
within \f$\tau\f$ of its bounding box, when that evaluates fewer than 10 distances per voxel of the
band. Elsewhere only the sign is
computed and the value is \f$\pm\tau\f$: every voxel carries its sign, deep interior voxels hold
\f$-\tau\f$. How the sign is decided is described in `Tsdf_sign_method`. Coordinates are read
through the vertex point map with `CGAL::to_double()` and everything is computed in double
precision on the normalized coordinates: no geometric traits class is needed.

\par Complexity
\f$O(F \log F)\f$ to build the tree of the \f$F\f$ triangles, then one closest-triangle query (logarithmic in
\f$F\f$ in practice) per voxel of the band of width \f$\tau\f$ around the surface (for a sweep instead,
one distance per triangle and voxel within \f$\tau\f$ of its box); linear time in the number of
voxels \f$r^3\f$ for the sign, plus the number of crossings of the rows of the grid by the
triangles (rows along one axis on a closed mesh, along the three axes on an open one, with the
default `Tsdf_sign_method::RAY_VOTES`).

\tparam ConcurrencyTag enables sequential versus parallel computation. Possible values are
        `CGAL::Sequential_tag`, `CGAL::Parallel_tag`, and `CGAL::Parallel_if_available_tag`.
        The result does not depend on it nor on the number of threads.
\tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeGraph`
\tparam NamedParameters a sequence of named parameters

\param tm the triangle mesh; it may be open, non-manifold, self-intersecting, made of several
          components, with components of any orientation
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{vertex_point_map}
    \cgalParamDescription{a property map associating points to the vertices of `tm`}
    \cgalParamType{a class model of `ReadablePropertyMap` with
                   `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and
                   `%Point_3` as value type}
    \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
  \cgalParamNEnd
  \cgalParamNBegin{normalization}
    \cgalParamDescription{the map from input coordinates to the normalized cube
                          \f$[-0.5,0.5]^3\f$ in which the grid lives}
    \cgalParamType{`CGAL::Part_decomposition::Normalization`}
    \cgalParamDefault{`compute_normalization(tm, np)`}
  \cgalParamNEnd
  \cgalParamNBegin{normalization_margin}
    \cgalParamDescription{passed to `compute_normalization()` when no `normalization` is given}
    \cgalParamType{`double`}
    \cgalParamDefault{`2.0/64`}
  \cgalParamNEnd
  \cgalParamNBegin{voxel_resolutions}
    \cgalParamDescription{the resolutions of the method; the TSDF grid has the finest (the last) one}
    \cgalParamType{`std::vector<int>` (or any range of integers): a non-empty list of powers of
                   two from 1 to 256, each twice the previous (the rule of `compute_flow_freeze_prior()`)}
    \cgalParamDefault{`std::vector<int>{16, 32, 64}`}
  \cgalParamNEnd
  \cgalParamNBegin{tsdf_truncation}
    \cgalParamDescription{\f$\tau\f$ in voxels of the TSDF grid (paper Table A.1: \f$8\Delta^{(64)}\f$)}
    \cgalParamType{`double`, in \f$(0, 4r]\f$ for the TSDF resolution \f$r\f$}
    \cgalParamDefault{`8.0`}
  \cgalParamNEnd
  \cgalParamNBegin{tsdf_sign_method}
    \cgalParamDescription{how the sign is decided}
    \cgalParamType{`CGAL::Part_decomposition::Tsdf_sign_method`}
    \cgalParamDefault{`Tsdf_sign_method::AUTOMATIC`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\pre `tm` lies inside the normalized cube once normalized (the default normalization ensures it).
\pre `tm` has no garbage (`Surface_mesh` after removals: call `collect_garbage()`).

\returns the field, its truncation in normalized units, the normalization and the sign method used.

\throws Invalid_input (see `check_input()`) if `tm` has no face, a face that is not a triangle,
        a non-finite coordinate or no extent, and with `Input_error::INVALID_PARAMETER` if
        `voxel_resolutions` breaks its rule or the truncation is out of range.
*/
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename TriangleMesh,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Truncated_signed_distance_field compute_tsdf(const TriangleMesh& tm,
                                             const NamedParameters& np = CGAL::parameters::default_values())
{
  check_input(tm, np);
  return internal::compute_tsdf_of_checked_mesh<ConcurrencyTag>(tm, np);
}


} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_TSDF_H
