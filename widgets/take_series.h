#pragma once
/// The thin adapter through which plots and tables see a take: time stamps and one channel's
/// values as Qt vectors, the value at any time by binary search (PlotJuggler's
/// timeseries_qwt.h seam), and a channel's min/max envelope for drawing long takes at any zoom
/// (SeriesEnvelope). Widgets never index a take's matrix directly.

#include "analysis/core/take.h"

#include <QVector>

#include <memory>
#include <optional>
#include <string_view>
#include <vector>

class QCPGraphData;

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

/// One channel of a take prepared for drawing at any zoom: min/max decimation. A graph never
/// needs more than a few points per pixel column, so for a view of `columns` pixel columns
/// sample() returns every frame while there are at most 2 frames a column, and otherwise, per
/// bucket of 2^k consecutive frames (k the largest with at least one bucket a column, so 1 to 2
/// buckets a column), the bucket's smallest and largest value at its middle time: at most
/// 4 * columns + 6 points (the buckets cut by the view's ends and one beyond each end) whatever
/// the take's length, and the curve drawn through them reaches exactly the extremes of the
/// frames in view. Buckets of 16 frames and more come from a pyramid built once (each level's
/// min and max from the level below: a quarter of the channel's size in all); smaller ones from
/// the frames in view. A view costs O(columns) above 16 frames a column, O(frames in view)
/// below, never O(take). The take is shared, not copied.
class SeriesEnvelope {
public:
    /// Frames per bucket of the pyramid's first level.
    static constexpr Eigen::Index kPyramidBase = 16;

    SeriesEnvelope() = default;
    /// An empty envelope for a missing take or channel.
    SeriesEnvelope(std::shared_ptr<const analysis::Take> take, Eigen::Index channel);

    bool empty() const { return m_frames == 0; }
    Eigen::Index frameCount() const { return m_frames; }
    /// Smallest and largest value of the whole channel (from the pyramid: O(1)).
    std::optional<ValueRange> range() const;
    /// Frames per bucket for `frames` frames in view across `columns` columns: 1 (every frame)
    /// up to 2 frames a column, else the largest power of two not above frames / columns.
    static Eigen::Index bucketFrames(double frames, int columns);
    /// The points to draw for [lower, upper] seconds across `columns` pixel columns (at least 1),
    /// sorted by time, with one bucket (or frame) beyond each end so the line leaves the view.
    QVector<QCPGraphData> sample(double lower, double upper, int columns) const;

private:
    /// Level k holds buckets of kPyramidBase * 2^k frames: mins and maxes, bucket b covering
    /// frames [b * size, (b + 1) * size) (the last one shorter).
    struct Level {
        Eigen::Index bucket = 0;
        std::vector<double> minimum;
        std::vector<double> maximum;
    };

    std::shared_ptr<const analysis::Take> m_take;
    const double* m_values = nullptr; ///< the channel's column (contiguous)
    Eigen::Index m_frames = 0;
    double m_rateHz = 1.0;
    std::optional<ValueRange> m_range;
    std::vector<Level> m_levels;
};

} // namespace bunraku::widgets
