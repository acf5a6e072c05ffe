#include "analysis/skeleton/take_resample.h"

#include "analysis/core/angle_channels.h"
#include "analysis/core/rotation.h"
#include "analysis/skeleton/skeleton_resample.h"

#include <algorithm>
#include <cmath>

namespace bunraku::analysis {

Eigen::VectorXd evenlySpacedFrames(Eigen::Index sourceFrames, Eigen::Index frames)
{
    if (frames <= 1) return Eigen::VectorXd::Zero(std::max<Eigen::Index>(frames, 0));
    return Eigen::VectorXd::LinSpaced(frames, 0.0, double(std::max<Eigen::Index>(sourceFrames - 1, 0)));
}

Take resampleTake(const Take& take, const Eigen::VectorXd& at)
{
    Take out;
    out.rateHz = take.rateHz;
    out.channels = take.channels;
    out.labels = take.labels;
    out.labels.source = (take.labels.source.empty() ? take.displayName() : take.labels.source) + " resampled";
    const Eigen::Index frames = at.size();
    out.values.resize(frames, take.channelCount());
    if (take.frameCount() == 0) return out;
    const Eigen::Index last = take.frameCount() - 1;
    const auto count = static_cast<std::size_t>(frames);
    std::vector<Eigen::Index> below(count), above(count);
    std::vector<double> weight(count);
    for (Eigen::Index u = 0; u < frames; ++u) {
        const double s = std::clamp(std::isfinite(at[u]) ? at[u] : 0.0, 0.0, double(last));
        below[std::size_t(u)] = std::min<Eigen::Index>(Eigen::Index(std::floor(s)), last);
        above[std::size_t(u)] = std::min<Eigen::Index>(below[std::size_t(u)] + 1, last);
        weight[std::size_t(u)] = s - double(below[std::size_t(u)]);
        const double w = weight[std::size_t(u)];
        out.values.row(u) = w > 0.0 ? Eigen::RowVectorXd((1.0 - w) * take.values.row(below[std::size_t(u)]) +
                                                         w * take.values.row(above[std::size_t(u)]))
                                    : Eigen::RowVectorXd(take.values.row(below[std::size_t(u)]));
    }
    for (const SixDofPart& part : sixDofParts(take)) {
        const Eigen::Index c = part.firstChannel;
        const std::vector<Eigen::Quaterniond> rotations = partRotations(take, part);
        for (Eigen::Index u = 0; u < frames; ++u) {
            const double w = weight[std::size_t(u)];
            const auto k = std::size_t(below[std::size_t(u)]);
            // whole frames keep their numbers; between frames the slerp, nearest the previous frame
            YawPitchRoll angles{take.values(Eigen::Index(k), c + 3), take.values(Eigen::Index(k), c + 4),
                                take.values(Eigen::Index(k), c + 5)};
            if (w > 0.0) {
                const Eigen::Quaterniond q = slerpShortest(rotations[k], rotations[std::size_t(above[std::size_t(u)])], w);
                angles = nearestEquivalent(yawPitchRollFromRotation(q), angles);
            }
            if (u > 0)
                angles = nearestEquivalent(angles, YawPitchRoll{out.values(u - 1, c + 3), out.values(u - 1, c + 4), out.values(u - 1, c + 5)});
            out.values(u, c + 3) = angles.yaw;
            out.values(u, c + 4) = angles.pitch;
            out.values(u, c + 5) = angles.roll;
        }
    }
    if (take.skeleton) out.skeleton = resampleSkeletalMotion(*take.skeleton, at);
    return out;
}

} // namespace bunraku::analysis
