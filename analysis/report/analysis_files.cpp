#include "analysis/report/analysis_files.h"

#include "analysis/axis/axis_channels.h"
#include "analysis/decompose/emotion_weight.h"
#include "analysis/io/atomic_file.h"
#include "analysis/io/staged_folder.h"
#include "analysis/io/take_csv.h"
#include "analysis/io/text_format.h"
#include "analysis/pipeline/parameters_json.h"

#include <nlohmann/json.hpp>

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
