// Subcommands: info, convert, preprocess.
#include "app/cli/commands.h"
#include "app/cli/take_output.h"

#include "analysis/core/puppet_layout.h"
#include "analysis/io/atomic_file.h"
#include "analysis/io/bvh.h"
#include "analysis/io/corpus_io.h"
#include "analysis/io/take_reader.h"
#include "analysis/preprocess/preprocess.h"
#include "analysis/synth/demo_corpus_io.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <limits>
#include <memory>

namespace bunraku::app::cli {
namespace {

namespace fs = std::filesystem;
namespace io = analysis::io;
namespace pre = analysis::preprocess;
namespace synth = analysis::synth;
using analysis::Corpus;
using analysis::Take;
using nlohmann::json;

/// Import options shared by info and convert.
struct ImportArguments {
    std::string joints;
    std::string jointMapFile;
    std::string upAxis = "auto";
    std::string units = "cm";
    bool allJoints = false;
    double rateHz = 0.0;
    std::string fastrakUnits = "cm";
};

void addImportOptions(CLI::App* command, ImportArguments& arguments)
{
    command->add_option("--joints", arguments.joints,
                        "BVH joint map, e.g. head=Head,shoulder=Chest,arm=LowerArm_R,hand=Hand_R (parts not named keep "
                        "the built-in defaults)");
    command->add_option("--joint-map", arguments.jointMapFile,
                        "BVH joint map as a JSON file {\"head\": ..., \"shoulder\": ..., \"arm\": ..., \"hand\": ...}");
    command->add_option("--up-axis", arguments.upAxis, "BVH up axis: auto, y or z")
        ->check(CLI::IsMember({"auto", "y", "z"}))
        ->capture_default_str();
    command->add_option("--units", arguments.units, "BVH length unit: cm, m, mm or in")
        ->check(CLI::IsMember({"cm", "m", "mm", "in"}))
        ->capture_default_str();
    command->add_flag("--all-joints", arguments.allJoints, "BVH: keep every joint (6 channels each) instead of the 4 puppet parts");
    command->add_option("--rate", arguments.rateHz, "Sample rate in Hz (CSV without time_s; FASTRAK, default 5)");
    command->add_option("--fastrak-units", arguments.fastrakUnits, "FASTRAK position unit: cm or in")
        ->check(CLI::IsMember({"cm", "in"}))
        ->capture_default_str();
}

io::ImportOptions importOptions(const ImportArguments& arguments)
{
    io::ImportOptions options;
    io::JointMap map;
    if (!arguments.jointMapFile.empty()) map = unwrap(io::readJointMapJson(arguments.jointMapFile));
    if (!arguments.joints.empty()) map = unwrap(io::parseJointMap(arguments.joints, map));
    const bool anyJoint = std::any_of(map.joints.begin(), map.joints.end(), [](const std::string& j) { return !j.empty(); });
    if (anyJoint) options.bvh.jointMap = map;
    options.bvh.upAxis = arguments.upAxis == "y" ? io::BvhUpAxis::Y : arguments.upAxis == "z" ? io::BvhUpAxis::Z : io::BvhUpAxis::Auto;
    options.bvh.unitScale = arguments.units == "m" ? 100.0 : arguments.units == "mm" ? 0.1 : arguments.units == "in" ? 2.54 : 1.0;
    options.bvhLayout = arguments.allJoints ? io::BvhTakeLayout::AllJoints : io::BvhTakeLayout::PuppetParts;
    if (arguments.rateHz != 0.0) {
        if (!(arguments.rateHz > 0.0)) throw CliError("--rate must be a positive number of Hz");
        options.csv.rateHz = arguments.rateHz;
        options.fastrak.rateHz = arguments.rateHz;
    }
    options.fastrak.units = arguments.fastrakUnits == "in" ? io::FastrakUnits::Inches : io::FastrakUnits::Centimetres;
    return options;
}

/// A corpus folder, or a one-take corpus made of a take file of any supported format.
struct Loaded {
    Corpus corpus;
    bool isCorpus = false;
    std::string format;
    std::unique_ptr<io::BvhFile> bvh;
};

Loaded load(const std::string& pathText, const ImportArguments& arguments)
{
    const fs::path path = pathText;
    std::error_code ec;
    Loaded loaded;
    if (fs::is_directory(path, ec)) {
        if (!io::isCorpusFolder(path)) throw CliError(path.string() + ": not a corpus folder (no corpus.json)");
        loaded.corpus = unwrap(io::readCorpus(path));
        loaded.isCorpus = true;
        loaded.format = "corpus";
        return loaded;
    }
    if (!fs::exists(path, ec)) throw CliError(path.string() + ": no such file or folder");
    const auto format = io::takeFileFormat(path);
    Take take = unwrap(io::readTakeFile(path, importOptions(arguments)));
    loaded.format = format == io::TakeFileFormat::Csv ? "csv" : format == io::TakeFileFormat::Bvh ? "bvh" : "fastrak";
    if (format == io::TakeFileFormat::Bvh) loaded.bvh = std::make_unique<io::BvhFile>(unwrap(io::readBvh(path)));
    loaded.corpus.name = path.stem().string();
    loaded.corpus.rateHz = take.rateHz;
    loaded.corpus.takes.push_back(std::move(take));
    return loaded;
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
    const Loaded loaded = load(arguments.path, arguments.import);
    const Corpus& corpus = loaded.corpus;
    const Take& first = corpus.takes.front();
    Eigen::Index frames = 0;
    for (const Take& take : corpus.takes) frames = std::max(frames, take.frameCount());
    const Eigen::Index channels = first.channelCount();
    Eigen::VectorXd low = Eigen::VectorXd::Constant(channels, std::numeric_limits<double>::infinity());
    Eigen::VectorXd high = -low;
    for (const Take& take : corpus.takes) {
        low = low.cwiseMin(take.values.colwise().minCoeff().transpose());
        high = high.cwiseMax(take.values.colwise().maxCoeff().transpose());
    }

    if (arguments.json) {
        json takeList = json::array();
        for (const Take& take : corpus.takes) takeList.push_back(takeJson(take));
        json names = json::array(), ranges = json::array();
        for (Eigen::Index c = 0; c < channels; ++c) {
            const auto& channel = first.channels[std::size_t(c)];
            names.push_back(channel.name());
            ranges.push_back({{"channel", channel.name()}, {"unit", channel.unit}, {"min", low[c]}, {"max", high[c]}});
        }
        json document{{"path", arguments.path},
                      {"format", loaded.format},
                      {"name", corpus.name},
                      {"takes", corpus.takes.size()},
                      {"channels", channels},
                      {"frames", frames},
                      {"rate_hz", corpus.rateHz},
                      {"parts", first.parts()},
                      {"take_list", takeList},
                      {"channel_names", names},
                      {"ranges", ranges}};
        if (loaded.isCorpus) {
            document["functions"] = corpus.functions();
            document["emotions"] = corpus.emotions();
            document["neutral_emotion"] = corpus.neutralEmotion;
            document["convention"] = corpus.convention;
        }
        if (loaded.bvh) {
            json joints = json::array();
            for (const auto& joint : loaded.bvh->skeleton.joints) {
                json channelNames = json::array();
                for (auto c : joint.channels) channelNames.push_back(io::bvhChannelName(c));
                joints.push_back({{"name", joint.name},
                                  {"parent", joint.parent >= 0 ? json(loaded.bvh->skeleton.joints[std::size_t(joint.parent)].name) : json()},
                                  {"end_site", joint.endSite},
                                  {"offset", {joint.offset.x(), joint.offset.y(), joint.offset.z()}},
                                  {"channels", channelNames}});
            }
            document["joints"] = joints;
            document["joint_count"] = loaded.bvh->skeleton.jointCount();
            document["end_site_count"] = loaded.bvh->skeleton.endSiteCount();
            document["frame_time_s"] = loaded.bvh->motion.frameTime;
        }
        printJson(document);
        return;
    }

    std::cout << arguments.path << " (" << loaded.format << ")\n";
    if (loaded.isCorpus) std::cout << "corpus: " << corpus.name << "\n";
    std::cout << "takes: " << corpus.takes.size() << ", frames: " << frames << " at most, rate: " << corpus.rateHz
              << " Hz, channels: " << channels << "\n";
    if (loaded.isCorpus) {
        std::cout << "\ntakes:\n";
        for (const Take& take : corpus.takes)
            std::cout << "  " << std::left << std::setw(28) << take.displayName() << std::right << std::setw(6) << take.frameCount()
                      << " frames  " << take.labels.source << "\n";
    }
    std::cout << "\nchannels (min .. max):\n";
    for (Eigen::Index c = 0; c < channels; ++c) {
        const auto& channel = first.channels[std::size_t(c)];
        std::cout << "  " << std::left << std::setw(22) << channel.name() << std::right << std::fixed << std::setprecision(3)
                  << std::setw(12) << low[c] << " .. " << std::setw(12) << high[c] << " " << channel.unit << "\n";
    }
    std::cout.unsetf(std::ios::fixed);
    if (loaded.bvh) {
        const auto& skeleton = loaded.bvh->skeleton;
        std::cout << "\nBVH joints: " << skeleton.jointCount() << " + " << skeleton.endSiteCount() << " End Sites, frame time "
                  << loaded.bvh->motion.frameTime << " s\n";
        for (const auto& joint : skeleton.joints) {
            int depth = 0;
            for (int p = joint.parent; p >= 0; p = skeleton.joints[std::size_t(p)].parent) ++depth;
            std::cout << "  " << std::string(std::size_t(2 * depth), ' ') << (joint.endSite ? "(end) " : "") << joint.name;
            if (!joint.channels.empty()) {
                std::cout << "  [";
                for (std::size_t k = 0; k < joint.channels.size(); ++k) std::cout << (k ? " " : "") << io::bvhChannelName(joint.channels[k]);
                std::cout << "]";
            }
            std::cout << "\n";
        }
    }
}

// ---- convert ----------------------------------------------------------------------------

struct ConvertArguments {
    std::string input;
    std::string output;
    bool json = false;
    ImportArguments import;
};

void runConvert(const ConvertArguments& arguments)
{
    const Loaded loaded = load(arguments.input, arguments.import);
    const fs::path output = arguments.output;
    std::string written;
    if (loaded.isCorpus) {
        if (io::takeFileFormat(output) != io::TakeFileFormat::Unknown)
            throw CliError(output.string() + ": a corpus converts to a corpus folder, not to a single file");
        unwrap(io::writeCorpus(loaded.corpus, output));
        written = "corpus";
    } else {
        requireTakeOutput(output.string());
        writeTakeOutput(loaded.corpus.takes.front(), output.string());
        written = output.extension().string().substr(1);
        std::transform(written.begin(), written.end(), written.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    }
    const Take& first = loaded.corpus.takes.front();
    if (arguments.json) {
        printJson({{"input", arguments.input},
                   {"output", output.string()},
                   {"input_format", loaded.format},
                   {"output_format", written},
                   {"takes", loaded.corpus.takes.size()},
                   {"channels", first.channelCount()},
                   {"frames", first.frameCount()},
                   {"rate_hz", loaded.corpus.rateHz}});
    } else {
        std::cout << "wrote " << output.string() << " (" << written << ": " << loaded.corpus.takes.size() << " take(s), "
                  << first.channelCount() << " channels, " << loaded.corpus.rateHz << " Hz)\n";
    }
}

// ---- preprocess -------------------------------------------------------------------------

struct PreprocessArguments {
    std::string input;
    std::string output;
    bool noPad = false, noUnwrap = false, noAlignStart = false, noAlignPosition = false, noAlignHeading = false;
    std::string headingPart = "shoulder";
    std::string method = "onset";
    int referenceTake = 0;
    int maxShift = 30;
    double onsetFraction = 0.1;
    bool json = false;
};

/// A synthetic corpus's ground truth (DIR/truth) describes the preprocessed takes too (their
/// cells and functions are unchanged), so it goes beside the output. It is staged in a
/// temporary folder before the corpus is written (the output may replace the input folder) and
/// renamed into place after; the stage is removed on any failure.
class GroundTruthCopy {
public:
    GroundTruthCopy(const fs::path& input, const fs::path& output)
    {
        const fs::path source = synth::groundTruthFolder(input);
        std::error_code ec;
        if (!fs::is_regular_file(source / "truth.json", ec)) return;
        const fs::path parent = fs::absolute(output, ec).lexically_normal().parent_path();
        m_stage = parent / io::temporarySiblingName("truth", ".tmp-");
        fs::create_directories(parent, ec);
        if (!ec) fs::copy(source, m_stage, fs::copy_options::recursive, ec);
        if (ec) fail(source.string() + ": cannot copy the ground truth: " + ec.message());
    }
    ~GroundTruthCopy()
    {
        std::error_code ignored;
        if (!m_stage.empty()) fs::remove_all(m_stage, ignored);
    }
    GroundTruthCopy(const GroundTruthCopy&) = delete;
    GroundTruthCopy& operator=(const GroundTruthCopy&) = delete;

    /// Moves the staged copy into the written corpus; false when there was no ground truth.
    bool place(const fs::path& output)
    {
        if (m_stage.empty()) return false;
        std::error_code ec;
        const fs::path target = synth::groundTruthFolder(output);
        fs::rename(m_stage, target, ec);
        if (ec) fail(target.string() + ": cannot place the ground truth: " + ec.message());
        m_stage.clear();
        return true;
    }

private:
    [[noreturn]] void fail(const std::string& message)
    {
        std::error_code ignored;
        fs::remove_all(m_stage, ignored);
        m_stage.clear();
        throw CliError(message);
    }

    fs::path m_stage;
};

void runPreprocess(const PreprocessArguments& arguments)
{
    if (!io::isCorpusFolder(arguments.input)) throw CliError(arguments.input + ": not a corpus folder (no corpus.json)");
    const Corpus corpus = unwrap(io::readCorpus(arguments.input));
    pre::PreprocessOptions options;
    options.pad = !arguments.noPad;
    options.unwrap = !arguments.noUnwrap;
    options.alignStart = !arguments.noAlignStart;
    options.alignPosition = !arguments.noAlignPosition;
    options.alignHeading = !arguments.noAlignHeading;
    options.headingPart = arguments.headingPart;
    options.alignMethod = arguments.method == "xcorr" ? pre::StartAlignMethod::CrossCorrelation : pre::StartAlignMethod::Onset;
    options.referenceTakeIndex = arguments.referenceTake;
    options.maxShiftFrames = arguments.maxShift;
    options.onsetFraction = arguments.onsetFraction;
    auto result = unwrap(pre::preprocessCorpus(corpus, options));
    GroundTruthCopy truth(arguments.input, arguments.output);
    unwrap(io::writeCorpus(result.corpus, arguments.output));
    const bool truthCopied = truth.place(arguments.output);

    const auto& report = result.report;
    Eigen::Index frames = 0;
    for (const Take& take : result.corpus.takes) frames = std::max(frames, take.frameCount());
    if (arguments.json) {
        json takes = json::array();
        for (std::size_t i = 0; i < report.takes.size(); ++i) {
            const auto& r = report.takes[i];
            json offsets = json::array();
            const auto parts = analysis::sixDofParts(result.corpus.takes[i]);
            for (std::size_t p = 0; p < r.positionOffsets.size(); ++p)
                offsets.push_back(json{{"part", parts[p].part},
                                       {"offset_cm", json::array({r.positionOffsets[p].x(), r.positionOffsets[p].y(), r.positionOffsets[p].z()})}});
            takes.push_back({{"take", r.take},
                             {"frames_padded", r.framesPadded},
                             {"angles_unwrapped", r.anglesUnwrapped},
                             {"shift_frames", r.shiftFrames},
                             {"time_reference", r.isTimeReference},
                             {"position_reference", r.isPositionReference},
                             {"position_offsets", offsets},
                             {"branch_turns", r.branchTurns},
                             {"heading_offset_deg", r.headingOffsetDeg},
                             {"heading_reference", r.isHeadingReference}});
        }
        printJson({{"input", arguments.input},
                   {"output", arguments.output},
                   {"steps", {{"pad", options.pad}, {"unwrap", options.unwrap}, {"align_start", options.alignStart}, {"align_position", options.alignPosition}, {"align_heading", options.alignHeading}}},
                   {"align_method", arguments.method},
                   {"takes", result.corpus.takes.size()},
                   {"channels", result.corpus.takes.front().channelCount()},
                   {"frames", frames},
                   {"rate_hz", result.corpus.rateHz},
                   {"truth_copied", truthCopied},
                   {"report", takes}});
        return;
    }
    std::cout << "preprocessed " << report.takes.size() << " takes into " << arguments.output << " (steps:"
              << (options.unwrap ? " unwrap" : "") << (options.pad ? " pad" : "")
              << (options.alignStart ? " align-start(" + arguments.method + ")" : std::string()) << (options.alignPosition ? " align-position" : "")
              << (options.alignHeading ? " align-heading(" + options.headingPart + ")" : std::string())
              << ")\n";
    std::cout << "  " << std::left << std::setw(28) << "take" << std::right << std::setw(8) << "padded" << std::setw(10) << "unwraps"
              << std::setw(8) << "shift" << "  reference\n";
    for (const auto& r : report.takes)
        std::cout << "  " << std::left << std::setw(28) << r.take << std::right << std::setw(8) << r.framesPadded << std::setw(10)
                  << r.anglesUnwrapped << std::setw(8) << r.shiftFrames << "  " << (r.isTimeReference ? "time " : "")
                  << (r.isPositionReference ? "position" : "") << "\n";
}

} // namespace

void addIoCommands(CommandSet& commands)
{
    {
        auto arguments = std::make_shared<InfoArguments>();
        CLI::App* info = commands.root.add_subcommand(
            "info", "Describe a corpus folder or a take file (.csv, .bvh, .txt/.fastrak): labels, frames, rate, channels, "
                    "ranges, and a BVH file's joints");
        info->add_option("PATH", arguments->path, "Corpus folder or take file")->required();
        info->add_flag("--json", arguments->json, "Print a machine-readable summary");
        addImportOptions(info, arguments->import);
        info->callback([arguments] { runInfo(*arguments); });
    }
    {
        auto arguments = std::make_shared<ConvertArguments>();
        CLI::App* convert = commands.root.add_subcommand(
            "convert", "Convert a take file (.csv, .bvh, .txt/.fastrak) to .csv, .bvh (on the take's own skeleton when it has one) or .glb (glTF binary) by the output's extension, or a corpus "
                       "folder to a corpus folder");
        convert->add_option("IN", arguments->input, "Input take file or corpus folder")->required();
        convert->add_option("-o,--output", arguments->output, "Output file (.bvh, .glb or .csv) or corpus folder")->required();
        convert->add_flag("--json", arguments->json, "Print a machine-readable summary");
        addImportOptions(convert, arguments->import);
        convert->callback([arguments] { runConvert(*arguments); });
    }
    {
        auto arguments = std::make_shared<PreprocessArguments>();
        CLI::App* preprocess = commands.root.add_subcommand(
            "preprocess", "Thesis 2.2 preprocessing of a corpus: unwrap angles, pad to the longest take, align start times to "
                          "each cell's reference take and start positions to each function's reference take");
        preprocess->add_option("CORPUS", arguments->input, "Input corpus folder")->required();
        preprocess->add_option("-o,--output", arguments->output, "Output corpus folder")->required();
        preprocess->add_flag("--no-pad", arguments->noPad, "Do not pad takes to the longest");
        preprocess->add_flag("--no-unwrap", arguments->noUnwrap, "Do not unwrap angles");
        preprocess->add_flag("--no-align-start", arguments->noAlignStart, "Do not align start times");
        preprocess->add_flag("--no-align-position", arguments->noAlignPosition, "Do not align start positions");
        preprocess->add_flag("--no-align-heading", arguments->noAlignHeading,
                             "Do not align the whole-body heading (start yaw of the heading part)");
        preprocess->add_option("--heading-part", arguments->headingPart, "Part whose start yaw is the whole-body heading")
            ->capture_default_str();
        preprocess->add_option("--align-method", arguments->method,
                               "Start-time alignment: onset (where the distance from the start pose, positions and "
                               "rotations, rises above its noise floor) or xcorr (cross-correlation of that rise)")
            ->check(CLI::IsMember({"onset", "xcorr"}))
            ->capture_default_str();
        preprocess->add_option("--reference-take", arguments->referenceTake, "Take index of each cell's time reference; 0 = automatic (median onset among the longest takes)")
            ->check(CLI::Range(0, 1000000))
            ->capture_default_str();
        preprocess->add_option("--max-shift", arguments->maxShift, "Largest shift in frames tried by xcorr")
            ->check(CLI::Range(0, 1000000))
            ->capture_default_str();
        preprocess->add_option("--onset-fraction", arguments->onsetFraction, "Onset threshold as a fraction of the peak speed")
            ->check(CLI::Range(1e-6, 1.0))
            ->capture_default_str();
        preprocess->add_flag("--json", arguments->json, "Print the per-take report as JSON");
        preprocess->callback([arguments] { runPreprocess(*arguments); });
    }
}

} // namespace bunraku::app::cli
