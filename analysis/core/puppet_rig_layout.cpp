#include "analysis/core/puppet_rig_layout.h"

#include "analysis/core/puppet_layout.h"

namespace bunraku::analysis {

bool isPuppetRig(const Skeleton& skeleton)
{
    if (skeleton.joints.size() != std::size_t(rig::kSlots)) return false;
    for (int slot = 0; slot < rig::kSlots; ++slot) {
        const SkeletonJoint& j = skeleton.joints[std::size_t(slot)];
        const rig::Slot& layout = rig::kLayout[std::size_t(slot)];
        if (j.name != layout.name || j.parent != layout.parent || j.endSite != layout.endSite) return false;
    }
    return true;
}

std::optional<std::vector<PartBinding>> puppetRigBindings(const Skeleton& skeleton)
{
    if (!isPuppetRig(skeleton)) return std::nullopt;
    // The head's and the hand's sensors at their End Sites; the shoulder's and the arm's at their joints.
    const std::array<Eigen::Vector3d, kPuppetPartCount> sensor{skeleton.joints[rig::kHeadEndSlot].offset, Eigen::Vector3d::Zero(),
                                                               Eigen::Vector3d::Zero(), skeleton.joints[rig::kHandEndSlot].offset};
    std::vector<PartBinding> bindings;
    for (int p = 0; p < kPuppetPartCount; ++p)
        bindings.push_back(PartBinding{std::string(kPuppetParts[std::size_t(p)]), rig::kPartSlot[std::size_t(p)],
                                       RigidTransform{Eigen::Quaterniond::Identity(), sensor[std::size_t(p)]}});
    return bindings;
}

} // namespace bunraku::analysis
