// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_READ_PLY_SOUP_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_READ_PLY_SOUP_H

#include <CGAL/Part_decomposition/internal/read_off_soup.h>

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
  Ply_soup_reader(const char* begin, const char* end) : m_pos(begin), m_end(end) {}

  // Appends the points and the faces of the file to `soup`. Returns false if the file is not
  // PLY, is truncated or holds a value that its type cannot have.
  bool read(Polygon_soup_arrays& soup)
  {
    if(!read_header()) return false;
    for(const Element& e : m_elements)
    {
      const bool is_vertex = e.name == "vertex" || e.name == "vertices";
      const bool is_face = e.name == "face" || e.name == "faces";
      std::size_t coordinate[3] = {npos, npos, npos}, indices = npos;
      for(std::size_t p = 0; p < e.properties.size(); ++p)
      {
        const Property& q = e.properties[p];
        for(int k = 0; k < 3 && is_vertex && !q.list; ++k)
          if(q.name == std::string(1, char('x' + k))) coordinate[k] = p;
        if(is_face && q.list && (q.name == "vertex_indices" || q.name == "vertex_index") && indices == npos)
          indices = p;
      }
      if(is_vertex && (coordinate[0] == npos || coordinate[1] == npos || coordinate[2] == npos)) return false;
      if(is_face && indices == npos) return false;
      // no property: items without data, however many the header claims
      if(e.properties.empty()) continue;

      for(std::size_t i = 0; i < e.count; ++i)
      {
        double c[3] = {0., 0., 0.};
        for(std::size_t p = 0; p < e.properties.size(); ++p)
        {
          const Property& q = e.properties[p];
          if(!q.list)
          {
            double v;
            if(!read_value(q.type, v)) return false;
            for(int k = 0; k < 3; ++k)
              if(is_vertex && p == coordinate[k]) c[k] = v;
            continue;
          }
          double length = 0.;
          if(!read_value(q.size_type, length) || !is_count(length)) return false;
          const bool keep = is_face && p == indices;
          for(std::size_t k = 0; k < std::size_t(length); ++k)
          {
            double v;
            if(!read_value(q.type, v)) return false;
            if(keep && std::floor(v) != v) return false;
            // an index past the vertices is the caller's out-of-range error
            if(keep) soup.add_vertex_index(is_count(v) ? std::size_t(v) : invalid_vertex_index);
          }
          if(keep) soup.end_polygon();
        }
        if(is_vertex) soup.add_point(c[0], c[1], c[2]);
      }
    }
    return true;
  }

private:
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
  };
  static constexpr std::size_t npos = std::size_t(-1);

  const char* m_pos;
  const char* m_end;
  Format m_format = ASCII;
  std::vector<Element> m_elements;

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

  // The next whitespace-separated token, as `stream >> string` would give it.
  bool next_token(std::string_view& token)
  {
    while(m_pos != m_end && std::isspace(static_cast<unsigned char>(*m_pos))) ++m_pos;
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

  bool read_header()
  {
    std::string line;
    if(!next_line(line)) return false;
    std::istringstream first(line);
    std::string word;
    if(!(first >> word) || word != "ply") return false;
    bool format = false;
    while(next_line(line))
    {
      std::istringstream iss(line);
      std::string keyword;
      if(!(iss >> keyword) || keyword == "comment" || keyword == "obj_info") continue;
      if(keyword == "end_header") return format;
      if(keyword == "format")
      {
        if(!(iss >> word)) return false;
        if(word == "ascii") m_format = ASCII;
        else if(word == "binary_little_endian") m_format = LITTLE_ENDIAN_BINARY;
        else if(word == "binary_big_endian") m_format = BIG_ENDIAN_BINARY;
        else return false;
        format = true;
      }
      else if(keyword == "element")
      {
        Element e;
        std::string count;
        if(!(iss >> e.name >> count)) return false;
        unsigned long long n = 0;
        const char* last = count.data() + count.size();
        const std::from_chars_result r = std::from_chars(count.data(), last, n);
        if(r.ec != std::errc() || r.ptr != last) return false;
        e.count = std::size_t(n);
        m_elements.push_back(e);
      }
      else if(keyword == "property")
      {
        if(m_elements.empty()) return false;
        Property q;
        if(!(iss >> word)) return false;
        if(word == "list")
        {
          std::string size_type;
          if(!(iss >> size_type >> word)) return false;
          q.list = true;
          q.size_type = type_of(size_type);
          if(q.size_type == UNKNOWN) return false;
        }
        q.type = type_of(word);
        if(q.type == UNKNOWN || !(iss >> q.name)) return false;
        m_elements.back().properties.push_back(q);
      }
      // other keywords are ignored, as by other readers
    }
    return false; // no end_header
  }

  bool read_value(Type t, double& v)
  {
    if(m_format == ASCII)
    {
      std::string_view token;
      if(!next_token(token) || !to_double(token, v)) return false;
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
