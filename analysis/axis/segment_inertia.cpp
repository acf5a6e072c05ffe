#include "analysis/axis/segment_inertia.h"

#include "analysis/body/body_pose.h"
#include "analysis/core/puppet_layout.h"
#include "analysis/core/skeleton.h"
#include "analysis/io/bvh_joint_map.h"
#include "analysis/normalise/skeleton_chains.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <map>

namespace bunraku::analysis {

namespace {

// de Leva (1996), Table 4: mass %, centre of mass % from the proximal end, radii of gyration %
// (sagittal, transverse, longitudinal), and the sample's mean length (mm in the paper, cm here).
// Rows in SegmentKind order; the head is VERT-CERV, the trunk CERV-MIDH, the shank KJC-AJC.
constexpr std::array<SegmentParameters, 8> kMale{{
    {0.0694, 0.5002, 0.303, 0.315, 0.261, 24.29}, // head (vertex to C7)
    {0.4346, 0.5138, 0.328, 0.306, 0.169, 60.33}, // trunk (C7 to the hip joints' midpoint)
    {0.0271, 0.5772, 0.285, 0.269, 0.158, 28.17}, // upper arm
    {0.0162, 0.4574, 0.276, 0.265, 0.121, 26.89}, // forearm
    {0.0061, 0.7900, 0.628, 0.513, 0.401, 8.62},  // hand (wrist to the 3rd metacarpal)
    {0.1416, 0.4095, 0.329, 0.329, 0.149, 42.22}, // thigh
    {0.0433, 0.4395, 0.251, 0.246, 0.102, 44.03}, // shank (knee to ankle joint centre)
    {0.0137, 0.4415, 0.257, 0.245, 0.124, 25.81}, // foot (heel to toe tip)
}};
constexpr std::array<SegmentParameters, 8> kFemale{{
    {0.0668, 0.4841, 0.271, 0.295, 0.261, 24.37},
    {0.4257, 0.4964, 0.307, 0.292, 0.147, 61.48},
    {0.0255, 0.5754, 0.278, 0.260, 0.148, 27.51},
    {0.0138, 0.4559, 0.261, 0.257, 0.094, 26.43},
    {0.0056, 0.7474, 0.531, 0.454, 0.335, 7.80},
    {0.1478, 0.3612, 0.369, 0.364, 0.162, 36.85},
    {0.0481, 0.4352, 0.267, 0.263, 0.092, 43.86},
    {0.0129, 0.4014, 0.299, 0.279, 0.139, 22.83},
}};

/// Joints closer than this to the previous station of a limb are one station with it (cm).
constexpr double kSameStation = 0.5;

bool isHelperJoint(const std::string& name)
{
    const std::string term = io::jointNameInfo(name).term;
    return term.find("roll") != std::string::npos || term.find("twist") != std::string::npos;
}

struct Geometry {
    const Skeleton& skeleton;
    std::vector<RigidTransform> world; ///< world_T_joint at the first frame, End Sites included
    std::vector<int> size;             ///< joints and End Sites in each subtree

    Geometry(const SkeletalMotion& motion) : skeleton(*motion.skeleton), world(motion.worldPoses(0)), size(skeleton.joints.size(), 1)
    {
        for (std::size_t j = skeleton.joints.size(); j-- > 0;)
            if (skeleton.joints[j].parent >= 0) size[std::size_t(skeleton.joints[j].parent)] += size[j];
    }
    Eigen::Vector3d at(int joint) const { return world[std::size_t(joint)].translation; }
};

/// A limb's line from its first joint: at each joint the child (End Sites included) with the
/// most below it, the farther one of a tie.
std::vector<int> mainPath(const Geometry& g, int first)
{
    std::vector<int> path{first};
    for (;;) {
        const int current = path.back();
        int best = -1;
        for (int child : g.skeleton.children(current)) {
            if (best < 0) {
                best = child;
                continue;
            }
            const int a = g.size[std::size_t(child)], b = g.size[std::size_t(best)];
            if (a > b || (a == b && (g.at(child) - g.at(current)).norm() > (g.at(best) - g.at(current)).norm())) best = child;
        }
        if (best < 0) return path;
        path.push_back(best);
    }
}

/// Stations of a limb: points of its main path more than kSameStation apart, helpers (roll,
/// twist) left out; each station's joint is the last joint at it (the one whose bone leaves it).
struct Station {
    Eigen::Vector3d point;
    int joint = -1;
};
std::vector<Station> stations(const Geometry& g, const std::vector<int>& path)
{
    std::vector<Station> result;
    for (int j : path) {
        const SkeletonJoint& joint = g.skeleton.joints[std::size_t(j)];
        if (!joint.endSite && isHelperJoint(joint.name) && j != path.front()) continue;
        const Eigen::Vector3d p = g.at(j);
        if (!result.empty() && (p - result.back().point).norm() < kSameStation) {
            if (!joint.endSite) result.back().joint = j;
            continue;
        }
        result.push_back({p, joint.endSite ? -1 : j});
    }
    return result;
}

/// The two consecutive bones of the largest summed length: the index of their first station.
std::optional<std::size_t> longBonePair(const std::vector<Station>& s)
{
    std::optional<std::size_t> best;
    double longest = 0.0;
    for (std::size_t i = 0; i + 2 < s.size(); ++i) {
        if (s[i].joint < 0 || s[i + 1].joint < 0) continue;
        const double sum = (s[i + 1].point - s[i].point).norm() + (s[i + 2].point - s[i + 1].point).norm();
        if (sum > longest) {
            longest = sum;
            best = i;
        }
    }
    return best;
}

Eigen::Vector3d closestOnSegment(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
    const Eigen::Vector3d d = b - a;
    const double t = d.squaredNorm() > 1e-12 ? std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
    return a + t * d;
}

/// A point mass in the world at the first frame and the joint that carries it.
struct WorldPoint {
    Eigen::Vector3d position;
    double mass = 0.0;
    int joint = -1;
};

} // namespace

const char* segmentTableName(SegmentTable table) { return table == SegmentTable::DeLevaFemale ? "female" : "male"; }

std::optional<SegmentTable> segmentTableFromName(std::string_view name)
{
    if (name == "male") return SegmentTable::DeLevaMale;
    if (name == "female") return SegmentTable::DeLevaFemale;
    return std::nullopt;
}

const char* segmentKindName(SegmentKind kind)
{
    switch (kind) {
    case SegmentKind::Head: return "head";
    case SegmentKind::Trunk: return "trunk";
    case SegmentKind::UpperArm: return "upper_arm";
    case SegmentKind::Forearm: return "forearm";
    case SegmentKind::Hand: return "hand";
    case SegmentKind::Thigh: return "thigh";
    case SegmentKind::Shank: return "shank";
    case SegmentKind::Foot: return "foot";
    }
    return "trunk";
}

const SegmentParameters& segmentParameters(SegmentTable table, SegmentKind kind)
{
    return (table == SegmentTable::DeLevaFemale ? kFemale : kMale)[std::size_t(kind)];
}

double segmentTableBodyMassKg(SegmentTable table) { return table == SegmentTable::DeLevaFemale ? 61.9 : 73.0; }

bool usesSegmentModel(const Take& take)
{
    if (!take.skeleton || !take.skeleton->skeleton) return false;
    const auto parts = sixDofParts(take);
    for (const auto puppet : kPuppetParts)
        if (std::none_of(parts.begin(), parts.end(), [&](const SixDofPart& p) { return p.part == puppet; })) return true;
    return false;
}

Result<SegmentBody> segmentBody(const Take& take, const SegmentModelOptions& options)
{
    const std::string name = "whole-body axis of " + take.displayName();
    if (!take.skeleton || !take.skeleton->skeleton || take.skeleton->frameCount() < 1)
        return makeError(ErrorCode::InvalidArgument, name + ": the take has no skeleton (the segments are found on one)");
    const SkeletalMotion& motion = *take.skeleton;
    const Geometry g(motion);
    const Skeleton& skeleton = g.skeleton;
    auto chains = skeletonChains(motion);
    if (!chains) return makeError(ErrorCode::InvalidArgument, name + ": " + chains.error().message);
    const SkeletonChain* root = nullptr;
    const SkeletonChain* spine = nullptr;
    std::vector<const SkeletonChain*> arms, legs;
    for (const SkeletonChain& chain : *chains) {
        if (chain.joints.empty()) continue;
        if (chain.name == "root" && !root) root = &chain;
        else if (chain.name == "spine" && !spine) spine = &chain;
        else if (chain.name.find("arm") != std::string::npos) arms.push_back(&chain);
        else if (chain.name.find("leg") != std::string::npos) legs.push_back(&chain);
    }
    if (!root || !spine)
        return makeError(ErrorCode::InvalidArgument, name + ": no spine was found in the skeleton " + skeleton.name +
                                                         " (the trunk and head segments lie on it)");

    const SegmentModelOptions& o = options;
    const auto params = [&](SegmentKind kind) -> const SegmentParameters& { return segmentParameters(o.table, kind); };
    // The table's fractions of a whole body (head, trunk, two of each limb segment) add up to
    // 100 % but for rounding (99.99 % for the women): scaled so the body weighs its mass.
    double fractions = params(SegmentKind::Head).massFraction + params(SegmentKind::Trunk).massFraction;
    for (const SegmentKind kind : {SegmentKind::UpperArm, SegmentKind::Forearm, SegmentKind::Hand, SegmentKind::Thigh, SegmentKind::Shank,
                                   SegmentKind::Foot})
        fractions += 2.0 * params(kind).massFraction;
    const double bodyMass = 1000.0 * (o.bodyMassKg > 0.0 ? o.bodyMassKg : segmentTableBodyMassKg(o.table)) / fractions; // g per unit fraction

    // The limbs: stations along each main line, the long bone pair.
    struct LimbLine {
        const SkeletonChain* chain = nullptr;
        std::vector<Station> stations;
        std::size_t first = 0; ///< the proximal station of the long pair
        std::vector<int> path;
    };
    const auto limbLine = [&](const SkeletonChain* chain, const char* what) -> Result<LimbLine> {
        LimbLine line;
        line.chain = chain;
        line.path = mainPath(g, chain->joints.front());
        line.stations = stations(g, line.path);
        const auto pair = longBonePair(line.stations);
        if (!pair)
            return makeError(ErrorCode::InvalidArgument, name + ": the " + chain->name + " chain of " + skeleton.name + " has " +
                                                             std::to_string(line.stations.size()) + " joint centres in line; the " + what +
                                                             " segments need three (two bones)");
        line.first = *pair;
        return line;
    };
    std::vector<LimbLine> armLines, legLines;
    for (const SkeletonChain* chain : arms) {
        auto line = limbLine(chain, "upper arm and forearm");
        if (!line) return line.error();
        armLines.push_back(std::move(line).value());
    }
    for (const SkeletonChain* chain : legs) {
        auto line = limbLine(chain, "thigh and shank");
        if (!line) return line.error();
        legLines.push_back(std::move(line).value());
    }

    // The spine's line: the pelvis (the root chain's last joint) up to the head.
    const int pelvis = root->joints.back();
    int head = -1;
    if (const PartBinding* binding = skeleton.binding("head"); binding && binding->joint >= 0) head = binding->joint;
    for (int j : spine->joints)
        if (head < 0 && io::jointNameInfo(skeleton.joints[std::size_t(j)].name).term == "head") head = j;
    if (head < 0 || std::find(spine->joints.begin(), spine->joints.end(), head) == spine->joints.end()) {
        // The highest joint of the spine's line.
        const std::vector<int> path = mainPath(g, spine->joints.front());
        head = -1;
        for (int j : path)
            if (!skeleton.joints[std::size_t(j)].endSite && (head < 0 || g.at(j).z() > g.at(head).z())) head = j;
    }
    std::vector<int> spineLine;
    for (int j = head; j >= 0; j = skeleton.joints[std::size_t(j)].parent) {
        spineLine.push_back(j);
        if (j == pelvis) break;
    }
    std::reverse(spineLine.begin(), spineLine.end());
    if (spineLine.front() != pelvis)
        return makeError(ErrorCode::InvalidArgument, name + ": the head joint " + skeleton.joints[std::size_t(head)].name +
                                                         " of " + skeleton.name + " is not above the pelvis " +
                                                         skeleton.joints[std::size_t(pelvis)].name);

    // Landmarks.
    const Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
    const auto mean = [](const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& fallback) {
        if (points.empty()) return fallback;
        Eigen::Vector3d sum = Eigen::Vector3d::Zero();
        for (const auto& p : points) sum += p;
        return Eigen::Vector3d(sum / double(points.size()));
    };
    std::vector<Eigen::Vector3d> hips, shoulders;
    for (const LimbLine& line : legLines) hips.push_back(line.stations[line.first].point);
    for (const LimbLine& line : armLines) shoulders.push_back(line.stations[line.first].point);
    const Eigen::Vector3d midHip = mean(hips, g.at(pelvis));
    // Left: the left limbs' joints minus the right ones' (legs, else arms), across `up`.
    Eigen::Vector3d left = Eigen::Vector3d::Zero();
    for (const auto* lines : {&legLines, &armLines}) {
        if (!left.isZero()) break;
        for (const LimbLine& line : *lines) {
            const double side = line.chain->name.rfind("left", 0) == 0 ? 1.0 : line.chain->name.rfind("right", 0) == 0 ? -1.0 : 0.0;
            left += side * line.stations[line.first].point;
        }
    }
    left -= left.dot(up) * up;
    left = left.norm() > 1e-6 ? Eigen::Vector3d(left.normalized()) : Eigen::Vector3d::UnitY();
    const Eigen::Vector3d forward = left.cross(up);

    // C7: the point of the spine's line nearest the shoulders' midpoint (the spine's top joint
    // below the head without arms).
    std::vector<Eigen::Vector3d> spinePoints;
    for (int j : spineLine) spinePoints.push_back(g.at(j));
    Eigen::Vector3d c7 = spineLine.size() > 1 ? spinePoints[spinePoints.size() - 2] : spinePoints.back();
    if (!shoulders.empty()) {
        const Eigen::Vector3d target = mean(shoulders, c7);
        double nearest = std::numeric_limits<double>::infinity();
        for (std::size_t k = 0; k + 1 < spinePoints.size(); ++k) {
            const Eigen::Vector3d p = closestOnSegment(target, spinePoints[k], spinePoints[k + 1]);
            if ((p - target).norm() < nearest) {
                nearest = (p - target).norm();
                c7 = p;
            }
        }
    }
    const double trunkLength = (c7 - midHip).norm();
    if (trunkLength < 1e-3)
        return makeError(ErrorCode::InvalidArgument, name + ": the trunk of " + skeleton.name + " has no length (C7 at the hips)");
    // The vertex: the farthest point the head carries along C7 -> head, else the table's head : trunk.
    const Eigen::Vector3d towardsHead = (g.at(head) - c7).norm() > 1e-6 ? Eigen::Vector3d((g.at(head) - c7).normalized())
                                                                        : Eigen::Vector3d((c7 - midHip).normalized());
    double reach = (g.at(head) - c7).dot(towardsHead);
    for (std::size_t j = std::size_t(head) + 1; j < skeleton.joints.size(); ++j) {
        int a = int(j);
        while (a >= 0 && a != head) a = skeleton.joints[std::size_t(a)].parent;
        if (a == head) reach = std::max(reach, (g.at(int(j)) - c7).dot(towardsHead));
    }
    const double headEstimate = trunkLength * params(SegmentKind::Head).lengthCm / params(SegmentKind::Trunk).lengthCm;
    const bool vertexEstimated = reach < 0.6 * headEstimate;
    const Eigen::Vector3d vertex = c7 + (vertexEstimated ? headEstimate : reach) * towardsHead;

    // The segments and their six points each.
    SegmentBody result;
    std::vector<WorldPoint> points;
    // Points on the spine's line go to the joint whose bone is nearest; the line runs on to the vertex.
    std::vector<Eigen::Vector3d> spineBones = spinePoints;
    spineBones.push_back(vertex);
    const auto spineCarrier = [&](const Eigen::Vector3d& p) {
        double nearest = std::numeric_limits<double>::infinity();
        int joint = spineLine.front();
        for (std::size_t k = 0; k + 1 < spineBones.size(); ++k) {
            const double d = (closestOnSegment(p, spineBones[k], spineBones[k + 1]) - p).norm();
            if (d < nearest - 1e-9) {
                nearest = d;
                joint = spineLine[std::min(k, spineLine.size() - 1)];
            }
        }
        return joint;
    };
    const auto addSegment = [&](SegmentKind kind, const std::string& chain, const Eigen::Vector3d& proximal, const Eigen::Vector3d& distal,
                                bool estimated, const std::function<int(const Eigen::Vector3d&)>& carrier) {
        const SegmentParameters& p = params(kind);
        BodySegment segment;
        segment.kind = kind;
        segment.chain = chain;
        segment.proximal = proximal;
        segment.distal = distal;
        segment.distalEstimated = estimated;
        segment.mass = p.massFraction * bodyMass;
        const double length = (distal - proximal).norm();
        const Eigen::Vector3d along = length > 1e-9 ? Eigen::Vector3d((distal - proximal) / length) : Eigen::Vector3d(-up);
        Eigen::Vector3d across = left - left.dot(along) * along; // the transverse (left-right) axis
        across = across.norm() > 1e-6 ? Eigen::Vector3d(across.normalized()) : along.unitOrthogonal();
        const Eigen::Vector3d sagittal = across.cross(along); // in the sagittal plane, across the segment
        segment.centre = proximal + p.centreFraction * (distal - proximal);
        // Principal moments m (r L)^2 about sagittal, transverse, longitudinal; the variances of
        // the mass along each axis follow: I_a = m (v_b + v_c).
        const double is = std::pow(p.radiusSagittal * length, 2), it = std::pow(p.radiusTransverse * length, 2),
                     il = std::pow(p.radiusLongitudinal * length, 2);
        const double vSagittal = std::max(0.0, 0.5 * (it + il - is)), vAcross = std::max(0.0, 0.5 * (is + il - it)),
                     vAlong = std::max(0.0, 0.5 * (is + it - il));
        Eigen::Matrix3d axes;
        axes << sagittal, across, along;
        segment.inertia = segment.mass * axes * Eigen::Vector3d(is, it, il).asDiagonal() * axes.transpose();
        const std::array<std::pair<Eigen::Vector3d, double>, 3> spread{
            {{sagittal, std::sqrt(3.0 * vSagittal)}, {across, std::sqrt(3.0 * vAcross)}, {along, std::sqrt(3.0 * vAlong)}}};
        for (const auto& [axis, offset] : spread)
            for (const double sign : {1.0, -1.0}) {
                const Eigen::Vector3d position = segment.centre + sign * offset * axis;
                const int joint = carrier(position);
                points.push_back({position, segment.mass / 6.0, joint});
                const std::string& jointName = skeleton.joints[std::size_t(joint)].name;
                if (std::find(segment.joints.begin(), segment.joints.end(), jointName) == segment.joints.end())
                    segment.joints.push_back(jointName);
            }
        result.segments.push_back(std::move(segment));
    };
    addSegment(SegmentKind::Head, spine->name, vertex, c7, vertexEstimated, spineCarrier);
    addSegment(SegmentKind::Trunk, spine->name, c7, midHip, false, spineCarrier);
    const auto limbSegments = [&](const LimbLine& line, SegmentKind upper, SegmentKind lower, SegmentKind end) {
        const std::vector<Station>& s = line.stations;
        const std::size_t i = line.first;
        const auto carriedBy = [](int joint) { return [joint](const Eigen::Vector3d&) { return joint; }; };
        addSegment(upper, line.chain->name, s[i].point, s[i + 1].point, false, carriedBy(s[i].joint));
        addSegment(lower, line.chain->name, s[i + 1].point, s[i + 2].point, false, carriedBy(s[i + 1].joint));
        // The end segment (hand, foot) from the third station: along the line beyond it when it
        // goes on, else along the lower bone (the hand) or forwards (the foot).
        const Eigen::Vector3d base = s[i + 2].point;
        const Eigen::Vector3d lowerBone = s[i + 2].point - s[i + 1].point;
        double beyond = 0.0;
        Eigen::Vector3d direction = end == SegmentKind::Foot ? forward : Eigen::Vector3d(lowerBone.normalized());
        for (std::size_t k = i + 3; k < s.size(); ++k)
            if ((s[k].point - base).norm() > beyond) {
                beyond = (s[k].point - base).norm();
                direction = (s[k].point - base) / beyond;
            }
        const double ratio = params(end).lengthCm / params(lower).lengthCm;
        const bool estimated = end == SegmentKind::Hand || beyond < 0.3 * ratio * lowerBone.norm();
        const double length = estimated ? ratio * lowerBone.norm() : beyond;
        const int carrier = s[i + 2].joint >= 0 ? s[i + 2].joint : s[i + 1].joint;
        addSegment(end, line.chain->name, base, base + length * direction, estimated, carriedBy(carrier));
    };
    for (const LimbLine& line : armLines) limbSegments(line, SegmentKind::UpperArm, SegmentKind::Forearm, SegmentKind::Hand);
    for (const LimbLine& line : legLines) limbSegments(line, SegmentKind::Thigh, SegmentKind::Shank, SegmentKind::Foot);

    // Per joint: its points in its own frame, reduced to moments; the joint must be a part of the take.
    std::map<int, std::vector<const WorldPoint*>> byJoint;
    for (const WorldPoint& point : points) byJoint[point.joint].push_back(&point);
    AxisModel& model = result.model;
    model.body.name = std::string("de Leva (1996) ") + segmentTableName(o.table) + " segments on " + skeleton.name;
    model.body.source = "the skeleton of " + take.displayName();
    model.massSource = MassSource::Segments;
    const auto parts = sixDofParts(take);
    const auto hasPart = [&](const std::string& part) {
        return std::any_of(parts.begin(), parts.end(), [&](const SixDofPart& p) { return p.part == part; });
    };
    for (const auto& [joint, jointPoints] : byJoint) {
        const std::string& jointName = skeleton.joints[std::size_t(joint)].name;
        if (!hasPart(jointName))
            return makeError(ErrorCode::NotFound, name + ": the take has no 6 channels " + jointName + ".x..roll for the joint that carries " +
                                                      "a body segment (import with every joint: --all-joints)");
        MassPoints local;
        local.positions.resize(3, Eigen::Index(jointPoints.size()));
        local.masses.resize(Eigen::Index(jointPoints.size()));
        const RigidTransform joint_T_world = g.world[std::size_t(joint)].inverse();
        for (std::size_t k = 0; k < jointPoints.size(); ++k) {
            local.positions.col(Eigen::Index(k)) = joint_T_world.apply(jointPoints[k]->position);
            local.masses[Eigen::Index(k)] = jointPoints[k]->mass;
        }
        BodyPart part;
        part.name = jointName;
        part.drivenBy = jointName;
        model.body.parts.push_back(part);
        model.parts.push_back(partMoments(local));
        model.totalMass += model.parts.back().mass;
    }
    // The facing: forward in the frame of the joint the arms branch from (else the pelvis).
    int facing = pelvis;
    if (!armLines.empty()) {
        const int branch = skeleton.joints[std::size_t(armLines.front().chain->joints.front())].parent;
        if (branch >= 0 && hasPart(skeleton.joints[std::size_t(branch)].name)) facing = branch;
    }
    model.body.mirrorFramePart = skeleton.joints[std::size_t(facing)].name;
    model.facing = g.world[std::size_t(facing)].rotation.conjugate() * forward;
    return result;
}

} // namespace bunraku::analysis
