// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

// The library CGAL::Part_decomposition: the mesh reader for a CGAL::Surface_mesh of Epick points
// (its parsers of OFF, OBJ, PLY, STL and glTF and the building of the mesh).
#define CGAL_PART_DECOMPOSITION_BUILDING_LIBRARY
#include <CGAL/Part_decomposition/IO/read_mesh.h>

CGAL_PART_DECOMPOSITION_INSTANTIATE_READER()
