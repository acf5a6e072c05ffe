#include "analysis/decompose/emotion_weight.h"

#include <cassert>
#include <cmath>
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

Result<Take> weightEmotion(const Decomposition& decomposition, const std::string& function, const std::string& emotion,
                           double weight)
{
    if (!std::isfinite(weight) || weight < kMinEmotionWeight || weight > kMaxEmotionWeight) {
        std::ostringstream message;
        message << "emotion weight a = " << weight << " outside [" << kMinEmotionWeight << ", " << kMaxEmotionWeight << "]";
        return makeError(ErrorCode::InvalidArgument, message.str());
    }
    int functionIndex = -1;
    for (std::size_t i = 0; i < decomposition.functions.size(); ++i)
        if (decomposition.functions[i].function == function) functionIndex = int(i);
    if (functionIndex < 0) {
        std::string known;
        for (const auto& f : decomposition.functions) known += (known.empty() ? "" : ", ") + f.function;
        return makeError(ErrorCode::NotFound, "unknown function '" + function + "' (known: " + known + ")");
    }
    const int cell = decomposition.cellIndex(function, emotion);
    if (cell < 0) {
        std::string known;
        for (const auto& e : decomposition.emotions)
            if (e.function == function) known += (known.empty() ? "" : ", ") + e.emotion;
        return makeError(ErrorCode::NotFound, "function '" + function + "' has no emotion '" + emotion + "' (known: " + known + ")");
    }
    Take take;
    weightEmotionInto(decomposition, functionIndex, cell, weight, take.values);
    take.rateHz = decomposition.rateHz;
    take.channels = decomposition.channels;
    take.labels.function = function;
    take.labels.emotion = emotion;
    take.labels.takeIndex = 0;
    std::ostringstream source;
    source << "emotion weight a = " << weight;
    take.labels.source = source.str();
    return take;
}

} // namespace bunraku::analysis
