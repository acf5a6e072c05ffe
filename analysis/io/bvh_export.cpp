#include "analysis/io/bvh_export.h"

#include "analysis/core/puppet_layout.h"
#include "analysis/io/atomic_file.h"

namespace bunraku::analysis::io {

Result<BvhFile> takeToBvh(const Take& take)
{
    if (auto valid = validateTake(take); !valid) return valid.error();
    const auto parts = sixDofParts(take);
    if (parts.empty())
        return makeError(ErrorCode::Unsupported, take.displayName() + ": BVH export needs parts with 6 channels x y z yaw pitch roll");
    BvhFile file;
    file.source = take.labels.source;
    file.motion.frameTime = 1.0 / take.rateHz;
    const std::vector<BvhChannel> sixChannels{BvhChannel::Xposition, BvhChannel::Yposition, BvhChannel::Zposition,
                                              BvhChannel::Zrotation, BvhChannel::Yrotation, BvhChannel::Xrotation};
    BvhJoint root;
    root.name = kBvhExportRootName;
    root.channels = sixChannels;
    file.skeleton.joints.push_back(root);
    for (std::size_t p = 0; p < parts.size(); ++p) {
        BvhJoint joint;
        joint.name = parts[p].part;
        joint.parent = 0;
        joint.channels = sixChannels;
        joint.firstChannel = int(6 * (p + 1));
        file.skeleton.joints.push_back(joint);
        BvhJoint end;
        end.name = parts[p].part + "_End";
        end.parent = int(file.skeleton.joints.size()) - 1;
        end.endSite = true;
        end.firstChannel = int(6 * (p + 2));
        file.skeleton.joints.push_back(end);
    }
    file.skeleton.channelCount = int(6 * (parts.size() + 1));
    file.motion.values = Eigen::MatrixXd::Zero(take.frameCount(), file.skeleton.channelCount);
    for (std::size_t p = 0; p < parts.size(); ++p)
        file.motion.values.middleCols(Eigen::Index(6 * (p + 1)), 6) = take.values.middleCols(parts[p].firstChannel, 6);
    return file;
}

Status writeTakeBvh(const Take& take, const std::filesystem::path& file)
{
    auto bvh = takeToBvh(take);
    if (!bvh) return makeError(bvh.error().code, file.string() + ": " + bvh.error().message);
    return writeFileAtomically(file, formatBvh(*bvh));
}

} // namespace bunraku::analysis::io
