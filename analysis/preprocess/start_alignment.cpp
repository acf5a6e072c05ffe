#include "analysis/preprocess/start_alignment.h"

#include "analysis/core/angle_channels.h"
#include "analysis/core/puppet_layout.h"
#include "analysis/core/rotation.h"
#include "analysis/skeleton/skeleton_resample.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace bunraku::analysis::preprocess {

namespace {

/// Threshold floor + fraction * (peak - floor) of an activity; NaN when the signal is flat.
double onsetThreshold(const Eigen::VectorXd& activity, double fraction, double quietFraction)
{
    if (activity.size() == 0) return std::numeric_limits<double>::quiet_NaN();
    const double peak = activity.maxCoeff();
    const double floor = noiseFloor(activity, quietFraction);
    if (!(peak > floor)) return std::numeric_limits<double>::quiet_NaN();
    return floor + fraction * (peak - floor);
}

/// Distance between two frames of a take in cm: per 6-DOF part the Euclidean norm of its
/// position change and its turn (the angle of the rotation between the two orientations, deg,
/// times cmPerDegree), summed over parts, plus the absolute change of every channel outside a
/// part (angles within +-180, times cmPerDegree). The turn is measured on rotations, so neither
/// the Euler branch, a gimbal region nor the part's frame convention changes it.
class PoseDistance {
public:
    PoseDistance(const Take& take, double cmPerDegree)
        : m_take(take), m_parts(sixDofParts(take)), m_inPart(std::size_t(take.channelCount()), false),
          m_cmPerDegree(cmPerDegree)
    {
        for (const auto& part : m_parts) {
            for (Eigen::Index c = part.firstChannel; c < part.firstChannel + 6; ++c) m_inPart[std::size_t(c)] = true;
            m_rotations.push_back(partRotations(take, part));
        }
    }

    double operator()(Eigen::Index a, Eigen::Index b) const
    {
        double sum = 0.0;
        for (std::size_t p = 0; p < m_parts.size(); ++p) {
            const Eigen::Index first = m_parts[p].firstChannel;
            const double moved = (m_take.values.row(a).segment(first, 3) - m_take.values.row(b).segment(first, 3)).norm();
            const double turned =
                m_cmPerDegree * rotationDistance(m_rotations[p][std::size_t(a)], m_rotations[p][std::size_t(b)]) * kDegreesPerRadian;
            sum += std::hypot(moved, turned);
        }
        for (Eigen::Index c = 0; c < m_take.channelCount(); ++c)
            if (!m_inPart[std::size_t(c)]) sum += std::fabs(change(a, b, c));
        return sum;
    }

private:
    static constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;

    double change(Eigen::Index a, Eigen::Index b, Eigen::Index c) const
    {
        const double d = m_take.values(a, c) - m_take.values(b, c);
        return m_take.channels[std::size_t(c)].unit == "deg" ? m_cmPerDegree * std::remainder(d, 360.0) : d;
    }

    const Take& m_take;
    std::vector<SixDofPart> m_parts;
    std::vector<std::vector<Eigen::Quaterniond>> m_rotations; // per part, per frame
    std::vector<bool> m_inPart;
    double m_cmPerDegree;
};

} // namespace

Eigen::VectorXd summedSpeed(const Take& take)
{
    const Eigen::Index frames = take.frameCount();
    Eigen::VectorXd speed = Eigen::VectorXd::Zero(frames);
    if (frames < 2) return speed;
    const auto parts = sixDofParts(take);
    for (Eigen::Index t = 1; t < frames; ++t) {
        double sum = 0.0;
        if (!parts.empty()) {
            for (const auto& part : parts)
                sum += (take.values.row(t).segment(part.firstChannel, 3) - take.values.row(t - 1).segment(part.firstChannel, 3)).norm();
        } else {
            sum = (take.values.row(t) - take.values.row(t - 1)).cwiseAbs().sum();
        }
        speed[t] = sum;
    }
    return speed;
}

Eigen::VectorXd rawActivity(const Take& take, double cmPerDegree)
{
    const Eigen::Index frames = take.frameCount();
    Eigen::VectorXd activity = Eigen::VectorXd::Zero(frames);
    if (frames < 2) return activity;
    const PoseDistance distance(take, cmPerDegree);
    for (Eigen::Index t = 1; t < frames; ++t) activity[t] = distance(t, t - 1);
    return activity;
}

Eigen::VectorXd departureSignal(const Take& take, const ActivityOptions& options)
{
    const Eigen::Index frames = take.frameCount();
    Eigen::VectorXd departure = Eigen::VectorXd::Zero(frames);
    if (frames < 2) return departure;
    const PoseDistance distance(take, options.cmPerDegree);
    for (Eigen::Index t = 1; t < frames; ++t) departure[t] = distance(t, 0);
    // Frame 0 is the start pose itself: its zero distance carries no noise and would pull the
    // smoothed start down (delaying the onset of a take that moves from the first frames).
    departure[0] = departure[1];
    return movingAverage(departure, options.smoothingFrames);
}

Eigen::VectorXd movingAverage(const Eigen::VectorXd& signal, int window)
{
    if (window <= 1 || signal.size() == 0) return signal;
    const Eigen::Index n = signal.size();
    const Eigen::Index before = (window - 1) / 2, after = window - 1 - before;
    Eigen::VectorXd out(n);
    for (Eigen::Index t = 0; t < n; ++t) {
        const Eigen::Index a = std::max<Eigen::Index>(0, t - before);
        const Eigen::Index b = std::min<Eigen::Index>(n - 1, t + after);
        out[t] = signal.segment(a, b - a + 1).mean();
    }
    return out;
}

Eigen::VectorXd activitySignal(const Take& take, const ActivityOptions& options)
{
    return movingAverage(rawActivity(take, options.cmPerDegree), options.smoothingFrames);
}

double noiseFloor(const Eigen::VectorXd& activity, double quietFraction)
{
    std::vector<double> moving;
    for (Eigen::Index t = 0; t < activity.size(); ++t)
        if (activity[t] > 0.0) moving.push_back(activity[t]);
    if (moving.empty()) return 0.0;
    const double q = std::clamp(quietFraction, 0.0, 1.0);
    const auto k = std::size_t(std::floor(q * double(moving.size() - 1)));
    std::nth_element(moving.begin(), moving.begin() + std::ptrdiff_t(k), moving.end());
    return moving[k];
}

double onsetTime(const Eigen::VectorXd& activity, double fraction, double quietFraction)
{
    const double threshold = onsetThreshold(activity, fraction, quietFraction);
    if (std::isnan(threshold)) return 0.0;
    for (Eigen::Index t = 0; t < activity.size(); ++t) {
        if (activity[t] < threshold) continue;
        if (t == 0) return 0.0;
        const double below = activity[t - 1], above = activity[t];
        return double(t - 1) + (threshold - below) / (above - below);
    }
    return 0.0;
}

double departureOnset(const Eigen::VectorXd& departure, double noise, double fraction, double band)
{
    if (departure.size() == 0) return 0.0;
    const double peak = departure.maxCoeff();
    if (!(peak > noise)) return 0.0;
    const double threshold = noise + fraction * (peak - noise);
    Eigen::Index crossing = 0;
    while (crossing < departure.size() && departure[crossing] < threshold) ++crossing;
    // Back from the crossing to the last frame still within the noise band.
    const double level = band * noise;
    Eigen::Index t = crossing;
    while (t > 0 && departure[t - 1] > level) --t;
    if (t == 0) return 0.0;
    const double below = departure[t - 1], above = departure[t];
    return double(t - 1) + std::clamp((level - below) / (above - below), 0.0, 1.0);
}

Eigen::VectorXd startEdge(const Eigen::VectorXd& departure, double ceiling)
{
    Eigen::VectorXd edge = departure.cwiseMin(ceiling);
    for (Eigen::Index t = 1; t < edge.size(); ++t) edge[t] = std::max(edge[t], edge[t - 1]);
    return edge;
}

Eigen::Index onsetFrame(const Eigen::VectorXd& speed, double fraction)
{
    const double threshold = onsetThreshold(speed, fraction, 0.1);
    if (std::isnan(threshold)) return 0;
    for (Eigen::Index t = 0; t < speed.size(); ++t)
        if (speed[t] >= threshold) return t;
    return 0;
}

int crossCorrelationShift(const Eigen::VectorXd& signal, const Eigen::VectorXd& reference, int maxShift)
{
    const Eigen::Index n = signal.size(), m = reference.size();
    if (n == 0 || m == 0) return 0;
    const Eigen::VectorXd a = signal.array() - signal.mean();
    const Eigen::VectorXd b = reference.array() - reference.mean();
    double best = -std::numeric_limits<double>::infinity();
    int bestShift = 0;
    for (int s = -maxShift; s <= maxShift; ++s) {
        // Overlap: reference t in [t0, t1), signal index t + s.
        const Eigen::Index t0 = std::max<Eigen::Index>(0, -s);
        const Eigen::Index t1 = std::min<Eigen::Index>(m, n - s);
        if (t1 - t0 < 2) continue;
        const auto x = a.segment(t0 + s, t1 - t0);
        const auto y = b.segment(t0, t1 - t0);
        const double norm = x.norm() * y.norm();
        if (!(norm > 0.0)) continue;
        const double score = x.dot(y) / norm;
        if (score > best + 1e-12 || (std::fabs(score - best) <= 1e-12 && std::abs(s) < std::abs(bestShift))) {
            best = score;
            bestShift = s;
        }
    }
    return bestShift;
}

int chooseTimeReference(const std::vector<ReferenceCandidate>& candidates, double longFraction)
{
    if (candidates.empty()) return -1;
    Eigen::Index longest = 0;
    for (const auto& candidate : candidates) longest = std::max(longest, candidate.frames);
    std::vector<int> longTakes;
    for (std::size_t i = 0; i < candidates.size(); ++i)
        if (double(candidates[i].frames) >= longFraction * double(longest)) longTakes.push_back(int(i));
    // Order by onset, ties: the longer take first, then the first candidate.
    std::stable_sort(longTakes.begin(), longTakes.end(), [&](int a, int b) {
        const auto& x = candidates[std::size_t(a)];
        const auto& y = candidates[std::size_t(b)];
        if (std::fabs(x.onset - y.onset) > 1e-9) return x.onset < y.onset;
        return x.frames > y.frames;
    });
    return longTakes[(longTakes.size() - 1) / 2];
}

void shiftTake(Take& take, int shift)
{
    const Eigen::Index frames = take.frameCount();
    if (shift == 0 || frames == 0) return;
    Eigen::MatrixXd shifted(frames, take.channelCount());
    for (Eigen::Index t = 0; t < frames; ++t) {
        const Eigen::Index source = std::clamp<Eigen::Index>(t + shift, 0, frames - 1);
        shifted.row(t) = take.values.row(source);
    }
    take.values = std::move(shifted);
    if (take.skeleton) take.skeleton = resampleSkeletalMotion(*take.skeleton, shiftedFrames(frames, frames, shift));
}

} // namespace bunraku::analysis::preprocess
