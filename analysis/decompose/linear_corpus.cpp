#include "analysis/decompose/linear_corpus.h"

#include <algorithm>

namespace bunraku::analysis {

int functionIndex(const LinearCorpus& linear, const std::string& function)
{
    const auto it = std::find(linear.functions.begin(), linear.functions.end(), function);
    return it == linear.functions.end() ? -1 : int(it - linear.functions.begin());
}

LinearCorpus lineariseCorpus(const Corpus& corpus)
{
    LinearCorpus linear;
    linear.corpus = corpus;
    linear.functions = corpus.functions();
    for (const auto& function : linear.functions) {
        std::vector<const Take*> takes;
        for (const Take& take : corpus.takes)
            if (take.labels.function == function) takes.push_back(&take);
        linear.charts.push_back(meanPartChart(takes, ChartTime::PerFrame));
        const auto neutral = corpus.cell(function, corpus.neutralEmotion);
        const Take& first = neutral.empty() ? *takes.front() : *neutral.front();
        linear.angleBranches.push_back(first.values.row(0));
    }
    for (Take& take : linear.corpus.takes) {
        const int f = functionIndex(linear, take.labels.function);
        take.values = rotationCoordinates(take, linear.charts[std::size_t(f)]);
        take.skeleton.reset();
    }

    // The skeleton, when every take carries one on the same joints.
    bool skeletons = !corpus.takes.empty();
    for (const Take& take : corpus.takes)
        skeletons = skeletons && take.skeleton && compatibleMotions(*corpus.takes.front().skeleton, *take.skeleton);
    if (!skeletons) return linear;
    for (const auto& function : linear.functions) {
        std::vector<std::shared_ptr<const SkeletalMotion>> motions;
        for (const Take& take : corpus.takes)
            if (take.labels.function == function) motions.push_back(take.skeleton);
        auto chart = meanSkeletonChart(motions);
        if (!chart) {
            linear.skeletonCharts.clear();
            return linear;
        }
        // One set of translating joints for the whole corpus, so every function's coordinates line up.
        linear.skeletonCharts.push_back(std::move(chart).value());
    }
    std::vector<const SkeletalMotion*> all;
    for (const Take& take : corpus.takes) all.push_back(take.skeleton.get());
    const std::vector<int> translating = translatingJoints(all);
    for (auto& chart : linear.skeletonCharts) chart.translating = translating;
    for (const Take& take : corpus.takes) {
        const int f = functionIndex(linear, take.labels.function);
        linear.skeletonCoordinates.push_back(skeletonCoordinates(*take.skeleton, linear.skeletonCharts[std::size_t(f)]));
    }
    return linear;
}

} // namespace bunraku::analysis
