// Writing a take by extension (render/take_export.h): a take without a skeleton goes to glTF as
// the modelled puppet, its joints posed as the 3D view poses them and its surface skinned to them.
#include "render_test_support.h"

#include "analysis/body/body_pose.h"
#include "analysis/body/puppet_model.h"
#include "analysis/io/gltf_export.h"
#include "analysis/io/take_csv.h"
#include "render/puppet_geometry.h"
#include "render/take_export.h"
#include "tests/support/gltf_readback.h"
#include "tests/support/test_paths.h"

#include <tiny_gltf.h>

#include <fstream>
#include <iterator>

using namespace bunraku;

TEST_CASE("the puppet rig is the modelled puppet's joints under a root posed as the 3D view poses them", "[render][export]")
{
    const auto body = analysis::defaultBodyDescription();
    const analysis::Take take = test::puppetTake(6, [](Eigen::Index f) {
        const double t = double(f);
        return std::array<test::PartPose, 4>{test::PartPose{4, 0, 122, 10 * t, 0, 0}, test::PartPose{0, 0, 100, 0, 5 * t, 0},
                                             test::PartPose{0, -27, 99, -90, 0, 3 * t}, test::PartPose{0, -43, 99, -90 + t, 0, 0}};
    });
    auto rig = render::puppetRig(body, take);
    REQUIRE(rig.ok());
    const analysis::SkeletalMotion& motion = *rig->motion;
    REQUIRE(motion.skeleton->jointCount() == 1 + analysis::kPuppetJointCount);
    CHECK(motion.frameCount() == take.frameCount());
    CHECK(rig->meshes.empty());
    const analysis::PuppetMesh& puppet = analysis::shippedPuppetMesh();
    for (Eigen::Index f = 0; f < take.frameCount(); ++f) {
        const auto parts = analysis::worldPartPoses(body, take, f);
        const auto expected = analysis::puppetJointPoses(puppet, body, parts);
        const auto actual = motion.worldPoses(f);
        for (int j = 0; j < analysis::kPuppetJointCount; ++j) {
            CHECK(motion.skeleton->joints[std::size_t(j) + 1].name == analysis::kPuppetJointNames[std::size_t(j)]);
            CHECK((actual[std::size_t(j) + 1].translation - expected[std::size_t(j)].translation).norm() < 1e-12);
            CHECK(actual[std::size_t(j) + 1].rotation.angularDistance(expected[std::size_t(j)].rotation) < 1e-12);
        }
        // The six parts' joints are the parts' own poses.
        const auto partOf = analysis::puppetJointPartIndices(body);
        for (int j = 0; j < 6; ++j)
            CHECK((actual[std::size_t(j) + 1].translation - parts[std::size_t(partOf[std::size_t(j)])].translation).norm() < 1e-12);
    }
    // The skinned surface is the model's: its vertices, colours, bind poses and four weights.
    const analysis::io::SkinnedMesh& mesh = rig->skinned;
    REQUIRE(mesh.positions.size() == puppet.vertexCount());
    CHECK(mesh.indices == puppet.indices);
    CHECK(mesh.colours == puppet.colours);
    REQUIRE(mesh.bindPoses.size() == std::size_t(1 + analysis::kPuppetJointCount));
    for (int j = 0; j < analysis::kPuppetJointCount; ++j)
        CHECK((mesh.bindPoses[std::size_t(j) + 1].translation - puppet.bindPoses[std::size_t(j)].translation).norm() < 1e-12);
    for (std::size_t v = 0; v < mesh.positions.size(); v += 97) {
        CHECK(std::abs(mesh.weights[v].sum() - 1.0f) < 1e-5f);
        for (int k = 0; k < 4; ++k)
            if (mesh.weights[v][k] > 0.0f) CHECK(mesh.joints[v][std::size_t(k)] == 1 + puppet.joints[v][std::size_t(k)]);
    }
}

TEST_CASE("a take without a skeleton exports as glTF with the modelled puppet skinned to its joints", "[render][export]")
{
    const auto body = analysis::defaultBodyDescription();
    const analysis::Take take = test::spreadArmsTake(4);
    const auto dir = test::scratchDir("take_export_puppet");
    REQUIRE(render::exportTake(take, body, dir / "puppet.glb").ok());
    const tinygltf::Model model = test::loadGlbBytes(test::readBinaryFile((dir / "puppet.glb").string()));
    REQUIRE(model.skins.size() == 1);
    REQUIRE(model.meshes.size() == 1);
    CHECK(model.skins[0].joints.size() == std::size_t(1 + analysis::kPuppetJointCount));
    const analysis::PuppetMesh& puppet = analysis::shippedPuppetMesh();
    const auto& primitive = model.meshes[0].primitives.at(0);
    CHECK(model.accessors[std::size_t(primitive.attributes.at("POSITION"))].count == puppet.vertexCount());
    CHECK(model.accessors[std::size_t(primitive.indices)].count == puppet.indices.size());
    // Rotation for every joint, translation for the puppet's joints (not the root).
    CHECK(model.animations[0].channels.size() == std::size_t(2 * analysis::kPuppetJointCount + 1));

    // A glTF client's linear blend of the file's skin at each frame is the model's surface
    // blended linearly from the view's joint poses (to float precision), and lies close to the
    // view's dual quaternion skinning (analysis::skinPuppet): docs/FORMATS.md.
    const auto weights = test::gltfFloats(model, primitive.attributes.at("WEIGHTS_0"));
    const auto positions = test::gltfFloats(model, primitive.attributes.at("POSITION"));
    const auto inverseBind = test::gltfFloats(model, model.skins[0].inverseBindMatrices);
    const tinygltf::Accessor& jointsAccessor = model.accessors[std::size_t(primitive.attributes.at("JOINTS_0"))];
    REQUIRE(jointsAccessor.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
    const tinygltf::BufferView& jointsView = model.bufferViews[std::size_t(jointsAccessor.bufferView)];
    const auto* joints = reinterpret_cast<const std::uint16_t*>(model.buffers[0].data.data() + jointsView.byteOffset + jointsAccessor.byteOffset);
    const Eigen::Quaterniond g = analysis::io::gltfAxisChange();
    const auto binding = analysis::bindBody(body, take);
    REQUIRE(binding.ok());
    for (Eigen::Index f = 0; f < take.frameCount(); ++f) {
        const auto nodes = test::gltfNodePoses(model, std::size_t(f));
        std::vector<Eigen::Matrix4d> skinning;
        for (std::size_t k = 0; k < model.skins[0].joints.size(); ++k) {
            Eigen::Matrix4d ibm;
            for (int c = 0; c < 4; ++c)
                for (int r = 0; r < 4; ++r) ibm(r, c) = inverseBind[16 * k + std::size_t(4 * c + r)];
            skinning.push_back(nodes.at(model.nodes[std::size_t(model.skins[0].joints[k])].name).matrix() * ibm);
        }
        const auto jointPoses = analysis::puppetJointPoses(puppet, body, analysis::worldPartPoses(body, *binding, take, f));
        const auto view = analysis::skinPuppet(puppet, jointPoses);
        double sum = 0.0, worst = 0.0, linearWorst = 0.0;
        for (std::size_t v = 0; v < puppet.vertexCount(); ++v) {
            double total = 0.0;
            Eigen::Vector4d p = Eigen::Vector4d::Zero();
            Eigen::Vector3d linear = Eigen::Vector3d::Zero();
            for (int k = 0; k < 4; ++k) {
                const double w = weights[4 * v + std::size_t(k)];
                total += w;
                p += w * skinning[joints[4 * v + std::size_t(k)]] * Eigen::Vector4d(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2], 1.0);
                const int j = puppet.joints[v][std::size_t(k)];
                linear += double(puppet.weights[v][k]) *
                          (jointPoses[std::size_t(j)] * puppet.bindPoses[std::size_t(j)].inverse()).apply(puppet.positions[v].cast<double>());
            }
            REQUIRE(std::abs(total - 1.0) < 1e-6);
            const Eigen::Vector3d file = 100.0 * (g.conjugate() * p.head<3>()); // workbench axes, cm
            linearWorst = std::max(linearWorst, (file - linear).norm());
            const double d = (file - view.positions[v].cast<double>()).norm();
            sum += d;
            worst = std::max(worst, d);
        }
        INFO("frame " << f << ": from the model blended linearly: worst " << linearWorst << " cm; from the view's dual quaternion skinning: mean "
                      << sum / double(puppet.vertexCount()) << " cm, worst " << worst << " cm");
        CHECK(linearWorst < 1e-3);
        CHECK(sum / double(puppet.vertexCount()) < 0.5);
        CHECK(worst < 5.0);
    }

    // CSV and BVH go through the take writers; anything else is refused, naming the file.
    REQUIRE(render::exportTake(take, body, dir / "puppet.csv").ok());
    auto back = analysis::io::readTakeCsv(dir / "puppet.csv");
    REQUIRE(back.ok());
    CHECK((back->values - take.values).cwiseAbs().maxCoeff() < 1e-9);
    const auto refused = render::exportTake(take, body, dir / "puppet.fbx");
    REQUIRE_FALSE(refused.ok());
    CHECK_THAT(refused.error().message, Catch::Contains("puppet.fbx") && Catch::Contains(".glb"));
    CHECK_FALSE(std::filesystem::exists(dir / "puppet.fbx"));
}
