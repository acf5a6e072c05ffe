#include "analysis/decompose/emotion_weight.h"

#include "analysis/core/message_text.h"
#include "analysis/skeleton/puppet_rig_fit.h"
#include "analysis/skeleton/skeleton_resample.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>

namespace bunraku::analysis {

void weightEmotionInto(const Decomposition& decomposition, int function, int cell, double weight, Eigen::MatrixXd& out)
{
    assert(function >= 0 && function < int(decomposition.functions.size()));
    assert(cell >= 0 && cell < int(decomposition.emotions.size()));
    const auto& y = decomposition.functions[std::size_t(function)].values;
    const auto& z = decomposition.emotions[std::size_t(cell)].values;
    out.resize(y.rows(), y.cols());
    out.noalias() = y + weight * z; // eq. 4.45
}

namespace {

/// A take of the decomposition's layout whose values are `coordinates` of function `function`,
/// written back: Euler angles on the function's branch, and the skeleton of `skeleton` when given.
Take takeFromCoordinates(const Decomposition& decomposition, int function, const Eigen::MatrixXd& coordinates,
                         const Eigen::MatrixXd* skeleton)
{
    Take take;
    take.rateHz = decomposition.rateHz;
    take.channels = decomposition.channels;
    const auto f = std::size_t(function);
    if (f < decomposition.charts.size() && decomposition.charts[f].tracks > 0) {
        std::optional<Eigen::RowVectorXd> branch;
        if (f < decomposition.angleBranches.size()) branch = decomposition.angleBranches[f];
        take.values = eulerFromRotationCoordinates(take, coordinates, decomposition.charts[f], branch);
    } else {
        take.values = coordinates;
    }
    if (skeleton && decomposition.skeleton && f < decomposition.skeleton->charts.size())
        take.skeleton = motionFromSkeletonCoordinates(*skeleton, decomposition.skeleton->charts[f]);
    return take;
}

/// The lowest point of the body (every joint and End Site but the roots) per frame, cm.
Eigen::VectorXd lowestPoints(const SkeletalMotion& motion)
{
    Eigen::VectorXd low(motion.frameCount());
    const auto& joints = motion.skeleton->joints;
    for (Eigen::Index f = 0; f < motion.frameCount(); ++f) {
        const auto poses = motion.worldPoses(f);
        double z = std::numeric_limits<double>::infinity();
        for (std::size_t j = 0; j < joints.size(); ++j)
            if (joints[j].parent >= 0) z = std::min(z, poses[j].translation.z());
        low(f) = z;
    }
    return low;
}

/// `weighted` with its roots shifted vertically per frame so that its lowest point is
/// neutral + a (emotional - neutral) of the inputs' lowest points, clamped to the range they
/// span; null for the puppet's rig (held in the air), a skeleton of roots only, or frames that
/// do not line up.
SkeletalMotionPtr keepOnFloor(const SkeletalMotion& weighted, const SkeletalMotion& neutral, const SkeletalMotion& emotional, double weight)
{
    if (!weighted.skeleton || isPuppetRig(*weighted.skeleton)) return nullptr;
    const Eigen::Index frames = weighted.frameCount();
    if (neutral.frameCount() != frames || emotional.frameCount() != frames || frames == 0) return nullptr;
    const Eigen::VectorXd low = lowestPoints(weighted);
    const Eigen::VectorXd lowNeutral = lowestPoints(neutral);
    const Eigen::VectorXd lowEmotional = lowestPoints(emotional);
    if (!low.allFinite() || !lowNeutral.allFinite() || !lowEmotional.allFinite()) return nullptr;
    const double floor = std::min(lowNeutral.minCoeff(), lowEmotional.minCoeff());
    const double ceiling = std::max(lowNeutral.maxCoeff(), lowEmotional.maxCoeff());
    std::vector<RigidTransform> corrections(static_cast<std::size_t>(frames));
    bool moved = false;
    for (Eigen::Index f = 0; f < frames; ++f) {
        const double target = std::clamp(lowNeutral(f) + weight * (lowEmotional(f) - lowNeutral(f)), floor, ceiling);
        corrections[std::size_t(f)].translation = Eigen::Vector3d(0.0, 0.0, target - low(f));
        moved = moved || std::abs(target - low(f)) > 1e-12;
    }
    if (!moved) return nullptr;
    std::vector<int> roots;
    for (std::size_t j = 0; j < weighted.skeleton->joints.size(); ++j)
        if (weighted.skeleton->joints[j].parent < 0) roots.push_back(int(j));
    return moveSkeletalRoots(weighted, corrections, roots);
}

int findFunction(const Decomposition& decomposition, const std::string& function)
{
    for (std::size_t i = 0; i < decomposition.functions.size(); ++i)
        if (decomposition.functions[i].function == function) return int(i);
    return -1;
}

Error unknownFunction(const Decomposition& decomposition, const std::string& function)
{
    std::string known;
    for (const auto& f : decomposition.functions) known += (known.empty() ? "" : ", ") + shortenedForMessage(f.function);
    return makeError(ErrorCode::NotFound,
                     "unknown function '" + shortenedForMessage(function) + "' (known: " + shortenedForMessage(known, 400) + ")");
}

} // namespace

Result<Take> functionComponentTake(const Decomposition& decomposition, const std::string& function)
{
    const int index = findFunction(decomposition, function);
    if (index < 0) return unknownFunction(decomposition, function);
    const Eigen::MatrixXd* skeleton = decomposition.skeleton ? &decomposition.skeleton->functions[std::size_t(index)] : nullptr;
    Take take = takeFromCoordinates(decomposition, index, decomposition.functions[std::size_t(index)].values, skeleton);
    take.labels = {function, decomposition.neutralEmotion, 0, "function component"};
    return take;
}

Result<Take> weightEmotion(const Decomposition& decomposition, const std::string& function, const std::string& emotion,
                           double weight)
{
    if (!std::isfinite(weight) || weight < kMinEmotionWeight || weight > kMaxEmotionWeight) {
        std::ostringstream message;
        message << "emotion weight a = " << weight << " outside [" << kMinEmotionWeight << ", " << kMaxEmotionWeight << "]";
        return makeError(ErrorCode::InvalidArgument, message.str());
    }
    const int functionIndex = findFunction(decomposition, function);
    if (functionIndex < 0) return unknownFunction(decomposition, function);
    const int cell = decomposition.cellIndex(function, emotion);
    if (cell < 0) {
        std::string known;
        for (const auto& e : decomposition.emotions)
            if (e.function == function) known += (known.empty() ? "" : ", ") + shortenedForMessage(e.emotion);
        return makeError(ErrorCode::NotFound, "function '" + shortenedForMessage(function) + "' has no emotion '" +
                                                  shortenedForMessage(emotion) + "' (known: " + shortenedForMessage(known, 400) + ")");
    }
    Eigen::MatrixXd coordinates;
    weightEmotionInto(decomposition, functionIndex, cell, weight, coordinates);
    Eigen::MatrixXd skeleton;
    if (decomposition.skeleton) // eq. 4.45 joint by joint
        skeleton = decomposition.skeleton->functions[std::size_t(functionIndex)] + weight * decomposition.skeleton->emotions[std::size_t(cell)];
    Take take = takeFromCoordinates(decomposition, functionIndex, coordinates, decomposition.skeleton ? &skeleton : nullptr);
    if (take.skeleton && weight != 0.0 && weight != 1.0) {
        // A performer weighted beyond (or between) its inputs stands where they stand: the lowest
        // point of the body at each frame follows y + a z of the inputs' lowest points, kept
        // within the lowest points the inputs reach (no foot below the floor, none lifted above
        // where the inputs ever stand). Joints move by one vertical shift of the roots.
        const auto& charts = decomposition.skeleton->charts[std::size_t(functionIndex)];
        const auto neutral = motionFromSkeletonCoordinates(decomposition.skeleton->functions[std::size_t(functionIndex)], charts);
        const auto emotional = motionFromSkeletonCoordinates(
            decomposition.skeleton->functions[std::size_t(functionIndex)] + decomposition.skeleton->emotions[std::size_t(cell)], charts);
        if (auto grounded = keepOnFloor(*take.skeleton, *neutral, *emotional, weight)) take.skeleton = std::move(grounded);
    }
    take.labels.function = function;
    take.labels.emotion = emotion;
    take.labels.takeIndex = 0;
    std::ostringstream source;
    source << "emotion weight a = " << weight;
    take.labels.source = source.str();
    return take;
}

} // namespace bunraku::analysis
