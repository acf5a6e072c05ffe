#include "analysis/core/skeleton.h"
#include "analysis/io/bvh_import.h"
#include "analysis/io/gltf_export.h"
#include "tests/support/gltf_readback.h"
#include "tests/support/peer.h"
#include "tests/support/shared_data.h"
#include "tests/support/test_paths.h"

#include <catch2/catch.hpp>

#include <cstring>
#include <functional>
#include <map>
#include <fstream>
#include <iterator>

using namespace bunraku::analysis;
using namespace bunraku::analysis::io;

namespace {

/// A unit triangle on every joint that is not an End Site.
std::vector<JointMesh> trianglePerJoint(const Skeleton& skeleton)
{
    std::vector<JointMesh> meshes;
    for (std::size_t j = 0; j < skeleton.joints.size(); ++j) {
        if (skeleton.joints[j].endSite) continue;
        JointMesh mesh;
        mesh.joint = int(j);
        mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
        mesh.normals.assign(3, Eigen::Vector3f(0, 0, 1));
        mesh.colours.assign(3, Eigen::Vector3f(0.5f, 0.5f, 0.5f));
        mesh.indices = {0, 1, 2};
        meshes.push_back(mesh);
    }
    return meshes;
}

} // namespace

TEST_CASE("glTF axes: workbench forward, left and up become +Z, +X and +Y")
{
    const Eigen::Quaterniond g = gltfAxisChange();
    CHECK((g * Eigen::Vector3d::UnitX() - Eigen::Vector3d::UnitZ()).norm() < 1e-15);
    CHECK((g * Eigen::Vector3d::UnitY() - Eigen::Vector3d::UnitX()).norm() < 1e-15);
    CHECK((g * Eigen::Vector3d::UnitZ() - Eigen::Vector3d::UnitY()).norm() < 1e-15);
}

TEST_CASE("a bandai take as glTF: 22 joints in a skin, one animation with the take's times, positions in metres")
{
    const auto path = bunraku::test::bandaiDir() / "bye_angry_001.bvh";
    if (!bunraku::test::requireBandaiData(std::filesystem::exists(path))) return;
    auto file = readBvh(path);
    REQUIRE(file.ok());
    auto take = bvhToPuppetTake(*file);
    REQUIRE(take.ok());
    const SkeletalMotion& motion = *take->skeleton;
    const auto out = bunraku::test::scratchDir("gltf_export") / "bye_angry.glb";
    REQUIRE(writeSkeletalGlb(motion, take->rateHz, trianglePerJoint(*motion.skeleton), out).ok());
    std::ifstream in(out, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    REQUIRE(bytes.substr(0, 4) == "glTF");
    const tinygltf::Model model = bunraku::test::loadGlbBytes(bytes);
    CHECK(model.asset.version == "2.0");
    REQUIRE(model.skins.size() == 1);
    CHECK(model.skins[0].joints.size() == 22);
    REQUIRE(model.animations.size() == 1);
    REQUIRE(model.meshes.size() == 1);
    const auto times = bunraku::test::gltfFloats(model, model.animations[0].samplers[0].input);
    REQUIRE(times.size() == std::size_t(take->frameCount()));
    CHECK(times.back() == Approx(double(take->frameCount() - 1) / 30.0).margin(1e-5));
    // Every joint's world position at sampled frames, read back through the node hierarchy.
    const Eigen::Quaterniond g = gltfAxisChange();
    double worst = 0.0;
    for (Eigen::Index f : {Eigen::Index(0), take->frameCount() / 3, take->frameCount() - 1}) {
        const auto positions = bunraku::test::gltfNodePositions(model, std::size_t(f));
        const auto expected = motion.worldPoses(f);
        for (std::size_t j = 0; j < expected.size(); ++j) {
            const auto& joint = motion.skeleton->joints[j];
            if (joint.endSite) continue;
            REQUIRE(positions.count(joint.name) == 1);
            const Eigen::Vector3d ours = g * (0.01 * expected[j].translation);
            worst = std::max(worst, (positions.at(joint.name) - ours).norm() * 100.0); // cm
        }
    }
    CHECK(worst < 1e-3);
}

TEST_CASE("glTF export refuses what a skin cannot hold")
{
    auto skeleton = std::make_shared<Skeleton>();
    skeleton->joints = {SkeletonJoint{"root", -1, Eigen::Vector3d::Zero(), {}, false},
                        SkeletonJoint{"root_End", 0, Eigen::Vector3d(0, 0, 10), {}, true}};
    const SkeletalMotion motion = makeRestMotion(skeleton, 4);
    CHECK_FALSE(skeletalMotionToGlb(motion, 30.0, {}).ok()); // no mesh
    auto onEnd = trianglePerJoint(*skeleton);
    onEnd.front().joint = 1;
    const auto refused = skeletalMotionToGlb(motion, 30.0, onEnd);
    REQUIRE_FALSE(refused.ok());
    CHECK_THAT(refused.error().message, Catch::Contains("End Site"));
    CHECK_FALSE(skeletalMotionToGlb(motion, 0.0, trianglePerJoint(*skeleton)).ok());
    CHECK(skeletalMotionToGlb(motion, 30.0, trianglePerJoint(*skeleton)).ok());
}

TEST_CASE("a smoothly skinned glTF mesh keeps four influences summing to one and refuses bad weights")
{
    auto skeleton = std::make_shared<Skeleton>();
    skeleton->joints = {SkeletonJoint{"root", -1, Eigen::Vector3d::Zero(), {}, false},
                        SkeletonJoint{"arm", 0, Eigen::Vector3d(0, 0, 10), {}, false},
                        SkeletonJoint{"arm_End", 1, Eigen::Vector3d(0, 0, 10), {}, true}};
    const SkeletalMotion motion = makeRestMotion(skeleton, 3);
    SkinnedMesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 5}, {0, 1, 10}};
    mesh.normals.assign(3, Eigen::Vector3f(0, 0, 1));
    mesh.colours.assign(3, Eigen::Vector3f(0.2f, 0.4f, 0.6f));
    // Unsorted, one joint named twice, weights not quite normalised.
    mesh.joints = {{{0, 1, 0, 0}}, {{1, 0, 1, 0}}, {{1, 0, 0, 0}}};
    mesh.weights = {{0.3f, 0.7f, 0.0f, 0.0f}, {0.25f, 0.5f, 0.26f, 0.0f}, {1.0f, 0.0f, 0.0f, 0.0f}};
    mesh.indices = {0, 1, 2};
    mesh.bindPoses = motion.worldPoses(0);
    const auto bytes = skinnedMotionToGlb(motion, 30.0, mesh);
    REQUIRE(bytes.ok());
    const tinygltf::Model model = bunraku::test::loadGlbBytes(*bytes);
    const auto& primitive = model.meshes.at(0).primitives.at(0);
    const auto weights = bunraku::test::gltfFloats(model, primitive.attributes.at("WEIGHTS_0"));
    const tinygltf::Accessor& jointsAccessor = model.accessors[std::size_t(primitive.attributes.at("JOINTS_0"))];
    const tinygltf::BufferView& view = model.bufferViews[std::size_t(jointsAccessor.bufferView)];
    const auto* joints = reinterpret_cast<const std::uint16_t*>(model.buffers[0].data.data() + view.byteOffset + jointsAccessor.byteOffset);
    for (std::size_t v = 0; v < 3; ++v) {
        float sum = 0.0f;
        for (std::size_t k = 0; k < 4; ++k) sum += weights[4 * v + k];
        CHECK(std::abs(sum - 1.0f) < 1e-6f);
        for (std::size_t k = 0; k + 1 < 4; ++k) CHECK(weights[4 * v + k] >= weights[4 * v + k + 1]); // largest first
    }
    // Vertex 1: the arm's two entries merged (0.51 of 1.01), then the root's 0.5.
    CHECK(joints[4] == 1);
    CHECK(weights[4] == Approx(0.51 / 1.01).epsilon(1e-6));
    CHECK(joints[5] == 0);
    CHECK(weights[5] == Approx(0.5 / 1.01).epsilon(1e-6));
    CHECK(weights[6] == 0.0f);

    SkinnedMesh negative = mesh;
    negative.weights[0][0] = -0.1f;
    CHECK_FALSE(skinnedMotionToGlb(motion, 30.0, negative).ok());
    SkinnedMesh onEnd = mesh;
    onEnd.joints[0][1] = 2;
    const auto refused = skinnedMotionToGlb(motion, 30.0, onEnd);
    REQUIRE_FALSE(refused.ok());
    CHECK_THAT(refused.error().message, Catch::Contains("vertex 0"));
    SkinnedMesh noBind = mesh;
    noBind.bindPoses.pop_back();
    CHECK_FALSE(skinnedMotionToGlb(motion, 30.0, noBind).ok());
    SkinnedMesh noWeight = mesh;
    noWeight.weights[2] = Eigen::Vector4f::Zero();
    CHECK_FALSE(skinnedMotionToGlb(motion, 30.0, noWeight).ok());
}
