#include "analysis/core/skeleton.h"
#include "analysis/io/bvh_import.h"
#include "analysis/io/gltf_export.h"
#include "tests/support/peer.h"
#include "tests/support/shared_data.h"
#include "tests/support/test_paths.h"

#include <catch2/catch.hpp>
#include <tiny_gltf.h>

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

/// Reads a float accessor (tightly packed) as doubles.
std::vector<double> floats(const tinygltf::Model& model, int accessorIndex)
{
    const tinygltf::Accessor& accessor = model.accessors[std::size_t(accessorIndex)];
    REQUIRE(accessor.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT);
    const tinygltf::BufferView& view = model.bufferViews[std::size_t(accessor.bufferView)];
    const auto* data = reinterpret_cast<const float*>(model.buffers[std::size_t(view.buffer)].data.data() + view.byteOffset + accessor.byteOffset);
    const std::size_t n = accessor.count * std::size_t(tinygltf::GetNumComponentsInType(std::uint32_t(accessor.type)));
    return std::vector<double>(data, data + n);
}

/// World positions (metres, glTF axes) of every node at keyframe `frame`, from the node
/// hierarchy and the animation's samplers (a peer's reading of the file).
std::map<std::string, Eigen::Vector3d> nodePositions(const tinygltf::Model& model, std::size_t frame)
{
    std::vector<Eigen::Quaterniond> rotation(model.nodes.size(), Eigen::Quaterniond::Identity());
    std::vector<Eigen::Vector3d> translation(model.nodes.size(), Eigen::Vector3d::Zero());
    for (std::size_t n = 0; n < model.nodes.size(); ++n) {
        const auto& node = model.nodes[n];
        if (node.rotation.size() == 4) rotation[n] = Eigen::Quaterniond(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
        if (node.translation.size() == 3) translation[n] = Eigen::Vector3d(node.translation[0], node.translation[1], node.translation[2]);
    }
    const auto& animation = model.animations.front();
    for (const auto& channel : animation.channels) {
        const auto values = floats(model, animation.samplers[std::size_t(channel.sampler)].output);
        const auto n = std::size_t(channel.target_node);
        if (channel.target_path == "rotation")
            rotation[n] = Eigen::Quaterniond(values[4 * frame + 3], values[4 * frame], values[4 * frame + 1], values[4 * frame + 2]).normalized();
        else if (channel.target_path == "translation")
            translation[n] = Eigen::Vector3d(values[3 * frame], values[3 * frame + 1], values[3 * frame + 2]);
    }
    std::map<std::string, Eigen::Vector3d> positions;
    std::function<void(int, const Eigen::Isometry3d&)> walk = [&](int n, const Eigen::Isometry3d& parent) {
        Eigen::Isometry3d local = Eigen::Isometry3d::Identity();
        local.linear() = rotation[std::size_t(n)].toRotationMatrix();
        local.translation() = translation[std::size_t(n)];
        const Eigen::Isometry3d world = parent * local;
        positions[model.nodes[std::size_t(n)].name] = world.translation();
        for (int child : model.nodes[std::size_t(n)].children) walk(child, world);
    };
    for (int root : model.scenes.front().nodes) walk(root, Eigen::Isometry3d::Identity());
    return positions;
}

tinygltf::Model loadGlb(const std::string& bytes)
{
    tinygltf::Model model;
    tinygltf::TinyGLTF loader;
    std::string error, warning;
    const bool loaded = loader.LoadBinaryFromMemory(&model, &error, &warning, reinterpret_cast<const unsigned char*>(bytes.data()),
                                                    unsigned(bytes.size()));
    INFO(error << warning);
    REQUIRE(loaded);
    return model;
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
    const tinygltf::Model model = loadGlb(bytes);
    CHECK(model.asset.version == "2.0");
    REQUIRE(model.skins.size() == 1);
    CHECK(model.skins[0].joints.size() == 22);
    REQUIRE(model.animations.size() == 1);
    REQUIRE(model.meshes.size() == 1);
    const auto times = floats(model, model.animations[0].samplers[0].input);
    REQUIRE(times.size() == std::size_t(take->frameCount()));
    CHECK(times.back() == Approx(double(take->frameCount() - 1) / 30.0).margin(1e-5));
    // Every joint's world position at sampled frames, read back through the node hierarchy.
    const Eigen::Quaterniond g = gltfAxisChange();
    double worst = 0.0;
    for (Eigen::Index f : {Eigen::Index(0), take->frameCount() / 3, take->frameCount() - 1}) {
        const auto positions = nodePositions(model, std::size_t(f));
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
