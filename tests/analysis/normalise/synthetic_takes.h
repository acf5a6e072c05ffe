#pragma once
/// Test fixtures: smooth puppet-like takes (24 channels of Gaussian bumps and slow drifts) and
/// time-warped copies of them with a known true correspondence.

#include "analysis/core/puppet_layout.h"
#include "analysis/core/take.h"

#include <Eigen/Core>

#include <cmath>
#include <functional>
#include <numbers>
#include <random>

namespace bunraku::test {

/// A smooth motion template: value of channel c at continuous reference time t (frames).
inline double templateValue(int channel, double t, int variant = 0)
{
    const double c = channel + 1;
    double value = 3.0 * std::sin(0.021 * c + 0.013 * t * (1 + 0.1 * (channel % 3)));
    for (int bump = 0; bump < 4; ++bump) {
        const double centre = 15.0 + 22.0 * bump + 3.0 * std::sin(c + bump);
        const double width = 3.0 + 1.5 * ((channel + bump) % 3);
        const double height = (8.0 + 4.0 * std::cos(c * 0.7 + bump)) * (bump % 2 ? -1.0 : 1.0);
        value += height * std::exp(-0.5 * (t - centre) * (t - centre) / (width * width));
    }
    if (variant == 1) value += 9.0 * std::exp(-0.5 * (t - 60.0) * (t - 60.0) / 16.0); // an extra event: an outlier
    return value;
}

/// phi: sample frame -> reference time, monotone; the sample is template(phi(u)).
using Warp = std::function<double(double)>;

inline Warp sineWarp(double amplitude, double frames, double shift = 0.0)
{
    return [=](double u) { return u + shift + amplitude * std::sin(std::numbers::pi * u / (frames - 1)); };
}

/// A 24-channel puppet take of `frames` frames sampling the template through phi, with
/// optional Gaussian noise.
inline analysis::Take warpedTake(const Warp& phi, Eigen::Index frames, int takeIndex, double noise = 0.0,
                                 int variant = 0, unsigned seed = 1)
{
    analysis::Take take;
    take.channels = analysis::puppetChannels();
    take.labels = {"greeting", "none", takeIndex, "synthetic"};
    take.values.resize(frames, analysis::kPuppetChannelCount);
    std::mt19937 random(seed);
    std::normal_distribution<double> normal(0.0, 1.0);
    for (Eigen::Index u = 0; u < frames; ++u)
        for (int c = 0; c < analysis::kPuppetChannelCount; ++c)
            take.values(u, c) = templateValue(c, phi(double(u)), variant) + noise * normal(random);
    return take;
}

/// True t_ref -> t_smp: phi^{-1}(t_ref) by bisection, clamped to the sample's frames.
inline Eigen::VectorXd trueCorrespondence(const Warp& phi, Eigen::Index referenceFrames, Eigen::Index sampleFrames)
{
    Eigen::VectorXd truth(referenceFrames);
    for (Eigen::Index t = 0; t < referenceFrames; ++t) {
        double low = -50.0, high = double(sampleFrames) + 50.0;
        for (int i = 0; i < 80; ++i) {
            const double mid = 0.5 * (low + high);
            (phi(mid) < double(t) ? low : high) = mid;
        }
        truth[t] = std::clamp(0.5 * (low + high), 0.0, double(sampleFrames - 1));
    }
    return truth;
}

} // namespace bunraku::test
