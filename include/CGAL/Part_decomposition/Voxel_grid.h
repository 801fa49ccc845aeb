// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_VOXEL_GRID_H
#define CGAL_PART_DECOMPOSITION_VOXEL_GRID_H

#include <CGAL/assertions.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Part_decomposition {

/*!
\ingroup PkgPartDecompositionRef
returns the index, along one axis, of the voxel of the `r`-grid of the normalized cube
\f$[-0.5,0.5]^3\f$ that contains the coordinate `p`: \f$\min(r-1, \lfloor (p+0.5)\,r \rfloor)\f$,
clamped to `[0, r-1]`. A coordinate on a voxel face belongs to the upper voxel, and `p = 0.5`
to the last voxel.
*/
inline int voxel_coordinate(double p, int r)
{
  const double t = std::floor((p + 0.5) * double(r));
  if(!(t > 0.)) return 0; // also maps NaN to 0
  if(t >= double(r - 1)) return r - 1;
  return int(t);
}

/*!
\ingroup PkgPartDecompositionRef
The role of a voxel in the Flow/Freeze prior (paper Sec.\ 3.2): `FLOW` voxels are low-complexity
surface support where primitives may grow, `FREEZE` voxels mark articulation and thin-structure
boundaries that stop them, `EMPTY` voxels hold no surface sample.
*/
enum class Voxel_class : std::uint8_t
{
  EMPTY = 0,  ///< no surface sample
  FLOW = 1,   ///< surface support below the Freeze threshold
  FREEZE = 2  ///< surface support at or above the Freeze threshold
};

/*!
\ingroup PkgPartDecompositionRef
A dense cubic grid of `r`\f$^3\f$ values over the normalized cube \f$[-0.5,0.5]^3\f$: voxel
`(i,j,k)` is the box \f$[-0.5 + i/r, -0.5 + (i+1)/r] \times \dots\f$ and is stored at the
linear index `i + r*(j + r*k)`. Every resolution of the method (16, 32, 64 by default) uses it.

\tparam T the value type. Use `std::uint8_t` rather than `bool` for masks
(`std::vector<bool>` has no references to its elements).
*/
template <typename T>
class Voxel_grid
{
public:
  /// the value type
  typedef T value_type;

  /// creates an empty grid of resolution 0.
  Voxel_grid() : m_r(0) {}

  /// creates a grid of resolution `r` with every value set to `value`.
  /// \pre `r >= 0`
  explicit Voxel_grid(int r, const T& value = T())
    : m_r(r), m_values(std::size_t(r) * std::size_t(r) * std::size_t(r), value)
  {
    CGAL_precondition(r >= 0);
  }

  /// the number of voxels per axis.
  int resolution() const { return m_r; }
  /// the total number of voxels, `r`\f$^3\f$.
  std::size_t size() const { return m_values.size(); }
  /// the edge length of a voxel, `1/r`.
  double voxel_size() const { return 1. / double(m_r); }

  /// the linear index of voxel `(i,j,k)`.
  std::size_t index(int i, int j, int k) const
  {
    CGAL_precondition(contains(i, j, k));
    return std::size_t(i) + std::size_t(m_r) * (std::size_t(j) + std::size_t(m_r) * std::size_t(k));
  }
  /// the coordinates `(i,j,k)` of the voxel of linear index `idx`.
  std::array<int, 3> coordinates(std::size_t idx) const
  {
    CGAL_precondition(idx < size());
    const std::size_t r = std::size_t(m_r);
    return {{int(idx % r), int((idx / r) % r), int(idx / (r * r))}};
  }
  /// returns whether `(i,j,k)` is a voxel of the grid.
  bool contains(int i, int j, int k) const
  {
    return i >= 0 && j >= 0 && k >= 0 && i < m_r && j < m_r && k < m_r;
  }

  /// the centre of voxel `(i,j,k)` in the normalized cube.
  std::array<double, 3> center(int i, int j, int k) const
  {
    const double h = voxel_size();
    return {{-0.5 + (i + 0.5) * h, -0.5 + (j + 0.5) * h, -0.5 + (k + 0.5) * h}};
  }
  /// the centre of the voxel of linear index `idx`.
  std::array<double, 3> center(std::size_t idx) const
  {
    const std::array<int, 3> c = coordinates(idx);
    return center(c[0], c[1], c[2]);
  }
  /// the coordinates of the voxel that contains the point `(x,y,z)` of the normalized cube
  /// (points outside the cube are clamped to the border voxels).
  std::array<int, 3> locate(double x, double y, double z) const
  {
    return {{voxel_coordinate(x, m_r), voxel_coordinate(y, m_r), voxel_coordinate(z, m_r)}};
  }

  /// \name Value access
  /// @{

  /// the value of voxel `(i,j,k)`. \pre `contains(i, j, k)`
  T& operator()(int i, int j, int k) { return m_values[index(i, j, k)]; }
  /// the value of voxel `(i,j,k)`. \pre `contains(i, j, k)`
  const T& operator()(int i, int j, int k) const { return m_values[index(i, j, k)]; }
  /// the value of the voxel of linear index `idx`. \pre `idx < size()`
  T& operator[](std::size_t idx) { return m_values[idx]; }
  /// the value of the voxel of linear index `idx`. \pre `idx < size()`
  const T& operator[](std::size_t idx) const { return m_values[idx]; }
  /// sets every value to `value`.
  void fill(const T& value) { std::fill(m_values.begin(), m_values.end(), value); }
  /// the values in linear-index order.
  std::vector<T>& values() { return m_values; }
  /// the values in linear-index order.
  const std::vector<T>& values() const { return m_values; }
  /// @}

  friend bool operator==(const Voxel_grid& a, const Voxel_grid& b)
  {
    return a.m_r == b.m_r && a.m_values == b.m_values;
  }
  friend bool operator!=(const Voxel_grid& a, const Voxel_grid& b) { return !(a == b); }

private:
  int m_r;
  std::vector<T> m_values;
};

} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_VOXEL_GRID_H
