#include "analysis/normalise/noise_experiment.h"

#include "analysis/normalise/amplitude_matching.h"
#include "analysis/normalise/wavelet_matching.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace bunraku::analysis {

MethodError correspondenceError(std::string name, const Eigen::VectorXi& correspondence, const Eigen::VectorXd& trueWarp)
{
    MethodError error;
    error.name = std::move(name);
    const Eigen::ArrayXd difference = (correspondence.cast<double>() - trueWarp).array().abs();
    error.meanAbsErrorFrames = difference.size() ? difference.mean() : 0.0;
    error.maxAbsErrorFrames = difference.size() ? difference.maxCoeff() : 0.0;
    return error;
}

std::vector<double> scalesInBand(double lowFrequency, double highFrequency, const Wavelet& wavelet)
{
    std::vector<double> scales;
    if (!(lowFrequency > 0.0) || !(highFrequency >= lowFrequency)) return scales;
    const double centre = centreFrequency(wavelet);
    // scale c has pseudo-frequency centre / c: c in [centre / high, centre / low]
    const int first = std::max(1, int(std::ceil(centre / highFrequency - 1e-9)));
    const int last = int(std::floor(centre / lowFrequency + 1e-9));
    for (int c = first; c <= last; ++c) scales.push_back(double(c));
    return scales;
}

NoiseExperimentOptions thesisBandOptions(const NoiseExperimentOptions& base, const ThesisNoiseBands& bands)
{
    NoiseExperimentOptions options = base;
    const double low = bands.lowestOfReference * base.referenceFrequency;
    options.scalesBelowNoise = scalesInBand(low, bands.highestOfReference * base.referenceFrequency);
    options.scalesWithNoise = scalesInBand(low, bands.highestOfNoise * base.noiseFrequency);
    return options;
}

Result<NoiseExperimentResult> runNoiseExperiment(const NoiseExperimentOptions& options, const RunControl& control)
{
    if (options.frames < 20 || options.referenceFrequency <= 0 || options.sampleFrequency <= 0 || options.noiseFrequency <= 0)
        return makeError(ErrorCode::InvalidArgument, "noise experiment: need >= 20 frames and positive frequencies");
    if (options.scalesBelowNoise.empty()) return makeError(ErrorCode::InvalidArgument, "noise experiment: no scales below the noise");
    if (options.scalesWithNoise.empty()) return makeError(ErrorCode::InvalidArgument, "noise experiment: no scales with the noise band");
    const double twoPi = 2.0 * std::numbers::pi;
    NoiseExperimentResult result;
    result.reference.resize(options.frames);
    result.sample.resize(options.frames);
    result.cleanSample.resize(options.frames);
    result.trueWarp.resize(options.frames);
    for (int t = 0; t < options.frames; ++t) {
        result.reference[t] = std::sin(twoPi * options.referenceFrequency * t);
        result.cleanSample[t] = std::sin(twoPi * options.sampleFrequency * t + options.phaseShiftRadians);
        result.sample[t] = result.cleanSample[t] + options.noiseAmplitude * std::sin(twoPi * options.noiseFrequency * t);
        // The sample reaches the reference's phase 2 pi f t at u: 2 pi f_s u + shift = 2 pi f t.
        const double phase = twoPi * options.referenceFrequency * t;
        result.trueWarp[t] = std::clamp((phase - options.phaseShiftRadians) / (twoPi * options.sampleFrequency), 0.0,
                                        double(options.frames - 1));
    }
    const Eigen::MatrixXd reference = result.reference;
    const Eigen::MatrixXd sample = result.sample;

    AmplitudeMatchOptions amplitude;
    amplitude.tau = options.tau;
    amplitude.searchBand = options.searchBand;
    amplitude.path = options.path;
    amplitude.level = LevelAlignment::None; // the sines' levels are part of the experiment
    auto byAmplitude = matchAmplitudes(reference, sample, amplitude, control);
    if (!byAmplitude) return byAmplitude.error();
    const auto scored = [&](std::string name, const Eigen::VectorXi& correspondence) {
        MethodError error = correspondenceError(std::move(name), correspondence, result.trueWarp);
        double sum = 0.0;
        for (Eigen::Index t = 0; t < correspondence.size(); ++t) {
            const double difference = result.cleanSample[correspondence[t]] - result.reference[t];
            sum += difference * difference;
        }
        error.shapeRms = correspondence.size() ? std::sqrt(sum / double(correspondence.size())) : 0.0;
        return error;
    };
    result.methods.push_back(scored("amplitude-dp", byAmplitude->correspondence));

    MatchOptions wavelet;
    wavelet.tau = options.tau;
    wavelet.searchBand = options.searchBand;
    wavelet.path = options.path;
    wavelet.level = LevelAlignment::None;
    wavelet.scales = options.scalesBelowNoise;
    auto belowNoise = matchChannels(reference, sample, wavelet, control);
    if (!belowNoise) return belowNoise.error();
    result.methods.push_back(scored("wavelet-below-noise", belowNoise->correspondence));
    result.methods.back().scales = wavelet.scales;

    wavelet.scales = options.scalesWithNoise;
    auto withNoise = matchChannels(reference, sample, wavelet, control);
    if (!withNoise) return withNoise.error();
    result.methods.push_back(scored("wavelet-with-noise-band", withNoise->correspondence));
    result.methods.back().scales = wavelet.scales;
    return result;
}

} // namespace bunraku::analysis
