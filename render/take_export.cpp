#include "render/take_export.h"

#include "analysis/body/body_pose.h"
#include "analysis/body/performer_body.h"
#include "analysis/body/puppet_model.h"
#include "analysis/core/skeleton_take.h"
#include "analysis/skeleton/puppet_rig_fit.h"
#include "analysis/io/take_csv.h"
#include "analysis/io/take_reader.h"
#include "render/puppet_geometry.h"
#include "render/skeleton_geometry.h"

#include <algorithm>
#include <cctype>
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

analysis::Result<ExportRig> puppetRig(const analysis::BodyDescription& body, const analysis::Take& take)
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
        mesh.indices = puppet->indices;
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
                            const std::string& name, const std::string& description)
{
    // One motion: every format holds the body's (analysis::bodyTake), as the view and graphs show it.
    const analysis::Take shown = analysis::bodyTake(take);
    switch (takeExportFormat(file)) {
    case TakeExportFormat::Csv: return analysis::io::writeTakeCsv(shown, file, description);
    case TakeExportFormat::Bvh: return analysis::io::writeTakeFile(shown, file);
    case TakeExportFormat::Glb: {
        if (auto valid = analysis::validateTake(shown); !valid)
            return analysis::makeError(valid.error().code, file.string() + ": " + valid.error().message);
        ExportRig rig;
        if (shown.skeleton && !analysis::isPuppetRig(*shown.skeleton->skeleton)) {
            rig = performerRig(shown.skeleton);
        } else {
            // The puppet itself (a take of the puppet's channels, or on its fitted rig).
            analysis::Take channels = shown;
            channels.skeleton = nullptr;
            auto puppet = puppetRig(body, channels);
            if (!puppet) return analysis::makeError(puppet.error().code, file.string() + ": " + puppet.error().message);
            rig = std::move(puppet).value();
        }
        analysis::io::GltfExportOptions options;
        options.name = name.empty() ? shown.displayName() : name;
        options.description = description;
        if (rig.meshes.empty()) return analysis::io::writeSkinnedGlb(*rig.motion, shown.rateHz, rig.skinned, file, options);
        return analysis::io::writeSkeletalGlb(*rig.motion, shown.rateHz, rig.meshes, file, options);
    }
    case TakeExportFormat::Unknown: break;
    }
    return analysis::makeError(analysis::ErrorCode::Unsupported,
                               file.string() + ": cannot write '" + file.extension().string() + "' (" + takeExportExpectation() + ")");
}

} // namespace bunraku::render
