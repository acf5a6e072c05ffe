// Subcommands: info, convert, preprocess.
#include "app/cli/commands.h"
#include "app/cli/chain_parameters.h"
#include "app/cli/import_options.h"
#include "app/cli/take_output.h"
#include "app/cli/output_guard.h"

#include "analysis/cloth/kimono_cloth.h"
#include "analysis/core/puppet_layout.h"
#include "analysis/io/bvh.h"
#include "analysis/io/take_csv.h"
#include "analysis/io/bvh_joint_map.h"
#include "analysis/io/corpus_io.h"
#include "analysis/io/take_reader.h"
#include "analysis/io/take_source.h"
#include "analysis/io/text_format.h"
#include "analysis/pipeline/heading_part.h"
#include "analysis/pipeline/stage_parameters.h"
#include "analysis/preprocess/preprocess.h"
#include "analysis/preprocess/preprocess_report.h"
#include "analysis/report/corpus_description.h"
#include "analysis/skeleton/puppet_rig_fit.h"
#include "analysis/synth/demo_corpus_io.h"
#include "render/take_export.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <limits>
#include <optional>

namespace bunraku::app::cli {
namespace {

namespace fs = std::filesystem;
namespace io = analysis::io;
namespace pre = analysis::preprocess;
namespace synth = analysis::synth;
using analysis::Corpus;
using analysis::Take;
using analysis::PuppetRigFit;
using analysis::fitPuppetRig;
using analysis::describePuppetRigResidual;
using analysis::hasPuppetLayout;
using analysis::kPuppetParts;
using nlohmann::json;

/// The path's corpus (io/take_source.h), the import options read only for a file that exists
/// (a folder, or nothing at the path, is reported before a bad option).
io::TakeSource load(const std::string& pathText, const ImportArguments& arguments,
                    io::UnmappedSkeleton unmapped = io::UnmappedSkeleton::Error)
{
    std::error_code ec;
    const bool file = !fs::is_directory(pathText, ec) && fs::exists(pathText, ec);
    return unwrap(io::readTakeSource(pathText, file ? importOptions(arguments, pathText) : io::ImportOptions{}, unmapped));
}

json takeJson(const Take& take)
{
    return {{"name", take.displayName()},
            {"function", take.labels.function},
            {"emotion", take.labels.emotion},
            {"take", take.labels.takeIndex},
            {"source", take.labels.source},
            {"frames", take.frameCount()},
            {"duration_s", take.duration()}};
}

// ---- info -------------------------------------------------------------------------------

struct InfoArguments {
    std::string path;
    bool json = false;
    ImportArguments import;
};

void runInfo(const InfoArguments& arguments)
{
    const io::TakeSource loaded = load(arguments.path, arguments.import, io::UnmappedSkeleton::Describe);
    const Corpus& corpus = loaded.corpus;
    json summary{{"path", arguments.path}, {"format", loaded.format}, {"name", corpus.name}, {"takes", corpus.takes.size()},
                 {"rate_hz", corpus.rateHz}};
    if (loaded.bvh) summary.update(io::skeletalFileJson(loaded));
    if (corpus.takes.empty()) // a BVH file whose puppet parts found no joints
        return report(arguments.json, summary, [&] {
            std::cout << arguments.path << " (" << loaded.format << ")\n";
            std::cout << io::skeletalFileText(loaded);
        });
    const Take& first = corpus.takes.front();
    Eigen::Index frames = 0;
    for (const Take& take : corpus.takes) frames = std::max(frames, take.frameCount());
    const Eigen::Index channels = first.channelCount();
    const rp::ChannelRanges ranges = rp::channelRanges(corpus);

    // Takes of the puppet's 24 channels without a skeleton get the puppet's rig (one body per
    // take; analysis/skeleton/puppet_rig_fit.h): how well it fits them.
    std::vector<const Take*> rigTakes;
    for (const Take& take : corpus.takes)
        if (!take.skeleton && hasPuppetLayout(take) && take.frameCount() > 0) rigTakes.push_back(&take);
    std::optional<PuppetRigFit> rig;
    if (!rigTakes.empty()) {
        auto fit = fitPuppetRig(rigTakes);
        if (!fit) throw CliError(arguments.path + ": " + fit.error().message, exitCodeOf(fit.error()));
        rig = std::move(fit).value();
    }

    json takeList = json::array();
    for (const Take& take : corpus.takes) takeList.push_back(takeJson(take));
    json names = json::array();
    for (Eigen::Index c = 0; c < channels; ++c) names.push_back(first.channels[std::size_t(c)].name());
    summary.update(json{{"channels", channels}, {"frames", frames}, {"parts", first.parts()}, {"take_list", takeList},
                        {"channel_names", names}, {"ranges", rp::channelRangesJson(first.channels, ranges)}});
    if (loaded.isCorpus) {
        summary["functions"] = corpus.functions();
        summary["emotions"] = corpus.emotions();
        summary["neutral_emotion"] = corpus.neutralEmotion;
        summary["convention"] = corpus.convention;
    }
    if (rig) summary["rig_fit"] = rp::puppetRigFitJson(*rig, rigTakes.size());
    report(arguments.json, summary, [&] {
        std::cout << arguments.path << " (" << loaded.format << ")\n";
        if (loaded.isCorpus) std::cout << "corpus: " << corpus.name << "\n";
        std::cout << "takes: " << corpus.takes.size() << ", frames: " << frames << " at most, rate: " << corpus.rateHz
                  << " Hz, channels: " << channels << "\n";
        if (loaded.isCorpus) {
            std::cout << "\ntakes:\n";
            for (const Take& take : corpus.takes)
                std::cout << "  " << std::left << std::setw(28) << take.displayName() << std::right << std::setw(6) << take.frameCount()
                          << " frames  " << take.labels.source << (take.skeleton ? "  (with its skeleton)" : "") << "\n";
        }
        std::cout << "\nchannels (min .. max):\n" << rp::channelRangesText(first.channels, ranges);
        if (rig)
            std::cout << "\npuppet rig fitted to " << rigTakes.size() << (rigTakes.size() == 1 ? " take" : " takes")
                      << " (one body: derived takes move it; each part's distance from its channels, largest and rms):\n  "
                      << describePuppetRigResidual(rig->residual) << "\n";
        if (loaded.bvh) std::cout << io::skeletalFileText(loaded);
    });
}

// ---- convert ----------------------------------------------------------------------------

struct ConvertArguments {
    std::string input;
    std::string output;
    bool json = false;
    bool kimono = false;
    analysis::ClothParameters cloth;
    ImportArguments import;
};

void runConvert(const ConvertArguments& arguments)
{
    refuseOutputOverInputs(arguments.output, fs::is_directory(arguments.input) ? OutputKind::Folder : OutputKind::File,
                           {arguments.input});
    const io::TakeSource loaded = load(arguments.input, arguments.import);
    const fs::path output = arguments.output;
    std::string written;
    if (loaded.isCorpus) {
        if (io::takeFileFormat(output) != io::TakeFileFormat::Unknown)
            throw CliError(output.string() + ": a corpus converts to a corpus folder, not to a single file");
        unwrap(io::writeCorpus(loaded.corpus, output));
        written = "corpus";
    } else if (arguments.kimono && io::takeFileFormat(output) != io::TakeFileFormat::Csv) {
        // The simulated cloth in a .glb (morph targets animated by weights; render/take_export.h).
        if (render::takeExportFormat(output) != render::TakeExportFormat::Glb)
            throw CliError(output.string() + ": --kimono writes a .csv take (the kimono's points are channels beside the take's) or a .glb "
                                             "(the simulated cloth)");
        writeTakeOutput(loaded.corpus.takes.front(), output.string(), &arguments.cloth);
        written = "glb";
    } else if (arguments.kimono) {
        // The kimono's measured points as 18 more channels (analysis/cloth/kimono_cloth.h): only a
        // CSV take holds channels that are not a skeleton's.
        const Take& take = loaded.corpus.takes.front();
        const auto simulation = analysis::simulateKimono(take, arguments.cloth);
        if (!simulation) throw CliError(arguments.input + ": " + simulation.error().message);
        unwrap(io::writeTakeCsv(analysis::withKimonoChannels(take, *simulation), output));
        written = "csv";
    } else {
        requireTakeOutput(output.string());
        writeTakeOutput(loaded.corpus.takes.front(), output.string());
        written = output.extension().string().substr(1);
        std::transform(written.begin(), written.end(), written.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    }
    const Take& first = loaded.corpus.takes.front();
    const bool kimonoChannels = arguments.kimono && !loaded.isCorpus && written == "csv";
    const Eigen::Index channels = first.channelCount() + (kimonoChannels ? Eigen::Index(analysis::kimonoChannels().size()) : 0);
    json summary{{"input", arguments.input},
                 {"output", output.string()},
                 {"input_format", loaded.format},
                 {"output_format", written},
                 {"takes", loaded.corpus.takes.size()},
                 {"channels", channels},
                 {"frames", first.frameCount()},
                 {"rate_hz", loaded.corpus.rateHz}};
    if (loaded.map) summary["part_map"] = io::partMapJson(*loaded.map);
    report(arguments.json, summary, [&] {
        if (loaded.map) std::cout << "part map: " << loaded.map->describe() << "\n";
        std::cout << "wrote " << output.string() << " (" << written << ": " << loaded.corpus.takes.size() << " take(s), "
                  << channels << " channels" << (kimonoChannels ? ", the kimono's 18 among them" : "")
                  << (arguments.kimono && written == "glb" ? ", the simulated kimono as morph targets" : "") << ", "
                  << loaded.corpus.rateHz << " Hz)\n";
    });
}

// ---- preprocess -------------------------------------------------------------------------

struct PreprocessArguments {
    std::string input;
    std::string output;
    bool noPad = false, noUnwrap = false, noAlignStart = false, noAlignPosition = false, noAlignHeading = false;
    std::string method = "onset";
    pre::PreprocessOptions options; ///< the options bound to it directly: the heading part, position, reference take, shift, onset
    bool json = false;
};

void runPreprocess(const PreprocessArguments& arguments)
{
    if (!io::isCorpusFolder(arguments.input)) throw CliError(arguments.input + ": not a corpus folder (no corpus.json)");
    refuseOutputOverInputs(arguments.output, OutputKind::Folder, {arguments.input});
    const Corpus corpus = unwrap(io::readCorpus(arguments.input));
    pre::PreprocessOptions options = arguments.options;
    options.pad = !arguments.noPad;
    options.unwrap = !arguments.noUnwrap;
    options.alignStart = !arguments.noAlignStart;
    options.alignPosition = !arguments.noAlignPosition;
    options.alignHeading = !arguments.noAlignHeading;
    options.headingPart = analysis::pipeline::headingPartFor(corpus, options.headingPart); // a skeleton's: its chest
    options.alignMethod = arguments.method == "xcorr" ? pre::StartAlignMethod::CrossCorrelation : pre::StartAlignMethod::Onset;
    auto result = unwrap(pre::preprocessCorpus(corpus, options));
    // A synthetic corpus's ground truth (DIR/truth) describes the preprocessed takes too (their
    // cells and functions are unchanged): it is copied into the output in the same staged write.
    const bool truthCopied = unwrap(synth::writeCorpusKeepingTruth(result.corpus, arguments.output, arguments.input));

    const auto& steps = result.report;
    Eigen::Index frames = 0;
    for (const Take& take : result.corpus.takes) frames = std::max(frames, take.frameCount());
    const json summary{{"input", arguments.input},
                       {"output", arguments.output},
                       {"steps", {{"pad", options.pad}, {"unwrap", options.unwrap}, {"align_start", options.alignStart},
                                  {"align_position", options.alignPosition}, {"align_heading", options.alignHeading}}},
                       {"position_alignment", pre::positionAlignmentName(options.positionAlignment)},
                       {"align_method", arguments.method},
                       {"takes", result.corpus.takes.size()},
                       {"channels", result.corpus.takes.front().channelCount()},
                       {"frames", frames},
                       {"rate_hz", result.corpus.rateHz},
                       {"truth_copied", truthCopied},
                       {"report", pre::preprocessReportJson(result)}};
    report(arguments.json, summary, [&] {
        std::cout << "preprocessed " << steps.takes.size() << " takes into " << arguments.output << " (steps:"
                  << (options.unwrap ? " unwrap" : "") << (options.pad ? " pad" : "")
                  << (options.alignStart ? " align-start(" + arguments.method + ")" : std::string())
                  << (options.alignPosition ? std::string(" align-position(") + pre::positionAlignmentName(options.positionAlignment) + ")" : std::string())
                  << (options.alignHeading ? " align-heading(" + options.headingPart + ")" : std::string()) << ")\n";
        std::cout << pre::preprocessReportTable(steps);
    });
}

} // namespace

void addIoCommands(CommandSet& commands)
{
    {
        auto [info, arguments] = addCommand(commands.root, "info", runInfo);
        info->add_option("PATH", arguments.path, "Corpus folder or take file")->required();
        addImportOptions(info, arguments.import);
    }
    {
        auto [convert, arguments] = addCommand(commands.root, "convert", runConvert);
        convert->add_option("IN", arguments.input, "Input take file or corpus folder")->required();
        convert->add_option("-o,--output", arguments.output, "Output file (.bvh, .glb or .csv) or corpus folder")->required();
        convert->add_flag("--kimono", arguments.kimono,
                          "Simulate the puppet's kimono as cloth over the take: a .csv output gets its measured points (sleeve tips, hem "
                          "front/back/left/right; x y z cm) as 18 more channels; a .glb output the cloth as a mesh 'kimono_cloth' moving by "
                          "morph targets animated by weights (at most " + std::to_string(render::kKimonoExportMaxKeys) +
                          " key shapes), the figure without its skinned skirt and sleeves (docs/KIMONO.md)");
        addClothOptions(convert, arguments.cloth);
        addImportOptions(convert, arguments.import);
    }
    {
        auto [preprocess, arguments] =
            addCommand(commands.root, "preprocess", runPreprocess, "Print the per-take report as JSON");
        preprocess->add_option("CORPUS", arguments.input, "Input corpus folder")->required();
        preprocess->add_option("-o,--output", arguments.output, "Output corpus folder")->required();
        preprocess->add_flag("--no-pad", arguments.noPad, "Do not pad takes to the longest");
        preprocess->add_flag("--no-unwrap", arguments.noUnwrap, "Do not unwrap angles");
        preprocess->add_flag("--no-align-start", arguments.noAlignStart, "Do not align start times");
        preprocess->add_flag("--no-align-position", arguments.noAlignPosition, "Do not align start positions");
        addNamedParameter(preprocess, "--position", arguments.options.positionAlignment,
                          "Start-position alignment: rigid (one translation per take, keeping the geometry between "
                          "the parts; thesis 2.2-4, default) or per-part (each part to the reference's start)");
        preprocess->add_flag("--no-align-heading", arguments.noAlignHeading,
                             "Do not align the whole-body heading (start yaw of the heading part)");
        preprocess->add_option("--heading-part", arguments.options.headingPart, "Part whose start yaw is the whole-body heading (on a skeleton's joints without it: the joint the arms branch from)")
            ->capture_default_str();
        preprocess->add_option("--align-method", arguments.method,
                               "Start-time alignment: onset (where the distance from the start pose, positions and "
                               "rotations, rises above its noise floor) or xcorr (cross-correlation of that rise)")
            ->check(CLI::IsMember({"onset", "xcorr"}))
            ->capture_default_str();
        preprocess->add_option("--reference-take", arguments.options.referenceTakeIndex, "Take index of each cell's time reference; 0 = automatic (median onset among the longest takes)")
            ->transform(parameterCheck("preprocess.referenceTake"))
            ->capture_default_str();
        preprocess->add_option("--max-shift", arguments.options.maxShiftFrames, "Largest shift in frames tried by xcorr")
            ->check(CLI::Range(0, 1000000))
            ->capture_default_str();
        preprocess->add_option("--onset-fraction", arguments.options.onsetFraction, "Onset threshold as a fraction of the peak speed")
            ->check(CLI::Range(1e-6, 1.0))
            ->capture_default_str();
    }
}

} // namespace bunraku::app::cli
