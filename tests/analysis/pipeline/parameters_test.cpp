#include "analysis/pipeline/parameters_json.h"

#include <catch2/catch.hpp>

using namespace bunraku::analysis;
using namespace bunraku::analysis::pipeline;
using nlohmann::json;

namespace {

std::string errorOf(const json& parameters)
{
    auto read = chainParametersFromJson(parameters, "p.json");
    REQUIRE_FALSE(read.ok());
    return read.error().message;
}

} // namespace

TEST_CASE("the chain's defaults are the thesis's but the normalisation path: normalised takes into KM2O with M chosen by P",
          "[pipeline][parameters]")
{
    const ChainParameters defaults;
    // The optimal path, not the thesis's greedy scan (docs/NORMALISATION.md, "Real takes").
    CHECK(defaults.normalise.path == PathMethod::Optimal);
    CHECK(defaults.normalise.options().match.path == PathMethod::Optimal);
    CHECK(defaults.normalise.reference == ReferenceChoice{}); // the suggested take (3.6.1)
    CHECK(defaults.normalise.tau == 4);
    CHECK(defaults.normalise.searchBand == 20);
    CHECK(defaults.normalise.maxScale == 16);
    CHECK(defaults.normalise.coupling == "auto");
    CHECK(defaults.decompose.input == DecomposeInput::Normalised);
    CHECK(defaults.decompose.method == DecomposeMethod::Km2o);
    CHECK(defaults.decompose.correlationLength == 0);
    CHECK(defaults.axis.approximationWeight == 8.0);
    CHECK(validate(defaults).ok());
}

TEST_CASE("parameters written as JSON read back equal", "[pipeline][parameters]")
{
    ChainParameters p;
    p.normalise.tau = 6;
    p.normalise.path = PathMethod::Greedy; // not the default: written and read back
    p.normalise.reference = {ReferenceKind::Average, 0};
    p.normalise.cellReferences["greeting/none"] = {ReferenceKind::Take, 4};
    p.decompose.method = DecomposeMethod::LeastSquares;
    p.decompose.correlationLength = 3;
    p.design.emotionWeight = 1.75;
    p.design.warp = identityWarp(50);
    p.design.setGain({2, 1, 0.5, 2.0});
    p.design.setGain({0, 3, 1.5, 1.0});
    p.design.boundaries = {false, {10, 30}};
    p.axis.segments = SegmentTable::DeLevaFemale;
    const json written = toJson(p);
    CHECK(written.at("axis").at("segments") == "female");
    auto read = chainParametersFromJson(json::parse(written.dump()), "p.json");
    INFO((read ? "" : read.error().message));
    REQUIRE(read.ok());
    CHECK(*read == p);
    CHECK(read->design.gains.front().phrase == 0); // kept sorted
}

TEST_CASE("every written parameter file names the path, and a file without one gets the default, the optimal path",
          "[pipeline][parameters]")
{
    for (const PathMethod path : {PathMethod::Greedy, PathMethod::Optimal}) {
        ChainParameters p;
        p.normalise.path = path;
        const json written = toJson(p);
        REQUIRE(written.at("normalise").contains("path"));
        CHECK(written.at("normalise").at("path") == pathName(path));
        CHECK(chainParametersFromJson(written, "p.json")->normalise.path == path);
    }
    CHECK(chainParametersFromJson(json::object(), "p.json")->normalise.path == PathMethod::Optimal);
    CHECK(chainParametersFromJson({{"normalise", {{"tau", 6}}}}, "p.json")->normalise.path == PathMethod::Optimal);
    CHECK(chainParametersFromJson({{"normalise", {{"path", "greedy"}}}}, "p.json")->normalise.path == PathMethod::Greedy);
}

TEST_CASE("out-of-range parameters are refused naming the parameter, never used", "[pipeline][parameters]")
{
    CHECK_THAT(errorOf({{"normalise", {{"maxScale", 2e9}}}}),
               Catch::Contains("p.json: parameters.normalise.maxScale: expected an integer in 1..256"));
    CHECK_THAT(errorOf({{"normalise", {{"maxScale", 100000}}}}), Catch::Contains("parameters.normalise.maxScale"));
    CHECK_THAT(errorOf({{"normalise", {{"tau", -1}}}}), Catch::Contains("parameters.normalise.tau: expected an integer in 0..200"));
    CHECK_THAT(errorOf({{"normalise", {{"tau", 4.5}}}}), Catch::Contains("normalise.tau"));
    CHECK_THAT(errorOf({{"normalise", {{"tua", 4}}}}), Catch::Contains("parameters.normalise.tua: unknown parameter"));
    CHECK_THAT(errorOf({{"decompose", {{"method", "pca"}}}}), Catch::Contains("expected one of km2o, least-squares"));
    CHECK_THAT(errorOf({{"design", {{"emotionWeight", -0.5}}}}), Catch::Contains("design.emotionWeight"));
    CHECK_THAT(errorOf({{"design", {{"emotionWeight", 7}}}}), Catch::Contains("expected a number in [0, 3]"));
    CHECK_THAT(errorOf({{"design", {{"boundaries", {30, 10}}}}}), Catch::Contains("design.boundaries[1]"));
    CHECK_THAT(errorOf({{"design", {{"boundaries", 0}}}}), Catch::Contains("design.boundaries"));
    CHECK_THAT(errorOf({{"design", {{"warp", {{0, 0}, {10, 1e300}}}}}}), Catch::Contains("design.warp[1]"));
    CHECK_THAT(errorOf({{"design", {{"warp", {{0, 5}, {10, 1}}}}}}), Catch::Contains("design.warp"));
    CHECK_THAT(errorOf({{"design", {{"gains", {{{"phrase", 0}, {"dof", 0}, {"g0", 1}, {"g1", 1}},
                                               {{"phrase", 0}, {"dof", 0}, {"g0", 2}, {"g1", 1}}}}}}}),
               Catch::Contains("given twice"));
    CHECK_THAT(errorOf({{"axis", {{"massSpacing", 0.001}}}}), Catch::Contains("parameters.axis.massSpacing"));
    CHECK_THAT(errorOf(json::array()), Catch::Contains("parameters: expected an object"));
}

TEST_CASE("a warp of more control points than allowed is refused before it is read", "[pipeline][parameters]")
{
    json points = json::array();
    for (int i = 0; i <= int(kMaxWarpPoints); ++i) points.push_back({i, i});
    CHECK_THAT(errorOf({{"design", {{"warp", points}}}}), Catch::Contains("expected null or 2..20000 control points"));
}

namespace {

/// Every value of `Enum` the table names has one name, and that name reads back to it; the table
/// holds `count` names.
template <class Enum>
void requireNamesRoundTrip(std::size_t count)
{
    const auto& names = parameterNames<Enum>();
    CHECK(names.size() == count);
    for (const auto& [name, value] : names) {
        CHECK(parameterName(value) == name);
        CHECK(parameterValue<Enum>(name) == value);
    }
    CHECK_FALSE(parameterValue<Enum>("no such name").has_value());
    CHECK(parameterNameList<Enum>().size() == count);
}

} // namespace

TEST_CASE("each enumerated parameter has one table of names, which the files and the command line read", "[pipeline][parameters]")
{
    requireNamesRoundTrip<PathMethod>(2);
    requireNamesRoundTrip<DecomposeMethod>(2);
    requireNamesRoundTrip<DecomposeInput>(2);
    requireNamesRoundTrip<ChannelWeighting>(2);
    requireNamesRoundTrip<LevelAlignment>(2);
    requireNamesRoundTrip<FrontBackAxis>(2);
    requireNamesRoundTrip<MassSource>(2);
    requireNamesRoundTrip<SegmentTable>(2);
    // The files write the tables' names.
    ChainParameters parameters;
    parameters.normalise.weighting = ChannelWeighting::Standardise;
    parameters.axis.frontBack = FrontBackAxis::Principal;
    parameters.axis.segments = SegmentTable::DeLevaFemale;
    const auto json = toJson(parameters);
    CHECK(json["normalise"]["weighting"] == parameterName(ChannelWeighting::Standardise));
    CHECK(json["axis"]["frontBack"] == parameterName(FrontBackAxis::Principal));
    CHECK(json["axis"]["segments"] == parameterName(SegmentTable::DeLevaFemale));
    CHECK(json["decompose"]["method"] == parameterName(parameters.decompose.method));
}
