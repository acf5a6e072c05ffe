#pragma once
/// Work split across threads where it divides into independent items (cells of a corpus, takes,
/// channels), with results that do not depend on the number of threads: each item writes only
/// its own result slot, and whatever combines the items does so afterwards in item order. The
/// calling thread works too; `threads` 1 runs everything on it, in order.

#include "analysis/core/result.h"

#include <cstddef>
#include <functional>
#include <stop_token>

namespace bunraku::analysis {

/// The largest thread count accepted (a typo like --threads 10000 is refused, not obeyed).
inline constexpr int kMaxThreads = 256;

/// `requested` threads, 0 meaning one per hardware thread; clamped to [1, kMaxThreads].
int resolveThreads(int requested);

/// Runs body(i) once for every i in [0, count) on up to `threads` threads (fewer when there are
/// fewer items). Items start in index order; after a failing item (an error, or an exception,
/// which is rethrown here) or a stop request no further item starts. Returns the error of the
/// lowest failing index, a Cancelled error when stopped, else ok.
Status parallelFor(std::size_t count, int threads, const std::function<Status(std::size_t)>& body, std::stop_token stop = {});

} // namespace bunraku::analysis
