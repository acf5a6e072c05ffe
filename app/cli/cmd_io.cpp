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
#include "analysis/io/text_format.h"
#include "analysis/pipeline/heading_part.h"
#include "analysis/pipeline/stage_parameters.h"
#include "analysis/preprocess/preprocess.h"
#include "analysis/skeleton/puppet_rig_fit.h"
#include "analysis/synth/demo_corpus_io.h"
#include "render/take_export.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <limits>
#include <memory>
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

/// A corpus folder, or a one-take corpus made of a take file of any supported format. A BVH
/// file is parsed once; when its puppet parts cannot be mapped and `requireTake` is false (info
/// describes any valid BVH), the corpus stays empty and `mapError` says why.
struct Loaded {
    Corpus corpus;
    bool isCorpus = false;
    std::string format;
    std::unique_ptr<io::BvhFile> bvh;
    std::shared_ptr<const io::PartMap> map; ///< the BVH part map used
    std::string mapError;
    io::BvhUnitsGuess units;
    double cmPerUnit = 1.0;
    io::BvhUpAxis upAxis = io::BvhUpAxis::Y;
    std::optional<io::SceneTakeInfo> scene; ///< FBX, glTF, Collada: what was converted
};

Loaded load(const std::string& pathText, const ImportArguments& arguments, bool requireTake = true)
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
    const io::ImportOptions options = importOptions(arguments, pathText);
    loaded.corpus.name = path.stem().string();
    if (format == io::TakeFileFormat::Bvh || format == io::TakeFileFormat::Scene) {
        // A scene file (FBX, glTF, Collada) is read as the BvhFile it converts to (y up, cm).
        io::SceneTakeInfo sceneInfo;
        loaded.bvh = std::make_unique<io::BvhFile>(unwrap(io::readSkeletalFile(path, options, {}, &sceneInfo)));
        const io::BvhImportOptions bvhOptions = format == io::TakeFileFormat::Scene ? io::sceneBvhOptions(options.bvh) : options.bvh;
        if (format == io::TakeFileFormat::Scene) {
            loaded.scene = sceneInfo;
            loaded.format = sceneInfo.format == io::SceneFormat::Fbx ? "fbx" : sceneInfo.format == io::SceneFormat::Gltf ? "gltf" : "collada";
        } else {
            loaded.format = "bvh";
        }
        loaded.units = io::guessBvhUnits(*loaded.bvh, bvhOptions.upAxis);
        loaded.cmPerUnit = io::bvhUnitScale(*loaded.bvh, bvhOptions);
        unwrap(io::checkBvhLengths(*loaded.bvh, loaded.cmPerUnit)); // `info` too: it prints the offsets
        loaded.upAxis = io::resolveUpAxis(*loaded.bvh, bvhOptions.upAxis);
        if (options.bvhLayout == io::BvhTakeLayout::AllJoints) {
            loaded.corpus.takes.push_back(unwrap(io::bvhToJointTake(*loaded.bvh, bvhOptions)));
        } else if (auto imported = io::importBvhPuppet(*loaded.bvh, bvhOptions); imported.ok()) {
            loaded.map = imported->map;
            loaded.corpus.takes.push_back(std::move(imported->take));
        } else if (requireTake) {
            throw CliError(imported.error().message);
        } else {
            loaded.mapError = imported.error().message;
        }
        loaded.corpus.rateHz = io::bvhRateHz(loaded.bvh->motion.frameTime);
        return loaded;
    }
    Take take = unwrap(io::readTakeFile(path, options));
    loaded.format = format == io::TakeFileFormat::Csv ? "csv" : "fastrak";
    loaded.corpus.rateHz = take.rateHz;
    loaded.corpus.takes.push_back(std::move(take));
    return loaded;
}

/// The part map for reports: {"head": {"joint": ..., "found_by": ...}, ..., "side": ...}.
json partMapJson(const io::PartMap& map)
{
    json out = json::object();
    for (std::size_t p = 0; p < 4; ++p)
        out[std::string(analysis::kPuppetParts[p])] = {{"joint", map.names.joints[p]}, {"found_by", io::mapMethodName(map.methods[p])}};
    out["side"] = analysis::bodySideName(map.side);
    return out;
}

/// "ZXY" for a joint whose rotation channels are Z, X, Y in that order.
std::string rotationOrder(const io::BvhJoint& joint)
{
    std::string order;
    for (auto c : joint.channels)
        if (!io::isPositionChannel(c)) order += char('X' + io::channelAxis(c));
    return order;
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

/// The BVH file's own description: hierarchy, channel orders, frames, rate, units and axes.
json bvhJson(const Loaded& loaded)
{
    const io::BvhFile& bvh = *loaded.bvh;
    json joints = json::array();
    for (const auto& joint : bvh.skeleton.joints) {
        json channelNames = json::array();
        for (auto c : joint.channels) channelNames.push_back(io::bvhChannelName(c));
        joints.push_back({{"name", joint.name},
                          {"parent", joint.parent >= 0 ? json(bvh.skeleton.joints[std::size_t(joint.parent)].name) : json()},
                          {"end_site", joint.endSite},
                          {"offset", {joint.offset.x(), joint.offset.y(), joint.offset.z()}},
                          {"channels", channelNames},
                          {"rotation_order", rotationOrder(joint)}});
    }
    json out{{"joints", joints},
             {"joint_count", bvh.skeleton.jointCount()},
             {"end_site_count", bvh.skeleton.endSiteCount()},
             {"bvh_channels", bvh.skeleton.channelCount},
             {"bvh_frames", bvh.motion.values.rows()},
             {"frame_time_s", bvh.motion.frameTime},
             {"up_axis", loaded.upAxis == io::BvhUpAxis::Z ? "z" : "y"},
             {"units", {{"guess", loaded.units.unit},
                        {"cm_per_unit_guessed", loaded.units.cmPerUnit},
                        {"height", loaded.units.height},
                        {"note", loaded.units.note},
                        {"cm_per_unit_used", loaded.cmPerUnit}}}};
    if (loaded.map) out["part_map"] = partMapJson(*loaded.map);
    if (!loaded.mapError.empty()) out["part_map_error"] = loaded.mapError;
    if (loaded.scene) {
        const io::SceneTakeInfo& scene = *loaded.scene;
        json animations = json::array();
        for (const auto& name : scene.animations) animations.push_back(name);
        // The file's own units and axes, converted to BVH's (y up, +Z forward, cm) before the
        // import (the "joints", "up_axis" and "units" above are of the converted skeleton).
        out["scene"] = {{"format", scene.formatName},
                        {"animations", animations},
                        {"animation", scene.animation},
                        {"file_unit", scene.unit},
                        {"file_cm_per_unit", scene.cmPerUnit},
                        {"file_up_axis", scene.upAxis},
                        {"converted_to", "cm, y up, +Z forward (BVH), then the workbench's z up"},
                        {"rate_hz", scene.rateHz},
                        {"rate_source", scene.rateSource},
                        {"start_time_s", scene.startTime},
                        {"fbx_helper_nodes_folded", scene.helperNodesFolded},
                        {"meshes", scene.meshes},
                        {"scale_dropped", scene.scaleDropped}};
        // The skinned mesh kept for the skeleton (the "mesh" figure), and what was dropped.
        json mesh = nullptr;
        if (scene.meshVertices > 0)
            mesh = {{"vertices", scene.meshVertices}, {"triangles", scene.meshTriangles}, {"bones", scene.meshBones}};
        out["scene"]["skinned_mesh"] = mesh;
        out["scene"]["mesh_notes"] = scene.meshNotes;
    }
    return out;
}

std::string joinedNames(const std::vector<std::string>& names)
{
    std::string out;
    for (std::size_t i = 0; i < names.size(); ++i) out += (i ? ", " : "") + names[i];
    return out;
}

void printBvh(const Loaded& loaded)
{
    const io::BvhFile& bvh = *loaded.bvh;
    const auto& skeleton = bvh.skeleton;
    const double frames = double(bvh.motion.values.rows());
    if (loaded.scene) {
        const io::SceneTakeInfo& scene = *loaded.scene;
        std::cout << "\n" << scene.formatName << ": animation " << scene.animation << " '" << scene.animations[std::size_t(scene.animation)]
                  << "' of " << scene.animations.size() << ", sampled at " << scene.rateHz << " Hz (" << scene.rateSource
                  << " rate) from " << scene.startTime << " s; file unit " << scene.unit << ", up axis " << scene.upAxis
                  << ": converted to cm, y up (then the workbench's z up)";
        if (scene.helperNodesFolded > 0) std::cout << "; " << scene.helperNodesFolded << " FBX pivot nodes folded into their joints";
        if (scene.scaleDropped) std::cout << "; joint scale dropped (kept in positions)";
        if (scene.meshVertices > 0)
            std::cout << "\nskinned mesh: " << scene.meshVertices << " vertices, " << scene.meshTriangles << " triangles, "
                      << scene.meshBones.size() << " bones (" << joinedNames(scene.meshBones) << "), of " << scene.meshes
                      << " meshes in the file (figure \"mesh\")";
        else if (scene.meshes > 0)
            std::cout << "\nskinned mesh: none (" << scene.meshes << " meshes in the file, none kept for the skeleton)";
        for (const std::string& note : scene.meshNotes) std::cout << "\n  mesh note: " << note;
        std::cout << "\nconverted skeleton as BVH:";
    }
    std::cout << "\nBVH: " << skeleton.jointCount() << " joints + " << skeleton.endSiteCount() << " End Sites, "
              << skeleton.channelCount << " channels, " << bvh.motion.values.rows() << " frames, frame time " << bvh.motion.frameTime
              << " s (" << io::bvhRateHz(bvh.motion.frameTime) << " Hz, " << std::max(0.0, frames - 1.0) * bvh.motion.frameTime
              << " s)\n";
    std::cout << "up axis: " << (loaded.upAxis == io::BvhUpAxis::Z ? "z" : "y") << ", units: " << loaded.units.unit << " guessed ("
              << loaded.units.note << "), " << loaded.cmPerUnit << " cm per unit used\n";
    if (loaded.map) std::cout << "part map: " << loaded.map->describe() << "\n";
    else if (!loaded.mapError.empty()) std::cout << "part map: none (" << loaded.mapError << ")\n";
    std::cout << "hierarchy (joint [channels]):\n";
    std::vector<int> depth(skeleton.joints.size(), 0);
    for (std::size_t j = 0; j < skeleton.joints.size(); ++j) {
        const auto& joint = skeleton.joints[j];
        if (joint.parent >= 0) depth[j] = depth[std::size_t(joint.parent)] + 1;
        // Deep chains are indented up to 40 levels and then labelled with their depth.
        const int shown = std::min(depth[j], 40);
        std::cout << "  " << std::string(std::size_t(2 * shown), ' ') << (depth[j] > 40 ? "[depth " + std::to_string(depth[j]) + "] " : "")
                  << (joint.endSite ? "(end) " : "") << joint.name;
        if (!joint.channels.empty()) {
            std::cout << "  [";
            for (std::size_t k = 0; k < joint.channels.size(); ++k) std::cout << (k ? " " : "") << io::bvhChannelName(joint.channels[k]);
            std::cout << "]";
        }
        std::cout << "\n";
    }
}

void runInfo(const InfoArguments& arguments)
{
    const Loaded loaded = load(arguments.path, arguments.import, false);
    const Corpus& corpus = loaded.corpus;
    if (corpus.takes.empty()) { // a BVH file whose puppet parts found no joints
        if (arguments.json) {
            json document{{"path", arguments.path}, {"format", loaded.format}, {"name", corpus.name}, {"takes", 0},
                          {"rate_hz", corpus.rateHz}};
            document.update(bvhJson(loaded));
            printJson(document);
            return;
        }
        std::cout << arguments.path << " (" << loaded.format << ")\n";
        printBvh(loaded);
        return;
    }
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
        if (loaded.bvh) document.update(bvhJson(loaded));
        if (rig) {
            json parts = json::object();
            for (std::size_t p = 0; p < kPuppetParts.size(); ++p)
                parts[std::string(kPuppetParts[p])] = {{"max_cm", rig->residual.maxCm[p]},
                                                       {"rms_cm", rig->residual.rmsCm[p]},
                                                       {"max_deg", rig->residual.maxDeg[p]}};
            json segments = json::object();
            for (const auto& joint : rig->skeleton->joints)
                if (joint.parent >= 0) segments[joint.name] = joint.offset.norm();
            document["rig_fit"] = {{"takes", rigTakes.size()}, {"frames", rig->residual.frames}, {"parts", parts},
                                   {"segment_cm", segments}};
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
                      << " frames  " << take.labels.source << (take.skeleton ? "  (with its skeleton)" : "") << "\n";
    }
    std::cout << "\nchannels (min .. max):\n";
    for (Eigen::Index c = 0; c < channels; ++c) {
        const auto& channel = first.channels[std::size_t(c)];
        std::cout << "  " << std::left << std::setw(22) << channel.name() << std::right << std::fixed << std::setprecision(3)
                  << std::setw(12) << low[c] << " .. " << std::setw(12) << high[c] << " " << channel.unit << "\n";
    }
    std::cout.unsetf(std::ios::fixed);
    std::cout << std::setprecision(6);
    if (rig)
        std::cout << "\npuppet rig fitted to " << rigTakes.size() << (rigTakes.size() == 1 ? " take" : " takes")
                  << " (one body: derived takes move it; each part's distance from its channels, largest and rms):\n  "
                  << describePuppetRigResidual(rig->residual) << "\n";
    if (loaded.bvh) printBvh(loaded);
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
    const Loaded loaded = load(arguments.input, arguments.import);
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
    if (arguments.json) {
        json document{{"input", arguments.input},
                      {"output", output.string()},
                      {"input_format", loaded.format},
                      {"output_format", written},
                      {"takes", loaded.corpus.takes.size()},
                      {"channels", channels},
                      {"frames", first.frameCount()},
                      {"rate_hz", loaded.corpus.rateHz}};
        if (loaded.map) document["part_map"] = partMapJson(*loaded.map);
        printJson(document);
    } else {
        if (loaded.map) std::cout << "part map: " << loaded.map->describe() << "\n";
        std::cout << "wrote " << output.string() << " (" << written << ": " << loaded.corpus.takes.size() << " take(s), "
                  << channels << " channels" << (kimonoChannels ? ", the kimono's 18 among them" : "")
                  << (arguments.kimono && written == "glb" ? ", the simulated kimono as morph targets" : "") << ", "
                  << loaded.corpus.rateHz << " Hz)\n";
    }
}

// ---- preprocess -------------------------------------------------------------------------

struct PreprocessArguments {
    std::string input;
    std::string output;
    bool noPad = false, noUnwrap = false, noAlignStart = false, noAlignPosition = false, noAlignHeading = false;
    std::string headingPart = "shoulder";
    std::string position = "rigid";
    std::string method = "onset";
    int referenceTake = 0;
    int maxShift = 30;
    double onsetFraction = 0.1;
    bool json = false;
};

void runPreprocess(const PreprocessArguments& arguments)
{
    if (!io::isCorpusFolder(arguments.input)) throw CliError(arguments.input + ": not a corpus folder (no corpus.json)");
    refuseOutputOverInputs(arguments.output, OutputKind::Folder, {arguments.input});
    const Corpus corpus = unwrap(io::readCorpus(arguments.input));
    pre::PreprocessOptions options;
    options.pad = !arguments.noPad;
    options.unwrap = !arguments.noUnwrap;
    options.alignStart = !arguments.noAlignStart;
    options.alignPosition = !arguments.noAlignPosition;
    options.alignHeading = !arguments.noAlignHeading;
    pre::parsePositionAlignment(arguments.position, options.positionAlignment);
    options.headingPart = analysis::pipeline::headingPartFor(corpus, arguments.headingPart); // a skeleton's: its chest
    options.alignMethod = arguments.method == "xcorr" ? pre::StartAlignMethod::CrossCorrelation : pre::StartAlignMethod::Onset;
    options.referenceTakeIndex = arguments.referenceTake;
    options.maxShiftFrames = arguments.maxShift;
    options.onsetFraction = arguments.onsetFraction;
    auto result = unwrap(pre::preprocessCorpus(corpus, options));
    // A synthetic corpus's ground truth (DIR/truth) describes the preprocessed takes too (their
    // cells and functions are unchanged): it is copied into the output in the same staged write.
    const bool truthCopied = unwrap(synth::writeCorpusKeepingTruth(result.corpus, arguments.output, arguments.input));

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
                   {"position_alignment", arguments.position},
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
              << (options.alignStart ? " align-start(" + arguments.method + ")" : std::string()) << (options.alignPosition ? " align-position(" + arguments.position + ")" : std::string())
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
        CLI::App* info = addCommand(commands.root, "info",
            "Describe a corpus folder or a take file (.csv, .bvh, .fbx, .glb/.gltf, .dae, .txt/.fastrak): labels, frames, rate, "
            "channels, ranges, and a BVH (or converted FBX, glTF, Collada) file's joints",
            arguments, runInfo);
        info->add_option("PATH", arguments->path, "Corpus folder or take file")->required();
        addImportOptions(info, arguments->import);
    }
    {
        auto arguments = std::make_shared<ConvertArguments>();
        CLI::App* convert = addCommand(commands.root, "convert",
            "Convert a take file (.csv, .bvh, .fbx, .glb/.gltf, .dae, .txt/.fastrak) to .csv, .bvh (on the take's own skeleton when it has one) or .glb (glTF binary) by the output's extension, or a corpus "
            "folder to a corpus folder",
            arguments, runConvert);
        convert->add_option("IN", arguments->input, "Input take file or corpus folder")->required();
        convert->add_option("-o,--output", arguments->output, "Output file (.bvh, .glb or .csv) or corpus folder")->required();
        convert->add_flag("--kimono", arguments->kimono,
                          "Simulate the puppet's kimono as cloth over the take: a .csv output gets its measured points (sleeve tips, hem "
                          "front/back/left/right; x y z cm) as 18 more channels; a .glb output the cloth as a mesh 'kimono_cloth' moving by "
                          "morph targets animated by weights (at most " + std::to_string(render::kKimonoExportMaxKeys) +
                          " key shapes), the figure without its skinned skirt and sleeves (docs/KIMONO.md)");
        addClothOptions(convert, arguments->cloth);
        addImportOptions(convert, arguments->import);
    }
    {
        auto arguments = std::make_shared<PreprocessArguments>();
        CLI::App* preprocess = addCommand(commands.root, "preprocess",
            "Thesis 2.2 preprocessing of a corpus: unwrap angles, pad to the longest take, align start times to "
            "each cell's reference take and start positions to each function's reference take",
            arguments, runPreprocess, "Print the per-take report as JSON");
        preprocess->add_option("CORPUS", arguments->input, "Input corpus folder")->required();
        preprocess->add_option("-o,--output", arguments->output, "Output corpus folder")->required();
        preprocess->add_flag("--no-pad", arguments->noPad, "Do not pad takes to the longest");
        preprocess->add_flag("--no-unwrap", arguments->noUnwrap, "Do not unwrap angles");
        preprocess->add_flag("--no-align-start", arguments->noAlignStart, "Do not align start times");
        preprocess->add_flag("--no-align-position", arguments->noAlignPosition, "Do not align start positions");
        preprocess->add_option("--position", arguments->position,
                               "Start-position alignment: rigid (one translation per take, keeping the geometry between "
                               "the parts; thesis 2.2-4, default) or per-part (each part to the reference's start)")
            ->check(CLI::IsMember({"rigid", "per-part"}));
        preprocess->add_flag("--no-align-heading", arguments->noAlignHeading,
                             "Do not align the whole-body heading (start yaw of the heading part)");
        preprocess->add_option("--heading-part", arguments->headingPart, "Part whose start yaw is the whole-body heading (on a skeleton's joints without it: the joint the arms branch from)")
            ->capture_default_str();
        preprocess->add_option("--align-method", arguments->method,
                               "Start-time alignment: onset (where the distance from the start pose, positions and "
                               "rotations, rises above its noise floor) or xcorr (cross-correlation of that rise)")
            ->check(CLI::IsMember({"onset", "xcorr"}))
            ->capture_default_str();
        preprocess->add_option("--reference-take", arguments->referenceTake, "Take index of each cell's time reference; 0 = automatic (median onset among the longest takes)")
            ->transform(parameterCheck("preprocess.referenceTake"))
            ->capture_default_str();
        preprocess->add_option("--max-shift", arguments->maxShift, "Largest shift in frames tried by xcorr")
            ->check(CLI::Range(0, 1000000))
            ->capture_default_str();
        preprocess->add_option("--onset-fraction", arguments->onsetFraction, "Onset threshold as a fraction of the peak speed")
            ->check(CLI::Range(1e-6, 1.0))
            ->capture_default_str();
    }
}

} // namespace bunraku::app::cli
