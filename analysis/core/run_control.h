#pragma once
/// Cancellation and progress for long computations: every long algorithm takes a RunControl,
/// checks `cancelled()` between stages and reports progress in [0, 1].

#include <functional>
#include <stop_token>

namespace bunraku::analysis {

struct RunControl {
    std::stop_token stop;                   ///< triggered by the caller to abandon the work
    std::function<void(double)> progress;   ///< called with the finished fraction, may be empty
    /// Threads the work may use where it splits into independent items (cells, takes, channels:
    /// analysis/core/parallel.h); the results do not depend on it. Progress may then be reported
    /// from any of them, one call at a time.
    int threads = 1;

    bool cancelled() const { return stop.stop_requested(); }
    void report(double fraction) const
    {
        if (progress) progress(fraction);
    }
    /// The same stop and threads for one step of the work, its fractions mapped to [from, to] of
    /// this control's (the returned control refers to this one: use it while this one lives).
    RunControl step(double from, double to) const
    {
        if (!progress) return RunControl{stop, {}, threads};
        return RunControl{stop, [this, from, to](double fraction) { report(from + (to - from) * fraction); }, threads};
    }
};

} // namespace bunraku::analysis
