#include "analysis/decompose/km2o_decomposition.h"

#include <algorithm>
#include <cmath>
#include <limits>
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

/// The mean of the finite entries (the KM2O cells' P), 0 when there is none.
double finiteMean(const Eigen::MatrixXd& values)
{
    const Eigen::ArrayXXd finite = values.array().isFinite().cast<double>();
    const double count = finite.sum();
    return count > 0.0 ? finite.select(values.array(), 0.0).sum() / count : 0.0;
}

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
    // Functions not estimable by KM2O keep the layout's least-squares components and P NaN.
    for (const auto& y : layout.functions) out.functions.push_back(y.values);
    for (const auto& z : layout.emotions) out.emotions.push_back(z.values);
    out.cellErrorPercent = Eigen::MatrixXd::Constant(channels, Eigen::Index(layout.emotions.size()),
                                                     std::numeric_limits<double>::quiet_NaN());
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

std::string cellName(const EmotionComponent& cell)
{
    return cell.function + "/" + cell.emotion;
}

std::string takesText(std::size_t k)
{
    return std::to_string(k) + (k == 1 ? " take" : " takes");
}

/// The cells of every function of `layout` estimable by KM2O (one of its cells has K >= 2),
/// their takes from `corpus`; per cell of the layout its K and source, and the notes
/// (Km2oDecomposition::cells, notes).
struct CellPlan {
    std::vector<FunctionCells> families;
    std::vector<Km2oCellEstimate> cells;
    std::vector<std::string> notes;
};

CellPlan planCells(const Corpus& corpus, const Decomposition& layout)
{
    CellPlan plan;
    plan.cells.resize(layout.emotions.size());
    for (std::size_t i = 0; i < layout.functions.size(); ++i) {
        FunctionCells family;
        family.function = int(i);
        std::string multi;  // the cells with K >= 2, "f/e (K takes)"
        std::string single; // the one-take cells
        for (std::size_t c = 0; c < layout.emotions.size(); ++c) {
            const auto& cell = layout.emotions[c];
            if (cell.function != layout.functions[i].function) continue;
            auto takes = corpus.cell(cell.function, cell.emotion);
            plan.cells[c] = {cell.function, cell.emotion, int(takes.size()), Km2oCellSource::OwnTakes};
            std::string& list = takes.size() >= 2 ? multi : single;
            list += (list.empty() ? "" : ", ") + cellName(cell) + (takes.size() >= 2 ? " (" + takesText(takes.size()) + ")" : "");
            family.cellIndices.push_back(int(c));
            family.takes.push_back(std::move(takes));
        }
        const auto& name = layout.functions[i].function;
        if (multi.empty()) {
            for (int c : family.cellIndices) plan.cells[std::size_t(c)].source = Km2oCellSource::LeastSquares;
            plan.notes.push_back("function '" + name + "': KM2O not estimable - " + single +
                                 (family.cellIndices.size() == 1 ? " has" : " have") +
                                 " 1 take each, and gamma_+, V_+ need the diff series of a cell with K >= 2 takes "
                                 "(eqs. 4.24-4.35); y and z of '" + name + "' by least squares (eq. 4.8)");
            continue;
        }
        for (std::size_t j = 0; j < family.cellIndices.size(); ++j) {
            if (family.takes[j].size() >= 2) continue;
            auto& cell = plan.cells[std::size_t(family.cellIndices[j])];
            cell.source = Km2oCellSource::Pooled;
            plan.notes.push_back(cell.function + "/" + cell.emotion + " has 1 take (its diff series is zero, eq. 4.24): gamma_+, V_+ "
                                 "from the pooled diff series of " + multi + " (same function, eq. 4.39)");
        }
        plan.families.push_back(std::move(family));
    }
    return plan;
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
    const CellPlan plan = planCells(skeletal.corpus, layout);
    auto prepared = prepareChannels(layout, plan.families, reading.correlationLength);
    if (!prepared) return prepared.error();
    auto evaluation = evaluate(layout, *prepared, reading);
    if (!evaluation) return evaluation.error();
    return SkeletalComponents{linear.skeletonCharts, std::move(evaluation->functions), std::move(evaluation->emotions)};
}

} // namespace

const char* km2oCellSourceName(Km2oCellSource source)
{
    switch (source) {
    case Km2oCellSource::OwnTakes: return "own takes";
    case Km2oCellSource::Pooled: return "pooled";
    case Km2oCellSource::LeastSquares: return "least squares";
    }
    return "?";
}

bool Km2oDecomposition::estimable() const
{
    return std::any_of(cells.begin(), cells.end(), [](const Km2oCellEstimate& c) { return c.source != Km2oCellSource::LeastSquares; });
}

std::string Km2oDecomposition::outcome() const
{
    const auto count = [&](Km2oCellSource source) {
        return std::count_if(cells.begin(), cells.end(), [&](const Km2oCellEstimate& c) { return c.source == source; });
    };
    const auto cellsText = [](long n) { return std::to_string(n) + (n == 1 ? " cell" : " cells"); };
    const long pooled = count(Km2oCellSource::Pooled);
    const long leastSquares = count(Km2oCellSource::LeastSquares);
    if (!estimable()) return "KM2O not estimable (no cell has 2 takes): y, z by least squares for all " + cellsText(leastSquares);
    std::string text = "KM2O for " + (leastSquares == 0 ? "all " : std::string()) + cellsText(long(cells.size()) - leastSquares);
    if (pooled > 0) text += " (" + std::to_string(pooled) + " with one take, gamma pooled over its function)";
    if (leastSquares > 0) text += ", least squares for " + cellsText(leastSquares) + " (functions without a cell of 2 takes)";
    return text;
}

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

    CellPlan plan = planCells(linear.corpus, layout);
    Km2oDecomposition result;
    result.cells = std::move(plan.cells);
    result.notes = std::move(plan.notes);
    if (!result.estimable()) {
        // No cell of any function has two takes: y, z, eta stay least squares (eq. 4.8).
        result.cellErrorPercent = Eigen::MatrixXd::Constant(Eigen::Index(layout.channels.size()), Eigen::Index(layout.emotions.size()),
                                                            std::numeric_limits<double>::quiet_NaN());
        result.meanCellErrorPercent = std::numeric_limits<double>::quiet_NaN();
        result.components = std::move(layout);
        control.report(1.0);
        return result;
    }
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
    auto prepared = prepareChannels(layout, plan.families, longest);
    if (!prepared) return prepared.error();
    double bestError = 0.0;
    Evaluation best;
    for (std::size_t index = 0; index < result.candidateLengths.size(); ++index) {
        if (control.cancelled()) return makeError(ErrorCode::Cancelled, "KM2O decomposition cancelled");
        ExogenousOptions reading = options.reading;
        reading.correlationLength = result.candidateLengths[index];
        auto evaluation = evaluate(layout, *prepared, reading);
        if (!evaluation) return evaluation.error();
        const double meanError = finiteMean(evaluation->cellErrorPercent);
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
