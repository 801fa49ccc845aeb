// Copyright (c) 2026 The Part_decomposition authors.
// All rights reserved.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The Part_decomposition authors

#ifndef CGAL_PART_DECOMPOSITION_INTERNAL_PRIOR_PARALLEL_H
#define CGAL_PART_DECOMPOSITION_INTERNAL_PRIOR_PARALLEL_H

#include <CGAL/assertions.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <type_traits>
#include <vector>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#endif

namespace CGAL {
namespace Part_decomposition {
namespace internal {

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
#ifdef CGAL_LINKED_WITH_TBB
  if(is_parallel_tag<ConcurrencyTag>() && number_of_blocks > 1)
  {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, number_of_blocks, 1),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                        for(std::size_t b = range.begin(); b != range.end(); ++b)
                          f(b * block_size, (std::min)(n, (b + 1) * block_size));
                      });
    return;
  }
#endif
  for(std::size_t b = 0; b < number_of_blocks; ++b)
    f(b * block_size, (std::min)(n, (b + 1) * block_size));
}

// The q-quantile of `values` with linear interpolation between order statistics (the default
// of numpy.quantile): h = (n-1) q, result = v[floor h] + (h - floor h) (v[floor h + 1] - v[floor h]).
// Reorders `values`. Precondition: `values` is not empty, q in [0,1].
inline double linear_quantile(std::vector<double>& values, double q)
{
  CGAL_precondition(!values.empty());
  const std::size_t n = values.size();
  const double h = double(n - 1) * q;
  std::size_t lo = std::size_t(std::floor(h));
  lo = (std::min)(lo, n - 1);
  std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(lo), values.end());
  const double v_lo = values[lo];
  if(lo + 1 >= n) return v_lo;
  const double v_hi = *std::min_element(values.begin() + std::ptrdiff_t(lo + 1), values.end());
  const double t = h - double(lo);
  // The clamp keeps rounding from putting the result above the next order statistic.
  return t > 0. ? (std::min)(v_hi, v_lo + t * (v_hi - v_lo)) : v_lo;
}

} // namespace internal
} // namespace Part_decomposition
} // namespace CGAL

#endif // CGAL_PART_DECOMPOSITION_INTERNAL_PRIOR_PARALLEL_H
