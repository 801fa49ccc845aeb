// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_DECOMPOSE_H
#define CGAL_PART_DECOMPOSITION_DECOMPOSE_H

#include <CGAL/Part_decomposition/parameters.h>
#include <CGAL/tags.h>

#include <cstddef>
#include <stdexcept>

namespace CGAL {
namespace Part_decomposition {

/*!
\ingroup PkgPartDecompositionRef
Wall-clock seconds spent in each stage of `decompose()`.
*/
struct Stage_timings
{
  double prior = 0.;             ///< geometric cues, topology scores and Flow/Freeze fusion
  double tsdf = 0.;              ///< truncated signed distance field and fitting zones
  double fitting = 0.;           ///< superquadric fitting
  double over_segmentation = 0.; ///< curvature-aware over-segmentation
  double assignment = 0.;        ///< superquadric-to-mesh assignment
  double total = 0.;             ///< the whole call
};

// Skeleton: the stages are being written; this entry point is completed once they exist.
template <typename ConcurrencyTag = CGAL::Parallel_if_available_tag, typename TriangleMesh,
          typename FacePartMap, typename NamedParameters = CGAL::parameters::Default_named_parameters>
std::size_t decompose(const TriangleMesh&, FacePartMap,
                      const NamedParameters& = CGAL::parameters::default_values())
{
  throw std::logic_error("decompose: not implemented yet");
}

} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_DECOMPOSE_H
