// The decomposition stage (thesis 4: least squares 4.3.1 or KM2O-Langevin 4.4.4) and the
// fluctuation analysis of its eta (4.3.2: spectra, Table 4.1's ARMA parameters).
#include "analysis/pipeline/stages.h"
#include "analysis/pipeline/parameters_json.h"

#include "analysis/core/parallel.h"

#include <algorithm>

namespace bunraku::analysis::pipeline {

StageKey decomposeKey(StageKey input, const DecomposeParameters& p)
{
    return KeyBuilder("decompose").add(input).add(parametersText(p)).key();
}

Result<DecomposeOutput> runDecompose(const Corpus& input, const DecomposeParameters& parameters, const RunControl& control)
{
    if (auto status = validate(parameters); !status) return status.error();
    DecomposeOutput out;
    out.parameters = parameters;
    if (parameters.method == DecomposeMethod::LeastSquares) {
        auto decomposition = decomposeLeastSquares(input);
        if (!decomposition) return decomposition.error();
        out.components = std::move(decomposition).value();
        control.report(1.0);
        return out;
    }
    Km2oDecompositionOptions options;
    options.correlationLength = parameters.correlationLength; // 0: chosen by P (4.4.4)
    auto decomposition = decomposeKm2o(input, options, control);
    if (!decomposition) return decomposition.error();
    out.components = decomposition->components;
    out.km2o = std::move(decomposition).value();
    return out;
}

StageKey fluctuationKey(StageKey decomposed, const FluctuationParameters& p)
{
    return KeyBuilder("fluctuations").add(decomposed).add(parametersText(p)).key();
}

Result<FluctuationOutput> runFluctuations(const Decomposition& d, const FluctuationParameters& parameters, const RunControl& control)
{
    if (auto status = validate(parameters); !status) return status.error();
    FluctuationOutput out;
    out.armaP = parameters.armaP;
    out.armaQ = parameters.armaQ;
    for (const auto& channel : d.channels) out.channelNames.push_back(channel.name());
    const auto channels = Eigen::Index(d.channels.size());
    // Welch spectra of eta, averaged over each cell's takes (thesis Figures 4.3-4.8).
    for (const auto& cell : d.emotions) {
        CellSpectra spectra{cell.function, cell.emotion, {}, {}};
        // A one-take cell has no fluctuation to analyse (its take is its mean, eq. 4.24): no spectrum.
        if (cellTakeCount(d, cell.function, cell.emotion) < 2) {
            out.spectra.push_back(std::move(spectra));
            continue;
        }
        int takes = 0;
        for (const auto& eta : d.fluctuations) {
            if (eta.labels.function != cell.function || eta.labels.emotion != cell.emotion) continue;
            for (Eigen::Index ch = 0; ch < channels; ++ch) {
                WelchOptions options;
                options.segmentLength = std::min<int>(parameters.welchSegment, int(eta.values.rows()));
                auto spectrum = welch(eta.values.col(ch), d.rateHz, options);
                if (!spectrum)
                    return makeError(spectrum.error().code, "spectrum of eta " + eta.labels.function + "/" + eta.labels.emotion +
                                                                "/" + std::to_string(eta.labels.takeIndex) + ", " +
                                                                d.channels[std::size_t(ch)].name() + ": " + spectrum.error().message);
                if (spectra.power.size() == 0) {
                    spectra.frequencyHz = spectrum->frequencyHz;
                    spectra.power = Eigen::MatrixXd::Zero(spectrum->power.size(), channels);
                }
                spectra.power.col(ch) += spectrum->power;
            }
            ++takes;
        }
        if (takes > 0) spectra.power /= double(takes);
        out.spectra.push_back(std::move(spectra));
    }
    if (control.cancelled()) return makeError(ErrorCode::Cancelled, "fluctuation analysis cancelled");
    control.report(0.2);
    // Table 4.1: ARMA(p, q) per take, averaged per cell, for every channel: channels are
    // independent, fitted on control.threads threads into their own slots.
    out.armaTables.resize(std::size_t(channels));
    out.armaErrors.resize(std::size_t(channels));
    ItemProgress progress(control, std::size_t(channels), 0.2, 1.0);
    const Status status = parallelFor(
        std::size_t(channels), control.threads,
        [&](std::size_t ch) -> Status {
            auto table = armaCellTable(d, Eigen::Index(ch), parameters.armaP, parameters.armaQ);
            out.armaTables[ch] = table ? std::move(table).value() : std::vector<ArmaCellRow>{};
            out.armaErrors[ch] = table ? std::string() : table.error().message;
            progress.finished();
            return okStatus();
        },
        control.stop);
    if (!status) return makeError(ErrorCode::Cancelled, "fluctuation analysis cancelled");
    return out;
}

} // namespace bunraku::analysis::pipeline
