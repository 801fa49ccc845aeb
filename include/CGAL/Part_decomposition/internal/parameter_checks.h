// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_PARAMETER_CHECKS_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_PARAMETER_CHECKS_H

// The checks of the named parameters (check_parameter() and the others) need the parameter table
// of parameters.h: they are in input_validation.h. This header is empty; it goes once no header
// includes it.

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_PARAMETER_CHECKS_H
