#include "analysis/decompose/least_squares.h"

#include <algorithm>

namespace bunraku::analysis {

const FunctionComponent* Decomposition::function(const std::string& name) const
{
    for (const auto& f : functions)
        if (f.function == name) return &f;
    return nullptr;
}

int Decomposition::cellIndex(const std::string& functionName, const std::string& emotionName) const
{
    for (std::size_t c = 0; c < emotions.size(); ++c)
        if (emotions[c].function == functionName && emotions[c].emotion == emotionName) return int(c);
    return -1;
}

const EmotionComponent* Decomposition::emotion(const std::string& functionName, const std::string& emotionName) const
{
    const int c = cellIndex(functionName, emotionName);
    return c < 0 ? nullptr : &emotions[std::size_t(c)];
}

Status checkDecomposable(const Corpus& corpus)
{
    if (corpus.takes.empty()) return makeError(ErrorCode::InvalidArgument, "decompose: the corpus has no takes");
    if (auto status = validateCorpus(corpus); !status) return status;
    const Eigen::Index frames = corpus.takes.front().frameCount();
    for (const auto& take : corpus.takes)
        if (take.frameCount() != frames)
            return makeError(ErrorCode::InvalidArgument,
                             "decompose: take " + take.displayName() + " has " + std::to_string(take.frameCount()) +
                                 " frames, expected " + std::to_string(frames) +
                                 " like the first take (pad or time-normalise the corpus first)");
    for (const auto& function : corpus.functions())
        if (corpus.cell(function, corpus.neutralEmotion).empty())
            return makeError(ErrorCode::NotFound, "decompose: function '" + function + "' has no take with the neutral emotion '" +
                                                      corpus.neutralEmotion + "' (hypothesis 4: z^{i,neutral} = 0)");
    return okStatus();
}

Result<Decomposition> decomposeLeastSquares(const Corpus& corpus)
{
    if (auto status = checkDecomposable(corpus); !status) return status.error();
    Decomposition d;
    d.rateHz = corpus.rateHz;
    d.channels = corpus.takes.front().channels;
    d.neutralEmotion = corpus.neutralEmotion;
    const auto emotions = corpus.emotions();
    auto cellMean = [](const std::vector<const Take*>& takes) {
        Eigen::MatrixXd mean = Eigen::MatrixXd::Zero(takes.front()->frameCount(), takes.front()->channelCount());
        for (const Take* take : takes) mean += take->values;
        return Eigen::MatrixXd(mean / double(takes.size()));
    };
    for (const auto& function : corpus.functions()) {
        const Eigen::MatrixXd y = cellMean(corpus.cell(function, corpus.neutralEmotion)); // eq. 4.4-4.5
        d.functions.push_back({function, y});
        // Neutral first, then the other emotions in corpus order.
        std::vector<std::string> order{corpus.neutralEmotion};
        for (const auto& e : emotions)
            if (e != corpus.neutralEmotion) order.push_back(e);
        for (const auto& emotion : order) {
            const auto takes = corpus.cell(function, emotion);
            if (takes.empty()) continue;
            const Eigen::MatrixXd mean = cellMean(takes);
            d.emotions.push_back({function, emotion, mean - y}); // minimiser of eq. 4.8
            d.cellMeans.push_back(mean);
        }
    }
    for (const auto& take : corpus.takes) {
        const int c = d.cellIndex(take.labels.function, take.labels.emotion);
        d.fluctuations.push_back({take.labels, take.values - d.cellMeans[std::size_t(c)]});
    }
    return d;
}

} // namespace bunraku::analysis
