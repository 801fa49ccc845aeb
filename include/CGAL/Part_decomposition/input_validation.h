// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INPUT_VALIDATION_H
#define CGAL_PART_DECOMPOSITION_INPUT_VALIDATION_H

#include <CGAL/Part_decomposition/parameters.h>

#include <CGAL/assertions.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Part_decomposition {

/*!
\ingroup PkgPartDecompositionRef
What is wrong with an input, as reported by `Invalid_input::error()`.
*/
enum class Input_error
{
  UNREADABLE_FILE,        ///< the file cannot be opened or parsed
  NO_FACES,               ///< the mesh or file has no face
  INVALID_FACE,           ///< a face refers to a vertex that does not exist or has fewer than 3 vertices
  NOT_TRIANGLE_MESH,      ///< a face of the mesh is not a triangle
  NON_FINITE_COORDINATES, ///< a vertex coordinate is infinite or NaN
  DEGENERATE_EXTENT,      ///< all vertices coincide: the shape has no extent to normalize
  INVALID_PARAMETER,      ///< a named parameter is out of its documented range
  COORDINATES_OUT_OF_RANGE ///< a coordinate or the extent is outside the range of `maximum_coordinate` and `minimum_extent`
};

/*!
\ingroup PkgPartDecompositionRef
The largest absolute value of a vertex coordinate the package accepts. Squared and fourth powers
of lengths (areas, cotangent weights, covariances) must stay far from overflow; results are
checked to be independent of the scale from `minimum_extent` to this value.
*/
constexpr double maximum_coordinate = 1e30;

/*!
\ingroup PkgPartDecompositionRef
The smallest extent (longest side of the bounding box) of a mesh the package accepts, for the
same reason as `maximum_coordinate`, at the other end of the range of `double`.
*/
constexpr double minimum_extent = 1e-30;

/*!
\ingroup PkgPartDecompositionRef
The exception thrown by the functions of this package when the user's data cannot be processed.
Unlike \cgal preconditions, these checks are done in every build type (also with `NDEBUG`).
*/
class Invalid_input : public std::invalid_argument
{
public:
  /// creates the exception for `error` with the human-readable explanation `what`.
  Invalid_input(Input_error error, const std::string& what)
    : std::invalid_argument(what), m_error(error)
  {}
  /// what is wrong.
  Input_error error() const { return m_error; }

private:
  Input_error m_error;
};

/// \cond SKIP_IN_MANUAL
namespace internal {

// The bounding box [lo, hi] of the vertices of `tm` incident to a face (vertex by vertex: a face
// loop visits each vertex six times); throws if one has a non-finite coordinate. Returns false if
// `tm` has no face.
template <typename FaceGraph, typename VertexPointMap>
bool face_vertex_box(const FaceGraph& tm, const VertexPointMap& vpm, double lo[3], double hi[3])
{
  std::fill(lo, lo + 3, std::numeric_limits<double>::infinity());
  std::fill(hi, hi + 3, -std::numeric_limits<double>::infinity());
  bool any = false;
  for(auto v : vertices(tm))
  {
    const auto h = halfedge(v, tm);
    if(h == boost::graph_traits<FaceGraph>::null_halfedge()) continue;
    bool on_face = false;
    for(auto g : halfedges_around_target(h, tm))
      if(!is_border(g, tm)) { on_face = true; break; }
    if(!on_face) continue;
    const auto& p = get(vpm, v);
    const double c[3] = {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
    for(int a = 0; a < 3; ++a)
    {
      if(!std::isfinite(c[a]))
        throw Invalid_input(Input_error::NON_FINITE_COORDINATES, "a vertex has a non-finite coordinate");
      lo[a] = (std::min)(lo[a], c[a]);
      hi[a] = (std::max)(hi[a], c[a]);
    }
    any = true;
  }
  return any;
}

// The bounding box [lo, hi] of finite coordinates must have an extent and lie in the range where
// squared lengths neither overflow nor underflow.
inline void check_extent(const double lo[3], const double hi[3])
{
  long double extent = 0;
  double magnitude = 0.;
  for(int a = 0; a < 3; ++a)
  {
    extent = (std::max)(extent, static_cast<long double>(hi[a]) - lo[a]);
    magnitude = (std::max)(magnitude, (std::max)(std::abs(lo[a]), std::abs(hi[a])));
  }
  if(!(extent > 0))
    throw Invalid_input(Input_error::DEGENERATE_EXTENT, "all vertices of the mesh coincide");
  if(!(magnitude <= maximum_coordinate) || !(extent >= minimum_extent))
    throw Invalid_input(Input_error::COORDINATES_OUT_OF_RANGE,
                        "the coordinates are out of range: each must be at most 1e30 in absolute value and "
                        "the mesh at least 1e-30 wide");
}

// Whether `index` maps the elements of `range` one to one onto [0, n).
template <typename Range, typename IndexMap>
bool is_bijection_onto_range(const Range& range, const IndexMap& index, std::size_t n)
{
  std::vector<char> seen(n, 0);
  std::size_t count = 0;
  for(auto x : range)
  {
    const std::size_t i = std::size_t(get(index, x));
    if(!(i < n) || seen[i]) return false;
    seen[i] = 1;
    ++count;
  }
  return count == n;
}

// The checks of the named parameters: one message format, "NAME must be RULE", for every stage;
// the RULE of a named parameter is its range in parameter_table.

// Throws Invalid_input (INVALID_PARAMETER) "NAME must be RULE" unless `ok`.
inline void check_parameter(bool ok, const char* name, const char* rule)
{
  if(!ok) throw Invalid_input(Input_error::INVALID_PARAMETER, std::string(name) + " must be " + rule);
}

// The same for the named parameter `name`, whose rule is its range in parameter_table.
inline void check_parameter(bool ok, const char* name)
{
  CGAL_assertion(*range_rule(name) != '\0');
  check_parameter(ok, name, range_rule(name));
}

inline void check_positive(double x, const char* name) { check_parameter(x > 0. && std::isfinite(x), name); }

inline void check_non_negative(double x, const char* name) { check_parameter(x >= 0. && std::isfinite(x), name); }

// An integer named parameter converted to T, checked first to be at least `minimum` and to fit in T.
template <typename T, typename V>
T checked_integer(V value, T minimum, const char* name)
{
  static_assert(std::is_integral<V>::value, "this named parameter takes an integer");
  bool ok = true;
  if constexpr(std::is_signed<V>::value) ok = value >= V(0);
  typedef unsigned long long U;
  ok = ok && U(value) >= U(minimum) && U(value) <= U((std::numeric_limits<T>::max)());
  check_parameter(ok, name);
  return T(value);
}

// The rule of `voxel_resolutions`: powers of two from 1 to 256, each twice the previous.
inline void check_voxel_resolutions(const std::vector<int>& r)
{
  bool ok = !r.empty();
  for(std::size_t l = 0; ok && l < r.size(); ++l)
    ok = r[l] >= 1 && r[l] <= 256 && (r[l] & (r[l] - 1)) == 0 && (l == 0 || r[l] == 2 * r[l - 1]);
  check_parameter(ok, "voxel_resolutions");
}

} // namespace internal
/// \endcond

/*!
\ingroup PkgPartDecompositionRef
checks that `tm` can be decomposed: it has at least one face, every face is a triangle, every
vertex of a face has finite coordinates, not all equal, of absolute value at most
`maximum_coordinate`, the extent of the mesh is at least `minimum_extent`, and the vertex and face
index maps number the vertices and faces from 0 to `num_vertices(tm) - 1` and `num_faces(tm) - 1`
(a `CGAL::Surface_mesh` after removals needs `collect_garbage()`). Open, non-manifold, self-intersecting meshes and
meshes of several connected components are accepted.

\par Complexity
Linear in the size of `tm`.

\tparam TriangleMesh a model of `FaceListGraph` and `VertexListGraph`
\tparam NamedParameters a sequence of named parameters

\param tm the mesh
\param np an optional sequence of named parameters; this function reads `vertex_point_map`,
`vertex_index_map` and `face_index_map` (\ref PD_MeshParameters)

\throws Invalid_input if one of the conditions above does not hold: `NO_FACES`,
`NOT_TRIANGLE_MESH`, `NON_FINITE_COORDINATES`, `DEGENERATE_EXTENT`, `COORDINATES_OUT_OF_RANGE`, or
`INVALID_PARAMETER` for an index map.
*/
template <typename TriangleMesh, typename NamedParameters = CGAL::parameters::Default_named_parameters>
void check_input(const TriangleMesh& tm, const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename GetVertexPointMap<TriangleMesh, NamedParameters>::const_type VPM;
  const VPM vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                   get_const_property_map(CGAL::vertex_point, tm));

  if(faces(tm).begin() == faces(tm).end())
    throw Invalid_input(Input_error::NO_FACES, "the mesh has no face");
  for(auto f : faces(tm))
    if(degree(f, tm) != 3)
      throw Invalid_input(Input_error::NOT_TRIANGLE_MESH, "the mesh has a face that is not a triangle");

  // The stages size arrays by num_vertices() and num_faces() and turn indices back into
  // elements: each index map must be a bijection onto [0, n). It is not on a Surface_mesh with
  // removed elements, whose num_faces() still counts them.
  {
    const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
    if(!internal::is_bijection_onto_range(vertices(tm), vim, std::size_t(num_vertices(tm))))
      throw Invalid_input(Input_error::INVALID_PARAMETER,
                          "the vertex indices are not 0 to num_vertices() - 1 (a Surface_mesh with removed "
                          "elements needs collect_garbage())");
    const auto fim = CGAL::get_initialized_face_index_map(tm, np);
    if(!internal::is_bijection_onto_range(faces(tm), fim, std::size_t(num_faces(tm))))
      throw Invalid_input(Input_error::INVALID_PARAMETER,
                          "the face indices are not 0 to num_faces() - 1 (a Surface_mesh with removed "
                          "elements needs collect_garbage())");
  }

  double lo[3], hi[3];
  internal::face_vertex_box(tm, vpm, lo, hi);
  internal::check_extent(lo, hi);
}

} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INPUT_VALIDATION_H
