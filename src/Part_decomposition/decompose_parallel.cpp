// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

// The library CGAL::Part_decomposition: the pipeline of decompose() for a CGAL::Surface_mesh of
// Epick points, parallel (one file per concurrency tag, so that the two compile side by side).
#define CGAL_PART_DECOMPOSITION_BUILDING_LIBRARY
#include <CGAL/Part_decomposition/decompose.h>

#ifdef CGAL_LINKED_WITH_TBB
CGAL_PART_DECOMPOSITION_INSTANTIATE_DECOMPOSE(, CGAL::Parallel_tag)
#endif
