#include "analysis/report/analysis_files.h"

#include "analysis/axis/axis_channels.h"
#include "analysis/decompose/emotion_weight.h"
#include "analysis/decompose/km2o_decomposition.h"
#include "analysis/decompose/spectrum.h"
#include "analysis/io/atomic_file.h"
#include "analysis/io/staged_folder.h"
#include "analysis/io/take_csv.h"
#include "analysis/io/text_format.h"
#include "analysis/pipeline/parameters_json.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace bunraku::analysis::report {
namespace {

using io::appendShortestNumber;
using io::shortestNumber;
using pipeline::ChainResult;

Take componentTake(const Decomposition& d, const Eigen::MatrixXd& values, TakeLabels labels)
{
    Take take;
    take.values = values;
    take.rateHz = d.rateHz;
    take.channels = d.channels;
    take.labels = std::move(labels);
    return take;
}

Take axisCoordinateTake(const Eigen::MatrixXd& coordinates, double rateHz, TakeLabels labels)
{
    Take take;
    take.values = coordinates;
    take.rateHz = rateHz;
    take.channels = axisCoordinateChannels();
    take.labels = std::move(labels);
    return take;
}

Result<std::string> takeCsv(const Take& take, const std::string& name)
{
    if (auto valid = validateTake(take); !valid) return makeError(valid.error().code, name + ": " + valid.error().message);
    return io::formatTakeCsv(take);
}

std::string gainsCsv(const GainSet& gains)
{
    std::string out = "phrase,dof,begin,end,g0,g1,dc_mode,offset,ac_mode,reason\n";
    for (std::size_t p = 0; p < gains.phrases.size(); ++p) {
        const PhraseGains& phrase = gains.phrases[p];
        for (std::size_t d = 0; d < phrase.dofs.size(); ++d) {
            const DofGain& g = phrase.dofs[d];
            out += std::to_string(p) + "," + (d < gains.dofNames.size() ? gains.dofNames[d] : std::to_string(d)) + "," +
                   std::to_string(phrase.begin) + "," + std::to_string(phrase.end) + ",";
            appendShortestNumber(out, g.g0);
            out += ',';
            appendShortestNumber(out, g.g1);
            out += g.dcMode == DcMode::Offset ? ",offset," : ",scale,";
            appendShortestNumber(out, g.offset);
            out += g.acMode == AcMode::Additive ? ",additive," : ",scale,";
            std::string reason = g.reason;
            for (char& c : reason)
                if (c == ',' || c == '\n' || c == '"') c = ';';
            out += reason + "\n";
        }
    }
    return out;
}

} // namespace

std::string cellStem(const std::string& function, const std::string& emotion)
{
    return io::fileSafeLabel(function) + "_" + io::fileSafeLabel(emotion);
}

std::string takeStem(const TakeLabels& labels) { return cellStem(labels.function, labels.emotion) + "_" + std::to_string(labels.takeIndex); }

std::string varianceCsv(const pipeline::CellNormalisation& cell)
{
    const VarianceTable& table = cell.variance;
    std::string out = "take,stage,total";
    for (const auto& name : table.channelNames) out += "," + name;
    out += "\n";
    for (std::size_t k = 0; k < table.takeNames.size(); ++k) {
        for (int stage = 0; stage < 2; ++stage) {
            const Eigen::MatrixXd& values = stage == 0 ? table.before : table.after;
            out += std::to_string(cell.takeIndices[k]) + (stage == 0 ? ",raw," : ",normalised,");
            appendShortestNumber(out, (stage == 0 ? table.totalBefore : table.totalAfter)[Eigen::Index(k)]);
            for (Eigen::Index c = 0; c < values.cols(); ++c) {
                out += ',';
                appendShortestNumber(out, values(Eigen::Index(k), c));
            }
            out += "\n";
        }
    }
    return out;
}

std::string correspondenceCsv(const TakeNormalisation& normalisation, Eigen::Index frames)
{
    std::string out = "t_ref";
    for (const auto& name : normalisation.coupling.names) out += "," + name;
    out += "\n";
    for (Eigen::Index t = 0; t < frames; ++t) {
        out += std::to_string(t);
        for (const auto& match : normalisation.matches) {
            out.push_back(',');
            out.append(std::to_string(match.correspondence[t]));
        }
        out += "\n";
    }
    return out;
}

Result<std::vector<OutputFile>> decompositionFiles(const pipeline::DecomposeOutput& decomposed)
{
    const Decomposition& d = decomposed.components;
    std::vector<OutputFile> files;
    for (const auto& y : d.functions) {
        // y as a pose (Euler angles); z's angle columns are rotation coordinates (docs/FORMATS.md)
        auto pose = functionComponentTake(d, y.function);
        if (!pose) return pose.error();
        pose->labels = {y.function, "", 0, "y"};
        const std::string name = "y_" + io::fileSafeLabel(y.function) + ".csv";
        auto csv = takeCsv(*pose, name);
        if (!csv) return csv.error();
        files.push_back({name, std::move(csv).value()});
    }
    for (const auto& z : d.emotions) {
        const std::string name = "z_" + cellStem(z.function, z.emotion) + ".csv";
        auto csv = takeCsv(componentTake(d, z.values, {z.function, z.emotion, 0, "z"}), name);
        if (!csv) return csv.error();
        files.push_back({name, std::move(csv).value()});
    }
    if (const auto& km2o = decomposed.km2o) {
        std::string byM = "M,mean_P_percent\n";
        for (std::size_t i = 0; i < km2o->candidateLengths.size(); ++i) {
            byM += std::to_string(km2o->candidateLengths[i]) + ",";
            appendShortestNumber(byM, km2o->meanErrorPercent[i]);
            byM += "\n";
        }
        files.push_back({"km2o_by_M.csv", byM});
        std::string errors = "channel";
        for (const auto& z : d.emotions) errors += ",P_" + z.function + "/" + z.emotion;
        errors += "\n";
        for (std::size_t ch = 0; ch < d.channels.size(); ++ch) {
            errors += d.channels[ch].name();
            for (Eigen::Index c = 0; c < km2o->cellErrorPercent.cols(); ++c) {
                errors += ',';
                appendShortestNumber(errors, km2o->cellErrorPercent(Eigen::Index(ch), c));
            }
            errors += "\n";
        }
        files.push_back({"km2o_errors.csv", errors});
    }
    return files;
}

Result<std::vector<OutputFile>> fluctuationTakeFiles(const Decomposition& d)
{
    std::vector<OutputFile> files;
    for (const auto& eta : d.fluctuations) {
        const std::string name = "eta_" + takeStem(eta.labels) + ".csv";
        auto csv = takeCsv(componentTake(d, eta.values, eta.labels), name);
        if (!csv) return csv.error();
        files.push_back({name, std::move(csv).value()});
    }
    return files;
}

namespace {

/// Each take's spectra of eta (spectra.csv holds the cells' averages).
Result<std::string> spectraCsv(const Decomposition& d, bool useWelch, int welchSegment)
{
    std::ostringstream out;
    out << std::setprecision(10) << "function,emotion,take,channel,frequency_hz,power\n";
    for (const auto& eta : d.fluctuations) {
        if (cellTakeCount(d, eta.labels.function, eta.labels.emotion) < 2) continue; // one take: no fluctuation (eq. 4.24)
        for (std::size_t ch = 0; ch < d.channels.size(); ++ch) {
            const Eigen::VectorXd x = eta.values.col(Eigen::Index(ch));
            WelchOptions welchOptions;
            welchOptions.segmentLength = std::min<int>(welchSegment, int(x.size()));
            auto spectrum = useWelch ? welch(x, d.rateHz, welchOptions) : periodogram(x, d.rateHz);
            if (!spectrum) return spectrum.error();
            const Spectrum& s = *spectrum;
            for (Eigen::Index k = 0; k < s.power.size(); ++k)
                out << eta.labels.function << ',' << eta.labels.emotion << ',' << eta.labels.takeIndex << ','
                    << d.channels[ch].name() << ',' << s.frequencyHz(k) << ',' << s.power(k) << '\n';
        }
    }
    return out.str();
}

std::string armaTakesCsv(const Decomposition& d, ArmaOrderSearch search, int maxOrder)
{
    std::ostringstream out;
    out << std::setprecision(8) << "function,emotion,take,channel,p,q,fpe,innovation_variance";
    for (int m = 1; m <= maxOrder; ++m) out << ",a" << m;
    for (int n = 0; n <= maxOrder; ++n) out << ",b" << n;
    for (int n = 0; n <= maxOrder; ++n) out << ",b" << n << "_thesis";
    out << '\n';
    ArmaOrderOptions options;
    options.maxOrder = maxOrder;
    options.search = search;
    for (const auto& eta : d.fluctuations) {
        if (cellTakeCount(d, eta.labels.function, eta.labels.emotion) < 2) continue; // one take: no fluctuation (eq. 4.24)
        for (std::size_t ch = 0; ch < d.channels.size(); ++ch) {
            const Eigen::VectorXd x = eta.values.col(Eigen::Index(ch));
            if (!(x.squaredNorm() > 0.0)) continue;
            auto selection = selectArmaOrder(x, options);
            if (!selection) continue; // too short for any order: nothing to report
            const ArmaModel& m = selection->best;
            out << eta.labels.function << ',' << eta.labels.emotion << ',' << eta.labels.takeIndex << ','
                << d.channels[ch].name() << ',' << m.p << ',' << m.q << ',' << m.fpe << ',' << m.innovationVariance;
            for (int i = 0; i < maxOrder; ++i) out << ',' << (i < m.p ? std::to_string(m.a(i)) : "");
            for (int i = 0; i <= maxOrder; ++i) out << ',' << (i <= m.q ? std::to_string(m.b(i)) : "");
            for (int i = 0; i <= maxOrder; ++i) out << ',' << (i <= m.q ? std::to_string(m.bThesis(i)) : "");
            out << '\n';
        }
    }
    return out.str();
}

} // namespace

Result<nlohmann::json> groundTruthErrorsJson(const Decomposition& d, const synth::DemoGroundTruth& truth)
{
    nlohmann::json out = nlohmann::json::object();
    auto percent = [](const Eigen::MatrixXd& estimate, const Eigen::MatrixXd& reference) {
        const double den = reference.squaredNorm();
        return den > 0.0 ? 100.0 * (estimate - reference).squaredNorm() / den : 0.0;
    };
    auto rms = [](const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
        return std::sqrt((a - b).squaredNorm() / double(std::max<Eigen::Index>(1, a.size())));
    };
    // y as a pose (Euler angles, compared modulo 360); z as rotation coordinates about the
    // function's chart on both sides (the truth's z is the difference of its cell motion and y).
    auto truthTake = [&](const Eigen::MatrixXd& values) {
        Take take;
        take.values = values;
        take.channels = d.channels;
        return take;
    };
    for (std::size_t i = 0; i < d.functions.size(); ++i) {
        const auto& f = d.functions[i];
        const auto* t = truth.function(f.function);
        if (!t || t->motion.rows() != f.values.rows() || t->motion.cols() != f.values.cols()) continue;
        auto component = functionComponentTake(d, f.function);
        if (!component) return component.error();
        Eigen::MatrixXd y = component->values;
        for (Eigen::Index c = 0; c < y.cols(); ++c)
            if (d.channels[std::size_t(c)].unit == "deg")
                for (Eigen::Index r = 0; r < y.rows(); ++r) y(r, c) = t->motion(r, c) + std::remainder(y(r, c) - t->motion(r, c), 360.0);
        out["y"][f.function] = {{"relative_error_percent", percent(y, t->motion)}, {"rms", rms(y, t->motion)}};
    }
    for (const auto& z : d.emotions) {
        const auto* t = truth.cell(z.function, z.emotion);
        const auto* y = truth.function(z.function);
        const int function = [&] {
            for (std::size_t i = 0; i < d.functions.size(); ++i)
                if (d.functions[i].function == z.function) return int(i);
            return -1;
        }();
        if (!t || !y || function < 0 || t->motion.rows() != z.values.rows() || t->motion.cols() != z.values.cols() ||
            y->motion.rows() != z.values.rows())
            continue;
        const RotationChart& chart = d.charts[std::size_t(function)];
        const Eigen::MatrixXd trueZ = rotationCoordinates(truthTake(t->motion), chart) - rotationCoordinates(truthTake(y->motion), chart);
        out["z"][z.function + "/" + z.emotion] = {{"rms", rms(z.values, trueZ)}};
    }
    return out;
}

Result<std::vector<OutputFile>> takeFluctuationFiles(const Decomposition& d, const TakeFluctuationOptions& options)
{
    std::vector<OutputFile> files;
    for (const bool useWelch : {false, true}) {
        auto csv = spectraCsv(d, useWelch, options.welchSegment);
        if (!csv) return csv.error();
        files.push_back({useWelch ? "spectra_welch.csv" : "spectra_periodogram.csv", std::move(csv).value()});
    }
    files.push_back({"arma_takes.csv", armaTakesCsv(d, options.search, options.armaMaxOrder)});
    return files;
}

std::vector<OutputFile> fluctuationFiles(const pipeline::FluctuationOutput& fluctuations)
{
    std::vector<OutputFile> files;
    std::string spectra = "function,emotion,channel,frequency_hz,power\n";
    for (const auto& cell : fluctuations.spectra)
        for (Eigen::Index ch = 0; ch < cell.power.cols(); ++ch)
            for (Eigen::Index k = 0; k < cell.power.rows(); ++k) {
                spectra += cell.function + "," + cell.emotion + "," + fluctuations.channelNames[std::size_t(ch)] + ",";
                appendShortestNumber(spectra, cell.frequencyHz[k]);
                spectra += ',';
                appendShortestNumber(spectra, cell.power(k, ch));
                spectra += "\n";
            }
    files.push_back({"spectra.csv", spectra});
    std::string arma = "channel,function,emotion,takes";
    for (int m = 1; m <= fluctuations.armaP; ++m) arma += ",a" + std::to_string(m);
    for (int n = 0; n <= fluctuations.armaQ; ++n) arma += ",b" + std::to_string(n);
    for (int n = 0; n <= fluctuations.armaQ; ++n) arma += ",b" + std::to_string(n) + "_thesis";
    arma += ",innovation_variance,fpe\n";
    for (std::size_t ch = 0; ch < fluctuations.armaTables.size(); ++ch)
        for (const auto& row : fluctuations.armaTables[ch]) {
            if (row.takes == 0) continue;
            arma += fluctuations.channelNames[ch] + "," + row.function + "," + row.emotion + "," + std::to_string(row.takes);
            const auto field = [&arma](double value) {
                arma += ',';
                appendShortestNumber(arma, value);
            };
            for (int m = 0; m < fluctuations.armaP; ++m) field(row.mean.a(m));
            for (int n = 0; n <= fluctuations.armaQ; ++n) field(row.mean.b(n));
            for (int n = 0; n <= fluctuations.armaQ; ++n) field(row.mean.bThesis(n));
            field(row.mean.innovationVariance);
            field(row.mean.fpe);
            arma += '\n';
        }
    files.push_back({"arma_table.csv", arma});
    return files;
}

nlohmann::json km2oOutcomeJson(const Km2oDecomposition& km2o)
{
    nlohmann::json cells = nlohmann::json::array();
    for (const auto& cell : km2o.cells)
        cells.push_back({{"function", cell.function},
                         {"emotion", cell.emotion},
                         {"takes", cell.takes},
                         {"gamma", km2oCellSourceName(cell.source)}});
    return {{"estimable", km2o.estimable()}, {"outcome", km2o.outcome()}, {"notes", km2o.notes}, {"cells", std::move(cells)}};
}

Result<std::vector<OutputFile>> analysisDataFiles(const ChainResult& chain, const pipeline::ChainParameters& parameters)
{
    if (!chain.preprocessed || !chain.normalised || !chain.decomposed || !chain.fluctuations || !chain.axes)
        return makeError(ErrorCode::InvalidArgument, "the analysis files need every stage's result");
    std::vector<OutputFile> files;
    auto addTake = [&](const Take& take, const std::string& name) -> Status {
        auto csv = takeCsv(take, name);
        if (!csv) return csv.error();
        files.push_back({name, std::move(csv).value()});
        return okStatus();
    };
    files.push_back({"parameters.json", nlohmann::json{{"parameters", pipeline::toJson(parameters)}}.dump(2) + "\n"});
    for (const auto& take : chain.preprocessed->corpus.takes)
        if (auto s = addTake(take, "preprocessed_" + takeStem(take.labels) + ".csv"); !s) return s.error();

    nlohmann::json cells = nlohmann::json::array();
    for (const auto& cell : chain.normalised->cells) {
        const std::string stem = cellStem(cell.function, cell.emotion);
        for (std::size_t k = 0; k < cell.normalisations.size(); ++k) {
            Take normalised = cell.normalisations[k].normalised;
            normalised.labels.takeIndex = cell.takeIndices[k];
            const std::string takeName = stem + "_" + std::to_string(cell.takeIndices[k]);
            if (auto s = addTake(normalised, "normalised_" + takeName + ".csv"); !s) return s.error();
            files.push_back({"correspondence_" + takeName + ".csv",
                             correspondenceCsv(cell.normalisations[k], cell.referenceTake.frameCount())});
        }
        if (auto s = addTake(cell.referenceTake, "reference_" + stem + ".csv"); !s) return s.error();
        if (auto s = addTake(cell.average, "average_" + stem + ".csv"); !s) return s.error();
        files.push_back({"variance_" + stem + ".csv", varianceCsv(cell)});
        cells.push_back({{"function", cell.function},
                         {"emotion", cell.emotion},
                         {"reference", cell.referenceName},
                         {"suggested_reference", cell.takeIndices[std::size_t(cell.suggestion.takeIndex)]},
                         {"average", cell.averageName},
                         {"average_members", cell.averageMembers},
                         {"variance_raw_total", cell.variance.totalBefore.sum()},
                         {"variance_normalised_total", cell.variance.totalAfter.sum()}});
    }

    const Decomposition& d = chain.decomposed->components;
    auto decomposed = decompositionFiles(*chain.decomposed);
    if (!decomposed) return decomposed.error();
    for (auto& file : *decomposed) files.push_back(std::move(file));
    nlohmann::json decomposition{{"method", pipeline::methodName(chain.decomposed->parameters.method)},
                                 {"input", pipeline::inputName(chain.decomposed->parameters.input)}};
    if (const auto& km2o = chain.decomposed->km2o) {
        decomposition["km2o"] = km2oOutcomeJson(*km2o);
        if (km2o->estimable()) { // else no M was chosen: y, z by least squares
            decomposition["M"] = km2o->correlationLength;
            decomposition["candidate_M"] = km2o->candidateLengths;
            decomposition["mean_P_percent_by_M"] = km2o->meanErrorPercent;
            decomposition["mean_P_percent"] = km2o->meanCellErrorPercent;
        }
    }
    for (auto& file : fluctuationFiles(*chain.fluctuations)) files.push_back(std::move(file));

    nlohmann::json axes = nlohmann::json::array();
    for (const auto& function : chain.axes->functions) {
        const DesignBasis& basis = *function.basis;
        if (auto s = addTake(axisCoordinateTake(basis.coordinates, basis.functional.rateHz, {function.function, "", 0, "axis"}),
                             "axis_functional_" + io::fileSafeLabel(function.function) + ".csv");
            !s)
            return s.error();
    }
    for (const auto& cell : chain.axes->cells) {
        const std::string stem = cellStem(cell.function, cell.emotion);
        const double rate = chain.corpus.corpus->rateHz;
        if (auto s = addTake(axisCoordinateTake(cell.coordinates, rate, {cell.function, cell.emotion, 0, "axis"}),
                             "axis_emotional_" + stem + ".csv");
            !s)
            return s.error();
        std::string warp = "output_frame,source_frame\n";
        for (const WarpPoint& point : cell.extracted.phase.curve.points)
            warp += shortestNumber(point.output) + "," + shortestNumber(point.source) + "\n";
        files.push_back({"warp_" + stem + ".csv", warp});
        std::string phase = "emotional_frame,functional_frame\n";
        for (Eigen::Index t = 0; t < cell.extracted.phase.emotionalToFunctional.size(); ++t)
            phase += std::to_string(t) + "," + shortestNumber(cell.extracted.phase.emotionalToFunctional[t]) + "\n";
        files.push_back({"phase_" + stem + ".csv", phase});
        files.push_back({"gains_" + stem + ".csv", gainsCsv(cell.extracted.gains)});
        // 5.4.1, eq. 5.18, Fig. 5.16: one row per largest scale c, one column per axis DOF and the mean
        const ApproximationError& approximation = cell.approximation;
        std::string scales = "scale";
        for (const auto& channel : axisCoordinateChannels()) scales += "," + channel.name();
        scales += ",mean\n";
        for (std::size_t c = 0; c < approximation.scales.size(); ++c) {
            scales += std::to_string(approximation.scales[c]);
            for (Eigen::Index q = 0; q < approximation.relativeError.cols(); ++q)
                scales += "," + shortestNumber(approximation.relativeError(Eigen::Index(c), q));
            scales += "," + shortestNumber(approximation.meanRelativeError(Eigen::Index(c))) + "\n";
        }
        files.push_back({"approximation_" + stem + ".csv", scales});
        axes.push_back({{"function", cell.function},
                        {"emotion", cell.emotion},
                        {"phrase_boundaries", chain.axes->function(cell.function)->boundaries},
                        {"design_relative_error", cell.designRelativeError},
                        {"undesigned_relative_error", cell.undesignedRelativeError},
                        {"phase_cost", cell.extracted.phase.cost}});
    }

    nlohmann::json keys = nlohmann::json::object();
    for (pipeline::Stage stage : pipeline::kStages) keys[pipeline::stageName(stage)] = chain.keys.of(stage).hex();
    std::vector<std::string> names;
    for (const auto& file : files) names.push_back(file.name);
    names.push_back("summary.json");
    const nlohmann::json summary{{"corpus", chain.corpus.corpus->name},
                                 {"takes", chain.corpus.corpus->takes.size()},
                                 {"frames", d.frameCount()},
                                 {"channels", d.channels.size()},
                                 {"keys", keys},
                                 {"cells", cells},
                                 {"decomposition", decomposition},
                                 {"axes", axes},
                                 {"axes_unavailable", chain.axes->unavailable},
                                 {"files", names}};
    files.push_back({"summary.json", summary.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n"});
    return files;
}

Status writeOutputFiles(const std::filesystem::path& folder, const std::vector<OutputFile>& files)
{
    auto staged = io::StagedFolder::begin(folder);
    if (!staged) return staged.error();
    for (const auto& file : files)
        if (auto status = staged->writeFile(file.name, file.content); !status) return status;
    return staged->commit();
}

} // namespace bunraku::analysis::report
