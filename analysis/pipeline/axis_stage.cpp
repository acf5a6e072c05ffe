// The motion-axis stage (thesis 5: axes 5.2.1, phrases 5.2.2, phase 5.3, gains 5.4) and the
// on-demand emotion weight (4.5) and design (5.5).
#include "analysis/pipeline/stages.h"
#include "analysis/pipeline/parameters_json.h"

#include "analysis/axis/axis_channels.h"
#include "analysis/axis/segment_inertia.h"
#include "analysis/core/parallel.h"
#include "analysis/core/puppet_layout.h"
#include "analysis/body/body_description.h"
#include "analysis/body/body_fit.h"
#include "analysis/decompose/emotion_weight.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <tuple>
#include <vector>

namespace bunraku::analysis::pipeline {
namespace {

/// The axis model of the default body for the given options, built once per lattice step and
/// front-back choice (it depends on nothing else).
std::shared_ptr<const AxisModel> defaultAxisModel(const AxisOptions& options)
{
    static std::mutex mutex;
    static std::map<std::tuple<double, int, int>, std::shared_ptr<const AxisModel>> models;
    const std::lock_guard lock(mutex);
    auto& model = models[{options.massPoints.spacing, int(options.frontBack), int(options.massPoints.source)}];
    if (!model) model = std::make_shared<const AxisModel>(makeAxisModel(defaultBodyDescription(), options));
    return model;
}

} // namespace

Result<std::shared_ptr<const AxisModel>> axisModelFor(const Take& take, const AxisOptions& options, bool fitToSkeleton)
{
    if (usesSegmentModel(take)) {
        auto body = segmentBody(take, SegmentModelOptions{options.segments});
        if (!body) return body.error();
        return std::make_shared<const AxisModel>(std::move(body->model));
    }
    if (fitToSkeleton && take.skeleton)
        return std::make_shared<const AxisModel>(makeAxisModel(bodyForTake(defaultBodyDescription(), take), options));
    return defaultAxisModel(options);
}

namespace {

std::vector<std::string> axisDofNames()
{
    std::vector<std::string> names;
    for (const auto& channel : axisCoordinateChannels()) names.push_back(channel.name());
    return names;
}

} // namespace

const FunctionAxis* AxisOutput::function(const std::string& name) const
{
    for (const auto& one : functions)
        if (one.function == name) return &one;
    return nullptr;
}

const CellAxis* AxisOutput::cell(const std::string& functionName, const std::string& emotion) const
{
    for (const auto& one : cells)
        if (one.function == functionName && one.emotion == emotion) return &one;
    return nullptr;
}

StageKey axisKey(StageKey normalised, const AxisParameters& p)
{
    return KeyBuilder("axes").add(normalised).add(parametersText(p)).key();
}

Result<AxisOutput> runAxes(const NormaliseOutput& normalised, const std::string& neutralEmotion, const AxisParameters& parameters,
                           const RunControl& control)
{
    if (auto status = validate(parameters); !status) return status.error();
    const AxisOptions axisOptions = parameters.axisOptions();
    AxisOutput out;
    // The axis integrates the puppet's parts, or a skeleton's body segments when the takes are
    // its joints (segment_inertia.h); a take with neither has no axis.
    for (const auto& cell : normalised.cells) {
        if (usesSegmentModel(cell.average)) continue;
        const auto parts = cell.average.parts();
        std::string missing;
        for (const auto part : kPuppetParts)
            if (std::find(parts.begin(), parts.end(), part) == parts.end()) missing += (missing.empty() ? "" : ", ") + std::string(part);
        if (missing.empty()) continue;
        out.unavailable = "motion axes, phase and gains (5) skipped: they integrate the puppet's parts (head, shoulder, arm, hand) "
                          "or a skeleton's segments, and the takes of " + cellName(cell.function, cell.emotion) + " have no " + missing +
                          " and no skeleton (" + std::to_string(parts.size()) + " parts)";
        control.report(1.0);
        return out;
    }
    // Functions (their neutral cells), then their emotional cells: independent items, each
    // computed on control.threads threads into its own slot and gathered in cell order.
    std::vector<const CellNormalisation*> neutrals;
    std::vector<std::pair<std::size_t, const CellNormalisation*>> emotional; // (function, cell)
    for (const auto& neutral : normalised.cells) {
        if (neutral.emotion != neutralEmotion) continue;
        for (const auto& cell : normalised.cells)
            if (cell.function == neutral.function && cell.emotion != neutralEmotion) emotional.emplace_back(neutrals.size(), &cell);
        neutrals.push_back(&neutral);
    }
    ItemProgress progress(control, neutrals.size() + emotional.size());
    auto cancelledOr = [](Status status) -> Status {
        if (!status && status.error().code == ErrorCode::Cancelled) return makeError(ErrorCode::Cancelled, "motion axes cancelled");
        return status;
    };
    out.functions.resize(neutrals.size());
    Status status = parallelFor(
        neutrals.size(), control.threads,
        [&](std::size_t f) -> Status {
            const CellNormalisation& neutral = *neutrals[f];
            auto model = axisModelFor(neutral.average, axisOptions);
            if (!model) return model.error();
            auto basis = prepareDesign(**model, neutral.average, axisOptions, RunControl{control.stop, {}});
            if (!basis)
                return makeError(basis.error().code, "motion axis of the " + neutral.function + "/" + neutral.emotion +
                                                         " average take: " + basis.error().message);
            FunctionAxis& function = out.functions[f];
            function.function = neutral.function;
            function.boundaries = suggestPhraseBoundaries(basis->coordinates);
            function.basis = std::make_shared<const DesignBasis>(std::move(basis).value());
            progress.finished();
            return okStatus();
        },
        control.stop);
    if (!status) return cancelledOr(status).error();
    out.cells.resize(emotional.size());
    status = parallelFor(
        emotional.size(), control.threads,
        [&](std::size_t c) -> Status {
            const FunctionAxis& function = out.functions[emotional[c].first];
            const CellNormalisation& cell = *emotional[c].second;
            const std::string name = cellName(cell.function, cell.emotion);
            auto model = axisModelFor(cell.average, axisOptions);
            if (!model) return makeError(model.error().code, "motion axis of the " + name + " average take: " + model.error().message);
            auto axis = computeMotionAxis(**model, cell.average, axisOptions, RunControl{control.stop, {}});
            if (!axis) return makeError(axis.error().code, "motion axis of the " + name + " average take: " + axis.error().message);
            CellAxis& result = out.cells[c];
            result.function = cell.function;
            result.emotion = cell.emotion;
            result.world_T_axis = axis->world_T_axis;
            result.coordinates = axisCoordinates(axis->world_T_axis);
            ExtractionOptions options = parameters.extractionOptions();
            options.boundaries = function.boundaries;
            auto extracted = extractDesign(function.basis->coordinates, result.coordinates, options, RunControl{control.stop, {}});
            if (!extracted) return makeError(extracted.error().code, "phase and gains of " + name + ": " + extracted.error().message);
            result.extracted = std::move(extracted).value();
            const DesignedMotion designed = designMotion(*function.basis, result.extracted.phase.curve, result.extracted.gains);
            result.designRelativeError = relativeError(designed.axisCoordinates, result.coordinates);
            result.undesignedRelativeError = relativeError(function.basis->coordinates, result.coordinates);
            ApproximationErrorOptions approximation;
            approximation.maxScale = parameters.maxScale;
            auto errors = approximationErrorByScale(function.basis->coordinates, result.extracted.emotionalOnFunctionalTime,
                                                    approximation, RunControl{control.stop, {}});
            if (!errors) return makeError(errors.error().code, "approximation error of " + name + ": " + errors.error().message);
            result.approximation = std::move(errors).value();
            progress.finished();
            return okStatus();
        },
        control.stop);
    if (!status) return cancelledOr(status).error();
    control.report(1.0);
    return out;
}

StageKey takeAxisKey(StageKey take, const AxisParameters& p)
{
    const nlohmann::json all = toJson(p);
    nlohmann::json used = nlohmann::json::object();
    for (const char* name : kTakeAxisParameters) used[name] = all.at(name);
    return KeyBuilder("take-axis").add(take).add(used.dump()).key();
}

Result<TakeAxis> runTakeAxis(const Take& take, const AxisParameters& parameters, const RunControl& control)
{
    if (auto status = validate(parameters); !status) return status.error();
    const AxisOptions options = parameters.axisOptions();
    // The axis of a take with its performer's skeleton integrates over the puppet fitted to it,
    // or over the performer's segments when the take's parts are the skeleton's joints.
    auto model = axisModelFor(take, options, true);
    if (!model) return makeError(model.error().code, "motion axis of " + take.displayName() + ": " + model.error().message);
    auto axis = computeMotionAxis(**model, take, options, control);
    if (!axis) return makeError(axis.error().code, "motion axis of " + take.displayName() + ": " + axis.error().message);
    TakeAxis out;
    out.coordinates = axisTake(*axis);
    out.coordinates.labels.source = "axis of " + take.displayName();
    out.world_T_axis = std::move(axis->world_T_axis);
    return out;
}

Result<Take> weightedTake(const DecomposeOutput& decomposed, const std::string& function, const std::string& emotion, double weight)
{
    return weightEmotion(decomposed.components, function, emotion, weight);
}

std::vector<Eigen::Index> boundariesInUse(const FunctionAxis& function, const PhraseBoundaries& edits)
{
    const Eigen::Index last = function.basis ? function.basis->functional.frameCount() - 1 : 0;
    if (edits.suggested || last < 2) return function.boundaries;
    std::vector<Eigen::Index> result{0};
    for (const Eigen::Index frame : edits.inner) {
        if (frame <= result.back() || frame >= last) return function.boundaries; // not valid for this take
        result.push_back(frame);
    }
    result.push_back(last);
    return result;
}

WarpCurve warpInUse(const FunctionAxis& function, const DesignEdits& edits)
{
    if (edits.warp && validateWarpCurve(*edits.warp).ok()) return *edits.warp;
    const Eigen::Index frames = function.basis ? function.basis->functional.frameCount() : 0;
    return frames > 1 ? identityWarp(frames) : WarpCurve{};
}

GainSet gainsInUse(const FunctionAxis& function, const DesignEdits& edits, const std::vector<std::string>& dofNames)
{
    GainSet set = unitGains(boundariesInUse(function, edits.boundaries), dofNames.empty() ? axisDofNames() : dofNames);
    for (const GainEdit& edit : edits.gains) {
        if (edit.phrase < 0 || std::size_t(edit.phrase) >= set.phrases.size()) continue;
        auto& dofs = set.phrases[std::size_t(edit.phrase)].dofs;
        if (edit.dof < 0 || std::size_t(edit.dof) >= dofs.size()) continue;
        dofs[std::size_t(edit.dof)].g0 = edit.g0;
        dofs[std::size_t(edit.dof)].g1 = edit.g1;
    }
    return set;
}

DesignedMotion designFunction(const FunctionAxis& function, const DesignEdits& edits)
{
    return designMotion(*function.basis, warpInUse(function, edits), gainsInUse(function, edits, {}));
}

} // namespace bunraku::analysis::pipeline
