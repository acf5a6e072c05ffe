#pragma once
/// The thin adapter through which plots and tables see a take: time stamps and one channel's
/// values as Qt vectors, and the value at any time by binary search (PlotJuggler's
/// timeseries_qwt.h seam). Widgets never index a take's matrix directly.

#include "analysis/core/take.h"

#include <QVector>

#include <optional>
#include <string_view>

namespace bunraku::widgets {

/// Seconds of every frame of `take`, frame k at k / rateHz.
QVector<double> frameTimes(const analysis::Take& take);
/// The values of one column of `take` (cm or degrees), one per frame.
QVector<double> channelValues(const analysis::Take& take, Eigen::Index channel);

/// The value of `channel` at `seconds`, linearly interpolated between the two frames around it;
/// std::nullopt outside [0, duration] or for an empty take or a bad channel.
std::optional<double> valueAt(const analysis::Take& take, Eigen::Index channel, double seconds);

/// The frame nearest to `seconds`, clamped to the take.
Eigen::Index nearestFrame(const analysis::Take& take, double seconds);

/// The channel of `take` named part.dof, or std::nullopt (a B take may lack A's channel).
std::optional<Eigen::Index> findChannel(const analysis::Take& take, std::string_view part, std::string_view dof);

/// Smallest and largest value of `channel`.
struct ValueRange {
    double lower = 0.0;
    double upper = 0.0;
};
std::optional<ValueRange> channelRange(const analysis::Take& take, Eigen::Index channel);

} // namespace bunraku::widgets
