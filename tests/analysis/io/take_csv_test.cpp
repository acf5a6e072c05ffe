#include "analysis/core/puppet_layout.h"
#include "analysis/io/take_csv.h"
#include "tests/analysis/io/io_test_support.h"

#include <catch2/catch.hpp>

using namespace bunraku::analysis;
using namespace bunraku::analysis::io;
using Catch::Matchers::Contains;

namespace {

Take smallPuppetTake(Eigen::Index frames = 4)
{
    Take take;
    take.channels = puppetChannels();
    take.rateHz = 5.0;
    take.values.resize(frames, kPuppetChannelCount);
    for (Eigen::Index f = 0; f < frames; ++f)
        for (int c = 0; c < kPuppetChannelCount; ++c) take.values(f, c) = 0.1 * double(f) + double(c) / 3.0 - 7.0;
    return take;
}

} // namespace

TEST_CASE("csv reader accepts semicolons, CRLF, comments and blank lines")
{
    auto take = readTakeCsv(bunraku::test::ioDataDir() / "semicolon_crlf.csv");
    REQUIRE(take.ok());
    CHECK(take->frameCount() == 3);
    REQUIRE(take->channelCount() == 3);
    CHECK(take->channels[0] == Channel{"head", "x", "cm"});
    CHECK(take->channels[1] == Channel{"head", "yaw", "deg"});
    CHECK(take->channels[2] == Channel{"hand", "z", "cm"});
    CHECK(take->rateHz == Approx(5.0));
    CHECK(take->values(0, 2) == -20.0);
    CHECK(take->values(2, 1) == -170.0);
}

TEST_CASE("a UTF-8 byte order mark before the header is skipped")
{
    auto take = parseTakeCsv("\xEF\xBB\xBFtime_s,head.x\n0,1\n0.2,2\n", "bom.csv");
    REQUIRE(take.ok());
    REQUIRE(take->channelCount() == 1);
    CHECK(take->channels[0] == Channel{"head", "x", "cm"});
    CHECK(take->values(1, 0) == 2.0);
    CHECK(take->rateHz == Approx(5.0));
    // only at the start of the file: elsewhere it is a byte of a field
    auto inside = parseTakeCsv("time_s,head.x\n\xEF\xBB\xBF" "0,1\n", "bom.csv");
    REQUIRE_FALSE(inside.ok());
    CHECK_THAT(inside.error().message, Contains("bom.csv:2"));
}

TEST_CASE("csv reader detects comma and tab separators")
{
    const std::string separator = GENERATE(std::string(","), std::string("\t"));
    const std::string text = "time_s" + separator + "arm.x" + separator + "arm.roll\n0" + separator + "1" + separator + "2\n0.5" +
                             separator + "3" + separator + "4\n";
    auto take = parseTakeCsv(text, "mem.csv");
    REQUIRE(take.ok());
    CHECK(take->rateHz == Approx(2.0));
    CHECK(take->values(1, 1) == 4.0);
}

TEST_CASE("csv writer and reader round-trip a puppet take exactly")
{
    const Take original = smallPuppetTake();
    const auto dir = bunraku::test::scratchDir("csv_round_trip");
    REQUIRE(writeTakeCsv(original, dir / "take.csv").ok());
    auto back = readTakeCsv(dir / "take.csv");
    REQUIRE(back.ok());
    CHECK(back->channels == original.channels);
    CHECK(back->rateHz == original.rateHz);
    CHECK(back->values == original.values);
}

TEST_CASE("csv errors name the file, line and column")
{
    SECTION("a word where a number belongs")
    {
        auto take = parseTakeCsv("time_s,head.x\n0,1\n0.2,abc\n", "bad.csv");
        REQUIRE_FALSE(take.ok());
        CHECK(take.error().code == ErrorCode::Parse);
        CHECK_THAT(take.error().message, Contains("bad.csv:3") && Contains("column 2") && Contains("head.x") && Contains("abc"));
    }
    SECTION("NaN and Inf are rejected with their location")
    {
        const std::string value = GENERATE(std::string("nan"), std::string("inf"), std::string("-Inf"), std::string("1e999"));
        auto take = parseTakeCsv("time_s,head.x\n0,1\n0.2," + value + "\n", "nan.csv");
        REQUIRE_FALSE(take.ok());
        CHECK_THAT(take.error().message, Contains("nan.csv:3") && Contains("non-finite"));
    }
    SECTION("a row with too few fields")
    {
        auto take = parseTakeCsv("time_s,head.x,head.y\n0,1,2\n0.2,1\n", "short.csv");
        REQUIRE_FALSE(take.ok());
        CHECK_THAT(take.error().message, Contains("short.csv:3") && Contains("expected 3 fields"));
    }
    SECTION("a header column that is not part.dof")
    {
        auto take = parseTakeCsv("time_s,headx\n0,1\n", "header.csv");
        REQUIRE_FALSE(take.ok());
        CHECK_THAT(take.error().message, Contains("header.csv:1") && Contains("column 2") && Contains("part.dof"));
    }
    SECTION("a non-uniform time column names the line")
    {
        auto take = parseTakeCsv("time_s,head.x\n0,1\n0.2,1\n0.5,1\n0.6,1\n", "time.csv");
        REQUIRE_FALSE(take.ok());
        CHECK_THAT(take.error().message, Contains("time.csv:4") && Contains("not uniform"));
    }
    SECTION("time steps too short for any recording name the line and the rates accepted")
    {
        auto take = parseTakeCsv("time_s,head.x\n0,1\n1e-300,1\n2e-300,1\n", "fast.csv");
        REQUIRE_FALSE(take.ok());
        CHECK_THAT(take.error().message, Contains("fast.csv:3") && Contains("(0, 1000000] Hz"));
    }
    SECTION("a time column that goes back names the line where it does")
    {
        auto take = parseTakeCsv("time_s,head.x\n0,1\n0.2,1\n0.1,1\n", "back.csv");
        REQUIRE_FALSE(take.ok());
        CHECK_THAT(take.error().message, Contains("back.csv:4") && Contains("increase") && Contains("0.1 s follows 0.2 s"));
    }
    SECTION("binary junk in a message is escaped, never printed raw")
    {
        auto take = parseTakeCsv("time_s,\x1b[2J\xffq\n0,1\n", "junk.csv");
        REQUIRE_FALSE(take.ok());
        CHECK_THAT(take.error().message, Contains("junk.csv:1") && Contains("\\x1b[2J\\xffq"));
        for (const char c : take.error().message) CHECK((static_cast<unsigned char>(c) >= 0x20 && static_cast<unsigned char>(c) < 0x7f));
    }
    SECTION("no time column and no rate")
    {
        auto take = parseTakeCsv("head.x\n1\n", "norate.csv");
        REQUIRE_FALSE(take.ok());
        CHECK_THAT(take.error().message, Contains("norate.csv:1") && Contains("time_s"));
    }
    SECTION("only a header")
    {
        auto take = parseTakeCsv("# just a comment\ntime_s,head.x\n", "empty.csv");
        REQUIRE_FALSE(take.ok());
        CHECK_THAT(take.error().message, Contains("empty.csv:2") && Contains("data rows"));
    }
    SECTION("a missing file")
    {
        auto take = readTakeCsv("/nonexistent/folder/take.csv");
        REQUIRE_FALSE(take.ok());
        CHECK_THAT(take.error().message, Contains("/nonexistent/folder/take.csv"));
    }
}

TEST_CASE("csv reader takes the rate from the option when there is no time column")
{
    TakeCsvOptions options;
    options.rateHz = 30.0;
    auto take = parseTakeCsv("hand.pitch;hand.x\n1;2\n3;4\n", "rate.csv", options);
    REQUIRE(take.ok());
    CHECK(take->rateHz == 30.0);
    CHECK(take->channels[0].unit == "deg");
}

TEST_CASE("csv reader never crashes on arbitrary bytes")
{
    const std::string inputs[] = {"", "\n\n\n", ",,,\n,,,", "time_s\n", "time_s,a.b\n\x01\x02,\xff", ";;\n;;", "\r\r\r", "#\n#", "a.b\n1e-400\n"};
    for (const auto& text : inputs) {
        auto take = parseTakeCsv(text, "fuzz.csv");
        if (take.ok()) CHECK(validateTake(*take).ok());
        else CHECK_THAT(take.error().message, Contains("fuzz.csv"));
    }
}

TEST_CASE("a failed csv write leaves the previous file untouched")
{
    const auto dir = bunraku::test::scratchDir("csv_atomic");
    const Take original = smallPuppetTake();
    REQUIRE(writeTakeCsv(original, dir / "take.csv").ok());
    Take broken = smallPuppetTake();
    broken.values(2, 5) = std::numeric_limits<double>::quiet_NaN();
    auto status = writeTakeCsv(broken, dir / "take.csv");
    REQUIRE_FALSE(status.ok());
    CHECK_THAT(status.error().message, Contains("frame 2") && Contains("head.roll"));
    auto back = readTakeCsv(dir / "take.csv");
    REQUIRE(back.ok());
    CHECK(back->values == original.values);
    CHECK_THAT(writeTakeCsv(original, dir / "missing-folder" / "take.csv").error().message, Contains("does not exist"));
    std::filesystem::create_directory(dir / "sub.csv");
    CHECK_THAT(writeTakeCsv(original, dir / "sub.csv").error().message, Contains("a folder of that name"));
    std::filesystem::remove(dir / "sub.csv");
    // no temporary files are left behind
    int files = 0;
    for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir)) ++files;
    CHECK(files == 1);
}
