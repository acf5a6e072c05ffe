#include "analysis/normalise/truth_experiment.h"

#include "analysis/core/puppet_layout.h"
#include "analysis/normalise/variance_evaluation.h"
#include "analysis/preprocess/preprocess.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace bunraku::analysis {

namespace {

struct Accumulator {
    TruthMethodResult result;
    double errorSum = 0;
    double errorCount = 0;
    double framesWithin = 0;
    double framesTotal = 0;
};

double armHandDistance(const Eigen::MatrixXd& values, Eigen::Index frame)
{
    const Eigen::Index arm = puppetChannel(2, Dof::X);
    const Eigen::Index hand = puppetChannel(3, Dof::X);
    return (values.block(frame, arm, 1, 3) - values.block(frame, hand, 1, 3)).norm();
}

} // namespace

Result<TruthExperimentResult> runTruthExperiment(const Corpus& corpus, const synth::DemoGroundTruth& truth,
                                                 const TruthExperimentOptions& options, const RunControl& control)
{
    if (auto status = validateCorpus(corpus); !status) return status.error();
    if (corpus.takes.empty() || !hasPuppetLayout(corpus.takes.front()))
        return makeError(ErrorCode::InvalidArgument, "truth experiment: the corpus needs the 24-channel puppet layout");

    struct Method {
        std::string name;
        NormaliseOptions options;
    };
    std::vector<Method> methods;
    NormaliseOptions base = options.normalise;
    base.features = MatchFeatures::Wavelet;
    base.match.path = PathMethod::Greedy;
    methods.push_back({"wavelet-greedy", base});
    base.match.path = PathMethod::Optimal;
    methods.push_back({"wavelet-optimal", base});
    NormaliseOptions amplitude = base;
    amplitude.features = MatchFeatures::Amplitude;
    amplitude.match.tau = 0; // classic DTW local cost, same band and constraint
    methods.push_back({"amplitude-dp", amplitude});
    if (options.includeIndependent) {
        NormaliseOptions independent = base;
        independent.coupling = "independent";
        methods.push_back({"wavelet-optimal-independent", independent});
    }
    std::vector<Accumulator> accumulators(methods.size());
    for (std::size_t m = 0; m < methods.size(); ++m) accumulators[m].result.name = methods[m].name;

    TruthExperimentResult result;
    const auto functions = corpus.functions();
    const auto emotions = corpus.emotions();
    const double cellCount = double(functions.size() * emotions.size());
    for (const auto& function : functions) {
        for (const auto& emotion : emotions) {
            if (control.cancelled()) return makeError(ErrorCode::Cancelled, "truth experiment cancelled");
            const std::vector<const Take*> raw = corpus.cell(function, emotion);
            if (raw.empty()) continue;
            std::vector<Take> takes;
            for (const Take* take : raw) {
                takes.push_back(*take);
                preprocess::unwrapAngles(takes.back());
            }
            std::vector<const Take*> cell;
            for (const auto& take : takes) cell.push_back(&take);

            std::size_t referenceIndex = 0;
            if (options.referenceTakeIndex > 0) {
                auto it = std::find_if(cell.begin(), cell.end(),
                                       [&](const Take* take) { return take->labels.takeIndex == options.referenceTakeIndex; });
                if (it == cell.end())
                    return makeError(ErrorCode::NotFound, "truth experiment: cell " + function + "/" + emotion + " has no take "
                                                              + std::to_string(options.referenceTakeIndex));
                referenceIndex = std::size_t(it - cell.begin());
            } else {
                auto suggestion = suggestReference(cell);
                if (!suggestion) return suggestion.error();
                referenceIndex = std::size_t(suggestion->takeIndex);
            }
            // Turn every take to the reference's whole-body heading (thesis 2.2's start-position
            // alignment, extended to the heading; the timing is untouched, so the correspondences
            // still compare with the raw takes' ground truth).
            for (std::size_t k = 0; k < takes.size(); ++k) {
                if (k == referenceIndex) continue;
                preprocess::alignStartHeading(takes[k], takes[referenceIndex], "shoulder");
                preprocess::matchAngleBranches(takes[k], takes[referenceIndex]);
            }
            const Take& reference = *cell[referenceIndex];

            // The arm-hand distance range the raw takes of the cell show.
            double low = std::numeric_limits<double>::infinity();
            double high = 0;
            for (const Take* take : cell)
                for (Eigen::Index t = 0; t < take->frameCount(); ++t) {
                    const double d = armHandDistance(take->values, t);
                    low = std::min(low, d);
                    high = std::max(high, d);
                }
            constexpr double kToleranceCm = 0.5;

            std::vector<const Take*> samples;
            std::vector<Eigen::VectorXd> truths;
            for (std::size_t k = 0; k < cell.size(); ++k) {
                if (k == referenceIndex) continue;
                auto correspondence = synth::trueCorrespondence(truth, reference.labels, cell[k]->labels);
                if (!correspondence)
                    return makeError(ErrorCode::InvalidArgument, "truth experiment: no ground truth for take "
                                                                     + cell[k]->displayName() + ": " + correspondence.error().message);
                samples.push_back(cell[k]);
                truths.push_back(std::move(*correspondence));
            }
            for (std::size_t m = 0; m < methods.size(); ++m) {
                auto normalised = normaliseTakes(reference, samples, methods[m].options, RunControl{control.stop, {}});
                if (!normalised) return normalised.error();
                Accumulator& acc = accumulators[m];
                for (std::size_t k = 0; k < samples.size(); ++k) {
                    const TakeNormalisation& one = (*normalised)[k];
                    const Eigen::MatrixXd error =
                        (one.correspondence.cast<double>().colwise() - truths[k]).cwiseAbs();
                    acc.errorSum += error.sum();
                    acc.errorCount += double(error.size());
                    acc.result.maxAbsErrorFrames = std::max(acc.result.maxAbsErrorFrames, error.maxCoeff());
                    for (Eigen::Index t = 0; t < one.normalised.frameCount(); ++t) {
                        const double d = armHandDistance(one.normalised.values, t);
                        const double excess = std::max({0.0, d - high, low - d});
                        acc.framesWithin += excess <= kToleranceCm ? 1.0 : 0.0;
                        acc.framesTotal += 1.0;
                        acc.result.armHandMaxExcessCm = std::max(acc.result.armHandMaxExcessCm, excess);
                    }
                }
            }
            result.pairs += int(samples.size());
            ++result.cells;
            control.report(double(result.cells) / cellCount);
        }
    }
    for (auto& acc : accumulators) {
        acc.result.meanAbsErrorFrames = acc.errorCount > 0 ? acc.errorSum / acc.errorCount : 0.0;
        acc.result.armHandWithinRange = acc.framesTotal > 0 ? acc.framesWithin / acc.framesTotal : 0.0;
        result.methods.push_back(acc.result);
    }
    return result;
}

} // namespace bunraku::analysis
