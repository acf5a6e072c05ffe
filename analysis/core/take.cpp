#include "analysis/core/take.h"

#include "analysis/core/skeleton.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace bunraku::analysis {

namespace {

std::string numberText(double value)
{
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

} // namespace

std::optional<Eigen::Index> Take::channelIndex(std::string_view part, std::string_view dof) const
{
    for (std::size_t i = 0; i < channels.size(); ++i)
        if (channels[i].part == part && channels[i].dof == dof) return Eigen::Index(i);
    return std::nullopt;
}

std::optional<Eigen::Index> Take::channelIndex(std::string_view name) const
{
    const auto dot = name.rfind('.');
    if (dot == std::string_view::npos) return std::nullopt;
    return channelIndex(name.substr(0, dot), name.substr(dot + 1));
}

std::vector<std::string> Take::parts() const
{
    std::vector<std::string> result;
    for (const auto& c : channels)
        if (std::find(result.begin(), result.end(), c.part) == result.end()) result.push_back(c.part);
    return result;
}

std::string Take::displayName() const
{
    if (!labels.function.empty())
        return labels.function + "/" + labels.emotion + "/" + std::to_string(labels.takeIndex);
    return labels.source.empty() ? std::string("take") : labels.source;
}

bool plausibleRate(double hz) { return std::isfinite(hz) && hz > 0.0 && hz <= kMaxRateHz; }

std::string rateExpectation() { return "expected a sample rate in (0, 1000000] Hz"; }

double valueLimit(std::string_view unit)
{
    if (unit == "cm") return 1e7;
    if (unit == "deg") return 1e9;
    return 1e12;
}

Status validateTake(const Take& take)
{
    const std::string name = take.displayName();
    if (!plausibleRate(take.rateHz))
        return makeError(ErrorCode::InvalidArgument, name + ": sample rate " + std::to_string(take.rateHz) + " Hz: " + rateExpectation());
    if (take.values.rows() < 1)
        return makeError(ErrorCode::InvalidArgument, name + ": a take needs at least one frame");
    if (std::size_t(take.values.cols()) != take.channels.size())
        return makeError(ErrorCode::InvalidArgument,
                         name + ": " + std::to_string(take.values.cols()) + " value columns but " +
                             std::to_string(take.channels.size()) + " channel names");
    for (Eigen::Index f = 0; f < take.values.rows(); ++f)
        for (Eigen::Index c = 0; c < take.values.cols(); ++c)
            if (!std::isfinite(take.values(f, c)))
                return makeError(ErrorCode::Numerical, name + ": non-finite value at frame " + std::to_string(f) +
                                                           ", channel " + take.channels[std::size_t(c)].name());
    for (Eigen::Index c = 0; c < take.values.cols(); ++c) {
        const Channel& channel = take.channels[std::size_t(c)];
        const double limit = valueLimit(channel.unit);
        for (Eigen::Index f = 0; f < take.values.rows(); ++f)
            if (std::fabs(take.values(f, c)) > limit)
                return makeError(ErrorCode::Numerical, name + ": value " + numberText(take.values(f, c)) + " at frame " +
                                                           std::to_string(f) + ", channel " + channel.name() +
                                                           " is beyond +-" + numberText(limit) +
                                                           (channel.unit.empty() ? "" : " " + channel.unit));
    }
    if (take.skeleton) {
        if (auto ok = validateSkeletalMotion(*take.skeleton); !ok)
            return makeError(ok.error().code, name + ": " + ok.error().message);
        if (take.skeleton->frameCount() != take.values.rows())
            return makeError(ErrorCode::InvalidArgument, name + ": the skeleton has " + std::to_string(take.skeleton->frameCount()) +
                                                             " frames but the take " + std::to_string(take.values.rows()));
    }
    return okStatus();
}

} // namespace bunraku::analysis
