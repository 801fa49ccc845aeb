// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_READ_ERROR_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_READ_ERROR_H

#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

// Why a file cannot be parsed and where: thrown by the parsers of internal/read_*_soup.h, reported
// by IO::read_triangle_mesh() as Invalid_input (UNREADABLE_FILE) with the file name and format.
struct Read_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

// `token` as a message quotes it: at most 40 characters, bytes other than printable ASCII as '?'
// (a binary file must not garble the message); the empty token is the end of the statement.
inline std::string quoted_token(std::string_view token)
{
  if(token.empty()) return "the end of the line";
  std::string out = "'";
  for(std::size_t i = 0; i < token.size() && i < 40; ++i)
    out += (token[i] >= 32 && token[i] < 127) ? token[i] : '?';
  return out + (token.size() > 40 ? "...'" : "'");
}

// Throws "line N: what" for the text at `at` of the buffer that starts at `begin`; the line is
// counted here, so that parsing never pays for it.
[[noreturn]] inline void throw_read_error_at_line(const char* begin, const char* at, const std::string& what)
{
  const std::size_t line = 1 + std::size_t(std::count(begin, at, '\n'));
  throw Read_error("line " + std::to_string(line) + ": " + what);
}

// Throws "byte N: what" for the binary data at `at` of the buffer that starts at `begin`.
[[noreturn]] inline void throw_read_error_at_byte(const char* begin, const char* at, const std::string& what)
{
  throw Read_error("byte " + std::to_string(std::size_t(at - begin)) + ": " + what);
}

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_READ_ERROR_H
