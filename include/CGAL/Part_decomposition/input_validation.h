// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INPUT_VALIDATION_H
#define CGAL_PART_DECOMPOSITION_INPUT_VALIDATION_H

#include <CGAL/Part_decomposition/parameters.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>

#include <cmath>
#include <stdexcept>
#include <string>

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
  INVALID_PARAMETER       ///< a named parameter is out of its documented range
};

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

/*!
\ingroup PkgPartDecompositionRef
checks that `tm` can be decomposed: it has at least one face, every face is a triangle, and every
vertex has finite coordinates, not all equal. Open, non-manifold, self-intersecting meshes and
meshes of several connected components are accepted.

\par Complexity
Linear in the size of `tm`.

\tparam TriangleMesh a model of `FaceListGraph`
\tparam NamedParameters a sequence of named parameters

\param tm the mesh
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{vertex_point_map}
    \cgalParamDescription{a property map associating points to the vertices of `tm`}
    \cgalParamType{a class model of `ReadablePropertyMap` with
                   `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and
                   `%Point_3` as value type}
    \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\throws Invalid_input if one of the conditions above does not hold.
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

  bool first = true, distinct = false;
  double ref[3] = {0., 0., 0.};
  for(auto f : faces(tm))
    for(auto v : vertices_around_face(halfedge(f, tm), tm))
    {
      const auto& p = get(vpm, v);
      const double c[3] = {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
      for(int a = 0; a < 3; ++a)
      {
        if(!std::isfinite(c[a]))
          throw Invalid_input(Input_error::NON_FINITE_COORDINATES,
                              "a vertex has a non-finite coordinate");
        if(first)
          ref[a] = c[a];
        else if(c[a] != ref[a])
          distinct = true;
      }
      first = false;
    }
  if(!distinct)
    throw Invalid_input(Input_error::DEGENERATE_EXTENT, "all vertices of the mesh coincide");
}

} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INPUT_VALIDATION_H
