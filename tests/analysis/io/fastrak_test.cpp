#include "analysis/core/puppet_layout.h"
#include "analysis/io/bvh_import.h"
#include "analysis/io/fastrak.h"
#include "analysis/io/take_reader.h"
#include "tests/analysis/io/io_test_support.h"

#include <catch2/catch.hpp>

using namespace bunraku::analysis;
using namespace bunraku::analysis::io;
using Catch::Matchers::Contains;

TEST_CASE("the fastrak conversion maps a known point and orientation as documented")
{
    // position: (x forward, y right, z down) -> (x forward, y left, z up)
    const RigidTransform pose = fastrakToWorkbench({10.0, 2.0, 3.0}, 30.0, 10.0, 5.0);
    CHECK((pose.translation - Eigen::Vector3d(10.0, -2.0, -3.0)).norm() < 1e-12);
    // angles: (azimuth, elevation, roll) -> (-azimuth, -elevation, roll)
    const YawPitchRoll angles = yawPitchRollFromRotation(pose.rotation);
    CHECK(angles.yaw == Approx(-30.0));
    CHECK(angles.pitch == Approx(-10.0));
    CHECK(angles.roll == Approx(5.0));
    // a positive azimuth turns the receiver's x to the right (-y in the workbench)
    const Eigen::Vector3d forward = fastrakToWorkbench({0, 0, 0}, 30.0, 0.0, 0.0).rotation * Eigen::Vector3d::UnitX();
    CHECK((forward - Eigen::Vector3d(std::cos(M_PI / 6), -std::sin(M_PI / 6), 0.0)).norm() < 1e-12);
    // a positive elevation raises it (+z in the workbench, -z in FASTRAK's z-down frame)
    const Eigen::Vector3d raised = fastrakToWorkbench({0, 0, 0}, 0.0, 20.0, 0.0).rotation * Eigen::Vector3d::UnitX();
    CHECK(raised.z() == Approx(std::sin(20.0 * M_PI / 180.0)));
}

TEST_CASE("the fastrak sample reads as a 24-channel take at 5 Hz")
{
    auto take = readTakeFile(bunraku::test::ioDataDir() / "fastrak_sample.txt");
    REQUIRE(take.ok());
    CHECK(hasPuppetLayout(*take));
    CHECK(take->rateHz == 5.0);
    REQUIRE(take->frameCount() == 2);
    CHECK(take->values(0, puppetChannel(0, Dof::X)) == Approx(10.0));
    CHECK(take->values(0, puppetChannel(0, Dof::Y)) == Approx(-2.0));
    CHECK(take->values(0, puppetChannel(0, Dof::Z)) == Approx(-3.0));
    CHECK(take->values(0, puppetChannel(0, Dof::Yaw)) == Approx(-30.0));
    CHECK(take->values(1, puppetChannel(1, Dof::Yaw)) == Approx(31.0));
    CHECK(take->values(1, puppetChannel(2, Dof::Pitch)) == Approx(-46.0));
    CHECK(take->values(1, puppetChannel(3, Dof::Roll)) == Approx(91.0));
    CHECK(take->values(1, puppetChannel(3, Dof::X)) == Approx(13.5));
}

TEST_CASE("fastrak options: inches, station order and rate")
{
    FastrakOptions options;
    options.units = FastrakUnits::Inches;
    options.rateHz = 10.0;
    options.stations = {4, 3, 2, 1};
    const std::string text = "1 1 0 0 0 0 0\n2 2 0 0 0 0 0\n3 3 0 0 0 0 0\n4 4 0 0 0 0 0\n";
    auto take = parseFastrak(text, "inches.txt", options);
    REQUIRE(take.ok());
    CHECK(take->rateHz == 10.0);
    CHECK(take->values(0, puppetChannel(0, Dof::X)) == Approx(4 * 2.54));
    CHECK(take->values(0, puppetChannel(3, Dof::X)) == Approx(2.54));
}

TEST_CASE("malformed fastrak files give errors naming the file and line")
{
    struct Case {
        std::string text;
        std::string where;
        std::string what;
    };
    const std::string frame = "01 1 2 3 4 5 6\n02 1 2 3 4 5 6\n03 1 2 3 4 5 6\n04 1 2 3 4 5 6\n";
    const Case cases[] = {
        {frame + "01 1 2 3 4 5\n", "f.txt:5", "expected 7 fields"},
        {frame + "01 1 2 x 4 5 6\n", "f.txt:5", "field z"},
        {frame + "01 1 2 3 nan 5 6\n", "f.txt:5", "non-finite"},
        {frame + "01 1 2 3 4 5 6\n01 1 2 3 4 5 6\n", "f.txt:6", "station 1 repeated"},
        {frame + "01 1 2 3 4 5 6\n02 1 2 3 4 5 6\n", "f.txt:6", "missing stations 3, 4"},
        {frame + "garbage here\n", "f.txt:5", "expected a record"},
        {"# only comments\n", "f.txt", "no FASTRAK records"},
    };
    for (const auto& c : cases) {
        INFO(c.text);
        auto take = parseFastrak(c.text, "f.txt");
        REQUIRE_FALSE(take.ok());
        CHECK_THAT(take.error().message, Contains(c.where) && Contains(c.what));
    }
}

TEST_CASE("a fastrak file starting with a UTF-8 byte order mark reads as without it")
{
    const std::string rows = "1 10 0 0 0 0 0\n2 0 10 0 0 0 0\n3 0 0 10 0 0 0\n4 0 0 0 10 0 0\n";
    auto plain = parseFastrak(rows, "f.txt");
    auto marked = parseFastrak("\xEF\xBB\xBF" + rows, "f.txt");
    REQUIRE(plain.ok());
    REQUIRE(marked.ok());
    CHECK(marked->values == plain->values);
}

TEST_CASE("the take reader refuses unknown extensions with a clear message")
{
    auto take = readTakeFile("/tmp/some.xyz");
    REQUIRE_FALSE(take.ok());
    CHECK(take.error().code == ErrorCode::Unsupported);
    CHECK_THAT(take.error().message, Contains("some.xyz") && Contains(".bvh"));
    CHECK(takeFileFormat("A.CSV") == TakeFileFormat::Csv);
    CHECK(takeFileFormat("a.Bvh") == TakeFileFormat::Bvh);
    CHECK(takeFileFormat("a.fastrak") == TakeFileFormat::Fastrak);
}

TEST_CASE("fastrak and bvh values too large for the pose maths are errors, not NaN takes")
{
    FastrakOptions inches;
    inches.units = FastrakUnits::Inches;
    auto take = parseFastrak("1 1e308 0 0 0 0 0\n2 0 0 0 0 0 0\n3 0 0 0 0 0 0\n4 0 0 0 0 0 0\n", "big.txt", inches);
    REQUIRE_FALSE(take.ok());
    CHECK_THAT(take.error().message, Contains("big.txt:1") && Contains("field x") && Contains("beyond"));
    auto file = parseBvh("HIERARCHY\nROOT A\n{\nOFFSET 0 0 0\nCHANNELS 1 Xposition\nJOINT B\n{\nOFFSET 1e308 0 0\nCHANNELS 0\n"
                         "JOINT C\n{\nOFFSET 1 0 0\nCHANNELS 0\nJOINT D\n{\nOFFSET 1 0 0\nCHANNELS 0\n}\n}\n}\n}\n"
                         "MOTION\nFrames: 1\nFrame Time: 1\n1e308\n",
                         "big.bvh");
    REQUIRE(file.ok());
    BvhImportOptions options;
    options.jointMap = JointMap{{"A", "B", "C", "D"}};
    options.upAxis = BvhUpAxis::Z;
    auto puppet = bvhToPuppetTake(*file, options);
    REQUIRE_FALSE(puppet.ok());
    // refused at the OFFSET's line before any pose is computed (checkBvhLengths)
    CHECK_THAT(puppet.error().message, Contains("big.bvh:8") && Contains("OFFSET") && Contains("beyond"));
}

TEST_CASE("the take writer picks csv or bvh by extension and refuses others")
{
    auto take = readTakeFile(bunraku::test::ioDataDir() / "fastrak_sample.txt");
    REQUIRE(take.ok());
    const auto dir = bunraku::test::scratchDir("take_writer");
    REQUIRE(writeTakeFile(*take, dir / "t.csv").ok());
    REQUIRE(writeTakeFile(*take, dir / "t.bvh").ok());
    auto csv = readTakeFile(dir / "t.csv");
    REQUIRE(csv.ok());
    CHECK(csv->values == take->values);
    auto bvh = readTakeFile(dir / "t.bvh");
    REQUIRE(bvh.ok());
    CHECK((bvh->values.leftCols(3) - take->values.leftCols(3)).cwiseAbs().maxCoeff() < 1e-9);
    auto refused = writeTakeFile(*take, dir / "t.txt");
    REQUIRE_FALSE(refused.ok());
    CHECK_THAT(refused.error().message, Contains("t.txt") && Contains(".csv or .bvh"));
    CHECK_FALSE(std::filesystem::exists(dir / "t.txt"));
}
