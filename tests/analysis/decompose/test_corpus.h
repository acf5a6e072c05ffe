#pragma once
/// A constructed corpus with known components for the decomposition tests: functions
/// "bow"/"walk", emotions "calm" (neutral), "warm", "cold" (labels deliberately not the
/// thesis's), K takes, x_k = y^i + z^{ij} + eta_k with sum_k eta_k = 0 per cell.

#include "analysis/core/corpus.h"

#include <Eigen/Core>

#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace bunraku::test {

struct KnownComponents {
    analysis::Corpus corpus;
    std::vector<Eigen::MatrixXd> y;              ///< per function
    std::vector<std::vector<Eigen::MatrixXd>> z; ///< [function][emotion], neutral zero
};

inline KnownComponents knownComponentsCorpus(int frames = 60, int takes = 4, int channels = 3, double noise = 0.3)
{
    KnownComponents out;
    out.corpus.name = "constructed";
    out.corpus.neutralEmotion = "calm";
    const std::vector<std::string> functions{"bow", "walk"};
    const std::vector<std::string> emotions{"calm", "warm", "cold"};
    std::mt19937_64 rng(42);
    std::normal_distribution<double> normal(0.0, 1.0);
    std::vector<analysis::Channel> layout;
    for (int c = 0; c < channels; ++c) layout.push_back({"part", "d" + std::to_string(c), "cm"});
    for (std::size_t i = 0; i < functions.size(); ++i) {
        Eigen::MatrixXd y(frames, channels);
        for (int t = 0; t < frames; ++t)
            for (int c = 0; c < channels; ++c) y(t, c) = 10.0 * std::sin(0.1 * t * (c + 1) + double(i)) + 5.0 * c;
        out.y.push_back(y);
        out.z.emplace_back();
        for (std::size_t j = 0; j < emotions.size(); ++j) {
            Eigen::MatrixXd z = Eigen::MatrixXd::Zero(frames, channels);
            if (j > 0)
                for (int t = 0; t < frames; ++t)
                    for (int c = 0; c < channels; ++c) z(t, c) = 3.0 * double(j) * std::cos(0.07 * t + double(c + i));
            out.z.back().push_back(z);
            std::vector<Eigen::MatrixXd> etas;
            Eigen::MatrixXd sum = Eigen::MatrixXd::Zero(frames, channels);
            for (int k = 0; k < takes; ++k) {
                Eigen::MatrixXd eta(frames, channels);
                for (int t = 0; t < frames; ++t)
                    for (int c = 0; c < channels; ++c) eta(t, c) = noise * normal(rng);
                sum += eta;
                etas.push_back(eta);
            }
            for (int k = 0; k < takes; ++k) {
                analysis::Take take;
                take.rateHz = 5.0;
                take.channels = layout;
                take.values = y + z + etas[std::size_t(k)] - sum / double(takes); // zero-mean eta per cell
                take.labels = {functions[i], emotions[j], k + 1, "constructed"};
                out.corpus.takes.push_back(take);
            }
        }
    }
    return out;
}

} // namespace bunraku::test
