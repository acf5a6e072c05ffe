#include "analysis/design/design_corpus.h"

#include "analysis/core/puppet_layout.h"
#include "analysis/design/motion_design.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace bunraku::analysis {
namespace {

/// v at fractional index x, linear between samples, clamped to the ends.
double sampleLinear(const Eigen::VectorXd& v, double x)
{
    if (v.size() == 0) return 0.0;
    const double last = double(v.size() - 1);
    const double c = std::clamp(x, 0.0, last);
    const auto i = Eigen::Index(std::floor(c));
    if (double(i) >= last) return v[v.size() - 1];
    const double f = c - double(i);
    return (1.0 - f) * v[i] + f * v[i + 1];
}

Take truthTake(const Eigen::MatrixXd& motion, const std::string& function, const std::string& emotion, double rateHz)
{
    Take take;
    take.values = motion;
    take.rateHz = rateHz;
    take.channels = puppetChannels();
    take.labels = {function, emotion, 0, "ground-truth cell motion"};
    return take;
}

DesignMean truthMean(const Eigen::MatrixXd& motion, const std::string& function, const std::string& emotion, double rateHz)
{
    DesignMean mean;
    mean.take = truthTake(motion, function, emotion, rateHz);
    mean.cellTime = Eigen::VectorXd::LinSpaced(motion.rows(), 0.0, double(motion.rows() - 1));
    mean.truthShapeError = 0.0;
    return mean;
}

/// Cell time shown by each frame of a preprocessed take: preprocessed frame t is padded frame
/// clamp(t + shift) (start alignment drops `shift` frames and repeats the ends), which is raw
/// frame min(padded, raw frames - 1) (padding repeats the last frame), which shows takeToCell.
Eigen::VectorXd preprocessedCellTime(const Take& take, const preprocess::TakeReport& report, const synth::TakeTruth& truth)
{
    const Eigen::Index frames = take.frameCount();
    const Eigen::Index rawLast = truth.takeToCell.size() - 1;
    Eigen::VectorXd u(frames);
    for (Eigen::Index t = 0; t < frames; ++t) {
        const Eigen::Index padded = std::clamp<Eigen::Index>(t + report.shiftFrames, 0, frames - 1);
        u[t] = truth.takeToCell[std::min(padded, rawLast)];
    }
    return u;
}

/// eq. 5.18 form of the mean against the truth at cellTime, each channel's constant offset
/// removed (the least-squares one: the mean difference) and the truth taken about its mean.
double shapeError(const Take& mean, const Eigen::MatrixXd& cellMotion, const Eigen::VectorXd& cellTime)
{
    const Eigen::MatrixXd truth = synth::resampleMotion(cellMotion, cellTime);
    Eigen::MatrixXd difference = mean.values - truth;
    difference.rowwise() -= difference.colwise().mean();
    const Eigen::MatrixXd centred = truth.rowwise() - truth.colwise().mean();
    return relativeError(centred + difference, centred);
}

Result<DesignMean> measuredMean(const Corpus& preprocessed, const preprocess::PreprocessReport& report,
                                const synth::DemoGroundTruth& truth, const synth::CellTruth& cell,
                                const AverageOptions& options, const RunControl& control)
{
    const std::vector<const Take*> takes = preprocessed.cell(cell.function, cell.emotion);
    if (takes.empty())
        return makeError(ErrorCode::NotFound, "design experiment: the corpus has no takes for " + cell.function + "/" + cell.emotion);
    std::vector<Eigen::VectorXd> memberCellTime;
    for (const Take* take : takes) {
        const auto index = std::size_t(take - preprocessed.takes.data());
        const synth::TakeTruth* takeTruth = truth.take(take->labels);
        if (!takeTruth || index >= report.takes.size())
            return makeError(ErrorCode::NotFound, "design experiment: no ground truth for take " + take->displayName());
        memberCellTime.push_back(preprocessedCellTime(*take, report.takes[index], *takeTruth));
    }
    Result<Take> average = averageTake(takes, options, control);
    if (!average) return average.error();
    DesignMean mean;
    mean.cellTime = averageTakeCellTime(memberCellTime, options, average->frameCount());
    mean.take = std::move(average).value();
    mean.truthShapeError = shapeError(mean.take, cell.motion, mean.cellTime);
    return mean;
}

} // namespace

AverageOptions designAverageOptions()
{
    AverageOptions options;
    options.normalise.coupling = "method2";
    options.normalise.match.scales = integerScales(16);
    options.normalise.match.tau = 4;
    options.normalise.match.searchBand = 20;
    options.normalise.match.path = PathMethod::Optimal;
    return options;
}

double firstFrameReaching(const Eigen::VectorXd& map, double value)
{
    const Eigen::Index n = map.size();
    if (n == 0 || value <= map[0]) return 0.0;
    for (Eigen::Index t = 1; t < n; ++t) {
        if (map[t] < value) continue;
        const double step = map[t] - map[t - 1];
        return double(t - 1) + (step > 0.0 ? (value - map[t - 1]) / step : 1.0);
    }
    return double(n - 1);
}

Eigen::VectorXd averageTakeCellTime(const std::vector<Eigen::VectorXd>& memberCellTime, const AverageOptions& options,
                                    Eigen::Index frames)
{
    Eigen::VectorXd result = Eigen::VectorXd::Zero(frames);
    const auto count = int(memberCellTime.size());
    if (count == 0 || frames == 0 || options.baseTake < 0 || options.baseTake >= count) return result;
    const Eigen::VectorXd& base = memberCellTime[std::size_t(options.baseTake)];
    std::vector<bool> included(std::size_t(count), true);
    for (int excluded : options.excludedTakes)
        if (excluded >= 0 && excluded < count && excluded != options.baseTake) included[std::size_t(excluded)] = false;

    // The curve (t_bar(t_b), u_b(t_b)) over the base's frames.
    Eigen::VectorXd meanTime(base.size());
    for (Eigen::Index tb = 0; tb < base.size(); ++tb) {
        double sum = 0.0;
        int members = 0;
        for (int k = 0; k < count; ++k) {
            if (!included[std::size_t(k)]) continue;
            sum += k == options.baseTake ? double(tb) : firstFrameReaching(memberCellTime[std::size_t(k)], base[tb]);
            ++members;
        }
        meanTime[tb] = sum / members;
    }
    // Resampled at t = 0..frames-1: the base frame where t_bar reaches t, then u_b there.
    for (Eigen::Index t = 0; t < frames; ++t) result[t] = sampleLinear(base, firstFrameReaching(meanTime, double(t)));
    return result;
}

Result<std::vector<SyntheticDesignCell>> syntheticDesignCells(const Corpus& corpus, const synth::DemoGroundTruth& truth,
                                                              const DesignCorpusOptions& options, const RunControl& control)
{
    Corpus preprocessed;
    preprocess::PreprocessReport report;
    if (options.means == DesignMeans::Measured) {
        auto result = preprocess::preprocessCorpus(corpus, options.preprocess, control);
        if (!result) return result.error();
        preprocessed = std::move(result->corpus);
        report = std::move(result->report);
    }
    std::vector<SyntheticDesignCell> cells;
    for (const synth::CellTruth& cellTruth : truth.cells) {
        if (control.cancelled()) return makeError(ErrorCode::Cancelled, "design experiment cancelled");
        const synth::FunctionTruth* function = truth.function(cellTruth.function);
        const synth::CellTruth* neutral = truth.cell(cellTruth.function, truth.neutralEmotion);
        if (!function || !neutral)
            return makeError(ErrorCode::NotFound, "design experiment: the ground truth has no neutral cell for " + cellTruth.function);
        SyntheticDesignCell result;
        if (options.means == DesignMeans::Truth) {
            result.functionalMean = truthMean(function->motion, cellTruth.function, truth.neutralEmotion, truth.rateHz);
            result.emotionalMean = truthMean(cellTruth.motion, cellTruth.function, cellTruth.emotion, truth.rateHz);
        } else {
            auto functional = measuredMean(preprocessed, report, truth, *neutral, options.average, control);
            if (!functional) return functional.error();
            auto emotional = measuredMean(preprocessed, report, truth, cellTruth, options.average, control);
            if (!emotional) return emotional.error();
            result.functionalMean = std::move(functional).value();
            result.emotionalMean = std::move(emotional).value();
        }
        // True correspondence of the means: emotional frame -> its cell time -> functional time
        // (the cell's phase warp) -> the functional mean's frame showing that functional time.
        const Eigen::VectorXd& emotionalTime = result.emotionalMean.cellTime;
        Eigen::VectorXd functionalFrameTime(result.functionalMean.cellTime.size());
        for (Eigen::Index t = 0; t < functionalFrameTime.size(); ++t)
            functionalFrameTime[t] = sampleLinear(neutral->phaseWarp, result.functionalMean.cellTime[t]);
        result.cell.trueEmotionalToFunctional.resize(emotionalTime.size());
        for (Eigen::Index t = 0; t < emotionalTime.size(); ++t)
            result.cell.trueEmotionalToFunctional[t] =
                firstFrameReaching(functionalFrameTime, sampleLinear(cellTruth.phaseWarp, emotionalTime[t]));
        result.cell.function = cellTruth.function;
        result.cell.emotion = cellTruth.emotion;
        result.cell.functional = result.functionalMean.take;
        result.cell.emotional = result.emotionalMean.take;
        cells.push_back(std::move(result));
    }
    return cells;
}

} // namespace bunraku::analysis
