#include "widgets/take_series.h"

#include "tests/widgets/synthetic_take.h"

#include <catch2/catch.hpp>

using namespace bunraku;

TEST_CASE("valueAt returns frame values at frame times and interpolates between them", "[widgets][take_series]")
{
    const auto take = test::syntheticPuppetTake(20);
    for (Eigen::Index k : {0, 7, 19}) {
        REQUIRE(widgets::valueAt(*take, 3, double(k) / 5.0).value() == Approx(test::syntheticValue(k, 3, 0.0)));
    }
    const double middle = 0.5 * (test::syntheticValue(4, 5, 0.0) + test::syntheticValue(5, 5, 0.0));
    REQUIRE(widgets::valueAt(*take, 5, 0.9).value() == Approx(middle));
}

TEST_CASE("valueAt has no value outside the take or for a missing channel", "[widgets][take_series]")
{
    const auto take = test::syntheticPuppetTake(20);
    REQUIRE_FALSE(widgets::valueAt(*take, 0, -0.5).has_value());
    REQUIRE_FALSE(widgets::valueAt(*take, 0, 19.0 / 5.0 + 0.01).has_value());
    REQUIRE_FALSE(widgets::valueAt(*take, 24, 1.0).has_value());
    REQUIRE(widgets::nearestFrame(*take, 100.0) == 19);
    REQUIRE(widgets::nearestFrame(*take, 0.29) == 1);
}

TEST_CASE("channelRange is the extreme values of a channel", "[widgets][take_series]")
{
    const auto take = test::syntheticPuppetTake(50);
    const auto range = widgets::channelRange(*take, 2).value();
    REQUIRE(range.lower == take->values.col(2).minCoeff());
    REQUIRE(range.upper == take->values.col(2).maxCoeff());
    REQUIRE(widgets::findChannel(*take, "arm", "pitch").value() == 16);
    REQUIRE_FALSE(widgets::findChannel(*take, "tail", "x").has_value());
}
