// The warp CSV and gains JSON readers check every field: exact columns, nothing after a number,
// a byte order mark, frames within bounds; phrases in order, disjoint, whole and bounded.
#include "analysis/design/phrase_gains.h"
#include "analysis/design/warp_curve.h"

#include <catch2/catch.hpp>

#include <string>

using namespace bunraku::analysis;
using Catch::Matchers::Contains;

namespace {

/// A gains document with phrases from {begin, end} pairs (JSON text) and `blend` (JSON text).
/// Strings are built stepwise: GCC 12 warns falsely (-Wrestrict) on chains of operator+.
std::string gainsJson(std::initializer_list<std::pair<const char*, const char*>> phrases, const char* blend = "3")
{
    std::string out = R"({"dofs": ["a", "b"], "blend_frames": )";
    out += blend;
    out += R"(, "phrases": [)";
    bool first = true;
    for (const auto& [begin, end] : phrases) {
        if (!first) out += ", ";
        first = false;
        out += R"({"begin": )";
        out += begin;
        out += R"(, "end": )";
        out += end;
        out += R"(, "gains": [{"g0": 1, "g1": 2}, {"g0": 1.5, "g1": 1}]})";
    }
    out += "]}";
    return out;
}

} // namespace

TEST_CASE("warp CSV lines with trailing junk, a third column or a bad header are errors with the line", "[design][files]")
{
    const auto error = [](const std::string& text) {
        auto curve = parseWarpCsv(text, "w.csv");
        REQUIRE_FALSE(curve.ok());
        return curve.error().message;
    };
    CHECK_THAT(error("output_frame,source_frame\n0,0\n24,17xyz\n"), Contains("w.csv:3") && Contains("17xyz"));
    CHECK_THAT(error("output_frame,source_frame\n0,0\n24,17,3\n"), Contains("w.csv:3") && Contains("3 fields"));
    CHECK_THAT(error("frames\n0,0\n24,17\n"), Contains("w.csv:1"));
    CHECK_THAT(error("0,0\n24,nan\n"), Contains("w.csv:2"));
    CHECK_THAT(error("0,0\n24,-1\n"), Contains("w.csv:2"));
    CHECK_THAT(error("0,0\n0,1\n"), Contains("w.csv:2") && Contains("increase"));
    CHECK_THAT(error("0,0\n10000000,40\n"), Contains("w.csv:2") && Contains("output_frame"));
    CHECK_THAT(error("0,0\n1e9,40\n"), Contains("w.csv:2"));
    CHECK_THAT(error("0,0\n"), Contains("2 control points"));
}

TEST_CASE("a byte order mark before a header-less warp keeps its first point", "[design][files]")
{
    auto curve = parseWarpCsv("\xEF\xBB\xBF" "0,0\r\n8,5.5\r\n20,21.25\r\n", "bom.csv");
    REQUIRE(curve.ok());
    REQUIRE(curve->points.size() == 3);
    CHECK(curve->points.front() == WarpPoint{0, 0});
    CHECK(curve->outputFrames == 21);
    auto headed = parseWarpCsv("\xEF\xBB\xBF" "output_frame,source_frame\n0,0\n8,5.5\n", "bom.csv");
    REQUIRE(headed.ok());
    CHECK(headed->points.size() == 2);
}

TEST_CASE("gains phrases must be in order, disjoint, whole and bounded", "[design][files]")
{
    const auto good = parseGainsJson(gainsJson({{"0", "40"}, {"40", "105"}}), "g.json");
    REQUIRE(good.ok());
    CHECK(good->phrases.size() == 2);
    CHECK(good->phrases[1].dofs[0].g1 == 2.0);

    const auto error = [](const std::string& text) {
        auto gains = parseGainsJson(text, "g.json");
        REQUIRE_FALSE(gains.ok());
        return gains.error().message;
    };
    CHECK_THAT(error(gainsJson({{"40", "0"}})), Contains("g.json") && Contains("phrases[0]"));
    CHECK_THAT(error(gainsJson({{"0", "40"}, {"30", "105"}})), Contains("phrases[1]"));     // overlap
    CHECK_THAT(error(gainsJson({{"0", "40"}, {"50", "105"}})), Contains("phrases[1]"));     // gap
    CHECK_THAT(error(gainsJson({{"40", "105"}, {"0", "40"}})), Contains("phrases[0]"));     // unsorted
    CHECK_THAT(error(gainsJson({{"-5", "40"}})), Contains("phrases[0].begin"));
    CHECK_THAT(error(gainsJson({{"0", "40.5"}})), Contains("phrases[0].end"));
    CHECK_THAT(error(gainsJson({{"0", "18446744073709551616"}})), Contains("phrases[0].end"));
    CHECK_THAT(error(gainsJson({{"0", "1e300"}})), Contains("phrases[0].end"));
    CHECK_THAT(error(gainsJson({{"0", "40"}}, "-5")), Contains("blend_frames"));
    CHECK_THAT(error(gainsJson({{"0", "40"}}, "1e300")), Contains("blend_frames"));
    CHECK_THAT(error(gainsJson({{"0", "40"}}, "2.5")), Contains("blend_frames"));
    CHECK_THAT(error(R"({"dofs": ["a"], "phrases": [{"begin": 0, "end": 4, "gains": [{"g0": 1e400}]}]})"), Contains("g.json"));
    CHECK_THAT(error(R"({"dofs": ["a"], "phrases": [{"begin": 0, "end": 4, "gains": [{"g1": 0}]}]})"), Contains("non-zero"));
    CHECK_THAT(error(R"({"dofs": ["a"], "phrases": [{"begin": 0, "end": 4, "gains": [{"offset": 1e20}]}]})"), Contains("offset"));
    CHECK_THAT(error(R"({"dofs": ["a", "a"], "phrases": []})"), Contains("dofs[1]"));
    CHECK_THAT(error("[1, 2]"), Contains("g.json"));
}
