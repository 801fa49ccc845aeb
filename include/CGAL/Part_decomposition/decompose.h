// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_DECOMPOSE_H
#define CGAL_PART_DECOMPOSITION_DECOMPOSE_H

#include <CGAL/Part_decomposition/Superquadric.h>
#include <CGAL/Part_decomposition/input_validation.h>
#include <CGAL/Part_decomposition/normalization.h>
#include <CGAL/Part_decomposition/parameters.h>
#include <CGAL/Part_decomposition/stage_results.h>
#include <CGAL/Part_decomposition/internal/toolbox/toolbox.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/tags.h>

#include <chrono>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Part_decomposition {


/// \cond SKIP_IN_MANUAL
namespace internal {

// The parts of one decomposition: per face index its part, per part its superquadric.
template <typename GeomTraits>
struct Decomposition_pass
{
  std::vector<std::size_t> parts;
  std::vector<Superquadric<GeomTraits> > primitives;
  std::size_t number_of_parts = 0;
  std::size_t default_number_of_parts = 0; // at the default granularity (maximum_merge_cost)
};

// A given value converted to the type of the pipeline; a value the type cannot hold (a negative
// count, a fraction where an integer is meant) is out of the range of the parameter `name`.
template <typename T, typename U>
T pipeline_value(const U& value, const char* name)
{
  if constexpr(std::is_same_v<T, bool> || std::is_enum_v<T> || std::is_floating_point_v<T> || !std::is_arithmetic_v<U>)
    return T(value);
  else
  {
    const long double v = static_cast<long double>(value);
    const bool fits = v == std::floor(v) && v >= static_cast<long double>((std::numeric_limits<T>::min)()) &&
                      v <= static_cast<long double>((std::numeric_limits<T>::max)());
    check_parameter(fits, name);
    return T(value);
  }
}

template <typename T>
struct Pipeline_value
{
  template <typename U>
  static T of(const U& value, const char* name) { return pipeline_value<T>(value, name); }
};

template <typename E>
struct Pipeline_value<std::vector<E> >
{
  template <typename Range>
  static std::vector<E> of(const Range& range, const char* name)
  {
    std::vector<E> v;
    for(const auto& x : range) v.push_back(pipeline_value<E>(x, name));
    return v;
  }
};

template <typename E>
struct Pipeline_value<std::optional<E> >
{
  template <typename U>
  static std::optional<E> of(const U& value, const char* name)
  {
    const auto given = as_optional(value);
    return given ? std::optional<E>(pipeline_value<E>(*given, name)) : std::nullopt;
  }
};

// The value of the parameter `tag` of `np` in the type of the pipeline, `fallback` if absent.
template <typename T, typename NamedParameters, typename Tag, typename Default>
T pipeline_parameter(const NamedParameters& np, Tag tag, const Default& fallback, const char* name)
{
  if constexpr(CGAL::parameters::is_default_parameter<NamedParameters, Tag>::value)
    return Pipeline_value<T>::of(fallback, name);
  else
    return Pipeline_value<T>::of(CGAL::parameters::get_parameter(np, tag), name);
}

// Every value of the list of parameters, at its default or as the program gave it, in the type of
// the pipeline: what `decompose()` hands the pipeline, whatever parameters the program gave (and
// what the package's programs hold their users' settings in).
struct Pipeline_values
{
#define CGAL_PART_DECOMPOSITION_PIPELINE_FIELD(NAME, TYPE, ...) TYPE NAME = Pipeline_value<TYPE>::of(defaults::NAME, #NAME);
  CGAL_PART_DECOMPOSITION_PARAMETERS(CGAL_PART_DECOMPOSITION_PIPELINE_FIELD, CGAL_PART_DECOMPOSITION_PIPELINE_FIELD)
#undef CGAL_PART_DECOMPOSITION_PIPELINE_FIELD
};

template <typename NamedParameters>
Pipeline_values pipeline_values(const NamedParameters& np)
{
  Pipeline_values v;
#define CGAL_PART_DECOMPOSITION_PIPELINE_VALUE(NAME, TYPE, ...)                                    \
  v.NAME = pipeline_parameter<TYPE>(np, internal_np::NAME, defaults::NAME, #NAME);
#define CGAL_PART_DECOMPOSITION_PIPELINE_CGAL_VALUE(NAME, TYPE, ...)                               \
  v.NAME = pipeline_parameter<TYPE>(np, CGAL::internal_np::NAME, defaults::NAME, #NAME);
  CGAL_PART_DECOMPOSITION_PARAMETERS(CGAL_PART_DECOMPOSITION_PIPELINE_VALUE,
                                     CGAL_PART_DECOMPOSITION_PIPELINE_CGAL_VALUE)
#undef CGAL_PART_DECOMPOSITION_PIPELINE_CGAL_VALUE
#undef CGAL_PART_DECOMPOSITION_PIPELINE_VALUE
  return v;
}

// The mesh's traits and maps, a given normalization and the hierarchy's output: the rest of what
// `decompose()` hands the pipeline.
template <typename GeomTraits, typename VertexPointMap, typename FaceIndexMap>
struct Pipeline_inputs
{
  GeomTraits traits;
  VertexPointMap vpm;
  FaceIndexMap fim;
  std::optional<Normalization> normalization;
  Part_hierarchy<GeomTraits>* hierarchy;
};

template <typename TriangleMesh, typename NamedParameters>
auto pipeline_inputs(const TriangleMesh& tm, const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename GetGeomTraits<TriangleMesh, NamedParameters>::type GT;
  const Mesh_maps<TriangleMesh, NamedParameters> maps(tm, np);
  return Pipeline_inputs<GT, decltype(maps.vpm), decltype(maps.fim)>{
    choose_parameter<GT>(get_parameter(np, CGAL::internal_np::geom_traits)), maps.vpm, maps.fim,
    optional_parameter<Normalization>(np, internal_np::normalization),
    choose_parameter(get_parameter(np, internal_np::part_hierarchy), static_cast<Part_hierarchy<GT>*>(nullptr))};
}

// `decompose()` on its inputs and values: the parts per face index, their superquadrics and the
// time of each stage but the total. The compiled library holds it for the common mesh types, so
// that a program that links it compiles neither the pipeline nor the pack of its parameters.
template <typename ConcurrencyTag, typename TriangleMesh, typename GeomTraits, typename VertexPointMap,
          typename FaceIndexMap>
void decompose_values(const TriangleMesh& tm, const Pipeline_inputs<GeomTraits, VertexPointMap, FaceIndexMap>& in,
                      const Pipeline_values& values, Decomposition_pass<GeomTraits>& pass, Stage_timings& timings);

} // namespace internal
/// \endcond

} // namespace Part_decomposition
} // namespace CGAL

// The library CGAL::Part_decomposition holds the pipeline for these types (see the manual);
// programs that do not link it compile the pipeline themselves, for any mesh.
#if defined(CGAL_PART_DECOMPOSITION_COMPILED_LIBRARY) || defined(CGAL_PART_DECOMPOSITION_BUILDING_LIBRARY)
#include <CGAL/Part_decomposition/compiled_types.h>

#include <utility>

/// \cond SKIP_IN_MANUAL
namespace CGAL {
namespace Part_decomposition {
namespace internal {

typedef decltype(pipeline_inputs(std::declval<const Compiled_mesh&>(), CGAL::parameters::default_values()))
  Compiled_inputs;

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#define CGAL_PART_DECOMPOSITION_INSTANTIATE_DECOMPOSE(EXTERN, CONCURRENCY_TAG)                      \
  namespace CGAL { namespace Part_decomposition { namespace internal {                            \
  EXTERN template void decompose_values<CONCURRENCY_TAG>(                                         \
    const Compiled_mesh&, const Compiled_inputs&, const Pipeline_values&, Decomposition_pass<CGAL::Epick>&, \
    Stage_timings&);                                                                               \
  } } }
/// \endcond
#endif

namespace CGAL {
namespace Part_decomposition {

/*!
\ingroup PkgPartDecompositionRef
decomposes the triangle mesh `tm` into parts with the Hi-TOPS method (paper Algorithm A.1) and
writes the part id of every face, from 0 to `K-1`, to `face_part_map`. Each part is explained by
one superquadric, optionally written to an output iterator. The same input and parameters give
the same output, whatever the number of threads.

It is the sequence of the stage functions, which give the same parts when called in this
order with the same named parameters (see the user manual): `segment_pieces()` and
`splittable_pieces()`; if a piece is splittable, `compute_flow_freeze_prior()`, `compute_tsdf()`
and `volumetric_pieces()`; if a piece is volumetric, `compute_fitting_zones()`,
`fit_superquadrics()`, `over_segment()`, `assign_parts()`, `separate_residual_patches()` (with
the switch `keep_residual_patches`) and `merge_thin_sheet_parts()`; then `compose_parts()` and the
part hierarchy (`build_part_hierarchy()`), whose merges go on from the composed parts as long as
they cost less than `maximum_merge_cost`. It runs them through a `Part_decomposer`, which keeps
the result of each. When no piece is volumetric and the open sheets that `inflate_sheets()`
inflates hold at least half of the area and have limbs (a cut-out figure, a relief; see
`inflate_sheets()`), the stages up to `compose_parts()` run on that solid instead, each face takes
the part of its copy, and the hierarchy measures its parts on the solid's side of their normals
(a decomposer's own `compose_parts()` does not take this path). Every named parameter of these
functions is accepted here and passed to the stage that reads it; \ref PD_ParameterTable lists
them all, as does `parameter_table` (with `weld_tolerance`, read by the mesh reader only). The normalization is
computed once from `normalization_margin` (a `normalization` given here must be that one).
`face_part_map` is written once, at the end.

With a parallel `ConcurrencyTag`, the stages that do not depend on each other also run at the same
time: the prior and the distance field side by side, followed by the fitting, while the
over-segmentation (which needs only the mesh) runs next to the three of them; every stage also
runs its own loops in parallel. The result is the same: each stage is deterministic and none
reads what another writes.

\tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or
`CGAL::Parallel_if_available_tag` (parallel with TBB when it is linked)
\tparam TriangleMesh a model of `FaceListGraph` whose faces are triangles
\tparam FacePartMap a model of `WritablePropertyMap` with
`boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and `std::size_t` as value type
\tparam NamedParameters a sequence of named parameters

\param tm the mesh: any triangle mesh, open, non-manifold, self-intersecting or made of several
components
\param face_part_map receives the part id of each face
\param np an optional sequence of named parameters (package parameters are chained with
`parameters::combine()`): `vertex_point_map`, `face_index_map` and `geom_traits`
(\ref PD_MeshParameters), those listed below, which have a meaning of their own here, and every
other parameter of \ref PD_ParameterTable, passed to the stage that reads it (`verbose` to
`compute_tsdf()` and `fit_superquadrics()`); each is documented once, with its type, default, range
and meaning, in \ref PD_ParameterTable

\cgalNamedParamsBegin
  \cgalParamNBegin{normalization}
    \cgalParamDescription{the normalization of the mesh into the unit cube; it must be the one `compute_normalization()` computes from `normalization_margin`}
    \cgalParamType{`Normalization`}
    \cgalParamDefault{computed by `compute_normalization()`}
  \cgalParamNEnd
  \cgalParamNBegin{primitive_output_iterator}
    \cgalParamDescription{receives, for each part in increasing id, its superquadric in input
                          coordinates: its fitted primitive if no other part has the same one
                          and it lies on average as close to the part's vertices, else (several
                          parts explained by one primitive, a part thinner than the fitting grid,
                          or a part no primitive could be fitted to, as a flat sheet) the box-like
                          superquadric of its principal-axis bounding box}
    \cgalParamType{a model of `OutputIterator` accepting `Superquadric<GeomTraits>`}
    \cgalParamDefault{none}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_parts}
    \cgalParamDescription{the number \f$k\f$ of parts: the parts are those of level \f$k\f$ of the part
                          hierarchy (`build_part_hierarchy()`), each with the superquadric
                          of its node; a \f$k\f$ above the number of leaves of the hierarchy gives its
                          leaves. Without it, the parts are those of the default granularity.}
    \cgalParamType{`std::size_t`, at least 1}
    \cgalParamDefault{none}
  \cgalParamNEnd
  \cgalParamNBegin{maximum_merge_cost}
    \cgalParamDescription{the default granularity: the parts of `compose_parts()` go on
                          merging in the order of the part hierarchy as long as each merge costs less
                          than this (`Part_hierarchy::level_below_cost()`; the cost is that of
                          `build_part_hierarchy()`: the volume one box of the union adds to the boxes
                          of the two parts, as a fraction of the bounding box, plus a term for a
                          concave common boundary). Two parts that touch and that one box explains
                          about as well as their two boxes, along a boundary that is not a concave
                          crease, become one part with the box-like superquadric of its node; parts
                          in separate places never merge. 0: the parts of the assignment}
    \cgalParamType{`double`, finite, at least 0}
    \cgalParamDefault{`0.003`}
  \cgalParamNEnd
  \cgalParamNBegin{part_hierarchy}
    \cgalParamDescription{if not null, receives the part hierarchy (`build_part_hierarchy()`),
                          built after the parts; its `default_number_of_parts` is the number of
                          parts of the default granularity (after the merges below
                          `maximum_merge_cost`)}
    \cgalParamType{`Part_hierarchy<GeomTraits>*`}
    \cgalParamDefault{`nullptr`}
  \cgalParamNEnd
  \cgalParamNBegin{stage_timings}
    \cgalParamDescription{receives the wall-clock time of each stage}
    \cgalParamType{`Stage_timings*`}
    \cgalParamDefault{`nullptr`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns the number `K` of parts (the clamped \f$k\f$ with `number_of_parts`).

\par Complexity
The sum of the costs of the stages, \f$O(F \log F + F\,N_{face} + r^3)\f$ for \f$F\f$ faces and the finest
resolution \f$r\f$, plus the superquadric fits, whose number and cost depend on the shape and on
\f$r\f$, not on \f$F\f$ (see `fit_superquadrics()`).

\throws Invalid_input if `tm` cannot be decomposed (no face, a face that is not a triangle, a
non-finite coordinate, all vertices equal, coordinates out of the range of `maximum_coordinate` and
`minimum_extent`, a `CGAL::Surface_mesh` with garbage: see `check_input()`) or a named parameter is
out of its range (`INVALID_PARAMETER`, also for a `normalization` that is not the one computed, or
a `number_of_parts` of 0).

\cgalExample{Part_decomposition/decompose_example.cpp}
*/
template <typename ConcurrencyTag = CGAL::Parallel_if_available_tag, typename TriangleMesh,
          typename FacePartMap, typename NamedParameters = CGAL::parameters::Default_named_parameters>
std::size_t decompose(const TriangleMesh& tm, FacePartMap face_part_map,
                      const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename GetGeomTraits<TriangleMesh, NamedParameters>::type GT;
  const auto t0 = std::chrono::steady_clock::now();
  const auto inputs = internal::pipeline_inputs(tm, np);
  internal::Decomposition_pass<GT> pass;
  Stage_timings timings;
#ifdef CGAL_PART_DECOMPOSITION_COMPILED_LIBRARY
  static_assert(std::is_same<TriangleMesh, internal::Compiled_mesh>::value &&
                  std::is_same<std::decay_t<decltype(inputs)>, internal::Compiled_inputs>::value,
                "the library CGAL::Part_decomposition holds decompose() for a CGAL::Surface_mesh of Epick points with "
                "its own vertex point and face index maps: link CGAL::Part_decomposition_headers for other types");
#endif
  internal::decompose_values<ConcurrencyTag>(tm, inputs, internal::pipeline_values(np), pass, timings);
  internal::put_face_values(tm, inputs.fim, pass.parts, face_part_map);
  auto out = choose_parameter(get_parameter(np, internal_np::primitive_output_iterator), CGAL::Emptyset_iterator());
  for(const Superquadric<GT>& sq : pass.primitives) *out++ = sq;
  timings.total = internal::seconds_since(t0);
  if(Stage_timings* st = choose_parameter(get_parameter(np, internal_np::stage_timings),
                                          static_cast<Stage_timings*>(nullptr)))
    *st = timings;
  return pass.number_of_parts;
}

} // namespace Part_decomposition
} // namespace CGAL


#ifdef CGAL_PART_DECOMPOSITION_COMPILED_LIBRARY
CGAL_PART_DECOMPOSITION_INSTANTIATE_DECOMPOSE(extern, CGAL::Sequential_tag)
#ifdef CGAL_LINKED_WITH_TBB
CGAL_PART_DECOMPOSITION_INSTANTIATE_DECOMPOSE(extern, CGAL::Parallel_tag)
#endif
#else
#include <CGAL/Part_decomposition/pipeline.h>
#endif

#endif // CGAL_PART_DECOMPOSITION_DECOMPOSE_H
