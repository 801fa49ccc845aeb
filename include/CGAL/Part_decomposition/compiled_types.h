// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_COMPILED_TYPES_H
#define CGAL_PART_DECOMPOSITION_COMPILED_TYPES_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

/// \cond SKIP_IN_MANUAL
namespace CGAL {
namespace Part_decomposition {
namespace internal {

// The mesh type the library CGAL::Part_decomposition is compiled for (`decompose()` and
// `IO::read_triangle_mesh()`); programs that link it and use another get a compile-time error.
typedef CGAL::Surface_mesh<CGAL::Epick::Point_3> Compiled_mesh;

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL
/// \endcond

#endif // CGAL_PART_DECOMPOSITION_COMPILED_TYPES_H
