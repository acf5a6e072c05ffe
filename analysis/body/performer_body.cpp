#include "analysis/body/performer_body.h"

#include "analysis/body/surface_nets.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <limits>
#include <string>

namespace bunraku::analysis {

namespace {

/// One piece of the mannequin: a capsule from a to b (a sphere when a == b), moving with `joint`.
struct Segment {
    Eigen::Vector3f a, b;
    float radius = 1.0f;
    int joint = 0;
};

float segmentDistance(const Segment& s, const Eigen::Vector3f& p)
{
    const Eigen::Vector3f ab = s.b - s.a;
    const float length2 = ab.squaredNorm();
    const float t = length2 > 0.0f ? std::clamp((p - s.a).dot(ab) / length2, 0.0f, 1.0f) : 0.0f;
    return (p - (s.a + t * ab)).norm();
}

/// Polynomial smooth minimum (blend radius k): the union of two distance fields with a fillet.
float smoothMin(float a, float b, float k)
{
    const float h = std::max(k - std::abs(a - b), 0.0f) / k;
    return std::min(a, b) - h * h * k * 0.25f;
}

bool nameHasHead(const std::string& name)
{
    std::string lower(name);
    std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return lower.find("head") != std::string::npos && lower.find("end") == std::string::npos;
}

} // namespace

Result<PerformerBody> performerBody(const SkeletalMotion& motion)
{
    if (!motion.skeleton) return makeError(ErrorCode::InvalidArgument, "the motion has no skeleton");
    const Skeleton& skeleton = *motion.skeleton;
    const int count = int(skeleton.joints.size());
    if (count > kMaxBodyJoints)
        return makeError(ErrorCode::Unsupported, "a body is made for at most " + std::to_string(kMaxBodyJoints) + " joints; the skeleton has " +
                                                     std::to_string(count));
    if (count == 0 || motion.staticTranslations.size() != std::size_t(count))
        return makeError(ErrorCode::InvalidArgument, "the skeleton has no joints");

    // The pose the body is built in: the take's first frame, with each arm turned about its
    // upper arm to hang 40 deg below the horizontal away from the trunk and each leg about its
    // thigh to point down, so that no limb touches the trunk or another limb (a surface built
    // with an arm against the side would tear when the arm rises).
    std::vector<RigidTransform> pose = motion.worldPoses(0);
    const auto position = [&pose](int j) { return Eigen::Vector3f(pose[std::size_t(j)].translation.cast<float>()); };
    const auto isEndSite = [&skeleton](int j) { return skeleton.joints[std::size_t(j)].channels.empty() && skeleton.children(j).empty(); };
    float lowest = std::numeric_limits<float>::max(), highest = std::numeric_limits<float>::lowest();
    for (int j = 0; j < count; ++j) {
        lowest = std::min(lowest, position(j).z());
        highest = std::max(highest, position(j).z());
    }
    const float firstHeight = highest - lowest;
    if (!(firstHeight > 1.0f)) return makeError(ErrorCode::InvalidArgument, "the skeleton has no height at its first frame");

    // The trunk: the chain from the root to the head.
    int head = -1;
    if (const PartBinding* bound = skeleton.binding("head")) head = bound->joint;
    for (int j = 0; j < count && head < 0; ++j)
        if (!isEndSite(j) && nameHasHead(skeleton.joints[std::size_t(j)].name)) head = j;
    if (head < 0) {
        float top = std::numeric_limits<float>::lowest();
        for (int j = 0; j < count; ++j)
            if (!isEndSite(j) && position(j).z() > top) {
                top = position(j).z();
                head = j;
            }
    }
    std::vector<int> chain; // root ... head
    for (int j = head; j >= 0; j = skeleton.joints[std::size_t(j)].parent) chain.insert(chain.begin(), j);
    std::vector<char> trunk(static_cast<std::size_t>(count), 0);
    for (const int j : chain) trunk[std::size_t(j)] = 1;
    // The pelvis: the lowest trunk joint where limbs branch off; the arms' branch: the highest
    // below the head. Bones below the pelvis (a root on the floor) carry no surface.
    int pelvis = -1, branch = -1;
    for (const int j : chain)
        if (j != head && skeleton.children(j).size() > 1) {
            if (pelvis < 0) pelvis = j;
            branch = j;
        }
    if (pelvis < 0) pelvis = chain.front();
    if (branch < 0) branch = pelvis;
    const auto chainIndex = [&chain](int j) { return int(std::find(chain.begin(), chain.end(), j) - chain.begin()); };

    const auto subtree = [&skeleton, count](int top) {
        std::vector<int> joints{top};
        for (int j = top + 1; j < count; ++j)
            for (int p = skeleton.joints[std::size_t(j)].parent; p >= 0; p = skeleton.joints[std::size_t(p)].parent)
                if (p == top) {
                    joints.push_back(j);
                    break;
                }
        return joints;
    };
    const Eigen::Vector3f trunkAxis = (position(head) - position(pelvis)).normalized();
    for (const int t : chain) {
        if (t == head || (t != pelvis && (chainIndex(t) < chainIndex(pelvis) || chainIndex(t) > chainIndex(branch)))) continue;
        for (const int limb : skeleton.children(t)) {
            if (trunk[std::size_t(limb)]) continue;
            // The pivot: of the limb's first three joints, the one with the longest bone on.
            int pivot = -1, next = -1;
            float longest = 0.0f;
            for (int j = limb, depth = 0; depth < 3; ++depth) {
                const auto children = skeleton.children(j);
                if (children.empty()) break;
                const float length = (position(children.front()) - position(j)).norm();
                if (length > longest) {
                    longest = length;
                    pivot = j;
                    next = children.front();
                }
                j = children.front();
            }
            if (pivot < 0 || longest < 0.05f * firstHeight) continue;
            const Eigen::Vector3f from = (position(next) - position(pivot)).normalized();
            Eigen::Vector3f outward = position(pivot) - position(t);
            outward -= trunkAxis * outward.dot(trunkAxis);
            outward.z() = 0.0f;
            if (outward.norm() < 1e-3f) continue;
            outward.normalize();
            const bool leg = t == pelvis;
            const float down = leg ? 87.0f : 40.0f; // deg below the horizontal
            const float radians = down * 3.14159265f / 180.0f;
            const Eigen::Vector3f to = std::cos(radians) * outward - std::sin(radians) * Eigen::Vector3f::UnitZ();
            const Eigen::Quaterniond turn = Eigen::Quaterniond::FromTwoVectors(from.cast<double>(), to.cast<double>());
            const Eigen::Vector3d origin = pose[std::size_t(pivot)].translation;
            for (const int j : subtree(pivot)) {
                RigidTransform& p = pose[std::size_t(j)];
                p.translation = origin + turn * (p.translation - origin);
                p.rotation = (turn * p.rotation).normalized();
            }
        }
    }
    std::vector<Eigen::Vector3f> rest(static_cast<std::size_t>(count));
    lowest = std::numeric_limits<float>::max();
    highest = std::numeric_limits<float>::lowest();
    for (int j = 0; j < count; ++j) {
        rest[std::size_t(j)] = position(j);
        lowest = std::min(lowest, rest[std::size_t(j)].z());
        highest = std::max(highest, rest[std::size_t(j)].z());
    }
    const float height = highest - lowest;
    const auto onTorso = [&](int joint) { // a trunk joint from the pelvis up to the arms' branch
        const int i = chainIndex(joint);
        return trunk[std::size_t(joint)] && i >= chainIndex(pelvis) && i <= chainIndex(branch);
    };

    std::vector<Segment> segments;
    std::vector<int> limbIndex(static_cast<std::size_t>(count), 0); // bones from the trunk down a limb
    for (int c = 0; c < count; ++c) {
        const int p = skeleton.joints[std::size_t(c)].parent;
        if (p < 0) continue;
        if (trunk[std::size_t(c)] && chainIndex(c) <= chainIndex(pelvis)) continue; // below the pelvis
        Segment s{rest[std::size_t(p)], rest[std::size_t(c)], 1.0f, p};
        const float length = (s.b - s.a).norm();
        if (trunk[std::size_t(c)]) {
            s.radius = onTorso(c) ? 0.075f * height : 0.03f * height; // the torso up to the arms, then the neck
        } else {
            limbIndex[std::size_t(c)] = trunk[std::size_t(p)] ? 0 : limbIndex[std::size_t(p)] + 1;
            s.radius = std::clamp(0.2f * length, 0.02f * height, 0.05f * height) * std::pow(0.9f, float(limbIndex[std::size_t(c)]));
            s.radius = std::max(s.radius, 0.015f * height);
        }
        segments.push_back(s);
    }
    {
        // The head: a sphere over the head joint (towards its End Site or child, else upwards).
        Eigen::Vector3f up(0.0f, 0.0f, 0.06f * height);
        for (const int child : skeleton.children(head)) up = 0.5f * (rest[std::size_t(child)] - rest[std::size_t(head)]);
        if (up.norm() < 0.03f * height) up = Eigen::Vector3f(0.0f, 0.0f, 0.06f * height);
        const Eigen::Vector3f centre = rest[std::size_t(head)] + up;
        segments.push_back(Segment{centre, centre, 0.062f * height, head});
    }
    if (segments.size() < 2) return makeError(ErrorCode::InvalidArgument, "the skeleton has no bones");

    const float blend = 0.02f * height;
    const auto distance = [&segments, blend](const Eigen::Vector3f& p) {
        float d = std::numeric_limits<float>::max();
        for (const Segment& s : segments) {
            const float e = segmentDistance(s, p) - s.radius;
            d = d == std::numeric_limits<float>::max() ? e : smoothMin(d, e, blend);
        }
        return d;
    };
    SurfaceNetsGrid grid;
    Eigen::Vector3f lower = Eigen::Vector3f::Constant(std::numeric_limits<float>::max());
    Eigen::Vector3f upper = Eigen::Vector3f::Constant(std::numeric_limits<float>::lowest());
    for (const Segment& s : segments) {
        lower = lower.cwiseMin(s.a.cwiseMin(s.b) - Eigen::Vector3f::Constant(s.radius));
        upper = upper.cwiseMax(s.a.cwiseMax(s.b) + Eigen::Vector3f::Constant(s.radius));
    }
    grid.cellSize = height / 120.0f;
    grid.lower = lower - Eigen::Vector3f::Constant(3.0f * grid.cellSize);
    grid.upper = upper + Eigen::Vector3f::Constant(3.0f * grid.cellSize);
    grid.threads = 2;
    SurfaceNetsMesh surface = surfaceNets(distance, grid);
    // Keep the largest piece (a detached crumb would be a second silhouette).
    int components = 0;
    const std::vector<int> component = meshComponents(surface.positions.size(), surface.indices, &components);
    std::vector<std::size_t> sizes(std::size_t(std::max(components, 1)), 0);
    for (const int c : component) ++sizes[std::size_t(c)];
    const int largest = int(std::max_element(sizes.begin(), sizes.end()) - sizes.begin());

    PerformerBody body;
    body.height = height;
    PuppetMesh& mesh = body.mesh;
    std::vector<std::uint32_t> remap(surface.positions.size(), std::numeric_limits<std::uint32_t>::max());
    const float falloff = 0.012f * height;
    for (std::size_t v = 0; v < surface.positions.size(); ++v) {
        if (component[v] != largest) continue;
        remap[v] = std::uint32_t(mesh.positions.size());
        const Eigen::Vector3f& p = surface.positions[v];
        mesh.positions.push_back(p);
        mesh.normals.push_back(surface.normals[v]);
        mesh.colours.emplace_back(0.80f, 0.76f, 0.71f);
        mesh.sheen.push_back(0.15f);
        mesh.regions.push_back(PuppetRegion::None);
        mesh.paintPositions.push_back(p);
        // The nearest segment of each joint, then the four nearest joints.
        std::vector<std::pair<float, int>> nearest;
        for (const Segment& s : segments) {
            const float d = segmentDistance(s, p) - s.radius;
            auto found = std::find_if(nearest.begin(), nearest.end(), [&s](const auto& e) { return e.second == s.joint; });
            if (found == nearest.end()) nearest.emplace_back(d, s.joint);
            else found->first = std::min(found->first, d);
        }
        std::partial_sort(nearest.begin(), nearest.begin() + std::min<std::ptrdiff_t>(4, std::ptrdiff_t(nearest.size())), nearest.end());
        std::array<std::uint8_t, 4> joints{0, 0, 0, 0};
        Eigen::Vector4f weights = Eigen::Vector4f::Zero();
        for (std::size_t k = 0; k < 4 && k < nearest.size(); ++k) {
            joints[k] = std::uint8_t(nearest[k].second);
            weights[Eigen::Index(k)] = std::exp(-(nearest[k].first - nearest[0].first) / falloff);
        }
        for (std::size_t k = nearest.size(); k < 4; ++k) joints[k] = joints[0];
        weights /= weights.sum();
        mesh.joints.push_back(joints);
        mesh.weights.push_back(weights);
    }
    for (std::size_t i = 0; i + 2 < surface.indices.size(); i += 3) {
        const std::uint32_t a = remap[surface.indices[i]], b = remap[surface.indices[i + 1]], c = remap[surface.indices[i + 2]];
        if (a == std::numeric_limits<std::uint32_t>::max() || b == std::numeric_limits<std::uint32_t>::max() ||
            c == std::numeric_limits<std::uint32_t>::max())
            continue;
        mesh.indices.insert(mesh.indices.end(), {a, b, c});
    }
    mesh.cellSize = grid.cellSize;
    mesh.droppedComponents = std::max(components - 1, 0);
    body.bindPoses = pose;
    return body;
}

Result<PerformerBody> skeletonMeshBody(const SkeletonMesh& mesh, const Skeleton& skeleton)
{
    const std::string name = skeleton.name.empty() ? std::string("skeleton") : skeleton.name;
    if (!meshFitsSkeleton(mesh, skeleton)) return makeError(ErrorCode::InvalidArgument, name + ": the file's mesh was made for other joints");
    if (mesh.bindPoses.size() > std::size_t(kMaxBodyJoints))
        return makeError(ErrorCode::Unsupported, name + ": the file's mesh moves with " + std::to_string(mesh.bindPoses.size()) + " joints (at most " +
                                                     std::to_string(kMaxBodyJoints) + " are drawn)");
    if (auto valid = validateSkeletonMesh(mesh); !valid) return makeError(valid.error().code, name + ": " + valid.error().message);
    PerformerBody body;
    PuppetMesh& out = body.mesh;
    const std::size_t n = mesh.vertexCount();
    out.positions = mesh.positions;
    out.normals = mesh.normals;
    out.colours.assign(n, Eigen::Vector3f(0.74f, 0.70f, 0.66f));
    out.sheen.assign(n, 0.15f);
    out.regions.assign(n, PuppetRegion::None);
    out.paintPositions = mesh.positions;
    out.joints.resize(n);
    for (std::size_t v = 0; v < n; ++v)
        for (std::size_t k = 0; k < 4; ++k) out.joints[v][k] = std::uint8_t(mesh.joints[v][k]);
    out.weights = mesh.weights;
    out.indices = mesh.indices;
    body.bindPoses = mesh.bindPoses;
    float lowest = std::numeric_limits<float>::max(), highest = std::numeric_limits<float>::lowest();
    for (const Eigen::Vector3f& p : mesh.positions) {
        lowest = std::min(lowest, p.z());
        highest = std::max(highest, p.z());
    }
    body.height = n > 0 ? highest - lowest : 0.0f;
    return body;
}

std::vector<RigidTransform> bodySkinningTransforms(const PerformerBody& body, const std::vector<RigidTransform>& world_T_joint)
{
    std::vector<RigidTransform> skinning(body.bindPoses.size());
    for (std::size_t j = 0; j < skinning.size() && j < world_T_joint.size(); ++j) skinning[j] = world_T_joint[j] * body.bindPoses[j].inverse();
    return skinning;
}

} // namespace bunraku::analysis
