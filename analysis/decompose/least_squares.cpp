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

int cellTakeCount(const Decomposition& decomposition, const std::string& function, const std::string& emotion)
{
    return int(std::count_if(decomposition.fluctuations.begin(), decomposition.fluctuations.end(), [&](const FluctuationComponent& eta) {
        return eta.labels.function == function && eta.labels.emotion == emotion;
    }));
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

Decomposition decomposeLinear(const LinearCorpus& linear)
{
    const Corpus& corpus = linear.corpus;
    Decomposition d;
    d.rateHz = corpus.rateHz;
    d.channels = corpus.takes.front().channels;
    d.neutralEmotion = corpus.neutralEmotion;
    d.charts = linear.charts;
    d.angleBranches = linear.angleBranches;
    const auto emotions = corpus.emotions();
    auto cellMean = [](const std::vector<const Take*>& takes) {
        Eigen::MatrixXd mean = Eigen::MatrixXd::Zero(takes.front()->frameCount(), takes.front()->channelCount());
        for (const Take* take : takes) mean += take->values;
        return Eigen::MatrixXd(mean / double(takes.size()));
    };
    const bool skeletal = !linear.skeletonCoordinates.empty();
    // The mean of the skeleton coordinates of a cell's takes.
    auto skeletonMean = [&](const std::vector<const Take*>& takes) {
        const Eigen::MatrixXd& first = linear.skeletonCoordinates.front();
        Eigen::MatrixXd mean = Eigen::MatrixXd::Zero(first.rows(), first.cols());
        for (const Take* take : takes) mean += linear.skeletonCoordinates[std::size_t(take - corpus.takes.data())];
        return Eigen::MatrixXd(mean / double(takes.size()));
    };
    if (skeletal) d.skeleton = SkeletalComponents{linear.skeletonCharts, {}, {}};
    for (const auto& function : linear.functions) {
        const auto neutral = corpus.cell(function, corpus.neutralEmotion);
        const Eigen::MatrixXd y = cellMean(neutral); // eq. 4.4-4.5
        d.functions.push_back({function, y});
        const Eigen::MatrixXd ySkeleton = skeletal ? skeletonMean(neutral) : Eigen::MatrixXd();
        if (skeletal) d.skeleton->functions.push_back(ySkeleton);
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
            if (skeletal) d.skeleton->emotions.push_back(skeletonMean(takes) - ySkeleton);
        }
    }
    for (const auto& take : corpus.takes) {
        const int c = d.cellIndex(take.labels.function, take.labels.emotion);
        d.fluctuations.push_back({take.labels, take.values - d.cellMeans[std::size_t(c)]});
    }
    return d;
}

Result<Decomposition> decomposeLeastSquares(const Corpus& corpus)
{
    if (auto status = checkDecomposable(corpus); !status) return status.error();
    return decomposeLinear(lineariseCorpus(corpus));
}

} // namespace bunraku::analysis
