// Reading and importing a long BVH take report their progress and stop when asked, and give the
// same take as a read without a control (analysis/io/bvh.h, bvh_import.h).
#include "analysis/io/bvh.h"
#include "analysis/io/bvh_import.h"
#include "analysis/synth/long_take.h"

#include <catch2/catch.hpp>

#include <stop_token>
#include <vector>

using namespace bunraku::analysis;

namespace {

std::string longText(Eigen::Index frames)
{
    synth::LongTakeOptions options;
    options.frames = frames;
    auto text = synth::longTakeBvh(options);
    REQUIRE(text.ok());
    return std::move(text).value();
}

} // namespace

TEST_CASE("a long BVH take is parsed with its progress, and the values do not depend on it", "[io][bvh][progress]")
{
    const std::string text = longText(10000);
    std::vector<double> fractions;
    const RunControl control{{}, [&](double fraction) { fractions.push_back(fraction); }};
    const auto watched = io::parseBvh(text, "long.bvh", control);
    const auto plain = io::parseBvh(text, "long.bvh");
    REQUIRE(watched.ok());
    REQUIRE(plain.ok());
    CHECK(watched->motion.values == plain->motion.values);
    // One report every 4096 rows: 4096 and 8192 of 10000.
    REQUIRE(fractions.size() == 2);
    CHECK(fractions[0] == Approx(0.4096));
    CHECK(fractions[1] == Approx(0.8192));
}

TEST_CASE("a long BVH take stops being parsed or imported when its stop is requested", "[io][bvh][progress]")
{
    const std::string text = longText(10000);
    SECTION("while parsing: at the next 4096 rows, with the file and the frame")
    {
        std::stop_source stop;
        const RunControl control{stop.get_token(), [&](double) { stop.request_stop(); }};
        const auto parsed = io::parseBvh(text, "long.bvh", control);
        REQUIRE_FALSE(parsed.ok());
        CHECK(parsed.error().code == ErrorCode::Cancelled);
        CHECK(parsed.error().message == "long.bvh: reading stopped at frame 8192");
    }
    SECTION("while importing: between two joints, after a fraction of them")
    {
        const auto parsed = io::parseBvh(text, "long.bvh");
        REQUIRE(parsed.ok());
        std::stop_source stop;
        std::vector<double> fractions;
        const RunControl control{stop.get_token(), [&](double fraction) {
                                     fractions.push_back(fraction);
                                     if (fractions.size() == 5) stop.request_stop();
                                 }};
        const auto imported = io::importBvhPuppet(*parsed, {}, control);
        REQUIRE_FALSE(imported.ok());
        CHECK(imported.error().code == ErrorCode::Cancelled);
        CHECK(fractions.size() == 5);
        CHECK(fractions.back() == Approx(0.9 * 4.0 / double(parsed->skeleton.joints.size())));
    }
    SECTION("not stopped: every joint is reported and the take is the plain import's")
    {
        const auto parsed = io::parseBvh(text, "long.bvh");
        REQUIRE(parsed.ok());
        std::vector<double> fractions;
        const auto watched = io::importBvhPuppet(*parsed, {}, RunControl{{}, [&](double f) { fractions.push_back(f); }});
        const auto plain = io::importBvhPuppet(*parsed);
        REQUIRE(watched.ok());
        REQUIRE(plain.ok());
        CHECK(fractions.size() == parsed->skeleton.joints.size()); // joints and End Sites
        CHECK(watched->take.values == plain->take.values);
    }
}
