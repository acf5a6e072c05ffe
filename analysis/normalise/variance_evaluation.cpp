#include "analysis/normalise/variance_evaluation.h"

#include "analysis/core/angle_channels.h"
#include "analysis/normalise/amplitude_matching.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace bunraku::analysis {

namespace {

// Sum over the reference's frames of the squared differences of two value matrices (frames
// missing in `values` repeat its last one).
Eigen::VectorXd summedSquares(const Eigen::MatrixXd& reference, const Eigen::MatrixXd& values)
{
    Eigen::VectorXd sum = Eigen::VectorXd::Zero(reference.cols());
    if (values.rows() == 0) return sum;
    for (Eigen::Index t = 0; t < reference.rows(); ++t) {
        const Eigen::Index frame = std::min<Eigen::Index>(t, values.rows() - 1);
        sum += (values.row(frame) - reference.row(t)).transpose().array().square().matrix();
    }
    return sum;
}

} // namespace

Eigen::VectorXd squaredDifference(const Take& reference, const Take& take)
{
    if (take.channels != reference.channels || sixDofParts(reference).empty())
        return summedSquares(reference.values, take.values);
    const RotationChart chart = meanPartChart({&reference});
    return summedSquares(rotationCoordinates(reference, chart), rotationCoordinates(take, chart));
}

Result<VarianceTable> varianceTable(const Take& reference, const std::vector<const Take*>& rawTakes,
                                    const std::vector<const Take*>& normalisedTakes)
{
    if (rawTakes.size() != normalisedTakes.size())
        return makeError(ErrorCode::InvalidArgument, "variance table: " + std::to_string(rawTakes.size()) + " raw takes but "
                                                         + std::to_string(normalisedTakes.size()) + " normalised ones");
    VarianceTable table;
    const auto takeCount = Eigen::Index(rawTakes.size());
    table.before.resize(takeCount, reference.channelCount());
    table.after.resize(takeCount, reference.channelCount());
    for (const auto& channel : reference.channels) table.channelNames.push_back(channel.name());
    const RotationChart chart = meanPartChart({&reference});
    const Eigen::MatrixXd referenceCoordinates = rotationCoordinates(reference, chart);
    for (Eigen::Index k = 0; k < takeCount; ++k) {
        const Take& raw = *rawTakes[std::size_t(k)];
        const Take& normalised = *normalisedTakes[std::size_t(k)];
        if (raw.channels != reference.channels || normalised.channels != reference.channels)
            return makeError(ErrorCode::InvalidArgument, "variance table: take " + raw.displayName() + " has other channels than the reference");
        table.takeNames.push_back(raw.displayName());
        table.before.row(k) = summedSquares(referenceCoordinates, rotationCoordinates(raw, chart)).transpose();
        table.after.row(k) = summedSquares(referenceCoordinates, rotationCoordinates(normalised, chart)).transpose();
    }
    table.totalBefore = table.before.rowwise().sum();
    table.totalAfter = table.after.rowwise().sum();
    return table;
}

Result<ReferenceSuggestion> suggestReference(const std::vector<const Take*>& givenTakes, const RunControl& control)
{
    const std::size_t count = givenTakes.size();
    if (count == 0) return makeError(ErrorCode::InvalidArgument, "reference suggestion: no takes given");
    for (const Take* take : givenTakes) {
        if (take->channels != givenTakes.front()->channels || take->frameCount() < 2)
            return makeError(ErrorCode::InvalidArgument, "reference suggestion: take " + take->displayName()
                                                             + " has other channels than the first or fewer than 2 frames");
    }
    // Angles as rotation coordinates about the takes' common mean part orientations.
    const RotationChart chart = meanPartChart(givenTakes);
    std::vector<Take> linear;
    linear.reserve(count);
    for (const Take* take : givenTakes) {
        linear.push_back(*take);
        linear.back().skeleton.reset();
        linear.back().values = rotationCoordinates(*take, chart);
    }
    std::vector<const Take*> takes;
    for (const Take& take : linear) takes.push_back(&take);
    const Take& first = *takes.front();
    // Channel scales over all takes, so cm and degrees weigh alike.
    Eigen::VectorXd deviation = Eigen::VectorXd::Zero(first.channelCount());
    {
        Eigen::Index rows = 0;
        Eigen::VectorXd mean = Eigen::VectorXd::Zero(first.channelCount());
        for (const Take* take : takes) {
            mean += take->values.colwise().sum().transpose();
            rows += take->frameCount();
        }
        mean /= double(rows);
        for (const Take* take : takes) deviation += (take->values.rowwise() - mean.transpose()).array().square().colwise().sum().matrix().transpose();
        deviation = (deviation / double(rows)).cwiseSqrt();
        for (Eigen::Index c = 0; c < deviation.size(); ++c)
            if (deviation[c] < 1e-12) deviation[c] = 1.0;
    }
    ReferenceSuggestion suggestion;
    for (const Take* take : takes) {
        // Standardised displacement from the first and from the last frame: robust to noise.
        const Eigen::Index frames = take->frameCount();
        Eigen::VectorXd fromStart(frames), fromEnd(frames);
        for (Eigen::Index t = 0; t < frames; ++t) {
            fromStart[t] = (take->values.row(t) - take->values.row(0)).transpose().cwiseQuotient(deviation).norm();
            fromEnd[t] = (take->values.row(t) - take->values.row(frames - 1)).transpose().cwiseQuotient(deviation).norm();
        }
        Eigen::Index start = 0;
        while (start + 1 < frames && !(fromStart[start] > 0.1 * fromStart.maxCoeff())) ++start;
        Eigen::Index end = frames - 1;
        while (end > 0 && !(fromEnd[end] > 0.1 * fromEnd.maxCoeff())) --end;
        suggestion.startFrame.push_back(start);
        suggestion.activeFrames.push_back(end + 1);
    }
    // Outliers: mean distance to the other takes after aligning their timing (amplitude DTW on
    // standardised values, so timing differences do not count) beyond twice the median.
    std::vector<Eigen::MatrixXd> standardised;
    for (const Take* take : takes) standardised.push_back(take->values * deviation.cwiseInverse().asDiagonal());
    // Up to kOutlierPeers + 1 takes every pair is compared; in a larger cell each take is compared
    // with kOutlierPeers others spread evenly over the cell (every step-th take after it), so
    // the work grows as n, not n^2 (issue 30: a cell of 1,000 takes).
    const std::size_t peers = std::min(count - 1, kOutlierPeers);
    std::vector<double> meanDistance(count, 0.0);
    for (std::size_t k = 0; k < count; ++k) {
        if (control.cancelled()) return makeError(ErrorCode::Cancelled, "reference suggestion: cancelled");
        for (std::size_t i = 0; i < peers; ++i) {
            // Offsets 1 .. count-1, evenly spaced: all of them when peers = count - 1.
            const std::size_t l = (k + 1 + (i * (count - 1)) / std::max<std::size_t>(peers, 1)) % count;
            if (k == l) continue;
            AmplitudeMatchOptions options;
            options.searchBand = int(std::max<Eigen::Index>(20, std::abs(takes[k]->frameCount() - takes[l]->frameCount()) + 1));
            auto aligned = matchAmplitudes(standardised[k], standardised[l], options);
            ++suggestion.alignments;
            const double distance = aligned ? aligned->cost
                                            : summedSquares(takes[k]->values, takes[l]->values).cwiseQuotient(deviation.cwiseAbs2()).sum();
            meanDistance[k] += distance / double(takes[k]->frameCount());
        }
        if (peers > 0) meanDistance[k] /= double(peers);
    }
    std::vector<double> sorted = meanDistance;
    std::sort(sorted.begin(), sorted.end());
    const double median = count % 2 ? sorted[count / 2] : 0.5 * (sorted[count / 2 - 1] + sorted[count / 2]);
    suggestion.outlier.assign(count, false);
    if (count >= 3)
        for (std::size_t k = 0; k < count; ++k) suggestion.outlier[k] = meanDistance[k] > 2.0 * median;

    int best = -1;
    for (std::size_t k = 0; k < count; ++k) {
        if (suggestion.outlier[k]) continue;
        if (best < 0 || suggestion.startFrame[k] < suggestion.startFrame[std::size_t(best)]
            || (suggestion.startFrame[k] == suggestion.startFrame[std::size_t(best)]
                && suggestion.activeFrames[k] > suggestion.activeFrames[std::size_t(best)]))
            best = int(k);
    }
    if (best < 0) best = 0;
    suggestion.takeIndex = best;
    std::ostringstream reason;
    reason << "take " << takes[std::size_t(best)]->displayName() << ": starts at frame " << suggestion.startFrame[std::size_t(best)]
           << ", active for " << suggestion.activeFrames[std::size_t(best)] << " frames";
    int outliers = 0;
    for (std::size_t k = 0; k < count; ++k) {
        if (!suggestion.outlier[k]) continue;
        reason << (outliers++ ? ", " : "; outliers: ") << takes[k]->displayName();
    }
    suggestion.reason = reason.str();
    return suggestion;
}

} // namespace bunraku::analysis
