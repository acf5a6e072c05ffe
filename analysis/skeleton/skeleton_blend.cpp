#include "analysis/skeleton/skeleton_blend.h"

#include "analysis/core/rotation.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace bunraku::analysis {

namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

/// Rotation of `joint` at fractional frame `s` (clamped), slerped between whole frames.
Eigen::Quaterniond rotationAt(const SkeletalMotion& motion, double s, int joint)
{
    const Eigen::Index last = motion.frameCount() - 1;
    const double t = std::clamp(s, 0.0, double(last));
    const Eigen::Index k = Eigen::Index(std::floor(t));
    const double w = t - double(k);
    if (w <= 0.0 || k >= last) return motion.rotation(std::min(k, last), joint);
    return slerpShortest(motion.rotation(k, joint), motion.rotation(k + 1, joint), w);
}

Eigen::Vector3d translationAt(const SkeletalMotion& motion, double s, int joint)
{
    const Eigen::Index last = motion.frameCount() - 1;
    const double t = std::clamp(s, 0.0, double(last));
    const Eigen::Index k = Eigen::Index(std::floor(t));
    const double w = t - double(k);
    if (w <= 0.0 || k >= last) return motion.translation(std::min(k, last), joint);
    return (1.0 - w) * motion.translation(k, joint) + w * motion.translation(k + 1, joint);
}

/// A motion of `frames` frames on the layout's skeleton and bone offsets whose translating
/// joints are `translating` (all moving).
std::shared_ptr<SkeletalMotion> blankMotion(const SkeletalMotion& layout, Eigen::Index frames, const std::vector<int>& translating)
{
    auto out = std::make_shared<SkeletalMotion>();
    out->skeleton = layout.skeleton;
    out->staticTranslations = layout.staticTranslations;
    out->movingJoints = translating;
    out->rotations.resize(std::size_t(frames) * std::size_t(layout.jointSlots()));
    out->movingTranslations.resize(frames, Eigen::Index(3 * translating.size()));
    return out;
}

Error incompatible(const SkeletalMotion& a, const SkeletalMotion& b)
{
    const std::string first = a.skeleton ? a.skeleton->name : std::string("?");
    const std::string second = b.skeleton ? b.skeleton->name : std::string("?");
    return makeError(ErrorCode::InvalidArgument, "skeletons '" + first + "' and '" + second +
                                                     "' have other joints (names, parents, End Sites): their motions cannot be averaged joint by joint");
}

} // namespace

Result<SkeletalMotionPtr> meanSkeletalMotion(const std::vector<BlendMember>& members)
{
    if (members.empty()) return makeError(ErrorCode::InvalidArgument, "skeleton average: no members");
    std::vector<const SkeletalMotion*> motions;
    for (const BlendMember& member : members) {
        if (!member.motion || member.motion->frameCount() == 0 || !member.motion->skeleton)
            return makeError(ErrorCode::InvalidArgument, "skeleton average: a member has no skeletal motion");
        if (member.at.size() != members.front().at.size())
            return makeError(ErrorCode::InvalidArgument, "skeleton average: the members' frame maps differ in length");
        if (!compatibleMotions(*members.front().motion, *member.motion)) return incompatible(*members.front().motion, *member.motion);
        motions.push_back(member.motion);
    }
    const SkeletalMotion& layout = *members.front().motion;
    const std::vector<int> translating = translatingJoints(motions);
    const Eigen::Index frames = members.front().at.size();
    auto out = blankMotion(layout, frames, translating);
    const int slots = layout.jointSlots();
    std::vector<Eigen::Quaterniond> samples(members.size());
    std::vector<double> weights(members.size());
    double total = 0.0;
    for (std::size_t k = 0; k < members.size(); ++k) {
        weights[k] = members[k].weight;
        total += weights[k];
    }
    if (!(total > 0.0)) return makeError(ErrorCode::InvalidArgument, "skeleton average: the weights sum to zero");
    for (Eigen::Index u = 0; u < frames; ++u) {
        for (int j = 0; j < slots; ++j) {
            for (std::size_t k = 0; k < members.size(); ++k) samples[k] = rotationAt(*members[k].motion, members[k].at[u], j);
            out->rotation(u, j) = meanRotation(samples, weights);
        }
        for (std::size_t t = 0; t < translating.size(); ++t) {
            Eigen::Vector3d sum = Eigen::Vector3d::Zero();
            for (std::size_t k = 0; k < members.size(); ++k)
                sum += weights[k] * translationAt(*members[k].motion, members[k].at[u], translating[t]);
            out->movingTranslations.block<1, 3>(u, Eigen::Index(3 * t)) = (sum / total).transpose();
        }
    }
    return SkeletalMotionPtr(std::move(out));
}

Result<SkeletonChart> meanSkeletonChart(const std::vector<std::shared_ptr<const SkeletalMotion>>& motions)
{
    if (motions.empty()) return makeError(ErrorCode::InvalidArgument, "skeleton chart: no motions");
    std::vector<const SkeletalMotion*> raw;
    Eigen::Index frames = motions.front() ? motions.front()->frameCount() : 0;
    for (const auto& motion : motions) {
        if (!motion || !motion->skeleton || motion->frameCount() == 0)
            return makeError(ErrorCode::InvalidArgument, "skeleton chart: a take has no skeletal motion");
        if (!compatibleMotions(*motions.front(), *motion)) return incompatible(*motions.front(), *motion);
        raw.push_back(motion.get());
        frames = std::min(frames, motion->frameCount());
    }
    SkeletonChart chart;
    chart.layout = motions.front();
    chart.translating = translatingJoints(raw);
    const int slots = motions.front()->jointSlots();
    chart.rotations.frames = frames;
    chart.rotations.tracks = slots;
    chart.rotations.base.resize(std::size_t(frames) * std::size_t(slots));
    std::vector<Eigen::Quaterniond> samples(raw.size());
    for (Eigen::Index f = 0; f < frames; ++f)
        for (int j = 0; j < slots; ++j) {
            for (std::size_t k = 0; k < raw.size(); ++k) samples[k] = raw[k]->rotation(f, j);
            chart.rotations.base[std::size_t(f) * std::size_t(slots) + std::size_t(j)] = chordalMeanRotation(samples);
        }
    return chart;
}

Eigen::MatrixXd skeletonCoordinates(const SkeletalMotion& motion, const SkeletonChart& chart)
{
    const Eigen::Index frames = motion.frameCount();
    const int slots = chart.rotations.tracks;
    Eigen::MatrixXd out(frames, chart.coordinateCount());
    const Eigen::Index lastBase = std::max<Eigen::Index>(chart.rotations.frames - 1, 0);
    for (int j = 0; j < slots; ++j) {
        Eigen::Vector3d previous = Eigen::Vector3d::Zero();
        for (Eigen::Index f = 0; f < frames; ++f) {
            const Eigen::Quaterniond relative = chart.rotations.at(std::min(f, lastBase), j).conjugate() * motion.rotation(f, j);
            const Eigen::Vector3d r = f == 0 ? logMap(relative) : nearestRotationVector(relative, previous);
            previous = r;
            out.block<1, 3>(f, 3 * Eigen::Index(j)) = r.transpose() / kDegree;
        }
    }
    for (std::size_t t = 0; t < chart.translating.size(); ++t)
        for (Eigen::Index f = 0; f < frames; ++f)
            out.block<1, 3>(f, 3 * Eigen::Index(slots) + 3 * Eigen::Index(t)) = motion.translation(f, chart.translating[t]).transpose();
    return out;
}

SkeletalMotionPtr motionFromSkeletonCoordinates(const Eigen::MatrixXd& coordinates, const SkeletonChart& chart)
{
    if (!chart.layout) return nullptr;
    const Eigen::Index frames = coordinates.rows();
    const int slots = chart.rotations.tracks;
    auto out = blankMotion(*chart.layout, frames, chart.translating);
    const Eigen::Index lastBase = std::max<Eigen::Index>(chart.rotations.frames - 1, 0);
    for (Eigen::Index f = 0; f < frames; ++f) {
        for (int j = 0; j < slots; ++j) {
            const Eigen::Vector3d r = coordinates.block<1, 3>(f, 3 * Eigen::Index(j)).transpose() * kDegree;
            out->rotation(f, j) = (chart.rotations.at(std::min(f, lastBase), j) * expMap(r)).normalized();
        }
        out->movingTranslations.row(f) = coordinates.block(f, 3 * Eigen::Index(slots), 1, 3 * Eigen::Index(chart.translating.size()));
    }
    return out;
}

} // namespace bunraku::analysis
