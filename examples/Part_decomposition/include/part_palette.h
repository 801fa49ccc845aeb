// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef PART_DECOMPOSITION_TOOLS_PART_PALETTE_H
#define PART_DECOMPOSITION_TOOLS_PART_PALETTE_H

// The colour of each part as 8-bit sRGB, for the tools that draw or write parts (hitops --colored,
// its thumbnails, the Python module's render_parts(), the manual's figures): the library's own
// palette, that of --parts-glb, so that a part has one colour everywhere.

#include <CGAL/Part_decomposition/IO/write_parts_gltf.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace Part_decomposition_tools {

inline std::array<std::uint8_t, 3> part_rgb(std::size_t k)
{
  const std::array<double, 3> c = CGAL::Part_decomposition::internal::part_srgb(k);
  return {{std::uint8_t(std::lround(255 * c[0])), std::uint8_t(std::lround(255 * c[1])),
           std::uint8_t(std::lround(255 * c[2]))}};
}

} // namespace Part_decomposition_tools

#endif // PART_DECOMPOSITION_TOOLS_PART_PALETTE_H
