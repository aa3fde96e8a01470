// Copyright (c) 2026 CGAL_pmsum contributors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// A parallel loop (TBB) that falls back to a plain loop, for the stages that are not
// organised in waves (normal filter, octree filter).

#ifndef CGAL_PMSUM_INTERNAL_PARALLEL_H
#define CGAL_PMSUM_INTERNAL_PARALLEL_H

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#endif

#include <cstddef>

namespace CGAL {
namespace Pmsum {
namespace internal {

/// Runs f(i) for i in [0, n), in parallel if asked and TBB is there.
template <class F>
void for_each_index(std::size_t n, bool parallel, const F& f)
{
#ifdef CGAL_LINKED_WITH_TBB
  if (parallel) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n), [&](const tbb::blocked_range<std::size_t>& r) {
      for (std::size_t i = r.begin(); i != r.end(); ++i) f(i);
    });
    return;
  }
#else
  (void)parallel;
#endif
  for (std::size_t i = 0; i < n; ++i) f(i);
}

} // namespace internal
} // namespace Pmsum
} // namespace CGAL

#endif // CGAL_PMSUM_INTERNAL_PARALLEL_H
