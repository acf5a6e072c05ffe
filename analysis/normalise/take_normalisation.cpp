#include "analysis/normalise/take_normalisation.h"

#include "analysis/normalise/feature_matching.h"
#include "analysis/normalise/wavelet_features.h"

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

// Everything that depends on the reference only, computed once for many samples.
struct Prepared {
    Coupling coupling;
    Eigen::VectorXd weights;
    CwtFilterBank bank;
    FeatureMatrix referenceFeatures; // frames x channels * perChannel
    Eigen::Index perChannel = 1;
};

Result<FeatureMatrix> featuresOf(const Eigen::MatrixXd& values, const Prepared& prepared, const NormaliseOptions& options,
                                 const RunControl& control)
{
    if (options.features == MatchFeatures::Amplitude)
        return FeatureMatrix(levelAligned(values, options.match.level) * prepared.weights.asDiagonal());
    return waveletFeatures(values, prepared.weights, options.match, prepared.bank, control);
}

Result<Prepared> prepare(const Take& reference, const NormaliseOptions& options, const RunControl& control)
{
    if (auto status = validateTake(reference); !status) return status.error();
    Prepared prepared;
    auto coupling = couplingFor(reference, options.coupling);
    if (!coupling) return coupling.error();
    prepared.coupling = std::move(*coupling);
    prepared.weights = channelWeights(reference.values, options.match.weighting);
    if (options.features == MatchFeatures::Wavelet) {
        auto bank = makeCwtFilterBank(options.match.scales, options.match.cwt);
        if (!bank) return bank.error();
        prepared.bank = std::move(*bank);
        prepared.perChannel = Eigen::Index(options.match.scales.size()) + (options.match.approximationWeight > 0 ? 1 : 0);
    }
    auto features = featuresOf(reference.values, prepared, options, control);
    if (!features) return features.error();
    prepared.referenceFeatures = std::move(*features);
    return prepared;
}

FeatureMatrix setColumns(const FeatureMatrix& features, const std::vector<Eigen::Index>& set, Eigen::Index perChannel)
{
    FeatureMatrix out(features.rows(), Eigen::Index(set.size()) * perChannel);
    for (std::size_t k = 0; k < set.size(); ++k)
        out.middleCols(Eigen::Index(k) * perChannel, perChannel) = features.middleCols(set[k] * perChannel, perChannel);
    return out;
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
    auto features = featuresOf(*values, prepared, options, control);
    if (!features) return features.error();

    TakeNormalisation result;
    result.coupling = prepared.coupling;
    result.normalised.channels = reference.channels;
    result.normalised.rateHz = sample.rateHz;
    result.normalised.labels = sample.labels;
    result.normalised.labels.source = "normalised to " + reference.displayName();
    result.normalised.values.resize(reference.frameCount(), reference.channelCount());
    result.correspondence.resize(reference.frameCount(), reference.channelCount());
    const FeatureMatchOptions matchOptions{options.match.tau, options.match.searchBand, options.match.path};
    for (const auto& set : prepared.coupling.sets) {
        if (control.cancelled()) return makeError(ErrorCode::Cancelled, "normalisation cancelled");
        auto match = matchFeatures(setColumns(prepared.referenceFeatures, set, prepared.perChannel),
                                   setColumns(*features, set, prepared.perChannel), matchOptions, control);
        if (!match) return match.error();
        for (Eigen::Index c : set) {
            result.correspondence.col(c) = match->correspondence;
            result.normalised.values.col(c) = applyCorrespondence(values->col(c), match->correspondence);
        }
        result.cost += match->cost;
        result.matches.push_back(std::move(*match));
    }
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
