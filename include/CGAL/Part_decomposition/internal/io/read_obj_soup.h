// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_READ_OBJ_SOUP_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_READ_OBJ_SOUP_H

#include <CGAL/Part_decomposition/internal/io/polygon_soup.h>
#include <CGAL/Part_decomposition/internal/io/read_error.h>
#include <CGAL/Part_decomposition/internal/io/read_off_soup.h>

#include <charconv>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <system_error>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

/*
A reader of Wavefront OBJ files from a memory buffer, that keeps the vertex positions (`v x y z`,
a weight or a colour after them ignored) and the polygons (`f` or `fo`, each corner `i`, `i/t`,
`i//n` or `i/t/n`, `i` counted from 1, or from the end when negative), and skips every other
statement (vt, vn, g, o, s, usemtl, mtllib, l, p, curves and surfaces...). A backslash that ends a
line continues the statement on the next one, as Rhino writes long faces; `#` starts a comment,
which ends the statement at the end of its line.

It exists because CGAL 5.5's read_OBJ() refuses the files of some exporters (an `l` statement, a
face continued on the next line) and reads a stream line by line, several times slower than
parsing the buffer in place. An index that is no vertex (0, or past either end) is kept as
invalid_vertex_index, the caller's out-of-range error.
*/
class Obj_soup_reader
{
public:
  Obj_soup_reader(const char* begin, const char* end) : m_begin(begin), m_pos(begin), m_end(end) {}

  // Appends the vertices and the polygons of the file to `soup`, which must be empty; throws
  // Read_error, naming the line, on a statement that is not OBJ or a vertex or face it cannot read.
  void read(Polygon_soup_arrays& soup)
  {
    std::string_view keyword;
    while(next_statement(keyword))
    {
      if(keyword == "v") read_vertex(soup);
      else if(keyword == "f" || keyword == "fo") read_face(soup);
      else skip_statement(keyword);
    }
  }

private:
  const char* m_begin;
  const char* m_pos;
  const char* m_end;

  // Space and control characters, the line end apart: nothing of a token.
  static bool is_blank(char c) { return static_cast<unsigned char>(c) <= ' ' && c != '\n'; }
  static bool ends_token(char c) { return static_cast<unsigned char>(c) <= ' ' || c == '#'; }

  [[noreturn]] void fail(const char* at, const std::string& what) const { throw_read_error_at_line(m_begin, at, what); }

  // Past the line end that follows the backslash at `p` and blanks, or nullptr if `p` does not
  // continue its line.
  const char* continuation_end(const char* p) const
  {
    if(*p != '\\') return nullptr;
    for(++p; p != m_end && is_blank(*p); ++p) {}
    if(p == m_end) return m_end;
    return *p == '\n' ? p + 1 : nullptr;
  }

  // Past the end of the physical line.
  void skip_line()
  {
    const char* eol = static_cast<const char*>(std::memchr(m_pos, '\n', std::size_t(m_end - m_pos)));
    m_pos = eol ? eol + 1 : m_end;
  }

  // Moves to the next token of the statement, over blanks and line continuations; false at the
  // end of the statement, m_pos then on its '\n' or '#', or at the end of the file.
  bool to_token()
  {
    for(;;)
    {
      while(m_pos != m_end && is_blank(*m_pos)) ++m_pos;
      if(m_pos == m_end || *m_pos == '\n' || *m_pos == '#') return false;
      const char* next = continuation_end(m_pos);
      if(!next) return true;
      m_pos = next;
    }
  }

  // The token at m_pos; a backslash glued to its end that continues the line is left for to_token().
  std::string_view take_token()
  {
    const char* start = m_pos;
    while(m_pos != m_end && !ends_token(*m_pos)) ++m_pos;
    if(m_pos - start > 1 && m_pos[-1] == '\\' && continuation_end(m_pos - 1)) --m_pos;
    return std::string_view(start, std::size_t(m_pos - start));
  }

  // Past the end of the statement, once to_token() has found it.
  void end_statement()
  {
    if(m_pos == m_end) return;
    if(*m_pos == '#') skip_line();
    else ++m_pos;
  }

  // The keyword of the next statement, over blank lines and comments; false at the end of the file.
  bool next_statement(std::string_view& keyword)
  {
    for(;;)
    {
      while(m_pos != m_end && static_cast<unsigned char>(*m_pos) <= ' ') ++m_pos;
      if(m_pos == m_end) return false;
      if(*m_pos == '#') skip_line();
      else if(const char* next = continuation_end(m_pos)) m_pos = next;
      else break;
    }
    keyword = take_token();
    return true;
  }

  // v x y z [w | r g b]
  void read_vertex(Polygon_soup_arrays& soup)
  {
    double c[3];
    for(int k = 0; k < 3; ++k)
    {
      const std::string_view t = to_token() ? take_token() : std::string_view();
      if(!to_double(t, c[k]))
        fail(t.empty() ? m_pos : t.data(), "expected 3 coordinates after 'v', got " + quoted_token(t));
    }
    soup.add_point(c[0], c[1], c[2]);
    while(to_token()) take_token();
    end_statement();
  }

  // f v1[/t1[/n1]] v2... with indices from 1, or from the last vertex read when negative.
  void read_face(Polygon_soup_arrays& soup)
  {
    const std::int64_t n = std::int64_t(soup.number_of_points());
    while(to_token())
    {
      const std::string_view t = take_token();
      const char* first = t.data() + (t[0] == '+' ? 1 : 0);
      const char* last = t.data() + t.size();
      std::int64_t i = 0;
      const std::from_chars_result r = std::from_chars(first, last, i);
      if(r.ptr == first || (r.ptr != last && *r.ptr != '/'))
        fail(t.data(), "expected a vertex index after 'f', got " + quoted_token(t));
      // beyond 64 bits: no vertex either
      if(r.ec != std::errc()) i = 0;
      if(i > 0) soup.add_vertex_index(std::size_t(i - 1));
      else if(i < 0 && i >= -n) soup.add_vertex_index(std::size_t(n + i));
      else soup.add_vertex_index(invalid_vertex_index);
    }
    soup.end_polygon();
    end_statement();
  }

  // A statement whose data is not kept; its keyword must still be one (a letter, then letters,
  // digits or '_'), so that a file that is not OBJ is refused.
  void skip_statement(std::string_view keyword)
  {
    const auto letter = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); };
    bool valid = letter(keyword[0]);
    for(char c : keyword) valid = valid && (letter(c) || (c >= '0' && c <= '9') || c == '_');
    if(!valid) fail(keyword.data(), "expected an OBJ statement (v, f, vt, g, ...), got " + quoted_token(keyword));
    for(;;)
    {
      const char* line = m_pos;
      skip_line();
      // the line goes on after a final backslash, unless a comment holds it
      const char* last = m_pos;
      if(last != line && last[-1] == '\n') --last;
      while(last != line && is_blank(last[-1])) --last;
      if(last == line || last[-1] != '\\' || std::memchr(line, '#', std::size_t(last - line))) return;
    }
  }
};

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_READ_OBJ_SOUP_H
