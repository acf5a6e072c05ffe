// The chains coupling (thesis 3.6 generalised to a skeleton) on every fixture family
// (tests/support/bvh_fixtures.h): the root, the spine up to the head, each arm and each leg.
#include "analysis/core/puppet_layout.h"
#include "analysis/io/bvh.h"
#include "analysis/io/bvh_import.h"
#include "analysis/normalise/coupling.h"
#include "analysis/normalise/skeleton_chains.h"
#include "tests/support/bvh_fixtures.h"
#include "tests/support/fixture_joint_take.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <map>
#include <set>

using namespace bunraku::analysis;
using bunraku::test::BvhFamily;

TEST_CASE("skeleton chains are found on every fixture family", "[coupling][chains]")
{
    for (const BvhFamily& family : bunraku::test::bvhFamilies()) {
        INFO(family.id);
        const Take take = bunraku::test::fixtureJointTake(family);
        const Skeleton& skeleton = *take.skeleton->skeleton;
        auto chains = skeletonChains(*take.skeleton);
        REQUIRE(chains.ok());
        std::vector<std::string> names;
        std::map<std::string, std::string> chainOf; // joint name -> chain name
        for (const auto& chain : *chains) {
            names.push_back(chain.name);
            for (int j : chain.joints) {
                CHECK_FALSE(skeleton.joints[std::size_t(j)].endSite);
                CHECK(chainOf.emplace(skeleton.joints[std::size_t(j)].name, chain.name).second); // each joint once
            }
        }
        CHECK(names == std::vector<std::string>{"root", "spine", "left_arm", "right_arm", "left_leg", "right_leg"});
        CHECK(int(chainOf.size()) == skeleton.jointCount());
        CHECK(chainOf[bunraku::test::fixtureJointAt(family, "hips")] == "root");
        CHECK(chainOf[family.expected[0]] == "spine"); // the head
        CHECK(chainOf[bunraku::test::fixtureJointAt(family, "neck")] == "spine");
        CHECK(chainOf[family.expected[2]] == "right_arm"); // forearm
        CHECK(chainOf[family.expected[3]] == "right_arm"); // hand
        CHECK(chainOf[family.expectedLeft[0]] == "left_arm");
        CHECK(chainOf[family.expectedLeft[1]] == "left_arm");
        for (const std::string side : {"L", "R"}) {
            const std::string leg = side == "L" ? "left_leg" : "right_leg";
            CHECK(chainOf[bunraku::test::fixtureJointAt(family, "knee" + side)] == leg);
            CHECK(chainOf[bunraku::test::fixtureJointAt(family, "ankle" + side)] == leg);
            CHECK(chainOf[bunraku::test::fixtureJointAt(family, "shoulder" + side)] == (side == "L" ? "left_arm" : "right_arm"));
        }
        // Face joints (eyes, jaw) and a head-top joint ride with the head.
        for (const std::string point : {"eyeL", "eyeR", "jaw", "headtop"})
            if (const std::string joint = bunraku::test::fixtureJointAt(family, point); !joint.empty()) CHECK(chainOf[joint] == "spine");

        // The coupling: per coordinate, each chain's channels together, named "left_leg.x".
        const auto coupling = couplingFor(take, "chains");
        REQUIRE(coupling.ok());
        CHECK(coupling->preset == "chains");
        CHECK(coupling->sets.size() == 6 * 6);
        CHECK(std::find(coupling->names.begin(), coupling->names.end(), "left_leg.x") != coupling->names.end());
        CHECK(std::find(coupling->names.begin(), coupling->names.end(), "spine.yaw") != coupling->names.end());
        std::vector<int> seen(take.channels.size(), 0);
        for (std::size_t s = 0; s < coupling->sets.size(); ++s) {
            const std::string chain = coupling->names[s].substr(0, coupling->names[s].find('.'));
            const std::string dof = coupling->names[s].substr(coupling->names[s].find('.') + 1);
            for (auto c : coupling->sets[s]) {
                ++seen[std::size_t(c)];
                CHECK(take.channels[std::size_t(c)].dof == dof);
                CHECK(chainOf[take.channels[std::size_t(c)].part] == chain);
            }
        }
        CHECK(std::all_of(seen.begin(), seen.end(), [](int n) { return n == 1; }));
        // The default on a take of more parts than the puppet's four is the chains coupling.
        const auto automatic = couplingFor(take, "auto");
        REQUIRE(automatic.ok());
        CHECK(automatic->preset == "chains");
        CHECK(automatic->sets == coupling->sets);
    }
}

TEST_CASE("the chains coupling of a puppet take couples as method2 and auto keeps method2", "[coupling][chains]")
{
    const auto families = bunraku::test::bvhFamilies();
    const BvhFamily& family = families.front(); // bandai
    auto file = io::parseBvh(bunraku::test::fixtureBvh(family, 12), family.id + ".bvh");
    REQUIRE(file.ok());
    io::BvhImportOptions options;
    options.guessUnits = true;
    auto take = io::bvhToPuppetTake(*file, options);
    REQUIRE(take.ok());
    const auto method2 = couplingFor(*take, "method2");
    const auto chains = couplingFor(*take, "chains");
    const auto automatic = couplingFor(*take, "auto");
    REQUIRE(method2.ok());
    REQUIRE(chains.ok());
    REQUIRE(automatic.ok());
    CHECK(chains->sets == method2->sets);   // head+shoulder in the spine, arm+hand in the right arm
    CHECK(chains->names[0] == "spine.x");
    CHECK(chains->names[1] == "right_arm.x");
    CHECK(automatic->preset == "method2");
    CHECK(automatic->sets == method2->sets);
    CHECK(automatic->names == method2->names);

    // Without a skeleton: the puppet's two chains; neither parts nor a skeleton: a clear error.
    Take bare = *take;
    bare.skeleton.reset();
    CHECK(couplingFor(bare, "chains")->sets == method2->sets);
    Take axis;
    axis.channels = sixDofChannels("axis");
    axis.values = Eigen::MatrixXd::Zero(10, 6);
    const auto none = couplingFor(axis, "chains");
    REQUIRE_FALSE(none.ok());
    CHECK(none.error().message.find("skeleton") != std::string::npos);
    CHECK(couplingFor(axis, "auto").error().message.find("neither") != std::string::npos);
}
