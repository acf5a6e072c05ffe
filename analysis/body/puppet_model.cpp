#include "analysis/body/puppet_model.h"

#include "analysis/body/body_pose.h"
#include "analysis/body/dual_quaternion.h"
#include "analysis/body/mesh_decimation.h"
#include "analysis/body/puppet_shapes.h"
#include "analysis/body/surface_nets.h"
#include "analysis/core/parallel.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <string_view>

namespace bunraku::analysis {
namespace {

using puppet_shapes::Group;
using puppet_shapes::Material;

float smoothstep(float edge0, float edge1, float x)
{
    const float t = std::clamp((x - edge0) / (edge1 - edge0), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

struct Look {
    Eigen::Vector3f colour;
    float sheen;
    PuppetRegion region;
};

Look materialLook(Material m)
{
    switch (m) {
    case Material::Skin: return {{0.96f, 0.94f, 0.90f}, 0.30f, PuppetRegion::None}; // gofun
    case Material::Hair: return {{0.055f, 0.05f, 0.06f}, 0.75f, PuppetRegion::None}; // lacquer black
    case Material::Kimono: return {{0.62f, 0.09f, 0.15f}, 0.35f, PuppetRegion::Kimono}; // silk
    case Material::CollarWhite: return {{0.95f, 0.93f, 0.88f}, 0.20f, PuppetRegion::None};
    case Material::CollarRed: return {{0.86f, 0.22f, 0.24f}, 0.30f, PuppetRegion::None};
    case Material::Obi: return {{0.86f, 0.66f, 0.27f}, 0.55f, PuppetRegion::Obi};
    case Material::ObiCord: return {{0.36f, 0.16f, 0.45f}, 0.40f, PuppetRegion::None};
    case Material::ObiKnot: return {{0.74f, 0.52f, 0.20f}, 0.55f, PuppetRegion::Obi};
    case Material::Gold: return {{0.92f, 0.74f, 0.30f}, 0.90f, PuppetRegion::None};
    case Material::Coral: return {{0.86f, 0.22f, 0.24f}, 0.70f, PuppetRegion::None};
    case Material::Tegara: return {{0.90f, 0.36f, 0.46f}, 0.30f, PuppetRegion::None};
    }
    return {{0.8f, 0.8f, 0.8f}, 0.2f, PuppetRegion::None};
}

/// Up to four (joint, weight) pairs, normalised.
struct Skin {
    std::array<std::uint8_t, 4> joints{0, 0, 0, 0};
    Eigen::Vector4f weights = Eigen::Vector4f::Zero();
    int used = 0;
    void add(PuppetJoint joint, float w)
    {
        if (w <= 1e-4f || used == 4) return;
        joints[std::size_t(used)] = std::uint8_t(joint);
        weights[used] = w;
        ++used;
    }
    void normalise()
    {
        const float sum = weights.sum();
        if (sum > 0.0f) weights /= sum;
    }
};

Skin skinWeights(Group group, const Eigen::Vector3f& p)
{
    const puppet_shapes::RestPose& rest = puppet_shapes::restPose();
    Skin skin;
    switch (group) {
    case Group::Body: {
        // Shoulder above the dō-wa, the hanging kimono below it.
        const float hang = smoothstep(float(rest.dowa.z()) + 1.0f, float(rest.dowa.z()) - 9.0f, p.z());
        skin.add(PuppetJoint::Shoulder, 1.0f - hang);
        skin.add(PuppetJoint::Kimono, hang);
        break;
    }
    case Group::Head: {
        // Along the neck from its base in the shoulder board to the head.
        const float head = smoothstep(float(rest.neckJoint.z()) + 0.6f, float(rest.neckJoint.z()) + 3.2f, p.z());
        skin.add(PuppetJoint::Shoulder, 1.0f - head);
        skin.add(PuppetJoint::Head, head);
        break;
    }
    case Group::RightArm:
    case Group::LeftArm: {
        const bool left = group == Group::LeftArm;
        Eigen::Vector3f q = p;
        if (left) q.y() = -q.y();
        // t: along the bone in the sleeve's vertical plane (a point low in the hanging sleeve
        // is as far along as the bone above it, not as its perpendicular foot).
        const Eigen::Vector3f along = rest.armDirection.cast<float>();
        const Eigen::Vector3f down(0.0f, 0.0f, -1.0f);
        const Eigen::Vector3f across = along.cross(down).normalized();
        Eigen::Vector3f r = q - rest.rightShoulderJoint.cast<float>();
        r -= r.dot(across) * across;
        const float c = along.dot(down);
        const float t = (r.dot(along) - c * r.dot(down)) / (1.0f - c * c);
        const float wrist = float(rest.wristAlong);
        const float shoulder = 1.0f - smoothstep(-1.0f, 3.0f, t);
        const float hand = smoothstep(wrist - 1.2f, wrist + 1.2f, t);
        // s: the depth below the bone. The sleeve below the arm hangs from its sleeve joint.
        const float depth = (r.dot(down) - c * r.dot(along)) / (1.0f - c * c);
        const float arm = std::max(0.0f, 1.0f - shoulder - hand);
        const float hang = arm * smoothstep(3.0f, 12.0f, depth);
        skin.add(PuppetJoint::Shoulder, shoulder);
        skin.add(left ? PuppetJoint::LeftArm : PuppetJoint::RightArm, arm - hang);
        skin.add(left ? PuppetJoint::LeftHand : PuppetJoint::RightHand, hand);
        skin.add(left ? PuppetJoint::LeftSleeve : PuppetJoint::RightSleeve, hang);
        break;
    }
    case Group::RightHand:
    case Group::LeftHand: {
        // Along the hand from the wrist (4 cm behind the hand's frame): the forearm's twist
        // stays above the wrist.
        const bool left = group == Group::LeftHand;
        Eigen::Vector3f q = p;
        if (left) q.y() = -q.y();
        const float x = float((rest.rightHand.inverse().apply(q.cast<double>())).x());
        const float hand = smoothstep(-5.2f, -2.8f, x);
        skin.add(left ? PuppetJoint::LeftArm : PuppetJoint::RightArm, 1.0f - hand);
        skin.add(left ? PuppetJoint::LeftHand : PuppetJoint::RightHand, hand);
        break;
    }
    }
    skin.normalise();
    return skin;
}

/// The weights of a vertex: its group's rule, and where a body vertex lies in the fillet
/// between the chest and an arm (within 3 cm of the arm's root) blended towards that
/// arm's rule, so the weights run on smoothly from the chest into the arm.
Skin blendedSkin(const std::vector<puppet_shapes::Shape>& list, Group group, const Eigen::Vector3f& p)
{
    if (group != Group::Body) return skinWeights(group, p);
    std::array<float, kPuppetJointCount> total{};
    const auto accumulate = [&](const Skin& skin, float w) {
        for (int k = 0; k < skin.used; ++k) total[skin.joints[std::size_t(k)]] += w * skin.weights[k];
    };
    float rest = 1.0f;
    for (const Group arm : {Group::RightArm, Group::LeftArm}) {
        float distance = 1e9f;
        for (const auto& shape : list)
            if (shape.group == arm && shape.growsFromBody) distance = std::min(distance, puppet_shapes::shapeDistance(shape, p));
        const float w = std::min(rest, 1.0f - smoothstep(0.0f, 3.0f, distance));
        if (w <= 0.0f) continue;
        accumulate(skinWeights(arm, p), w);
        rest -= w;
    }
    accumulate(skinWeights(Group::Body, p), rest);
    // The four largest, renormalised.
    std::array<int, kPuppetJointCount> order{};
    for (int j = 0; j < kPuppetJointCount; ++j) order[std::size_t(j)] = j;
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return total[std::size_t(a)] > total[std::size_t(b)]; });
    Skin skin;
    for (int k = 0; k < 4; ++k) skin.add(PuppetJoint(order[std::size_t(k)]), total[std::size_t(order[std::size_t(k)])]);
    skin.normalise();
    return skin;
}

RigidTransform mirrored(const RigidTransform& model_T_part)
{
    return mirroredPose(model_T_part, RigidTransform{});
}

Eigen::Vector3f apply(const RigidTransform& t, const Eigen::Vector3f& p) { return t.apply(p.cast<double>()).cast<float>(); }

/// Fewer triangles where the surface is flat (the skirt, the sleeves), the same vertices where it
/// is not; the borders between materials and painted regions are kept as they are.
void simplify(PuppetMesh& mesh, const PuppetMeshOptions& options)
{
    const std::size_t n = mesh.vertexCount();
    std::vector<char> locked(n, 0);
    const auto differ = [&](std::uint32_t a, std::uint32_t b) {
        return mesh.regions[a] != mesh.regions[b] || mesh.sheen[a] != mesh.sheen[b] || mesh.colours[a] != mesh.colours[b];
    };
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
        for (int e = 0; e < 3; ++e) {
            const std::uint32_t a = mesh.indices[t + std::size_t(e)], b = mesh.indices[t + std::size_t((e + 1) % 3)];
            if (differ(a, b)) locked[a] = locked[b] = 1;
        }
    DecimationOptions decimation;
    decimation.targetTriangles = options.targetTriangles;
    decimation.maxError = options.maxError;
    decimation.maxEdge = options.maxEdge;
    // Where the skin weights change (the bends at the neck, shoulders, wrists, below the dō-wa
    // and down the sleeves) the vertices stay as dense as polygonised.
    const auto weightsOf = [&](std::uint32_t v) {
        Eigen::Matrix<float, kPuppetJointCount, 1> w = Eigen::Matrix<float, kPuppetJointCount, 1>::Zero();
        for (int k = 0; k < 4; ++k) w[mesh.joints[v][std::size_t(k)]] += mesh.weights[v][k];
        return w;
    };
    const auto difference = [&](std::uint32_t u, std::uint32_t v) { return (weightsOf(u) - weightsOf(v)).cwiseAbs().sum(); };
    const std::vector<std::uint32_t> into = decimateMesh(mesh.positions, mesh.indices, locked, decimation, difference, 0.1f);
    std::vector<std::int64_t> remap(n, -1);
    PuppetMesh kept = mesh;
    kept.positions.clear();
    kept.normals.clear();
    kept.colours.clear();
    kept.sheen.clear();
    kept.regions.clear();
    kept.paintPositions.clear();
    kept.joints.clear();
    kept.weights.clear();
    kept.indices.clear();
    for (const std::uint32_t v : mesh.indices) {
        if (remap[v] >= 0) continue;
        remap[v] = std::int64_t(kept.positions.size());
        kept.positions.push_back(mesh.positions[v]);
        kept.normals.push_back(mesh.normals[v]);
        kept.colours.push_back(mesh.colours[v]);
        kept.sheen.push_back(mesh.sheen[v]);
        kept.regions.push_back(mesh.regions[v]);
        kept.paintPositions.push_back(mesh.paintPositions[v]);
        kept.joints.push_back(mesh.joints[v]);
        kept.weights.push_back(mesh.weights[v]);
    }
    for (const std::uint32_t v : mesh.indices) kept.indices.push_back(std::uint32_t(remap[v]));
    (void)into;
    mesh = std::move(kept);
}

} // namespace

int PuppetMesh::dominantJoint(std::size_t v) const
{
    int best = 0;
    for (int k = 1; k < 4; ++k)
        if (weights[v][k] > weights[v][best]) best = k;
    return joints[v][std::size_t(best)];
}

float puppetSignedDistance(const Eigen::Vector3f& modelPoint) { return puppet_shapes::evaluate(puppet_shapes::shapes(), modelPoint); }

std::array<RigidTransform, 6> puppetPartBindPoses()
{
    const puppet_shapes::RestPose& rest = puppet_shapes::restPose();
    return {rest.head, rest.shoulder, rest.rightArm, rest.rightHand, mirrored(rest.rightArm), mirrored(rest.rightHand)};
}

PuppetBounds puppetModelBounds()
{
    PuppetBounds bounds{Eigen::Vector3f::Constant(1e9f), Eigen::Vector3f::Constant(-1e9f)};
    for (const auto& s : puppet_shapes::shapes()) {
        bounds.lower = bounds.lower.cwiseMin(s.centre - Eigen::Vector3f::Constant(s.radius));
        bounds.upper = bounds.upper.cwiseMax(s.centre + Eigen::Vector3f::Constant(s.radius));
    }
    return bounds;
}

PuppetJoint puppetDominantJointAt(const Eigen::Vector3f& modelPoint)
{
    const std::vector<puppet_shapes::Shape>& list = puppet_shapes::shapes();
    puppet_shapes::Nearest nearest;
    puppet_shapes::evaluate(list, modelPoint, &nearest);
    const Skin skin = blendedSkin(list, list[std::size_t(std::max(nearest.shape, 0))].group, modelPoint);
    int best = 0;
    for (int k = 1; k < skin.used; ++k)
        if (skin.weights[k] > skin.weights[best]) best = k;
    return PuppetJoint(skin.joints[std::size_t(best)]);
}

PuppetMesh generatePuppetMesh(const PuppetMeshOptions& options)
{
    const std::vector<puppet_shapes::Shape>& list = puppet_shapes::shapes();
    const puppet_shapes::RestPose& rest = puppet_shapes::restPose();
    SurfaceNetsGrid grid;
    const PuppetBounds bounds = puppetModelBounds();
    grid.lower = bounds.lower;
    grid.upper = bounds.upper;
    grid.lower -= Eigen::Vector3f::Constant(2.0f * options.cellSize);
    grid.upper += Eigen::Vector3f::Constant(2.0f * options.cellSize);
    grid.cellSize = options.cellSize;
    grid.threads = resolveThreads(options.threads);
    SurfaceNetsMesh net = surfaceNets([&](const Eigen::Vector3f& p) { return puppet_shapes::evaluate(list, p); }, grid);

    // Keep the largest connected piece (a pin thinner than the grid can leave a crumb).
    int components = 0;
    const std::vector<int> label = meshComponents(net.positions.size(), net.indices, &components);
    std::vector<std::size_t> sizes(std::size_t(std::max(components, 1)), 0);
    for (const int l : label) ++sizes[std::size_t(l)];
    const int keep = int(std::max_element(sizes.begin(), sizes.end()) - sizes.begin());
    std::vector<std::int64_t> remap(net.positions.size(), -1);

    PuppetMesh mesh;
    mesh.cellSize = options.cellSize;
    mesh.droppedComponents = std::max(0, components - 1);
    for (std::size_t v = 0; v < net.positions.size(); ++v) {
        if (label[v] != keep) continue;
        remap[v] = std::int64_t(mesh.positions.size());
        mesh.positions.push_back(net.positions[v]);
        mesh.normals.push_back(net.normals[v]);
    }
    for (std::size_t t = 0; t + 2 < net.indices.size(); t += 3) {
        if (remap[net.indices[t]] < 0) continue;
        for (int k = 0; k < 3; ++k) mesh.indices.push_back(std::uint32_t(remap[net.indices[t + std::size_t(k)]]));
    }

    // Material and skin weights from the shape nearest each vertex.
    const std::size_t count = mesh.positions.size();
    mesh.colours.resize(count);
    mesh.sheen.resize(count);
    mesh.regions.resize(count);
    mesh.joints.resize(count);
    mesh.weights.resize(count);
    const int threads = grid.threads;
    (void)parallelFor(std::size_t(threads), threads, [&](std::size_t part) {
        for (std::size_t v = part * count / std::size_t(threads); v < (part + 1) * count / std::size_t(threads); ++v) {
            puppet_shapes::Nearest nearest;
            puppet_shapes::evaluate(list, mesh.positions[v], &nearest);
            const puppet_shapes::Shape& shape = list[std::size_t(std::max(nearest.shape, 0))];
            Look look = materialLook(shape.material);
            if (shape.material == Material::Skin && shape.group == Group::Head) look.region = PuppetRegion::Face;
            // The hem shows the kimono's orange lining.
            if (shape.material == Material::Kimono && mesh.positions[v].z() < float(rest.hemZ) + 1.4f)
                look.colour = Eigen::Vector3f(0.93f, 0.45f, 0.18f);
            mesh.colours[v] = look.colour;
            mesh.sheen[v] = look.sheen;
            mesh.regions[v] = look.region;
            const Skin skin = blendedSkin(list, shape.group, mesh.positions[v]);
            mesh.joints[v] = skin.joints;
            mesh.weights[v] = skin.weights;
        }
        return okStatus();
    });
    mesh.paintPositions = mesh.positions;
    if (options.targetTriangles > 0) simplify(mesh, options);

    const auto parts = puppetPartBindPoses();
    for (int j = 0; j < 6; ++j) mesh.bindPoses[std::size_t(j)] = parts[std::size_t(j)];
    mesh.bindPoses[std::size_t(PuppetJoint::Kimono)] = RigidTransform{Eigen::Quaterniond::Identity(), rest.dowa};
    mesh.dowaInShoulder = rest.dowa;
    mesh.restArmHeadingDeg = std::atan2(rest.armDirection.y(), rest.armDirection.x()) * 180.0 / M_PI;
    const Eigen::Vector3d sleeve = rest.rightArm.apply(mesh.sleeveInArm);
    mesh.bindPoses[std::size_t(PuppetJoint::RightSleeve)] = RigidTransform{Eigen::Quaterniond::Identity(), sleeve};
    mesh.bindPoses[std::size_t(PuppetJoint::LeftSleeve)] =
        RigidTransform{Eigen::Quaterniond::Identity(), Eigen::Vector3d(sleeve.x(), -sleeve.y(), sleeve.z())};
    return mesh;
}

const PuppetMesh& shippedPuppetMesh()
{
    static const PuppetMesh mesh = generatePuppetMesh();
    return mesh;
}

bool bodyHasPuppetParts(const BodyDescription& body)
{
    const auto indices = puppetJointPartIndices(body);
    return std::all_of(indices.begin(), indices.end(), [](int i) { return i >= 0; });
}

std::array<int, kPuppetJointCount> puppetJointPartIndices(const BodyDescription& body)
{
    std::array<int, kPuppetJointCount> indices{};
    for (int j = 0; j < kPuppetJointCount; ++j) indices[std::size_t(j)] = body.partIndex(kPuppetJointParts[std::size_t(j)]);
    return indices;
}

PuppetMesh fittedPuppetMesh(const PuppetMesh& shipped, const BodyDescription& body)
{
    const auto partOf = puppetJointPartIndices(body);
    std::array<Eigen::Affine3d, kPuppetJointCount> fit;
    bool identity = true;
    for (int j = 0; j < kPuppetJointCount; ++j) {
        const int p = partOf[std::size_t(j)];
        fit[std::size_t(j)] = p >= 0 ? body.parts[std::size_t(p)].fit : Eigen::Affine3d::Identity();
        if (!fit[std::size_t(j)].matrix().isIdentity(1e-12)) identity = false;
    }
    if (identity) return shipped;
    PuppetMesh mesh = shipped;
    // The kimono joint's vertices are in the shoulder's frame (it hangs from the shoulder's dō-wa),
    // and a sleeve joint's in its arm's frame.
    const auto frameOf = [](int joint) {
        if (joint == int(PuppetJoint::Kimono)) return int(PuppetJoint::Shoulder);
        if (joint == int(PuppetJoint::RightSleeve)) return int(PuppetJoint::RightArm);
        if (joint == int(PuppetJoint::LeftSleeve)) return int(PuppetJoint::LeftArm);
        return joint;
    };
    std::array<Eigen::Affine3d, kPuppetJointCount> model_fit_model;
    std::array<Eigen::Matrix3d, kPuppetJointCount> normalMap;
    for (int j = 0; j < kPuppetJointCount; ++j) {
        const RigidTransform& bind = shipped.bindPoses[std::size_t(frameOf(j))];
        Eigen::Affine3d model_T_part = Eigen::Affine3d::Identity();
        model_T_part.linear() = bind.rotation.toRotationMatrix();
        model_T_part.translation() = bind.translation;
        model_fit_model[std::size_t(j)] = model_T_part * fit[std::size_t(frameOf(j))] * model_T_part.inverse();
        normalMap[std::size_t(j)] = model_fit_model[std::size_t(j)].linear().inverse().transpose();
    }
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        Eigen::Vector3d p = Eigen::Vector3d::Zero(), n = Eigen::Vector3d::Zero();
        for (int k = 0; k < 4; ++k) {
            const double w = shipped.weights[v][k];
            if (w <= 0.0) continue;
            const int j = shipped.joints[v][std::size_t(k)];
            p += w * (model_fit_model[std::size_t(j)] * shipped.positions[v].cast<double>());
            n += w * (normalMap[std::size_t(j)] * shipped.normals[v].cast<double>());
        }
        mesh.positions[v] = p.cast<float>();
        mesh.normals[v] = n.norm() > 1e-12 ? Eigen::Vector3f(n.normalized().cast<float>()) : shipped.normals[v];
    }
    const Eigen::Affine3d& shoulderFit = fit[std::size_t(PuppetJoint::Shoulder)];
    mesh.dowaInShoulder = shoulderFit * shipped.dowaInShoulder;
    mesh.bindPoses[std::size_t(PuppetJoint::Kimono)] =
        RigidTransform{Eigen::Quaterniond::Identity(), shipped.bindPoses[std::size_t(PuppetJoint::Shoulder)].apply(mesh.dowaInShoulder)};
    const Eigen::Affine3d& armFit = fit[std::size_t(PuppetJoint::RightArm)];
    mesh.sleeveInArm = armFit * shipped.sleeveInArm;
    for (const PuppetJoint sleeve : {PuppetJoint::RightSleeve, PuppetJoint::LeftSleeve}) {
        const bool left = sleeve == PuppetJoint::LeftSleeve;
        const Eigen::Vector3d local = left ? Eigen::Vector3d(mesh.sleeveInArm.x(), -mesh.sleeveInArm.y(), mesh.sleeveInArm.z()) : mesh.sleeveInArm;
        const RigidTransform& arm = shipped.bindPoses[std::size_t(left ? PuppetJoint::LeftArm : PuppetJoint::RightArm)];
        mesh.bindPoses[std::size_t(sleeve)] = RigidTransform{Eigen::Quaterniond::Identity(), arm.apply(local)};
    }
    return mesh;
}

std::array<RigidTransform, kPuppetJointCount> puppetJointPoses(const PuppetMesh& mesh, const BodyDescription& body,
                                                               const std::vector<RigidTransform>& world_T_part)
{
    const auto partOf = puppetJointPartIndices(body);
    std::array<RigidTransform, kPuppetJointCount> poses{};
    for (int j = 0; j < kPuppetJointCount; ++j) {
        const int p = partOf[std::size_t(j)];
        if (p >= 0 && std::size_t(p) < world_T_part.size()) poses[std::size_t(j)] = world_T_part[std::size_t(p)];
    }
    // The kimono joint: at the dō-wa, turned only about the vertical by the shoulder's heading
    // (its forward axis, or in a deep bow its up axis, projected on the floor).
    const RigidTransform& shoulder = poses[std::size_t(PuppetJoint::Shoulder)];
    const Eigen::Matrix3d R = shoulder.rotation.toRotationMatrix();
    Eigen::Vector2d heading = R.col(0).head<2>() + 0.5 * R.col(2).head<2>();
    if (heading.norm() < 1e-6) heading = Eigen::Vector2d::UnitX();
    const double yaw = std::atan2(heading.y(), heading.x());
    poses[std::size_t(PuppetJoint::Kimono)] =
        RigidTransform{Eigen::Quaterniond(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ())), shoulder.apply(mesh.dowaInShoulder)};
    // A sleeve joint: on its arm, turned from the rest by the change of the arm's heading (the
    // arm's bone projected on the floor; within 25 deg of the vertical, the shoulder's heading
    // turned as at rest takes over smoothly).
    const double restHeading = mesh.restArmHeadingDeg * M_PI / 180.0;
    for (const bool left : {false, true}) {
        const RigidTransform& arm = poses[std::size_t(left ? PuppetJoint::LeftArm : PuppetJoint::RightArm)];
        const double sign = left ? -1.0 : 1.0;
        const Eigen::Vector2d bone = (arm.rotation * Eigen::Vector3d::UnitX()).head<2>();
        const Eigen::Vector2d asAtRest(std::cos(yaw + sign * restHeading), std::sin(yaw + sign * restHeading));
        Eigen::Vector2d armHeading = bone + 0.35 * (1.0 - std::clamp((bone.norm() - 0.15) / 0.25, 0.0, 1.0)) * asAtRest;
        if (armHeading.norm() < 1e-9) armHeading = asAtRest;
        const double turn = std::atan2(armHeading.y(), armHeading.x()) - sign * restHeading;
        const Eigen::Vector3d local = left ? Eigen::Vector3d(mesh.sleeveInArm.x(), -mesh.sleeveInArm.y(), mesh.sleeveInArm.z()) : mesh.sleeveInArm;
        poses[std::size_t(left ? PuppetJoint::LeftSleeve : PuppetJoint::RightSleeve)] =
            RigidTransform{Eigen::Quaterniond(Eigen::AngleAxisd(turn, Eigen::Vector3d::UnitZ())), arm.apply(local)};
    }
    return poses;
}

SkinnedSurface skinPuppet(const PuppetMesh& mesh, const std::array<RigidTransform, kPuppetJointCount>& world_T_joint)
{
    std::array<DualQuaternion, kPuppetJointCount> q;
    for (int j = 0; j < kPuppetJointCount; ++j)
        q[std::size_t(j)] = DualQuaternion::fromRigid(world_T_joint[std::size_t(j)] * mesh.bindPoses[std::size_t(j)].inverse());
    SkinnedSurface out;
    out.positions.resize(mesh.positions.size());
    out.normals.resize(mesh.positions.size());
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        std::array<DualQuaternion, 4> parts;
        std::array<double, 4> w{};
        int used = 0;
        for (int k = 0; k < 4; ++k) {
            if (mesh.weights[v][k] <= 0.0f) continue;
            parts[std::size_t(used)] = q[mesh.joints[v][std::size_t(k)]];
            w[std::size_t(used)] = mesh.weights[v][k];
            ++used;
        }
        const RigidTransform t = used > 0 ? blendDualQuaternions(parts.data(), w.data(), used).toRigid() : RigidTransform{};
        out.positions[v] = apply(t, mesh.positions[v]);
        out.normals[v] = (t.rotation * mesh.normals[v].cast<double>()).cast<float>();
    }
    return out;
}

} // namespace bunraku::analysis
