// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_READ_STL_SOUP_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_READ_STL_SOUP_H

#include <CGAL/Part_decomposition/internal/io/polygon_soup.h>
#include <CGAL/Part_decomposition/internal/io/read_error.h>
#include <CGAL/Part_decomposition/internal/io/read_off_soup.h>

#include <cctype>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

/*
A reader of STL files (ASCII and binary) from a memory buffer, with the format detection of
CGAL 5.5's read_STL(): a file whose first word is "solid" is ASCII, else binary, and each is tried
as the other when it fails (the error reported is then the one of the detected format). Each
triangle gets its own three points (the caller merges equal points), so that reading is a single
linear pass, where CGAL's reader looks every corner up in a std::map.
*/
class Stl_soup_reader
{
public:
  Stl_soup_reader(const char* begin, const char* end) : m_begin(begin), m_end(end) {}

  // Appends the corners and the triangles of the file to `soup`; throws Read_error, naming the
  // line (the byte of a binary file), if it is not STL.
  void read(Polygon_soup_arrays& soup) const
  {
    const char* p = m_begin;
    while(p != m_end && std::isspace(static_cast<unsigned char>(*p))) ++p;
    // nothing, or fewer than six characters: an empty mesh, as for CGAL
    if(m_end - p < 6) return;
    const bool solid = std::string_view(p, 5) == "solid" && (p[5] == '\n' || p[5] == '\r' || p[5] == ' ');
    Polygon_soup_arrays attempt;
    try
    {
      if(solid) read_ascii(attempt);
      else read_binary(attempt);
      soup = std::move(attempt);
    }
    catch(const Read_error& first)
    {
      try
      {
        if(solid) read_binary(soup);
        else read_ascii(soup);
      }
      catch(const Read_error&)
      {
        throw first;
      }
    }
  }

private:
  const char* m_begin;
  const char* m_end;

  static void add_triangle_of_last_corners(Polygon_soup_arrays& soup)
  {
    const std::size_t n = soup.number_of_points();
    for(std::size_t k = 3; k > 0; --k) soup.add_vertex_index(n - k);
    soup.end_polygon();
  }

  static float little_endian_float(const char* b)
  {
    const unsigned char* u = reinterpret_cast<const unsigned char*>(b);
    const std::uint32_t v = std::uint32_t(u[0]) | (std::uint32_t(u[1]) << 8) | (std::uint32_t(u[2]) << 16) |
                            (std::uint32_t(u[3]) << 24);
    float f;
    std::memcpy(&f, &v, 4);
    return f;
  }

  // 80 bytes of header, a 32-bit count, then 50 bytes per triangle (normal, corners, attribute).
  void read_binary(Polygon_soup_arrays& soup) const
  {
    const std::size_t size = std::size_t(m_end - m_begin);
    if(size < 80) return;
    if(size < 84)
      throw_read_error_at_byte(m_begin, m_begin + 80, "expected the number of triangles, got the end of the file");
    const unsigned char* c = reinterpret_cast<const unsigned char*>(m_begin + 80);
    const std::uint32_t n = std::uint32_t(c[0]) | (std::uint32_t(c[1]) << 8) | (std::uint32_t(c[2]) << 16) |
                            (std::uint32_t(c[3]) << 24);
    if(std::uint64_t(n) * 50 > size - 84)
      throw_read_error_at_byte(m_begin, m_begin + 84, "expected " + std::to_string(n) + " triangles of 50 bytes, got " +
                                                        std::to_string(size - 84) + " bytes");
    soup.points.reserve(3 * std::size_t(n));
    soup.polygon_vertices.reserve(3 * std::size_t(n));
    soup.polygon_start.reserve(std::size_t(n) + 1);
    for(std::uint32_t i = 0; i < n; ++i)
    {
      const char* t = m_begin + 84 + 50 * std::size_t(i) + 12;
      for(int k = 0; k < 3; ++k, t += 12)
        soup.add_point(little_endian_float(t), little_endian_float(t + 4), little_endian_float(t + 8));
      add_triangle_of_last_corners(soup);
    }
  }

  bool next_token(const char*& p, std::string_view& token) const
  {
    while(p != m_end && std::isspace(static_cast<unsigned char>(*p))) ++p;
    const char* start = p;
    while(p != m_end && !std::isspace(static_cast<unsigned char>(*p))) ++p;
    token = std::string_view(start, std::size_t(p - start));
    return p != start;
  }

  // solid ... facet ... vertex x y z (three times) ... endfacet ... endsolid
  void read_ascii(Polygon_soup_arrays& soup) const
  {
    const char* p = m_begin;
    bool solid_found = false, in_solid = false;
    std::string_view s;
    while(next_token(p, s))
    {
      if(s == "solid")
      {
        if(in_solid) throw_read_error_at_line(m_begin, s.data(), "expected 'endsolid' before the next 'solid'");
        in_solid = true;
      }
      if(s == "facet") read_ascii_facet(p, soup);
      else if(s == "endsolid")
      {
        in_solid = false;
        solid_found = true;
      }
    }
    if(!solid_found || in_solid)
      throw_read_error_at_line(m_begin, m_end, "expected 'endsolid', got the end of the file");
  }

  void read_ascii_facet(const char*& p, Polygon_soup_arrays& soup) const
  {
    const char* facet = p;
    int count = 0;
    std::string_view s;
    while(next_token(p, s))
    {
      if(s == "endfacet")
      {
        if(count != 3)
          throw_read_error_at_line(m_begin, s.data(), "expected 3 vertices in the facet, got " + std::to_string(count));
        add_triangle_of_last_corners(soup);
        return;
      }
      if(s != "vertex") continue;
      if(count == 3) throw_read_error_at_line(m_begin, s.data(), "expected 3 vertices in the facet, got a fourth");
      double c[3];
      for(int k = 0; k < 3; ++k)
        if(!next_token(p, s) || !to_double(s, c[k]))
          throw_read_error_at_line(m_begin, s.empty() ? m_end : s.data(),
                                   "expected 3 coordinates after 'vertex', got " +
                                     (s.empty() ? std::string("the end of the file") : quoted_token(s)));
      soup.add_point(c[0], c[1], c[2]);
      ++count;
    }
    throw_read_error_at_line(m_begin, facet, "expected 'endfacet' after this facet, got the end of the file");
  }
};

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_READ_STL_SOUP_H
