#include "analysis/decompose/km2o_decomposition.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace bunraku::analysis {
namespace {

/// The cells of one function in Decomposition::emotions order, as frames x K per channel.
struct FunctionCells {
    int function = 0;
    std::vector<int> cellIndices;                 ///< into Decomposition::emotions
    std::vector<std::vector<const Take*>> takes;  ///< per cell
};

/// The components of one correlation length: y^i per function and z^{ij} per cell (frames x
/// channels, Decomposition's order) and P^{ij} (channels x cells).
struct Evaluation {
    std::vector<Eigen::MatrixXd> functions;
    std::vector<Eigen::MatrixXd> emotions;
    Eigen::MatrixXd cellErrorPercent;
};

/// The function's cells of one channel, prepared once for every M (ExogenousCells).
struct PreparedChannel {
    const FunctionCells* family = nullptr;
    Eigen::Index channel = 0;
    ExogenousCells cells;
};

std::string channelContext(const Decomposition& layout, const FunctionCells& family, Eigen::Index channel)
{
    return "KM2O decomposition, channel " + layout.channels[std::size_t(channel)].name() + ", function '" +
           layout.functions[std::size_t(family.function)].function + "': ";
}

Result<std::vector<PreparedChannel>> prepareChannels(const Decomposition& layout, const std::vector<FunctionCells>& families,
                                                     int maxCorrelationLength)
{
    std::vector<PreparedChannel> prepared;
    const Eigen::Index channels = Eigen::Index(layout.channels.size());
    const Eigen::Index frames = layout.frameCount();
    for (const auto& family : families) {
        for (Eigen::Index ch = 0; ch < channels; ++ch) {
            std::vector<Eigen::MatrixXd> cells(family.takes.size());
            for (std::size_t j = 0; j < family.takes.size(); ++j) {
                auto& m = cells[j];
                m.resize(frames, Eigen::Index(family.takes[j].size()));
                for (std::size_t k = 0; k < family.takes[j].size(); ++k) m.col(Eigen::Index(k)) = family.takes[j][k]->values.col(ch);
            }
            auto one = ExogenousCells::prepare(std::move(cells), maxCorrelationLength);
            if (!one) return makeError(one.error().code, channelContext(layout, family, ch) + one.error().message);
            prepared.push_back({&family, ch, std::move(one).value()});
        }
    }
    return prepared;
}

Result<Evaluation> evaluate(const Decomposition& layout, const std::vector<PreparedChannel>& prepared, const ExogenousOptions& reading)
{
    Evaluation out;
    const Eigen::Index channels = Eigen::Index(layout.channels.size());
    const Eigen::Index frames = layout.frameCount();
    out.functions.assign(layout.functions.size(), Eigen::MatrixXd(frames, channels));
    out.emotions.assign(layout.emotions.size(), Eigen::MatrixXd(frames, channels));
    out.cellErrorPercent = Eigen::MatrixXd::Zero(channels, Eigen::Index(layout.emotions.size()));
    for (const auto& one : prepared) {
        const FunctionCells& family = *one.family;
        const Eigen::Index ch = one.channel;
        auto est = one.cells.estimate(reading);
        if (!est) return makeError(est.error().code, channelContext(layout, family, ch) + est.error().message);
        out.functions[std::size_t(family.function)].col(ch) = est->functionComponent;
        for (std::size_t j = 0; j < family.cellIndices.size(); ++j) {
            const int cell = family.cellIndices[j];
            out.emotions[std::size_t(cell)].col(ch) = est->emotionComponents.col(Eigen::Index(j));
            const Eigen::VectorXd reconstruction = est->functionComponent + est->emotionComponents.col(Eigen::Index(j));
            const double p = relativeError(reconstruction, est->cellMeans.col(Eigen::Index(j)));
            out.cellErrorPercent(ch, cell) = std::isfinite(p) ? 100.0 * p : 0.0; // all-zero mean: nothing to miss
        }
    }
    return out;
}

/// The cells of every function of `layout`, their takes from `corpus`; InvalidArgument for a
/// cell with fewer than 2 takes.
Result<std::vector<FunctionCells>> functionCells(const Corpus& corpus, const Decomposition& layout)
{
    std::vector<FunctionCells> families;
    for (std::size_t i = 0; i < layout.functions.size(); ++i) {
        FunctionCells family;
        family.function = int(i);
        for (std::size_t c = 0; c < layout.emotions.size(); ++c) {
            const auto& cell = layout.emotions[c];
            if (cell.function != layout.functions[i].function) continue;
            auto takes = corpus.cell(cell.function, cell.emotion);
            if (takes.size() < 2)
                return makeError(ErrorCode::InvalidArgument, "KM2O decomposition: cell " + cell.function + "/" + cell.emotion +
                                                                 " has " + std::to_string(takes.size()) +
                                                                 " take(s); the diff series need K >= 2 (eq. 4.35)");
            family.cellIndices.push_back(int(c));
            family.takes.push_back(std::move(takes));
        }
        families.push_back(std::move(family));
    }
    return families;
}

/// The skeletons' y and z by the same KM2O reading as the channels: the skeleton coordinates of
/// every take decomposed as channels of their own.
Result<SkeletalComponents> skeletalKm2o(const LinearCorpus& linear, const ExogenousOptions& reading)
{
    LinearCorpus skeletal;
    skeletal.corpus = linear.corpus;
    skeletal.functions = linear.functions;
    std::vector<Channel> channels;
    for (Eigen::Index c = 0; c < linear.skeletonCoordinates.front().cols(); ++c) {
        // Appended piecewise: GCC 12 reports a false -Wrestrict on "c" + std::to_string at -O3.
        std::string dof = "c";
        dof.append(std::to_string(c));
        channels.push_back({"skeleton", dof, ""});
    }
    for (std::size_t k = 0; k < skeletal.corpus.takes.size(); ++k) {
        skeletal.corpus.takes[k].channels = channels;
        skeletal.corpus.takes[k].values = linear.skeletonCoordinates[k];
    }
    const Decomposition layout = decomposeLinear(skeletal);
    auto families = functionCells(skeletal.corpus, layout);
    if (!families) return families.error();
    auto prepared = prepareChannels(layout, *families, reading.correlationLength);
    if (!prepared) return prepared.error();
    auto evaluation = evaluate(layout, *prepared, reading);
    if (!evaluation) return evaluation.error();
    return SkeletalComponents{linear.skeletonCharts, std::move(evaluation->functions), std::move(evaluation->emotions)};
}

} // namespace

Result<Km2oDecomposition> decomposeKm2o(const Corpus& corpus, const Km2oDecompositionOptions& options, const RunControl& control)
{
    if (auto status = checkDecomposable(corpus); !status) return status.error();
    // Orientations and skeletons in linear coordinates (linear_corpus.h); least squares gives
    // the cell order and means.
    const LinearCorpus linear = lineariseCorpus(corpus);
    Decomposition layout = decomposeLinear(linear);
    const Eigen::Index frames = layout.frameCount();
    const int maxM = maxCorrelationLength(frames);
    auto outOfRange = [&](int m) {
        return makeError(ErrorCode::InvalidArgument, "KM2O: correlation length M = " + std::to_string(m) + " outside 1..M_max = " +
                                                         std::to_string(maxM) + " (M_max = floor(3 sqrt(T+1)) - 1, T = " +
                                                         std::to_string(frames - 1) + ", thesis eq. 4.30)");
    };
    if (options.correlationLength < 0 || options.correlationLength > maxM) return outOfRange(options.correlationLength);
    if (options.lastCandidateLength < 0 || options.lastCandidateLength > maxM) return outOfRange(options.lastCandidateLength);

    auto families = functionCells(linear.corpus, layout);
    if (!families) return families.error();

    Km2oDecomposition result;
    if (options.correlationLength > 0) {
        result.candidateLengths = {options.correlationLength};
    } else {
        const int last = options.lastCandidateLength > 0 ? options.lastCandidateLength : maxM;
        for (int m = 1; m <= last; ++m) result.candidateLengths.push_back(m);
    }
    // What does not depend on M (the cells of every function and channel, their means and
    // diff-series autocovariances) once; then every candidate M.
    if (result.candidateLengths.empty()) return outOfRange(0);
    const int longest = *std::max_element(result.candidateLengths.begin(), result.candidateLengths.end());
    auto prepared = prepareChannels(layout, *families, longest);
    if (!prepared) return prepared.error();
    double bestError = 0.0;
    Evaluation best;
    for (std::size_t index = 0; index < result.candidateLengths.size(); ++index) {
        if (control.cancelled()) return makeError(ErrorCode::Cancelled, "KM2O decomposition cancelled");
        ExogenousOptions reading = options.reading;
        reading.correlationLength = result.candidateLengths[index];
        auto evaluation = evaluate(layout, *prepared, reading);
        if (!evaluation) return evaluation.error();
        const double meanError = evaluation->cellErrorPercent.size() > 0 ? evaluation->cellErrorPercent.mean() : 0.0;
        result.meanErrorPercent.push_back(meanError);
        if (index == 0 || meanError < bestError) {
            bestError = meanError;
            result.correlationLength = reading.correlationLength;
            best = std::move(evaluation).value();
        }
        control.report(double(index + 1) / double(result.candidateLengths.size()));
    }
    result.components = std::move(layout);
    for (std::size_t f = 0; f < best.functions.size(); ++f) result.components.functions[f].values = std::move(best.functions[f]);
    for (std::size_t c = 0; c < best.emotions.size(); ++c) result.components.emotions[c].values = std::move(best.emotions[c]);
    result.cellErrorPercent = std::move(best.cellErrorPercent);
    result.meanCellErrorPercent = bestError;
    if (result.components.skeleton) {
        if (control.cancelled()) return makeError(ErrorCode::Cancelled, "KM2O decomposition cancelled");
        ExogenousOptions reading = options.reading;
        reading.correlationLength = result.correlationLength;
        auto skeletal = skeletalKm2o(linear, reading);
        if (!skeletal) return skeletal.error();
        result.components.skeleton = std::move(skeletal).value();
    }
    // eta = x - y - z with the KM2O components.
    for (auto& eta : result.components.fluctuations) {
        const Take* take = linear.corpus.find(eta.labels.function, eta.labels.emotion, eta.labels.takeIndex);
        const int cell = result.components.cellIndex(eta.labels.function, eta.labels.emotion);
        const auto* y = result.components.function(eta.labels.function);
        if (take && y && cell >= 0)
            eta.values = take->values - y->values - result.components.emotions[std::size_t(cell)].values;
    }
    return result;
}

} // namespace bunraku::analysis
