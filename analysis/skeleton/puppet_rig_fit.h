#pragma once
/// The puppet's articulated rig for takes of the 24 puppet channels that carry no skeleton (the
/// demo corpus, FASTRAK, CSV): one body per take. The shoulder part is the root; the head turns
/// on a neck joint, the arm on a shoulder joint, the hand on a wrist joint, each at a constant
/// offset in its parent's frame, each part's sensor at a constant offset in its own frame.
///
/// Fit (per child part c of parent p, over every frame f of every take):
///     p_c(f) - p_p(f) = R_p(f) a + R_c(f) b
/// is linear in a (the joint in the parent's frame, from the parent's sensor) and b (the child's
/// sensor in its own frame): least squares over 3 x frames equations, the minimum-norm solution
/// where the two are not separable (a part that never turns against its parent). Orientations
/// are the channels' own (each joint has three rotational degrees of freedom), so only positions
/// have a residual: the rig's segment lengths are constant, a sensor that slides along a limb
/// (the demo's arm reach) is what the rig cannot follow, and the fit says by how much.

#include "analysis/core/puppet_rig_layout.h"
#include "analysis/core/result.h"
#include "analysis/core/skeleton.h"
#include "analysis/core/take.h"

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace bunraku::analysis {

/// How far the rig's parts are from the channels it was fitted to, per part (kPuppetParts order).
struct PuppetRigResidual {
    std::array<double, 4> rmsCm{};  ///< root mean square distance of the part's position over every frame
    std::array<double, 4> maxCm{};  ///< largest distance
    std::array<double, 4> maxDeg{}; ///< largest angle between the orientations (rounding: joints turn freely)
    Eigen::Index frames = 0;
};

struct PuppetRigFit {
    std::shared_ptr<const Skeleton> skeleton;
    PuppetRigResidual residual;
};

/// The rig of `takes` (each with the 24 puppet channels, hasPuppetLayout), one set of segment
/// lengths for all of them (one puppet). InvalidArgument for no takes, a take of another
/// layout or a non-finite fit.
Result<PuppetRigFit> fitPuppetRig(const std::vector<const Take*>& takes);

/// The take's motion on the rig: root at the shoulder part's pose, every joint's rotation the
/// relative orientation of its part to the parent part. InvalidArgument for a take of another
/// layout or a skeleton that is not a fitted rig.
Result<std::shared_ptr<const SkeletalMotion>> puppetRigMotion(const Take& take, std::shared_ptr<const Skeleton> rig);

/// The residual of `takes` on `rig` (as fitPuppetRig reports it).
Result<PuppetRigResidual> puppetRigResidual(const std::vector<const Take*>& takes, const Skeleton& rig);

/// Gives every take of `takes` with the 24 puppet channels and no skeleton the motion of one rig
/// fitted to all of them; takes with a skeleton or another layout are left alone. Returns the
/// fit, or nothing when no take needed one.
Result<std::optional<PuppetRigFit>> attachPuppetRig(std::vector<Take>& takes);

/// "head 0.00 cm, shoulder 0.00 cm, arm 2.31 cm, hand 4.02 cm (largest; rms 0.00 ...)".
std::string describePuppetRigResidual(const PuppetRigResidual& residual);

} // namespace bunraku::analysis
