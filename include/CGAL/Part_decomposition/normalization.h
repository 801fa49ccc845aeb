// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_NORMALIZATION_H
#define CGAL_PART_DECOMPOSITION_NORMALIZATION_H

#include <CGAL/Part_decomposition/parameters.h>
#include <CGAL/Part_decomposition/input_validation.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

namespace CGAL {
namespace Part_decomposition {

/*!
\ingroup PkgPartDecompositionRef
A uniform scaling and translation that maps the input coordinates of a mesh into the normalized
cube \f$[-0.5,0.5]^3\f$ in which every voxel grid of the method lives:
`unit = (p - center) * scale`. Results are mapped back with `from_unit()`.
*/
class Normalization
{
public:
  /// the identity.
  Normalization() : m_center{{0., 0., 0.}}, m_scale(1.) {}
  /// the map `p -> (p - center) * scale`.
  /// \throws Invalid_input (`INVALID_PARAMETER`) unless `scale` is positive and every value is finite.
  Normalization(const std::array<double, 3>& center, double scale) : m_center(center), m_scale(scale)
  {
    if(!(scale > 0.) || !std::isfinite(scale) || !std::isfinite(center[0]) || !std::isfinite(center[1]) ||
       !std::isfinite(center[2]))
      throw Invalid_input(Input_error::INVALID_PARAMETER, "a normalization needs a finite center and a positive finite scale");
  }

  /// the input point mapped to the centre of the cube.
  const std::array<double, 3>& center() const { return m_center; }
  /// the factor from input lengths to normalized lengths.
  double scale() const { return m_scale; }

  /// maps input coordinates to the normalized cube.
  std::array<double, 3> to_unit(double x, double y, double z) const
  {
    return {{(x - m_center[0]) * m_scale, (y - m_center[1]) * m_scale, (z - m_center[2]) * m_scale}};
  }
  /// maps a point with `x()`, `y()`, `z()` (any \cgal point) to the normalized cube.
  template <typename Point_3>
  std::array<double, 3> to_unit(const Point_3& p) const
  {
    return to_unit(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  }
  /// maps normalized coordinates back to input coordinates.
  std::array<double, 3> from_unit(const std::array<double, 3>& u) const
  {
    return {{u[0] / m_scale + m_center[0], u[1] / m_scale + m_center[1], u[2] / m_scale + m_center[2]}};
  }

private:
  std::array<double, 3> m_center;
  double m_scale;
};

/// \cond SKIP_IN_MANUAL
namespace internal {

// Whether `a` and `b` are the same map (center and scale): grids computed in two frames do not
// match voxel for voxel.
inline bool same_frame(const Normalization& a, const Normalization& b)
{
  return a.center() == b.center() && a.scale() == b.scale();
}

// The named parameters of compute_normalization(); the one reader of `normalization_margin`.
struct Normalization_parameters
{
  double margin;
};

template <typename NamedParameters>
Normalization_parameters read_normalization_parameters(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  Normalization_parameters p;
  p.margin = double(choose_parameter(get_parameter(np, internal_np::normalization_margin), defaults::normalization_margin));
  check_parameter(p.margin >= 0. && p.margin <= 0.25, "normalization_margin");
  return p;
}

} // namespace internal
/// \endcond

/*!
\ingroup PkgPartDecompositionRef
computes the normalization of `tm`: the centre of its axis-aligned bounding box goes to the
origin and its longest side to `1 - 2*margin`, `margin` being `normalization_margin`, so that a
free layer of width `margin` separates the shape from the border of the cube and the exterior of
the shape is connected around it on every grid.

\tparam FaceListGraph a model of `FaceListGraph`
\tparam NamedParameters a sequence of named parameters

\param tm the mesh
\param np an optional sequence of named parameters; this function reads `vertex_point_map`
(\ref PD_MeshParameters) and `normalization_margin` (\ref PD_ParameterTable)

Only the vertices incident to a face count.

\returns the normalization.

\par Complexity
Linear in the size of `tm`.

\throws Invalid_input if `tm` has no face (`NO_FACES`), a non-finite coordinate
(`NON_FINITE_COORDINATES`), all its vertices coincide (`DEGENERATE_EXTENT`), or its coordinates are
out of the range of `maximum_coordinate` and `minimum_extent` (`COORDINATES_OUT_OF_RANGE`).
*/
template <typename FaceListGraph, typename NamedParameters = CGAL::parameters::Default_named_parameters>
Normalization compute_normalization(const FaceListGraph& tm,
                                    const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename GetVertexPointMap<FaceListGraph, NamedParameters>::const_type VPM;
  const VPM vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                   get_const_property_map(CGAL::vertex_point, tm));
  const double margin = internal::read_normalization_parameters(np).margin;

  double lo[3], hi[3];
  if(!internal::face_vertex_box(tm, vpm, lo, hi))
    throw Invalid_input(Input_error::NO_FACES, "the mesh has no face");
  internal::check_extent(lo, hi);

  // Centre and extent in long double: at 1e8 offsets with 1e-8 extents the difference matters.
  std::array<double, 3> center;
  long double extent = 0;
  for(int a = 0; a < 3; ++a)
  {
    center[a] = double((static_cast<long double>(lo[a]) + hi[a]) / 2);
    extent = (std::max)(extent, static_cast<long double>(hi[a]) - lo[a]);
  }
  const double scale = double((1. - 2. * margin) / extent);
  if(!(extent > 0) || !std::isfinite(scale) || !(scale > 0.))
    throw Invalid_input(Input_error::DEGENERATE_EXTENT, "all vertices of the mesh coincide");
  return Normalization(center, scale);
}

/// \cond SKIP_IN_MANUAL
namespace internal {

// The one reader of the `normalization` named parameter: `compute_normalization(tm, np)` when absent.
template <typename TriangleMesh, typename NamedParameters>
Normalization read_normalization(const TriangleMesh& tm, const NamedParameters& np)
{
  const std::optional<Normalization> given = optional_parameter<Normalization>(np, internal_np::normalization);
  return given ? *given : compute_normalization(tm, np);
}

// The one reader of the `voxel_resolutions` named parameter (any range of integers), checked by
// check_voxel_resolutions(): the grids of every stage live in the normalized cube.
template <typename NamedParameters>
std::vector<int> read_voxel_resolutions(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  // a copy: get_parameter() may return a temporary that a reference would outlive
  const auto range = choose_parameter(get_parameter(np, internal_np::voxel_resolutions), defaults::voxel_resolutions);
  std::vector<int> resolutions;
  for(const auto& r : range) resolutions.push_back(int(r));
  check_voxel_resolutions(resolutions);
  return resolutions;
}

} // namespace internal
/// \endcond

} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_NORMALIZATION_H
