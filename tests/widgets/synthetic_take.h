#pragma once
/// Small analytic takes for widget tests: channel c of frame k is a known function of (k, c).

#include "analysis/core/puppet_layout.h"
#include "analysis/core/take.h"

#include <cmath>
#include <memory>

namespace bunraku::test {

/// The value every synthetic take stores: sin(0.1 k + c) * (c + 1) + offset.
inline double syntheticValue(Eigen::Index frame, Eigen::Index channel, double offset)
{
    return std::sin(0.1 * double(frame) + double(channel)) * double(channel + 1) + offset;
}

/// A 24-channel puppet take of `frames` frames at 5 Hz.
inline std::shared_ptr<analysis::Take> syntheticPuppetTake(Eigen::Index frames, double offset = 0.0)
{
    auto take = std::make_shared<analysis::Take>();
    take->rateHz = 5.0;
    take->channels = analysis::puppetChannels();
    take->values.resize(frames, analysis::kPuppetChannelCount);
    for (Eigen::Index k = 0; k < frames; ++k)
        for (Eigen::Index c = 0; c < analysis::kPuppetChannelCount; ++c) take->values(k, c) = syntheticValue(k, c, offset);
    take->labels = {"greeting", "none", 1, "synthetic"};
    return take;
}

} // namespace bunraku::test
