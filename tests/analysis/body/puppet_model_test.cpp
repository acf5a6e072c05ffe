// The modelled puppet (analysis/body/puppet_model.h): one closed, connected surface whose skin
// weights move each part's surface with that part's frame alone, a kimono that hangs below the
// dō-wa in a bow, and dual quaternion blending that keeps a twisted wrist's thickness.
#include "analysis/body/body_fit.h"
#include "analysis/body/body_pose.h"
#include "analysis/body/dual_quaternion.h"
#include "analysis/body/puppet_model.h"
#include "analysis/body/surface_nets.h"
#include "analysis/core/puppet_layout.h"
#include "analysis/synth/puppet_rig.h"

#include <catch2/catch.hpp>

#include <Eigen/Geometry>

#include <cmath>
#include <map>

using namespace bunraku::analysis;

namespace {

/// A one-frame 24-channel take from the demo rig's parameters.
Take rigTake(const Eigen::VectorXd& parameters)
{
    Take take;
    take.channels = puppetChannels();
    take.values = synth::rigChannels(parameters);
    take.labels.source = "test";
    return take;
}

float jointWeight(const PuppetMesh& mesh, std::size_t v, PuppetJoint joint)
{
    float w = 0.0f;
    for (int k = 0; k < 4; ++k)
        if (mesh.joints[v][std::size_t(k)] == std::uint8_t(joint)) w += mesh.weights[v][k];
    return w;
}

} // namespace

TEST_CASE("puppet model: the same mesh on one thread and on several", "[puppet_model]")
{
    PuppetMeshOptions one;
    one.cellSize = 1.0f;
    one.threads = 1;
    PuppetMeshOptions two = one;
    two.threads = 3;
    const PuppetMesh a = generatePuppetMesh(one), b = generatePuppetMesh(two);
    REQUIRE(a.vertexCount() == b.vertexCount());
    CHECK(a.indices == b.indices);
    CHECK(a.positions == b.positions);
}

TEST_CASE("dual quaternion skinning keeps a twisted wrist's thickness", "[puppet_model]")
{
    // Two joints on the x axis, the second rolled 170 deg about it: a point 1 cm off the axis
    // blended half and half stays 1 cm off it (linear blending would pull it to 0.09 cm).
    const DualQuaternion a = DualQuaternion::fromRigid(RigidTransform{});
    const DualQuaternion b =
        DualQuaternion::fromRigid(RigidTransform{Eigen::Quaterniond(Eigen::AngleAxisd(170.0 * M_PI / 180.0, Eigen::Vector3d::UnitX())), Eigen::Vector3d::Zero()});
    const DualQuaternion q[2] = {a, b};
    const double w[2] = {0.5, 0.5};
    const RigidTransform blended = blendDualQuaternions(q, w, 2).toRigid();
    const Eigen::Vector3d p = blended.apply(Eigen::Vector3d(3.0, 0.0, 1.0));
    CHECK(std::hypot(p.y(), p.z()) == Approx(1.0).margin(1e-9));
    CHECK(p.x() == Approx(3.0).margin(1e-9));
    // A translation survives the round trip.
    const RigidTransform t{Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized())), Eigen::Vector3d(4, -5, 6)};
    const RigidTransform back = DualQuaternion::fromRigid(t).toRigid();
    CHECK((back.translation - t.translation).norm() < 1e-12);
    CHECK(back.rotation.angularDistance(t.rotation) < 1e-12);
}

// The shipped mesh is made once per process (about 1.2 s, and 30 s under the sanitizers): its
// checks are sections of one case, so that ctest starts one process for them, not seven.
TEST_CASE("puppet model: the shipped mesh", "[puppet_model]")
{
    SECTION("one closed connected surface with weights summing to one")
    {
        const PuppetMesh& mesh = shippedPuppetMesh();
        REQUIRE(mesh.vertexCount() > 5000);
        REQUIRE(mesh.triangleCount() > 10000);
        CHECK(mesh.droppedComponents == 0);
        int components = 0;
        meshComponents(mesh.vertexCount(), mesh.indices, &components);
        CHECK(components == 1);
        // Watertight: every edge has as many triangles on one side as on the other (no border), and
        // all but a few (where two sheets pinch through one grid cell: the thin collar and finger
        // tips) are shared by exactly two triangles.
        std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
        for (std::size_t t = 0; t < mesh.indices.size(); t += 3)
            for (int e = 0; e < 3; ++e) ++edges[{mesh.indices[t + std::size_t(e)], mesh.indices[t + std::size_t((e + 1) % 3)]}];
        std::size_t border = 0, pinched = 0;
        for (const auto& [edge, count] : edges) {
            const auto opposite = edges.find({edge.second, edge.first});
            if (opposite == edges.end() || opposite->second != count) ++border;
            if (count != 1) ++pinched;
        }
        CHECK(border == 0);
        CHECK(double(pinched) < 1e-3 * double(edges.size()));
        for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
            REQUIRE(std::abs(mesh.weights[v].sum() - 1.0f) < 1e-5f);
            for (int k = 0; k < 4; ++k) REQUIRE(mesh.joints[v][std::size_t(k)] < kPuppetJointCount);
            REQUIRE(std::abs(mesh.normals[v].norm() - 1.0f) < 1e-3f);
        }
        // About 2/3 of a person: the hem to the top of the hair.
        float low = 1e9f, high = -1e9f;
        for (const auto& p : mesh.positions) {
            low = std::min(low, p.z());
            high = std::max(high, p.z());
        }
        CHECK(high - low == Approx(77.0).margin(4.0));
    }
    SECTION("the painted regions and materials are where the kashira and kimono are")
    {
        const PuppetMesh& mesh = shippedPuppetMesh();
        int face = 0, faceWrong = 0, hairDark = 0;
        for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
            const Eigen::Vector3f& p = mesh.positions[v];
            if (mesh.regions[v] == PuppetRegion::Face) {
                ++face;
                if (p.z() < 6.0f || jointWeight(mesh, v, PuppetJoint::Head) + jointWeight(mesh, v, PuppetJoint::Shoulder) < 0.999f) ++faceWrong;
            }
            // The top of the head is lacquer-black hair.
            if (p.z() > 20.0f && mesh.colours[v].maxCoeff() < 0.1f) ++hairDark;
        }
        CHECK(face > 200);
        CHECK(faceWrong == 0);
        CHECK(hairDark > 50);
    }
    SECTION("each part posed alone moves its own surface and nothing else")
    {
        const PuppetMesh& mesh = shippedPuppetMesh();
        const BodyDescription& body = defaultBodyDescription();
        const Take rest = rigTake(synth::restParameters());
        const std::vector<RigidTransform> restParts = worldPartPoses(body, rest, 0);
        const auto restJoints = puppetJointPoses(mesh, body, restParts);
        const SkinnedSurface before = skinPuppet(mesh, restJoints);

        // A move of one part about its own origin: turned 35 deg and shifted (an arm turned about
        // the vertical, which its hanging sleeve follows rigidly too).
        const Eigen::Vector3d shift(2.0, -3.0, 4.0);
        const Eigen::Quaterniond slanted(Eigen::AngleAxisd(0.61, Eigen::Vector3d(0.3, 0.8, 0.5).normalized()));
        const Eigen::Quaterniond vertical(Eigen::AngleAxisd(0.61, Eigen::Vector3d::UnitZ()));
        struct Case {
            const char* part;
            std::vector<PuppetJoint> joints; ///< the joints that move with the part
            bool aboutVertical;
        };
        for (const Case& c : {Case{"head", {PuppetJoint::Head}, false}, Case{"right_hand", {PuppetJoint::RightHand}, false},
                              Case{"left_hand", {PuppetJoint::LeftHand}, false},
                              Case{"right_arm", {PuppetJoint::RightArm, PuppetJoint::RightSleeve}, true},
                              Case{"left_arm", {PuppetJoint::LeftArm, PuppetJoint::LeftSleeve}, true}}) {
            SECTION(c.part)
            {
                std::vector<RigidTransform> parts = restParts;
                const int index = body.partIndex(c.part);
                REQUIRE(index >= 0);
                const RigidTransform world_T_part = restParts[std::size_t(index)];
                // world_T_moved = about the part's origin, in the world's axes.
                const RigidTransform about{c.aboutVertical ? vertical : slanted,
                                           world_T_part.translation + shift - (c.aboutVertical ? vertical : slanted) * world_T_part.translation};
                parts[std::size_t(index)] = about * world_T_part;
                const SkinnedSurface after = skinPuppet(mesh, puppetJointPoses(mesh, body, parts));
                int own = 0, still = 0;
                for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
                    float w = 0.0f;
                    for (const PuppetJoint joint : c.joints) w += jointWeight(mesh, v, joint);
                    const Eigen::Vector3d was = before.positions[v].cast<double>();
                    const Eigen::Vector3d now = after.positions[v].cast<double>();
                    if (w >= 1.0f - 1e-6f) {
                        ++own;
                        REQUIRE((now - about.apply(was)).norm() < 2e-3);
                    } else if (w <= 1e-6f) {
                        ++still;
                        REQUIRE((now - was).norm() < 1e-3);
                    }
                }
                CHECK(own > 100);
                CHECK(still > 1000);
            }
        }
    }
    SECTION("the head and hands and sleeves are skinned wholly to their parts' joints")
    {
        // Found by place, not by weight: the kashira above the neck, the hands in their frames' boxes,
        // the sleeves hanging more than 5 cm below the arm's bone between elbow and wrist (in the
        // sleeve's vertical plane through the bone: t along the bone, s straight down).
        const PuppetMesh& mesh = shippedPuppetMesh();
        const RigidTransform& arm = mesh.bindPoses[std::size_t(PuppetJoint::RightArm)];
        const Eigen::Vector3d along = arm.rotation * Eigen::Vector3d::UnitX();
        const Eigen::Vector3d shoulderJoint = arm.translation - 10.0 * along;
        int head = 0, hands = 0, sleeves = 0;
        for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
            Eigen::Vector3d p = mesh.positions[v].cast<double>();
            const bool left = p.y() > 0.0;
            if (p.z() > 11.5 && std::abs(p.y()) < 7.0 && p.x() > -8.0) {
                ++head;
                REQUIRE(jointWeight(mesh, v, PuppetJoint::Head) > 0.999f);
                continue;
            }
            if (left) p.y() = -p.y();
            const Eigen::Vector3d down(0.0, 0.0, -1.0);
            const Eigen::Vector3d across = along.cross(down).normalized();
            const Eigen::Vector3d inPlane = (p - shoulderJoint) - (p - shoulderJoint).dot(across) * across;
            const double c = along.dot(down), det = 1.0 - c * c;
            const double tPanel = (inPlane.dot(along) - c * inPlane.dot(down)) / det;
            const double sPanel = (inPlane.dot(down) - c * inPlane.dot(along)) / det;
            const Eigen::Vector3d inHand = mesh.bindPoses[std::size_t(PuppetJoint::RightHand)].inverse().apply(p);
            if (inHand.x() > -2.5 && std::abs(inHand.y()) < 4.5 && std::abs(inHand.z()) < 3.0) {
                ++hands;
                REQUIRE(jointWeight(mesh, v, left ? PuppetJoint::LeftHand : PuppetJoint::RightHand) > 0.999f);
            } else if (tPanel > 8.0 && tPanel < 17.0 && sPanel > 5.0 && sPanel < 20.0 && std::abs((p - shoulderJoint).dot(across)) < 3.0) {
                ++sleeves;
                // The arm and the sleeve hanging from it.
                REQUIRE(jointWeight(mesh, v, left ? PuppetJoint::LeftArm : PuppetJoint::RightArm) +
                            jointWeight(mesh, v, left ? PuppetJoint::LeftSleeve : PuppetJoint::RightSleeve) >
                        0.999f);
            }
        }
        CHECK(head > 300);
        CHECK(hands > 150);
        CHECK(sleeves > 100);
    }
    SECTION("in a deep bow the kimono hangs below the do-wa")
    {
        const PuppetMesh& mesh = shippedPuppetMesh();
        for (const double pitch : {60.0, 75.0, 90.0}) {
            Eigen::VectorXd parameters = synth::restParameters();
            parameters(synth::rigIndex(synth::RigParameter::BodyPitch)) = pitch;
            const Take take = rigTake(parameters);
            const BodyDescription& body = defaultBodyDescription();
            const auto parts = worldPartPoses(body, take, 0);
            // The torso is pitched as asked.
            const Eigen::Vector3d up = parts[std::size_t(body.partIndex("shoulder"))].rotation * Eigen::Vector3d::UnitZ();
            REQUIRE(std::acos(std::clamp(up.z(), -1.0, 1.0)) * 180.0 / M_PI == Approx(pitch).margin(0.5));
            const auto joints = puppetJointPoses(mesh, body, parts);
            const SkinnedSurface skinned = skinPuppet(mesh, joints);
            const double dowaZ = parts[std::size_t(body.partIndex("shoulder"))].apply(mesh.dowaInShoulder).z();
            double hemSum = 0.0, hemHighest = -1e9;
            int hem = 0;
            for (std::size_t v = 0; v < mesh.vertexCount(); ++v)
                if (mesh.positions[v].z() < mesh.dowaInShoulder.z() - 25.0) {
                    hemSum += skinned.positions[v].z();
                    hemHighest = std::max(hemHighest, double(skinned.positions[v].z()));
                    ++hem;
                }
            INFO("pitch " << pitch << " deg: do-wa at z " << dowaZ << ", hem highest " << hemHighest << ", mean " << hemSum / hem);
            REQUIRE(hem > 200);
            // Every hem vertex is lower than the dō-wa, and the hem as a whole hangs most of the
            // skirt's length (29 cm at rest) below it: the skirt does not lie in the air.
            CHECK(hemHighest < dowaZ - 10.0);
            CHECK(hemSum / hem < dowaZ - 20.0);
        }
    }
    SECTION("a fitted body's fit moves its parts' vertices")
    {
        const PuppetMesh& shipped = shippedPuppetMesh();
        BodyDescription body = defaultBodyDescription();
        CHECK(fittedPuppetMesh(shipped, body).positions == shipped.positions);
        // The head twice as large about the neck joint (in the head frame).
        const int head = body.partIndex("head");
        const Eigen::Vector3d neck(-3.0, 0.0, -7.0);
        Eigen::Affine3d fit = Eigen::Affine3d::Identity();
        fit.linear() *= 2.0;
        fit.translation() = neck - 2.0 * neck;
        body.parts[std::size_t(head)].fit = fit;
        const PuppetMesh fitted = fittedPuppetMesh(shipped, body);
        const RigidTransform& bind = shipped.bindPoses[std::size_t(PuppetJoint::Head)];
        int checked = 0;
        for (std::size_t v = 0; v < shipped.vertexCount(); ++v) {
            if (jointWeight(shipped, v, PuppetJoint::Head) < 1.0f - 1e-6f) {
                if (jointWeight(shipped, v, PuppetJoint::Head) < 1e-6f) REQUIRE((fitted.positions[v] - shipped.positions[v]).norm() < 1e-4f);
                continue;
            }
            const Eigen::Vector3d local = bind.inverse().apply(shipped.positions[v].cast<double>());
            REQUIRE((fitted.positions[v].cast<double>() - bind.apply(fit * local)).norm() < 1e-3);
            ++checked;
        }
        CHECK(checked > 500);
    }
    SECTION("arms raised or spread stretch no triangle (no part grown into another)")
    {
        // Surfaces of parts that move apart (a sleeve and the obi, an arm and the chest) must not
        // be joined: a joined spot would stretch into long triangles. At rest no edge is longer than
        // the simplification's 3 cm; spread or raised arms, a turned head and a bow lengthen no edge
        // by 3 cm or more.
        const PuppetMesh& mesh = shippedPuppetMesh();
        const BodyDescription& body = defaultBodyDescription();
        // The most any edge grows from the rest (cm).
        const auto longestGrowth = [&](const std::vector<Eigen::Vector3f>& positions) {
            float longest = 0.0f;
            for (std::size_t t = 0; t < mesh.indices.size(); t += 3)
                for (int e = 0; e < 3; ++e) {
                    const std::uint32_t a = mesh.indices[t + std::size_t(e)], b = mesh.indices[t + std::size_t((e + 1) % 3)];
                    longest = std::max(longest, (positions[a] - positions[b]).norm() - (mesh.positions[a] - mesh.positions[b]).norm());
                }
            return longest;
        };
        float restLongest = 0.0f;
        for (std::size_t t = 0; t < mesh.indices.size(); t += 3)
            for (int e = 0; e < 3; ++e)
                restLongest = std::max(restLongest, (mesh.positions[mesh.indices[t + std::size_t(e)]] - mesh.positions[mesh.indices[t + std::size_t((e + 1) % 3)]]).norm());
        CHECK(restLongest <= 3.0f + 1e-3f);
        using synth::RigParameter;
        const std::vector<std::vector<std::pair<RigParameter, double>>> poses{
            {{RigParameter::ArmYaw, -80.0}, {RigParameter::ArmPitch, 0.0}},
            {{RigParameter::ArmPitch, -60.0}},
            {{RigParameter::ArmYaw, 30.0}, {RigParameter::ArmPitch, 70.0}, {RigParameter::ArmRoll, 60.0}},
            {{RigParameter::HeadYaw, 50.0}, {RigParameter::HeadPitch, 30.0}, {RigParameter::HandRoll, 90.0}},
            {{RigParameter::BodyPitch, 80.0}},
        };
        for (std::size_t k = 0; k < poses.size(); ++k) {
            Eigen::VectorXd parameters = synth::restParameters();
            for (const auto& [parameter, value] : poses[k]) parameters(synth::rigIndex(parameter)) = value;
            const Take take = rigTake(parameters);
            const SkinnedSurface skinned = skinPuppet(mesh, puppetJointPoses(mesh, body, worldPartPoses(body, take, 0)));
            INFO("pose " << k);
            CHECK(longestGrowth(skinned.positions) < 3.0f);
        }
    }
}
