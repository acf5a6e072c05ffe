#pragma once
/// Cancellation and progress for long computations: every long algorithm takes a RunControl,
/// checks `cancelled()` between stages and reports progress in [0, 1].

#include <functional>
#include <stop_token>

namespace bunraku::analysis {

struct RunControl {
    std::stop_token stop;                   ///< triggered by the caller to abandon the work
    std::function<void(double)> progress;   ///< called with the finished fraction, may be empty

    bool cancelled() const { return stop.stop_requested(); }
    void report(double fraction) const
    {
        if (progress) progress(fraction);
    }
};

} // namespace bunraku::analysis
