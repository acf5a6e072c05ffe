#include "analysis/core/puppet_layout.h"
#include "analysis/core/take.h"

#include <catch2/catch.hpp>

#include <limits>

using namespace bunraku::analysis;

TEST_CASE("the puppet layout has 24 channels head.x to hand.roll", "[take]")
{
    const auto channels = puppetChannels();
    REQUIRE(channels.size() == 24);
    CHECK(channels.front().name() == "head.x");
    CHECK(channels[puppetChannel(2, Dof::Pitch)].name() == "arm.pitch");
    CHECK(channels.back().name() == "hand.roll");
    CHECK(channels[3].unit == "deg");
    CHECK(channels[2].unit == "cm");
}

TEST_CASE("channels are found by part and dof or by name", "[take]")
{
    Take take;
    take.channels = puppetChannels();
    take.values = Eigen::MatrixXd::Zero(3, 24);
    CHECK(take.channelIndex("hand", "yaw") == 21);
    CHECK(take.channelIndex("shoulder.z") == 8);
    CHECK_FALSE(take.channelIndex("knee.z").has_value());
    CHECK_FALSE(take.channelIndex("nodot").has_value());
    CHECK(take.parts() == std::vector<std::string>{"head", "shoulder", "arm", "hand"});
    CHECK(hasPuppetLayout(take));
    const auto parts = sixDofParts(take);
    REQUIRE(parts.size() == 4);
    CHECK(parts[3].part == "hand");
    CHECK(parts[3].firstChannel == 18);
}

TEST_CASE("validation names the first non-finite value", "[take]")
{
    Take take;
    take.channels = puppetChannels();
    take.values = Eigen::MatrixXd::Zero(10, 24);
    take.labels = {"greeting", "none", 2, ""};
    CHECK(validateTake(take).ok());
    take.values(7, 5) = std::numeric_limits<double>::quiet_NaN();
    const auto status = validateTake(take);
    REQUIRE_FALSE(status.ok());
    CHECK(status.error().message == "greeting/none/2: non-finite value at frame 7, channel head.roll");
    take.values(7, 5) = 0.0;
    take.channels.pop_back();
    CHECK_FALSE(validateTake(take).ok());
}

TEST_CASE("validation refuses sample rates no recording has", "[take]")
{
    Take take;
    take.channels = puppetChannels();
    take.values = Eigen::MatrixXd::Zero(3, 24);
    for (double rate : {120.0, 1.0e-3, kMaxRateHz}) {
        take.rateHz = rate;
        CHECK(validateTake(take).ok());
    }
    for (double rate : {0.0, -5.0, 1.0e300, kMaxRateHz * 1.01, std::numeric_limits<double>::infinity(),
                        std::numeric_limits<double>::quiet_NaN()}) {
        take.rateHz = rate;
        const auto status = validateTake(take);
        INFO(rate);
        REQUIRE_FALSE(status.ok());
        CHECK(status.error().message.find("(0, 1000000] Hz") != std::string::npos);
    }
}
