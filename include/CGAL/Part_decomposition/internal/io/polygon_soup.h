// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_POLYGON_SOUP_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_POLYGON_SOUP_H

#include <array>
#include <cstddef>
#include <memory>
#include <new>
#include <vector>

namespace CGAL {
namespace Part_decomposition {
namespace internal {

// The largest single allocation, in bytes, of the containers the file parser fills on this thread.
inline std::size_t& read_allocation_limit()
{
  thread_local std::size_t limit = std::size_t(-1);
  return limit;
}

// Sets the limit for the lifetime of the object.
class Read_allocation_limit
{
public:
  explicit Read_allocation_limit(std::size_t bytes) : m_previous(read_allocation_limit())
  {
    read_allocation_limit() = bytes;
  }
  ~Read_allocation_limit() { read_allocation_limit() = m_previous; }
  Read_allocation_limit(const Read_allocation_limit&) = delete;
  Read_allocation_limit& operator=(const Read_allocation_limit&) = delete;

private:
  std::size_t m_previous;
};

// std::allocator that throws std::bad_alloc beyond read_allocation_limit().
template <typename T>
struct Bounded_allocator
{
  typedef T value_type;
  Bounded_allocator() = default;
  template <typename U>
  Bounded_allocator(const Bounded_allocator<U>&) {}
  T* allocate(std::size_t n)
  {
    if(n > read_allocation_limit() / sizeof(T)) throw std::bad_alloc();
    return std::allocator<T>().allocate(n);
  }
  void deallocate(T* p, std::size_t n) { std::allocator<T>().deallocate(p, n); }
  template <typename U>
  bool operator==(const Bounded_allocator<U>&) const { return true; }
  template <typename U>
  bool operator!=(const Bounded_allocator<U>&) const { return false; }
};

// A vertex index that is an integer but no vertex (negative, or too large): reported by the
// caller of the parsers as an out-of-range index.
constexpr std::size_t invalid_vertex_index = std::size_t(-1);

/*
The polygon soup a file parser fills, in flat arrays: no allocation per polygon, and every
allocation bounded by read_allocation_limit(). Polygon f is
polygon_vertices[polygon_start[f] .. polygon_start[f + 1]).
*/
struct Polygon_soup_arrays
{
  std::vector<std::array<double, 3>, Bounded_allocator<std::array<double, 3> > > points;
  std::vector<std::size_t, Bounded_allocator<std::size_t> > polygon_start = std::vector<std::size_t, Bounded_allocator<std::size_t> >(1, 0);
  std::vector<std::size_t, Bounded_allocator<std::size_t> > polygon_vertices;
  // values a text format holds beyond what its header declares, skipped
  std::size_t ignored_values = 0;

  void add_point(double x, double y, double z) { points.push_back({{x, y, z}}); }
  // to the polygon under construction
  void add_vertex_index(std::size_t i) { polygon_vertices.push_back(i); }
  void end_polygon() { polygon_start.push_back(polygon_vertices.size()); }
  // drops the indices added since the last end_polygon()
  void discard_open_polygon() { polygon_vertices.resize(polygon_start.back()); }

  std::size_t number_of_points() const { return points.size(); }
  std::size_t number_of_polygons() const { return polygon_start.size() - 1; }
  std::size_t polygon_size(std::size_t f) const { return polygon_start[f + 1] - polygon_start[f]; }
  const std::size_t* polygon_begin(std::size_t f) const { return polygon_vertices.data() + polygon_start[f]; }
  const std::size_t* polygon_end(std::size_t f) const { return polygon_vertices.data() + polygon_start[f + 1]; }
};

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_POLYGON_SOUP_H
