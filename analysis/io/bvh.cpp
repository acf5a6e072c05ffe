#include "analysis/io/bvh.h"

#include "analysis/io/text_format.h"

#include <cmath>

namespace bunraku::analysis::io {

const char* bvhChannelName(BvhChannel channel)
{
    switch (channel) {
    case BvhChannel::Xposition: return "Xposition";
    case BvhChannel::Yposition: return "Yposition";
    case BvhChannel::Zposition: return "Zposition";
    case BvhChannel::Xrotation: return "Xrotation";
    case BvhChannel::Yrotation: return "Yrotation";
    case BvhChannel::Zrotation: return "Zrotation";
    }
    return "";
}

bool isPositionChannel(BvhChannel c)
{
    return c == BvhChannel::Xposition || c == BvhChannel::Yposition || c == BvhChannel::Zposition;
}

int channelAxis(BvhChannel c)
{
    switch (c) {
    case BvhChannel::Xposition: case BvhChannel::Xrotation: return 0;
    case BvhChannel::Yposition: case BvhChannel::Yrotation: return 1;
    default: return 2;
    }
}

int BvhSkeleton::find(const std::string& name) const
{
    for (std::size_t i = 0; i < joints.size(); ++i)
        if (joints[i].name == name) return int(i);
    return -1;
}

int BvhSkeleton::jointCount() const
{
    int count = 0;
    for (const auto& j : joints) count += j.endSite ? 0 : 1;
    return count;
}

int BvhSkeleton::endSiteCount() const { return int(joints.size()) - jointCount(); }

std::vector<RigidTransform> bvhLocalPoses(const BvhFile& file, Eigen::Index frame, const BvhKinematicsOptions& options)
{
    assert(frame >= 0 && frame < file.motion.values.rows());
    std::vector<RigidTransform> local(file.skeleton.joints.size());
    for (std::size_t j = 0; j < file.skeleton.joints.size(); ++j) {
        const BvhJoint& joint = file.skeleton.joints[j];
        Eigen::Vector3d translation = joint.offset;
        Eigen::Vector3d channelsPosition = Eigen::Vector3d::Zero();
        bool replaced[3] = {false, false, false};
        Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
        for (std::size_t k = 0; k < joint.channels.size(); ++k) {
            const double value = file.motion.values(frame, joint.firstChannel + Eigen::Index(k));
            const int axis = channelAxis(joint.channels[k]);
            if (isPositionChannel(joint.channels[k])) {
                channelsPosition[axis] = value;
                replaced[axis] = true;
            } else {
                rotation = rotation * Eigen::Quaterniond(Eigen::AngleAxisd(value * M_PI / 180.0, Eigen::Vector3d::Unit(axis)));
            }
        }
        for (int a = 0; a < 3; ++a) {
            if (!replaced[a]) continue;
            if (options.positionMode == BvhPositionMode::ReplaceOffset) translation[a] = channelsPosition[a];
            else translation[a] += channelsPosition[a];
        }
        local[j] = RigidTransform{rotation.normalized(), translation};
    }
    return local;
}

std::vector<RigidTransform> bvhWorldPoses(const BvhFile& file, Eigen::Index frame, const BvhKinematicsOptions& options)
{
    auto poses = bvhLocalPoses(file, frame, options);
    for (std::size_t j = 0; j < poses.size(); ++j) {
        const int parent = file.skeleton.joints[j].parent;
        if (parent >= 0) poses[j] = poses[std::size_t(parent)] * poses[j];
    }
    return poses;
}

std::string formatBvh(const BvhFile& file)
{
    std::string out = "HIERARCHY\n";
    const auto& joints = file.skeleton.joints;
    std::vector<int> depth(joints.size(), 0);
    std::vector<int> open; // indices whose braces are open
    const auto closeUntil = [&](int parent) {
        while (!open.empty() && open.back() != parent) {
            out += std::string(std::size_t(2 * (int(open.size()) - 1)), ' ') + "}\n";
            open.pop_back();
        }
    };
    for (std::size_t j = 0; j < joints.size(); ++j) {
        const BvhJoint& joint = joints[j];
        closeUntil(joint.parent);
        const std::string indent(std::size_t(2 * open.size()), ' ');
        if (joint.endSite) out += indent + "End Site\n";
        else out += indent + (joint.parent < 0 ? "ROOT " : "JOINT ") + joint.name + "\n";
        out += indent + "{\n";
        out += indent + "  OFFSET";
        for (int a = 0; a < 3; ++a) {
            out += ' ';
            appendShortestNumber(out, joint.offset[a]);
        }
        out += "\n";
        if (!joint.endSite) {
            out += indent + "  CHANNELS " + std::to_string(joint.channels.size());
            for (BvhChannel c : joint.channels) out += std::string(" ") + bvhChannelName(c);
            out += "\n";
        }
        open.push_back(int(j));
    }
    closeUntil(-1);
    out += "MOTION\nFrames: " + std::to_string(file.motion.values.rows()) + "\nFrame Time: ";
    appendShortestNumber(out, file.motion.frameTime);
    out += "\n";
    for (Eigen::Index f = 0; f < file.motion.values.rows(); ++f) {
        for (Eigen::Index c = 0; c < file.motion.values.cols(); ++c) {
            if (c > 0) out += ' ';
            appendShortestNumber(out, file.motion.values(f, c));
        }
        out += "\n";
    }
    return out;
}

} // namespace bunraku::analysis::io
