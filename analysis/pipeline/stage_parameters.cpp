#include "analysis/pipeline/stage_parameters.h"

#include "analysis/decompose/emotion_weight.h"
#include "analysis/decompose/km2o.h"
#include "analysis/wavelet/cwt.h"
#include "analysis/normalise/coupling.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <stdexcept>

namespace bunraku::analysis::pipeline {
namespace {

Error outOfRange(const std::string& name, const std::string& range, double value)
{
    std::ostringstream text;
    text << name << " = " << value << " is outside " << range;
    return makeError(ErrorCode::InvalidArgument, text.str());
}

Status checkInt(const std::string& name, int value, int low, int high)
{
    if (value < low || value > high)
        return outOfRange(name, std::to_string(low) + ".." + std::to_string(high), double(value));
    return okStatus();
}

/// `value` against the table's range of `path`.
Status check(std::string_view path, double value)
{
    const ParameterRange& range = parameterRange(path);
    if (!range.contains(value)) return outOfRange(std::string(path), range.interval(), value);
    return okStatus();
}

constexpr ParameterRange kRanges[] = {
    {"preprocess.referenceTake", 0, kMaxTakeIndex},
    {"normalise.tau", 0, kMaxTau},
    {"normalise.searchBand", 0, kMaxSearchBand},
    {"normalise.maxScale", 1, kMaxScale},
    {"normalise.averageBase", 0, kMaxTakeIndex},
    {"normalise.averageExcluded", 1, kMaxTakeIndex},
    {"normalise.approximationWeight", 0.0, kMaxApproximationWeight, false},
    {"decompose.M", 0, kMaxCorrelationLength},
    {"fluctuations.armaP", 0, kMaxArmaOrder},
    {"fluctuations.armaQ", 0, kMaxArmaOrder},
    {"fluctuations.welchSegment", 2, kMaxWelchSegment},
    {"axis.massSpacing", kMinMassSpacing, kMaxMassSpacing, false},
    {"axis.tau", 0, kMaxTau},
    {"axis.searchBand", 0, kMaxSearchBand},
    {"axis.maxScale", 1, kMaxScale},
    {"axis.approximationWeight", 0.0, kMaxApproximationWeight, false},
    {"axis.controlSpacing", 1, kMaxControlSpacing},
    {"axis.refinementPasses", 0, kMaxRefinementPasses},
    {"design.emotionWeight", kMinEmotionWeight, kMaxEmotionWeight, false},
};

Status checkReal(const std::string& name, double value, double low, double high, bool openLow = false)
{
    const bool below = openLow ? !(value > low) : !(value >= low);
    if (!std::isfinite(value) || below || value > high) {
        std::ostringstream range;
        range << (openLow ? "(" : "[") << low << ", " << high << "]";
        return outOfRange(name, range.str(), value);
    }
    return okStatus();
}

Status checkReference(const std::string& name, const ReferenceChoice& choice)
{
    if (choice.kind == ReferenceKind::Take) return checkInt(name + ".take", choice.takeIndex, 1, kMaxTakeIndex);
    return okStatus();
}

/// Runs the checks in order, returning the first failure.
template <class... Checks> Status firstFailure(Checks&&... checks)
{
    Status result = okStatus();
    ((result.ok() ? (void)(result = checks()) : (void)0), ...);
    return result;
}

} // namespace

bool ParameterRange::contains(double value) const
{
    return std::isfinite(value) && value >= low && value <= high && (!integer || value == std::floor(value));
}

std::string ParameterRange::interval() const
{
    std::ostringstream text;
    if (integer) text << std::int64_t(low) << ".." << std::int64_t(high);
    else text << "[" << low << ", " << high << "]";
    return text.str();
}

std::string ParameterRange::expected() const { return (integer ? "an integer in " : "a number in ") + interval(); }

std::span<const ParameterRange> parameterRanges() { return kRanges; }

const ParameterRange& parameterRange(std::string_view path)
{
    for (const ParameterRange& range : kRanges)
        if (range.path == path) return range;
    throw std::logic_error("no range for the parameter " + std::string(path));
}

preprocess::PreprocessOptions PreprocessParameters::options() const
{
    preprocess::PreprocessOptions options;
    options.pad = pad;
    options.unwrap = unwrap;
    options.alignStart = alignStart;
    options.alignHeading = alignHeading;
    options.alignPosition = alignPosition;
    options.positionAlignment = positionAlignment;
    options.referenceTakeIndex = referenceTakeIndex;
    return options;
}

NormaliseOptions NormaliseParameters::options() const
{
    NormaliseOptions options;
    options.coupling = coupling;
    options.match.tau = tau;
    options.match.searchBand = searchBand;
    options.match.scales = scales.empty() ? integerScales(maxScale) : scales;
    options.match.path = path;
    options.match.weighting = weighting;
    options.match.level = level;
    options.match.approximationWeight = approximationWeight;
    return options;
}

std::string cellName(const std::string& function, const std::string& emotion) { return function + "/" + emotion; }

ReferenceChoice NormaliseParameters::referenceFor(const std::string& function, const std::string& emotion) const
{
    const auto found = cellReferences.find(cellName(function, emotion));
    return found == cellReferences.end() ? reference : found->second;
}

AxisOptions AxisParameters::axisOptions() const
{
    AxisOptions options;
    options.frontBack = frontBack;
    options.massPoints.spacing = massSpacing;
    options.massPoints.source = masses;
    options.segments = segments;
    return options;
}

ExtractionOptions AxisParameters::extractionOptions() const
{
    ExtractionOptions options;
    options.phase.match.tau = tau;
    options.phase.match.searchBand = searchBand;
    options.phase.match.scales = integerScales(maxScale);
    options.phase.match.approximationWeight = approximationWeight;
    options.phase.match.level = level;
    options.phase.match.path = path;
    options.phase.controlPointSpacing = controlSpacing;
    options.refinementPasses = refinementPasses;
    return options;
}

const GainEdit* DesignEdits::gain(int phrase, int dof) const
{
    const auto found = std::find_if(gains.begin(), gains.end(), [&](const GainEdit& g) { return g.phrase == phrase && g.dof == dof; });
    return found == gains.end() ? nullptr : &*found;
}

void DesignEdits::setGain(const GainEdit& edit)
{
    const auto at = std::lower_bound(gains.begin(), gains.end(), edit, [](const GainEdit& a, const GainEdit& b) {
        return std::pair(a.phrase, a.dof) < std::pair(b.phrase, b.dof);
    });
    if (at != gains.end() && at->phrase == edit.phrase && at->dof == edit.dof)
        *at = edit;
    else
        gains.insert(at, edit);
}

bool DesignEdits::operator==(const DesignEdits& other) const
{
    const bool sameWarp = warp.has_value() == other.warp.has_value() &&
                          (!warp || (warp->points == other.warp->points && warp->outputFrames == other.warp->outputFrames));
    return emotionWeight == other.emotionWeight && sameWarp && gains == other.gains && boundaries == other.boundaries;
}

namespace {

/// Frames of the shortest take of `corpus`, none without takes.
std::optional<Eigen::Index> shortestTake(const Corpus& corpus)
{
    std::optional<Eigen::Index> frames;
    for (const Take& take : corpus.takes) frames = std::min(frames.value_or(take.frameCount()), take.frameCount());
    return frames;
}

} // namespace

int usableMaxScale(const Corpus& corpus)
{
    const auto frames = shortestTake(corpus);
    if (!frames) return kMaxScale;
    return std::clamp(largestScale(CwtOptions{}.wavelet, *frames), 1, kMaxScale);
}

int usableCorrelationLength(const Corpus& corpus)
{
    const auto frames = shortestTake(corpus);
    if (!frames) return kMaxCorrelationLength;
    return std::clamp(maxCorrelationLength(*frames), 0, kMaxCorrelationLength);
}

Status validate(const PreprocessParameters& p)
{
    return check("preprocess.referenceTake", p.referenceTakeIndex);
}

Status validate(const NormaliseParameters& p)
{
    return firstFailure([&] { return check("normalise.tau", p.tau); },
                        [&] { return check("normalise.searchBand", p.searchBand); },
                        [&] { return check("normalise.maxScale", p.maxScale); },
                        [&]() -> Status {
                            if (p.coupling.empty())
                                return makeError(ErrorCode::InvalidArgument, "normalise.coupling is empty (expected a preset "
                                                                             "such as method2, or sets like arm.x+hand.x)");
                            if (p.coupling.size() > 4096)
                                return makeError(ErrorCode::InvalidArgument, "normalise.coupling is longer than 4096 characters");
                            return okStatus();
                        },
                        [&] { return checkReference("normalise.reference", p.reference); },
                        [&] { return check("normalise.averageBase", p.averageBase); },
                        [&] { return check("normalise.approximationWeight", p.approximationWeight); },
                        [&]() -> Status {
                            if (p.scales.size() > std::size_t(kMaxScale))
                                return makeError(ErrorCode::InvalidArgument, "normalise.scales: more than 256 scales");
                            for (double scale : p.scales)
                                if (auto status = checkReal("normalise.scales", scale, 0.0, double(kMaxScale), true); !status) return status;
                            return okStatus();
                        },
                        [&]() -> Status {
                            if (p.averageExcluded.size() > 10000)
                                return makeError(ErrorCode::InvalidArgument, "normalise.averageExcluded has more than 10000 takes");
                            for (int take : p.averageExcluded)
                                if (auto status = check("normalise.averageExcluded", take); !status) return status;
                            return okStatus();
                        },
                        [&]() -> Status {
                            for (const auto& [cell, choice] : p.cellReferences)
                                if (auto status = checkReference("normalise.cellReferences." + cell, choice); !status) return status;
                            return okStatus();
                        });
}

Status validate(const DecomposeParameters& p)
{
    return check("decompose.M", p.correlationLength);
}

Status validate(const FluctuationParameters& p)
{
    return firstFailure([&] { return check("fluctuations.armaP", p.armaP); },
                        [&] { return check("fluctuations.armaQ", p.armaQ); },
                        [&] { return check("fluctuations.welchSegment", p.welchSegment); });
}

Status validate(const AxisParameters& p)
{
    return firstFailure([&] { return check("axis.massSpacing", p.massSpacing); },
                        [&] { return check("axis.tau", p.tau); },
                        [&] { return check("axis.searchBand", p.searchBand); },
                        [&] { return check("axis.maxScale", p.maxScale); },
                        [&] { return check("axis.approximationWeight", p.approximationWeight); },
                        [&] { return check("axis.controlSpacing", p.controlSpacing); },
                        [&] { return check("axis.refinementPasses", p.refinementPasses); });
}

Status validate(const DesignEdits& d)
{
    if (auto status = check("design.emotionWeight", d.emotionWeight); !status)
        return status;
    if (d.warp) {
        if (d.warp->points.size() > kMaxWarpPoints)
            return makeError(ErrorCode::InvalidArgument, "design.warp has " + std::to_string(d.warp->points.size()) +
                                                             " control points; at most " + std::to_string(kMaxWarpPoints));
        for (const auto& point : d.warp->points) {
            if (auto status = checkReal("design.warp output frame", point.output, 0.0, kMaxWarpFrame); !status) return status;
            if (auto status = checkReal("design.warp source frame", point.source, 0.0, kMaxWarpFrame); !status) return status;
        }
        if (auto status = validateWarpCurve(*d.warp); !status)
            return makeError(ErrorCode::InvalidArgument, "design.warp: " + status.error().message);
    }
    if (d.gains.size() > kMaxGainEdits)
        return makeError(ErrorCode::InvalidArgument, "design.gains has more than " + std::to_string(kMaxGainEdits) + " entries");
    for (std::size_t i = 0; i < d.gains.size(); ++i) {
        const GainEdit& g = d.gains[i];
        const std::string name = "design.gains[" + std::to_string(i) + "]";
        if (auto status = firstFailure([&] { return checkInt(name + ".phrase", g.phrase, 0, int(kMaxPhraseBoundaries)); },
                                       [&] { return checkInt(name + ".dof", g.dof, 0, 1000); },
                                       [&] { return checkReal(name + ".g0", g.g0, -kMaxGain, kMaxGain); },
                                       [&] { return checkReal(name + ".g1", g.g1, -kMaxGain, kMaxGain); });
            !status)
            return status;
        if (i > 0 && std::pair(d.gains[i - 1].phrase, d.gains[i - 1].dof) >= std::pair(g.phrase, g.dof))
            return makeError(ErrorCode::InvalidArgument, name + ": gains must be sorted by phrase and DOF, each once");
    }
    const auto& inner = d.boundaries.inner;
    if (d.boundaries.suggested && !inner.empty())
        return makeError(ErrorCode::InvalidArgument, "design.boundaries: suggested boundaries carry no frames");
    if (inner.size() > kMaxPhraseBoundaries)
        return makeError(ErrorCode::InvalidArgument, "design.boundaries has more than " + std::to_string(kMaxPhraseBoundaries) +
                                                         " boundaries");
    for (std::size_t i = 0; i < inner.size(); ++i) {
        if (inner[i] < 1 || double(inner[i]) > kMaxWarpFrame)
            return outOfRange("design.boundaries[" + std::to_string(i) + "]", "1..1e8", double(inner[i]));
        if (i > 0 && inner[i] <= inner[i - 1])
            return makeError(ErrorCode::InvalidArgument, "design.boundaries must increase (boundary " + std::to_string(i) + ")");
    }
    return okStatus();
}

Status validate(const ChainParameters& p)
{
    return firstFailure([&] { return validate(p.preprocess); }, [&] { return validate(p.normalise); },
                        [&] { return validate(p.decompose); }, [&] { return validate(p.fluctuations); },
                        [&] { return validate(p.axis); }, [&] { return validate(p.design); });
}

} // namespace bunraku::analysis::pipeline
