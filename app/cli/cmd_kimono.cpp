// bunraku experiment kimono: the kimono simulated over every take of a corpus and measured
// (analysis/cloth/kimono_cloth.h; docs/KIMONO.md): per take and per emotion, the sleeves' and
// the hem's own swing and the sleeve's lag behind the hand.
#include "app/cli/commands.h"
#include "app/cli/output_guard.h"

#include "analysis/cloth/kimono_cloth.h"
#include "analysis/io/atomic_file.h"
#include "analysis/pipeline/stages.h"
#include "analysis/report/kimono_report.h"

#include <iostream>
#include <map>

namespace bunraku::app::cli {
namespace {

struct KimonoArguments {
    std::string corpus;
    bool json = false;
    std::string figure; ///< an SVG file: the measures per take, coloured by emotion
    an::ClothParameters cloth;
};

void runKimonoExperiment(const KimonoArguments& arguments)
{
    const pl::CorpusInput input = unwrap(pl::importCorpus(arguments.corpus));
    if (!arguments.figure.empty()) refuseOutputOverInputs(arguments.figure, OutputKind::File, {arguments.corpus}, "--figure");
    const std::vector<rp::KimonoTakeMeasures> rows = unwrap(rp::measureKimonos(*input.corpus, arguments.cloth));
    const std::vector<rp::KimonoCellMeans> cells = rp::kimonoCellMeans(rows);
    if (!arguments.figure.empty())
        if (auto status = an::io::writeFileAtomically(arguments.figure, rp::kimonoFigureSvg(rows)); !status)
            throw CliError(status.error().message);
    nlohmann::json summary = rp::kimonoMeasuresJson(rows, cells);
    summary["corpus"] = arguments.corpus;
    report(arguments.json, summary, [&] { std::cout << rp::kimonoCellMeansText(cells); });
}

} // namespace

void addClothOptions(CLI::App* command, analysis::ClothParameters& cloth)
{
    // The option and its help per parameter; the range is analysis's one table
    // (clothParameterLimits), as the workbench's Cloth Settings use it.
    const std::map<std::string, std::pair<const char*, const char*>> options{
        {"massPerArea", {"--cloth-mass", "Kimono cloth: mass per area, g/cm^2 (default 0.015, silk crepe)"}},
        {"stretchCompliance", {"--cloth-stretch", "Kimono cloth: stretch compliance of its threads, cm/dyn (default 0: inextensible)"}},
        {"bendCompliance", {"--cloth-bend", "Kimono cloth: bending compliance, cm/dyn (default 2e-4)"}},
        {"damping", {"--cloth-damping", "Kimono cloth: damping towards the body's motion, 1/s (default 1.5)"}},
        {"drag", {"--cloth-drag", "Kimono cloth: air drag, 1/s (default 0.6)"}},
        {"substepRate", {"--cloth-substeps", "Kimono cloth: simulation substeps per second (default 240)"}},
        {"collisionMargin", {"--cloth-margin", "Kimono cloth: cm it keeps off the torso and arms (default 0.3)"}},
        {"settleSeconds", {"--cloth-settle", "Kimono cloth: s the first pose is held before frame 0 so it hangs at rest (default 0.5)"}},
    };
    for (const analysis::ClothParameterLimit& limit : analysis::clothParameterLimits()) {
        const auto& [name, help] = options.at(limit.name);
        command->add_option(name, cloth.*(limit.member), help)->check(CLI::Range(limit.low, limit.high));
    }
}

void addKimonoCommands(CommandSet& commands)
{
    auto [command, arguments] =
        addCommand(commands.experiment, "kimono", runKimonoExperiment, "Print JSON (every take and the means per cell)");
    command->add_option("CORPUS", arguments.corpus, "Corpus folder (corpus.json), or 'demo' for the embedded synthetic corpus")->required();
    command->add_option("--figure", arguments.figure,
                        "Also write an SVG figure: per take, the sleeve's own swing against the hand's and its lag behind the hand, "
                        "coloured by emotion");
    addClothOptions(command, arguments.cloth);
}

} // namespace bunraku::app::cli
