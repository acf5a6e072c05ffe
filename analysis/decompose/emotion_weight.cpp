#include "analysis/decompose/emotion_weight.h"

#include "analysis/core/message_text.h"

#include <cassert>
#include <cmath>
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
    take.labels.function = function;
    take.labels.emotion = emotion;
    take.labels.takeIndex = 0;
    std::ostringstream source;
    source << "emotion weight a = " << weight;
    take.labels.source = source.str();
    return take;
}

} // namespace bunraku::analysis
