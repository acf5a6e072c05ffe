#include "widgets/take_series.h"

#include <algorithm>
#include <cmath>

namespace bunraku::widgets {

QVector<double> frameTimes(const analysis::Take& take)
{
    QVector<double> times(take.frameCount());
    for (Eigen::Index k = 0; k < take.frameCount(); ++k) times[k] = take.timeOfFrame(k);
    return times;
}

QVector<double> channelValues(const analysis::Take& take, Eigen::Index channel)
{
    if (channel < 0 || channel >= take.channelCount()) return {};
    QVector<double> values(take.frameCount());
    for (Eigen::Index k = 0; k < take.frameCount(); ++k) values[k] = take.values(k, channel);
    return values;
}

std::optional<double> valueAt(const analysis::Take& take, Eigen::Index channel, double seconds)
{
    const Eigen::Index frames = take.frameCount();
    if (frames == 0 || channel < 0 || channel >= take.channelCount() || take.rateHz <= 0.0) return std::nullopt;
    // Frames are uniformly spaced, so the binary search over time stamps reduces to a division;
    // the tolerance keeps the last frame reachable despite rounding.
    const double position = seconds * take.rateHz;
    if (!std::isfinite(position) || position < -1e-9 || position > double(frames - 1) + 1e-9) return std::nullopt;
    const double clamped = std::clamp(position, 0.0, double(frames - 1));
    const auto lower = Eigen::Index(std::floor(clamped));
    const Eigen::Index upper = std::min(lower + 1, frames - 1);
    const double fraction = clamped - double(lower);
    return (1.0 - fraction) * take.values(lower, channel) + fraction * take.values(upper, channel);
}

Eigen::Index nearestFrame(const analysis::Take& take, double seconds)
{
    if (take.frameCount() == 0) return 0;
    const auto frame = Eigen::Index(std::llround(std::max(0.0, seconds) * take.rateHz));
    return std::clamp<Eigen::Index>(frame, 0, take.frameCount() - 1);
}

std::optional<Eigen::Index> findChannel(const analysis::Take& take, std::string_view part, std::string_view dof)
{
    return take.channelIndex(part, dof);
}

std::optional<ValueRange> channelRange(const analysis::Take& take, Eigen::Index channel)
{
    if (channel < 0 || channel >= take.channelCount() || take.frameCount() == 0) return std::nullopt;
    const auto column = take.values.col(channel);
    return ValueRange{column.minCoeff(), column.maxCoeff()};
}

} // namespace bunraku::widgets
