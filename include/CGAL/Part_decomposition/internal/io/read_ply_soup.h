// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_READ_PLY_SOUP_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_READ_PLY_SOUP_H

#include <CGAL/Part_decomposition/internal/io/read_error.h>
#include <CGAL/Part_decomposition/internal/io/read_off_soup.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <sstream>
#include <string_view>
#include <string>
#include <system_error>
#include <vector>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

/*
A reader of PLY files (ASCII, binary little and big endian) from a memory buffer, that keeps the x, y, z properties of
the `vertex` element and the `vertex_indices` (or `vertex_index`) list of the `face` element, and
skips every other element and property. It exists because CGAL 5.5's PLY reader trusts the file:
a list length read from the body sizes a buffer before any item is read (a few bytes claiming
2^32 indices allocate and zero 16 GB), an element count like `-5` wraps to 2^64 items of an
element without properties (an endless loop), and a property before any element indexes an
empty vector. Parsing the buffer in place is several times faster than reading a stream.

Nothing is allocated from a count: items are appended as they are read, and a count larger than
what the file holds ends in a read failure.
*/
class Ply_soup_reader
{
public:
  Ply_soup_reader(const char* begin, const char* end) : m_begin(begin), m_pos(begin), m_end(end) {}

  // Appends the points and the faces of the file to `soup`. Throws Read_error, naming the line
  // (the byte in binary data), if the file is not PLY, is truncated or holds a value that its
  // type cannot have.
  void read(Polygon_soup_arrays& soup)
  {
    read_header();
    for(const Element& e : m_elements)
    {
      Element_use use;
      use.is_vertex = e.name == "vertex" || e.name == "vertices";
      use.is_face = e.name == "face" || e.name == "faces";
      for(std::size_t p = 0; p < e.properties.size(); ++p)
      {
        const Property& q = e.properties[p];
        for(int k = 0; k < 3 && use.is_vertex && !q.list; ++k)
          if(q.name == std::string(1, char('x' + k))) use.coordinate[k] = p;
        if(use.is_face && q.list && (q.name == "vertex_indices" || q.name == "vertex_index") && use.indices == npos)
          use.indices = p;
      }
      if(use.is_vertex && (use.coordinate[0] == npos || use.coordinate[1] == npos || use.coordinate[2] == npos))
        throw_read_error_at_line(m_begin, e.where, "expected the properties x, y and z of element '" + e.name + "'");
      if(use.is_face && use.indices == npos)
        throw_read_error_at_line(m_begin, e.where,
                                 "expected a list property vertex_indices of element '" + e.name + "'");
      // no property: items without data, however many the header claims
      if(e.properties.empty()) continue;
      for(std::size_t i = 0; i < e.count; ++i)
      {
        if(m_format == ASCII) start_line();
        read_item(e, i, use, soup);
        if(m_format == ASCII) soup.ignored_values += skip_rest_of_line();
      }
    }
  }

private:
  static constexpr std::size_t npos = std::size_t(-1);
  enum Type { INT8, UINT8, INT16, UINT16, INT32, UINT32, FLOAT32, FLOAT64, UNKNOWN };
  enum Format { ASCII, LITTLE_ENDIAN_BINARY, BIG_ENDIAN_BINARY };
  struct Property
  {
    bool list = false;
    Type size_type = UNKNOWN, type = UNKNOWN;
    std::string name;
  };
  struct Element
  {
    std::string name;
    std::size_t count = 0;
    std::vector<Property> properties;
    const char* where = nullptr; // its line of the header
  };
  // what the reader keeps of an element: the positions of x, y, z or of the vertex indices
  struct Element_use
  {
    bool is_vertex = false, is_face = false;
    std::size_t coordinate[3] = {npos, npos, npos}, indices = npos;
  };

  const char* m_begin;
  const char* m_pos;
  const char* m_end;
  Format m_format = ASCII;
  // the value read last: where it starts, and its text in ASCII (for the messages)
  const char* m_value = nullptr;
  std::string_view m_token;
  std::vector<Element> m_elements;
  bool m_in_line = false; // reading the values of an ASCII item

  // The next line (without its '\n'), as std::getline would give it.
  bool next_line(std::string& line)
  {
    if(m_pos == m_end) return false;
    const char* eol = static_cast<const char*>(std::memchr(m_pos, '\n', std::size_t(m_end - m_pos)));
    const char* last = eol ? eol : m_end;
    line.assign(m_pos, last);
    m_pos = eol ? eol + 1 : m_end;
    return true;
  }

  // ASCII items are read one per line: the values of an item end at its line's end, and the
  // values after the header's properties (MeshLab writes lists the header does not declare) are
  // skipped and counted.
  void start_line()
  {
    while(m_pos != m_end && std::isspace(static_cast<unsigned char>(*m_pos))) ++m_pos;
    m_in_line = true;
  }

  std::size_t skip_rest_of_line()
  {
    std::size_t extra = 0;
    std::string_view token;
    while(next_token(token)) ++extra;
    m_in_line = false;
    return extra;
  }

  // The next whitespace-separated token, as `stream >> string` would give it; within an ASCII
  // item, none past the end of its line.
  bool next_token(std::string_view& token)
  {
    while(m_pos != m_end && std::isspace(static_cast<unsigned char>(*m_pos)) && !(m_in_line && *m_pos == '\n')) ++m_pos;
    const char* start = m_pos;
    while(m_pos != m_end && !std::isspace(static_cast<unsigned char>(*m_pos))) ++m_pos;
    token = std::string_view(start, std::size_t(m_pos - start));
    return m_pos != start;
  }

  static Type type_of(const std::string& s)
  {
    static const char* const names[8][2] = {{"char", "int8"},     {"uchar", "uint8"},   {"short", "int16"},
                                            {"ushort", "uint16"}, {"int", "int32"},     {"uint", "uint32"},
                                            {"float", "float32"}, {"double", "float64"}};
    for(int t = 0; t < 8; ++t)
      if(s == names[t][0] || s == names[t][1]) return Type(t);
    return UNKNOWN;
  }

  static std::size_t size_of(Type t)
  {
    static const std::size_t sizes[8] = {1, 1, 2, 2, 4, 4, 4, 8};
    return sizes[t];
  }

  [[noreturn]] void fail_header(const char* line, const std::string& what) const
  {
    throw_read_error_at_line(m_begin, line, what);
  }

  // The lines up to end_header; the elements and their properties in m_elements.
  void read_header()
  {
    std::string line, word;
    const char* start = m_pos;
    if(m_pos == m_end) fail_header(start, "expected 'ply', got an empty file");
    next_line(line);
    if(!(std::istringstream(line) >> word) || word != "ply")
      fail_header(start, "expected 'ply', got " + quoted_token(word));
    bool format = false;
    for(start = m_pos; next_line(line); start = m_pos)
    {
      std::istringstream iss(line);
      std::string keyword;
      if(!(iss >> keyword) || keyword == "comment" || keyword == "obj_info") continue;
      if(keyword == "end_header")
      {
        if(!format) fail_header(start, "expected a format line before end_header");
        return;
      }
      if(keyword == "format")
      {
        word.clear();
        iss >> word;
        if(word == "ascii") m_format = ASCII;
        else if(word == "binary_little_endian") m_format = LITTLE_ENDIAN_BINARY;
        else if(word == "binary_big_endian") m_format = BIG_ENDIAN_BINARY;
        else
          fail_header(start, "expected the format ascii, binary_little_endian or binary_big_endian, got " +
                               quoted_token(word));
        format = true;
      }
      else if(keyword == "element") read_element_line(iss, start);
      else if(keyword == "property") read_property_line(iss, start);
      // other keywords are ignored, as by other readers
    }
    fail_header(m_end, "expected end_header, got the end of the file");
  }

  // element NAME COUNT
  void read_element_line(std::istringstream& iss, const char* line)
  {
    Element e;
    e.where = line;
    std::string count;
    iss >> e.name >> count;
    unsigned long long n = 0;
    const char* last = count.data() + count.size();
    const std::from_chars_result r = std::from_chars(count.data(), last, n);
    if(e.name.empty() || r.ec != std::errc() || r.ptr != last)
      fail_header(line, "expected 'element NAME COUNT' with a non-negative COUNT, got " +
                          quoted_token(count.empty() ? e.name : count));
    e.count = std::size_t(n);
    m_elements.push_back(e);
  }

  // property TYPE NAME, or property list SIZE_TYPE TYPE NAME
  void read_property_line(std::istringstream& iss, const char* line)
  {
    if(m_elements.empty()) fail_header(line, "expected an element line before the first property");
    Property q;
    std::string word;
    iss >> word;
    if(word == "list")
    {
      std::string size_type;
      iss >> size_type >> word;
      q.list = true;
      q.size_type = type_of(size_type);
      if(q.size_type == UNKNOWN)
        fail_header(line, "expected the type of a list length, got " + quoted_token(size_type));
    }
    q.type = type_of(word);
    if(q.type == UNKNOWN) fail_header(line, "expected a property type (char, uchar, short, ushort, int, uint, float, "
                                            "double or their sized names), got " + quoted_token(word));
    if(!(iss >> q.name)) fail_header(line, "expected the name of the property");
    m_elements.back().properties.push_back(q);
  }

  // Throws for the value `what` of item i of e that could not be read or is not what it must be.
  [[noreturn]] void fail_value(const std::string& what, const Element& e, std::size_t i, const std::string& got) const
  {
    const std::string message = "expected " + what + " of " + e.name + " " + std::to_string(i + 1) + " of " +
                                std::to_string(e.count) + ", got " + got;
    if(m_format == ASCII) throw_read_error_at_line(m_begin, m_value, message);
    throw_read_error_at_byte(m_begin, m_value, message);
  }

  // The value last read, or what was found instead, for a message.
  std::string value_text(double v, bool was_read) const
  {
    if(!was_read && m_format == ASCII && m_token.empty() && m_pos != m_end) return "the end of the line";
    if(!was_read && (m_format != ASCII || m_token.empty())) return "the end of the file";
    if(m_format == ASCII) return quoted_token(m_token);
    std::ostringstream out;
    out << v;
    return out.str();
  }

  static std::string type_name(Type t)
  {
    static const char* const names[8] = {"a char", "a uchar", "a short",  "a ushort",
                                         "an int", "a uint",  "a float", "a double"};
    return names[t];
  }

  // One item of element e: its coordinates to the soup if it is a vertex, its polygon if a face.
  void read_item(const Element& e, std::size_t i, const Element_use& use, Polygon_soup_arrays& soup)
  {
    double c[3] = {0., 0., 0.};
    for(std::size_t p = 0; p < e.properties.size(); ++p)
    {
      const Property& q = e.properties[p];
      double v = 0.;
      if(!q.list)
      {
        if(!read_value(q.type, v)) fail_value(type_name(q.type) + " '" + q.name + "'", e, i, value_text(v, false));
        for(int k = 0; k < 3; ++k)
          if(use.is_vertex && p == use.coordinate[k]) c[k] = v;
        continue;
      }
      double length = 0.;
      const bool length_read = read_value(q.size_type, length);
      if(!length_read || !is_count(length))
        fail_value("the length of list '" + q.name + "'", e, i, value_text(length, length_read));
      const bool keep = use.is_face && p == use.indices;
      for(std::size_t k = 0; k < std::size_t(length); ++k)
      {
        const bool read = read_value(q.type, v);
        if(!read || (keep && std::floor(v) != v))
          fail_value(std::string(keep ? "an integer" : type_name(q.type)) + " in list '" + q.name + "'", e, i,
                     value_text(v, read));
        // an index past the vertices is the caller's out-of-range error
        if(keep) soup.add_vertex_index(is_count(v) ? std::size_t(v) : invalid_vertex_index);
      }
      if(keep) soup.end_polygon();
    }
    if(use.is_vertex) soup.add_point(c[0], c[1], c[2]);
  }

  bool read_value(Type t, double& v)
  {
    if(m_format == ASCII)
    {
      const bool found = next_token(m_token);
      m_value = found ? m_token.data() : m_pos;
      if(!found || !to_double(m_token, v)) return false;
      if(t == FLOAT64) return true;
      if(t == FLOAT32)
      {
        // the value a float holds, as in a binary file (beyond its range: an infinity)
        if(std::abs(v) <= double((std::numeric_limits<float>::max)())) v = double(float(v));
        else if(!std::isnan(v)) v = v < 0 ? -std::numeric_limits<double>::infinity() : std::numeric_limits<double>::infinity();
        return true;
      }
      // an integer property holds an integer of its range
      static const double lowest[6] = {-128., 0., -32768., 0., -2147483648., 0.};
      static const double highest[6] = {127., 255., 32767., 65535., 2147483647., 4294967295.};
      return std::floor(v) == v && v >= lowest[t] && v <= highest[t];
    }
    unsigned char b[8];
    const std::size_t n = size_of(t);
    m_value = m_pos;
    if(std::size_t(m_end - m_pos) < n) return false;
    std::memcpy(b, m_pos, n);
    m_pos += n;
    // to the little-endian order, then assembled arithmetically: no host-order assumption
    if(m_format == BIG_ENDIAN_BINARY) std::reverse(b, b + n);
    std::uint64_t u = 0;
    for(std::size_t k = n; k-- > 0;) u = (u << 8) | b[k];
    switch(t)
    {
    case INT8: v = double(std::int8_t(std::uint8_t(u))); break;
    case UINT8: v = double(std::uint8_t(u)); break;
    case INT16: v = double(std::int16_t(std::uint16_t(u))); break;
    case UINT16: v = double(std::uint16_t(u)); break;
    case INT32: v = double(std::int32_t(std::uint32_t(u))); break;
    case UINT32: v = double(std::uint32_t(u)); break;
    case FLOAT32:
    {
      const std::uint32_t u32 = std::uint32_t(u);
      float f;
      std::memcpy(&f, &u32, 4);
      v = f;
      break;
    }
    default:
    {
      double d;
      std::memcpy(&d, &u, 8);
      v = d;
    }
    }
    return true;
  }
};

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_READ_PLY_SOUP_H
