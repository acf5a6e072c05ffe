#pragma once
/// Benchmark inputs: long smooth 24-channel puppet takes and a warped copy (the warp drifts by
/// up to +-0.8 T_cmp), deterministic.

#include "analysis/core/puppet_layout.h"
#include "analysis/core/take.h"

#include <cmath>
#include <random>

namespace bunraku::bench {

/// Channel c at continuous time t: a few slow sines with per-channel phases plus bumps.
inline double longMotion(int channel, double t)
{
    const double c = channel + 1;
    return 10.0 * std::sin(0.031 * t + c) + 6.0 * std::sin(0.0113 * t + 2.0 * c) + 3.0 * std::sin(0.173 * t + 0.5 * c)
           + 2.0 * std::sin(0.0047 * t * (1.0 + 0.01 * c));
}

/// frames x 24; phi maps sample frames to motion time: u + amplitude * sin(2 pi u / period).
inline analysis::Take longTake(Eigen::Index frames, double warpAmplitude, double warpPeriod, unsigned seed)
{
    analysis::Take take;
    take.channels = analysis::puppetChannels();
    take.labels = {"bench", "none", int(seed), "bench"};
    take.values.resize(frames, analysis::kPuppetChannelCount);
    std::mt19937 random(seed);
    std::normal_distribution<double> noise(0.0, 0.05);
    for (Eigen::Index u = 0; u < frames; ++u) {
        const double t = double(u) + warpAmplitude * std::sin(2.0 * 3.141592653589793 * double(u) / warpPeriod);
        for (int c = 0; c < analysis::kPuppetChannelCount; ++c) take.values(u, c) = longMotion(c, t) + noise(random);
    }
    return take;
}

} // namespace bunraku::bench
