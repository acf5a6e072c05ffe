#pragma once
/// Coupling: which channels share one correspondence (thesis 3.6, eqs. 3.28/3.29, and the
/// variants of 3.9). Normalising each channel alone tears the arm from the hand; coupled
/// channels are matched with their costs summed.

#include "analysis/core/result.h"
#include "analysis/core/take.h"

#include <Eigen/Core>

#include <string>
#include <string_view>
#include <vector>

namespace bunraku::analysis {

/// Disjoint sets of channel indices covering every channel of a take exactly once.
struct Coupling {
    std::vector<std::vector<Eigen::Index>> sets;
    std::vector<std::string> names; ///< one per set, e.g. "arm+hand.x"
};

/// The preset names couplingFor accepts.
std::vector<std::string> couplingPresetNames();

/// A coupling for the take's channels from a preset or an explicit list:
/// - `independent`: every channel alone;
/// - `method1` (eq. 3.28): per coordinate q, arm.q + hand.q; head and shoulder alone;
/// - `method2` (eq. 3.29): per coordinate q, head.q + shoulder.q and arm.q + hand.q;
/// - `per-part`: each part's channels together;
/// - `per-coordinate`: per coordinate q, every part's q together;
/// - `all`: every channel together;
/// - explicit: sets separated by ';', channels by '+', e.g. "arm.x+hand.x;head.yaw+head.pitch";
///   channels not named stay alone.
/// method1/method2 need parts head, shoulder, arm, hand; NotFound names the missing part or
/// channel; InvalidArgument for a channel named twice or an unknown preset.
Result<Coupling> couplingFor(const Take& take, std::string_view spec);

} // namespace bunraku::analysis
