// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_GEOMETRIC_CUES_H
#define CGAL_PART_DECOMPOSITION_GEOMETRIC_CUES_H

#include <CGAL/Part_decomposition/input_validation.h>
#include <CGAL/Part_decomposition/parameters.h>
#include <CGAL/Part_decomposition/internal/cues/mean_curvature.h>
#include <CGAL/Part_decomposition/internal/cues/normal_deviation.h>
#include <CGAL/Part_decomposition/internal/toolbox/toolbox.h>
#include <CGAL/Part_decomposition/internal/toolbox/triangle_arrays.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/assertions.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace CGAL {
namespace Part_decomposition {

/// \cond SKIP_IN_MANUAL
namespace internal {

// The mesh as Triangle_arrays. Throws Invalid_input(NOT_TRIANGLE_MESH) on a face that is not a triangle.
template <typename TriangleMesh, typename VertexPointMap, typename VertexIndexMap, typename FaceIndexMap>
Triangle_arrays make_triangle_arrays(const TriangleMesh& tm, const VertexPointMap& vpm,
                                     const VertexIndexMap& vim, const FaceIndexMap& fim)
{
  Triangle_arrays arrays;
  const std::size_t nv = num_vertices(tm), nf = num_faces(tm);
  CGAL_precondition(nv < std::size_t((std::numeric_limits<std::uint32_t>::max)()));
  arrays.points.assign(nv, Vec3{{0., 0., 0.}});
  arrays.faces.resize(nf);
  for(auto v : vertices(tm))
  {
    const std::size_t i = std::size_t(get(vim, v));
    CGAL_precondition(i < nv);
    arrays.points[i] = vec3_of(get(vpm, v));
  }
  for(auto f : faces(tm))
  {
    const std::size_t fi = std::size_t(get(fim, f));
    CGAL_precondition(fi < nf);
    auto h = halfedge(f, tm);
    std::array<std::uint32_t, 3> corners;
    for(int c = 0; c < 3; ++c)
    {
      corners[c] = std::uint32_t(get(vim, target(h, tm)));
      h = next(h, tm);
    }
    if(h != halfedge(f, tm))
      throw Invalid_input(Input_error::NOT_TRIANGLE_MESH, "the mesh has a face that is not a triangle");
    arrays.faces[fi] = corners;
  }
  return arrays;
}

// The same with the maps of the named parameters.
template <typename TriangleMesh, typename NamedParameters>
Triangle_arrays make_triangle_arrays(const TriangleMesh& tm, const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename GetVertexPointMap<TriangleMesh, NamedParameters>::const_type VPM;
  const VPM vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                   get_const_property_map(CGAL::vertex_point, tm));
  return make_triangle_arrays(tm, vpm, CGAL::get_initialized_vertex_index_map(tm, np),
                              CGAL::get_initialized_face_index_map(tm, np));
}

// The named parameters of the geometric cues; one reader for the three cue functions and the prior.
struct Cue_parameters
{
  double curvature_percentile;
  std::size_t number_of_neighbors;
  bool use_concave_curvature;
};

template <typename NamedParameters>
Cue_parameters read_cue_parameters(const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  Cue_parameters p;
  p.curvature_percentile =
    double(choose_parameter(get_parameter(np, internal_np::curvature_percentile), defaults::curvature_percentile));
  check_parameter(p.curvature_percentile >= 0. && p.curvature_percentile <= 100., "curvature_percentile");
  const double k = double(choose_parameter(get_parameter(np, internal_np::number_of_neighbors), defaults::number_of_neighbors));
  check_parameter(k >= 1. && k <= 1e6 && k == std::floor(k), "number_of_neighbors");
  p.number_of_neighbors = std::size_t(k);
  p.use_concave_curvature = internal::method_switches(np).use_concave_curvature;
  return p;
}

// c_f of every face (face_curvature_cue() of the vertex mean curvatures, concave ones only if
// `use_concave_curvature`): the one computation behind the curvature cue of every stage.
template <typename ConcurrencyTag>
std::vector<double> face_curvatures(const Triangle_arrays& mesh, const Vertex_corners& vc, const Cue_parameters& p)
{
  const std::vector<double> kappa = vertex_mean_curvatures<ConcurrencyTag>(mesh, vc, p.use_concave_curvature);
  return face_curvature_cue(mesh, vc, kappa, p.curvature_percentile);
}

template <typename TriangleMesh, typename FaceMap, typename NamedParameters>
void write_face_values(const TriangleMesh& tm, FaceMap map, const std::vector<double>& values,
                       const NamedParameters& np)
{
  const auto fim = CGAL::get_initialized_face_index_map(tm, np);
  for(auto f : faces(tm)) put(map, f, values[std::size_t(get(fim, f))]);
}

} // namespace internal
/// \endcond

/*!
\ingroup PkgPartDecompositionRef
computes the mean curvature \f$\kappa_v = \|\mathbf{H}_v\|/2\f$ of every vertex of `tm`, where
\f$\mathbf{H}_v = \frac{1}{2A_v}\sum_j (\cot\alpha_{vj} + \cot\beta_{vj})(\mathbf{x}_v - \mathbf{x}_j)\f$
is the mean-curvature normal given by the cotangent Laplace-Beltrami operator and \f$A_v\f$ the
mixed Voronoi area of Meyer et al.\ (Voronoi area in non-obtuse triangles, half the triangle's
area at an obtuse corner, a quarter at the other corners). A sphere of radius \f$R\f$ gives
\f$1/R\f$, a cylinder \f$1/(2R)\f$, a plane 0 (paper App.\ B).

At a border edge the missing cotangent is left out; the sum then also measures how the border
curve bends within the surface, so at a border vertex (one of its edges has a single incident
face) only the component of \f$\mathbf{H}_v\f$ along the area-weighted vertex normal is kept:
a flat sheet gives 0 on its rim too, a spherical cap \f$1/R\f$. A triangle whose doubled area is at most
\f$10^{-12}\f$ times its longest squared edge is degenerate and contributes nothing; a vertex
with no non-degenerate incident face (also an isolated vertex) gets 0. Values are always finite.
The computation is done in `double`.

\par Complexity
Linear in the size of `tm`: one pass over the corners of the faces.

\tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag`
\tparam TriangleMesh a model of `FaceListGraph` and `VertexListGraph`
\tparam VertexCurvatureMap a model of `WritablePropertyMap` with
        `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and `double` as value type
\tparam NamedParameters a sequence of named parameters

\param tm the triangle mesh
\param vertex_curvature_map receives \f$\kappa_v\f$ for every vertex
\param np an optional sequence of named parameters; this function reads `vertex_point_map`,
`vertex_index_map` and `face_index_map` (\ref PD_MeshParameters)

\pre `tm` has no garbage (`Surface_mesh`)
\throws Invalid_input (`NOT_TRIANGLE_MESH`) if a face of `tm` is not a triangle.
*/
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename TriangleMesh,
          typename VertexCurvatureMap, typename NamedParameters = CGAL::parameters::Default_named_parameters>
void compute_vertex_mean_curvature(const TriangleMesh& tm, VertexCurvatureMap vertex_curvature_map,
                                   const NamedParameters& np = CGAL::parameters::default_values())
{
  internal::static_check_concurrency_tag<ConcurrencyTag>();
  const internal::Triangle_arrays mesh = internal::make_triangle_arrays(tm, np);
  const std::vector<double> kappa =
    internal::vertex_mean_curvatures<ConcurrencyTag>(mesh, internal::make_vertex_corners(mesh));
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  for(auto v : vertices(tm)) put(vertex_curvature_map, v, kappa[std::size_t(get(vim, v))]);
}

/*!
\ingroup PkgPartDecompositionRef
computes the face curvature cue \f$c_f \in [0,1]\f$ of paper App.\ B: the vertex mean curvatures
of `compute_vertex_mean_curvature()`, those of the convex vertices set to 0 (`use_concave_curvature`,
see below), are clipped at their `curvature_percentile`-th percentile
(over the vertices incident to a face; linear interpolation between order statistics, as
`numpy.quantile`), divided by the maximum of the clipped values, and averaged over the three
vertices of each face. If that maximum is 0 or below \f$10^{-9}\f$ divided by the diagonal of the
bounding box of `tm` (rounding noise on a planar mesh), every \f$c_f\f$ is 0.

A vertex is convex if its cotangent Laplacian \f$\sum_j (\cot\alpha_{ij} + \cot\beta_{ij})(x_i - x_j)\f$
points to the side of its faces' normals (the outside of a closed surface oriented outward, as the
reader orients it; an open surface is taken as it is oriented). Parts meet where the surface is
concave (the minima rule of Hoffman and Richards): the convex curvature of a thin limb, which the
paper's \f$|H|/2\f$ counts in full, would mark the whole limb as a boundary and leave no room to fit
it; `use_concave_curvature = false` gives the paper's cue.

\par Complexity
Linear in the size of `tm` (the percentile is a selection, not a sort).

\tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag`
\tparam TriangleMesh a model of `FaceListGraph` and `VertexListGraph`
\tparam FaceCurvatureMap a model of `WritablePropertyMap` with
        `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and `double` as value type
\tparam NamedParameters a sequence of named parameters

\param tm the triangle mesh
\param face_curvature_map receives \f$c_f\f$ for every face
\param np an optional sequence of named parameters; this function reads `vertex_point_map`,
`vertex_index_map`, `face_index_map` (\ref PD_MeshParameters), `curvature_percentile` and
`method_variant` (its switch `use_concave_curvature`) (\ref PD_ParameterTable)

\pre `tm` has no garbage (`Surface_mesh`)
\throws Invalid_input (`NOT_TRIANGLE_MESH`) if a face is not a triangle, (`INVALID_PARAMETER`) if
`curvature_percentile` or `number_of_neighbors` is out of range (the cue functions share one
check of their parameters).
*/
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename TriangleMesh,
          typename FaceCurvatureMap, typename NamedParameters = CGAL::parameters::Default_named_parameters>
void compute_face_curvature_cue(const TriangleMesh& tm, FaceCurvatureMap face_curvature_map,
                                const NamedParameters& np = CGAL::parameters::default_values())
{
  internal::static_check_concurrency_tag<ConcurrencyTag>();
  const internal::Cue_parameters parameters = internal::read_cue_parameters(np);
  const internal::Triangle_arrays mesh = internal::make_triangle_arrays(tm, np);
  internal::write_face_values(
    tm, face_curvature_map,
    internal::face_curvatures<ConcurrencyTag>(mesh, internal::make_vertex_corners(mesh), parameters), np);
}

/*!
\ingroup PkgPartDecompositionRef
computes the normal deviation cue of paper App.\ B for every face `f`:
\f$\phi_{norm}(f) = \frac{2}{\pi}\,\frac{1}{|N_f|}\sum_{f' \in N_f} \arccos\langle n_f, n_{f'}\rangle\f$,
where \f$N_f\f$ are the `number_of_neighbors` faces whose centroids are nearest to the centroid
of `f` (a kd-tree search, `CGAL::Orthogonal_k_neighbor_search`), `f` itself excluded. The value
is in \f$[0, 2]\f$ and is not clipped: values above 1 mean neighbouring normals turn by more than
a right angle, as at thin sheets.

Details: the dot product is clamped to \f$[-1,1]\f$. A degenerate (zero-area, see
`compute_vertex_mean_curvature()`) face has no normal: it is nobody's neighbour, and its value is
the mean value of its `number_of_neighbors` nearest non-degenerate faces. When another face has
the same centroid as `f` (duplicated faces), `f` may not come first in the search: then the
farthest of the `number_of_neighbors + 1` faces found is dropped instead of `f`. Ties at the last
distance are broken by the kd-tree: the result is deterministic and does not depend on the
number of threads. A mesh with fewer faces gives smaller neighbourhoods; a face with no neighbour
gets 0.

\par Complexity
\f$O(F \log F)\f$ for \f$F\f$ faces: the kd-tree of the centroids is built once, and each of the \f$F\f$
queries for `number_of_neighbors` neighbours takes logarithmic time in practice.

\tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag`
\tparam TriangleMesh a model of `FaceListGraph` and `VertexListGraph`
\tparam FaceNormalDeviationMap a model of `WritablePropertyMap` with
        `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and `double` as value type
\tparam NamedParameters a sequence of named parameters

\param tm the triangle mesh
\param face_normal_deviation_map receives \f$\phi_{norm}(f)\f$ for every face
\param np an optional sequence of named parameters; this function reads `vertex_point_map`,
`vertex_index_map`, `face_index_map` (\ref PD_MeshParameters) and `number_of_neighbors`
(\ref PD_ParameterTable)

\pre `tm` has no garbage (`Surface_mesh`)
\throws Invalid_input (`NOT_TRIANGLE_MESH`) if a face is not a triangle, (`INVALID_PARAMETER`) if
`number_of_neighbors` is not a positive integer or `curvature_percentile` is out of range (the cue
functions share one check of their parameters).
*/
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename TriangleMesh,
          typename FaceNormalDeviationMap, typename NamedParameters = CGAL::parameters::Default_named_parameters>
void compute_face_normal_deviation(const TriangleMesh& tm, FaceNormalDeviationMap face_normal_deviation_map,
                                   const NamedParameters& np = CGAL::parameters::default_values())
{
  internal::static_check_concurrency_tag<ConcurrencyTag>();
  const std::size_t k = internal::read_cue_parameters(np).number_of_neighbors;
  const internal::Triangle_arrays mesh = internal::make_triangle_arrays(tm, np);
  internal::write_face_values(tm, face_normal_deviation_map,
                              internal::face_normal_deviation<ConcurrencyTag>(mesh, k), np);
}

/*!
\ingroup PkgPartDecompositionRef
computes the two per-face geometric cues of paper App.\ B in one call: the face curvature cue
\f$c_f\f$ (`compute_face_curvature_cue()`) and the normal deviation \f$\phi_{norm}(f)\f$
(`compute_face_normal_deviation()`). They feed `compute_topology_score()`.

\par Complexity
\f$O(F \log F)\f$ for \f$F\f$ faces, dominated by the normal deviation.

\tparam ConcurrencyTag `CGAL::Sequential_tag` or `CGAL::Parallel_tag`
\tparam TriangleMesh a model of `FaceListGraph` and `VertexListGraph`
\tparam FaceCurvatureMap a model of `WritablePropertyMap` with
        `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and `double` as value type
\tparam FaceNormalDeviationMap a model of `WritablePropertyMap` with
        `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and `double` as value type
\tparam NamedParameters a sequence of named parameters

\param tm the triangle mesh
\param face_curvature_map receives \f$c_f \in [0,1]\f$ for every face
\param face_normal_deviation_map receives \f$\phi_{norm}(f) \in [0,2]\f$ for every face
\param np an optional sequence of named parameters; this function reads `vertex_point_map`,
`vertex_index_map`, `face_index_map` (\ref PD_MeshParameters), `curvature_percentile`,
`number_of_neighbors` and `method_variant` (its switch `use_concave_curvature`) (\ref PD_ParameterTable)

\pre `tm` has no garbage (`Surface_mesh`)
\throws Invalid_input (`NOT_TRIANGLE_MESH`) if a face is not a triangle, (`INVALID_PARAMETER`) if
a parameter is out of range.
*/
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename TriangleMesh,
          typename FaceCurvatureMap, typename FaceNormalDeviationMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
void compute_geometric_cues(const TriangleMesh& tm, FaceCurvatureMap face_curvature_map,
                            FaceNormalDeviationMap face_normal_deviation_map,
                            const NamedParameters& np = CGAL::parameters::default_values())
{
  internal::static_check_concurrency_tag<ConcurrencyTag>();
  const internal::Cue_parameters parameters = internal::read_cue_parameters(np);
  const internal::Triangle_arrays mesh = internal::make_triangle_arrays(tm, np);
  internal::write_face_values(
    tm, face_curvature_map,
    internal::face_curvatures<ConcurrencyTag>(mesh, internal::make_vertex_corners(mesh), parameters), np);
  internal::write_face_values(tm, face_normal_deviation_map,
                              internal::face_normal_deviation<ConcurrencyTag>(mesh, parameters.number_of_neighbors), np);
}

} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_GEOMETRIC_CUES_H
