#pragma once
/// Small synthetic BVH files in the styles of the skeletons users bring (Bandai Namco, CMU's
/// ASF conversions and its DAZ/Poser version with face joints, Mixamo, the classic
/// Hips/Chest/Chest2 naming, Biovision, 3ds Max Biped, and variants in Z-up axes, metres and
/// other channel orders), written by the tests: one canonical 172 cm performer standing with
/// the arms down and waving the right hand, expressed in each family's names, hierarchy, rest
/// pose (T-pose, standing, or Bandai's bones along x), axes, unit and channel order.
#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace bunraku::test {

/// How a family's rest pose (all channels 0) relates to the standing pose of frame 0.
enum class RestStyle {
    Standing,   ///< the rest pose is the standing pose
    TPose,      ///< the arms stretch sideways at rest
    BoneAlongX, ///< every joint's x runs along its bone (Bandai): the rest pose lies on its side
};

struct FixtureJoint {
    std::string name;
    std::string parent;   ///< empty for the root
    std::string point;    ///< key of the canonical point where the joint sits
    std::string endPoint; ///< End Site at this point; "zero" for an End Site of length 0; empty: none
};

struct BvhFamily {
    std::string id;
    std::vector<FixtureJoint> joints;
    RestStyle rest = RestStyle::Standing;
    bool zUp = false;          ///< file axes: Z up, x forward (else Y up, facing +Z)
    double unitsPerCm = 1.0;   ///< 0.01 for metres
    std::string rootChannels = "Xposition Yposition Zposition Zrotation Xrotation Yrotation";
    std::string jointChannels = "Zrotation Xrotation Yrotation";
    bool sixChannelsEverywhere = false; ///< Bandai: every joint has its position channels (= its offset)
    /// The joints the automatic map must choose: head, shoulder, arm, hand (right side).
    std::array<std::string, 4> expected{};
    /// The left arm and hand (`--side left`).
    std::array<std::string, 2> expectedLeft{};
};

/// Canonical points of the standing performer, workbench axes (x forward, y left, z up), cm.
inline const std::map<std::string, Eigen::Vector3d>& canonicalPoints()
{
    static const std::map<std::string, Eigen::Vector3d> points = [] {
        std::map<std::string, Eigen::Vector3d> p{
            {"floor", {0, 0, 0}},        {"hips", {0, 0, 95}},       {"spine1", {-1, 0, 106}},  {"spine2", {-2, 0, 118}},
            {"spine3", {-2, 0, 130}},    {"neck", {-1, 0, 144}},     {"neck2", {0, 0, 150}},    {"head", {1, 0, 155}},
            {"headtop", {1, 0, 172}},    {"jaw", {7, 0, 151}},       {"eyeL", {9, 3.2, 161}},   {"eyeR", {9, -3.2, 161}},
        };
        for (const double side : {1.0, -1.0}) {
            const std::string s = side > 0 ? "L" : "R";
            p["collar" + s] = {1, side * 3, 141};
            p["shoulder" + s] = {-1, side * 18, 140};
            p["elbow" + s] = {-3, side * 21, 111};
            p["wrist" + s] = {2, side * 22, 86};
            p["hand" + s] = {3, side * 22, 82};
            p["index" + s] = {4, side * 22.5, 76};
            p["thumb" + s] = {6, side * 20, 80};
            p["tip" + s] = {5, side * 22, 68};
            p["hip" + s] = {0, side * 9, 91};
            p["knee" + s] = {3, side * 10, 50};
            p["ankle" + s] = {-1, side * 10, 8};
            p["toe" + s] = {13, side * 10, 2};
            p["toeEnd" + s] = {20, side * 10, 1};
        }
        return p;
    }();
    return points;
}

namespace fixture_detail {

inline std::string number(double value)
{
    if (std::fabs(value) < 1e-12) value = 0.0;
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

inline Eigen::Matrix3d axisRotation(char axis, double degrees)
{
    const double a = degrees * M_PI / 180.0;
    const Eigen::Vector3d unit = axis == 'X' ? Eigen::Vector3d::UnitX() : axis == 'Y' ? Eigen::Vector3d::UnitY() : Eigen::Vector3d::UnitZ();
    return Eigen::AngleAxisd(a, unit).toRotationMatrix();
}

/// Rotation axes of a channel list ("Zrotation Xrotation Yrotation" -> "ZXY").
inline std::string rotationOrder(const std::string& channels)
{
    std::string order;
    for (std::size_t i = 0; i + 8 < channels.size() + 1; ++i)
        if (channels.compare(i, 8, "rotation") == 0 && i > 0) order += channels[i - 1];
    return order;
}

/// Intrinsic angles (degrees) with R = R_a(alpha) R_b(beta) R_c(gamma) for the order "abc".
inline Eigen::Vector3d eulerAngles(const Eigen::Matrix3d& rotation, const std::string& order)
{
    const auto index = [](char c) { return c == 'X' ? 0 : c == 'Y' ? 1 : 2; };
    const Eigen::Vector3d angles = rotation.eulerAngles(index(order[0]), index(order[1]), index(order[2]));
    return angles * 180.0 / M_PI;
}

} // namespace fixture_detail

/// The BVH text of `family`: `frames` frames at 30 Hz; frame 0 is the canonical standing pose,
/// later frames raise the right forearm and wave it. `leftWave` waves the left arm instead.
inline std::string fixtureBvh(const BvhFamily& unordered, int frames = 12, bool leftWave = false)
{
    using namespace fixture_detail;
    // Depth-first order (a BVH lists each joint's subtree inside its braces), children in list order.
    BvhFamily family = unordered;
    family.joints.clear();
    std::vector<std::string> stack{unordered.joints.front().name};
    while (!stack.empty()) {
        const std::string name = stack.back();
        stack.pop_back();
        for (const auto& joint : unordered.joints)
            if (joint.name == name) family.joints.push_back(joint);
        for (auto it = unordered.joints.rbegin(); it != unordered.joints.rend(); ++it)
            if (it->parent == name) stack.push_back(it->name);
    }
    const auto& points = canonicalPoints();
    const std::size_t n = family.joints.size();
    std::map<std::string, int> index;
    for (std::size_t j = 0; j < n; ++j) index[family.joints[j].name] = int(j);
    std::vector<int> parent(n, -1);
    for (std::size_t j = 0; j < n; ++j)
        if (!family.joints[j].parent.empty()) parent[j] = index.at(family.joints[j].parent);
    const auto at = [&](std::size_t j) { return points.at(family.joints[j].point); };
    // The joint's main child: the first child (its bone).
    std::vector<int> mainChild(n, -1);
    for (std::size_t j = 0; j < n; ++j)
        if (parent[j] >= 0 && mainChild[std::size_t(parent[j])] < 0) mainChild[std::size_t(parent[j])] = int(j);
    const auto isArm = [&](std::size_t j) {
        const std::string& p = family.joints[j].point;
        return p.rfind("shoulder", 0) == 0 || p.rfind("elbow", 0) == 0 || p.rfind("wrist", 0) == 0 || p.rfind("hand", 0) == 0 ||
               p.rfind("index", 0) == 0 || p.rfind("thumb", 0) == 0 || p.rfind("tip", 0) == 0;
    };
    // World frames at frame 0 (workbench axes).
    std::vector<Eigen::Matrix3d> world(n, Eigen::Matrix3d::Identity());
    for (std::size_t j = 0; j < n; ++j) {
        if (family.rest == RestStyle::TPose && isArm(j)) {
            const double side = at(j).y() > 0 ? 1.0 : -1.0;
            world[j] = axisRotation('X', -side * 80.0); // the T-pose arm turned down to hang
        } else if (family.rest == RestStyle::BoneAlongX) {
            Eigen::Vector3d bone = mainChild[j] >= 0 ? Eigen::Vector3d(at(std::size_t(mainChild[j])) - at(j)) : Eigen::Vector3d::UnitZ();
            if (bone.norm() < 1e-9) bone = Eigen::Vector3d::UnitZ();
            const double side = at(j).y() < -1.0 ? -1.0 : 1.0; // right-side bones run along -x (Bandai)
            world[j] = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitX() * side, bone).toRotationMatrix();
        }
    }
    // file axes: Y up facing +Z: file (x, y, z) = world (y, z, x); Z up: the same axes.
    Eigen::Matrix3d fileFromWorld = Eigen::Matrix3d::Identity();
    if (!family.zUp) fileFromWorld << 0, 1, 0, 0, 0, 1, 1, 0, 0;
    const auto toFile = [&](const Eigen::Vector3d& v) { return Eigen::Vector3d(fileFromWorld * v * family.unitsPerCm); };
    const auto rotationToFile = [&](const Eigen::Matrix3d& r) { return Eigen::Matrix3d(fileFromWorld * r * fileFromWorld.transpose()); };

    std::vector<Eigen::Vector3d> offset(n);
    for (std::size_t j = 0; j < n; ++j)
        offset[j] = parent[j] >= 0 ? Eigen::Vector3d(world[std::size_t(parent[j])].transpose() * (at(j) - at(std::size_t(parent[j])))) : at(j);

    // Text of the hierarchy.
    std::string text = "HIERARCHY\n";
    std::vector<int> open;
    const auto closeTo = [&](int p) {
        while (!open.empty() && open.back() != p) {
            text += std::string(2 * (open.size() - 1), ' ') + "}\n";
            open.pop_back();
        }
    };
    const auto channelsOf = [&](std::size_t j) {
        if (parent[j] < 0) return family.rootChannels;
        return family.sixChannelsEverywhere ? "Xposition Yposition Zposition " + family.jointChannels : family.jointChannels;
    };
    for (std::size_t j = 0; j < n; ++j) {
        closeTo(parent[j]);
        const std::string indent(2 * open.size(), ' ');
        const Eigen::Vector3d o = toFile(offset[j]);
        text += indent + (parent[j] < 0 ? "ROOT " : "JOINT ") + family.joints[j].name + "\n" + indent + "{\n";
        text += indent + "  OFFSET " + number(o.x()) + " " + number(o.y()) + " " + number(o.z()) + "\n";
        const std::string channels = channelsOf(j);
        int names = 0;
        for (std::size_t i = 0; i < channels.size(); ++i)
            if ((i == 0 || channels[i - 1] == ' ') && channels[i] != ' ') ++names;
        text += indent + "  CHANNELS " + std::to_string(names) + " " + channels + "\n";
        if (!family.joints[j].endPoint.empty()) {
            const Eigen::Vector3d end = family.joints[j].endPoint == "zero"
                                            ? Eigen::Vector3d::Zero()
                                            : toFile(world[j].transpose() * (points.at(family.joints[j].endPoint) - at(j)));
            text += indent + "  End Site\n" + indent + "  {\n" + indent + "    OFFSET " + number(end.x()) + " " + number(end.y()) + " " +
                    number(end.z()) + "\n" + indent + "  }\n";
        }
        open.push_back(int(j));
    }
    closeTo(-1);
    text += "MOTION\nFrames: " + std::to_string(frames) + "\nFrame Time: 0.0333333\n";

    // Motion: the waving side's upper arm lifts sideways and the elbow bends.
    const std::string waveSide = leftWave ? "L" : "R";
    for (int f = 0; f < frames; ++f) {
        const double phase = double(f) / double(std::max(frames - 1, 1));
        std::vector<Eigen::Matrix3d> posed = world;
        // Extra world rotation of the waving arm's subtree, about its shoulder joint.
        const double outwards = leftWave ? 1.0 : -1.0; // about +x, positive turns towards +y (left)
        const Eigen::Matrix3d lift = axisRotation('X', outwards * 70.0 * phase);
        const Eigen::Matrix3d bend = axisRotation('Y', -60.0 * phase) * axisRotation('X', outwards * 20.0 * std::sin(6.0 * phase));
        std::vector<Eigen::Vector3d> position(n);
        for (std::size_t j = 0; j < n; ++j) {
            const std::string& p = family.joints[j].point;
            const bool upper = p == "shoulder" + waveSide;
            const bool lower = p == "elbow" + waveSide || p == "wrist" + waveSide || p == "hand" + waveSide || p == "index" + waveSide ||
                               p == "thumb" + waveSide || p == "tip" + waveSide;
            if (upper) posed[j] = lift * world[j];
            if (lower) posed[j] = lift * bend * world[j];
        }
        for (std::size_t j = 0; j < n; ++j) {
            if (parent[j] < 0) {
                position[j] = at(j) + Eigen::Vector3d(0.0, 2.0 * std::sin(3.0 * phase), 0.0);
                continue;
            }
            position[j] = position[std::size_t(parent[j])] + posed[std::size_t(parent[j])] * offset[j];
        }
        std::string row;
        for (std::size_t j = 0; j < n; ++j) {
            const Eigen::Matrix3d local = parent[j] >= 0 ? Eigen::Matrix3d(posed[std::size_t(parent[j])].transpose() * posed[j]) : posed[j];
            const bool root = parent[j] < 0;
            const std::string channels = channelsOf(j);
            if (root || family.sixChannelsEverywhere) {
                const Eigen::Vector3d t = toFile(root ? position[j] : offset[j]);
                row += number(t.x()) + " " + number(t.y()) + " " + number(t.z()) + " ";
            }
            const Eigen::Vector3d angles = eulerAngles(rotationToFile(local), rotationOrder(channels));
            row += number(angles.x()) + " " + number(angles.y()) + " " + number(angles.z()) + " ";
        }
        row.pop_back();
        text += row + "\n";
    }
    return text;
}

/// The families every import test covers.
inline std::vector<BvhFamily> bvhFamilies()
{
    std::vector<BvhFamily> families;
    const auto limbs = [](std::vector<FixtureJoint>& joints, const std::string& parent, const std::array<std::string, 4>& names,
                          const std::string& side, const std::string& end) {
        const std::array<std::string, 4> points{"collar" + side, "shoulder" + side, "elbow" + side, "wrist" + side};
        std::string p = parent;
        for (std::size_t k = 0; k < 4; ++k) {
            if (names[k].empty()) continue;
            joints.push_back({names[k], p, points[k], k == 3 ? end : ""});
            p = names[k];
        }
    };
    {
        BvhFamily f{"bandai", {}, RestStyle::BoneAlongX};
        f.rootChannels = f.jointChannels = "Xposition Yposition Zposition Zrotation Xrotation Yrotation";
        f.jointChannels = "Zrotation Xrotation Yrotation";
        f.sixChannelsEverywhere = true;
        f.joints = {{"joint_Root", "", "floor", ""}, {"Hips", "joint_Root", "hips", ""}, {"Spine", "Hips", "spine1", ""},
                    {"Chest", "Spine", "spine3", ""},  {"Neck", "Chest", "neck", ""},       {"Head", "Neck", "head", "zero"}};
        for (const std::string s : {"L", "R"}) {
            limbs(f.joints, "Chest", {"Shoulder_" + s, "UpperArm_" + s, "LowerArm_" + s, "Hand_" + s}, s, "zero");
            f.joints.push_back({"UpperLeg_" + s, "Hips", "hip" + s, ""});
            f.joints.push_back({"LowerLeg_" + s, "UpperLeg_" + s, "knee" + s, ""});
            f.joints.push_back({"Foot_" + s, "LowerLeg_" + s, "ankle" + s, ""});
            f.joints.push_back({"Toes_" + s, "Foot_" + s, "toe" + s, "zero"});
        }
        f.expected = {"Head", "Chest", "LowerArm_R", "Hand_R"};
        f.expectedLeft = {"LowerArm_L", "Hand_L"};
        families.push_back(f);
    }
    {
        BvhFamily f{"cmu-asf", {}, RestStyle::TPose};
        f.rootChannels = "Xposition Yposition Zposition Zrotation Yrotation Xrotation";
        f.jointChannels = "Zrotation Yrotation Xrotation";
        f.joints = {{"root", "", "hips", ""},
                    {"lowerback", "root", "spine1", ""}, {"upperback", "lowerback", "spine2", ""}, {"thorax", "upperback", "spine3", ""},
                    {"lowerneck", "thorax", "neck", ""}, {"upperneck", "lowerneck", "neck2", ""},  {"head", "upperneck", "head", "headtop"}};
        for (const std::string s : {"l", "r"}) {
            const std::string S = s == "l" ? "L" : "R";
            f.joints.push_back({s + "clavicle", "thorax", "collar" + S, ""});
            f.joints.push_back({s + "humerus", s + "clavicle", "shoulder" + S, ""});
            f.joints.push_back({s + "radius", s + "humerus", "elbow" + S, ""});
            f.joints.push_back({s + "wrist", s + "radius", "wrist" + S, ""});
            f.joints.push_back({s + "hand", s + "wrist", "hand" + S, ""});
            f.joints.push_back({s + "fingers", s + "hand", "index" + S, "tip" + S});
            f.joints.push_back({s + "thumb", s + "wrist", "thumb" + S, "zero"});
            f.joints.push_back({s + "hipjoint", "root", "hip" + S, ""});
            f.joints.push_back({s + "femur", s + "hipjoint", "knee" + S, ""});
            f.joints.push_back({s + "tibia", s + "femur", "ankle" + S, ""});
            f.joints.push_back({s + "foot", s + "tibia", "toe" + S, "toeEnd" + S});
        }
        f.expected = {"head", "thorax", "rradius", "rhand"};
        f.expectedLeft = {"lradius", "lhand"};
        families.push_back(f);
    }
    {
        BvhFamily f{"cmu-daz", {}, RestStyle::Standing};
        f.rootChannels = "Xposition Yposition Zposition Zrotation Xrotation Yrotation";
        f.jointChannels = "Zrotation Xrotation Yrotation";
        f.joints = {{"hip", "", "hips", ""},       {"abdomen", "hip", "spine1", ""}, {"chest", "abdomen", "spine3", ""},
                    {"neck", "chest", "neck", ""}, {"head", "neck", "head", "headtop"}, {"leye", "head", "eyeL", "zero"},
                    {"reye", "head", "eyeR", "zero"}, {"jaw", "head", "jaw", "zero"}};
        for (const std::string s : {"l", "r"}) {
            const std::string S = s == "l" ? "L" : "R";
            limbs(f.joints, "chest", {s + "collar", s + "shoulder", s + "elbow", s + "hand"}, S, "tip" + S);
            f.joints.push_back({s + "thigh", "hip", "hip" + S, ""});
            f.joints.push_back({s + "shin", s + "thigh", "knee" + S, ""});
            f.joints.push_back({s + "foot", s + "shin", "ankle" + S, "toe" + S});
        }
        f.expected = {"head", "chest", "relbow", "rhand"};
        f.expectedLeft = {"lelbow", "lhand"};
        families.push_back(f);
    }
    {
        BvhFamily f{"mixamo", {}, RestStyle::TPose};
        const std::string m = "mixamorig:";
        f.rootChannels = "Xposition Yposition Zposition Zrotation Xrotation Yrotation";
        f.jointChannels = "Zrotation Xrotation Yrotation";
        f.joints = {{m + "Hips", "", "hips", ""},           {m + "Spine", m + "Hips", "spine1", ""},  {m + "Spine1", m + "Spine", "spine2", ""},
                    {m + "Spine2", m + "Spine1", "spine3", ""}, {m + "Neck", m + "Spine2", "neck", ""}, {m + "Head", m + "Neck", "head", ""},
                    {m + "HeadTop_End", m + "Head", "headtop", "zero"}};
        for (const std::string s : {"Left", "Right"}) {
            const std::string S = s == "Left" ? "L" : "R";
            limbs(f.joints, m + "Spine2", {m + s + "Shoulder", m + s + "Arm", m + s + "ForeArm", m + s + "Hand"}, S, "");
            f.joints.push_back({m + s + "HandIndex1", m + s + "Hand", "index" + S, "tip" + S});
            f.joints.push_back({m + s + "HandThumb1", m + s + "Hand", "thumb" + S, "zero"});
            f.joints.push_back({m + s + "UpLeg", m + "Hips", "hip" + S, ""});
            f.joints.push_back({m + s + "Leg", m + s + "UpLeg", "knee" + S, ""});
            f.joints.push_back({m + s + "Foot", m + s + "Leg", "ankle" + S, ""});
            f.joints.push_back({m + s + "ToeBase", m + s + "Foot", "toe" + S, "toeEnd" + S});
        }
        f.expected = {m + "Head", m + "Spine2", m + "RightForeArm", m + "RightHand"};
        f.expectedLeft = {m + "LeftForeArm", m + "LeftHand"};
        families.push_back(f);
    }
    {
        BvhFamily f{"classic", {}, RestStyle::TPose};
        f.rootChannels = "Xposition Yposition Zposition Zrotation Xrotation Yrotation";
        f.jointChannels = "Zrotation Xrotation Yrotation";
        f.joints = {{"Hips", "", "hips", ""}, {"Chest", "Hips", "spine1", ""}, {"Chest2", "Chest", "spine3", ""}};
        for (const std::string s : {"Left", "Right"}) {
            const std::string S = s == "Left" ? "L" : "R";
            limbs(f.joints, "Chest2", {s + "Collar", s + "Shoulder", s + "Elbow", s + "Wrist"}, S, "tip" + S);
        }
        f.joints.push_back({"Neck", "Chest2", "neck", ""});
        f.joints.push_back({"Head", "Neck", "head", "headtop"});
        for (const std::string s : {"Left", "Right"}) {
            const std::string S = s == "Left" ? "L" : "R";
            f.joints.push_back({s + "Hip", "Hips", "hip" + S, ""});
            f.joints.push_back({s + "Knee", s + "Hip", "knee" + S, ""});
            f.joints.push_back({s + "Ankle", s + "Knee", "ankle" + S, "toe" + S});
        }
        f.expected = {"Head", "Chest2", "RightElbow", "RightWrist"};
        f.expectedLeft = {"LeftElbow", "LeftWrist"};
        families.push_back(f);
    }
    {
        BvhFamily f{"biovision", {}, RestStyle::Standing};
        f.rootChannels = "Xposition Yposition Zposition Zrotation Xrotation Yrotation";
        f.jointChannels = "Zrotation Xrotation Yrotation";
        f.joints = {{"Hips", "", "hips", ""}, {"Chest", "Hips", "spine2", ""}, {"Neck", "Chest", "neck", ""}, {"Head", "Neck", "head", "headtop"}};
        for (const std::string s : {"Left", "Right"}) {
            const std::string S = s == "Left" ? "L" : "R";
            limbs(f.joints, "Chest", {s + "Collar", s + "UpArm", s + "LowArm", s + "Hand"}, S, "tip" + S);
            f.joints.push_back({s + "UpLeg", "Hips", "hip" + S, ""});
            f.joints.push_back({s + "LowLeg", s + "UpLeg", "knee" + S, ""});
            f.joints.push_back({s + "Foot", s + "LowLeg", "ankle" + S, "toe" + S});
        }
        f.expected = {"Head", "Chest", "RightLowArm", "RightHand"};
        f.expectedLeft = {"LeftLowArm", "LeftHand"};
        families.push_back(f);
    }
    {
        BvhFamily f{"biped", {}, RestStyle::Standing};
        f.zUp = true;
        f.rootChannels = "Xposition Yposition Zposition Zrotation Yrotation Xrotation";
        f.jointChannels = "Zrotation Yrotation Xrotation";
        f.joints = {{"Bip01", "", "hips", ""},
                    {"Bip01 Pelvis", "Bip01", "spine1", ""},
                    {"Bip01 Spine", "Bip01 Pelvis", "spine2", ""},
                    {"Bip01 Spine1", "Bip01 Spine", "spine3", ""},
                    {"Bip01 Neck", "Bip01 Spine1", "neck", ""},
                    {"Bip01 Head", "Bip01 Neck", "head", "headtop"}};
        for (const std::string s : {"L", "R"}) {
            limbs(f.joints, "Bip01 Neck", {"Bip01 " + s + " Clavicle", "Bip01 " + s + " UpperArm", "Bip01 " + s + " Forearm", "Bip01 " + s + " Hand"}, s, "");
            f.joints.push_back({"Bip01 " + s + " Finger0", "Bip01 " + s + " Hand", "index" + s, "tip" + s});
            f.joints.push_back({"Bip01 " + s + " Thigh", "Bip01 Spine", "hip" + s, ""});
            f.joints.push_back({"Bip01 " + s + " Calf", "Bip01 " + s + " Thigh", "knee" + s, ""});
            f.joints.push_back({"Bip01 " + s + " Foot", "Bip01 " + s + " Calf", "ankle" + s, ""});
            f.joints.push_back({"Bip01 " + s + " Toe0", "Bip01 " + s + " Foot", "toe" + s, "toeEnd" + s});
        }
        f.expected = {"Bip01 Head", "Bip01 Neck", "Bip01 R Forearm", "Bip01 R Hand"};
        f.expectedLeft = {"Bip01 L Forearm", "Bip01 L Hand"};
        families.push_back(f);
    }
    // Variants: axes, units and channel orders.
    for (const auto& base : std::vector<BvhFamily>(families)) {
        if (base.id == "mixamo") {
            BvhFamily f = base;
            f.id = "mixamo-z-up";
            f.zUp = true;
            families.push_back(f);
        }
        if (base.id == "classic") {
            BvhFamily f = base;
            f.id = "classic-metres";
            f.unitsPerCm = 0.01;
            families.push_back(f);
        }
        if (base.id == "biovision") {
            BvhFamily f = base;
            f.id = "biovision-xyz";
            f.rootChannels = "Xposition Yposition Zposition Xrotation Yrotation Zrotation";
            f.jointChannels = "Xrotation Yrotation Zrotation";
            families.push_back(f);
        }
        if (base.id == "cmu-daz") {
            BvhFamily f = base;
            f.id = "cmu-daz-yxz";
            f.rootChannels = "Xposition Yposition Zposition Yrotation Xrotation Zrotation";
            f.jointChannels = "Yrotation Xrotation Zrotation";
            families.push_back(f);
        }
        if (base.id == "mixamo") {
            // Names that say nothing: the topology alone must find the parts.
            BvhFamily f = base;
            f.id = "unnamed";
            std::map<std::string, std::string> rename;
            for (std::size_t j = 0; j < f.joints.size(); ++j) rename[f.joints[j].name] = std::string("j").append(std::to_string(j));
            for (auto& joint : f.joints) {
                joint.name = rename[joint.name];
                if (!joint.parent.empty()) joint.parent = rename[joint.parent];
            }
            for (auto& e : f.expected) e = rename[e];
            for (auto& e : f.expectedLeft) e = rename[e];
            families.push_back(f);
        }
    }
    return families;
}

} // namespace bunraku::test
