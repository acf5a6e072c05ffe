#include "analysis/io/bvh_import.h"

#include "analysis/core/skeleton_mesh.h"

#include "analysis/core/puppet_layout.h"
#include "analysis/core/puppet_rig_layout.h"
#include "analysis/core/skeleton_calibration.h"
#include "analysis/core/skeleton_mesh.h"
#include "analysis/core/skeleton_take.h"
#include "analysis/io/atomic_file.h"
#include "analysis/io/bvh_export.h"
#include "analysis/io/bvh_joint_map.h"
#include "analysis/io/json_text.h"
#include "analysis/io/text_scan.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>

namespace bunraku::analysis::io {

namespace {

int partIndex(std::string_view part)
{
    for (std::size_t p = 0; p < kPuppetParts.size(); ++p)
        if (kPuppetParts[p] == part) return int(p);
    return -1;
}

RigidTransform toWorkbench(const RigidTransform& file_T_joint, const Eigen::Quaterniond& world_R_file, double scale)
{
    return RigidTransform{(world_R_file * file_T_joint.rotation * world_R_file.conjugate()).normalized(),
                          world_R_file * (scale * file_T_joint.translation)};
}

Status checkOptions(const BvhFile& file, const BvhImportOptions& options)
{
    if (!(options.unitScale > 0.0) || !std::isfinite(options.unitScale))
        return makeError(ErrorCode::InvalidArgument, file.source + ": the unit scale must be a positive number");
    if (file.motion.values.rows() < 1) return makeError(ErrorCode::InvalidArgument, file.source + ": the BVH file has no frames");
    return okStatus();
}

/// A puppet take written by bvh_export.h: the root kBvhExportRootName and the four parts as
/// its children.
bool isWorkbenchExport(const BvhFile& file)
{
    const auto& joints = file.skeleton.joints;
    if (joints.empty() || joints.front().name != kBvhExportRootName) return false;
    for (const auto part : kPuppetParts) {
        const int j = file.skeleton.find(std::string(part));
        if (j < 0 || joints[std::size_t(j)].parent != 0) return false;
    }
    return true;
}

/// The puppet's rig as this workbench writes it (analysis/core/puppet_rig_layout.h).
bool isRigLayout(const BvhSkeleton& skeleton)
{
    if (skeleton.joints.size() != std::size_t(rig::kSlots)) return false;
    for (int slot = 0; slot < rig::kSlots; ++slot) {
        const BvhJoint& j = skeleton.joints[std::size_t(slot)];
        const rig::Slot& layout = rig::kLayout[std::size_t(slot)];
        if (j.name != layout.name || j.parent != layout.parent || j.endSite != layout.endSite) return false;
    }
    return true;
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
    auto parsed = parseJsonText(*text, file.string(), "invalid JSON");
    if (!parsed) return parsed.error();
    const nlohmann::json document = std::move(parsed).value();
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
    auto map = mapPuppetParts(skeleton);
    if (!map) return std::nullopt;
    return map->names;
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

BvhUnitsGuess guessBvhUnits(const BvhFile& file, BvhUpAxis upAxis)
{
    BvhUnitsGuess guess;
    const BvhUpAxis up = resolveUpAxis(file, upAxis);
    std::vector<Eigen::Vector3d> points;
    if (file.motion.values.rows() > 0) {
        for (const auto& pose : bvhWorldPoses(file, 0)) points.push_back(pose.translation);
    } else {
        for (std::size_t j = 0; j < file.skeleton.joints.size(); ++j) {
            const int parent = file.skeleton.joints[j].parent;
            points.push_back(file.skeleton.joints[j].offset + (parent >= 0 ? points[std::size_t(parent)] : Eigen::Vector3d::Zero()));
        }
    }
    double low = 0.0, high = 0.0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const double h = up == BvhUpAxis::Z ? points[i].z() : points[i].y();
        low = i == 0 ? h : std::min(low, h);
        high = i == 0 ? h : std::max(high, h);
    }
    guess.height = high - low;
    const std::string height = detail::shortText(guess.height);
    if (guess.height > 0.0 && guess.height < 5.0) {
        guess.unit = "m";
        guess.cmPerUnit = 100.0;
        guess.note = "the joints span " + height + " units from top to bottom: metres";
    } else if (guess.height >= 500.0 && guess.height < 5000.0) {
        guess.unit = "mm";
        guess.cmPerUnit = 0.1;
        guess.note = "the joints span " + height + " units from top to bottom: millimetres";
    } else {
        guess.note = "the joints span " + height + " units from top to bottom: centimetres";
        if (guess.height >= 40.0 && guess.height < 100.0) {
            // A small figure in cm or a person in inches: a take that walks says which. Walking
            // keeps the Froude number v^2 / (g L) (L the leg, about 0.53 of the height) near
            // 0.25; below 0.1 in centimetres the pace is too slow for any walker's legs, and
            // the same take in inches walks at 2.54 times that.
            const Eigen::Index frames = file.motion.values.rows();
            const double seconds = double(frames - 1) * file.motion.frameTime;
            if (frames > 1 && seconds >= 2.0 && !file.skeleton.joints.empty()) {
                const Eigen::Index step = std::max<Eigen::Index>(1, frames / 200);
                double travel = 0.0;
                Eigen::Vector2d last = Eigen::Vector2d::Zero();
                for (Eigen::Index f = 0; f < frames; f += step) {
                    const Eigen::Vector3d root = bvhWorldPoses(file, f).front().translation;
                    const Eigen::Vector2d ground = up == BvhUpAxis::Z ? Eigen::Vector2d(root.x(), root.y()) : Eigen::Vector2d(root.x(), root.z());
                    if (f > 0) travel += (ground - last).norm();
                    last = ground;
                }
                const double speed = travel / seconds; // units per second
                const double froudeCm = speed * speed / (981.0 * 0.53 * guess.height);
                if (travel > guess.height && froudeCm < 0.1) {
                    guess.unit = "in";
                    guess.cmPerUnit = 2.54;
                    guess.note = "the joints span " + height + " units from top to bottom and the take walks " +
                                 detail::shortText(speed) + " units/s: too slow for legs that short in centimetres " +
                                 "(Froude number " + detail::shortText(froudeCm) + "), a walk in inches (" +
                                 detail::shortText(froudeCm * 2.54) + "): inches";
                    return guess;
                }
            }
            guess.note += " (or inches: give --units in)";
        }
    }
    return guess;
}

double bvhUnitScale(const BvhFile& file, const BvhImportOptions& options)
{
    return options.guessUnits ? guessBvhUnits(file, options.upAxis).cmPerUnit : options.unitScale;
}

Result<std::shared_ptr<const SkeletalMotion>> bvhToSkeletalMotion(const BvhFile& file, const BvhImportOptions& options,
                                                                  const std::array<int, 4>* joints, const RunControl& control)
{
    if (auto ok = checkOptions(file, options); !ok) return ok.error();
    const BvhUpAxis upAxis = resolveUpAxis(file, options.upAxis);
    const Eigen::Quaterniond world_R_file = bvhAxisChange(upAxis);
    const Eigen::Matrix3d C = world_R_file.toRotationMatrix();
    const double scale = bvhUnitScale(file, options);
    if (auto lengths = checkBvhLengths(file, scale); !lengths) return lengths.error();
    const std::size_t slots = file.skeleton.joints.size();
    const Eigen::Index frames = file.motion.values.rows();
    const Eigen::Index width = file.motion.values.cols();
    // Memory follows the file's content, not its claims: the motion (a quaternion per joint
    // and frame) may take at most 8 times the channel data, plus 256 MB.
    const double bytes = double(frames) * double(slots) * double(sizeof(Eigen::Quaterniond) + sizeof(Eigen::Vector3d));
    if (bytes > 8.0 * double(frames) * double(std::max<Eigen::Index>(width, 1)) * 8.0 + 256e6)
        return makeError(ErrorCode::InvalidArgument,
                         file.source + ": " + std::to_string(slots) + " joints for " + std::to_string(width) + " channels over " +
                             std::to_string(frames) + " frames: the motion would take " + detail::shortText(bytes / 1e6) +
                             " MB (expected at most 8 times the channel data)");

    auto skeleton = std::make_shared<Skeleton>();
    skeleton->name = std::filesystem::path(file.source).stem().string();
    skeleton->source = SourceFrame{world_R_file, scale, upAxis == BvhUpAxis::Z ? "z" : "y"};
    skeleton->positionMode = options.kinematics.positionMode == BvhPositionMode::ReplaceOffset ? PositionChannelMode::ReplaceOffset
                                                                                               : PositionChannelMode::AddToOffset;
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
    if (auto valid = validateSkeleton(*skeleton); !valid) return makeError(valid.error().code, file.source + ": " + valid.error().message);
    // The file's skinned mesh, in the workbench's axes and cm as the joints are.
    if (file.mesh && meshFitsSkeleton(*file.mesh, *skeleton)) {
        auto mesh = std::make_shared<SkeletonMesh>(transformedSkeletonMesh(*file.mesh, world_R_file, scale));
        if (validateSkeletonMesh(*mesh).ok()) skeleton->mesh = std::move(mesh);
    }

    // A joint moves when one of its position channels changes over the take.
    auto motion = std::make_shared<SkeletalMotion>();
    motion->skeleton = skeleton;
    motion->staticTranslations.assign(slots, Eigen::Vector3d::Zero()); // a take of no frames keeps zeros
    for (std::size_t j = 0; j < slots; ++j) {
        const BvhJoint& joint = file.skeleton.joints[j];
        bool moving = false;
        for (std::size_t k = 0; k < joint.channels.size() && !moving; ++k) {
            if (!isPositionChannel(joint.channels[k])) continue;
            const auto column = file.motion.values.col(joint.firstChannel + Eigen::Index(k));
            moving = (column.array() != column(0)).any();
        }
        if (moving) motion->movingJoints.push_back(int(j));
    }
    motion->rotations.resize(std::size_t(frames) * slots);
    motion->movingTranslations.resize(frames, Eigen::Index(3 * motion->movingJoints.size()));
    std::vector<int> movingSlot(slots, -1);
    for (std::size_t k = 0; k < motion->movingJoints.size(); ++k) movingSlot[std::size_t(motion->movingJoints[k])] = int(k);

    const bool replace = options.kinematics.positionMode == BvhPositionMode::ReplaceOffset;
    const Eigen::Quaterniond file_R_world = world_R_file.conjugate();
    // Joint by joint: each joint's channels are contiguous columns of the (column-major) matrix.
    struct ChannelUse {
        const double* column;
        int axis;
        bool position;
    };
    std::vector<ChannelUse> uses;
    for (std::size_t j = 0; j < slots; ++j) {
        if (control.cancelled()) return makeError(ErrorCode::Cancelled, file.source + ": import stopped at joint " + file.skeleton.joints[j].name);
        control.report(double(j) / double(slots));
        const BvhJoint& joint = file.skeleton.joints[j];
        uses.clear();
        for (std::size_t k = 0; k < joint.channels.size(); ++k)
            uses.push_back({file.motion.values.col(joint.firstChannel + Eigen::Index(k)).data(), channelAxis(joint.channels[k]),
                            isPositionChannel(joint.channels[k])});
        const bool moving = movingSlot[j] >= 0;
        Eigen::Quaterniond* rotations = motion->rotations.data() + j;
        for (Eigen::Index f = 0; f < frames; ++f) {
            Eigen::Vector3d translation = joint.offset;
            Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
            for (const ChannelUse& use : uses) {
                const double value = use.column[f];
                if (use.position) {
                    translation[use.axis] = replace ? value : translation[use.axis] + value;
                } else {
                    const double half = 0.5 * value * M_PI / 180.0;
                    Eigen::Quaterniond step(std::cos(half), 0.0, 0.0, 0.0);
                    step.vec()[use.axis] = std::sin(half);
                    rotation = rotation * step;
                }
            }
            rotations[std::size_t(f) * slots] = (world_R_file * rotation * file_R_world).normalized();
            if (moving) motion->movingTranslations.block<1, 3>(f, 3 * movingSlot[j]) = (C * (scale * translation)).transpose();
            // A moving joint's static translation is its first frame's (what the skeleton file shows).
            if (f == 0) motion->staticTranslations[j] = C * (scale * translation);
        }
    }
    if (auto valid = validateSkeletalMotion(*motion); !valid)
        return makeError(ErrorCode::Numerical, file.source + ": the poses overflow (values too large?): " + valid.error().message);
    if (joints && isPuppetRig(*skeleton)) {
        // The puppet's rig as this workbench writes it: its parts where the rig puts them.
        skeleton->parts = *puppetRigBindings(*skeleton);
    } else if (joints && isWorkbenchExport(file)) {
        // This workbench's own export: its joints are the puppet's part frames already.
        for (std::size_t p = 0; p < 4; ++p) skeleton->parts.push_back(PartBinding{std::string(kPuppetParts[p]), (*joints)[p], {}});
    } else if (joints) {
        CalibrationOptions calibration;
        calibration.side = options.side;
        calibration.referenceFrame = std::clamp<Eigen::Index>(options.calibrationFrame, 0, std::max<Eigen::Index>(frames - 1, 0));
        auto bindings = calibratePartBindings(*motion, *joints, calibration);
        if (!bindings) return makeError(bindings.error().code, file.source + ": " + bindings.error().message);
        skeleton->parts = std::move(bindings).value();
    }
    return std::shared_ptr<const SkeletalMotion>(std::move(motion));
}

Result<BvhPuppetImport> importBvhPuppet(const BvhFile& file, const BvhImportOptions& options, const RunControl& control)
{
    if (auto ok = checkOptions(file, options); !ok) return ok.error();
    if (auto lengths = checkBvhLengths(file, bvhUnitScale(file, options)); !lengths) return lengths.error(); // before mapping on them
    std::optional<JointMap> given = options.jointMap;
    if (!given && isWorkbenchExport(file)) given = JointMap{{"head", "shoulder", "arm", "hand"}};
    if (!given && isRigLayout(file.skeleton)) given = JointMap{{kRigNeckJoint, kRigRootJoint, kRigArmSensorJoint, kRigWristJoint}};
    auto map = mapPuppetParts(file, given, PartMapOptions{options.side}, options);
    if (!map) return map.error();
    // The joints' rotations are most of the work: 90 % of the progress, the part channels the rest.
    auto motion = bvhToSkeletalMotion(file, options, &map->joints, control.step(0.0, 0.9));
    if (!motion) return motion.error();
    if (control.cancelled()) return makeError(ErrorCode::Cancelled, file.source + ": import stopped");
    TakeLabels labels = options.labels;
    if (labels.source.empty()) labels.source = file.source;
    auto take = puppetTakeFromSkeleton(*motion, bvhRateHz(file.motion.frameTime), labels);
    if (!take) return makeError(take.error().code, file.source + ": " + take.error().message);
    return BvhPuppetImport{std::move(take).value(), std::make_shared<const PartMap>(std::move(map).value()),
                           bvhUnitScale(file, options), resolveUpAxis(file, options.upAxis)};
}

Result<Take> bvhToPuppetTake(const BvhFile& file, const BvhImportOptions& options)
{
    auto imported = importBvhPuppet(file, options);
    if (!imported) return imported.error();
    return std::move(imported->take);
}

Result<Take> bvhToJointTake(const BvhFile& file, const BvhImportOptions& options)
{
    // The puppet's four parts are bound too when the part map finds them (as a puppet import
    // would), so the whole body can also be drawn as the puppet; a skeleton the map cannot read,
    // or whose calibration fails, is imported without them.
    std::shared_ptr<const SkeletalMotion> motion;
    if (auto ok = checkOptions(file, options); !ok) return ok.error();
    if (auto lengths = checkBvhLengths(file, bvhUnitScale(file, options)); !lengths) return lengths.error();
    std::optional<JointMap> given = options.jointMap;
    if (!given && isWorkbenchExport(file)) given = JointMap{{"head", "shoulder", "arm", "hand"}};
    if (!given && isRigLayout(file.skeleton)) given = JointMap{{kRigNeckJoint, kRigRootJoint, kRigArmSensorJoint, kRigWristJoint}};
    if (auto map = mapPuppetParts(file, given, PartMapOptions{options.side}, options))
        if (auto mapped = bvhToSkeletalMotion(file, options, &map->joints)) motion = std::move(mapped).value();
    if (!motion) {
        auto unmapped = bvhToSkeletalMotion(file, options);
        if (!unmapped) return unmapped.error();
        motion = std::move(unmapped).value();
    }
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
        const auto poses = motion->worldPoses(f);
        for (std::size_t k = 0; k < kept.size(); ++k) setPartPose(take, f, Eigen::Index(k) * kDofCount, poses[kept[k]]);
    }
    take.skeleton = motion;
    if (auto valid = validateTake(take); !valid)
        return makeError(ErrorCode::Numerical, file.source + ": the poses overflow (values too large?): " + valid.error().message);
    return take;
}

} // namespace bunraku::analysis::io
