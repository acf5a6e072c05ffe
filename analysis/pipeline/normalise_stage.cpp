// The normalisation stage (thesis 3): every cell normalised to its reference (3.6, 3.6.1),
// evaluated (3.8) and averaged (3.7).
#include "analysis/pipeline/stages.h"
#include "analysis/pipeline/parameters_json.h"

#include "analysis/core/parallel.h"
#include "analysis/normalise/average_take.h"

#include <algorithm>
#include <optional>
#include <string>

namespace bunraku::analysis::pipeline {
namespace {

Result<CellNormalisation> normaliseCell(const std::string& function, const std::string& emotion,
                                        const std::vector<const Take*>& takes, const NormaliseParameters& parameters,
                                        const RunControl& control)
{
    const std::string cell = cellName(function, emotion);
    auto prefixed = [&](const Error& error) { return makeError(error.code, "normalise " + cell + ": " + error.message); };
    CellNormalisation out;
    out.function = function;
    out.emotion = emotion;
    for (const Take* take : takes) out.takeIndices.push_back(take->labels.takeIndex);
    auto suggestion = suggestReference(takes, RunControl{control.stop, {}});
    if (!suggestion) return prefixed(suggestion.error());
    out.suggestion = std::move(suggestion).value();
    const NormaliseOptions options = parameters.options();

    // Thesis 3.7: the average take, based on the suggested reference ("5ave"; "4ave" without outliers).
    AverageOptions average;
    average.normalise = options;
    auto indexOf = [&](int takeIndex) {
        const auto found = std::find(out.takeIndices.begin(), out.takeIndices.end(), takeIndex);
        return found == out.takeIndices.end() ? -1 : int(found - out.takeIndices.begin());
    };
    average.baseTake = out.suggestion.takeIndex;
    if (parameters.averageBase > 0) {
        average.baseTake = indexOf(parameters.averageBase);
        if (average.baseTake < 0)
            return makeError(ErrorCode::NotFound, "normalise " + cell + ": the cell has no take " +
                                                      std::to_string(parameters.averageBase) + " to base the average on");
    }
    if (!parameters.averageExcluded.empty()) {
        for (int take : parameters.averageExcluded) {
            const int index = indexOf(take);
            if (index < 0)
                return makeError(ErrorCode::NotFound, "normalise " + cell + ": the cell has no take " + std::to_string(take) +
                                                          " to leave out of the average");
            if (index == average.baseTake)
                return makeError(ErrorCode::InvalidArgument, "normalise " + cell + ": take " + std::to_string(take) +
                                                                 " is the base of the average and cannot be left out");
            average.excludedTakes.push_back(index);
        }
    } else if (parameters.averageExcludesOutliers) {
        for (std::size_t k = 0; k < takes.size(); ++k)
            if (out.suggestion.outlier[k] && int(k) != average.baseTake) average.excludedTakes.push_back(int(k));
    }
    // The reference's index among the takes (none for the average take, or a missing take).
    out.reference = parameters.referenceFor(function, emotion);
    int referenceIndex = -1;
    if (out.reference.kind == ReferenceKind::Suggested) referenceIndex = out.suggestion.takeIndex;
    if (out.reference.kind == ReferenceKind::Take) referenceIndex = indexOf(out.reference.takeIndex);

    // Thesis 3.6.1's suggested reference is the base of the 3.7 average by default: the takes'
    // matchings to it serve both the normalisation and the average (averageTakeFrom, the same
    // bits as matching them twice).
    const bool baseIsReference = referenceIndex >= 0 && referenceIndex == average.baseTake;
    if (baseIsReference) {
        auto normalised = normaliseTakes(*takes[std::size_t(referenceIndex)], takes, options, RunControl{control.stop, {}});
        if (!normalised) return prefixed(normalised.error());
        out.normalisations = std::move(normalised).value();
        auto averaged = averageTakeFrom(takes, average, out.normalisations);
        if (!averaged) return prefixed(averaged.error());
        out.average = std::move(averaged).value();
    } else {
        auto averaged = averageTake(takes, average, RunControl{control.stop, {}});
        if (!averaged) return prefixed(averaged.error());
        out.average = std::move(averaged).value();
    }
    for (std::size_t k = 0; k < takes.size(); ++k)
        if (std::find(average.excludedTakes.begin(), average.excludedTakes.end(), int(k)) == average.excludedTakes.end())
            out.averageMembers.push_back(out.takeIndices[k]);
    out.averageName = std::to_string(out.averageMembers.size()) + "ave";

    switch (out.reference.kind) {
    case ReferenceKind::Suggested:
        out.referenceTake = *takes[std::size_t(out.suggestion.takeIndex)];
        out.referenceName = "take " + std::to_string(out.referenceTake.labels.takeIndex) + " (suggested)";
        break;
    case ReferenceKind::Take:
        if (referenceIndex < 0)
            return makeError(ErrorCode::NotFound, "normalise " + cell + ": the cell has no take " +
                                                      std::to_string(out.reference.takeIndex) + " to use as reference");
        out.referenceTake = *takes[std::size_t(referenceIndex)];
        out.referenceName = "take " + std::to_string(out.reference.takeIndex);
        break;
    case ReferenceKind::Average:
        out.referenceTake = out.average;
        out.referenceName = out.averageName;
        break;
    }
    if (!baseIsReference) {
        auto normalised = normaliseTakes(out.referenceTake, takes, options, RunControl{control.stop, {}});
        if (!normalised) return prefixed(normalised.error());
        out.normalisations = std::move(normalised).value();
    }
    std::vector<const Take*> results;
    for (auto& one : out.normalisations) {
        one.normalised.labels.source = "normalised to " + out.referenceName;
        results.push_back(&one.normalised);
    }
    auto variance = varianceTable(out.referenceTake, takes, results);
    if (!variance) return prefixed(variance.error());
    out.variance = std::move(variance).value();
    return out;
}

} // namespace

const CellNormalisation* NormaliseOutput::cell(const std::string& function, const std::string& emotion) const
{
    for (const auto& one : cells)
        if (one.function == function && one.emotion == emotion) return &one;
    return nullptr;
}

StageKey normaliseKey(StageKey preprocessed, const NormaliseParameters& p)
{
    return KeyBuilder("normalise").add(preprocessed).add(parametersText(p)).key();
}

Result<NormaliseOutput> runNormalise(const Corpus& preprocessed, const NormaliseParameters& parameters, const RunControl& control)
{
    if (auto status = validate(parameters); !status) return status.error();
    NormaliseOutput out;
    std::vector<std::pair<std::string, std::string>> cells;
    for (const auto& function : preprocessed.functions())
        for (const auto& emotion : preprocessed.emotions())
            if (!preprocessed.cell(function, emotion).empty()) cells.emplace_back(function, emotion);
    // Cells are independent: normalised on control.threads threads, each into its own slot,
    // then gathered in cell order (the same result for any thread count).
    std::vector<std::optional<CellNormalisation>> results(cells.size());
    ItemProgress progress(control, cells.size());
    const Status status = parallelFor(
        cells.size(), control.threads,
        [&](std::size_t c) -> Status {
            const auto& [function, emotion] = cells[c];
            auto cell = normaliseCell(function, emotion, preprocessed.cell(function, emotion), parameters, control);
            if (!cell) return cell.error();
            results[c] = std::move(cell).value();
            progress.finished();
            return okStatus();
        },
        control.stop);
    if (!status) {
        if (status.error().code == ErrorCode::Cancelled) return makeError(ErrorCode::Cancelled, "normalisation cancelled");
        return status.error();
    }
    out.normalised = preprocessed;
    for (std::size_t c = 0; c < cells.size(); ++c) {
        const auto& [function, emotion] = cells[c];
        CellNormalisation& cell = *results[c];
        for (std::size_t k = 0; k < cell.takeIndices.size(); ++k) {
            for (auto& take : out.normalised.takes)
                if (take.labels.function == function && take.labels.emotion == emotion &&
                    take.labels.takeIndex == cell.takeIndices[k]) {
                    take = cell.normalisations[k].normalised;
                    take.labels.takeIndex = cell.takeIndices[k];
                }
        }
        out.cells.push_back(std::move(cell));
    }
    return out;
}

} // namespace bunraku::analysis::pipeline
