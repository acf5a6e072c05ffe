// The performer's body: one closed surface around every bone of any skeleton family and of the
// Bandai takes, skinned so that it follows the skeleton (every joint inside it at every frame).
#include "analysis/body/performer_body.h"
#include "analysis/body/dual_quaternion.h"
#include "analysis/body/surface_nets.h"
#include "analysis/io/bvh.h"
#include "analysis/io/bvh_import.h"
#include "tests/support/bandai_files.h"
#include "tests/support/bvh_fixtures.h"

#include <catch2/catch.hpp>

#include <map>

using namespace bunraku;

namespace {

/// Skins the body's vertices to `frame` (dual quaternions, as the renderer does).
std::vector<Eigen::Vector3d> skinned(const analysis::PerformerBody& body, const analysis::SkeletalMotion& motion, Eigen::Index frame)
{
    const auto transforms = analysis::bodySkinningTransforms(body, motion.worldPoses(frame));
    std::vector<analysis::DualQuaternion> q;
    for (const auto& t : transforms) q.push_back(analysis::DualQuaternion::fromRigid(t));
    std::vector<Eigen::Vector3d> out;
    for (std::size_t v = 0; v < body.mesh.vertexCount(); ++v) {
        analysis::DualQuaternion four[4];
        double weights[4];
        for (int k = 0; k < 4; ++k) {
            four[k] = q[body.mesh.joints[v][std::size_t(k)]];
            weights[k] = double(body.mesh.weights[v][k]);
        }
        out.push_back(analysis::blendDualQuaternions(four, weights, 4).toRigid().apply(body.mesh.positions[v].cast<double>()));
    }
    return out;
}

void checkBody(const analysis::SkeletalMotion& motion, const std::string& name)
{
    INFO(name);
    auto made = analysis::performerBody(motion);
    INFO((made.ok() ? std::string() : made.error().message));
    REQUIRE(made.ok());
    const analysis::PerformerBody& body = *made;
    const analysis::PuppetMesh& mesh = body.mesh;
    CHECK(body.height > 1.0f); // cm, or the units of a file read without its unit
    CHECK(mesh.triangleCount() > 2000);
    // One closed piece: a single component, no edge on the border of a hole (surface nets may
    // pinch where two parts of the surface meet within a cell: an edge of four triangles).
    int components = 0;
    analysis::meshComponents(mesh.vertexCount(), mesh.indices, &components);
    CHECK(components == 1);
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
    for (std::size_t i = 0; i < mesh.indices.size(); i += 3)
        for (int e = 0; e < 3; ++e) {
            const std::uint32_t a = mesh.indices[i + std::size_t(e)], b = mesh.indices[i + std::size_t((e + 1) % 3)];
            ++edges[{std::min(a, b), std::max(a, b)}];
        }
    int open = 0, pinched = 0;
    for (const auto& [edge, uses] : edges) {
        open += uses % 2 == 1 ? 1 : 0;
        pinched += uses > 2 ? 1 : 0;
    }
    CHECK(open == 0);
    CHECK(pinched <= 20);
    // Weights sum to one and name joints of the skeleton.
    int badWeights = 0;
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
        badWeights += std::abs(mesh.weights[v].sum() - 1.0f) < 1e-4f ? 0 : 1;
        for (const auto j : mesh.joints[v]) badWeights += j < motion.skeleton->joints.size() ? 0 : 1;
    }
    CHECK(badWeights == 0);
    // The surface follows the skeleton: at sampled frames every vertex stays near the bone it
    // moves with - within the body's thickest radius of its dominant joint's bones.
    for (const Eigen::Index frame : {Eigen::Index(0), motion.frameCount() / 2, motion.frameCount() - 1}) {
        const auto poses = motion.worldPoses(frame);
        const auto vertices = skinned(body, motion, frame);
        double worst = 0.0;
        for (std::size_t v = 0; v < vertices.size(); ++v) {
            const int j = mesh.dominantJoint(v);
            double nearest = (vertices[v] - poses[std::size_t(j)].translation).norm();
            for (const int child : motion.skeleton->children(j)) {
                const Eigen::Vector3d a = poses[std::size_t(j)].translation, b = poses[std::size_t(child)].translation;
                const double t = std::clamp((vertices[v] - a).dot(b - a) / std::max((b - a).squaredNorm(), 1e-9), 0.0, 1.0);
                nearest = std::min(nearest, (vertices[v] - (a + t * (b - a))).norm());
            }
            worst = std::max(worst, nearest);
        }
        INFO("frame " << frame << ": the farthest vertex is " << worst << " cm from its joint's bones");
        CHECK(worst < 0.16 * body.height);
    }
}

} // namespace

TEST_CASE("the performer's body is one closed surface that follows every fixture family's skeleton", "[body][performer]")
{
    for (const auto& family : test::bvhFamilies()) {
        auto file = analysis::io::parseBvh(test::fixtureBvh(family, 12), family.id + ".bvh");
        REQUIRE(file.ok());
        auto motion = analysis::io::bvhToSkeletalMotion(*file);
        REQUIRE(motion.ok());
        checkBody(**motion, family.id);
    }
}

TEST_CASE("the performer's body is one closed surface that follows every Bandai take's skeleton", "[body][performer]")
{
    for (const auto& path : test::bandaiFilesOrSkip()) {
        auto file = analysis::io::readBvh(path);
        REQUIRE(file.ok());
        auto motion = analysis::io::bvhToSkeletalMotion(*file);
        REQUIRE(motion.ok());
        checkBody(**motion, path.filename().string());
    }
}
