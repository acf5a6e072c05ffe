// The pipeline's stages for Python (analysis/pipeline): each is the function the workbench and
// the command line call (chain.h, stages.h), with the parameters read and validated by
// parameters_json.h; results hold the stage's own memory and Python sees it as NumPy views.
#include "bindings/python/common.h"

#include "app/cli/chain_parameters.h"
#include "app/cli/cli.h"

#include "analysis/axis/axis_channels.h"
#include "analysis/body/body_description.h"
#include "analysis/body/body_fit.h"
#include "analysis/cloth/kimono_cloth.h"
#include "analysis/core/parallel.h"
#include "analysis/decompose/emotion_weight.h"
#include "analysis/io/take_csv.h"
#include "analysis/normalise/variance_families.h"
#include "analysis/pipeline/chain.h"
#include "analysis/pipeline/parameters_json.h"
#include "analysis/report/analysis_files.h"

#include <nlohmann/json.hpp>
#include <pybind11/eigen.h>

#include <cmath>
#include <sstream>

namespace bunraku::python {
namespace {

namespace an = bunraku::analysis;
namespace pl = bunraku::analysis::pipeline;
namespace rp = bunraku::analysis::report;

template <class T> using Ptr = std::shared_ptr<T>;
using TakePtr = std::shared_ptr<an::Take>;

struct Preprocessed {
    pl::CorpusInput input;
    pl::Shared<pl::PreprocessOutput> output;
    pl::StageKey key;
};

struct Normalisation {
    Ptr<const Preprocessed> preprocessed;
    pl::Shared<pl::NormaliseOutput> output;
    pl::StageKey key;
};

struct Decomposed {
    Ptr<const Normalisation> normalisation;
    pl::Shared<pl::DecomposeOutput> output;
    pl::StageKey key;
};

struct Fluctuations {
    pl::Shared<pl::FluctuationOutput> output;
};

struct Axes {
    Ptr<const Normalisation> normalisation;
    pl::Shared<pl::AxisOutput> output;
    pl::AxisParameters parameters;
};

/// One take of a normalised cell: what `bunraku normalise --json` reports under "takes".
struct NormalisedTake {
    pl::Shared<pl::CellNormalisation> cell;
    std::size_t k = 0;
};

struct Phase {
    pl::Shared<an::PhaseResult> phase;
};

struct Gains {
    pl::Shared<an::GainSet> gains;
};

struct Designed {
    pl::Shared<an::DesignedMotion> motion;
};

struct TakeAxis {
    pl::Shared<pl::TakeAxis> axis;
};

/// A take's kimono simulated as cloth (analysis/cloth) and the take it was simulated for.
struct Kimono {
    std::shared_ptr<const an::KimonoSimulation> simulation;
    std::shared_ptr<const an::Take> take;
};

struct Analysis {
    pl::ChainResult chain;
    pl::ChainParameters parameters;
    Ptr<const Preprocessed> preprocessed;
    Ptr<const Normalisation> normalisation;
    Ptr<const Decomposed> decomposed;
    Ptr<const Fluctuations> fluctuations;
    Ptr<const Axes> axes;
};

/// A stage's error as runChain words it: "<stage title>: <message>".
template <class T> T staged(pl::Stage stage, an::Result<T> result)
{
    if (!result.ok()) throw Failure(std::string(pl::stageTitle(stage)) + ": " + result.error().message);
    return std::move(result).value();
}

pl::CorpusInput corpusInput(const an::Corpus& corpus) { return unwrap(pl::makeCorpusInput(corpus)); }

py::object pandas() { return py::module_::import("pandas"); }

/// "a1", "b0_thesis": the ARMA table's column names (built without operator+, which GCC 12's
/// -Wrestrict misreads here).
std::string numbered(const char* prefix, int n, const char* suffix = "")
{
    std::string name(prefix);
    name.append(std::to_string(n)).append(suffix);
    return name;
}

std::vector<std::string> names(const std::vector<an::Channel>& channels)
{
    std::vector<std::string> out;
    for (const auto& channel : channels) out.push_back(channel.name());
    return out;
}

py::array copyMatrix(const Eigen::MatrixXd& m)
{
    py::array_t<double> out({py::ssize_t(m.rows()), py::ssize_t(m.cols())});
    auto w = out.mutable_unchecked<2>();
    for (Eigen::Index r = 0; r < m.rows(); ++r)
        for (Eigen::Index c = 0; c < m.cols(); ++c) w(r, c) = m(r, c);
    return out;
}

py::array posesArray(const std::vector<an::RigidTransform>& poses)
{
    py::array_t<double> out({py::ssize_t(poses.size()), py::ssize_t(4), py::ssize_t(4)});
    auto w = out.mutable_unchecked<3>();
    for (std::size_t f = 0; f < poses.size(); ++f) {
        const Eigen::Matrix4d matrix = poses[f].isometry().matrix();
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c) w(py::ssize_t(f), r, c) = matrix(r, c);
    }
    return out;
}

const pl::CellNormalisation& findCell(const pl::NormaliseOutput& output, const std::string& function, const std::string& emotion)
{
    if (const auto* cell = output.cell(function, emotion)) return *cell;
    std::string cells;
    for (const auto& cell : output.cells) cells += (cells.empty() ? "" : ", ") + cell.function + "/" + cell.emotion;
    throw Failure("no normalised cell " + function + "/" + emotion + " (cells: " + cells + ")");
}

const pl::CellAxis& findCellAxis(const pl::AxisOutput& axes, const std::string& function, const std::string& emotion)
{
    if (const auto* cell = axes.cell(function, emotion)) return *cell;
    std::string cells;
    for (const auto& cell : axes.cells) cells += (cells.empty() ? "" : ", ") + cell.function + "/" + cell.emotion;
    throw Failure("no emotional cell " + function + "/" + emotion + " among the motion axes (cells: " + cells + ")");
}

const pl::FunctionAxis& findFunctionAxis(const pl::AxisOutput& axes, const std::string& function)
{
    if (const auto* found = axes.function(function)) return *found;
    std::string functions;
    for (const auto& f : axes.functions) functions += (functions.empty() ? "" : ", ") + f.function;
    throw Failure("no functional motion for " + function + " (functions: " + functions + ")");
}

py::dict normalisedTakeDict(const NormalisedTake& row)
{
    const pl::CellNormalisation& cell = *row.cell;
    const an::VarianceTable& table = cell.variance;
    py::list families;
    for (const an::VarianceRow& v : an::varianceRows(table, cell.referenceTake.channels))
        if (v.take == table.takeNames[row.k] && v.part.empty()) {
            py::dict family;
            family["family"] = v.family;
            family["unit"] = v.unit;
            family["raw"] = v.before;
            family["normalised"] = v.after;
            families.append(family);
        }
    py::dict out;
    out["take"] = cell.takeIndices[row.k];
    out["cost"] = cell.normalisations[row.k].cost;
    out["variance_raw"] = table.totalBefore[Eigen::Index(row.k)];
    out["variance_normalised"] = table.totalAfter[Eigen::Index(row.k)];
    out["families"] = families;
    out["outlier"] = bool(cell.suggestion.outlier[row.k]);
    return out;
}

/// The one cell of a normalisation asked for by function and emotion.
Ptr<pl::CellNormalisation> onlyCell(const Ptr<Normalisation>& n)
{
    if (n->output->cells.size() != 1)
        throw Failure("this normalisation has " + std::to_string(n->output->cells.size()) +
                      " cells: use .cells or .cell(function, emotion) (or normalise one cell with function= and emotion=)");
    return alias(n->output, n->output->cells.front());
}

Ptr<Normalisation> normaliseCorpus(const Ptr<const Preprocessed>& preprocessed, const pl::NormaliseParameters& parameters,
                                   const std::optional<std::string>& function, const std::optional<std::string>& emotion, int threads)
{
    if (function.has_value() != emotion.has_value())
        throw Failure("normalise: give both function and emotion (one cell) or neither (every cell)");
    auto result = std::make_shared<Normalisation>();
    result->preprocessed = preprocessed;
    result->key = pl::normaliseKey(preprocessed->key, parameters);
    const an::Corpus& corpus = preprocessed->output->corpus;
    if (!function) {
        result->output = staged(pl::Stage::Normalise, runReleased(
                                                          [&](const an::RunControl& control) {
                                                              return pl::normaliseStage(preprocessed->key, *preprocessed->output,
                                                                                        parameters, nullptr, control);
                                                          },
                                                          threads));
        return result;
    }
    // One cell, as `bunraku normalise CORPUS --function F --emotion E`: the preprocessed cell's
    // takes as a corpus of their own, through the stage's function.
    if (corpus.cell(*function, *emotion).empty()) {
        std::string cells;
        for (const auto& f : corpus.functions())
            for (const auto& e : corpus.emotions())
                if (!corpus.cell(f, e).empty()) cells += (cells.empty() ? "" : ", ") + f + "/" + e;
        throw Failure("no takes for " + *function + "/" + *emotion + " in " + corpus.name + " (cells: " + cells + ")");
    }
    an::Corpus cellCorpus = corpus;
    cellCorpus.takes.clear();
    for (const an::Take* take : corpus.cell(*function, *emotion)) cellCorpus.takes.push_back(*take);
    auto output = staged(pl::Stage::Normalise,
                         runReleased([&](const an::RunControl& control) { return pl::runNormalise(cellCorpus, parameters, control); },
                                     threads));
    result->output = std::make_shared<const pl::NormaliseOutput>(std::move(output));
    return result;
}

Ptr<Decomposed> decomposeNormalisation(const Ptr<const Normalisation>& normalisation, const pl::DecomposeParameters& parameters,
                                       int threads)
{
    const bool fromNormalised = parameters.input == pl::DecomposeInput::Normalised;
    const pl::StageKey inputKey = fromNormalised ? normalisation->key : normalisation->preprocessed->key;
    const an::Corpus& input = fromNormalised ? normalisation->output->normalised : normalisation->preprocessed->output->corpus;
    auto result = std::make_shared<Decomposed>();
    result->normalisation = normalisation;
    result->key = pl::decomposeKey(inputKey, parameters);
    result->output = staged(pl::Stage::Decompose, runReleased(
                                                      [&](const an::RunControl& control) {
                                                          return pl::decomposeStage(inputKey, input, parameters, nullptr, control);
                                                      },
                                                      threads));
    return result;
}

py::object gainsFrame(const an::GainSet& gains)
{
    py::dict columns;
    py::list phrase, dof, begin, end, g0, g1, dcMode, offset, acMode, reason;
    for (std::size_t p = 0; p < gains.phrases.size(); ++p) {
        const an::PhraseGains& ph = gains.phrases[p];
        for (std::size_t d = 0; d < ph.dofs.size(); ++d) {
            const an::DofGain& g = ph.dofs[d];
            phrase.append(p);
            dof.append(d < gains.dofNames.size() ? gains.dofNames[d] : std::to_string(d));
            begin.append(ph.begin);
            end.append(ph.end);
            g0.append(g.g0);
            g1.append(g.g1);
            dcMode.append(g.dcMode == an::DcMode::Offset ? "offset" : "scale");
            offset.append(g.offset);
            acMode.append(g.acMode == an::AcMode::Additive ? "additive" : "scale");
            reason.append(g.reason);
        }
    }
    columns["phrase"] = phrase;
    columns["dof"] = dof;
    columns["begin"] = begin;
    columns["end"] = end;
    columns["g0"] = g0;
    columns["g1"] = g1;
    columns["dc_mode"] = dcMode;
    columns["offset"] = offset;
    columns["ac_mode"] = acMode;
    columns["reason"] = reason;
    return pandas().attr("DataFrame")(columns);
}

py::array gainMatrix(const an::GainSet& gains, bool first)
{
    const std::size_t dofs = gains.dofNames.size();
    py::array_t<double> out({py::ssize_t(gains.phrases.size()), py::ssize_t(dofs)});
    auto w = out.mutable_unchecked<2>();
    for (std::size_t p = 0; p < gains.phrases.size(); ++p)
        for (std::size_t d = 0; d < dofs; ++d)
            w(py::ssize_t(p), py::ssize_t(d)) = d < gains.phrases[p].dofs.size() ? (first ? gains.phrases[p].dofs[d].g0 : gains.phrases[p].dofs[d].g1)
                                                                                : 1.0;
    return out;
}

Ptr<Analysis> wrapChain(pl::ChainResult chain, const pl::ChainParameters& parameters)
{
    auto analysis = std::make_shared<Analysis>();
    analysis->parameters = parameters;
    auto preprocessed = std::make_shared<Preprocessed>(Preprocessed{chain.corpus, chain.preprocessed, chain.keys.preprocess});
    auto normalisation = std::make_shared<Normalisation>(Normalisation{preprocessed, chain.normalised, chain.keys.normalise});
    analysis->decomposed = std::make_shared<Decomposed>(Decomposed{normalisation, chain.decomposed, chain.keys.decompose});
    if (chain.fluctuations) analysis->fluctuations = std::make_shared<Fluctuations>(Fluctuations{chain.fluctuations});
    if (chain.axes) analysis->axes = std::make_shared<Axes>(Axes{normalisation, chain.axes, parameters.axis});
    analysis->preprocessed = preprocessed;
    analysis->normalisation = normalisation;
    analysis->chain = std::move(chain);
    return analysis;
}

} // namespace

void bindStages(py::module_& m)
{
    py::class_<pl::ChainParameters, Ptr<pl::ChainParameters>>(m, "Parameters", R"doc(
Every parameter of the chain (analysis/pipeline/stage_parameters.h), as the JSON parameter
file of `bunraku analyse --parameters` holds them (docs/FORMATS.md). Build one with
bunraku.parameters(...) or read one with bunraku.Parameters.from_json(text).)doc")
        .def(py::init<>(), "The defaults: the thesis's, but for normalisation's optimal path.")
        .def_static(
            "from_json",
            [](const std::string& text, const std::string& where) {
                nlohmann::json value = nlohmann::json::parse(text, nullptr, false);
                if (value.is_discarded()) throw Failure(where + ": not JSON");
                return std::make_shared<pl::ChainParameters>(unwrap(pl::chainParametersFromJson(value, where)));
            },
            py::arg("text"), py::arg("where") = "parameters",
            "Parses and validates a parameters JSON text (analysis/pipeline/parameters_json.h): the same reader and "
            "messages as a parameters file; `where` starts every message.")
        .def_static(
            "read",
            [](const std::string& file) {
                try {
                    return std::make_shared<pl::ChainParameters>(app::cli::readChainParameters(file));
                } catch (const app::cli::CliError& error) {
                    throw Failure(error.what());
                }
            },
            py::arg("file"),
            "Reads a parameters file, or a project file's \"parameters\": the reader of `bunraku analyse --parameters` "
            "(app/cli/chain_parameters.h), with its messages.")
        .def("to_json", [](const pl::ChainParameters& p) { return pl::toJson(p).dump(2); }, "Every parameter as JSON text, defaults included.")
        .def("__eq__", [](const pl::ChainParameters& a, const pl::ChainParameters& b) { return a == b; })
        .def("__repr__", [](const pl::ChainParameters& p) { return "<bunraku.Parameters " + pl::toJson(p).dump() + ">"; });

    // ---- preprocess ----
    py::class_<Preprocessed, Ptr<Preprocessed>>(m, "Preprocessed", "The preprocessed corpus (thesis 2.2) and what each step did.")
        .def_property_readonly("corpus",
                               [](const Ptr<Preprocessed>& p) { return alias(p->output, p->output->corpus); },
                               "The preprocessed Corpus (padded, unwrapped, aligned).")
        .def_property_readonly("input", [](const Ptr<Preprocessed>& p) { return std::const_pointer_cast<an::Corpus>(p->input.corpus); },
                               "The Corpus it was made from.")
        .def_property_readonly("padded_frames", [](const Preprocessed& p) { return p.output->report.paddedFrames; },
                               "The common length after padding (0 when not padded).")
        .def_property_readonly("key", [](const Preprocessed& p) { return p.key.hex(); }, "The stage key (16 hex digits).")
        .def("to_pandas",
             [](const Preprocessed& p) {
                 py::dict columns;
                 py::list take, padded, unwrapped, shift, timeRef, onset, heading, branch;
                 for (const auto& r : p.output->report.takes) {
                     take.append(r.take);
                     padded.append(r.framesPadded);
                     unwrapped.append(r.anglesUnwrapped);
                     shift.append(r.shiftFrames);
                     timeRef.append(r.isTimeReference);
                     onset.append(r.onsetFrame);
                     heading.append(r.headingOffsetDeg);
                     branch.append(r.branchTurns);
                 }
                 columns["take"] = take;
                 columns["frames_padded"] = padded;
                 columns["angles_unwrapped"] = unwrapped;
                 columns["shift_frames"] = shift;
                 columns["time_reference"] = timeRef;
                 columns["onset_frame"] = onset;
                 columns["heading_offset_deg"] = heading;
                 columns["branch_turns"] = branch;
                 return pandas().attr("DataFrame")(columns);
             },
             "The preprocessing report, one row per take (thesis 2.2: padding, unwrapping, start shift, heading).")
        .def("__repr__", [](const Preprocessed& p) {
            return "<bunraku.Preprocessed " + std::to_string(p.output->corpus.takes.size()) + " takes, " +
                   std::to_string(p.output->corpus.takes.empty() ? 0 : p.output->corpus.takes.front().frameCount()) + " frames>";
        });

    m.def(
        "_preprocess",
        [](const an::Corpus& corpus, const pl::ChainParameters& parameters, int threads) {
            auto result = std::make_shared<Preprocessed>();
            result->input = corpusInput(corpus);
            result->key = pl::preprocessKey(result->input.key, parameters.preprocess);
            result->output = staged(pl::Stage::Preprocess, runReleased(
                                                               [&](const an::RunControl& control) {
                                                                   return pl::preprocessStage(result->input, parameters.preprocess,
                                                                                              nullptr, control);
                                                               },
                                                               resolvedThreads(threads)));
            return result;
        },
        py::arg("corpus"), py::arg("parameters"), py::arg("threads") = 0);

    // ---- normalise ----
    py::class_<NormalisedTake>(m, "NormalisedTake",
                               "One take of a normalised cell, as `bunraku normalise --json` reports it under \"takes\".")
        .def_property_readonly("take", [](const NormalisedTake& t) { return t.cell->takeIndices[t.k]; }, "Its take index.")
        .def_property_readonly("cost", [](const NormalisedTake& t) { return t.cell->normalisations[t.k].cost; },
                               "The matching cost summed over the coupling sets (eq. 3.28).")
        .def_property_readonly("variance_raw", [](const NormalisedTake& t) { return t.cell->variance.totalBefore[Eigen::Index(t.k)]; },
                               "Thesis 3.8: variance of the raw take against the reference, summed over channels.")
        .def_property_readonly("variance_normalised",
                               [](const NormalisedTake& t) { return t.cell->variance.totalAfter[Eigen::Index(t.k)]; },
                               "Thesis 3.8: variance of the normalised take against the reference, summed over channels.")
        .def_property_readonly("outlier", [](const NormalisedTake& t) { return bool(t.cell->suggestion.outlier[t.k]); },
                               "Marked as an outlier by the reference suggestion (3.6.1).")
        .def_property_readonly("families", [](const NormalisedTake& t) -> py::object { return normalisedTakeDict(t)["families"]; },
                               "Variance per DOF family (position cm², rotation deg²): [{family, unit, raw, normalised}].")
        .def_property_readonly("normalised",
                               [](const NormalisedTake& t) { return alias(t.cell, t.cell->normalisations[t.k].normalised); },
                               "The take on the reference's time axis (a Take).")
        .def_property_readonly("correspondence",
                               [](py::object self) {
                                   const auto& t = self.cast<const NormalisedTake&>();
                                   return matrixView(t.cell->normalisations[t.k].correspondence, self);
                               },
                               "reference frames x channels, int32: the sample frame each channel took (eq. 3.28's path).")
        .def_property_readonly("body_time",
                               [](py::object self) {
                                   const auto& t = self.cast<const NormalisedTake&>();
                                   return vectorView(t.cell->normalisations[t.k].bodyTime, self);
                               },
                               "Per reference frame the fractional sample frame the whole body shows.")
        .def("to_dict", &normalisedTakeDict, "The entry of `bunraku normalise --json`'s \"takes\".")
        .def("__repr__", [](const NormalisedTake& t) {
            std::ostringstream text;
            text << "<bunraku.NormalisedTake " << t.cell->function << "/" << t.cell->emotion << "/" << t.cell->takeIndices[t.k]
                 << ": variance " << t.cell->variance.totalBefore[Eigen::Index(t.k)] << " -> "
                 << t.cell->variance.totalAfter[Eigen::Index(t.k)] << ">";
            return text.str();
        });

    py::class_<pl::CellNormalisation, Ptr<pl::CellNormalisation>>(
        m, "NormalisedCell",
        "One function x emotion cell normalised to its reference (thesis 3.6), evaluated (3.8, eq. 3.30) and averaged (3.7).")
        .def_property_readonly("function", [](const pl::CellNormalisation& c) { return c.function; })
        .def_property_readonly("emotion", [](const pl::CellNormalisation& c) { return c.emotion; })
        .def_property_readonly("take_indices", [](const pl::CellNormalisation& c) { return c.takeIndices; },
                               "The cell's take indices, in order.")
        .def_property_readonly("reference", [](const pl::CellNormalisation& c) { return c.referenceName; },
                               "The reference's name: \"take 4 (suggested)\", \"take 2\", \"4ave\".")
        .def_property_readonly("suggested_reference",
                               [](const pl::CellNormalisation& c) { return c.takeIndices[std::size_t(c.suggestion.takeIndex)]; },
                               "The take index thesis 3.6.1 suggests.")
        .def_property_readonly("suggestion", [](const pl::CellNormalisation& c) { return c.suggestion.reason; },
                               "Why that take was suggested.")
        .def_property_readonly("reference_take", [](const Ptr<pl::CellNormalisation>& c) { return alias(c, c->referenceTake); },
                               "The reference Take.")
        .def_property_readonly("average", [](const Ptr<pl::CellNormalisation>& c) { return alias(c, c->average); },
                               "The cell's average take (thesis 3.7).")
        .def_property_readonly("average_name", [](const pl::CellNormalisation& c) { return c.averageName; })
        .def_property_readonly("average_members", [](const pl::CellNormalisation& c) { return c.averageMembers; })
        .def_property_readonly("takes",
                               [](const Ptr<pl::CellNormalisation>& c) {
                                   std::vector<NormalisedTake> takes;
                                   for (std::size_t k = 0; k < c->normalisations.size(); ++k) takes.push_back({c, k});
                                   return takes;
                               },
                               "Per take: NormalisedTake (variance_raw, variance_normalised, cost, normalised Take...).")
        .def_property_readonly("variance_raw",
                               [](py::object self) { return matrixView(self.cast<const pl::CellNormalisation&>().variance.before, self); },
                               "takes x channels: eq. 3.30 variance of each raw take against the reference.")
        .def_property_readonly("variance_normalised",
                               [](py::object self) { return matrixView(self.cast<const pl::CellNormalisation&>().variance.after, self); },
                               "takes x channels: eq. 3.30 variance of each normalised take against the reference.")
        .def_property_readonly("channels", [](const pl::CellNormalisation& c) { return c.variance.channelNames; })
        .def_property_readonly("variance_raw_total", [](const pl::CellNormalisation& c) { return c.variance.totalBefore.sum(); })
        .def_property_readonly("variance_normalised_total", [](const pl::CellNormalisation& c) { return c.variance.totalAfter.sum(); })
        .def("to_pandas",
             [](const pl::CellNormalisation& c) {
                 const an::VarianceTable& table = c.variance;
                 py::list rows;
                 for (std::size_t k = 0; k < table.takeNames.size(); ++k)
                     for (int stage = 0; stage < 2; ++stage) {
                         const Eigen::MatrixXd& values = stage == 0 ? table.before : table.after;
                         py::dict row;
                         row["take"] = c.takeIndices[k];
                         row["stage"] = stage == 0 ? "raw" : "normalised";
                         row["total"] = (stage == 0 ? table.totalBefore : table.totalAfter)[Eigen::Index(k)];
                         for (Eigen::Index ch = 0; ch < values.cols(); ++ch)
                             row[py::str(table.channelNames[std::size_t(ch)])] = values(Eigen::Index(k), ch);
                         rows.append(row);
                     }
                 return pandas().attr("DataFrame")(rows);
             },
             "The variance table (thesis 3.8) as variance_<f>_<e>.csv holds it: a row per take and stage.")
        .def("__repr__", [](const pl::CellNormalisation& c) {
            return "<bunraku.NormalisedCell " + c.function + "/" + c.emotion + ": " + std::to_string(c.normalisations.size()) +
                   " takes to " + c.referenceName + ">";
        });

    py::class_<Normalisation, Ptr<Normalisation>>(m, "Normalisation", R"doc(
The normalise stage's result (thesis 3): every cell (or the one asked for) normalised to its
reference by wavelet matching, evaluated and averaged; .corpus is the corpus with every take
replaced by its normalised take. With one cell, .takes, .reference and the other fields of
`bunraku normalise --json` are that cell's.)doc")
        .def_property_readonly("cells",
                               [](const Ptr<Normalisation>& n) {
                                   std::vector<Ptr<pl::CellNormalisation>> cells;
                                   for (const auto& cell : n->output->cells) cells.push_back(alias(n->output, cell));
                                   return cells;
                               },
                               "Every NormalisedCell, functions x emotions order.")
        .def(
            "cell",
            [](const Ptr<Normalisation>& n, const std::string& function, const std::string& emotion) {
                return alias(n->output, findCell(*n->output, function, emotion));
            },
            py::arg("function"), py::arg("emotion"), "One NormalisedCell.")
        .def_property_readonly("corpus", [](const Ptr<Normalisation>& n) { return alias(n->output, n->output->normalised); },
                               "The normalised Corpus (reference frames, labels kept).")
        .def_property_readonly("preprocessed", [](const Normalisation& n) { return std::const_pointer_cast<Preprocessed>(n.preprocessed); },
                               "The Preprocessed result it was computed from.")
        .def_property_readonly("key", [](const Normalisation& n) { return n.key.hex(); })
        // One cell normalised (normalise(..., function=, emotion=)): the fields of `bunraku normalise --json`.
        .def_property_readonly("takes", [](const Ptr<Normalisation>& n) -> py::object { return py::cast(onlyCell(n)).attr("takes"); },
                               "With one cell: its takes (NormalisedTake: variance_raw, variance_normalised, ...).")
        .def_property_readonly("reference", [](const Ptr<Normalisation>& n) { return onlyCell(n)->referenceName; },
                               "With one cell: its reference's name.")
        .def_property_readonly("suggested_reference",
                               [](const Ptr<Normalisation>& n) {
                                   const auto cell = onlyCell(n);
                                   return cell->takeIndices[std::size_t(cell->suggestion.takeIndex)];
                               },
                               "With one cell: the take index 3.6.1 suggests.")
        .def_property_readonly("variance_raw_total", [](const Ptr<Normalisation>& n) { return onlyCell(n)->variance.totalBefore.sum(); })
        .def_property_readonly("variance_normalised_total",
                               [](const Ptr<Normalisation>& n) { return onlyCell(n)->variance.totalAfter.sum(); })
        .def("to_pandas", [](const Ptr<Normalisation>& n) -> py::object { return py::cast(onlyCell(n)).attr("to_pandas")(); },
             "With one cell: its variance table (thesis 3.8).")
        .def("__repr__", [](const Normalisation& n) {
            return "<bunraku.Normalisation " + std::to_string(n.output->cells.size()) + " cell(s), " +
                   std::to_string(n.output->normalised.takes.size()) + " takes>";
        });

    m.def(
        "_normalise",
        [](const Ptr<Preprocessed>& preprocessed, const pl::ChainParameters& parameters, std::optional<std::string> function,
           std::optional<std::string> emotion, int threads) {
            return normaliseCorpus(preprocessed, parameters.normalise, function, emotion, resolvedThreads(threads));
        },
        py::arg("preprocessed"), py::arg("parameters"), py::arg("function") = py::none(), py::arg("emotion") = py::none(),
        py::arg("threads") = 0);

    // ---- decompose ----
    py::class_<Decomposed, Ptr<Decomposed>>(m, "Decomposition", R"doc(
The decompose stage's result (thesis 4): x^{ijk} = y^i + z^{ij} + eta^{ijk} (eq. 4.1) by
KM2O-Langevin with exogenous inputs (4.4.4, eqs. 4.42/4.43; M chosen by the relative error P)
or least squares (4.3.1, eq. 4.8). Angle columns of y and z are rotation coordinates about
each function's chart (docs/FORMATS.md); function_take() gives y as a pose.)doc")
        .def_property_readonly("method", [](const Decomposed& d) { return pl::methodName(d.output->parameters.method); })
        .def_property_readonly("input", [](const Decomposed& d) { return pl::inputName(d.output->parameters.input); })
        .def_property_readonly("channels", [](const Decomposed& d) { return names(d.output->components.channels); })
        .def_property_readonly("rate_hz", [](const Decomposed& d) { return d.output->components.rateHz; })
        .def_property_readonly("functions",
                               [](const Decomposed& d) {
                                   std::vector<std::string> out;
                                   for (const auto& y : d.output->components.functions) out.push_back(y.function);
                                   return out;
                               },
                               "Function labels, in order.")
        .def_property_readonly("cells",
                               [](const Decomposed& d) {
                                   std::vector<std::pair<std::string, std::string>> out;
                                   for (const auto& z : d.output->components.emotions) out.emplace_back(z.function, z.emotion);
                                   return out;
                               },
                               "(function, emotion) of every cell with takes, function-major.")
        .def(
            "y",
            [](py::object self, const std::string& function) {
                const auto& d = self.cast<const Decomposed&>();
                const auto* y = d.output->components.function(function);
                if (!y) throw Failure("no function " + function + " in the decomposition");
                return matrixView(y->values, self);
            },
            py::arg("function"), "frames x channels: the function component y^i (eq. 4.42), a view.")
        .def(
            "z",
            [](py::object self, const std::string& function, const std::string& emotion) {
                const auto& d = self.cast<const Decomposed&>();
                const auto* z = d.output->components.emotion(function, emotion);
                if (!z) throw Failure("no cell " + function + "/" + emotion + " in the decomposition");
                return matrixView(z->values, self);
            },
            py::arg("function"), py::arg("emotion"), "frames x channels: the emotion component z^{ij} (eq. 4.43), a view.")
        .def(
            "cell_mean",
            [](py::object self, const std::string& function, const std::string& emotion) {
                const auto& d = self.cast<const Decomposed&>();
                const int index = d.output->components.cellIndex(function, emotion);
                if (index < 0) throw Failure("no cell " + function + "/" + emotion + " in the decomposition");
                return matrixView(d.output->components.cellMeans[std::size_t(index)], self);
            },
            py::arg("function"), py::arg("emotion"), "frames x channels: the mean of the cell's takes (eq. 4.22), a view.")
        .def(
            "function_take",
            [](const Decomposed& d, const std::string& function) {
                auto take = unwrap(an::functionComponentTake(d.output->components, function));
                take.labels = {function, "", 0, "y"};
                return std::make_shared<an::Take>(std::move(take));
            },
            py::arg("function"), "y^i as a Take of Euler angles (what `bunraku analyse` writes as y_<f>.csv).")
        .def_property_readonly("M", [](const Decomposed& d) { return d.output->km2o ? d.output->km2o->correlationLength : 0; },
                               "KM2O's correlation length M (0 with least squares).")
        .def_property_readonly("candidate_M",
                               [](const Decomposed& d) { return d.output->km2o ? d.output->km2o->candidateLengths : std::vector<int>{}; })
        .def_property_readonly("mean_P_percent_by_M",
                               [](const Decomposed& d) {
                                   return d.output->km2o ? d.output->km2o->meanErrorPercent : std::vector<double>{};
                               },
                               "Mean relative error P [%] per candidate M (4.4.4).")
        .def_property_readonly("mean_P_percent",
                               [](const Decomposed& d) { return d.output->km2o ? d.output->km2o->meanCellErrorPercent : std::nan(""); },
                               "Mean P^{ij} [%] at the chosen M (thesis: 2.32 %).")
        .def_property_readonly("cell_error_percent",
                               [](py::object self) -> py::object {
                                   const auto& d = self.cast<const Decomposed&>();
                                   if (!d.output->km2o) return py::none();
                                   return matrixView(d.output->km2o->cellErrorPercent, self);
                               },
                               "channels x cells: P^{ij} [%] (Table 4.5); None with least squares.")
        .def_property_readonly("outcome", [](const Decomposed& d) { return d.output->km2o ? d.output->km2o->outcome() : std::string(); })
        .def_property_readonly("notes",
                               [](const Decomposed& d) { return d.output->km2o ? d.output->km2o->notes : std::vector<std::string>{}; })
        .def_property_readonly("normalisation", [](const Decomposed& d) { return std::const_pointer_cast<Normalisation>(d.normalisation); })
        .def("to_pandas",
             [](const Decomposed& d) -> py::object {
                 if (!d.output->km2o) return py::none();
                 const auto& c = d.output->components;
                 py::list columns;
                 for (const auto& z : c.emotions) columns.append("P_" + z.function + "/" + z.emotion);
                 py::dict kwargs;
                 kwargs["index"] = pandas().attr("Index")(names(c.channels), py::arg("name") = "channel");
                 kwargs["columns"] = columns;
                 return pandas().attr("DataFrame")(copyMatrix(d.output->km2o->cellErrorPercent), **kwargs);
             },
             "KM2O's P^{ij} [%] per channel and cell (Table 4.5, km2o_errors.csv); None with least squares.")
        .def("__repr__", [](const Decomposed& d) {
            std::ostringstream text;
            text << "<bunraku.Decomposition " << pl::methodName(d.output->parameters.method) << " of "
                 << d.output->components.emotions.size() << " cells";
            if (d.output->km2o && d.output->km2o->estimable())
                text << ", M = " << d.output->km2o->correlationLength << ", mean P = " << d.output->km2o->meanCellErrorPercent << " %";
            text << ">";
            return text.str();
        });

    m.def(
        "_decompose",
        [](const Ptr<Normalisation>& normalisation, const pl::ChainParameters& parameters, int threads) {
            return decomposeNormalisation(normalisation, parameters.decompose, resolvedThreads(threads));
        },
        py::arg("normalisation"), py::arg("parameters"), py::arg("threads") = 0);

    // ---- fluctuations ----
    py::class_<Fluctuations, Ptr<Fluctuations>>(m, "Fluctuations", R"doc(
The fluctuation eta (thesis 4.3.2): Welch power spectra averaged over each cell's takes, and
ARMA(p, q) models per take averaged per cell and channel (Table 4.1, docs/ARMA.md).)doc")
        .def_property_readonly("channels", [](const Fluctuations& f) { return f.output->channelNames; })
        .def_property_readonly("arma_p", [](const Fluctuations& f) { return f.output->armaP; })
        .def_property_readonly("arma_q", [](const Fluctuations& f) { return f.output->armaQ; })
        .def_property_readonly("arma_errors", [](const Fluctuations& f) { return f.output->armaErrors; },
                               "Per channel: why its ARMA table is empty (empty text when it is not).")
        .def_property_readonly("cells",
                               [](const Fluctuations& f) {
                                   std::vector<std::pair<std::string, std::string>> out;
                                   for (const auto& s : f.output->spectra) out.emplace_back(s.function, s.emotion);
                                   return out;
                               })
        .def(
            "frequency_hz",
            [](py::object self, const std::string& function, const std::string& emotion) {
                for (const auto& s : self.cast<const Fluctuations&>().output->spectra)
                    if (s.function == function && s.emotion == emotion) return vectorView(s.frequencyHz, self);
                throw Failure("no spectra for " + function + "/" + emotion);
            },
            py::arg("function"), py::arg("emotion"), "The frequency bins, Hz (a view).")
        .def(
            "power",
            [](py::object self, const std::string& function, const std::string& emotion) {
                for (const auto& s : self.cast<const Fluctuations&>().output->spectra)
                    if (s.function == function && s.emotion == emotion) return matrixView(s.power, self);
                throw Failure("no spectra for " + function + "/" + emotion);
            },
            py::arg("function"), py::arg("emotion"), "bins x channels: Welch PSD of eta averaged over the cell's takes (a view).")
        .def("to_pandas",
             [](const Fluctuations& f) {
                 const auto& out = *f.output;
                 py::list rows;
                 for (std::size_t ch = 0; ch < out.armaTables.size(); ++ch)
                     for (const auto& row : out.armaTables[ch]) {
                         if (row.takes == 0) continue;
                         py::dict r;
                         r["channel"] = out.channelNames[ch];
                         r["function"] = row.function;
                         r["emotion"] = row.emotion;
                         r["takes"] = row.takes;
                         for (int i = 0; i < out.armaP; ++i) r[py::str(numbered("a", i + 1))] = row.mean.a(i);
                         for (int n = 0; n <= out.armaQ; ++n) r[py::str(numbered("b", n))] = row.mean.b(n);
                         for (int n = 0; n <= out.armaQ; ++n) r[py::str(numbered("b", n, "_thesis"))] = row.mean.bThesis(n);
                         r["innovation_variance"] = row.mean.innovationVariance;
                         r["fpe"] = row.mean.fpe;
                         rows.append(r);
                     }
                 return pandas().attr("DataFrame")(rows);
             },
             "The ARMA table (Table 4.1; arma_table.csv): a row per channel and cell.")
        .def("__repr__", [](const Fluctuations& f) {
            return "<bunraku.Fluctuations ARMA(" + std::to_string(f.output->armaP) + ", " + std::to_string(f.output->armaQ) + ") of " +
                   std::to_string(f.output->spectra.size()) + " cells>";
        });

    m.def(
        "_fluctuations",
        [](const Decomposed& decomposed, const pl::ChainParameters& parameters, int threads) {
            auto output = staged(pl::Stage::Fluctuations, runReleased(
                                                              [&](const an::RunControl& control) {
                                                                  return pl::fluctuationStage(decomposed.key, *decomposed.output,
                                                                                              parameters.fluctuations, nullptr, control);
                                                              },
                                                              resolvedThreads(threads)));
            return std::make_shared<Fluctuations>(Fluctuations{output});
        },
        py::arg("decomposition"), py::arg("parameters"), py::arg("threads") = 0);

    m.def(
        "_emotion_weight",
        [](const Decomposed& decomposed, const std::string& function, const std::string& emotion, const pl::ChainParameters& parameters) {
            return std::make_shared<an::Take>(unwrap(runReleased([&](const an::RunControl&) {
                return pl::weightedTake(*decomposed.output, function, emotion, parameters.design.emotionWeight);
            })));
        },
        py::arg("decomposition"), py::arg("function"), py::arg("emotion"), py::arg("parameters"));

    // ---- motion axes, phase, gains, design ----
    py::class_<Phase>(m, "Phase", R"doc(
The phase component (thesis 5.3): the emotional axis matched to the functional one on all 6 axis
DOF; the warp maps emotional frames to functional frames.)doc")
        .def_property_readonly("control_points",
                               [](const Phase& p) {
                                   Eigen::MatrixXd points(Eigen::Index(p.phase->curve.points.size()), 2);
                                   for (std::size_t i = 0; i < p.phase->curve.points.size(); ++i)
                                       points.row(Eigen::Index(i)) << p.phase->curve.points[i].output, p.phase->curve.points[i].source;
                                   return copyMatrix(points);
                               },
                               "n x 2: the warp's control points (emotional frame, functional frame), as warp_<f>_<e>.csv.")
        .def_property_readonly("emotional_to_functional",
                               [](py::object self) { return vectorView(self.cast<const Phase&>().phase->emotionalToFunctional, self); },
                               "Per emotional frame its functional frame (monotone; phase_<f>_<e>.csv).")
        .def_property_readonly("functional_to_emotional",
                               [](py::object self) { return vectorView(self.cast<const Phase&>().phase->functionalToEmotional, self); })
        .def_property_readonly("correspondence",
                               [](py::object self) { return vectorView(self.cast<const Phase&>().phase->correspondence, self); },
                               "Functional frame -> emotional frame (the matcher's integer path).")
        .def_property_readonly("cost", [](const Phase& p) { return p.phase->cost; })
        .def("to_pandas",
             [](py::object self) {
                 py::dict columns;
                 const auto& p = self.cast<const Phase&>();
                 py::list output, source;
                 for (const auto& point : p.phase->curve.points) {
                     output.append(point.output);
                     source.append(point.source);
                 }
                 columns["output_frame"] = output;
                 columns["source_frame"] = source;
                 return pandas().attr("DataFrame")(columns);
             },
             "The warp's control points (output_frame = emotional, source_frame = functional).")
        .def("__repr__", [](const Phase& p) {
            return "<bunraku.Phase " + std::to_string(p.phase->curve.points.size()) + " control points, " +
                   std::to_string(p.phase->emotionalToFunctional.size()) + " emotional frames>";
        });

    py::class_<Gains>(m, "Gains", R"doc(
The amplitude component (thesis 5.4): per phrase and axis DOF the gains g0 = a0_no / a0_em
(eq. 5.22) and g1 = A1_no / A1_em (eq. 5.23) of the functional axis against the
phase-adjusted emotional axis.)doc")
        .def_property_readonly("dof_names", [](const Gains& g) { return g.gains->dofNames; })
        .def_property_readonly("phrases",
                               [](const Gains& g) {
                                   std::vector<std::pair<Eigen::Index, Eigen::Index>> out;
                                   for (const auto& p : g.gains->phrases) out.emplace_back(p.begin, p.end);
                                   return out;
                               },
                               "(first, last) functional frame of each phrase.")
        .def_property_readonly("g0", [](const Gains& g) { return gainMatrix(*g.gains, true); }, "phrases x DOF: g0 (eq. 5.22).")
        .def_property_readonly("g1", [](const Gains& g) { return gainMatrix(*g.gains, false); }, "phrases x DOF: g1 (eq. 5.23).")
        .def("to_pandas", [](const Gains& g) { return gainsFrame(*g.gains); },
             "A row per phrase and DOF, the columns of gains_<f>_<e>.csv.")
        .def("__repr__", [](const Gains& g) {
            return "<bunraku.Gains " + std::to_string(g.gains->phrases.size()) + " phrases x " +
                   std::to_string(g.gains->dofNames.size()) + " DOF>";
        });

    py::class_<pl::FunctionAxis, Ptr<pl::FunctionAxis>>(m, "FunctionAxis",
                                                          "A function's functional motion: the neutral cell's average take (3.7), its "
                                                          "motion axis (5.2.1) and suggested phrase boundaries (5.2.2).")
        .def_property_readonly("function", [](const pl::FunctionAxis& f) { return f.function; })
        .def_property_readonly("take", [](const Ptr<pl::FunctionAxis>& f) { return alias(f, f->basis->functional); },
                               "The functional Take (the neutral cell's average take).")
        .def_property_readonly("coordinates",
                               [](py::object self) { return matrixView(self.cast<const pl::FunctionAxis&>().basis->coordinates, self); },
                               "frames x 6 axis coordinates (axis_functional_<f>.csv).")
        .def_property_readonly("boundaries", [](const pl::FunctionAxis& f) { return f.boundaries; },
                               "Suggested phrase boundaries, functional frames (0 ... last).")
        .def("__repr__", [](const pl::FunctionAxis& f) {
            return "<bunraku.FunctionAxis " + f.function + ": " + std::to_string(f.basis->coordinates.rows()) + " frames, " +
                   std::to_string(f.boundaries.size() > 0 ? f.boundaries.size() - 1 : 0) + " phrases>";
        });

    py::class_<pl::CellAxis, Ptr<pl::CellAxis>>(m, "CellAxis",
                                                  "An emotional cell against its function (thesis 5.2-5.5): the average take's axis, "
                                                  "phase, gains and the eq. 5.18 error of the motion designed with them.")
        .def_property_readonly("function", [](const pl::CellAxis& c) { return c.function; })
        .def_property_readonly("emotion", [](const pl::CellAxis& c) { return c.emotion; })
        .def_property_readonly("coordinates",
                               [](py::object self) { return matrixView(self.cast<const pl::CellAxis&>().coordinates, self); },
                               "frames x 6 axis coordinates of the emotional average take (axis_emotional_<f>_<e>.csv).")
        .def_property_readonly("phase",
                               [](const Ptr<pl::CellAxis>& c) { return Phase{alias(c, c->extracted.phase)}; }, "The Phase (5.3).")
        .def_property_readonly("gains", [](const Ptr<pl::CellAxis>& c) { return Gains{alias(c, c->extracted.gains)}; },
                               "The Gains (5.4).")
        .def_property_readonly("design_relative_error", [](const pl::CellAxis& c) { return c.designRelativeError; },
                               "Eq. 5.18: designed (extracted phase and gains) vs emotional axis.")
        .def_property_readonly("undesigned_relative_error", [](const pl::CellAxis& c) { return c.undesignedRelativeError; },
                               "Eq. 5.18: functional vs emotional axis.")
        .def_property_readonly("approximation_error",
                               [](py::object self) {
                                   return matrixView(self.cast<const pl::CellAxis&>().approximation.relativeError, self);
                               },
                               "scales x 6: eq. 5.18 per largest scale c = 1..maxScale and axis DOF (5.4.1, Fig. 5.16).")
        .def("__repr__", [](const pl::CellAxis& c) {
            std::ostringstream text;
            text << "<bunraku.CellAxis " << c.function << "/" << c.emotion << ": design error " << c.designRelativeError << ">";
            return text.str();
        });

    py::class_<Axes, Ptr<Axes>>(m, "Axes", R"doc(
Motion axes (thesis 5.2.1: principal axes of inertia of the posed body), phase (5.3) and
gains (5.4) of every emotional cell against its function's functional motion.)doc")
        .def_property_readonly("functions",
                               [](const Axes& a) {
                                   std::vector<Ptr<pl::FunctionAxis>> out;
                                   for (const auto& f : a.output->functions) out.push_back(alias(a.output, f));
                                   return out;
                               })
        .def_property_readonly("cells",
                               [](const Axes& a) {
                                   std::vector<Ptr<pl::CellAxis>> out;
                                   for (const auto& c : a.output->cells) out.push_back(alias(a.output, c));
                                   return out;
                               })
        .def(
            "function", [](const Axes& a, const std::string& function) { return alias(a.output, findFunctionAxis(*a.output, function)); },
            py::arg("function"))
        .def(
            "cell",
            [](const Axes& a, const std::string& function, const std::string& emotion) {
                return alias(a.output, findCellAxis(*a.output, function, emotion));
            },
            py::arg("function"), py::arg("emotion"))
        .def("__repr__", [](const Axes& a) {
            return "<bunraku.Axes " + std::to_string(a.output->functions.size()) + " function(s), " +
                   std::to_string(a.output->cells.size()) + " emotional cell(s)>";
        });

    m.def(
        "_axes",
        [](const Ptr<Normalisation>& normalisation, const pl::ChainParameters& parameters, int threads) {
            auto output = staged(pl::Stage::Axes, runReleased(
                                                      [&](const an::RunControl& control) {
                                                          return pl::axisStage(normalisation->key, *normalisation->output,
                                                                               normalisation->preprocessed->input.corpus->neutralEmotion,
                                                                               parameters.axis, nullptr, control);
                                                      },
                                                      resolvedThreads(threads)));
            return std::make_shared<Axes>(Axes{normalisation, output, parameters.axis});
        },
        py::arg("normalisation"), py::arg("parameters"), py::arg("threads") = 0);

    py::class_<TakeAxis>(m, "TakeAxis", "A take's motion axis (thesis 5.2.1), per frame and as the 6 axis-coordinate channels.")
        .def_property_readonly("take", [](const TakeAxis& a) { return alias(a.axis, a.axis->coordinates); },
                               "The axis as a Take of the thesis's 6 axis channels (axis_channels.h), as `bunraku axis` "
                               "writes it and the workbench's \"axis\" take.")
        .def_property_readonly("coordinates", [](const TakeAxis& a) { return copyMatrix(an::axisCoordinates(a.axis->world_T_axis)); },
                               "frames x 6 axis coordinates: the centre (cm) and the continuous rotation vector (deg), as "
                               "`bunraku axis --coordinates` writes them and phase and gains (5.3, 5.4) compare them.")
        .def_property_readonly("poses", [](const TakeAxis& a) { return posesArray(a.axis->world_T_axis); },
                               "frames x 4 x 4: world_T_axis per frame (a copy).")
        .def("__repr__", [](const TakeAxis& a) { return "<bunraku.TakeAxis " + a.axis->coordinates.displayName() + ">"; });

    m.def(
        "_take_axis",
        [](const an::Take& take, const pl::ChainParameters& parameters) {
            auto axis = unwrap(runReleased([&](const an::RunControl& control) { return pl::runTakeAxis(take, parameters.axis, control); }));
            return TakeAxis{std::make_shared<const pl::TakeAxis>(std::move(axis))};
        },
        py::arg("take"), py::arg("parameters"));

    py::class_<Kimono>(m, "Kimono", R"doc(
A take's kimono simulated as cloth (thesis 6, future work; docs/KIMONO.md): the skirt and the long
sleeves driven by the take's parts, on the puppet the take is drawn with (fitted to its skeleton
when it has one).)doc")
        .def_property_readonly("take", [](const Kimono& k) { return std::make_shared<an::Take>(an::kimonoTake(*k.take, *k.simulation)); },
                               "The measured points as a Take of 18 channels (sleeve_right_tip.x ... hem_right.z, cm), "
                               "as the workbench's \"kimono\" take and the last 18 columns `bunraku convert --kimono` writes.")
        .def_property_readonly("points", [](py::object self) { return matrixView(self.cast<const Kimono&>().simulation->points, self); },
                               "frames x 18: the measured points (cm, world).")
        .def_property_readonly("frames", [](const Kimono& k) { return k.simulation->frameCount(); })
        .def_property_readonly("triangles",
                               [](const Kimono& k) {
                                   const auto& t = k.simulation->cloth->triangles;
                                   py::array_t<std::uint32_t> out({py::ssize_t(t.size() / 3), py::ssize_t(3)});
                                   std::copy(t.begin(), t.end(), out.mutable_data());
                                   return out;
                               },
                               "triangles x 3: the cloth's surface (particle indices, counter-clockwise seen from outside the skirt).")
        .def(
            "particles",
            [](const Kimono& k, Eigen::Index frame) {
                auto x = unwrap(an::kimonoFrame(*k.simulation, *k.take, frame));
                Eigen::MatrixXd out(Eigen::Index(x.size()), 3);
                for (std::size_t i = 0; i < x.size(); ++i) out.row(Eigen::Index(i)) = x[i].transpose();
                return out;
            },
            py::arg("frame"), "particles x 3: the cloth at `frame` (cm, world), the same values however the frames are visited.")
        .def(
            "measures",
            [](const Kimono& k) {
                const auto measured = unwrap(an::measureKimono(*k.take, *k.simulation));
                py::dict out;
                out["sleeve_swing_right_cm"] = measured.sleeveSwingCm[0];
                out["sleeve_swing_left_cm"] = measured.sleeveSwingCm[1];
                out["sleeve_lag_s"] = measured.sleeveLagSeconds;
                out["hem_swing_cm"] = measured.hemSwingCm;
                out["hand_swing_cm"] = measured.handSwingCm;
                return out;
            },
            "The kimono's own motion beyond what the parts carry, as `bunraku experiment kimono --json` reports per take.")
        .def("__repr__", [](const Kimono& k) { return "<bunraku.Kimono of " + k.take->displayName() + ">"; });

    m.def(
        "_kimono",
        [](const an::Take& take, const py::dict& cloth) {
            an::ClothParameters parameters;
            for (const an::ClothParameterLimit& limit : an::clothParameterLimits())
                if (cloth.contains(limit.name)) parameters.*(limit.member) = cloth[limit.name].cast<double>();
            auto shared = std::make_shared<const an::Take>(take);
            const an::BodyDescription body = take.skeleton ? an::bodyForTake(an::defaultBodyDescription(), take) : an::defaultBodyDescription();
            auto simulation = unwrap(runReleased([&](const an::RunControl& control) { return pl::runKimono(*shared, body, parameters, control); }));
            return Kimono{std::make_shared<const an::KimonoSimulation>(std::move(simulation)), shared};
        },
        py::arg("take"), py::arg("cloth"));

    m.def(
        "_gains",
        [](const Axes& axes, const std::string& function, const std::string& emotion, const std::vector<Eigen::Index>& boundaries) {
            const pl::CellAxis& cell = findCellAxis(*axes.output, function, emotion);
            const pl::FunctionAxis& f = findFunctionAxis(*axes.output, function);
            auto gains = unwrap(
                an::extractGainsForBoundaries(f.basis->coordinates, cell.extracted, boundaries, axes.parameters.extractionOptions().gains));
            return Gains{std::make_shared<const an::GainSet>(std::move(gains))};
        },
        py::arg("axes"), py::arg("function"), py::arg("emotion"), py::arg("boundaries"));

    py::class_<Designed>(m, "Designed", "A designed motion (thesis 5.5): the functional motion with phrase gains and a time warp.")
        .def_property_readonly("take", [](const Designed& d) { return alias(d.motion, d.motion->take); }, "The designed Take.")
        .def_property_readonly("axis_coordinates",
                               [](py::object self) { return matrixView(self.cast<const Designed&>().motion->axisCoordinates, self); },
                               "output frames x 6: the designed axis.")
        .def("__repr__", [](const Designed& d) { return "<bunraku.Designed " + std::to_string(d.motion->take.frameCount()) + " frames>"; });

    m.def(
        "_design",
        [](const Axes& axes, const std::string& function, const pl::ChainParameters& parameters) {
            const pl::FunctionAxis& f = findFunctionAxis(*axes.output, function);
            auto motion = runReleased([&](const an::RunControl&) { return pl::designFunction(f, parameters.design); });
            return Designed{std::make_shared<const an::DesignedMotion>(std::move(motion))};
        },
        py::arg("axes"), py::arg("function"), py::arg("parameters"));

    m.def(
        "relative_error", [](const Eigen::MatrixXd& designed, const Eigen::MatrixXd& measured) { return an::relativeError(designed, measured); },
        py::arg("designed"), py::arg("measured"),
          "Thesis eq. 5.18's form: sqrt(sum |designed - measured|^2) / sqrt(sum |measured|^2) (rows beyond the shorter ignored).");

    // ---- the whole chain ----
    py::class_<Analysis, Ptr<Analysis>>(m, "Analysis", R"doc(
The whole chain as `bunraku analyse` runs it (analysis/pipeline/chain.h): preprocess (2.2),
normalise every cell (3), decompose (4), fluctuations (4.3.2), motion axes, phase and gains (5).
data_files() are the bytes `bunraku analyse -o DIR` writes beside its report.)doc")
        .def_property_readonly("corpus", [](const Analysis& a) { return std::const_pointer_cast<an::Corpus>(a.chain.corpus.corpus); })
        .def_property_readonly("preprocessed", [](const Analysis& a) { return std::const_pointer_cast<Preprocessed>(a.preprocessed); })
        .def_property_readonly("normalisation", [](const Analysis& a) { return std::const_pointer_cast<Normalisation>(a.normalisation); })
        .def_property_readonly("decomposition", [](const Analysis& a) { return std::const_pointer_cast<Decomposed>(a.decomposed); })
        .def_property_readonly("fluctuations", [](const Analysis& a) { return std::const_pointer_cast<Fluctuations>(a.fluctuations); })
        .def_property_readonly("axes", [](const Analysis& a) { return std::const_pointer_cast<Axes>(a.axes); })
        .def_property_readonly("parameters", [](const Analysis& a) { return std::make_shared<pl::ChainParameters>(a.parameters); })
        .def_property_readonly("keys",
                               [](const Analysis& a) {
                                   py::dict keys;
                                   for (pl::Stage stage : pl::kStages) keys[pl::stageName(stage)] = a.chain.keys.of(stage).hex();
                                   return keys;
                               },
                               "Every stage's key (16 hex digits), as summary.json's \"keys\".")
        .def("data_files",
             [](const Analysis& a) {
                 const auto files = unwrap(rp::analysisDataFiles(a.chain, a.parameters));
                 py::dict out;
                 for (const auto& file : files) out[py::str(file.name)] = py::bytes(file.content);
                 return out;
             },
             "{name: bytes}: every data file `bunraku analyse` writes (parameters.json, summary.json, the CSV files).")
        .def(
            "write",
            [](const Analysis& a, const std::string& folder) {
                const auto files = unwrap(rp::analysisDataFiles(a.chain, a.parameters));
                unwrap(rp::writeOutputFiles(folder, files));
            },
            py::arg("folder"), "Writes the data files into `folder` (built beside it and swapped in whole, as `bunraku analyse`).")
        .def("__repr__", [](const Analysis& a) {
            return "<bunraku.Analysis of '" + a.chain.corpus.corpus->name + "': " + std::to_string(a.chain.normalised->cells.size()) +
                   " cells>";
        });

    m.def(
        "_analyse",
        [](const an::Corpus& corpus, const pl::ChainParameters& parameters, int threads) {
            const pl::CorpusInput input = corpusInput(corpus);
            pl::ChainOptions options;
            options.threads = resolvedThreads(threads);
            auto chain = unwrap(runReleased(
                [&](const an::RunControl& control) {
                    pl::ChainOptions run = options;
                    run.stop = control.stop;
                    return pl::runChain(input, parameters, nullptr, run);
                },
                options.threads));
            return wrapChain(std::move(chain), parameters);
        },
        py::arg("corpus"), py::arg("parameters"), py::arg("threads") = 0);
}

} // namespace bunraku::python
