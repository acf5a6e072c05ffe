#include "analysis/io/take_source.h"

#include "analysis/core/puppet_layout.h"
#include "analysis/io/corpus_io.h"

#include <algorithm>
#include <sstream>
#include <utility>

namespace bunraku::analysis::io {
namespace {

using nlohmann::json;

/// "ZXY" for a joint whose rotation channels are Z, X, Y in that order.
std::string rotationOrder(const BvhJoint& joint)
{
    std::string order;
    for (auto c : joint.channels)
        if (!isPositionChannel(c)) order += char('X' + channelAxis(c));
    return order;
}

const char* sceneFormatName(SceneFormat format)
{
    return format == SceneFormat::Fbx ? "fbx" : format == SceneFormat::Gltf ? "gltf" : "collada";
}

std::string joinedNames(const std::vector<std::string>& names)
{
    std::string out;
    for (std::size_t i = 0; i < names.size(); ++i) out += (i ? ", " : "") + names[i];
    return out;
}

} // namespace

Result<TakeSource> readTakeSource(const std::filesystem::path& path, const ImportOptions& options, UnmappedSkeleton unmapped)
{
    std::error_code ec;
    TakeSource source;
    if (std::filesystem::is_directory(path, ec)) {
        if (!isCorpusFolder(path)) return makeError(ErrorCode::NotFound, path.string() + ": not a corpus folder (no corpus.json)");
        auto corpus = readCorpus(path);
        if (!corpus) return corpus.error();
        source.corpus = std::move(corpus).value();
        source.isCorpus = true;
        source.format = "corpus";
        return source;
    }
    if (!std::filesystem::exists(path, ec)) return makeError(ErrorCode::NotFound, path.string() + ": no such file or folder");
    const auto format = takeFileFormat(path);
    source.corpus.name = path.stem().string();
    if (format != TakeFileFormat::Bvh && format != TakeFileFormat::Scene) {
        auto take = readTakeFile(path, options);
        if (!take) return take.error();
        source.format = format == TakeFileFormat::Csv ? "csv" : "fastrak";
        source.corpus.rateHz = take->rateHz;
        source.corpus.takes.push_back(std::move(take).value());
        return source;
    }
    // A scene file (FBX, glTF, Collada) is read as the BvhFile it converts to (y up, cm).
    SceneTakeInfo sceneInfo;
    auto bvh = readSkeletalFile(path, options, {}, &sceneInfo);
    if (!bvh) return bvh.error();
    source.bvh = std::make_unique<BvhFile>(std::move(bvh).value());
    const BvhImportOptions bvhOptions = format == TakeFileFormat::Scene ? sceneBvhOptions(options.bvh) : options.bvh;
    if (format == TakeFileFormat::Scene) source.scene = sceneInfo;
    source.format = format == TakeFileFormat::Scene ? sceneFormatName(sceneInfo.format) : "bvh";
    source.units = guessBvhUnits(*source.bvh, bvhOptions.upAxis);
    source.cmPerUnit = bvhUnitScale(*source.bvh, bvhOptions);
    if (auto lengths = checkBvhLengths(*source.bvh, source.cmPerUnit); !lengths) return lengths.error(); // `info` too: it prints the offsets
    source.upAxis = resolveUpAxis(*source.bvh, bvhOptions.upAxis);
    if (options.bvhLayout == BvhTakeLayout::AllJoints) {
        auto take = bvhToJointTake(*source.bvh, bvhOptions);
        if (!take) return take.error();
        source.corpus.takes.push_back(std::move(take).value());
    } else if (auto imported = importBvhPuppet(*source.bvh, bvhOptions); imported.ok()) {
        source.map = imported->map;
        source.corpus.takes.push_back(std::move(imported->take));
    } else if (unmapped == UnmappedSkeleton::Error) {
        return imported.error();
    } else {
        source.mapError = imported.error().message;
    }
    source.corpus.rateHz = bvhRateHz(source.bvh->motion.frameTime);
    return source;
}

json partMapJson(const PartMap& map)
{
    json out = json::object();
    for (std::size_t p = 0; p < 4; ++p)
        out[std::string(kPuppetParts[p])] = {{"joint", map.names.joints[p]}, {"found_by", mapMethodName(map.methods[p])}};
    out["side"] = bodySideName(map.side);
    return out;
}

json skeletalFileJson(const TakeSource& source)
{
    const BvhFile& bvh = *source.bvh;
    json joints = json::array();
    for (const auto& joint : bvh.skeleton.joints) {
        json channelNames = json::array();
        for (auto c : joint.channels) channelNames.push_back(bvhChannelName(c));
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
             {"up_axis", source.upAxis == BvhUpAxis::Z ? "z" : "y"},
             {"units", {{"guess", source.units.unit},
                        {"cm_per_unit_guessed", source.units.cmPerUnit},
                        {"height", source.units.height},
                        {"note", source.units.note},
                        {"cm_per_unit_used", source.cmPerUnit}}}};
    if (source.map) out["part_map"] = partMapJson(*source.map);
    if (!source.mapError.empty()) out["part_map_error"] = source.mapError;
    if (source.scene) {
        const SceneTakeInfo& scene = *source.scene;
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

std::string skeletalFileText(const TakeSource& loaded)
{
    std::ostringstream out;
    const BvhFile& bvh = *loaded.bvh;
    const auto& skeleton = bvh.skeleton;
    const double frames = double(bvh.motion.values.rows());
    if (loaded.scene) {
        const SceneTakeInfo& scene = *loaded.scene;
        out << "\n" << scene.formatName << ": animation " << scene.animation << " '" << scene.animations[std::size_t(scene.animation)]
            << "' of " << scene.animations.size() << ", sampled at " << scene.rateHz << " Hz (" << scene.rateSource
            << " rate) from " << scene.startTime << " s; file unit " << scene.unit << ", up axis " << scene.upAxis
            << ": converted to cm, y up (then the workbench's z up)";
        if (scene.helperNodesFolded > 0) out << "; " << scene.helperNodesFolded << " FBX pivot nodes folded into their joints";
        if (scene.scaleDropped) out << "; joint scale dropped (kept in positions)";
        if (scene.meshVertices > 0)
            out << "\nskinned mesh: " << scene.meshVertices << " vertices, " << scene.meshTriangles << " triangles, "
                << scene.meshBones.size() << " bones (" << joinedNames(scene.meshBones) << "), of " << scene.meshes
                << " meshes in the file (figure \"mesh\")";
        else if (scene.meshes > 0)
            out << "\nskinned mesh: none (" << scene.meshes << " meshes in the file, none kept for the skeleton)";
        for (const std::string& note : scene.meshNotes) out << "\n  mesh note: " << note;
        out << "\nconverted skeleton as BVH:";
    }
    out << "\nBVH: " << skeleton.jointCount() << " joints + " << skeleton.endSiteCount() << " End Sites, "
        << skeleton.channelCount << " channels, " << bvh.motion.values.rows() << " frames, frame time " << bvh.motion.frameTime
        << " s (" << bvhRateHz(bvh.motion.frameTime) << " Hz, " << std::max(0.0, frames - 1.0) * bvh.motion.frameTime
        << " s)\n";
    out << "up axis: " << (loaded.upAxis == BvhUpAxis::Z ? "z" : "y") << ", units: " << loaded.units.unit << " guessed ("
        << loaded.units.note << "), " << loaded.cmPerUnit << " cm per unit used\n";
    if (loaded.map) out << "part map: " << loaded.map->describe() << "\n";
    else if (!loaded.mapError.empty()) out << "part map: none (" << loaded.mapError << ")\n";
    out << "hierarchy (joint [channels]):\n";
    std::vector<int> depth(skeleton.joints.size(), 0);
    for (std::size_t j = 0; j < skeleton.joints.size(); ++j) {
        const auto& joint = skeleton.joints[j];
        if (joint.parent >= 0) depth[j] = depth[std::size_t(joint.parent)] + 1;
        // Deep chains are indented up to 40 levels and then labelled with their depth.
        const int shown = std::min(depth[j], 40);
        out << "  " << std::string(std::size_t(2 * shown), ' ') << (depth[j] > 40 ? "[depth " + std::to_string(depth[j]) + "] " : "")
            << (joint.endSite ? "(end) " : "") << joint.name;
        if (!joint.channels.empty()) {
            out << "  [";
            for (std::size_t k = 0; k < joint.channels.size(); ++k) out << (k ? " " : "") << bvhChannelName(joint.channels[k]);
            out << "]";
        }
        out << "\n";
    }
    return out.str();
}

} // namespace bunraku::analysis::io
