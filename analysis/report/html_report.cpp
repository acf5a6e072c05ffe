#include "analysis/report/html_report.h"

#include "analysis/axis/axis_channels.h"
#include "analysis/io/bvh_joint_map.h"
#include "analysis/io/text_format.h"
#include "analysis/pipeline/parameters_json.h"
#include "analysis/report/analysis_files.h"
#include "analysis/report/svg_plot.h"
#include "analysis/report/thesis_values.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace bunraku::analysis::report {
namespace {

using pipeline::ChainResult;

std::string shown(double value, int precision = 4)
{
    if (!std::isfinite(value)) return "&mdash;";
    char text[32];
    std::snprintf(text, sizeof text, "%.*g", precision, value);
    return text;
}

/// A table cell holding a number of a data file: shown rounded, exact in data-value.
std::string dataCell(const std::string& source, const std::string& row, const std::string& column, double value)
{
    return "<td data-source=\"" + escapeXml(source) + "\" data-row=\"" + escapeXml(row) + "\" data-column=\"" + escapeXml(column) +
           "\" data-value=\"" + io::shortestNumber(value) + "\">" + shown(value) + "</td>";
}

std::string thesisCell(double value) { return "<td class=\"thesis\">" + shown(value) + "</td>"; }

Eigen::VectorXd frameAxis(Eigen::Index frames) { return Eigen::VectorXd::LinSpaced(frames, 0.0, double(std::max<Eigen::Index>(frames - 1, 0))); }

/// The channel whose variance normalisation lowered most in the cell (the figure's channel).
Eigen::Index mostImprovedChannel(const pipeline::CellNormalisation& cell)
{
    Eigen::Index best = 0;
    if (cell.variance.before.cols() == 0) return 0;
    (cell.variance.before.colwise().sum() - cell.variance.after.colwise().sum()).maxCoeff(&best);
    return best;
}

class Html {
public:
    Html& operator<<(const std::string& text)
    {
        m_out += text;
        return *this;
    }
    Html& section(const std::string& id, const std::string& title)
    {
        m_out += "<section id=\"" + id + "\"><h2>" + escapeXml(title) + "</h2>\n";
        return *this;
    }
    Html& end()
    {
        m_out += "</section>\n";
        return *this;
    }
    std::string str() const { return m_out; }

private:
    std::string m_out;
};

void overview(Html& html, const ChainResult& chain, const pipeline::ChainParameters& parameters, const ReportOptions& options)
{
    const Corpus& corpus = *chain.corpus.corpus;
    html.section("overview", "Overview");
    html << "<p>Corpus <b>" + escapeXml(corpus.name.empty() ? options.corpusSource : corpus.name) + "</b>" +
                (options.corpusSource.empty() ? "" : " (" + escapeXml(options.corpusSource) + ")") + ": " +
                std::to_string(corpus.takes.size()) + " takes, " + std::to_string(corpus.functions().size()) + " functions x " +
                std::to_string(corpus.emotions().size()) + " emotions, " + shown(corpus.rateHz) + " Hz. Chain: preprocessing "
                "(thesis 2.2), normalisation of every cell (3), decomposition (4: " +
                pipeline::methodName(parameters.decompose.method) + " on the " + pipeline::inputName(parameters.decompose.input) +
                " takes), fluctuation analysis (4.3.2), motion axes, phase and gains (5). Values in <span class=\"thesis\">grey"
                "</span> are the thesis's, measured on its (lost) recordings; ours come from this corpus.</p>\n";
    html << "<table><tr><th>stage</th><th>key</th></tr>";
    for (pipeline::Stage stage : pipeline::kStages)
        html << "<tr><td>" + std::string(pipeline::stageTitle(stage)) + "</td><td><code>" + chain.keys.of(stage).hex() + "</code></td></tr>";
    html << "</table>\n<details><summary>Parameters (parameters.json)</summary><pre>" +
                escapeXml(pipeline::toJson(parameters).dump(2)) + "</pre></details>\n";
    html.end();
}

void preprocessSection(Html& html, const ChainResult& chain)
{
    html.section("preprocess", "Preprocessing (thesis 2.2)");
    html << "<p>Takes padded to the longest, angles unwrapped, start times aligned within each cell, headings and start "
            "positions aligned to each function's reference.</p><table><tr><th>take</th><th>frames padded</th><th>wraps removed"
            "</th><th>start shift (frames)</th><th>heading offset (deg)</th></tr>";
    for (const auto& take : chain.preprocessed->report.takes)
        html << "<tr><td>" + escapeXml(take.take) + "</td><td>" + std::to_string(take.framesPadded) + "</td><td>" +
                    std::to_string(take.anglesUnwrapped) + "</td><td>" + std::to_string(take.shiftFrames) + "</td><td>" +
                    shown(take.headingOffsetDeg) + "</td></tr>";
    html << "</table>\n";
    html.end();
}

void normaliseSection(Html& html, const ChainResult& chain, const pipeline::ChainParameters& parameters)
{
    html.section("normalise", "Normalisation of every cell (thesis 3.6-3.8)");
    // The preset `auto` resolved to (method2 on the puppet's parts, chains on a skeleton's joints).
    std::string coupling = parameters.normalise.coupling;
    for (const auto& cell : chain.normalised->cells)
        if (!cell.normalisations.empty() && !cell.normalisations.front().coupling.preset.empty() &&
            cell.normalisations.front().coupling.preset != coupling) {
            coupling += " (" + cell.normalisations.front().coupling.preset + ")";
            break;
        }
    html << "<p>tau = " + std::to_string(parameters.normalise.tau) + ", T_cmp = " + std::to_string(parameters.normalise.searchBand) +
                ", scales 1.." + std::to_string(parameters.normalise.maxScale) + ", coupling " +
                escapeXml(coupling) + ", " + pipeline::pathName(parameters.normalise.path) +
                " path. Variance: sum over frames and channels of the squared difference to the reference (3.8).</p>\n";
    for (const auto& cell : chain.normalised->cells) {
        const std::string stem = cellStem(cell.function, cell.emotion);
        const Eigen::Index channel = mostImprovedChannel(cell);
        const std::string channelName = cell.variance.channelNames.empty() ? "" : cell.variance.channelNames[std::size_t(channel)];
        html << "<h3 id=\"normalise-" + escapeXml(stem) + "\">" + escapeXml(cell.function + "/" + cell.emotion) + " to " +
                    escapeXml(cell.referenceName) + "</h3><div class=\"figures\">";
        SvgPlot raw{"raw (preprocessed) takes, " + channelName, "frame", channelName, 420, 240, false, {}};
        SvgPlot normalised{"normalised takes, " + channelName, "reference frame", channelName, 420, 240, false, {}};
        const auto takes = chain.preprocessed->corpus.cell(cell.function, cell.emotion);
        for (std::size_t k = 0; k < takes.size() && k < cell.normalisations.size(); ++k) {
            const std::string label = "take " + std::to_string(cell.takeIndices[k]);
            raw.series.push_back({label, frameAxis(takes[k]->frameCount()), takes[k]->values.col(channel), paletteColour(k)});
            const Take& n = cell.normalisations[k].normalised;
            normalised.series.push_back({label, frameAxis(n.frameCount()), n.values.col(channel), paletteColour(k)});
        }
        normalised.series.push_back({"reference", frameAxis(cell.referenceTake.frameCount()), cell.referenceTake.values.col(channel),
                                     "#000", true, 1.6});
        html << renderSvg(raw) + renderSvg(normalised) + "</div>";
        const std::string source = "variance_" + stem + ".csv";
        const bool thesisCellShown = cell.function == "greeting" && cell.emotion == "none";
        html << "<table class=\"numbers\" data-table=\"variance\"><tr><th>take</th><th>raw</th><th>normalised</th>" +
                    std::string(thesisCellShown ? "<th class=\"thesis\">thesis x_4: raw x10^5</th><th class=\"thesis\">normalised"
                                                  "</th><th class=\"thesis\">4ave: raw</th><th class=\"thesis\">normalised</th>"
                                                : "") +
                    "</tr>";
        for (std::size_t k = 0; k < cell.takeIndices.size(); ++k) {
            const std::string take = std::to_string(cell.takeIndices[k]);
            html << "<tr><td>" + take + (int(k) == cell.suggestion.takeIndex ? " (suggested)" : "") +
                        (cell.suggestion.outlier[k] ? " (outlier)" : "") + "</td>" +
                        dataCell(source, take + ",raw", "total", cell.variance.totalBefore[Eigen::Index(k)]) +
                        dataCell(source, take + ",normalised", "total", cell.variance.totalAfter[Eigen::Index(k)]);
            if (thesisCellShown && cell.takeIndices[k] >= 1 && cell.takeIndices[k] <= 5) {
                const auto& row = thesisVarianceTable(2)[std::size_t(cell.takeIndices[k] - 1)];
                html << thesisCell(row.values[0]) + thesisCell(row.values[1]) + thesisCell(row.values[4]) + thesisCell(row.values[5]);
            }
            html << "</tr>";
        }
        html << "</table>\n";
        if (thesisCellShown)
            html << "<p class=\"note\">Thesis Table 3.5 (method 2, greeting/none, x 10^5, its raw FASTRAK units): normalisation "
                    "lowered every take's variance, and the averaged reference 4ave lowered it further than take 4.</p>\n";
    }
    html.end();
}

void averageSection(Html& html, const ChainResult& chain)
{
    html.section("average", "Average takes (thesis 3.7)");
    html << "<p>Per cell, the average take (base: the suggested reference; outliers left out) over its members, for the channel "
            "shown above.</p><div class=\"figures\">";
    for (const auto& cell : chain.normalised->cells) {
        const Eigen::Index channel = mostImprovedChannel(cell);
        const std::string channelName = cell.variance.channelNames.empty() ? "" : cell.variance.channelNames[std::size_t(channel)];
        SvgPlot plot{cell.function + "/" + cell.emotion + ": " + cell.averageName + ", " + channelName, "frame", channelName, 420, 240,
                     false, {}};
        for (std::size_t k = 0; k < cell.normalisations.size(); ++k)
            plot.series.push_back({"", frameAxis(cell.normalisations[k].normalised.frameCount()),
                                   cell.normalisations[k].normalised.values.col(channel), "#bbb"});
        plot.series.push_back({cell.averageName, frameAxis(cell.average.frameCount()), cell.average.values.col(channel), "#d62728",
                               false, 2.0});
        html << renderSvg(plot);
    }
    html << "</div>\n";
    html.end();
}

/// The cells with one take, which have no fluctuation to analyse (4.3.2); empty when none.
std::string oneTakeCellsNote(const ChainResult& chain)
{
    const Decomposition& d = chain.decomposed->components;
    std::string cells;
    for (const auto& z : d.emotions)
        if (cellTakeCount(d, z.function, z.emotion) < 2) cells += (cells.empty() ? "" : ", ") + z.function + "/" + z.emotion;
    if (cells.empty()) return {};
    return "<p class=\"one-take\">No spectrum and no ARMA model for the cells with one take (" + escapeXml(cells) +
           "): the fluctuation is the take minus its cell mean (eq. 4.24), identically zero with one take.</p>";
}

/// The channels the spectra and the ARMA table show: the thesis's head.x and arm.z (Table 4.1,
/// Fig. 4.5), or on takes of a skeleton's joints the head joint's x and the bound-side forearm's
/// z (the joints the automatic part map gives the puppet's head and arm), by the joints' names.
std::pair<std::string, std::string> shownChannels(const std::vector<std::string>& channelNames)
{
    const auto has = [&](const std::string& name) { return std::find(channelNames.begin(), channelNames.end(), name) != channelNames.end(); };
    std::pair<std::string, std::string> shown{"head.x", "arm.z"};
    if (has(shown.first) || has(shown.second)) return shown;
    shown = {};
    for (const auto& name : channelNames) {
        const std::string part = name.substr(0, name.rfind('.'));
        const io::JointNameInfo info = io::jointNameInfo(part);
        if (shown.first.empty() && !info.side && info.term == "head" && has(part + ".x")) shown.first = part + ".x";
        const bool forearm = info.term == "forearm" || info.term == "lowerarm" || info.term == "lowarm" || info.term == "elbow" ||
                             info.term == "radius";
        if (shown.second.empty() && forearm && info.side == BodySide::Right && has(part + ".z")) shown.second = part + ".z";
    }
    if (shown.first.empty() && !channelNames.empty()) shown.first = channelNames.front();
    return shown;
}

void spectraSection(Html& html, const ChainResult& chain)
{
    const auto& f = *chain.fluctuations;
    html.section("spectra", "Spectra of the fluctuation (thesis 4.3.2)");
    html << "<p>Welch power spectral density of eta = x - y - z, averaged over each cell's takes (data: spectra.csv).</p>";
    html << oneTakeCellsNote(chain);
    html << "<div class=\"figures\">";
    const std::vector<std::string> functions = chain.corpus.corpus->functions();
    for (const auto& function : functions) {
        const auto [first, second] = shownChannels(f.channelNames);
        for (const std::string& channel : {first, second}) {
            const auto at = std::find(f.channelNames.begin(), f.channelNames.end(), channel);
            if (at == f.channelNames.end()) continue;
            const auto ch = Eigen::Index(at - f.channelNames.begin());
            SvgPlot plot{function + ": eta " + channel, "frequency [Hz]", "power", 420, 240, true, {}};
            std::size_t colour = 0;
            for (const auto& cell : f.spectra)
                if (cell.function == function && cell.power.cols() > ch)
                    plot.series.push_back({cell.emotion, cell.frequencyHz, cell.power.col(ch), paletteColour(colour++)});
            html << renderSvg(plot);
        }
    }
    html << "</div>\n";
    html.end();
}

void armaSection(Html& html, const ChainResult& chain)
{
    const auto& f = *chain.fluctuations;
    html.section("arma", "ARMA identification of the fluctuation (thesis 4.3.2, Table 4.1)");
    html << "<p>ARMA(" + std::to_string(f.armaP) + "," + std::to_string(f.armaQ) +
                ") per take, averaged over each cell's takes (data: arma_table.csv, every channel). " +
                shownChannels(f.channelNames).first + " as Table 4.1's head-x. "
                "The MA part is known only up to its spectrum: b is the invertible factor (every root of B inside the "
                "unit circle), b<sup>T</sup> the same spectrum in Table 4.1's convention (B's largest root outside, "
                "b1/b0 &gt; 1; docs/ARMA.md):</p>";
    html << oneTakeCellsNote(chain);
    const std::string shown = shownChannels(f.channelNames).first;
    const auto at = std::find(f.channelNames.begin(), f.channelNames.end(), shown);
    const std::size_t ch = at == f.channelNames.end() ? 0 : std::size_t(at - f.channelNames.begin());
    html << "<table class=\"numbers\" data-table=\"arma\"><tr><th>cell</th>";
    for (int m = 1; m <= f.armaP; ++m) html << "<th>a" + std::to_string(m) + "</th>";
    for (int n = 0; n <= f.armaQ; ++n) html << "<th>b" + std::to_string(n) + "</th>";
    for (int n = 0; n <= f.armaQ; ++n) html << "<th>b" + std::to_string(n) + "<sup>T</sup></th>";
    // The thesis's values beside ours only for the puppet's head-x.
    const bool thesisShape = f.armaP == 2 && f.armaQ == 2 && shown == "head.x";
    if (thesisShape) html << "<th class=\"thesis\">thesis a1</th><th class=\"thesis\">a2</th><th class=\"thesis\">b0</th><th class=\"thesis\">b1</th><th class=\"thesis\">b2</th>";
    html << "</tr>";
    if (ch < f.armaTables.size()) {
        for (const auto& row : f.armaTables[ch]) {
            if (row.takes == 0) continue;
            const std::string key = f.channelNames[ch] + "," + row.function + "," + row.emotion;
            html << "<tr><td>" + escapeXml(row.function + "/" + row.emotion) + "</td>";
            for (int m = 0; m < f.armaP; ++m) html << dataCell("arma_table.csv", key, "a" + std::to_string(m + 1), row.mean.a(m));
            for (int n = 0; n <= f.armaQ; ++n) html << dataCell("arma_table.csv", key, "b" + std::to_string(n), row.mean.b(n));
            for (int n = 0; n <= f.armaQ; ++n)
                html << dataCell("arma_table.csv", key, "b" + std::to_string(n) + "_thesis", row.mean.bThesis(n));
            if (thesisShape)
                for (double value : thesisArmaHeadX(thesisFunctionIndex(row.function), thesisEmotionIndex(row.emotion)))
                    html << thesisCell(value);
            html << "</tr>";
        }
        if (!f.armaErrors[ch].empty()) html << "<tr><td colspan=\"14\">" + escapeXml(f.armaErrors[ch]) + "</td></tr>";
    }
    html << "</table>\n";
    html.end();
}

void km2oSection(Html& html, const ChainResult& chain)
{
    html.section("km2o", "KM2O-Langevin decomposition: P by M (thesis 4.4.4, Table 4.5)");
    const auto& km2o = chain.decomposed->km2o;
    if (!km2o) {
        html << "<p>The decomposition ran by least squares (4.3.1): no correlation length to choose.</p>";
        html.end();
        return;
    }
    if (!km2o->notes.empty()) {
        // Cells with one take (docs/KM2O.md): where each cell's gamma_+ and V_+ came from.
        html << "<p data-km2o-outcome=\"" + std::string(km2o->estimable() ? "estimable" : "not-estimable") + "\"><b>" +
                    escapeXml(km2o->outcome()) + ".</b> A cell with one take has no diff series (eq. 4.24, x - x<sub>mean</sub> = 0); "
                    "its gamma<sub>+</sub>, V<sub>+</sub> are pooled from the cells of its function with two or more takes "
                    "(eq. 4.39 gives the dynamics per function); a function without such a cell keeps its least-squares y, z "
                    "(eq. 4.8).</p><ul class=\"km2o-notes\">";
        for (const auto& note : km2o->notes) html << "<li>" + escapeXml(note) + "</li>";
        html << "</ul><table class=\"numbers\" data-table=\"km2o-cells\"><tr><th>cell</th><th>takes</th><th>gamma, V</th></tr>";
        for (const auto& cell : km2o->cells)
            html << "<tr><td>" + escapeXml(cell.function + "/" + cell.emotion) + "</td><td>" + std::to_string(cell.takes) + "</td><td>" +
                        km2oCellSourceName(cell.source) + "</td></tr>";
        html << "</table>";
    }
    if (!km2o->estimable()) {
        html << "<p>No correlation length M and no P<sup>ij</sup>: the function and emotion components above are the "
                "least-squares ones (4.3.1).</p>";
        html.end();
        return;
    }
    html << "<p>Relative error P (eq. 4.40) of y + z against the cell means, averaged over channels and cells, for every "
            "correlation length M = 1..M_max; the smallest P chooses M. Ours: <b>M = " +
                std::to_string(km2o->correlationLength) + "</b>, mean P = <b>" + shown(km2o->meanCellErrorPercent) +
                " %</b>; <span class=\"thesis\">the thesis: M = " + std::to_string(kThesisCorrelationLength) + ", mean P = " +
                shown(kThesisMeanErrorPercent) + " %</span>.</p>";
    SvgPlot plot{"mean P by M", "M", "P [%]", 460, 260, false, {}};
    Eigen::VectorXd m(Eigen::Index(km2o->candidateLengths.size())), p(m.size());
    for (Eigen::Index i = 0; i < m.size(); ++i) {
        m[i] = km2o->candidateLengths[std::size_t(i)];
        p[i] = km2o->meanErrorPercent[std::size_t(i)];
    }
    plot.series.push_back({"ours", m, p, paletteColour(0), false, 1.6});
    html << "<div class=\"figures\">" + renderSvg(plot) + "</div><table class=\"numbers\" data-table=\"km2o\"><tr><th>M</th><th>mean P [%]</th></tr>";
    for (std::size_t i = 0; i < km2o->candidateLengths.size(); ++i)
        html << "<tr><td>" + std::to_string(km2o->candidateLengths[i]) + "</td>" +
                    dataCell("km2o_by_M.csv", std::to_string(km2o->candidateLengths[i]), "mean_P_percent", km2o->meanErrorPercent[i]) +
                    "</tr>";
    html << "</table><h3>P<sup>ij</sup> [%] per channel at M = " + std::to_string(km2o->correlationLength) + " (Table 4.5)</h3>";
    const Decomposition& d = chain.decomposed->components;
    html << "<table class=\"numbers\" data-table=\"km2o-errors\"><tr><th>channel</th>";
    for (const auto& z : d.emotions) html << "<th>" + escapeXml(z.function + "/" + z.emotion) + "</th><th class=\"thesis\">thesis</th>";
    html << "</tr>";
    for (std::size_t ch = 0; ch < d.channels.size(); ++ch) {
        const std::string name = d.channels[ch].name();
        html << "<tr><td>" + escapeXml(name) + "</td>";
        for (std::size_t c = 0; c < d.emotions.size(); ++c) {
            const auto& z = d.emotions[c];
            const double cellP = km2o->cellErrorPercent(Eigen::Index(ch), Eigen::Index(c));
            // NaN: a cell of a function KM2O could not estimate (least squares, no P).
            html << (std::isfinite(cellP) ? dataCell("km2o_errors.csv", name, "P_" + z.function + "/" + z.emotion, cellP) : "<td>&mdash;</td>");
            html << thesisCell(thesisCellErrorPercent(name, thesisFunctionIndex(z.function), thesisEmotionIndex(z.emotion)));
        }
        html << "</tr>";
    }
    html << "</table>\n";
    html.end();
}

SvgPlot axisPlot(const std::string& title, const Eigen::MatrixXd& coordinates, int first)
{
    static const char* names[] = {"x", "y", "z", "rot_x", "rot_y", "rot_z"};
    SvgPlot plot{title, "frame", first == 0 ? "cm" : "deg", 420, 240, false, {}};
    for (int q = first; q < first + 3 && q < coordinates.cols(); ++q)
        plot.series.push_back({names[q], frameAxis(coordinates.rows()), coordinates.col(q), paletteColour(std::size_t(q))});
    return plot;
}

/// A section of chapter 5 when the motion axes were not computed: the one line that says why.
bool axesSkipped(Html& html, const ChainResult& chain)
{
    if (chain.axes->unavailable.empty()) return false;
    html << "<p class=\"note\">" + escapeXml(chain.axes->unavailable) + "</p>\n";
    html.end();
    return true;
}

void axesSection(Html& html, const ChainResult& chain)
{
    html.section("axes", "Motion axes (thesis 5.2.1)");
    if (axesSkipped(html, chain)) return;
    html << "<p>The principal axes of inertia of the posed puppet per frame, as centre of mass (cm) and rotation vector (deg), "
            "for each function's functional motion (the neutral cell's average take) and each emotional cell's average take "
            "(data: axis_functional_*.csv, axis_emotional_*.csv).</p><div class=\"figures\">";
    for (const auto& function : chain.axes->functions) {
        html << renderSvg(axisPlot(function.function + " (functional): centre", function.basis->coordinates, 0));
        html << renderSvg(axisPlot(function.function + " (functional): rotation", function.basis->coordinates, 3));
    }
    for (const auto& cell : chain.axes->cells) {
        html << renderSvg(axisPlot(cell.function + "/" + cell.emotion + ": centre", cell.coordinates, 0));
        html << renderSvg(axisPlot(cell.function + "/" + cell.emotion + ": rotation", cell.coordinates, 3));
    }
    html << "</div>\n";
    html.end();
}

void warpsSection(Html& html, const ChainResult& chain)
{
    html.section("warps", "Phase: warp curves (thesis 5.3)");
    if (axesSkipped(html, chain)) return;
    html << "<p>For each emotional cell, the functional frame each emotional frame shows (Fig. 5.13), with the control points "
            "a design edits (data: phase_*.csv, warp_*.csv).</p><div class=\"figures\">";
    for (const auto& cell : chain.axes->cells) {
        const auto& phase = cell.extracted.phase;
        SvgPlot plot{cell.function + "/" + cell.emotion, "emotional frame", "functional frame", 420, 260, false, {}};
        const Eigen::Index frames = phase.emotionalToFunctional.size();
        plot.series.push_back({"identity", frameAxis(frames), frameAxis(frames), "#999", true});
        plot.series.push_back({"warp", frameAxis(frames), phase.emotionalToFunctional, paletteColour(0), false, 1.8});
        Eigen::VectorXd x(Eigen::Index(phase.curve.points.size())), y(x.size());
        for (Eigen::Index i = 0; i < x.size(); ++i) {
            x[i] = phase.curve.points[std::size_t(i)].output;
            y[i] = phase.curve.points[std::size_t(i)].source;
        }
        plot.series.push_back({"control points", x, y, paletteColour(1), true, 1.0});
        html << renderSvg(plot);
    }
    html << "</div>\n";
    html.end();
}

void approximationSection(Html& html, const ChainResult& chain)
{
    html.section("approximation", "Approximation error per scale (thesis 5.4.1, eq. 5.18, Fig. 5.16)");
    if (axesSkipped(html, chain)) return;
    html << "<p>For each emotional cell, the relative error of eq. 5.18 between the wavelet approximations (scales 1..c, "
            "eq. 5.13) of the functional axis and of the phase-adjusted emotional axis, against c (data: approximation_*.csv). "
            "The thesis plots it for no emotion against friendly (Fig. 5.16, no values printed): it falls as c grows but "
            "stays large for some DOF, which is why the amplitude is taken from Fourier series over phrases (5.4.2).</p>"
            "<div class=\"figures\">";
    const auto channels = axisCoordinateChannels();
    for (const auto& cell : chain.axes->cells) {
        const ApproximationError& error = cell.approximation;
        if (error.scales.empty()) continue;
        SvgPlot plot{cell.function + "/" + cell.emotion, "largest scale c", "relative error", 420, 260, false, {}};
        Eigen::VectorXd scales(Eigen::Index(error.scales.size()));
        for (Eigen::Index c = 0; c < scales.size(); ++c) scales[c] = error.scales[std::size_t(c)];
        for (Eigen::Index q = 0; q < error.relativeError.cols(); ++q)
            plot.series.push_back({q < Eigen::Index(channels.size()) ? channels[std::size_t(q)].dof : std::to_string(q), scales,
                                   error.relativeError.col(q), paletteColour(std::size_t(q)), false, 1.2});
        plot.series.push_back({"mean", scales, error.meanRelativeError, "#000", false, 2.2});
        html << renderSvg(plot);
    }
    html << "</div>\n<table class=\"numbers\" data-table=\"approximation\"><tr><th>cell</th>";
    const std::vector<int> shownScales{1, 2, 4, 8, 12, 16};
    for (int c : shownScales) html << "<th>mean, c = " + std::to_string(c) + "</th>";
    html << "</tr>";
    for (const auto& cell : chain.axes->cells) {
        const std::string source = "approximation_" + cellStem(cell.function, cell.emotion) + ".csv";
        html << "<tr><td>" + escapeXml(cell.function + "/" + cell.emotion) + "</td>";
        for (int c : shownScales)
            html << (c <= int(cell.approximation.scales.size())
                         ? dataCell(source, std::to_string(c), "mean", cell.approximation.meanRelativeError(c - 1))
                         : std::string("<td>&mdash;</td>"));
        html << "</tr>";
    }
    html << "</table>\n";
    html.end();
}

void gainsSection(Html& html, const ChainResult& chain)
{
    html.section("gains", "Amplitude: gains per phrase (thesis 5.4) and the design check (5.5)");
    if (axesSkipped(html, chain)) return;
    html << "<p>g0 (eq. 5.22, phrase mean) and g1 (eq. 5.23, first harmonic) of the functional axis against the phase-adjusted "
            "emotional axis, per phrase and axis DOF (data: gains_*.csv). Designing the functional motion with the extracted "
            "warp and gains reproduces the emotional axis to the relative error (eq. 5.18 form) shown.</p>";
    for (const auto& cell : chain.axes->cells) {
        const std::string source = "gains_" + cellStem(cell.function, cell.emotion) + ".csv";
        const GainSet& gains = cell.extracted.gains;
        html << "<h3>" + escapeXml(cell.function + "/" + cell.emotion) + "</h3><p>relative error of the designed axis: <b>" +
                    shown(cell.designRelativeError) + "</b> (functional axis undesigned: " + shown(cell.undesignedRelativeError) +
                    ")</p><table class=\"numbers\" data-table=\"gains\"><tr><th>phrase (frames)</th>";
        for (const auto& dof : gains.dofNames) html << "<th>" + escapeXml(dof) + " g0</th><th>g1</th>";
        html << "</tr>";
        for (std::size_t p = 0; p < gains.phrases.size(); ++p) {
            const auto& phrase = gains.phrases[p];
            html << "<tr><td>" + std::to_string(p) + " (" + std::to_string(phrase.begin) + "-" + std::to_string(phrase.end) + ")</td>";
            for (std::size_t d = 0; d < phrase.dofs.size(); ++d) {
                const std::string row = std::to_string(p) + "," + (d < gains.dofNames.size() ? gains.dofNames[d] : std::to_string(d));
                html << dataCell(source, row, "g0", phrase.dofs[d].g0) + dataCell(source, row, "g1", phrase.dofs[d].g1);
            }
            html << "</tr>";
        }
        html << "</table>\n";
    }
    html.end();
}

const char* kStyle = R"(body{font-family:sans-serif;margin:1.5em auto;max-width:1100px;color:#222;line-height:1.4}
h1{font-size:1.6em}h2{border-bottom:1px solid #ccc;padding-bottom:.2em;margin-top:1.6em}h3{font-size:1.05em}
table{border-collapse:collapse;margin:.5em 0;font-size:.85em}td,th{border:1px solid #ccc;padding:2px 6px;text-align:right}
th{background:#f3f3f3}td:first-child{text-align:left}.thesis{color:#777;background:#fafafa}.note{color:#555;font-size:.9em}
.figures{display:flex;flex-wrap:wrap;gap:8px}nav a{margin-right:.8em}pre{font-size:.8em;background:#f7f7f7;padding:.5em})";

} // namespace

const std::vector<std::string>& reportSections()
{
    static const std::vector<std::string> ids{"overview", "preprocess", "normalise", "average", "spectra",
                                              "arma",     "km2o",       "axes",      "warps",   "approximation", "gains"};
    return ids;
}

Result<std::string> htmlReport(const ChainResult& chain, const pipeline::ChainParameters& parameters, const ReportOptions& options)
{
    if (!chain.corpus.corpus || !chain.preprocessed || !chain.normalised || !chain.decomposed || !chain.fluctuations || !chain.axes)
        return makeError(ErrorCode::InvalidArgument, "the report needs every stage's result");
    Html html;
    html << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>" + escapeXml(options.title) +
                "</title><style>" + kStyle + "</style></head><body>\n<h1>" + escapeXml(options.title) + "</h1>\n<nav>";
    for (const auto& id : reportSections()) html << "<a href=\"#" + id + "\">" + id + "</a>";
    html << "</nav>\n";
    overview(html, chain, parameters, options);
    preprocessSection(html, chain);
    normaliseSection(html, chain, parameters);
    averageSection(html, chain);
    spectraSection(html, chain);
    armaSection(html, chain);
    km2oSection(html, chain);
    axesSection(html, chain);
    warpsSection(html, chain);
    approximationSection(html, chain);
    gainsSection(html, chain);
    html << "<footer><p class=\"note\">" + escapeXml(options.generator) +
                ". Thesis: M. Hattori, Analysis of emotional expression in the performance motions of Bunraku puppets, Kobe "
                "University, 2000.</p></footer></body></html>\n";
    return html.str();
}

} // namespace bunraku::analysis::report
