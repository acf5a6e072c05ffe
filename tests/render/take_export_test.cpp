// Writing a take by extension (render/take_export.h): a take without a skeleton goes to glTF as
// the puppet, its parts as joints carrying the puppet's meshes, posed as the 3D view poses them.
#include "render_test_support.h"

#include "analysis/body/body_pose.h"
#include "analysis/io/gltf_export.h"
#include "analysis/io/take_csv.h"
#include "render/puppet_geometry.h"
#include "render/take_export.h"
#include "tests/support/test_paths.h"

#include <tiny_gltf.h>

#include <fstream>
#include <iterator>

using namespace bunraku;

TEST_CASE("the puppet rig is the body's parts under a root, posed as the 3D view poses them", "[render][export]")
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
    REQUIRE(motion.skeleton->jointCount() == int(1 + body.parts.size()));
    CHECK(motion.frameCount() == take.frameCount());
    CHECK(rig->meshes.size() == body.parts.size());
    for (Eigen::Index f = 0; f < take.frameCount(); ++f) {
        const auto expected = analysis::worldPartPoses(body, take, f);
        const auto actual = motion.worldPoses(f);
        for (std::size_t p = 0; p < expected.size(); ++p) {
            CHECK(motion.skeleton->joints[p + 1].name == body.parts[p].name);
            CHECK((actual[p + 1].translation - expected[p].translation).norm() < 1e-12);
            CHECK(actual[p + 1].rotation.angularDistance(expected[p].rotation) < 1e-12);
        }
    }
}

TEST_CASE("a take without a skeleton exports as glTF with the puppet's mesh bound to its parts", "[render][export]")
{
    const auto body = analysis::defaultBodyDescription();
    const analysis::Take take = test::spreadArmsTake(4);
    const auto dir = test::scratchDir("take_export_puppet");
    REQUIRE(render::exportTake(take, body, dir / "puppet.glb").ok());
    std::ifstream in(dir / "puppet.glb", std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    tinygltf::Model model;
    tinygltf::TinyGLTF loader;
    std::string error, warning;
    REQUIRE(loader.LoadBinaryFromMemory(&model, &error, &warning, reinterpret_cast<const unsigned char*>(bytes.data()), unsigned(bytes.size())));
    REQUIRE(model.skins.size() == 1);
    CHECK(model.skins[0].joints.size() == 1 + body.parts.size());
    std::size_t vertices = 0;
    for (const auto& mesh : render::buildPuppetMeshes(body)) vertices += mesh.vertices.size();
    CHECK(model.accessors[std::size_t(model.meshes[0].primitives[0].attributes.at("POSITION"))].count == vertices);
    CHECK(model.animations[0].channels.size() == 2 * body.parts.size() + 1); // rotation + translation per part, the root's rotation
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
