#include "analysis/normalise/take_normalisation.h"

#include "analysis/normalise/feature_matching.h"
#include "analysis/normalise/wavelet_features.h"
#include "analysis/skeleton/skeleton_resample.h"

#include <algorithm>
#include <cmath>

#include <optional>
#include <string>

namespace bunraku::analysis {

namespace {

// The sample's values in the reference's channel order.
Result<Eigen::MatrixXd> alignedChannels(const Take& reference, const Take& sample)
{
    if (sample.channels == reference.channels) return sample.values;
    Eigen::MatrixXd values(sample.frameCount(), reference.channelCount());
    for (std::size_t c = 0; c < reference.channels.size(); ++c) {
        const auto index = sample.channelIndex(reference.channels[c].name());
        if (!index)
            return makeError(ErrorCode::NotFound, "normalise: take " + sample.displayName() + " has no channel '"
                                                      + reference.channels[c].name() + "' of the reference");
        values.col(Eigen::Index(c)) = sample.values.col(*index);
    }
    return values;
}

// Features of takes up to this size (frames x channels x features per channel x 8 bytes) are
// computed for all channels at once and the reference's are kept for every sample; longer takes
// are transformed one coupling set at a time, so memory stays at one set's features (and the
// transform's output is matched while it is still fresh).
constexpr double kWholeTakeFeatureBytes = 64e6;

// Everything that depends on the reference only, computed once for many samples.
struct Prepared {
    Coupling coupling;
    RotationChart chart;                  // the reference's mean part orientations
    Eigen::MatrixXd referenceCoordinates; // the reference in rotation coordinates
    Eigen::VectorXd weights;
    CwtFilterBank bank;
    std::optional<FeatureSeries> referenceFeatures; // frames x channels * perChannel, for short references
    Eigen::Index perChannel = 1;
};

bool wholeTake(Eigen::Index frames, Eigen::Index channels, Eigen::Index perChannel)
{
    return double(frames) * double(channels) * double(perChannel) * 8.0 <= kWholeTakeFeatureBytes;
}

Result<FeatureSeries> featuresOf(const Eigen::MatrixXd& values, const Eigen::VectorXd& weights, const Prepared& prepared,
                                 const NormaliseOptions& options, const RunControl& control)
{
    if (options.features == MatchFeatures::Amplitude)
        return FeatureSeries(levelAligned(values, options.match.level) * weights.asDiagonal());
    return waveletFeatures(values, weights, options.match, prepared.bank, control);
}

// The features of one coupling set's channels (columns in the set's order), into `out`.
Status setFeatures(const Eigen::MatrixXd& values, const std::vector<Eigen::Index>& set, const Prepared& prepared,
                   const NormaliseOptions& options, FeatureSeries& out, const RunControl& control)
{
    Eigen::MatrixXd channels(values.rows(), Eigen::Index(set.size()));
    Eigen::VectorXd weights(Eigen::Index(set.size()));
    for (std::size_t k = 0; k < set.size(); ++k) {
        channels.col(Eigen::Index(k)) = values.col(set[k]);
        weights[Eigen::Index(k)] = prepared.weights[set[k]];
    }
    if (options.features == MatchFeatures::Amplitude) {
        out = levelAligned(channels, options.match.level) * weights.asDiagonal();
        return okStatus();
    }
    return waveletFeaturesInto(channels, weights, options.match, prepared.bank, out, control);
}

Result<Prepared> prepare(const Take& reference, const NormaliseOptions& options, const RunControl& control)
{
    if (auto status = validateTake(reference); !status) return status.error();
    Prepared prepared;
    auto coupling = couplingFor(reference, options.coupling);
    if (!coupling) return coupling.error();
    prepared.coupling = std::move(*coupling);
    prepared.chart = meanPartChart({&reference}, ChartTime::Constant);
    prepared.referenceCoordinates = rotationCoordinates(reference, prepared.chart);
    prepared.weights = channelWeights(prepared.referenceCoordinates, options.match.weighting);
    if (options.features == MatchFeatures::Wavelet) {
        auto bank = makeCwtFilterBank(options.match.scales, options.match.cwt);
        if (!bank) return bank.error();
        prepared.bank = std::move(*bank);
        prepared.perChannel = Eigen::Index(options.match.scales.size()) + (options.match.approximationWeight > 0 ? 1 : 0);
    }
    if (wholeTake(reference.frameCount(), reference.channelCount(), prepared.perChannel)) {
        auto features = featuresOf(prepared.referenceCoordinates, prepared.weights, prepared, options, control);
        if (!features) return features.error();
        prepared.referenceFeatures = std::move(*features);
    }
    return prepared;
}

/// The largest difference (deg or cm) between a value and its round trip through rotation
/// coordinates that is rounding; a branch change or any resampling is far larger.
constexpr double kRoundTripTolerance = 1e-9;

/// Whether every channel shows sample frame f at reference frame f, over as many frames.
bool isIdentity(const Eigen::MatrixXi& correspondence, Eigen::Index sampleFrames)
{
    if (correspondence.rows() != sampleFrames) return false;
    for (Eigen::Index c = 0; c < correspondence.cols(); ++c)
        for (Eigen::Index f = 0; f < correspondence.rows(); ++f)
            if (correspondence(f, c) != f) return false;
    return true;
}

// The feature columns of one coupling set's channels.
std::vector<Eigen::Index> setColumns(const std::vector<Eigen::Index>& set, Eigen::Index perChannel)
{
    std::vector<Eigen::Index> columns;
    columns.reserve(set.size() * std::size_t(perChannel));
    for (Eigen::Index channel : set)
        for (Eigen::Index k = 0; k < perChannel; ++k) columns.push_back(channel * perChannel + k);
    return columns;
}

Result<TakeNormalisation> normalisePrepared(const Take& reference, const Take& sample, const Prepared& prepared,
                                            const NormaliseOptions& options, const RunControl& control)
{
    if (auto status = validateTake(sample); !status) return status.error();
    auto values = alignedChannels(reference, sample);
    if (!values) return values.error();
    if (options.features == MatchFeatures::Wavelet) {
        if (auto status = validateMatchOptions(options.match, reference.frameCount(), sample.frameCount()); !status)
            return status.error();
    }
    // The sample in rotation coordinates about the reference's chart, so the matching sees the
    // orientations and not the Euler branch they happen to be written on.
    Take aligned;
    aligned.channels = reference.channels;
    aligned.values = *values;
    const Eigen::MatrixXd coordinates = rotationCoordinates(aligned, prepared.chart);
    // Takes of other lengths: a global time scale first (TimeScaling), then the local matching.
    const Eigen::Index sampleFrames = sample.frameCount();
    const double scale = globalTimeScale(options.match, reference.frameCount(), sampleFrames);
    const Eigen::MatrixXd matched = scale == 1.0 ? coordinates : scaledInTime(coordinates, scale, reference.frameCount());
    // Short takes: every channel's features at once; long ones: a coupling set at a time.
    std::optional<FeatureSeries> sampleFeatures;
    if (prepared.referenceFeatures && wholeTake(matched.rows(), matched.cols(), prepared.perChannel)) {
        auto features = featuresOf(matched, prepared.weights, prepared, options, control);
        if (!features) return features.error();
        sampleFeatures = std::move(*features);
    }

    TakeNormalisation result;
    result.coupling = prepared.coupling;
    result.chart = prepared.chart;
    result.normalised.channels = reference.channels;
    result.normalised.rateHz = sample.rateHz;
    result.normalised.labels = sample.labels;
    result.normalised.labels.source = "normalised to " + reference.displayName();
    result.coordinates.resize(reference.frameCount(), reference.channelCount());
    result.correspondence.resize(reference.frameCount(), reference.channelCount());
    const FeatureMatchOptions matchOptions{options.match.tau, options.match.searchBand, options.match.path};
    FeatureSeries referenceSet, sampleSet; // reused from set to set
    for (const auto& set : prepared.coupling.sets) {
        if (control.cancelled()) return makeError(ErrorCode::Cancelled, "normalisation cancelled");
        auto matchSet = [&]() -> Result<MatchResult> {
            if (sampleFeatures)
                return matchFeatures(*prepared.referenceFeatures, *sampleFeatures, setColumns(set, prepared.perChannel),
                                     matchOptions, control);
            if (auto status = setFeatures(prepared.referenceCoordinates, set, prepared, options, referenceSet, control); !status)
                return status.error();
            if (auto status = setFeatures(matched, set, prepared, options, sampleSet, control); !status) return status.error();
            return matchFeatures(referenceSet, sampleSet, matchOptions, control);
        };
        auto match = matchSet();
        if (!match) return match.error();
        MatchResult unscaled = unscaledMatch(std::move(match).value(), scale, sampleFrames);
        for (Eigen::Index c : set) {
            result.correspondence.col(c) = unscaled.correspondence;
            result.coordinates.col(c) = applyCorrespondence(coordinates.col(c), unscaled.correspondence);
        }
        result.cost += unscaled.cost;
        result.matches.push_back(std::move(unscaled));
    }
    // Back to Euler angles, continuous and starting on the branch of the sample frame shown first.
    result.bodyTime = result.correspondence.cast<double>().rowwise().mean();
    const Eigen::Index first = std::clamp<Eigen::Index>(Eigen::Index(std::lround(result.bodyTime[0])), 0, sampleFrames - 1);
    result.normalised.values =
        eulerFromRotationCoordinates(aligned, result.coordinates, prepared.chart, Eigen::RowVectorXd(values->row(first)));
    if (isIdentity(result.correspondence, sampleFrames) &&
        (result.normalised.values - *values).cwiseAbs().maxCoeff() <= kRoundTripTolerance) {
        // Every frame kept (the reference against itself): the sample's own numbers, not their
        // round trip through rotation coordinates (about 1e-13 deg off), so its variance is 0.
        result.normalised.values = *values;
        result.normalised.skeleton = sample.skeleton;
        return result;
    }
    if (sample.skeleton) result.normalised.skeleton = resampleSkeletalMotion(*sample.skeleton, result.bodyTime);
    return result;
}

} // namespace

Result<TakeNormalisation> normaliseTake(const Take& reference, const Take& sample, const NormaliseOptions& options,
                                        const RunControl& control)
{
    auto prepared = prepare(reference, options, control);
    if (!prepared) return prepared.error();
    return normalisePrepared(reference, sample, *prepared, options, control);
}

Result<std::vector<TakeNormalisation>> normaliseTakes(const Take& reference, const std::vector<const Take*>& takes,
                                                      const NormaliseOptions& options, const RunControl& control)
{
    auto prepared = prepare(reference, options, control);
    if (!prepared) return prepared.error();
    std::vector<TakeNormalisation> results;
    for (std::size_t k = 0; k < takes.size(); ++k) {
        auto one = normalisePrepared(reference, *takes[k], *prepared, options, RunControl{control.stop, {}});
        if (!one) return one.error();
        results.push_back(std::move(*one));
        control.report(double(k + 1) / double(takes.size()));
    }
    return results;
}

} // namespace bunraku::analysis
