#include "render/take_export.h"

#include "analysis/body/body_pose.h"
#include "analysis/body/performer_body.h"
#include "analysis/body/puppet_model.h"
#include "analysis/cloth/kimono_mesh.h"
#include "analysis/core/skeleton_take.h"
#include "analysis/skeleton/puppet_rig_fit.h"
#include "analysis/io/take_csv.h"
#include "analysis/io/take_reader.h"
#include "render/puppet_geometry.h"
#include "render/skeleton_geometry.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

namespace bunraku::render {

namespace {

analysis::io::JointMesh toJointMesh(const Mesh& mesh, int joint)
{
    analysis::io::JointMesh out;
    out.joint = joint;
    for (const Vertex& v : mesh.vertices) {
        out.positions.emplace_back(v.position.x, v.position.y, v.position.z);
        out.normals.emplace_back(v.normal.x, v.normal.y, v.normal.z);
        out.colours.emplace_back(v.colour.x, v.colour.y, v.colour.z);
    }
    out.indices = mesh.indices;
    return out;
}

} // namespace

TakeExportFormat takeExportFormat(const std::filesystem::path& file)
{
    std::string extension = file.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (extension == ".csv") return TakeExportFormat::Csv;
    if (extension == ".bvh") return TakeExportFormat::Bvh;
    if (extension == ".glb") return TakeExportFormat::Glb;
    return TakeExportFormat::Unknown;
}

const char* takeExportExpectation() { return "expected a .bvh, .glb or .csv file name"; }

ExportRig skeletonRig(const std::shared_ptr<const analysis::SkeletalMotion>& motion)
{
    ExportRig rig;
    rig.motion = motion;
    const std::vector<Mesh> meshes = buildSkeletonMeshes(*motion);
    for (std::size_t j = 0; j < meshes.size(); ++j)
        if (!meshes[j].empty()) rig.meshes.push_back(toJointMesh(meshes[j], int(j)));
    return rig;
}

ExportRig performerRig(const std::shared_ptr<const analysis::SkeletalMotion>& motion)
{
    auto body = analysis::performerBody(*motion);
    if (!body) return skeletonRig(motion);
    const analysis::Skeleton& skeleton = *motion->skeleton;
    ExportRig rig;
    rig.motion = motion;
    analysis::io::SkinnedMesh& mesh = rig.skinned;
    const analysis::PuppetMesh& surface = body->mesh;
    mesh.positions = surface.positions;
    mesh.normals = surface.normals;
    mesh.colours = surface.colours;
    mesh.indices = surface.indices;
    mesh.weights = surface.weights;
    mesh.bindPoses = body->bindPoses;
    // An End Site moves rigidly with its parent (its bind pose is the parent's, offset): its
    // weight goes to the parent, which has a node in the file.
    const auto carrier = [&](int joint) {
        while (joint >= 0 && skeleton.joints[std::size_t(joint)].endSite) joint = skeleton.joints[std::size_t(joint)].parent;
        return std::max(joint, 0);
    };
    mesh.joints.reserve(surface.vertexCount());
    for (const auto& influence : surface.joints)
        mesh.joints.push_back({carrier(influence[0]), carrier(influence[1]), carrier(influence[2]), carrier(influence[3])});
    return rig;
}

analysis::Result<ExportRig> puppetRig(const analysis::BodyDescription& body, const analysis::Take& take, bool underCloth)
{
    auto binding = analysis::bindBody(body, take);
    if (!binding) return binding.error();
    // The modelled puppet stands for a body with its six parts, as in the 3D view (renderer.cpp);
    // another body is its parts' primitives, each carried rigidly by its part.
    const bool modelled = analysis::bodyHasPuppetParts(body);
    std::vector<std::string> names;
    if (modelled)
        names.assign(analysis::kPuppetJointNames.begin(), analysis::kPuppetJointNames.end());
    else
        for (const auto& part : body.parts) names.push_back(part.name);
    auto skeleton = std::make_shared<analysis::Skeleton>();
    skeleton->name = body.name.empty() ? std::string("puppet") : body.name;
    skeleton->joints.push_back(analysis::SkeletonJoint{"puppet", -1, Eigen::Vector3d::Zero(), {}, false});
    for (const std::string& name : names) skeleton->joints.push_back(analysis::SkeletonJoint{name, 0, Eigen::Vector3d::Zero(), {}, false});
    if (auto valid = analysis::validateSkeleton(*skeleton); !valid) return valid.error();
    const Eigen::Index frames = take.frameCount();
    auto motion = std::make_shared<analysis::SkeletalMotion>(analysis::makeRestMotion(skeleton, frames));
    const int joints = int(names.size());
    for (int j = 0; j < joints; ++j) motion->movingJoints.push_back(1 + j);
    motion->movingTranslations.resize(frames, 3 * joints);
    ExportRig rig;
    rig.motion = motion;
    std::shared_ptr<const analysis::PuppetMesh> puppet;
    if (modelled) puppet = std::make_shared<const analysis::PuppetMesh>(analysis::fittedPuppetMesh(analysis::shippedPuppetMesh(), body));
    for (Eigen::Index f = 0; f < frames; ++f) {
        // The view's poses: the parts' (worldPartPoses) and, for the modelled puppet, its joints
        // posed from them (puppetJointPoses, what the renderer's skinning takes).
        const auto parts = analysis::worldPartPoses(body, *binding, take, f);
        std::vector<analysis::RigidTransform> poses(parts);
        if (puppet) {
            const auto posed = analysis::puppetJointPoses(*puppet, body, parts);
            poses.assign(posed.begin(), posed.end());
        }
        for (int j = 0; j < joints; ++j) {
            motion->rotation(f, 1 + j) = poses[std::size_t(j)].rotation;
            motion->movingTranslations.block<1, 3>(f, 3 * j) = poses[std::size_t(j)].translation.transpose();
        }
    }
    if (puppet) {
        analysis::io::SkinnedMesh& mesh = rig.skinned;
        mesh.positions = puppet->positions;
        mesh.normals = puppet->normals;
        mesh.colours = puppet->colours;
        mesh.indices = underCloth ? analysis::puppetIndicesUnderCloth(*puppet) : puppet->indices;
        mesh.weights = puppet->weights;
        mesh.joints.reserve(puppet->vertexCount());
        for (const auto& influence : puppet->joints)
            mesh.joints.push_back({1 + influence[0], 1 + influence[1], 1 + influence[2], 1 + influence[3]});
        mesh.bindPoses.push_back(analysis::RigidTransform{}); // the root, at the origin
        mesh.bindPoses.insert(mesh.bindPoses.end(), puppet->bindPoses.begin(), puppet->bindPoses.end());
        return rig;
    }
    const std::vector<Mesh> meshes = buildPuppetMeshes(body);
    for (std::size_t p = 0; p < meshes.size(); ++p)
        if (!meshes[p].empty()) rig.meshes.push_back(toJointMesh(meshes[p], int(p) + 1));
    return rig;
}

namespace {

/// True when a .glb of the body take `shown` holds the performer's skeleton and body, false when
/// it holds the puppet (exportTake's choice).
bool exportsPerformer(const analysis::Take& shown) { return shown.skeleton && !analysis::isPuppetRig(*shown.skeleton->skeleton); }

} // namespace

std::vector<Eigen::Index> kimonoKeyFrames(Eigen::Index frames, int maxKeys)
{
    std::vector<Eigen::Index> keys;
    if (frames <= 0) return keys;
    const Eigen::Index n = std::max<Eigen::Index>(2, maxKeys);
    if (frames <= n) {
        for (Eigen::Index f = 0; f < frames; ++f) keys.push_back(f);
        return keys;
    }
    for (Eigen::Index k = 0; k < n; ++k)
        keys.push_back(Eigen::Index(std::llround(double(k) * double(frames - 1) / double(n - 1))));
    return keys;
}

analysis::Take kimonoExportTake(const analysis::Take& take)
{
    analysis::Take shown = analysis::bodyTake(take);
    if (!exportsPerformer(shown)) shown.skeleton = nullptr;
    return shown;
}

analysis::Result<analysis::io::MorphAnimatedMesh> kimonoMorphMesh(const std::shared_ptr<const analysis::KimonoSimulation>& simulation,
                                                                 const std::shared_ptr<const analysis::Take>& take, int maxKeys,
                                                                 const analysis::RunControl& control)
{
    const analysis::KimonoCloth& cloth = *simulation->cloth;
    analysis::io::MorphAnimatedMesh mesh;
    mesh.name = "kimono_cloth";
    mesh.indices = cloth.triangles;
    mesh.colours = analysis::kimonoLook(cloth, analysis::shippedPuppetMesh()).colours;
    const std::vector<Eigen::Index> keys = kimonoKeyFrames(simulation->frameCount(), maxKeys);
    analysis::KimonoPlayer player(simulation, take);
    for (std::size_t k = 0; k < keys.size(); ++k) {
        if (control.cancelled()) return analysis::makeError(analysis::ErrorCode::Cancelled, take->displayName() + ": the kimono's export was cancelled");
        auto particles = player.frame(keys[k]);
        if (!particles) return particles.error();
        const std::vector<Eigen::Vector3d>& x = **particles;
        if (k == 0) mesh.normals = analysis::kimonoNormals(cloth, x);
        std::vector<Eigen::Vector3f> positions(x.size());
        for (std::size_t i = 0; i < x.size(); ++i) positions[i] = x[i].cast<float>();
        mesh.keyPositions.push_back(std::move(positions));
        mesh.keyTimes.push_back(double(keys[k]) / simulation->rateHz);
        if (k % 16 == 0) control.report(double(k + 1) / double(keys.size()));
    }
    control.report(1.0);
    return mesh;
}

std::string takeExportNote(const analysis::Take& take, const std::filesystem::path& file, const analysis::Take* perChannel)
{
    if (takeExportFormat(file) == TakeExportFormat::Unknown) return {};
    const auto body = analysis::bodyMotion(take);
    const Eigen::MatrixXd* ghost = body.perChannel ? body.perChannel.get() : perChannel ? &perChannel->values : nullptr;
    if (!ghost) return {};
    const auto distance = analysis::perChannelDistance(body.take, *ghost);
    if (!distance || (distance->maxPositionCm < analysis::kSkeletonGapNoticeCm && distance->maxAngleDeg < analysis::kSkeletonGapNoticeDeg))
        return {};
    char by[160];
    std::snprintf(by, sizeof by, "up to %.1f cm (%s, frame %lld) and %.1f deg", distance->maxPositionCm, distance->worstPart.c_str(),
                  static_cast<long long>(distance->worstFrame), distance->maxAngleDeg);
    return file.filename().string() + " holds the take as one body moves (its skeleton, and the channels posed from it); the thesis's " +
           "per-channel result differs from it by " + by;
}

analysis::Status exportTake(const analysis::Take& take, const analysis::BodyDescription& body, const std::filesystem::path& file,
                            const std::string& name, const std::string& description, const KimonoExport* kimono)
{
    // One motion: every format holds the body's (analysis::bodyTake), as the view and graphs show it.
    const analysis::Take shown = analysis::bodyTake(take);
    const TakeExportFormat format = takeExportFormat(file);
    const auto failed = [&](const analysis::Error& error) { return analysis::makeError(error.code, file.string() + ": " + error.message); };
    // The kimono, simulated on the take the file holds (kimonoExportTake): 80% of the progress,
    // the key shapes the rest.
    std::shared_ptr<const analysis::Take> clothTake;
    std::shared_ptr<const analysis::KimonoSimulation> simulation;
    if (kimono && format != TakeExportFormat::Unknown) {
        if (format == TakeExportFormat::Bvh)
            return analysis::makeError(analysis::ErrorCode::Unsupported,
                                       file.string() + ": a .bvh cannot hold the kimono (the simulated cloth goes into a .glb or a .csv)");
        if (kimono->maxKeys < 2) return analysis::makeError(analysis::ErrorCode::InvalidArgument, file.string() + ": the kimono needs at least 2 key shapes");
        clothTake = std::make_shared<const analysis::Take>(kimonoExportTake(take));
        auto simulated = analysis::simulateKimono(*clothTake, kimono->cloth,
                                                  format == TakeExportFormat::Glb ? kimono->control.step(0.0, 0.8) : kimono->control);
        if (!simulated) return failed(simulated.error());
        simulation = std::make_shared<const analysis::KimonoSimulation>(std::move(simulated).value());
    }
    switch (format) {
    case TakeExportFormat::Csv:
        if (simulation) return analysis::io::writeTakeCsv(analysis::withKimonoChannels(shown, *simulation), file, description);
        return analysis::io::writeTakeCsv(shown, file, description);
    case TakeExportFormat::Bvh: return analysis::io::writeTakeFile(shown, file);
    case TakeExportFormat::Glb: {
        if (auto valid = analysis::validateTake(shown); !valid) return failed(valid.error());
        ExportRig rig;
        if (exportsPerformer(shown)) {
            rig = performerRig(shown.skeleton);
        } else {
            // The puppet itself (a take of the puppet's channels, or on its fitted rig).
            analysis::Take channels = shown;
            channels.skeleton = nullptr;
            auto puppet = puppetRig(body, channels, simulation != nullptr);
            if (!puppet) return failed(puppet.error());
            rig = std::move(puppet).value();
        }
        analysis::io::GltfExportOptions options;
        options.name = name.empty() ? shown.displayName() : name;
        options.description = description;
        if (simulation) {
            auto cloth = kimonoMorphMesh(simulation, clothTake, kimono->maxKeys, kimono->control.step(0.8, 1.0));
            if (!cloth) return failed(cloth.error());
            options.animatedMesh = std::make_shared<const analysis::io::MorphAnimatedMesh>(std::move(cloth).value());
        }
        if (rig.meshes.empty()) return analysis::io::writeSkinnedGlb(*rig.motion, shown.rateHz, rig.skinned, file, options);
        return analysis::io::writeSkeletalGlb(*rig.motion, shown.rateHz, rig.meshes, file, options);
    }
    case TakeExportFormat::Unknown: break;
    }
    return analysis::makeError(analysis::ErrorCode::Unsupported,
                               file.string() + ": cannot write '" + file.extension().string() + "' (" + takeExportExpectation() + ")");
}

} // namespace bunraku::render
