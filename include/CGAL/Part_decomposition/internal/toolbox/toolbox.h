// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_TOOLBOX_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_TOOLBOX_H

// The small tools every stage uses: parallel loops, a 3D vector, quantiles, voxel neighbours.

#include <CGAL/assertions.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/number_utils.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <type_traits>
#include <utility>
#include <vector>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#include <tbb/parallel_sort.h>
#include <tbb/task_arena.h>
#endif

namespace CGAL {
namespace Part_decomposition {
namespace internal {

// ---- Parallel loops
//
// Every loop body goes through one non-template entry point, so that TBB's partitioner code is
// compiled once per translation unit rather than once per lambda (it was an eighth of the object
// code of a program calling decompose()); the indirect call per chunk costs nothing measurable.

template <typename ConcurrencyTag>
constexpr bool is_parallel_tag()
{
  return std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value;
}

template <typename ConcurrencyTag>
void static_check_concurrency_tag()
{
#ifndef CGAL_LINKED_WITH_TBB
  CGAL_static_assertion_msg(!is_parallel_tag<ConcurrencyTag>(),
                            "Parallel_tag is enabled but TBB is unavailable.");
#endif
}

// A non-owning reference to a callable `void(std::size_t, std::size_t)`.
class Range_function
{
public:
  template <typename F>
  Range_function(const F& f)
    : m_object(&f), m_call([](const void* o, std::size_t b, std::size_t e) { (*static_cast<const F*>(o))(b, e); })
  {}
  void operator()(std::size_t b, std::size_t e) const { m_call(m_object, b, e); }

private:
  const void* m_object;
  void (*m_call)(const void*, std::size_t, std::size_t);
};

// A non-owning reference to a callable `void()`.
class Task_function
{
public:
  template <typename F>
  Task_function(const F& f)
    : m_object(&f), m_call([](const void* o) { (*static_cast<const F*>(o))(); })
  {}
  void operator()() const { m_call(m_object); }

private:
  const void* m_object;
  void (*m_call)(const void*);
};

#ifdef CGAL_LINKED_WITH_TBB
// f(begin, end) on TBB chunks of [0, n) of at least `grain` items.
inline void tbb_for_each_range(std::size_t n, std::size_t grain, Range_function f)
{
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, grain),
                    [&](const tbb::blocked_range<std::size_t>& r) { f(r.begin(), r.end()); });
}

inline void tbb_run_side_by_side(Task_function f, Task_function g) { tbb::parallel_invoke(f, g); }
#endif

// Calls f(begin, end) on chunks of [0, n) whose split is left to TBB (at least `grain` items
// each): for loops whose items write only to slots they own, so the split does not matter.
template <typename ConcurrencyTag, typename F>
void for_each_range(std::size_t n, const F& f, std::size_t grain = 1)
{
  static_check_concurrency_tag<ConcurrencyTag>();
  if(n == 0) return;
  grain = (std::max)(grain, std::size_t(1));
#ifdef CGAL_LINKED_WITH_TBB
  if constexpr(is_parallel_tag<ConcurrencyTag>())
  {
    // the body is compiled once, behind the reference, also for the short loops run in place
    const Range_function body(f);
    if(n > grain) tbb_for_each_range(n, grain, body);
    else body(0, n);
  }
  else
#endif
    f(std::size_t(0), n);
}

// Calls f(begin, end) on the blocks [b*block_size, min(n, (b+1)*block_size)). The blocks do not
// depend on the number of threads, so a caller that keeps one result per block and merges the
// blocks in order gets the same bits with any number of threads.
template <typename ConcurrencyTag, typename F>
void for_each_block(std::size_t n, std::size_t block_size, const F& f)
{
  static_check_concurrency_tag<ConcurrencyTag>();
  if(n == 0) return;
  block_size = (std::max)(block_size, std::size_t(1));
  const std::size_t number_of_blocks = (n + block_size - 1) / block_size;
  const auto blocks = [&](std::size_t first, std::size_t last) {
    for(std::size_t b = first; b != last; ++b) f(b * block_size, (std::min)(n, (b + 1) * block_size));
  };
#ifdef CGAL_LINKED_WITH_TBB
  if constexpr(is_parallel_tag<ConcurrencyTag>())
  {
    const Range_function body(blocks);
    if(number_of_blocks > 1) tbb_for_each_range(number_of_blocks, 1, body);
    else body(0, number_of_blocks);
  }
  else
#endif
    blocks(0, number_of_blocks);
}

// The number of threads the parallel loops of `ConcurrencyTag` may use.
template <typename ConcurrencyTag>
std::size_t concurrency()
{
#ifdef CGAL_LINKED_WITH_TBB
  if constexpr(is_parallel_tag<ConcurrencyTag>()) return std::size_t((std::max)(tbb::this_task_arena::max_concurrency(), 1));
#endif
  return 1;
}

// Runs `f` and `g`, as two tasks when `ConcurrencyTag` is parallel (each may run parallel loops:
// a thread idle in one joins the other), else `f` then `g`. An exception of either is rethrown.
template <typename ConcurrencyTag, typename F, typename G>
void run_side_by_side(const F& f, const G& g)
{
  static_check_concurrency_tag<ConcurrencyTag>();
#ifdef CGAL_LINKED_WITH_TBB
  if constexpr(is_parallel_tag<ConcurrencyTag>())
  {
    tbb_run_side_by_side(Task_function(f), Task_function(g));
  }
  else
#endif
  {
    f();
    g();
  }
}

// The vertex point map and the face index map of `np` (the mesh's own if absent), read once.
template <typename TriangleMesh, typename NamedParameters>
struct Mesh_maps
{
  typename GetVertexPointMap<TriangleMesh, NamedParameters>::const_type vpm;
  typename GetInitializedFaceIndexMap<TriangleMesh, NamedParameters>::const_type fim;

  Mesh_maps(const TriangleMesh& tm, const NamedParameters& np)
    : vpm(CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                             get_const_property_map(CGAL::vertex_point, tm))),
      fim(CGAL::get_initialized_face_index_map(tm, np))
  {}
};

// Wall-clock seconds since `t0`, for the stage timings.
inline double seconds_since(const std::chrono::steady_clock::time_point& t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Runs f() and adds its wall-clock seconds to `total`, also when f() throws; returns what f() returns.
template <typename F>
decltype(auto) add_seconds(double& total, const F& f)
{
  struct Timed
  {
    double& total;
    std::chrono::steady_clock::time_point start;
    ~Timed() { total += seconds_since(start); }
  };
  const Timed timed{total, std::chrono::steady_clock::now()};
  return f();
}

// Sorts [first, last) with `less`, with TBB when `ConcurrencyTag` is parallel: only for ranges in
// which elements that compare equal are identical (all distinct, or plain numbers), so that the
// result does not depend on the sort.
template <typename ConcurrencyTag, typename Iterator, typename Less = std::less<> >
void sort_values(Iterator first, Iterator last, const Less& less = Less())
{
  static_check_concurrency_tag<ConcurrencyTag>();
#ifdef CGAL_LINKED_WITH_TBB
  if constexpr(is_parallel_tag<ConcurrencyTag>())
  {
    tbb::parallel_sort(first, last, less);
    return;
  }
#endif
  std::sort(first, last, less);
}

// Asks the processor to fetch the cache line of `p`, read soon (no effect where unsupported).
inline void prefetch_address(const void* p)
{
#if defined(__GNUC__)
  __builtin_prefetch(p);
#else
  (void)p;
#endif
}

// Disjoint sets of the indices [0, n) on one flat array, which several threads may join at once
// (neither CGAL nor Boost offers that; CGAL::Union_find also allocates a node per element, whose
// pointers miss the cache over millions of faces): a root is linked below a smaller root by
// compare-and-swap, and paths are halved on the way up. Parents only ever decrease, so the root of
// a set is its smallest index.
class Index_sets
{
public:
  template <typename ConcurrencyTag = CGAL::Sequential_tag>
  explicit Index_sets(std::size_t n, ConcurrencyTag = ConcurrencyTag()) : m_parent(n)
  {
    for_each_range<ConcurrencyTag>(n, [&](std::size_t b, std::size_t e) {
      for(std::size_t i = b; i < e; ++i) m_parent[i].store(i, std::memory_order_relaxed);
    }, 4096);
  }

  // the smallest index of the set of i
  std::size_t find(std::size_t i)
  {
    for(;;)
    {
      std::size_t p = m_parent[i].load(std::memory_order_relaxed);
      if(p == i) return i;
      const std::size_t g = m_parent[p].load(std::memory_order_relaxed);
      if(g != p) m_parent[i].compare_exchange_weak(p, g, std::memory_order_relaxed);
      i = g;
    }
  }

  // joins the sets of i and j; returns the root of the joined set (exact once no other thread
  // joins these sets)
  std::size_t unite(std::size_t i, std::size_t j)
  {
    for(;;)
    {
      i = find(i);
      j = find(j);
      if(i == j) return i;
      if(i < j) std::swap(i, j);
      std::size_t root = i;
      if(m_parent[i].compare_exchange_strong(root, j, std::memory_order_relaxed)) return j;
    }
  }

  // asks the processor for the parent of i ahead of a find(): joins in a global order jump across
  // the whole index range, and waiting for each parent dominates their time
  void prefetch(std::size_t i) const { prefetch_address(&m_parent[i]); }

private:
  std::vector<std::atomic<std::size_t> > m_parent;
};

// Writes `values` (indexed by `fim`) to a caller's face property map: the one conversion from the
// stages' face-indexed vectors back to the caller's map.
template <typename FaceListGraph, typename FaceIndexMap, typename FaceMap>
void put_face_values(const FaceListGraph& g, const FaceIndexMap& fim, const std::vector<std::size_t>& values,
                     FaceMap face_map)
{
  for(auto f : faces(g)) put(face_map, f, values[std::size_t(get(fim, f))]);
}

// The indices i in [0, n) with keep(i), grouped by key(i) in [0, number_of_keys) and increasing
// inside a group (a counting sort): group g is order[start[g] .. start[g + 1]). Sums over a group
// then run in a fixed order whatever the number of threads.
template <typename Key, typename Keep>
void group_indices(std::size_t n, std::size_t number_of_keys, const Key& key, const Keep& keep,
                   std::vector<std::size_t>& start, std::vector<std::size_t>& order)
{
  start.assign(number_of_keys + 1, 0);
  for(std::size_t i = 0; i < n; ++i)
    if(keep(i)) ++start[key(i) + 1];
  for(std::size_t g = 0; g < number_of_keys; ++g) start[g + 1] += start[g];
  order.resize(start[number_of_keys]);
  std::vector<std::size_t> fill(start.begin(), start.end() - 1);
  for(std::size_t i = 0; i < n; ++i)
    if(keep(i)) order[fill[key(i)]++] = i;
}

// ---- 3D vectors of doubles (the inner loops work on plain arrays, not on kernel objects)

typedef std::array<double, 3> Vec3;
// the three corners of a triangle
typedef std::array<Vec3, 3> Triangle_points;

inline Vec3 sub3(const Vec3& a, const Vec3& b) { return {{a[0] - b[0], a[1] - b[1], a[2] - b[2]}}; }
inline double dot3(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec3 cross3(const Vec3& a, const Vec3& b)
{
  return {{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
}
inline double norm3(const Vec3& a) { return std::sqrt(dot3(a, a)); }
// The coordinates of a kernel point (of any number type) as doubles.
template <typename Point>
Vec3 vec3_of(const Point& p)
{
  return {{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
}

// ---- Quantiles, with linear interpolation between order statistics (numpy's default)

// The value at fractional rank h in [0, n-1] of `values` (reordered). 0 if empty.
inline double value_at_rank(std::vector<double>& values, double h)
{
  if(values.empty()) return 0.;
  const std::size_t n = values.size();
  const std::size_t lo = (std::min)(n - 1, std::size_t(std::floor(h)));
  std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(lo), values.end());
  const double v_lo = values[lo];
  if(lo + 1 >= n) return v_lo;
  const double v_hi = *std::min_element(values.begin() + std::ptrdiff_t(lo + 1), values.end());
  const double t = h - double(lo);
  // the clamp keeps rounding from putting the result above the next order statistic
  return t > 0. ? (std::min)(v_hi, v_lo + t * (v_hi - v_lo)) : v_lo;
}

// The q-quantile, q in [0, 1].
inline double linear_quantile(std::vector<double>& values, double q)
{
  return value_at_rank(values, double(values.empty() ? 0 : values.size() - 1) * q);
}

// The p-th percentile, p in [0, 100] (rank computed as (n-1) p / 100, not (n-1) (p / 100)).
inline double percentile(std::vector<double>& values, double p)
{
  return value_at_rank(values, double(values.empty() ? 0 : values.size() - 1) * p / 100.);
}

// ---- Voxel neighbours

// Calls f(neighbour) for the 6-neighbours of voxel `v` of an r^3 grid stored x fastest, in the
// order -x, +x, -y, +y, -z, +z.
template <typename F>
void for_each_face_neighbor(std::size_t v, std::size_t r, const F& f)
{
  const std::size_t i = v % r, j = (v / r) % r, k = v / (r * r);
  if(i > 0) f(v - 1);
  if(i + 1 < r) f(v + 1);
  if(j > 0) f(v - r);
  if(j + 1 < r) f(v + r);
  if(k > 0) f(v - r * r);
  if(k + 1 < r) f(v + r * r);
}

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_TOOLBOX_H
