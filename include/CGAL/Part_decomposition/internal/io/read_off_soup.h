// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_READ_OFF_SOUP_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_READ_OFF_SOUP_H

#include <CGAL/Part_decomposition/internal/io/polygon_soup.h>
#include <CGAL/Part_decomposition/internal/io/read_error.h>
#include <CGAL/Part_decomposition/internal/toolbox/toolbox.h>

#include <CGAL/tags.h>

#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <exception>
#include <limits>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

// A whole token of a mesh file as a double, whatever the locale; overflow gives an infinity (a
// non-finite coordinate error downstream) and underflow a zero.
inline bool to_double(std::string_view s, double& d)
{
  const char* first = s.data();
  const char* last = first + s.size();
  if(first != last && *first == '+') ++first;
  if(first == last) return false;
  const std::from_chars_result r = std::from_chars(first, last, d);
  if(r.ptr != last) return false;
  if(r.ec == std::errc::result_out_of_range)
  {
    const std::size_t e = s.find_first_of("eE");
    const bool negative = s[0] == '-';
    if(e != std::string_view::npos && e + 1 < s.size() && s[e + 1] == '-') d = negative ? -0. : 0.;
    else d = negative ? -std::numeric_limits<double>::infinity() : std::numeric_limits<double>::infinity();
  }
  else if(r.ec != std::errc())
    return false;
  return true;
}

// Whether `d` is an integer that a std::size_t holds exactly.
inline bool is_count(double d) { return d >= 0. && d < 9007199254740992. && std::floor(d) == d; }

// The index `id` read from a file with `nv` vertices, or invalid_vertex_index.
inline std::size_t vertex_index(double id, std::size_t nv)
{
  return (is_count(id) && id < double(nv)) ? std::size_t(id) : invalid_vertex_index;
}

// A token of plain decimal digits (the common case of a count or an index), parsed without going
// through a double; false for anything else, which the caller then parses with to_double().
inline bool to_unsigned(std::string_view s, std::uint64_t& u)
{
  const char* last = s.data() + s.size();
  const std::from_chars_result r = std::from_chars(s.data(), last, u);
  return r.ec == std::errc() && r.ptr == last && u < (std::uint64_t(1) << 53);
}

/*
A reader of OFF files (the Geomview variants [ST][C][N][4][n]OFF, ASCII, and binary without
colours or texture coordinates) from a memory buffer, that keeps only the vertex coordinates and
the vertex indices of the faces. It exists because CGAL 5.5's File_scanner_OFF turns hostile
files into undefined behaviour: it casts any parsed double to an index or a face degree, looks
colour indices up in a fixed table and reads texture entries past the end of a line, all
unchecked; and because reading the whole file at once and parsing it in place is several times
faster than a stream.

Nothing is allocated from a count of the header: vertices and faces are appended as they are
read, so a lying header costs no memory. Tokens are parsed independently of the locale.
*/
class Off_soup_reader
{
public:
  Off_soup_reader(const char* begin, const char* end) : m_begin(begin), m_pos(begin), m_end(end) {}

  // Appends the points and the faces of the file to `soup`. Throws Read_error, naming the line,
  // if the file is not OFF, is truncated or holds a token that is not a number.
  void read(Polygon_soup_arrays& soup)
  {
    if(!next_line()) fail(m_end, "expected the OFF header, got an empty file");
    std::size_t t = 0;
    if(!is_number(m_tokens[0]))
    {
      read_keyword(t);
      if(t < m_tokens.size() && m_tokens[t] == "BINARY")
      {
        // the binary part starts right after the header line
        if(t + 1 != m_tokens.size()) fail(at(t + 1), "expected the end of the line after BINARY, got " + got(t + 1));
        read_binary(soup);
        return;
      }
    }
    if(m_dimension_follows)
    {
      const char* where = take_count(t, m_dimension, "the dimension");
      if(m_dimension != 3) fail(where, "expected dimension 3, got " + std::to_string(m_dimension));
    }
    std::size_t nv = 0, nf = 0;
    take_count(t, nv, "the number of vertices");
    take_count(t, nf, "the number of faces");
    // the edge count, when present, is ignored

    read_body(soup, nv, nf);
  }

private:
  // The text after the header in blocks of whole lines, of about this many bytes: the blocks do
  // not depend on the number of threads.
  static constexpr std::size_t block_bytes = std::size_t(1) << 20;

  // The lines of vertex i (i < nv), then of face i - nv (i < nv + nf), parsed from m_pos: in
  // blocks, in parallel when TBB is there (parsing numbers is most of the time of reading a large
  // mesh). Each block counts its lines with tokens, then parses them into its own soup; the soups
  // are appended in file order and the first failure in file order is thrown.
  void read_body(Polygon_soup_arrays& soup, std::size_t nv, std::size_t nf)
  {
    std::vector<const char*> cut(1, m_pos);
    while(cut.back() != m_end)
    {
      const char* b = cut.back();
      const char* e = std::size_t(m_end - b) <= block_bytes ? m_end : b + block_bytes;
      const char* eol = e == m_end ? nullptr : static_cast<const char*>(std::memchr(e, '\n', std::size_t(m_end - e)));
      cut.push_back(eol ? eol + 1 : m_end);
    }
    const std::size_t nb = cut.size() - 1;
    std::vector<std::size_t> first_line(nb + 1, 0);
    for_each_range<CGAL::Parallel_if_available_tag>(nb, [&](std::size_t b, std::size_t e) {
      for(std::size_t k = b; k < e; ++k) first_line[k + 1] = block_reader(cut[k], cut[k + 1]).count_lines();
    });
    for(std::size_t k = 0; k < nb; ++k) first_line[k + 1] += first_line[k];
    std::vector<Polygon_soup_arrays> part(nb);
    std::vector<std::exception_ptr> failure(nb);
    for_each_range<CGAL::Parallel_if_available_tag>(nb, [&](std::size_t b, std::size_t e) {
      for(std::size_t k = b; k < e && first_line[k] < nv + nf; ++k)
        try
        {
          block_reader(cut[k], cut[k + 1]).read_lines(part[k], first_line[k], nv, nf);
        }
        catch(...)
        {
          failure[k] = std::current_exception();
        }
    });
    for(const std::exception_ptr& f : failure)
      if(f) std::rethrow_exception(f);
    const std::size_t lines = first_line[nb];
    if(lines < nv) fail(m_end, "expected vertex " + of(lines, nv) + ", got the end of the file");
    if(lines < nv + nf) fail(m_end, "expected face " + of(lines - nv, nf) + ", got the end of the file");
    append_soups(part, soup);
  }

  // A reader of the lines in [b, e) of the same file, with the header's settings.
  Off_soup_reader block_reader(const char* b, const char* e) const
  {
    Off_soup_reader r(m_begin, e);
    r.m_pos = b;
    r.m_homogeneous = m_homogeneous;
    return r;
  }

  // The number of lines with tokens (as next_line() finds them, without splitting them).
  std::size_t count_lines() const
  {
    std::size_t n = 0;
    for(const char* p = m_pos; p != m_end;)
    {
      while(p != m_end && *p != '\n' && is_space(*p)) ++p;
      if(p != m_end && *p != '\n' && *p != '#') ++n;
      const char* eol = static_cast<const char*>(std::memchr(p, '\n', std::size_t(m_end - p)));
      p = eol ? eol + 1 : m_end;
    }
    return n;
  }

  // Parses the lines with tokens, the first being line `line` of the body, until line nv + nf.
  void read_lines(Polygon_soup_arrays& soup, std::size_t line, std::size_t nv, std::size_t nf)
  {
    for(; line < nv + nf && next_line(); ++line)
      if(line < nv) read_vertex(soup);
      else read_face(soup, nv);
  }

  static void append_soups(const std::vector<Polygon_soup_arrays>& parts, Polygon_soup_arrays& soup)
  {
    std::size_t points = soup.points.size(), polygons = soup.polygon_start.size(), indices = soup.polygon_vertices.size();
    for(const Polygon_soup_arrays& p : parts)
    {
      points += p.points.size();
      polygons += p.number_of_polygons();
      indices += p.polygon_vertices.size();
    }
    soup.points.reserve(points);
    soup.polygon_start.reserve(polygons);
    soup.polygon_vertices.reserve(indices);
    for(const Polygon_soup_arrays& p : parts)
    {
      soup.points.insert(soup.points.end(), p.points.begin(), p.points.end());
      const std::size_t offset = soup.polygon_vertices.size();
      soup.polygon_vertices.insert(soup.polygon_vertices.end(), p.polygon_vertices.begin(), p.polygon_vertices.end());
      for(std::size_t f = 1; f < p.polygon_start.size(); ++f) soup.polygon_start.push_back(offset + p.polygon_start[f]);
    }
  }

  const char* m_begin;
  const char* m_pos;
  const char* m_end;
  std::vector<std::string_view> m_tokens;
  bool m_homogeneous = false, m_dimension_follows = false, m_normals = false, m_colors = false, m_texture = false;
  std::size_t m_dimension = 3;

  [[noreturn]] void fail(const char* at, const std::string& what) const { throw_read_error_at_line(m_begin, at, what); }

  // "i+1 of n", for the messages
  static std::string of(std::size_t i, std::size_t n) { return std::to_string(i + 1) + " of " + std::to_string(n); }

  // The token `k` of the line, quoted for a message, or the end of the line.
  std::string got(std::size_t k) const { return quoted_token(k < m_tokens.size() ? m_tokens[k] : std::string_view()); }

  // Where token `k` of the line is, or its end.
  const char* at(std::size_t k) const
  {
    return k < m_tokens.size() ? m_tokens[k].data() : m_tokens.back().data() + m_tokens.back().size();
  }

  static bool is_space(char c)
  {
    return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f';
  }

  // The tokens of the next line that has any, comments (from '#') removed.
  bool next_line()
  {
    while(m_pos != m_end)
    {
      const char* eol = static_cast<const char*>(std::memchr(m_pos, '\n', std::size_t(m_end - m_pos)));
      const char* line_end = eol ? eol : m_end;
      const char* hash = static_cast<const char*>(std::memchr(m_pos, '#', std::size_t(line_end - m_pos)));
      const char* last = hash ? hash : line_end;
      m_tokens.clear();
      for(const char* p = m_pos; p != last;)
      {
        while(p != last && is_space(*p)) ++p;
        const char* start = p;
        while(p != last && !is_space(*p)) ++p;
        if(p != start) m_tokens.emplace_back(start, std::size_t(p - start));
      }
      m_pos = eol ? eol + 1 : m_end;
      if(!m_tokens.empty()) return true;
    }
    return false;
  }

  // One vertex line: the coordinates, then ignored tokens (normal, colour, texture coordinates).
  void read_vertex(Polygon_soup_arrays& soup) const
  {
    const std::size_t coordinates = m_homogeneous ? 4 : 3;
    double c[4] = {0., 0., 0., 1.};
    for(std::size_t k = 0; k < coordinates; ++k)
      if(k >= m_tokens.size() || !to_double(m_tokens[k], c[k]))
        fail(at(k), "expected " + std::to_string(coordinates) + " vertex coordinates, got " + got(k));
    soup.add_point(c[0] / c[3], c[1] / c[3], c[2] / c[3]);
  }

  // One face line: the degree, the indices, then ignored tokens (the face colour).
  void read_face(Polygon_soup_arrays& soup, std::size_t nv) const
  {
    std::uint64_t degree = 0;
    if(!to_unsigned(m_tokens[0], degree))
    {
      double d = 0.;
      if(!to_double(m_tokens[0], d) || !is_count(d))
        fail(at(0), "expected the number of vertices of a face, got " + got(0));
      degree = std::uint64_t(d);
    }
    if(degree >= m_tokens.size())
      fail(at(0), "expected " + std::to_string(degree) + " vertex indices after the face degree, got " +
                    std::to_string(m_tokens.size() - 1));
    for(std::size_t k = 1; k <= std::size_t(degree); ++k)
    {
      std::uint64_t u = 0;
      if(to_unsigned(m_tokens[k], u))
      {
        soup.add_vertex_index(u < nv ? std::size_t(u) : invalid_vertex_index);
        continue;
      }
      double id = 0.;
      if(!to_double(m_tokens[k], id) || std::floor(id) != id) fail(at(k), "expected a vertex index, got " + got(k));
      soup.add_vertex_index(vertex_index(id, nv));
    }
    soup.end_polygon();
  }

  // [ST][C][N][4][n]OFF, maybe with the first count glued to it ("OFF8 6 12"); `t` becomes the
  // token after the keyword.
  void read_keyword(std::size_t& t)
  {
    const std::string_view k = m_tokens[0];
    const std::size_t off = k.find("OFF");
    if(off == std::string_view::npos || !read_variant(k.substr(0, off)) ||
       (off + 3 < k.size() && !is_number(k.substr(off + 3))))
      fail(at(0), "expected OFF or a variant [ST][C][N][4][n]OFF, got " + got(0));
    if(off + 3 == k.size())
    {
      t = 1;
      return;
    }
    m_tokens[0] = k.substr(off + 3);
    t = 0;
  }

  // The letters before OFF: [ST][C][N][4][n]
  bool read_variant(std::string_view k)
  {
    std::size_t i = 0;
    auto take = [&](std::string_view p) {
      if(k.substr(i, p.size()) != p) return false;
      i += p.size();
      return true;
    };
    m_texture = take("ST");
    m_colors = take("C");
    m_normals = take("N"); // skipped, like any trailing token of an ASCII line
    m_homogeneous = take("4");
    m_dimension_follows = take("n");
    return i == k.size();
  }

  static bool is_number(std::string_view s)
  {
    double d;
    return to_double(s, d);
  }

  // Reads a count of the header, from the next line if this one has no more tokens; returns where it is.
  const char* take_count(std::size_t& t, std::size_t& count, const char* what)
  {
    if(t == m_tokens.size())
    {
      if(!next_line()) fail(m_end, std::string("expected ") + what + ", got the end of the file");
      t = 0;
    }
    double d = 0.;
    if(!to_double(m_tokens[t], d) || !is_count(d)) fail(at(t), std::string("expected ") + what + ", got " + got(t));
    count = std::size_t(d);
    return at(t++);
  }

  [[noreturn]] void fail_binary(const std::string& what) const
  {
    throw_read_error_at_byte(m_begin, m_pos, "expected " + what + ", got the end of the file");
  }

  // Binary OFF: big-endian 32-bit integers and floats after the header line.
  bool read_int(std::int32_t& v)
  {
    if(m_end - m_pos < 4) return false;
    const unsigned char* b = reinterpret_cast<const unsigned char*>(m_pos);
    const std::uint32_t u = (std::uint32_t(b[0]) << 24) | (std::uint32_t(b[1]) << 16) | (std::uint32_t(b[2]) << 8) | b[3];
    std::memcpy(&v, &u, 4);
    m_pos += 4;
    return true;
  }

  bool read_float(double& v)
  {
    std::int32_t i;
    if(!read_int(i)) return false;
    float f;
    std::memcpy(&f, &i, 4);
    v = f;
    return true;
  }

  void read_binary(Polygon_soup_arrays& soup)
  {
    // colours and texture coordinates have no agreed binary layout
    if(m_colors || m_texture || m_dimension_follows)
      fail(at(0), "expected binary OFF without colours, texture coordinates or dimension (C, ST, n), got " + got(0));
    std::int32_t nv = 0, nf = 0, ne = 0;
    if(!read_int(nv) || !read_int(nf) || !read_int(ne)) fail_binary("the vertex, face and edge counts");
    if(nv < 0 || nf < 0)
      throw_read_error_at_byte(m_begin, m_pos - 12, "expected non-negative counts, got " + std::to_string(nv) +
                                                      " vertices and " + std::to_string(nf) + " faces");
    const int coordinates = m_homogeneous ? 4 : 3;
    for(std::int32_t i = 0; i < nv; ++i)
    {
      double c[4] = {0., 0., 0., 1.};
      for(int k = 0; k < coordinates; ++k)
        if(!read_float(c[k])) fail_binary("vertex " + of(std::size_t(i), std::size_t(nv)));
      double ignored;
      for(int k = 0; m_normals && k < coordinates; ++k)
        if(!read_float(ignored)) fail_binary("the normal of vertex " + std::to_string(i + 1));
      soup.add_point(c[0] / c[3], c[1] / c[3], c[2] / c[3]);
    }
    for(std::int32_t i = 0; i < nf; ++i) read_binary_face(soup, i, nf, nv);
  }

  // The degree, the indices, the number of colour components and the components.
  void read_binary_face(Polygon_soup_arrays& soup, std::int32_t i, std::int32_t nf, std::int32_t nv)
  {
    // the messages are made only on failure: no allocation per face
    const auto face = [&] { return "face " + of(std::size_t(i), std::size_t(nf)); };
    std::int32_t degree = 0, colors = 0;
    if(!read_int(degree)) fail_binary(face());
    if(degree < 0)
      throw_read_error_at_byte(m_begin, m_pos - 4, "expected the degree of " + face() + ", got " + std::to_string(degree));
    for(std::int32_t k = 0; k < degree; ++k)
    {
      std::int32_t id = 0;
      if(!read_int(id)) fail_binary("the vertex indices of " + face());
      soup.add_vertex_index(vertex_index(double(id), std::size_t(nv)));
    }
    soup.end_polygon();
    if(!read_int(colors)) fail_binary("the number of colour components of " + face());
    if(colors < 0 || colors > 4)
      throw_read_error_at_byte(m_begin, m_pos - 4,
                               "expected 0 to 4 colour components of " + face() + ", got " + std::to_string(colors));
    for(std::int32_t k = 0; k < colors; ++k)
    {
      double ignored;
      if(!read_float(ignored)) fail_binary("the colour of " + face());
    }
  }
};

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_READ_OFF_SOUP_H
