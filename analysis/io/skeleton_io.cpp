#include "analysis/io/skeleton_io.h"

#include "analysis/io/atomic_file.h"
#include "analysis/io/json_text.h"
#include "analysis/io/take_csv.h"
#include "analysis/io/text_format.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace bunraku::analysis::io {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr std::array<const char*, 6> kChannelNames{"Xposition", "Yposition", "Zposition", "Xrotation", "Yrotation", "Zrotation"};
constexpr std::array<const char*, 4> kQuaternion{"qw", "qx", "qy", "qz"};
constexpr std::array<const char*, 3> kTranslation{"x", "y", "z"};

json vector3(const Eigen::Vector3d& v) { return json::array({v.x(), v.y(), v.z()}); }
json quaternion(const Eigen::Quaterniond& q) { return json::array({q.w(), q.x(), q.y(), q.z()}); }

/// The motion CSV's column part for a joint: "j<index>-<name with file-safe characters>".
std::string columnPart(const Skeleton& skeleton, int joint)
{
    std::string part = "j";
    part += std::to_string(joint);
    part += '-';
    part += fileSafeLabel(skeleton.joints[std::size_t(joint)].name);
    return part;
}

/// The motion as a take: the moving joints' translations, then every joint's rotation.
Take motionTake(const SkeletalMotion& motion, double rateHz)
{
    const Skeleton& skeleton = *motion.skeleton;
    Take take;
    take.rateHz = rateHz;
    for (int j : motion.movingJoints)
        for (const char* d : kTranslation) take.channels.push_back(Channel{columnPart(skeleton, j), d, "cm"});
    std::vector<int> rotated;
    for (std::size_t j = 0; j < skeleton.joints.size(); ++j)
        if (!skeleton.joints[j].endSite) rotated.push_back(int(j));
    for (int j : rotated)
        for (const char* d : kQuaternion) take.channels.push_back(Channel{columnPart(skeleton, j), d, ""});
    const Eigen::Index frames = motion.frameCount();
    take.values.resize(frames, Eigen::Index(take.channels.size()));
    for (Eigen::Index f = 0; f < frames; ++f) {
        Eigen::Index c = 0;
        for (std::size_t k = 0; k < motion.movingJoints.size(); ++k)
            for (int a = 0; a < 3; ++a) take.values(f, c++) = motion.movingTranslations(f, Eigen::Index(3 * k) + a);
        for (int j : rotated) {
            const Eigen::Quaterniond& q = motion.rotation(f, j);
            take.values(f, c++) = q.w();
            take.values(f, c++) = q.x();
            take.values(f, c++) = q.y();
            take.values(f, c++) = q.z();
        }
    }
    return take;
}

/// Reads JSON values with errors "file: path: what".
struct Reader {
    std::string file;
    Error fail(const std::string& where, const std::string& what) const { return makeError(ErrorCode::Parse, file + ": " + where + ": " + what); }

    Result<Eigen::Vector3d> vector(const json& object, const char* key, const std::string& where) const
    {
        const auto it = object.find(key);
        if (it == object.end() || !it->is_array() || it->size() != 3) return fail(where, std::string("\"") + key + "\" must be 3 numbers");
        Eigen::Vector3d v;
        for (std::size_t i = 0; i < 3; ++i) {
            if (!(*it)[i].is_number()) return fail(where, std::string("\"") + key + "\" must be 3 numbers");
            v[Eigen::Index(i)] = (*it)[i].get<double>();
        }
        if (!v.allFinite()) return fail(where, std::string("\"") + key + "\" must be finite");
        return v;
    }
    Result<Eigen::Quaterniond> rotation(const json& object, const char* key, const std::string& where) const
    {
        const auto it = object.find(key);
        if (it == object.end() || !it->is_array() || it->size() != 4)
            return fail(where, std::string("\"") + key + "\" must be a unit quaternion [w, x, y, z]");
        double c[4];
        for (std::size_t i = 0; i < 4; ++i) {
            if (!(*it)[i].is_number()) return fail(where, std::string("\"") + key + "\" must be a unit quaternion [w, x, y, z]");
            c[i] = (*it)[i].get<double>();
        }
        const Eigen::Quaterniond q(c[0], c[1], c[2], c[3]);
        if (!q.coeffs().allFinite() || std::fabs(q.squaredNorm() - 1.0) > 1e-6)
            return fail(where, std::string("\"") + key + "\" must be a unit quaternion [w, x, y, z]");
        return q;
    }
    Result<int> index(const json& object, const char* key, const std::string& where, int low, int high) const
    {
        const auto it = object.find(key);
        if (it == object.end() || !it->is_number_integer() || it->get<long long>() < low || it->get<long long>() >= high)
            return fail(where, std::string("\"") + key + "\" must be a joint index from " + std::to_string(low) + " to " +
                                   std::to_string(high - 1));
        return int(it->get<long long>());
    }
};

Result<std::shared_ptr<Skeleton>> parseSkeleton(const json& document, const Reader& reader, SkeletalMotion& motion)
{
    if (!document.is_object()) return reader.fail("top level", "expected a JSON object");
    if (document.value("format", std::string()) != kSkeletonFormatName)
        return reader.fail("\"format\"", std::string("expected \"") + kSkeletonFormatName + "\"");
    if (!document.contains("version") || !document["version"].is_number_integer() || document["version"].get<int>() != kSkeletonFormatVersion)
        return makeError(ErrorCode::Unsupported, reader.file + ": skeleton format version " +
                                                     (document.contains("version") ? document["version"].dump() : std::string("(none)")) +
                                                     " is not supported (expected " + std::to_string(kSkeletonFormatVersion) + ")");
    auto skeleton = std::make_shared<Skeleton>();
    if (document.contains("name") && document["name"].is_string()) skeleton->name = document["name"].get<std::string>();
    if (!document.contains("source") || !document["source"].is_object()) return reader.fail("top level", "missing \"source\" (an object)");
    const json& source = document["source"];
    auto world_R_source = reader.rotation(source, "world_R_source", "source");
    if (!world_R_source) return world_R_source.error();
    skeleton->source.world_R_source = *world_R_source;
    if (!source.contains("cm_per_unit") || !source["cm_per_unit"].is_number() || !(source["cm_per_unit"].get<double>() > 0.0) ||
        !std::isfinite(source["cm_per_unit"].get<double>()))
        return reader.fail("source", "\"cm_per_unit\" must be a positive number");
    skeleton->source.cmPerUnit = source["cm_per_unit"].get<double>();
    skeleton->source.upAxis = source.value("up_axis", std::string("y"));
    const std::string mode = document.value("position_mode", std::string("replace_offset"));
    if (mode != "replace_offset" && mode != "add_to_offset")
        return reader.fail("\"position_mode\"", "expected \"replace_offset\" or \"add_to_offset\"");
    skeleton->positionMode = mode == "replace_offset" ? PositionChannelMode::ReplaceOffset : PositionChannelMode::AddToOffset;

    if (!document.contains("joints") || !document["joints"].is_array() || document["joints"].empty())
        return reader.fail("top level", "missing \"joints\" (a non-empty array)");
    const json& joints = document["joints"];
    const int count = int(joints.size());
    motion.staticTranslations.resize(std::size_t(count));
    for (int j = 0; j < count; ++j) {
        const json& entry = joints[std::size_t(j)];
        const std::string where = "joints[" + std::to_string(j) + "]";
        if (!entry.is_object() || !entry.contains("name") || !entry["name"].is_string())
            return reader.fail(where, "expected an object with a \"name\"");
        SkeletonJoint joint;
        joint.name = entry["name"].get<std::string>();
        auto parent = reader.index(entry, "parent", where, -1, j);
        if (!parent) return parent.error();
        joint.parent = *parent;
        auto offset = reader.vector(entry, "offset", where);
        if (!offset) return offset.error();
        joint.offset = *offset;
        joint.endSite = entry.value("end_site", false);
        if (entry.contains("channels")) {
            if (!entry["channels"].is_array()) return reader.fail(where, "\"channels\" must be an array of BVH channel names");
            for (const auto& name : entry["channels"]) {
                const auto it = name.is_string() ? std::find(kChannelNames.begin(), kChannelNames.end(), name.get<std::string>())
                                                 : kChannelNames.end();
                if (it == kChannelNames.end()) return reader.fail(where, "unknown channel " + name.dump() + " (expected Xposition ... Zrotation)");
                joint.channels.push_back(JointChannel(it - kChannelNames.begin()));
            }
        }
        auto translation = reader.vector(entry, "translation", where);
        if (!translation) return translation.error();
        motion.staticTranslations[std::size_t(j)] = *translation;
        skeleton->joints.push_back(std::move(joint));
    }
    if (document.contains("moving_joints")) {
        if (!document["moving_joints"].is_array()) return reader.fail("\"moving_joints\"", "expected an array of joint indices");
        for (std::size_t k = 0; k < document["moving_joints"].size(); ++k) {
            const json& value = document["moving_joints"][k];
            if (!value.is_number_integer() || value.get<long long>() < 0 || value.get<long long>() >= count)
                return reader.fail("moving_joints[" + std::to_string(k) + "]", "expected a joint index from 0 to " + std::to_string(count - 1));
            motion.movingJoints.push_back(int(value.get<long long>()));
        }
    }
    if (document.contains("parts")) {
        if (!document["parts"].is_array()) return reader.fail("\"parts\"", "expected an array of part bindings");
        for (std::size_t p = 0; p < document["parts"].size(); ++p) {
            const json& entry = document["parts"][p];
            const std::string where = "parts[" + std::to_string(p) + "]";
            if (!entry.is_object() || !entry.contains("part") || !entry["part"].is_string())
                return reader.fail(where, "expected an object with a \"part\"");
            auto joint = reader.index(entry, "joint", where, 0, count);
            if (!joint) return joint.error();
            if (!entry.contains("joint_T_part") || !entry["joint_T_part"].is_object())
                return reader.fail(where, "missing \"joint_T_part\" {rotation, translation}");
            auto rotation = reader.rotation(entry["joint_T_part"], "rotation", where + ".joint_T_part");
            if (!rotation) return rotation.error();
            auto translation = reader.vector(entry["joint_T_part"], "translation", where + ".joint_T_part");
            if (!translation) return translation.error();
            skeleton->parts.push_back(PartBinding{entry["part"].get<std::string>(), *joint, RigidTransform{*rotation, *translation}});
        }
    }
    if (auto valid = validateSkeleton(*skeleton); !valid) return makeError(ErrorCode::Parse, reader.file + ": " + valid.error().message);
    return skeleton;
}

} // namespace

std::string skeletonJson(const Skeleton& skeleton, const std::vector<int>& movingJoints, const std::vector<Eigen::Vector3d>& staticTranslations)
{
    json joints = json::array();
    for (std::size_t j = 0; j < skeleton.joints.size(); ++j) {
        const SkeletonJoint& joint = skeleton.joints[j];
        json channels = json::array();
        for (JointChannel c : joint.channels) channels.push_back(kChannelNames[std::size_t(c)]);
        joints.push_back({{"name", joint.name},
                          {"parent", joint.parent},
                          {"offset", vector3(joint.offset)},
                          {"channels", channels},
                          {"end_site", joint.endSite},
                          {"translation", vector3(staticTranslations[j])}});
    }
    json parts = json::array();
    for (const PartBinding& b : skeleton.parts)
        parts.push_back({{"part", b.part},
                         {"joint", b.joint},
                         {"joint_name", skeleton.joints[std::size_t(b.joint)].name},
                         {"joint_T_part", {{"rotation", quaternion(b.joint_T_part.rotation)}, {"translation", vector3(b.joint_T_part.translation)}}}});
    const json document{{"format", kSkeletonFormatName},
                        {"version", kSkeletonFormatVersion},
                        {"name", skeleton.name},
                        {"units", {{"length", "cm"}, {"rotation", "unit quaternion w x y z"}}},
                        {"convention", "right-handed, z up, x towards the partner; cm"},
                        {"source", {{"up_axis", skeleton.source.upAxis},
                                    {"cm_per_unit", skeleton.source.cmPerUnit},
                                    {"world_R_source", quaternion(skeleton.source.world_R_source)}}},
                        {"position_mode", skeleton.positionMode == PositionChannelMode::ReplaceOffset ? "replace_offset" : "add_to_offset"},
                        {"joints", joints},
                        {"moving_joints", movingJoints},
                        {"parts", parts}};
    // Joint names are UTF-8 (the BVH reader refuses others); the skeleton's name comes from a file
    // name, which may not be: written with a replacement character rather than thrown.
    return document.dump(1, ' ', false, json::error_handler_t::replace) + "\n";
}

Result<std::pair<std::string, std::string>> formatSkeletalMotion(const SkeletalMotion& motion, double rateHz)
{
    if (auto valid = validateSkeletalMotion(motion); !valid) return valid.error();
    return std::pair{skeletonJson(*motion.skeleton, motion.movingJoints, motion.staticTranslations),
                     formatTakeCsv(motionTake(motion, rateHz))};
}

Status writeSkeletalMotion(const SkeletalMotion& motion, double rateHz, const fs::path& skeletonFile, const fs::path& motionFile)
{
    auto files = formatSkeletalMotion(motion, rateHz);
    if (!files) return makeError(files.error().code, skeletonFile.string() + ": " + files.error().message);
    if (auto written = writeFileAtomically(motionFile, files->second); !written) return written;
    return writeFileAtomically(skeletonFile, files->first);
}

Result<std::shared_ptr<const SkeletalMotion>> readSkeletalMotion(const fs::path& skeletonFile, const fs::path& motionFile, double rateHz)
{
    auto text = readTextFile(skeletonFile);
    if (!text) return text.error();
    const Reader reader{skeletonFile.string()};
    auto parsed = parseJsonText(*text, skeletonFile.string(), "invalid JSON");
    if (!parsed) return parsed.error();
    const json document = std::move(parsed).value();
    auto motion = std::make_shared<SkeletalMotion>();
    auto skeleton = parseSkeleton(document, reader, *motion);
    if (!skeleton) return skeleton.error();
    motion->skeleton = *skeleton;

    TakeCsvOptions csv;
    csv.rateHz = rateHz;
    auto table = readTakeCsv(motionFile, csv);
    if (!table) return table.error();
    const Take expected = motionTake(makeRestMotion(motion->skeleton, 0), rateHz);
    // The expected columns: translations of the moving joints, then every joint's rotation.
    std::vector<Channel> columns;
    for (int j : motion->movingJoints)
        for (const char* d : kTranslation) columns.push_back(Channel{columnPart(**skeleton, j), d, "cm"});
    for (const Channel& c : expected.channels) columns.push_back(c);
    if (table->channels.size() != columns.size())
        return makeError(ErrorCode::Parse, motionFile.string() + ":1: " + std::to_string(table->channels.size()) + " columns after time_s, " +
                                               skeletonFile.filename().string() + " needs " + std::to_string(columns.size()));
    for (std::size_t c = 0; c < columns.size(); ++c)
        if (table->channels[c].name() != columns[c].name())
            return makeError(ErrorCode::Parse, motionFile.string() + ":1: column " + std::to_string(c + 2) + " is " + table->channels[c].name() +
                                                   ", expected " + columns[c].name());
    const Eigen::Index frames = table->frameCount();
    const std::size_t slots = (*skeleton)->joints.size();
    motion->rotations.assign(std::size_t(frames) * slots, Eigen::Quaterniond::Identity());
    motion->movingTranslations.resize(frames, Eigen::Index(3 * motion->movingJoints.size()));
    for (Eigen::Index f = 0; f < frames; ++f) {
        Eigen::Index c = 0;
        for (std::size_t k = 0; k < motion->movingJoints.size(); ++k)
            for (int a = 0; a < 3; ++a) motion->movingTranslations(f, Eigen::Index(3 * k) + a) = table->values(f, c++);
        for (std::size_t j = 0; j < slots; ++j) {
            if ((*skeleton)->joints[j].endSite) continue;
            const Eigen::Quaterniond q(table->values(f, c), table->values(f, c + 1), table->values(f, c + 2), table->values(f, c + 3));
            c += 4;
            if (std::fabs(q.squaredNorm() - 1.0) > 1e-6)
                return makeError(ErrorCode::Parse, motionFile.string() + ": frame " + std::to_string(f) + ", joint '" +
                                                       (*skeleton)->joints[j].name + "': expected a unit quaternion");
            motion->rotation(f, int(j)) = q;
        }
    }
    if (auto valid = validateSkeletalMotion(*motion); !valid)
        return makeError(ErrorCode::Parse, skeletonFile.string() + ": " + valid.error().message);
    return std::shared_ptr<const SkeletalMotion>(std::move(motion));
}

} // namespace bunraku::analysis::io
