// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_TSDF_H
#define CGAL_PART_DECOMPOSITION_TSDF_H

#include <CGAL/Part_decomposition/Adaptive_grid.h>
#include <CGAL/Part_decomposition/stage_results.h>
#include <CGAL/Part_decomposition/Voxel_grid.h>
#include <CGAL/Part_decomposition/input_validation.h>
#include <CGAL/Part_decomposition/normalization.h>
#include <CGAL/Part_decomposition/parameters.h>
#include <CGAL/Part_decomposition/internal/grid/adaptive_grid_builder.h>
#include <CGAL/Part_decomposition/internal/grid/leaf_signs.h>
#include <CGAL/Part_decomposition/internal/grid/mesh_voxelization.h>
#include <CGAL/Part_decomposition/internal/toolbox/toolbox.h>
#include <CGAL/Part_decomposition/internal/grid/triangle_soup_aabb_tree.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iostream>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

namespace CGAL {
namespace Part_decomposition {

namespace internal {

// The named parameters of compute_tsdf(): the finest of `voxel_resolutions` (the unit of
// lengths), the grid's finest resolution and refinement, tau in voxels, the sign method.
struct Tsdf_parameters
{
  int resolution;
  int grid_resolution;
  bool adaptive;
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
  p.grid_resolution = int(choose_parameter(get_parameter(np, internal_np::grid_resolution), defaults::grid_resolution));
  check_parameter(p.grid_resolution >= 1 && p.grid_resolution <= 256 && (p.grid_resolution & (p.grid_resolution - 1)) == 0,
                  "grid_resolution");
  // never coarser than the finest voxel resolution, the unit of the method's lengths
  p.grid_resolution = (std::max)(p.grid_resolution, p.resolution);
  p.adaptive = internal::method_switches(np).adaptive_grid;
  p.truncation_voxels = double(choose_parameter(get_parameter(np, internal_np::tsdf_truncation), defaults::tsdf_truncation));
  check_parameter(p.truncation_voxels > 0. && p.truncation_voxels <= 4. * p.resolution, "tsdf_truncation");
  p.sign_method = choose_parameter(get_parameter(np, internal_np::tsdf_sign_method), defaults::tsdf_sign_method);
  if(p.sign_method == Tsdf_sign_method::AUTOMATIC) p.sign_method = Tsdf_sign_method::RAY_VOTES;
  return p;
}

// The depth each point of the surface asks for: that of its fused prior leaf (16, 32 or 64 by
// default), the finest prior resolution where the prior holds no sample.
inline Surface_depths prior_surface_depths(const Hierarchical_prior& prior, int resolution)
{
  Surface_depths s;
  const Voxel_grid<std::uint16_t>& res = prior.leaf_resolution;
  if(res.resolution() == 0) return s;
  check_parameter(res.resolution() == resolution, "the prior", "computed at the same voxel_resolutions");
  s.resolution = res.resolution();
  s.depth.resize(res.size());
  const std::uint8_t finest = std::uint8_t(Adaptive_grid::depth_of(resolution));
  for(std::size_t v = 0; v < res.size(); ++v)
    s.depth[v] = res[v] == 0 ? finest : std::uint8_t(Adaptive_grid::depth_of(int(res[v])));
  return s;
}

// The grid of the leaves, numbered by smallest corner as Adaptive_grid numbers them, with the
// distances of their centres and whether the surface may meet them, in the same order.
inline Adaptive_grid grid_of_leaves(std::vector<Grid_leaf>& leaves, int finest_resolution, std::vector<double>& distance,
                                    std::vector<std::uint8_t>& crossed)
{
  const int D = Adaptive_grid::depth_of(finest_resolution);
  const std::uint64_t R = std::uint64_t(finest_resolution);
  auto corner_key = [&](const Grid_leaf& l) {
    const int s = D - l.depth;
    return (std::uint64_t(l.position[0]) << s) + R * ((std::uint64_t(l.position[1]) << s) + R * (std::uint64_t(l.position[2]) << s));
  };
  std::sort(leaves.begin(), leaves.end(), [&](const Grid_leaf& a, const Grid_leaf& b) { return corner_key(a) < corner_key(b); });
  std::vector<Adaptive_grid::Cell> cells;
  cells.reserve(leaves.size());
  distance.resize(leaves.size());
  crossed.resize(leaves.size());
  for(std::size_t l = 0; l < leaves.size(); ++l)
  {
    cells.push_back(Adaptive_grid::Cell{leaves[l].depth, leaves[l].position});
    distance[l] = leaves[l].distance;
    crossed[l] = leaves[l].crossed ? 1 : 0;
  }
  return Adaptive_grid(finest_resolution, cells);
}

// Inside flags of the leaves by `method` (never AUTOMATIC); `crossed`: per leaf, whether the surface
// may meet it.
template <typename ConcurrencyTag>
std::vector<std::uint8_t> leaf_inside_flags(const std::vector<Triangle_points>& tris, bool closed,
                                            Tsdf_sign_method method, const Adaptive_grid& grid,
                                            const std::vector<std::uint8_t>& crossed)
{
  switch(method)
  {
  case Tsdf_sign_method::INSIDE_TEST:
    return leaf_inside_from_rows<ConcurrencyTag>(tris, grid, true);
  case Tsdf_sign_method::FLOOD_FILL:
  {
    // the leaves the surface may meet take the sign of RAY_VOTES
    const std::vector<std::uint8_t> votes = closed ? leaf_inside_from_rows<ConcurrencyTag>(tris, grid, false)
                                                   : leaf_inside_by_ray_votes<ConcurrencyTag>(tris, grid);
    return leaf_inside_by_flood_fill(grid, crossed, &votes);
  }
  case Tsdf_sign_method::RAY_VOTES:
    if(closed) return leaf_inside_from_rows<ConcurrencyTag>(tris, grid, false);
    return leaf_inside_by_ray_votes<ConcurrencyTag>(tris, grid);
  default:
  {
    if(closed) return leaf_inside_from_rows<ConcurrencyTag>(tris, grid, false);
    std::vector<std::uint8_t> inside(grid.number_of_leaves(), 0);
    leaf_inside_by_winding_number<ConcurrencyTag>(tris, grid, {}, inside);
    return inside;
  }
  }
}

// compute_tsdf() on a mesh that check_input() accepted (Part_decomposer checks its mesh once);
// `prior` may be null (the surface at the finest voxel resolution everywhere). `thin_faces`, if
// given, holds per face index whether its thin parts are refined (the faces of the pieces the
// volume stages may decompose); else every face's are.
template <typename ConcurrencyTag, typename TriangleMesh, typename NamedParameters>
Truncated_signed_distance_field compute_tsdf_of_checked_mesh(const TriangleMesh& tm, const Hierarchical_prior* prior,
                                                             const NamedParameters& np,
                                                             const std::vector<std::uint8_t>* thin_faces = nullptr)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  static_check_concurrency_tag<ConcurrencyTag>();
  typedef typename GetVertexPointMap<TriangleMesh, NamedParameters>::const_type VPM;
  const VPM vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                   get_const_property_map(CGAL::vertex_point, tm));
  const Tsdf_parameters parameters = read_tsdf_parameters(np);

  Truncated_signed_distance_field out;
  out.normalization = read_normalization(tm, np);
  out.truncation = parameters.truncation_voxels / double(parameters.resolution);
  out.voxel_size = 1. / double(parameters.resolution);
  out.sign_method = parameters.sign_method;

  const std::vector<Triangle_points> tris = normalized_triangles(tm, vpm, out.normalization, ConcurrencyTag());
  const bool closed = faces_form_closed_surface(tm);
  Grid_refinement_rule rule;
  rule.base_depth = Adaptive_grid::depth_of(parameters.resolution);
  rule.finest_depth = Adaptive_grid::depth_of(parameters.adaptive ? parameters.grid_resolution : parameters.resolution);
  rule.uniform = !parameters.adaptive;
  rule.band = out.truncation;
  if(prior != nullptr && parameters.adaptive) rule.surface = prior_surface_depths(*prior, parameters.resolution);
  if(thin_faces != nullptr)
  {
    // soup order is the order of faces(tm)
    const auto fim = CGAL::get_initialized_face_index_map(tm, np);
    for(auto f : faces(tm)) rule.thin_triangles.push_back((*thin_faces)[std::size_t(get(fim, f))]);
  }
  std::vector<double> distance;
  std::vector<std::uint8_t> crossed;
  {
    const Triangle_soup_aabb_tree tree(tris, ConcurrencyTag());
    std::vector<Grid_leaf> leaves = adaptive_grid_leaves<ConcurrencyTag>(tree, rule);
    out.grid = grid_of_leaves(leaves, 1 << rule.finest_depth, distance, crossed);
  }
  if(choose_parameter(get_parameter(np, CGAL::internal_np::verbose), defaults::verbose))
  {
    std::cerr << "grid: " << out.grid.number_of_leaves() << " leaves, by resolution:";
    for(int d = 0; d <= rule.finest_depth; ++d)
      if(out.grid.number_of_leaves_of_depth(d) > 0) std::cerr << " " << (1 << d) << ": " << out.grid.number_of_leaves_of_depth(d);
    std::cerr << "\n";
  }
  const std::vector<std::uint8_t> inside =
    leaf_inside_flags<ConcurrencyTag>(tris, closed, parameters.sign_method, out.grid, crossed);
  out.values.resize(distance.size());
  for(std::size_t l = 0; l < distance.size(); ++l)
  {
    const double d = (std::min)(distance[l], out.truncation);
    out.values[l] = inside[l] ? -d : d;
  }
  return out;
}

} // namespace internal

/*!
\ingroup PkgPartDecompositionRef
computes the truncated signed distance field \f$d_\mathcal{M}\f$ of `tm` (paper App.\ E.2) on an
adaptive grid of the normalized cube (`Adaptive_grid`), one value per leaf, at its centre: the
Euclidean distance to the surface, negative inside and positive outside, clipped to \f$\pm\tau\f$,
\f$\tau\f$ being `tsdf_truncation` voxels of the finest of `voxel_resolutions` (paper Table A.1:
\f$8\Delta^{(64)}\f$).

<b>The grid.</b> The leaves are the leaves of a `CGAL::Octree` over the normalized cube, refined
where the shape needs it. A cell is split while its centre is closer to the surface than its own
side and it is larger than the surface needs at the nearest surface point: the resolution of the
fused leaf of `prior` there (the Flow/Freeze prior keeps smooth Flow regions at coarse
resolutions and refines its Freeze boundaries down to the finest of `voxel_resolutions`), and,
for a cell the surface crosses, a quarter of the local feature size: while the surface faces
another sheet of surface, turned by more than 120 degrees, closer than two sides of the cell (the
other side of a thin part, or across a narrow gap), it is split down to `grid_resolution`.
Away from the surface the leaves grow with the distance, and the interior of bulky parts and the
empty space are covered by a few large leaves. Without `prior`, the surface asks for the finest
of `voxel_resolutions` everywhere. With `adaptive_grid = false`, every leaf is a voxel of the
finest of `voxel_resolutions`: the dense grid of the paper. With `verbose`, the number of leaves
of each resolution is printed to `std::cerr`.

<b>The values.</b> Distances are exact, up to rounding, wherever they are below \f$\tau\f$: the
distance to the closest triangle, found in a `CGAL::AABB_tree` of the normalized triangles by a
nearest-first traversal bounded from the start by the triangle closest to the parent cell's
centre. Beyond \f$\tau\f$ the value is \f$\pm\tau\f$. The sign is decided at the centre of the
finest voxel in the middle of each leaf (the centre of a leaf of one finest voxel) by
`tsdf_sign_method` (see `Tsdf_sign_method`), from the exact signed crossings of the rows of the
finest voxels with the triangles. Coordinates are read through the vertex point map with
`CGAL::to_double()` and everything is computed in double precision on the normalized coordinates.

\par Complexity
\f$O(F \log F)\f$ to build the tree of the \f$F\f$ triangles, one closest-triangle query
(logarithmic in \f$F\f$ in practice) per cell of the octree and two per cell of the surface below
the prior's resolution, and the crossings of the rows of the finest grid with the triangles.

\tparam ConcurrencyTag enables sequential versus parallel computation. Possible values are
        `CGAL::Sequential_tag`, `CGAL::Parallel_tag`, and `CGAL::Parallel_if_available_tag`.
        The result does not depend on it nor on the number of threads.
\tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeGraph`
\tparam NamedParameters a sequence of named parameters

\param tm the triangle mesh; it may be open, non-manifold, self-intersecting, made of several
          components, with components of any orientation
\param prior the Flow/Freeze prior of `tm` at the same `voxel_resolutions` and normalization
       (`compute_flow_freeze_prior()`), whose fused leaves tell how fine the surface must be
\param np an optional sequence of named parameters; this function reads `vertex_point_map`,
`vertex_index_map`, `face_index_map` (\ref PD_MeshParameters), `normalization`,
`normalization_margin`, `voxel_resolutions`, `grid_resolution`, `tsdf_truncation`,
`tsdf_sign_method`, `verbose` and `method_variant` (its switch `adaptive_grid`) (\ref PD_ParameterTable)

\pre `tm` lies inside the normalized cube once normalized (the default normalization ensures it).
\pre `tm` has no garbage (`Surface_mesh` after removals: call `collect_garbage()`).

\returns the grid, the field on its leaves, its truncation in normalized units, the normalization
and the sign method used.

\throws Invalid_input (see `check_input()`) if `tm` has no face, a face that is not a triangle,
        a non-finite coordinate or no extent, and with `Input_error::INVALID_PARAMETER` if
        `voxel_resolutions` breaks its rule, `grid_resolution` or the truncation is out of range, or
        `prior` was computed at other resolutions.
*/
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename TriangleMesh,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Truncated_signed_distance_field compute_tsdf(const TriangleMesh& tm, const Hierarchical_prior& prior,
                                             const NamedParameters& np = CGAL::parameters::default_values())
{
  check_input(tm, np);
  return internal::compute_tsdf_of_checked_mesh<ConcurrencyTag>(tm, &prior, np);
}

/*!
\ingroup PkgPartDecompositionRef
computes the truncated signed distance field of `tm` as `compute_tsdf(tm, prior, np)` does, without
a prior: the surface asks for the finest of `voxel_resolutions` everywhere (and finer where it is
thin).
*/
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename TriangleMesh,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Truncated_signed_distance_field compute_tsdf(const TriangleMesh& tm,
                                             const NamedParameters& np = CGAL::parameters::default_values())
{
  check_input(tm, np);
  return internal::compute_tsdf_of_checked_mesh<ConcurrencyTag>(tm, nullptr, np);
}


} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_TSDF_H
