#include "widgets/take_series.h"

#include <qcustomplot.h>

#include <algorithm>
#include <bit>
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

SeriesEnvelope::SeriesEnvelope(std::shared_ptr<const analysis::Take> take, Eigen::Index channel)
{
    if (!take || channel < 0 || channel >= take->channelCount() || take->frameCount() == 0 || !(take->rateHz > 0.0)) return;
    m_take = std::move(take);
    m_values = m_take->values.col(channel).data();
    m_frames = m_take->frameCount();
    m_rateHz = m_take->rateHz;
    // Level 0 from the frames, each further level from the one below, up to a single bucket.
    Level level;
    level.bucket = kPyramidBase;
    const Eigen::Index buckets = (m_frames + kPyramidBase - 1) / kPyramidBase;
    level.minimum.resize(std::size_t(buckets));
    level.maximum.resize(std::size_t(buckets));
    for (Eigen::Index b = 0; b < buckets; ++b) {
        const Eigen::Index begin = b * kPyramidBase;
        const Eigen::Index end = std::min(m_frames, begin + kPyramidBase);
        const auto [low, high] = std::minmax_element(m_values + begin, m_values + end);
        level.minimum[std::size_t(b)] = *low;
        level.maximum[std::size_t(b)] = *high;
    }
    m_levels.push_back(std::move(level));
    while (m_levels.back().minimum.size() > 1) {
        const Level& below = m_levels.back();
        Level next;
        next.bucket = 2 * below.bucket;
        const std::size_t count = (below.minimum.size() + 1) / 2;
        next.minimum.resize(count);
        next.maximum.resize(count);
        for (std::size_t b = 0; b < count; ++b) {
            const std::size_t right = std::min(2 * b + 1, below.minimum.size() - 1);
            next.minimum[b] = std::min(below.minimum[2 * b], below.minimum[right]);
            next.maximum[b] = std::max(below.maximum[2 * b], below.maximum[right]);
        }
        m_levels.push_back(std::move(next));
    }
    m_range = ValueRange{m_levels.back().minimum.front(), m_levels.back().maximum.front()};
}

std::optional<ValueRange> SeriesEnvelope::range() const { return m_range; }

Eigen::Index SeriesEnvelope::bucketFrames(double frames, int columns)
{
    const double perColumn = frames / double(std::max(1, columns));
    if (!(perColumn > 2.0)) return 1;
    const double capped = std::min(perColumn, 0x1p40);
    return Eigen::Index(std::bit_floor(std::uint64_t(capped)));
}

QVector<QCPGraphData> SeriesEnvelope::sample(double lower, double upper, int columns) const
{
    QVector<QCPGraphData> points;
    if (empty()) return points;
    if (!std::isfinite(lower) || !std::isfinite(upper)) return points;
    if (!(upper > lower)) upper = lower + 1.0 / m_rateHz;
    const double last = double(m_frames - 1);
    // Frame positions of the view, clamped to the take before any conversion to an integer.
    const double from = std::clamp(lower * m_rateHz, 0.0, last);
    const double to = std::clamp(upper * m_rateHz, 0.0, last);
    const Eigen::Index bucket = bucketFrames((upper - lower) * m_rateHz, columns);
    if (bucket == 1) {
        const Eigen::Index first = std::max<Eigen::Index>(0, Eigen::Index(std::floor(from)) - 1);
        const Eigen::Index end = std::min(m_frames, Eigen::Index(std::ceil(to)) + 2);
        points.reserve(end - first);
        for (Eigen::Index f = first; f < end; ++f) points.append(QCPGraphData(double(f) / m_rateHz, m_values[f]));
        return points;
    }
    // Buckets of the pyramid's level of this size (its top level for views wider than the
    // take), or, below kPyramidBase frames, reduced from the frames in view.
    const Level* level = nullptr;
    if (bucket >= kPyramidBase) {
        const auto index = std::size_t(std::countr_zero(std::uint64_t(bucket / kPyramidBase)));
        level = &m_levels[std::min(index, m_levels.size() - 1)];
    }
    const Eigen::Index size = level ? level->bucket : bucket;
    const Eigen::Index buckets = (m_frames + size - 1) / size;
    const Eigen::Index begin = std::max<Eigen::Index>(0, Eigen::Index(from) / size - 1);
    const Eigen::Index stop = std::min(buckets, Eigen::Index(to) / size + 2);
    const bool fromLevel = level != nullptr;
    points.reserve(2 * (stop - begin));
    for (Eigen::Index b = begin; b < stop; ++b) {
        const Eigen::Index start = b * size;
        const Eigen::Index finish = std::min(m_frames, start + size);
        double low = 0.0;
        double high = 0.0;
        if (fromLevel) {
            low = level->minimum[std::size_t(b)];
            high = level->maximum[std::size_t(b)];
        } else {
            const auto [minimum, maximum] = std::minmax_element(m_values + start, m_values + finish);
            low = *minimum;
            high = *maximum;
        }
        const double middle = 0.5 * double(start + finish - 1) / m_rateHz;
        points.append(QCPGraphData(middle, low));
        points.append(QCPGraphData(middle, high));
    }
    return points;
}

} // namespace bunraku::widgets
