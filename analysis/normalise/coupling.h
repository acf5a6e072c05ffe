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
    std::vector<std::string> names; ///< one per set, e.g. "arm+hand.x", "left_leg.x"
    /// The preset the sets come from ("method2", "chains", ...; `auto` resolved), empty for
    /// explicit sets.
    std::string preset;
};

/// The default preset: `method2` on the puppet's parts, `chains` on a skeleton's joints.
inline constexpr const char* kDefaultCoupling = "auto";

/// The preset names couplingFor accepts.
std::vector<std::string> couplingPresetNames();

/// A coupling for the take's channels from a preset or an explicit list:
/// - `independent`: every channel alone;
/// - `method1` (eq. 3.28): per coordinate q, arm.q + hand.q; head and shoulder alone;
/// - `method2` (eq. 3.29): per coordinate q, head.q + shoulder.q and arm.q + hand.q;
/// - `per-part`: each part's channels together;
/// - `per-coordinate`: per coordinate q, every part's q together;
/// - `all`: every channel together;
/// - `chains` (3.6 generalised to a skeleton): per coordinate q, the q of every joint of one
///   chain of the take's skeleton together (skeleton_chains.h: root, spine up to the head, each
///   arm from the collar to the hand, each leg from the hip to the toe), sets named
///   "left_leg.x", "spine.yaw"; a part is a joint of that name or a puppet part bound to one;
///   channels of other parts stay alone. Needs the take's skeleton (Take::skeleton);
/// - `auto` (the default, kDefaultCoupling): `method2` when the take has the puppet's four
///   parts and no others, else `chains` when it carries a skeleton, else `method2` when it has
///   the four parts among others;
/// - explicit: sets separated by ';', channels by '+', e.g. "arm.x+hand.x;head.yaw+head.pitch";
///   channels not named stay alone.
/// method1/method2 need parts head, shoulder, arm, hand; NotFound names the missing part or
/// channel (and, for `auto`, says what neither preset found); InvalidArgument for a channel
/// named twice or an unknown preset.
Result<Coupling> couplingFor(const Take& take, std::string_view spec);

} // namespace bunraku::analysis
