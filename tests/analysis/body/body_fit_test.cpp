// The puppet fitted to a performer's skeleton: proportions that follow the skeleton, on every
// fixture family and every shared Bandai file.
#include "analysis/body/body_fit.h"
#include "analysis/body/body_pose.h"
#include "analysis/core/puppet_layout.h"
#include "analysis/core/skeleton_anatomy.h"
#include "analysis/io/bvh_import.h"
#include "tests/support/bandai_files.h"
#include "tests/support/bvh_fixtures.h"

#include <catch2/catch.hpp>

using namespace bunraku::analysis;

namespace {

Take importedTake(const io::BvhFile& file)
{
    io::BvhImportOptions options;
    options.guessUnits = true;
    auto take = io::bvhToPuppetTake(file, options);
    INFO((take.ok() ? std::string() : take.error().message));
    REQUIRE(take.ok());
    return std::move(take).value();
}

/// World z range of a body part's solid at a frame (its mass-point lattice, 1 cm apart).
std::pair<double, double> heightRange(const BodyDescription& body, const Take& take, const std::string& part)
{
    const int index = body.partIndex(part);
    REQUIRE(index >= 0);
    const auto points = sampleMassPoints(body, MassPointOptions{1.0})[std::size_t(index)];
    const RigidTransform world_T_part = worldPartPoses(body, take, 0)[std::size_t(index)];
    double low = 1e9, high = -1e9;
    for (Eigen::Index k = 0; k < points.positions.cols(); ++k) {
        const double z = world_T_part.apply(points.positions.col(k)).z();
        low = std::min(low, z);
        high = std::max(high, z);
    }
    return {low, high};
}

/// True when the world point lies inside one of the part's primitives at frame 0.
bool inside(const BodyDescription& body, const Take& take, const std::string& part, const Eigen::Vector3d& world)
{
    const int index = body.partIndex(part);
    REQUIRE(index >= 0);
    const RigidTransform world_T_part = worldPartPoses(body, take, 0)[std::size_t(index)];
    for (const Primitive& primitive : body.parts[std::size_t(index)].primitives)
        if (primitive.containsLocal((world_T_part * primitive.part_T_primitive).inverse().apply(world))) return true;
    return false;
}

/// Head on the shoulders, the top of the head at the skeleton's, arm and hand over their bones.
void checkFitted(const Take& take)
{
    const BodyDescription& puppet = defaultBodyDescription();
    auto fitted = fitBodyToSkeleton(puppet, *take.skeleton);
    INFO((fitted.ok() ? std::string() : fitted.error().message));
    REQUIRE(fitted.ok());
    const BodyDescription& body = *fitted;
    REQUIRE(body.parts.size() == puppet.parts.size());
    PartJoints joints{};
    for (std::size_t p = 0; p < 4; ++p) joints[p] = take.skeleton->skeleton->binding(kPuppetParts[p])->joint;
    const auto landmarks = findLandmarks(*take.skeleton, joints, 0);
    REQUIRE(landmarks.ok());

    const auto head = heightRange(body, take, "head");
    const auto shoulder = heightRange(body, take, "shoulder");
    INFO("head " << head.first << ".." << head.second << " cm, shoulder " << shoulder.first << ".." << shoulder.second << " cm");
    // The neck's foot rests in the shoulders (an overlap of a few cm), not above them.
    CHECK(head.first - shoulder.second < 1.0);
    CHECK(head.first - shoulder.second > -8.0);
    CHECK(head.second == Approx(landmarks->headTop.z()).margin(4.0));
    CHECK(shoulder.second == Approx(landmarks->neckBase.z()).margin(2.0));
    CHECK(inside(body, take, "head", landmarks->head));
    CHECK(inside(body, take, "right_arm", 0.5 * (landmarks->elbow + landmarks->wrist)));
    CHECK(inside(body, take, "right_hand", 0.5 * (landmarks->wrist + landmarks->fingerTip)));
    CHECK(inside(body, take, "shoulder", 0.5 * (landmarks->neckBase + landmarks->hips)));
    // The mirrored limbs are the fitted ones reflected.
    const auto& right = body.parts[std::size_t(body.partIndex("right_arm"))].primitives;
    const auto& left = body.parts[std::size_t(body.partIndex("left_arm"))].primitives;
    REQUIRE(right.size() == left.size());
    CHECK(left.front().length == Approx(right.front().length));
    CHECK(left.front().part_T_primitive.translation.y() == Approx(-right.front().part_T_primitive.translation.y()));
}

} // namespace

TEST_CASE("a 170 cm performer's head sits on the shoulders of the fitted puppet (classic naming)")
{
    for (const auto& family : bunraku::test::bvhFamilies()) {
        if (family.id != "classic") continue;
        auto file = io::parseBvh(bunraku::test::fixtureBvh(family), "classic.bvh");
        REQUIRE(file.ok());
        const Take take = importedTake(*file);
        // The unfitted puppet's head floats: its neck is 15 cm long, a person's 28 cm.
        const auto head = heightRange(defaultBodyDescription(), take, "head");
        const auto shoulder = heightRange(defaultBodyDescription(), take, "shoulder");
        CHECK(head.first - shoulder.second > 8.0);
        checkFitted(take);
        const BodyDescription fitted = bodyForTake(defaultBodyDescription(), take);
        CHECK(fitted.name == defaultBodyDescription().name + ", fitted to classic");
        CHECK(fitted.mass() > 3.0 * defaultBodyDescription().mass()); // a person, not a 1 m puppet
    }
}

TEST_CASE("the puppet fitted to every fixture family sits on its skeleton")
{
    for (const auto& family : bunraku::test::bvhFamilies()) {
        INFO(family.id);
        auto file = io::parseBvh(bunraku::test::fixtureBvh(family), family.id + ".bvh");
        REQUIRE(file.ok());
        checkFitted(importedTake(*file));
    }
}

TEST_CASE("the puppet fitted to every bandai file sits on its skeleton")
{
    for (const auto& path : bunraku::test::bandaiFilesOrSkip()) {
        INFO(path.filename().string());
        auto file = io::readBvh(path);
        REQUIRE(file.ok());
        checkFitted(importedTake(*file));
    }
}

TEST_CASE("a take without a skeleton keeps the puppet's own body")
{
    Take take;
    take.channels = puppetChannels();
    take.values = Eigen::MatrixXd::Zero(2, kPuppetChannelCount);
    const BodyDescription body = bodyForTake(defaultBodyDescription(), take);
    CHECK(body.name == defaultBodyDescription().name);
    CHECK(body.mass() == defaultBodyDescription().mass());
}
