#include "analysis/io/bvh_import.h"

#include "analysis/core/puppet_layout.h"
#include "analysis/io/atomic_file.h"
#include "analysis/io/bvh_export.h"
#include "analysis/io/text_scan.h"

#include <nlohmann/json.hpp>

#include <cctype>
#include <cmath>

namespace bunraku::analysis::io {

namespace {

/// Built-in maps, tried in order: Bandai Namco, Mixamo (prefixed and plain), CMU, Daz/Truebones,
/// this workbench's own export.
const std::vector<JointMap>& builtInMaps()
{
    static const std::vector<JointMap> maps{
        JointMap{{"Head", "Chest", "LowerArm_R", "Hand_R"}},
        JointMap{{"mixamorig:Head", "mixamorig:Spine2", "mixamorig:RightForeArm", "mixamorig:RightHand"}},
        JointMap{{"Head", "Spine2", "RightForeArm", "RightHand"}},
        JointMap{{"Head", "Spine1", "RightForeArm", "RightHand"}},
        JointMap{{"Head", "Chest", "RightForeArm", "RightHand"}},
        JointMap{{"head", "chest", "rForeArm", "rHand"}},
        JointMap{{"head", "shoulder", "arm", "hand"}}, // bvh_export.h
    };
    return maps;
}

int partIndex(std::string_view part)
{
    for (std::size_t p = 0; p < kPuppetParts.size(); ++p)
        if (kPuppetParts[p] == part) return int(p);
    return -1;
}

std::string jointList(const BvhSkeleton& skeleton)
{
    std::string out;
    for (const auto& joint : skeleton.joints) {
        if (joint.endSite) continue;
        if (!out.empty()) out += ", ";
        out += joint.name;
    }
    return out;
}

RigidTransform toWorkbench(const RigidTransform& file_T_joint, const Eigen::Quaterniond& world_R_file, double scale)
{
    return RigidTransform{(world_R_file * file_T_joint.rotation * world_R_file.conjugate()).normalized(),
                          world_R_file * (scale * file_T_joint.translation)};
}

/// Resolves the joint map (explicit parts over defaults) into joint indices.
Result<std::array<int, 4>> resolveJoints(const BvhFile& file, const BvhImportOptions& options)
{
    const auto fallback = defaultJointMap(file.skeleton);
    std::array<int, 4> indices{};
    for (std::size_t p = 0; p < 4; ++p) {
        std::string name = options.jointMap ? options.jointMap->joints[p] : std::string();
        if (name.empty() && fallback) name = fallback->joints[p];
        if (name.empty())
            return makeError(ErrorCode::NotFound, file.source + ": no joint for the puppet part '" + std::string(kPuppetParts[p]) +
                                                      "': the skeleton matches no built-in joint map; give --joints " +
                                                      "head=...,shoulder=...,arm=...,hand=... (joints: " + jointList(file.skeleton) + ")");
        const int index = file.skeleton.find(name);
        if (index < 0)
            return makeError(ErrorCode::NotFound, file.source + ": joint '" + name + "' (for part '" + std::string(kPuppetParts[p]) +
                                                      "') is not in the skeleton (joints: " + jointList(file.skeleton) + ")");
        indices[p] = index;
    }
    return indices;
}

Status checkOptions(const BvhFile& file, const BvhImportOptions& options)
{
    if (!(options.unitScale > 0.0) || !std::isfinite(options.unitScale))
        return makeError(ErrorCode::InvalidArgument, file.source + ": the unit scale must be a positive number");
    if (file.motion.values.rows() < 1) return makeError(ErrorCode::InvalidArgument, file.source + ": the BVH file has no frames");
    return okStatus();
}

JointChannel toJointChannel(BvhChannel channel)
{
    switch (channel) {
    case BvhChannel::Xposition: return JointChannel::Xposition;
    case BvhChannel::Yposition: return JointChannel::Yposition;
    case BvhChannel::Zposition: return JointChannel::Zposition;
    case BvhChannel::Xrotation: return JointChannel::Xrotation;
    case BvhChannel::Yrotation: return JointChannel::Yrotation;
    default: return JointChannel::Zrotation;
    }
}

} // namespace

Result<JointMap> parseJointMap(const std::string& text, const JointMap& base)
{
    JointMap map = base;
    for (const auto item : detail::splitFields(text, ',')) {
        if (item.empty()) continue;
        const auto equals = item.find('=');
        if (equals == std::string_view::npos)
            return makeError(ErrorCode::InvalidArgument, "joint map item " + detail::quoted(item) + ": expected part=Joint");
        const auto part = detail::trim(item.substr(0, equals));
        const auto joint = detail::trim(item.substr(equals + 1));
        const int p = partIndex(part);
        if (p < 0)
            return makeError(ErrorCode::InvalidArgument,
                             "joint map item " + detail::quoted(item) + ": unknown part, expected head, shoulder, arm or hand");
        if (joint.empty()) return makeError(ErrorCode::InvalidArgument, "joint map item " + detail::quoted(item) + ": empty joint name");
        map.joints[std::size_t(p)] = std::string(joint);
    }
    return map;
}

Result<JointMap> readJointMapJson(const std::filesystem::path& file, const JointMap& base)
{
    auto text = readTextFile(file);
    if (!text) return text.error();
    nlohmann::json document;
    try {
        document = nlohmann::json::parse(*text);
    } catch (const nlohmann::json::parse_error& e) {
        long line = 1;
        for (std::size_t i = 0; i < std::min<std::size_t>(e.byte, text->size()); ++i) line += (*text)[i] == '\n' ? 1 : 0;
        return parseError(file.string(), line, std::string("invalid JSON: ") + e.what());
    }
    if (!document.is_object())
        return parseError(file.string(), 0, "expected a JSON object {\"head\": \"Joint\", \"shoulder\": ..., \"arm\": ..., \"hand\": ...}");
    JointMap map = base;
    for (const auto& [key, value] : document.items()) {
        const int p = partIndex(key);
        if (p < 0) return parseError(file.string(), 0, "unknown part \"" + key + "\", expected head, shoulder, arm or hand");
        if (!value.is_string() || value.get<std::string>().empty())
            return parseError(file.string(), 0, "part \"" + key + "\" must name a joint (a non-empty string)");
        map.joints[std::size_t(p)] = value.get<std::string>();
    }
    return map;
}

std::optional<JointMap> defaultJointMap(const BvhSkeleton& skeleton)
{
    for (const JointMap& map : builtInMaps()) {
        bool all = true;
        for (const auto& name : map.joints) all = all && skeleton.find(name) >= 0;
        if (all) return map;
    }
    return std::nullopt;
}

BvhUpAxis resolveUpAxis(const BvhFile& file, BvhUpAxis requested)
{
    if (requested != BvhUpAxis::Auto) return requested;
    if (!file.skeleton.joints.empty() && file.skeleton.joints.front().name == kBvhExportRootName) return BvhUpAxis::Z;
    std::vector<Eigen::Vector3d> points;
    if (file.motion.values.rows() > 0) {
        for (const auto& pose : bvhWorldPoses(file, 0)) points.push_back(pose.translation);
    } else {
        std::vector<Eigen::Vector3d> world(file.skeleton.joints.size());
        for (std::size_t j = 0; j < world.size(); ++j) {
            const int parent = file.skeleton.joints[j].parent;
            world[j] = file.skeleton.joints[j].offset + (parent >= 0 ? world[std::size_t(parent)] : Eigen::Vector3d::Zero());
        }
        points = world;
    }
    if (points.empty()) return BvhUpAxis::Y;
    Eigen::Vector3d low = points.front(), high = points.front();
    for (const auto& p : points) {
        low = low.cwiseMin(p);
        high = high.cwiseMax(p);
    }
    const Eigen::Vector3d extent = high - low;
    return extent.z() > extent.y() ? BvhUpAxis::Z : BvhUpAxis::Y;
}

Eigen::Quaterniond bvhAxisChange(BvhUpAxis upAxis)
{
    if (upAxis == BvhUpAxis::Z) return Eigen::Quaterniond::Identity();
    Eigen::Matrix3d world_R_file;
    world_R_file << 0, 0, 1, //
        1, 0, 0,             //
        0, 1, 0;
    return Eigen::Quaterniond(world_R_file);
}

std::vector<RigidTransform> bvhWorkbenchPoses(const BvhFile& file, Eigen::Index frame, BvhUpAxis upAxis, double unitScale,
                                              const BvhKinematicsOptions& kinematics)
{
    const Eigen::Quaterniond world_R_file = bvhAxisChange(resolveUpAxis(file, upAxis));
    auto poses = bvhWorldPoses(file, frame, kinematics);
    for (auto& pose : poses) pose = toWorkbench(pose, world_R_file, unitScale);
    return poses;
}

double bvhRateHz(double frameTime)
{
    const double rate = 1.0 / frameTime;
    const double whole = std::round(rate);
    return whole > 0.0 && std::fabs(rate - whole) <= 1e-4 * rate ? whole : rate;
}

Result<std::shared_ptr<const SkeletalMotion>> bvhToSkeletalMotion(const BvhFile& file, const BvhImportOptions& options,
                                                                  const std::array<int, 4>* joints)
{
    if (auto ok = checkOptions(file, options); !ok) return ok.error();
    const BvhUpAxis upAxis = resolveUpAxis(file, options.upAxis);
    const Eigen::Quaterniond world_R_file = bvhAxisChange(upAxis);
    const double scale = options.unitScale;
    auto skeleton = std::make_shared<Skeleton>();
    skeleton->name = std::filesystem::path(file.source).stem().string();
    skeleton->source = SourceFrame{world_R_file, scale, upAxis == BvhUpAxis::Z ? "z" : "y"};
    skeleton->positionMode = options.kinematics.positionMode == BvhPositionMode::ReplaceOffset ? PositionChannelMode::ReplaceOffset
                                                                                               : PositionChannelMode::AddToOffset;
    const std::size_t slots = file.skeleton.joints.size();
    skeleton->joints.reserve(slots);
    for (const BvhJoint& joint : file.skeleton.joints) {
        SkeletonJoint out;
        out.name = joint.name;
        out.parent = joint.parent;
        out.offset = world_R_file * (scale * joint.offset);
        out.endSite = joint.endSite;
        for (const BvhChannel c : joint.channels) out.channels.push_back(toJointChannel(c));
        skeleton->joints.push_back(std::move(out));
    }
    if (joints)
        for (std::size_t p = 0; p < 4; ++p) skeleton->parts.push_back(PartBinding{std::string(kPuppetParts[p]), (*joints)[p], {}});
    if (auto valid = validateSkeleton(*skeleton); !valid) return makeError(valid.error().code, file.source + ": " + valid.error().message);

    const Eigen::Index frames = file.motion.values.rows();
    auto motion = std::make_shared<SkeletalMotion>(makeRestMotion(skeleton, frames));
    // Local translations of every frame first, to tell moving joints from static ones.
    std::vector<Eigen::Vector3d> translations(std::size_t(frames) * slots);
    for (Eigen::Index f = 0; f < frames; ++f) {
        const auto local = bvhLocalPoses(file, f, options.kinematics);
        for (std::size_t j = 0; j < slots; ++j) {
            const RigidTransform pose = toWorkbench(local[j], world_R_file, scale);
            motion->rotation(f, int(j)) = pose.rotation;
            translations[std::size_t(f) * slots + j] = pose.translation;
        }
    }
    for (std::size_t j = 0; j < slots; ++j) {
        const Eigen::Vector3d first = frames > 0 ? translations[j] : skeleton->joints[j].offset;
        bool moving = false;
        for (Eigen::Index f = 1; f < frames && !moving; ++f) moving = translations[std::size_t(f) * slots + j] != first;
        motion->staticTranslations[j] = first;
        if (moving) motion->movingJoints.push_back(int(j));
    }
    motion->movingTranslations.resize(frames, Eigen::Index(3 * motion->movingJoints.size()));
    for (std::size_t k = 0; k < motion->movingJoints.size(); ++k)
        for (Eigen::Index f = 0; f < frames; ++f)
            motion->movingTranslations.block<1, 3>(f, Eigen::Index(3 * k)) =
                translations[std::size_t(f) * slots + std::size_t(motion->movingJoints[k])].transpose();
    if (auto valid = validateSkeletalMotion(*motion); !valid)
        return makeError(ErrorCode::Numerical, file.source + ": the poses overflow (values too large?): " + valid.error().message);
    return std::shared_ptr<const SkeletalMotion>(std::move(motion));
}

Result<Take> bvhToPuppetTake(const BvhFile& file, const BvhImportOptions& options)
{
    if (auto ok = checkOptions(file, options); !ok) return ok.error();
    auto joints = resolveJoints(file, options);
    if (!joints) return joints.error();
    const BvhUpAxis upAxis = resolveUpAxis(file, options.upAxis);
    Take take;
    take.channels = puppetChannels();
    take.rateHz = bvhRateHz(file.motion.frameTime);
    take.values = Eigen::MatrixXd::Zero(file.motion.values.rows(), kPuppetChannelCount);
    take.labels = options.labels;
    if (take.labels.source.empty()) take.labels.source = file.source;
    for (Eigen::Index f = 0; f < take.frameCount(); ++f) {
        const auto poses = bvhWorkbenchPoses(file, f, upAxis, options.unitScale, options.kinematics);
        for (int p = 0; p < kPuppetPartCount; ++p)
            setPartPose(take, f, Eigen::Index(p) * kDofCount, poses[std::size_t((*joints)[std::size_t(p)])]);
    }
    auto skeleton = bvhToSkeletalMotion(file, options, &*joints);
    if (!skeleton) return skeleton.error();
    take.skeleton = *skeleton;
    if (auto valid = validateTake(take); !valid)
        return makeError(ErrorCode::Numerical, file.source + ": the poses overflow (values too large?): " + valid.error().message);
    return take;
}

Result<Take> bvhToJointTake(const BvhFile& file, const BvhImportOptions& options)
{
    if (auto ok = checkOptions(file, options); !ok) return ok.error();
    const BvhUpAxis upAxis = resolveUpAxis(file, options.upAxis);
    std::vector<std::size_t> kept;
    Take take;
    for (std::size_t j = 0; j < file.skeleton.joints.size(); ++j) {
        if (file.skeleton.joints[j].endSite) continue;
        kept.push_back(j);
        for (auto& channel : sixDofChannels(file.skeleton.joints[j].name)) take.channels.push_back(channel);
    }
    take.rateHz = bvhRateHz(file.motion.frameTime);
    take.values = Eigen::MatrixXd::Zero(file.motion.values.rows(), Eigen::Index(take.channels.size()));
    take.labels = options.labels;
    if (take.labels.source.empty()) take.labels.source = file.source;
    for (Eigen::Index f = 0; f < take.frameCount(); ++f) {
        const auto poses = bvhWorkbenchPoses(file, f, upAxis, options.unitScale, options.kinematics);
        for (std::size_t k = 0; k < kept.size(); ++k) setPartPose(take, f, Eigen::Index(k) * kDofCount, poses[kept[k]]);
    }
    auto skeleton = bvhToSkeletalMotion(file, options);
    if (!skeleton) return skeleton.error();
    take.skeleton = *skeleton;
    if (auto valid = validateTake(take); !valid)
        return makeError(ErrorCode::Numerical, file.source + ": the poses overflow (values too large?): " + valid.error().message);
    return take;
}

} // namespace bunraku::analysis::io
