// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_SHEET_MERGING_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_SHEET_MERGING_H

#include <CGAL/Part_decomposition/Voxel_grid.h>
#include <CGAL/Part_decomposition/internal/grid_morphology.h>
#include <CGAL/Part_decomposition/primitive_assignment.h>
#include <CGAL/Part_decomposition/superquadric_fitting.h>
#include <CGAL/Part_decomposition/tsdf.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/number_utils.h>
#include <CGAL/number_type_config.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

// Thresholds of the sheet merge, measured on the development meshes (see the user manual).
struct Sheet_merging_thresholds
{
  // a primitive is flat when its smallest semi-axis times this is below its middle one
  double flatness_ratio = 2.;
  // and thin when no voxel it claims lies deeper than this inside the shape, in finest voxels
  // (a wall up to five voxels thick: the wall of a cup at 64^3)
  double maximum_depth = 2.5;
  // two sheets merge unless this fraction of their seam lies on sharp edges
  double sharp_seam_fraction = 0.5;
  // sharp: a dihedral angle at or above this percentile of the mesh's interior edges and at or
  // above the minimum angle, in degrees (the sides of a 16-gon prism, 22.5 degrees apart, are smooth)
  double sharp_edge_percentile = 90.;
  double minimum_sharp_angle = 30.;
};


/*
Thin shells (the wall of a cup, the skin of a wing, a table top a few voxels thick) are fitted by
several flat superquadrics that tile one smooth sheet: the fitter cannot grow one primitive along
a curved shell. Parts whose primitives are flat and thin are merged with their flat, thin
neighbours across every seam that mostly runs over smooth edges; a seam on a crease (the rim of a
table top, a wing's edge against the fuselage) keeps them apart. A merged part keeps the primitive
that claimed the most voxels.

`part` holds the part of each face (by face index) and `part_to_primitive` the primitive of each
part; both are renumbered in place. Returns the new number of parts.
*/
template <typename TriangleMesh, typename VertexPointMap, typename FaceIndexMap, typename GeomTraits>
std::size_t merge_thin_sheet_parts(const TriangleMesh& tm, VertexPointMap vpm, FaceIndexMap fim,
                                   const Truncated_signed_distance_field& tsdf,
                                   const Superquadric_fitting_result<GeomTraits>& fitting,
                                   std::vector<std::size_t>& part,
                                   std::vector<std::size_t>& part_to_primitive,
                                   const Sheet_merging_thresholds& th = Sheet_merging_thresholds())
{
  typedef boost::graph_traits<TriangleMesh> GT;
  const std::size_t K = part_to_primitive.size();
  if(K < 2) return K;

  // Depth of each voxel inside the shape, in voxels: its distance to the nearest outside voxel.
  const std::size_t n_voxels = tsdf.values.size();
  Voxel_grid<std::uint8_t> outside(tsdf.values.resolution(), 0);
  for(std::size_t v = 0; v < n_voxels; ++v) outside[v] = tsdf.values[v] > 0. ? 1 : 0;
  const Voxel_grid<double> depth2 = squared_distance_transform<CGAL::Sequential_tag>(outside);

  std::vector<char> sheet(K, 0);
  bool any_sheet = false;
  for(std::size_t k = 0; k < K; ++k)
  {
    const std::size_t q = part_to_primitive[k];
    if(q >= fitting.primitives.size()) continue;
    std::array<double, 3> a = fitting.primitives[q].scales();
    std::sort(a.begin(), a.end());
    double deepest2 = 0.;
    for(std::size_t v : fitting.claimed_voxels[q])
      if(v < n_voxels) deepest2 = (std::max)(deepest2, depth2[v]);
    sheet[k] = (a[0] * th.flatness_ratio < a[1] && deepest2 <= th.maximum_depth * th.maximum_depth) ? 1 : 0;
    any_sheet = any_sheet || sheet[k];
  }
  if(!any_sheet) return K;

  // Unit face normals, for the dihedral angle of each interior edge.
  const std::size_t nf = part.size();
  std::vector<std::array<double, 3> > normal(nf, {{0., 0., 0.}});
  for(auto f : faces(tm))
  {
    std::array<std::array<double, 3>, 3> p;
    int c = 0;
    for(auto v : vertices_around_face(halfedge(f, tm), tm))
    {
      if(c == 3) break;
      const auto& q = get(vpm, v);
      p[c++] = {{CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z())}};
    }
    if(c < 3) continue;
    const double u[3] = {p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2]};
    const double w[3] = {p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2]};
    const double n[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
    const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if(len > 0. && std::isfinite(len))
      normal[get(fim, f)] = {{n[0] / len, n[1] / len, n[2] / len}};
  }

  struct Seam_edge { std::size_t p, q; double angle, length; };
  std::vector<Seam_edge> seam;
  std::vector<double> angles;
  angles.reserve(num_edges(tm));
  for(auto e : edges(tm))
  {
    const typename GT::halfedge_descriptor h = halfedge(e, tm);
    if(is_border_edge(h, tm)) continue;
    const std::size_t a = get(fim, face(h, tm)), b = get(fim, face(opposite(h, tm), tm));
    const double d = normal[a][0] * normal[b][0] + normal[a][1] * normal[b][1] + normal[a][2] * normal[b][2];
    const double angle = std::acos((std::max)(-1., (std::min)(1., d)));
    angles.push_back(angle);
    const std::size_t pa = part[a], pb = part[b];
    if(pa == pb || pa >= K || pb >= K || !sheet[pa] || !sheet[pb]) continue;
    const auto& s = get(vpm, source(h, tm));
    const auto& t = get(vpm, target(h, tm));
    const double dx = CGAL::to_double(s.x()) - CGAL::to_double(t.x());
    const double dy = CGAL::to_double(s.y()) - CGAL::to_double(t.y());
    const double dz = CGAL::to_double(s.z()) - CGAL::to_double(t.z());
    seam.push_back({(std::min)(pa, pb), (std::max)(pa, pb), angle, std::sqrt(dx * dx + dy * dy + dz * dz)});
  }
  if(seam.empty()) return K;
  const std::size_t rank = std::size_t(th.sharp_edge_percentile / 100. * double(angles.size() - 1));
  std::nth_element(angles.begin(), angles.begin() + rank, angles.end());
  const double sharp = (std::max)(angles[rank], th.minimum_sharp_angle * CGAL_PI / 180.);

  // (sharp length, total length) of the seam of each pair of sheets
  std::map<std::pair<std::size_t, std::size_t>, std::pair<double, double> > seams;
  for(const Seam_edge& e : seam)
  {
    std::pair<double, double>& s = seams[std::make_pair(e.p, e.q)];
    s.second += e.length;
    if(e.angle >= sharp) s.first += e.length;
  }
  std::vector<std::size_t> leader(K);
  for(std::size_t k = 0; k < K; ++k) leader[k] = k;
  auto find = [&leader](std::size_t x) {
    while(leader[x] != x) x = leader[x] = leader[leader[x]];
    return x;
  };
  for(const auto& s : seams)
    if(s.second.first < th.sharp_seam_fraction * s.second.second)
    {
      const std::size_t a = find(s.first.first), b = find(s.first.second);
      if(a != b) leader[(std::max)(a, b)] = (std::min)(a, b);
    }

  // Renumber in order of first part id; each merged part keeps its largest primitive.
  std::vector<std::size_t> new_id(K, std::size_t(-1)), old_to_new(K);
  std::size_t K2 = 0;
  for(std::size_t k = 0; k < K; ++k)
  {
    const std::size_t r = find(k);
    if(new_id[r] == std::size_t(-1)) new_id[r] = K2++;
    old_to_new[k] = new_id[r];
  }
  std::vector<std::size_t> primitive(K2, no_primitive), volume(K2, 0);
  for(std::size_t k = 0; k < K; ++k)
  {
    const std::size_t n = old_to_new[k], q = part_to_primitive[k];
    const std::size_t size = q < fitting.claimed_voxels.size() ? fitting.claimed_voxels[q].size() + 1 : 0;
    if(primitive[n] == no_primitive || size > volume[n])
    {
      primitive[n] = q;
      volume[n] = size;
    }
  }
  part_to_primitive.swap(primitive);
  for(std::size_t& p : part)
    if(p < K) p = old_to_new[p];
  return K2;
}

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_SHEET_MERGING_H
