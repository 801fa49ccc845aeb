// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_SUPERQUADRIC_H
#define CGAL_PART_DECOMPOSITION_SUPERQUADRIC_H

#include <CGAL/Part_decomposition/Voxel_grid.h>
#include <CGAL/Part_decomposition/normalization.h>
#include <CGAL/Part_decomposition/internal/fitting/superquadric_distance.h>

#include <CGAL/Bbox_3.h>
#include <CGAL/assertions.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Part_decomposition {

/*!
\ingroup PkgPartDecompositionRef
A superquadric (paper Sec.\ 3.3, Eq.\ 6): the solid
\f[
\left( \left|\frac{\bar x}{a_x}\right|^{2/\epsilon_2} + \left|\frac{\bar y}{a_y}\right|^{2/\epsilon_2} \right)^{\epsilon_2/\epsilon_1}
+ \left|\frac{\bar z}{a_z}\right|^{2/\epsilon_1} \le 1,
\qquad (\bar x, \bar y, \bar z)^\top = R^\top (p - c),
\f]
given by its semi-axes (scales) \f$a_x, a_y, a_z > 0\f$, its shape exponents
\f$\epsilon_1, \epsilon_2 \in [0, 2]\f$, a rotation \f$R\f$ whose columns are the local axes in
world coordinates (\f$R\f$ maps local to world coordinates), and its centre \f$c\f$.

All computations are done in `double`. Exponents are clamped to \f$[10^{-3}, 2]\f$ internally,
and every power is evaluated max-normalised, so that values and derivatives stay finite and
accurate for exponents near 0 (box-like shapes), near 2 (octahedron-like shapes) and for points
arbitrarily close to the centre.

\tparam GeomTraits a model of `PartDecompositionTraits`; only `GeomTraits::Point_3`,
`GeomTraits::Vector_3` and `GeomTraits::FT` are used.
*/
template <typename GeomTraits>
class Superquadric
{
public:
  /// \name Types
  /// @{

  /// the geometric traits
  typedef GeomTraits Geom_traits;
  /// the point type
  typedef typename GeomTraits::Point_3 Point_3;
  /// the vector type
  typedef typename GeomTraits::Vector_3 Vector_3;
  /// a 3x3 rotation matrix stored row by row: entry `(i,j)` at index `3*i+j`; column `j` is the
  /// local axis `j` in world coordinates.
  typedef std::array<double, 9> Rotation;
  /// @}

  /// \name Creation
  /// @{

  /// creates the unit ball centred at the origin.
  Superquadric() {}

  /// creates the superquadric of semi-axes `scales`, exponents `epsilon1` (\f$\epsilon_1\f$,
  /// along the local \f$z\f$ axis) and `epsilon2` (\f$\epsilon_2\f$, in the local \f$xy\f$
  /// plane), rotation `rotation` and centre `center`.
  /// \pre the scales are positive, the exponents in `[0,2]`, `rotation` is a rotation matrix.
  Superquadric(const std::array<double, 3>& scales, double epsilon1, double epsilon2,
               const Rotation& rotation, const Point_3& center)
  {
    set_scales(scales);
    set_exponents(epsilon1, epsilon2);
    set_rotation(rotation);
    set_center(center);
  }
  /// @}

  /// \name Parameters
  /// @{

  /// the semi-axes \f$(a_x, a_y, a_z)\f$.
  std::array<double, 3> scales() const { return {{m_data.a[0], m_data.a[1], m_data.a[2]}}; }
  /// \f$\epsilon_1\f$, the exponent along the local \f$z\f$ axis.
  double epsilon1() const { return m_data.e1; }
  /// \f$\epsilon_2\f$, the exponent in the local \f$xy\f$ plane.
  double epsilon2() const { return m_data.e2; }
  /// the rotation (local to world).
  Rotation rotation() const
  {
    Rotation R;
    std::copy(m_data.R, m_data.R + 9, R.begin());
    return R;
  }
  /// the local axis `i` (0, 1 or 2) in world coordinates: column `i` of the rotation.
  Vector_3 axis(int i) const
  {
    CGAL_precondition(i >= 0 && i < 3);
    return Vector_3(m_data.R[i], m_data.R[3 + i], m_data.R[6 + i]);
  }
  /// the centre.
  Point_3 center() const { return Point_3(m_data.c[0], m_data.c[1], m_data.c[2]); }

  /// sets the semi-axes. \pre they are positive and finite.
  void set_scales(const std::array<double, 3>& scales)
  {
    CGAL_precondition(scales[0] > 0. && scales[1] > 0. && scales[2] > 0.);
    for(int i = 0; i < 3; ++i) m_data.a[i] = scales[i];
  }
  /// sets the exponents. \pre both are in `[0,2]`.
  void set_exponents(double epsilon1, double epsilon2)
  {
    CGAL_precondition(epsilon1 >= 0. && epsilon1 <= 2. && epsilon2 >= 0. && epsilon2 <= 2.);
    m_data.e1 = epsilon1;
    m_data.e2 = epsilon2;
  }
  /// sets the rotation. \pre `rotation` is orthonormal with determinant 1 (up to rounding).
  void set_rotation(const Rotation& rotation)
  {
    std::copy(rotation.begin(), rotation.end(), m_data.R);
  }
  /// sets the centre.
  void set_center(const Point_3& center)
  {
    m_data.c[0] = CGAL::to_double(center.x());
    m_data.c[1] = CGAL::to_double(center.y());
    m_data.c[2] = CGAL::to_double(center.z());
  }
  /// @}

  /// \name Queries
  /// @{

  /// the inside-outside function \f$F(p)\f$ (left side of the equation above): less than 1
  /// inside, 1 on the surface, greater than 1 outside. It grows like
  /// \f$|p-c|^{2/\epsilon_1}\f$ and may be `+infinity` far away for tiny \f$\epsilon_1\f$;
  /// `signed_distance()` has no such range problem.
  double inside_outside(const Point_3& p) const
  {
    double x[3];
    const double q[3] = {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
    m_data.to_local(q, x);
    const double g = internal::superquadric_gauge(m_data, x);
    return std::pow(g, 2. / internal::clamp_exponent(m_data.e1));
  }

  /// the radial signed distance \f$\tilde d(p) = |p-c|\,(1 - F(p)^{-\epsilon_1/2})\f$: the signed
  /// distance from `p` to the surface point on the ray from the centre through `p`, negative
  /// inside. It is exact for spheres, equals \f$|\bar x_i| - a_i\f$ on a local axis, and is never
  /// smaller in magnitude than the Euclidean distance to the surface. At the centre itself it
  /// depends on the direction of approach; \f$-\min(a_x,a_y,a_z)\f$ is returned.
  double signed_distance(const Point_3& p) const
  {
    const double q[3] = {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
    return internal::superquadric_radial_distance(m_data, q);
  }

  /// returns whether `p` is in the closed solid (\f$F(p) \le 1\f$).
  bool has_on_bounded_side_or_boundary(const Point_3& p) const
  {
    double x[3];
    const double q[3] = {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
    m_data.to_local(q, x);
    return internal::superquadric_gauge(m_data, x) <= 1.;
  }

  /// the world axis-aligned bounding box of the local box \f$[-a_x,a_x]\times[-a_y,a_y]\times[-a_z,a_z]\f$,
  /// which contains the solid for every exponent in `[0,2]`.
  CGAL::Bbox_3 bbox() const
  {
    double e[3];
    internal::superquadric_half_extents(m_data, e);
    return CGAL::Bbox_3(m_data.c[0] - e[0], m_data.c[1] - e[1], m_data.c[2] - e[2],
                        m_data.c[0] + e[0], m_data.c[1] + e[1], m_data.c[2] + e[2]);
  }

  /// the volume of the solid: \f$2 a_x a_y a_z\, \epsilon_1 \epsilon_2\,
  /// B(\epsilon_1/2 + 1, \epsilon_1)\, B(\epsilon_2/2, \epsilon_2/2)\f$ with the Beta function \f$B\f$.
  double volume() const
  {
    const double e1 = internal::clamp_exponent(m_data.e1), e2 = internal::clamp_exponent(m_data.e2);
    auto log_beta = [](double x, double y) { return std::lgamma(x) + std::lgamma(y) - std::lgamma(x + y); };
    return 2. * m_data.a[0] * m_data.a[1] * m_data.a[2] *
           std::exp(std::log(e1) + std::log(e2) + log_beta(e1 / 2. + 1., e1) + log_beta(e2 / 2., e2 / 2.));
  }
  /// @}

  /// \name Rasterization and Sampling
  /// @{

  /// calls `f(i, j, k, index)` for every voxel `(i,j,k)` of the `r`\f$^3\f$ grid of the normalized
  /// cube \f$[-0.5,0.5]^3\f$ (same layout as `Voxel_grid`, `index = i + r*(j + r*k)`) whose centre
  /// satisfies \f$\tilde d \le\f$ `margin`; with `margin == 0` these are the voxel centres in the
  /// solid. Only the voxels of the world bounding box (grown by `margin`) are visited, in
  /// increasing index; the cost is linear in their number.
  /// \pre `r > 0` and `margin >= 0`.
  template <typename Function>
  void for_each_covered_voxel(int r, const Function& f, double margin = 0.) const
  {
    CGAL_precondition(r > 0 && margin >= 0.);
    internal::for_each_voxel_within(m_data, r, margin, f);
  }

  /// sets to `value` the voxels of `grid` covered as in `for_each_covered_voxel()`, and returns
  /// their number.
  template <typename T>
  std::size_t rasterize(Voxel_grid<T>& grid, const T& value, double margin = 0.) const
  {
    std::size_t n = 0;
    for_each_covered_voxel(grid.resolution(), [&](int, int, int, std::size_t idx) {
      grid[idx] = value;
      ++n;
    }, margin);
    return n;
  }

  /// writes points of the surface to `out`: a regular grid of spacing at most `spacing` on each
  /// face of the local box, projected radially onto the surface. Returns the output iterator.
  /// The number of points is linear in the area of the local box divided by `spacing`\f$^2\f$.
  /// \pre `spacing > 0`
  template <typename OutputIterator>
  OutputIterator sample_surface(double spacing, OutputIterator out) const
  {
    CGAL_precondition(spacing > 0.);
    internal::for_each_surface_sample(m_data, spacing, [&](const double p[3]) {
      *out++ = Point_3(p[0], p[1], p[2]);
      return true;
    });
    return out;
  }

  /*!
  adds the surface of the superquadric to `tm` as a closed, outward-oriented triangle mesh: each
  face of the local box is cut into a grid, `resolution` cells along the longest semi-axis and
  proportionally fewer (at least one) along the others, whose vertices are projected radially
  onto the surface. The mesh has \f$4(n_xn_y + n_yn_z + n_zn_x)\f$ triangles.

  \tparam PolygonMesh a model of `MutableFaceGraph`
  \tparam NamedParameters a sequence of named parameters

  \param tm the mesh the surface is added to (its previous content is kept)
  \param resolution the number of cells along the longest axis
  \param np an optional sequence of named parameters among the ones listed below

  \cgalNamedParamsBegin
    \cgalParamNBegin{vertex_point_map}
      \cgalParamDescription{a property map associating points to the vertices of `tm`}
      \cgalParamType{a class model of `WritablePropertyMap` with
                     `boost::graph_traits<PolygonMesh>::%vertex_descriptor` as key type and a
                     point type constructible from three `double` as value type}
      \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
    \cgalParamNEnd
  \cgalNamedParamsEnd

  \pre `resolution >= 1`
  */
  template <typename PolygonMesh, typename NamedParameters = CGAL::parameters::Default_named_parameters>
  void to_triangle_mesh(PolygonMesh& tm, int resolution,
                        const NamedParameters& np = CGAL::parameters::default_values()) const
  {
    CGAL_precondition(resolution >= 1);
    using CGAL::parameters::choose_parameter;
    using CGAL::parameters::get_parameter;
    typedef typename GetVertexPointMap<PolygonMesh, NamedParameters>::type VPM;
    typedef typename boost::property_traits<VPM>::value_type Mesh_point;
    typedef typename boost::graph_traits<PolygonMesh>::vertex_descriptor vertex_descriptor;
    VPM vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                               get_property_map(CGAL::vertex_point, tm));

    const double amax = (std::max)({m_data.a[0], m_data.a[1], m_data.a[2]});
    int n[3];
    for(int l = 0; l < 3; ++l)
      n[l] = (std::max)(1, int(std::ceil(double(resolution) * m_data.a[l] / amax - 1e-9)));

    std::unordered_map<long long, vertex_descriptor> lattice_vertex;
    auto vertex_at = [&](const int ijk[3]) {
      const long long key = ijk[0] + (long long)(n[0] + 1) * (ijk[1] + (long long)(n[1] + 1) * ijk[2]);
      auto it = lattice_vertex.find(key);
      if(it != lattice_vertex.end()) return it->second;
      double b[3];
      for(int l = 0; l < 3; ++l) b[l] = -m_data.a[l] + 2. * m_data.a[l] * double(ijk[l]) / double(n[l]);
      const double g = internal::superquadric_gauge(m_data, b);
      const double s[3] = {b[0] / g, b[1] / g, b[2] / g};
      double p[3];
      m_data.to_world(s, p);
      const vertex_descriptor v = add_vertex(tm);
      put(vpm, v, Mesh_point(p[0], p[1], p[2]));
      lattice_vertex.emplace(key, v);
      return v;
    };

    std::vector<vertex_descriptor> tri(3);
    for(int axis = 0; axis < 3; ++axis)
    {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      for(int side = 0; side <= 1; ++side)
        for(int iu = 0; iu < n[u]; ++iu)
          for(int iv = 0; iv < n[v]; ++iv)
          {
            // quad corners in (u,v); e_u x e_v = e_axis points outward on the upper side
            vertex_descriptor q[4];
            const int cu[4] = {iu, iu + 1, iu + 1, iu};
            const int cv[4] = {iv, iv, iv + 1, iv + 1};
            for(int c = 0; c < 4; ++c)
            {
              int ijk[3];
              ijk[axis] = side == 0 ? 0 : n[axis];
              ijk[u] = cu[c];
              ijk[v] = cv[c];
              q[c] = vertex_at(ijk);
            }
            if(side == 0) std::swap(q[1], q[3]);
            tri[0] = q[0]; tri[1] = q[1]; tri[2] = q[2];
            CGAL::Euler::add_face(tri, tm);
            tri[0] = q[0]; tri[1] = q[2]; tri[2] = q[3];
            CGAL::Euler::add_face(tri, tm);
          }
    }
  }
  /// @}

  /// \name Coordinate Systems
  /// @{

  /// the same solid in input coordinates, for a superquadric given in the normalized cube of
  /// `normalization`: scales divided by `normalization.scale()`, centre mapped by
  /// `normalization.from_unit()`, same rotation and exponents.
  Superquadric in_input_coordinates(const Normalization& normalization) const
  {
    Superquadric s(*this);
    for(int i = 0; i < 3; ++i) s.m_data.a[i] = m_data.a[i] / normalization.scale();
    const std::array<double, 3> c = normalization.from_unit({{m_data.c[0], m_data.c[1], m_data.c[2]}});
    for(int i = 0; i < 3; ++i) s.m_data.c[i] = c[i];
    return s;
  }
  /// the inverse of `in_input_coordinates()`.
  Superquadric in_normalized_coordinates(const Normalization& normalization) const
  {
    Superquadric s(*this);
    for(int i = 0; i < 3; ++i) s.m_data.a[i] = m_data.a[i] * normalization.scale();
    const std::array<double, 3> c = normalization.to_unit(m_data.c[0], m_data.c[1], m_data.c[2]);
    for(int i = 0; i < 3; ++i) s.m_data.c[i] = c[i];
    return s;
  }
  /// @}

  /// \cond SKIP_IN_MANUAL
  const internal::Superquadric_data& data() const { return m_data; }
  explicit Superquadric(const internal::Superquadric_data& d) : m_data(d) {}
  /// \endcond

private:
  internal::Superquadric_data m_data;
};

/// \cond SKIP_IN_MANUAL
namespace internal {

// The box-like superquadric of a box on its axes (`Box`: Part_box of internal/part_merging.h),
// `origin` (an Eigen vector) added back to its centre.
template <typename GeomTraits, typename Box, typename Vector>
Superquadric<GeomTraits> box_superquadric(const Box& b, const Vector& origin)
{
  typedef typename GeomTraits::Point_3 Point_3;
  // flat or degenerate parts still need positive semi-axes
  const double floor_axis = (std::max)(1e-6 * b.half.maxCoeff(), std::numeric_limits<double>::min());
  std::array<double, 3> scales;
  for(int i = 0; i < 3; ++i) scales[i] = (std::max)(b.half[i], floor_axis);
  typename Superquadric<GeomTraits>::Rotation R;
  for(int i = 0; i < 3; ++i)
    for(int j = 0; j < 3; ++j) R[3 * i + j] = b.axes(i, j);
  const double c[3] = {origin[0] + b.center[0], origin[1] + b.center[1], origin[2] + b.center[2]};
  return Superquadric<GeomTraits>(scales, 0.1, 0.1, R, Point_3(c[0], c[1], c[2]));
}

} // namespace internal
/// \endcond

} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_SUPERQUADRIC_H
