#pragma once
/// Work split across threads where it divides into independent items (cells of a corpus, takes,
/// channels), with results that do not depend on the number of threads: each item writes only
/// its own result slot, and whatever combines the items does so afterwards in item order. The
/// calling thread works too; `threads` 1 runs everything on it, in order.

#include "analysis/core/result.h"
#include "analysis/core/run_control.h"

#include <cstddef>
#include <functional>
#include <mutex>
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

/// The progress of parallelFor's items: finished() from any thread counts one more item done
/// and reports done / total, mapped to [from, to], to the control, one report at a time.
class ItemProgress {
public:
    ItemProgress(const RunControl& control, std::size_t total, double from = 0.0, double to = 1.0)
        : m_control(control), m_total(total == 0 ? 1 : total), m_from(from), m_to(to)
    {
    }
    void finished()
    {
        const std::lock_guard lock(m_mutex);
        m_control.report(m_from + (m_to - m_from) * double(++m_done) / double(m_total));
    }

private:
    const RunControl& m_control;
    std::size_t m_total;
    double m_from, m_to;
    std::mutex m_mutex;
    std::size_t m_done = 0;
};

} // namespace bunraku::analysis
