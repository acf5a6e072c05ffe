#include "analysis/body/body_description.h"

#include "tests/support/test_paths.h"

#include <catch2/catch.hpp>

#include <numbers>

using namespace bunraku::analysis;

namespace {

std::string onePart(const std::string& primitive)
{
    return R"({"parts": [{"name": "head", "driven_by": "head", "density": 1.0, "primitives": [)" + primitive + "]}]}";
}

} // namespace

TEST_CASE("the shipped puppet description has six parts with the left limbs mirrored")
{
    const auto body = loadBodyDescription(bunraku::test::sourceDir() / "resources/puppet/bunraku_puppet.json");
    REQUIRE(body.ok());
    REQUIRE(body->parts.size() == 6);
    CHECK(body->mirrorFramePart == "shoulder");
    const BodyPart& left = body->parts[std::size_t(body->partIndex("left_arm"))];
    const BodyPart& right = body->parts[std::size_t(body->partIndex("right_arm"))];
    CHECK(left.mirrored);
    CHECK(left.mirrorOf == "right_arm");
    CHECK(left.drivenBy == "arm");
    CHECK(left.mass() == Approx(right.mass()));
    // a female puppet weighs a few kilograms; head about 12 cm, torso + skirt about 60 cm
    CHECK(body->mass() > 2000.0);
    CHECK(body->mass() < 10000.0);
    // the embedded copy is the same file
    CHECK(defaultBodyDescription().parts.size() == body->parts.size());
    CHECK(defaultBodyDescription().mass() == Approx(body->mass()));
}

TEST_CASE("mirrored primitives are the source's reflected in the part's y axis")
{
    const std::string text = R"({"parts": [
        {"name": "r", "driven_by": "arm", "density": 1, "primitives": [
            {"shape": "box", "size": [1, 2, 3], "position": [1, -2, 3], "yaw_pitch_roll_deg": [30, 20, 10]}]},
        {"name": "l", "driven_by": "arm", "mirror_of": "r"}]})";
    const auto body = parseBodyDescription(text, "mirror.json");
    REQUIRE(body.ok());
    const Primitive& source = body->parts[0].primitives[0];
    const Primitive& mirrored = body->parts[1].primitives[0];
    const Eigen::Matrix3d flip = Eigen::Vector3d(1, -1, 1).asDiagonal();
    CHECK(mirrored.part_T_primitive.translation.isApprox(Eigen::Vector3d(1, 2, 3)));
    const Eigen::Matrix3d expected = flip * source.part_T_primitive.rotation.toRotationMatrix() * flip;
    CHECK(mirrored.part_T_primitive.rotation.toRotationMatrix().isApprox(expected, 1e-12));
    // every corner of the mirrored box is the reflection of a corner of the source box
    for (double sx : {-0.5, 0.5})
        for (double sy : {-1.0, 1.0})
            for (double sz : {-1.5, 1.5}) {
                const Eigen::Vector3d corner(sx, sy, sz);
                const Eigen::Vector3d reflected = flip * source.part_T_primitive.apply(corner);
                const Eigen::Vector3d local = mirrored.part_T_primitive.inverse().apply(reflected);
                CHECK(mirrored.containsLocal(local * (1.0 - 1e-9)));
            }
}

TEST_CASE("primitive volumes are the analytic ones")
{
    const auto body = parseBodyDescription(onePart(R"(
        {"shape": "box", "size": [2, 3, 4]},
        {"shape": "cylinder", "radius": 2, "length": 5},
        {"shape": "ellipsoid", "radii": [1, 2, 3]},
        {"shape": "frustum", "radius": 3, "top_radius": 1, "length": 6})"),
                                           "volumes.json");
    REQUIRE(body.ok());
    const auto& p = body->parts[0].primitives;
    constexpr double pi = std::numbers::pi;
    CHECK(p[0].volume() == Approx(24.0));
    CHECK(p[1].volume() == Approx(pi * 4 * 5));
    CHECK(p[2].volume() == Approx(4.0 / 3.0 * pi * 6));
    CHECK(p[3].volume() == Approx(pi * 6 / 3 * (9 + 3 + 1)));
    CHECK(p[3].containsLocal(Eigen::Vector3d(2.9, 0, -2.99)));
    CHECK_FALSE(p[3].containsLocal(Eigen::Vector3d(1.2, 0, 2.99)));
}

TEST_CASE("body description parse errors name the source, the JSON path and the expectation")
{
    struct Case {
        std::string text;
        std::string path;
        std::string expectation;
    };
    const std::string part = R"({"name": "head", "driven_by": "head", "density": 1.0, "primitives": [{"shape": "box", "size": [1, 1, 1]}]})";
    const auto [text, path, expectation] = GENERATE_COPY(values<Case>({
        {"{\"parts\": [", "puppet.json", "not valid JSON"},
        {"{\"name\": \"x\"}", "parts", "non-empty array of parts"},
        {onePart(R"({"shape": "cylinder", "length": 5})"), "parts[0].primitives[0]", "\"radius\""},
        {onePart(R"({"shape": "cylinder", "radius": -1, "length": 5})"), "parts[0].primitives[0].radius", "positive number"},
        {onePart(R"({"shape": "cone", "radius": 1})"), "parts[0].primitives[0].shape", "box, cylinder, ellipsoid, frustum"},
        {onePart(R"({"shape": "box", "size": [1, 2]})"), "parts[0].primitives[0].size", "3 positive numbers"},
        {onePart(R"({"shape": "box", "size": [1, 2, 3], "colour": "red"})"), "parts[0].primitives[0].colour", "#rrggbb"},
        {"{\"parts\": [" + part + R"(, {"name": "l", "driven_by": "head", "mirror_of": "nothing"}]})", "parts[1].mirror_of",
         "earlier part"},
        {"{\"parts\": [" + part + "," + part + "]}", "parts[1].name", "duplicate"},
        {R"({"parts": [{"name": "head", "density": 1, "primitives": []}]})", "parts[0]", "driven_by"},
    }));
    const auto body = parseBodyDescription(text, "puppet.json");
    REQUIRE_FALSE(body.ok());
    CHECK(body.error().code == ErrorCode::Parse);
    INFO(body.error().message);
    CHECK(body.error().message.find("puppet.json") == 0);
    CHECK(body.error().message.find(path) != std::string::npos);
    CHECK(body.error().message.find(expectation) != std::string::npos);
}

TEST_CASE("a missing body description file is a NotFound error naming the file")
{
    const auto body = loadBodyDescription(bunraku::test::scratchDir("body-missing") / "nope.json");
    REQUIRE_FALSE(body.ok());
    CHECK(body.error().code == ErrorCode::NotFound);
    CHECK(body.error().message.find("nope.json") != std::string::npos);
}
