#include "analysis/report/experiment_tables.h"

#include "analysis/axis/axis_channels.h"
#include "analysis/design/motion_design.h"
#include "analysis/design/phase_extraction.h"
#include "analysis/design/phrase_gains.h"

#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace bunraku::analysis::report {
namespace {

using nlohmann::json;

json methodsJson(const std::vector<MethodError>& methods)
{
    json out = json::array();
    for (const auto& method : methods)
        out.push_back({{"name", method.name},
                       {"mean_abs_error_frames", method.meanAbsErrorFrames},
                       {"max_abs_error_frames", method.maxAbsErrorFrames},
                       {"shape_rms", method.shapeRms},
                       {"scales", method.scales}});
    return out;
}

/// "28..36" for consecutive scales, else the list.
std::string scaleText(const std::vector<double>& scales)
{
    if (scales.empty()) return "-";
    bool consecutive = true;
    for (std::size_t i = 1; i < scales.size(); ++i) consecutive = consecutive && scales[i] == scales[i - 1] + 1.0;
    std::ostringstream out;
    if (consecutive) {
        out << scales.front() << ".." << scales.back();
    } else {
        for (std::size_t i = 0; i < scales.size(); ++i) out << (i ? "," : "") << scales[i];
    }
    return out.str();
}

void noiseTable(std::ostream& out, const std::string& title, const NoiseExperimentResult& result)
{
    out << title << "\n    method                     scales     mean |err|   max |err|   shape RMS\n";
    for (const auto& method : result.methods)
        out << "    " << std::left << std::setw(27) << method.name << std::setw(9) << scaleText(method.scales) << std::right
            << std::fixed << std::setprecision(3) << std::setw(12) << method.meanAbsErrorFrames << std::setw(12)
            << method.maxAbsErrorFrames << std::setw(12) << method.shapeRms << "\n";
}

NoiseExperimentOptions constrained(NoiseExperimentOptions options)
{
    options.path = PathMethod::Optimal;
    options.tau = 4;
    return options;
}

/// NaN (a value the thesis does not have) as null.
json finiteOrNull(const std::vector<double>& values)
{
    json out = json::array();
    for (double x : values) out.push_back(std::isfinite(x) ? json(x) : json(nullptr));
    return out;
}

/// Table 4.4 as printed beside each M (T = 1000 in units of 0.1 %, so also "read as %").
std::vector<double> table44Printed(const Km2oExperimentResult& result)
{
    const auto printed = thesisTable44Printed(result.finalTime);
    std::vector<double> asPrinted;
    for (int m : result.correlationLengths)
        asPrinted.push_back(m >= 3 && m <= 20 && !printed.empty() ? printed[std::size_t(m - 3)]
                                                                  : std::numeric_limits<double>::quiet_NaN());
    return asPrinted;
}

const char* noiseSharingName(NoiseSharing sharing) { return sharing == NoiseSharing::SharedAcrossCells ? "shared" : "per-cell"; }

} // namespace

Result<NoiseComparison> runNoiseComparison()
{
    NoiseComparison comparison;
    const NoiseExperimentOptions thesis = thesisBandOptions(comparison.ours);
    for (auto [result, options] : {std::pair{&comparison.thesis, thesis}, std::pair{&comparison.thesisConstrained, constrained(thesis)},
                                   std::pair{&comparison.workbench, comparison.ours},
                                   std::pair{&comparison.workbenchConstrained, constrained(comparison.ours)}}) {
        auto run = runNoiseExperiment(options);
        if (!run) return run.error();
        *result = std::move(run).value();
    }
    return comparison;
}

json noiseComparisonJson(const NoiseComparison& c)
{
    const ThesisNoiseBands bands;
    const NoiseExperimentOptions& ours = c.ours;
    return {{"thesis_bands",
             {{"bands",
               {{"below_noise_of_reference_frequency", {bands.lowestOfReference, bands.highestOfReference}},
                {"with_noise_band_of_noise_frequency_max", bands.highestOfNoise}}},
              {"methods", methodsJson(c.thesis.methods)},
              {"with_time_constraint", {{"path", "optimal"}, {"tau", 4}, {"methods", methodsJson(c.thesisConstrained.methods)}}}}},
            {"methods", methodsJson(c.workbench.methods)},
            {"setup",
             {{"frames", ours.frames},
              {"reference_frequency", ours.referenceFrequency},
              {"sample_frequency", ours.sampleFrequency},
              {"phase_shift_rad", ours.phaseShiftRadians},
              {"noise_amplitude", ours.noiseAmplitude},
              {"noise_frequency", ours.noiseFrequency},
              {"tau", ours.tau},
              {"tcmp", ours.searchBand},
              {"path", "independent (thesis 3.3/3.4 single-frame matching)"}}},
            {"with_time_constraint", {{"path", "optimal"}, {"tau", 4}, {"methods", methodsJson(c.workbenchConstrained.methods)}}}};
}

std::string noiseComparisonText(const NoiseComparison& c)
{
    std::ostringstream out;
    out << "thesis 3.4: sine 0.025 cycles/frame, 200 frames; sample 1.1x, phase -0.4 rad, + 0.4 sin at 4x as noise\n"
        << "error vs the true warp (frames) and RMS of the normalised noiseless sample vs the reference\n";
    noiseTable(out, "thesis bands (0.894-1.151 x the signal's frequency; with noise: up to 2 x the noise's), single frames, T_cmp 20:",
               c.thesis);
    noiseTable(out, "thesis bands, windows (tau 4) and the optimal monotone path:", c.thesisConstrained);
    noiseTable(out, "workbench bands (14..20 below the noise; 1..20 with it), single frames, T_cmp 20:", c.workbench);
    noiseTable(out, "workbench bands, windows (tau 4) and the optimal monotone path:", c.workbenchConstrained);
    return out.str();
}

json truthExperimentJson(const TruthExperimentResult& result, const TruthExperimentOptions& options)
{
    const TruthMethodResult* optimal = nullptr;
    for (const auto& method : result.methods)
        if (method.name == "wavelet-optimal") optimal = &method;
    json methods = json::array();
    for (const auto& method : result.methods)
        methods.push_back({{"name", method.name},
                           {"mean_abs_error_frames", method.meanAbsErrorFrames},
                           {"max_abs_error_frames", method.maxAbsErrorFrames},
                           {"arm_hand_within_range", method.armHandWithinRange},
                           {"arm_hand_max_excess_cm", method.armHandMaxExcessCm}});
    return {{"methods", methods},
            {"cells", result.cells},
            {"pairs", result.pairs},
            {"coupling", options.normalise.coupling},
            {"arm_hand_together", optimal && optimal->armHandWithinRange >= 0.99}};
}

std::string truthExperimentText(const TruthExperimentResult& result, const TruthExperimentOptions& options)
{
    std::ostringstream out;
    out << result.cells << " cells, " << result.pairs << " take pairs per method (coupling " << options.normalise.coupling << ")\n"
        << "method                        mean |err|  max |err|  arm-hand in range\n";
    for (const auto& method : result.methods)
        out << std::left << std::setw(30) << method.name << std::right << std::fixed << std::setprecision(3) << std::setw(10)
            << method.meanAbsErrorFrames << std::setw(11) << method.maxAbsErrorFrames << std::setw(18) << method.armHandWithinRange
            << "\n";
    return out.str();
}

json km2oExperimentJson(const Km2oExperimentResult& result, const Km2oExperimentOptions& options)
{
    return {{"T", result.finalTime},
            {"M", result.correlationLengths},
            {"P_percent", finiteOrNull(result.errorPercent)},
            {"thesis_P_percent", finiteOrNull(result.thesisErrorPercent)},
            {"thesis_printed", finiteOrNull(table44Printed(result))},
            {"seeds", options.seeds},
            {"takes", options.takes},
            {"noise_sharing", noiseSharingName(options.noise)},
            {"first_window_offset", options.reading.firstWindowOffset},
            {"initial_times", options.reading.initialTimes == InitialTimeRange::Thesis ? "thesis" : "full"}};
}

std::string km2oExperimentText(const Km2oExperimentResult& result, const Km2oExperimentOptions& options)
{
    const std::vector<double> asPrinted = table44Printed(result);
    std::ostringstream out;
    out << "KM2O exogenous-input identification of the eq. 4.39 ARX series, T = " << result.finalTime << ", K = " << options.takes
        << ", " << options.seeds << " seed(s), noise " << noiseSharingName(options.noise)
        << "; P = relative error (eq. 4.40) averaged over the six inputs\n";
    const bool tenths = result.finalTime == 1000;
    out << "   M    P [%]   thesis Table 4.4 [%]" << (tenths ? "   (printed, read as %)" : "") << "\n";
    for (std::size_t i = 0; i < result.correlationLengths.size(); ++i) {
        out << std::setw(4) << result.correlationLengths[i] << std::setw(9) << std::fixed << std::setprecision(3)
            << result.errorPercent[i] << "   ";
        if (std::isfinite(result.thesisErrorPercent[i])) out << std::setw(8) << result.thesisErrorPercent[i];
        else out << "       -";
        if (tenths && std::isfinite(asPrinted[i])) out << std::setw(25) << asPrinted[i];
        out << "\n";
    }
    return out.str();
}

Result<DesignExperimentCell> runDesignExperimentCell(const AxisModel& model, const SyntheticDesignCell& designCell,
                                                     const ExtractionOptions& options, const AxisOptions& axisOptions)
{
    const DesignCell& cell = designCell.cell;
    auto result = evaluateDesignCell(model, cell, options, axisOptions);
    if (!result) return result.error();
    auto functional = computeMotionAxis(model, cell.functional, axisOptions);
    if (!functional) return functional.error();
    auto emotional = computeMotionAxis(model, cell.emotional, axisOptions);
    if (!emotional) return emotional.error();
    const Eigen::MatrixXd functionalAxis = axisCoordinates(functional->world_T_axis);
    const Eigen::VectorXd trueInverse = invertMonotone(cell.trueEmotionalToFunctional, functionalAxis.rows());
    const double amplitudeError = relativeError(applyGains(functionalAxis, result->parameters.gains),
                                                resampleRows(axisCoordinates(emotional->world_T_axis), trueInverse));
    return DesignExperimentCell{std::move(result).value(), amplitudeError, designCell.functionalMean.truthShapeError,
                                designCell.emotionalMean.truthShapeError};
}

json designExperimentCellJson(const DesignExperimentCell& cell)
{
    const DesignCellResult& result = cell.result;
    return {{"function", result.function},
            {"emotion", result.emotion},
            {"axis_relative_error", result.axisRelativeError},
            {"undesigned_relative_error", result.functionalRelativeError},
            {"dof_relative_error",
             std::vector<double>(result.dofRelativeError.data(), result.dofRelativeError.data() + result.dofRelativeError.size())},
            {"phase_mean_abs_error_frames", result.phaseMeanAbsErrorFrames},
            {"amplitude_relative_error", cell.amplitudeError},
            {"functional_mean_truth_error", cell.functionalMeanTruthError},
            {"emotional_mean_truth_error", cell.emotionalMeanTruthError},
            {"phrase_boundaries", result.boundaries}};
}

std::string designExperimentHeader()
{
    return "function      emotion     axis err  undesigned  phase |err| frames  amplitude err  phrases  mean vs truth (fun/emo)\n";
}

std::string designExperimentCellText(const DesignExperimentCell& cell)
{
    const DesignCellResult& result = cell.result;
    std::ostringstream out;
    out << std::left << std::setw(14) << result.function << std::setw(12) << result.emotion << std::right << std::fixed
        << std::setprecision(4) << std::setw(8) << result.axisRelativeError << std::setw(12) << result.functionalRelativeError
        << std::setprecision(2) << std::setw(20) << result.phaseMeanAbsErrorFrames << std::setprecision(4) << std::setw(15)
        << cell.amplitudeError << std::setw(9) << result.boundaries.size() - 1 << std::setw(10) << cell.functionalMeanTruthError
        << " / " << cell.emotionalMeanTruthError << "\n";
    return out.str();
}

} // namespace bunraku::analysis::report
