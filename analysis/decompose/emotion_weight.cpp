#include "analysis/decompose/emotion_weight.h"

#include "analysis/core/message_text.h"
#include "analysis/skeleton/ground_contact.h"
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

/// `weighted` on the floor (analysis/skeleton/ground_contact.h): per frame, its pelvis at
/// neutral + a (emotional - neutral) of the inputs' pelvis heights and its lowest point at the
/// same combination of their lowest points, each clamped to the range the inputs span, so that a
/// weight past 1 neither lifts the feet off the floor nor pushes them through it nor crouches
/// deeper than the inputs do (the legs bend less instead); null for the puppet's rig (held in the
/// air), a skeleton of roots only, or frames that do not line up.
SkeletalMotionPtr keepOnFloor(const SkeletalMotion& weighted, const SkeletalMotion& neutral, const SkeletalMotion& emotional, double weight)
{
    if (!weighted.skeleton || isPuppetRig(*weighted.skeleton)) return nullptr;
    const Eigen::Index frames = weighted.frameCount();
    if (neutral.frameCount() != frames || emotional.frameCount() != frames || frames == 0) return nullptr;
    const auto combined = [&](const Eigen::VectorXd& y, const Eigen::VectorXd& z) -> std::optional<Eigen::VectorXd> {
        if (!y.allFinite() || !z.allFinite()) return std::nullopt;
        const double floor = std::min(y.minCoeff(), z.minCoeff());
        const double ceiling = std::max(y.maxCoeff(), z.maxCoeff());
        return Eigen::VectorXd((y + weight * (z - y)).array().max(floor).min(ceiling));
    };
    const auto lowest = combined(lowestPoints(neutral), lowestPoints(emotional));
    if (!lowest) return nullptr;
    const int pelvis = findLegs(weighted).pelvis;
    std::optional<Eigen::VectorXd> pelvisHeight;
    if (pelvis >= 0) pelvisHeight = combined(jointHeights(neutral, pelvis), jointHeights(emotional, pelvis));
    if (!pelvisHeight) pelvisHeight = jointHeights(weighted, std::max(pelvis, 0));
    auto grounded = groundBody(weighted, *pelvisHeight, *lowest);
    if (!grounded || !grounded->skeleton) return nullptr;
    return grounded;
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
