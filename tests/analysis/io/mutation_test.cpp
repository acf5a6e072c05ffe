// Every importer either reads a damaged file or reports where it is wrong; it never crashes.
// Run under the sanitizer build this also catches undefined behaviour on damaged input.
#include "analysis/io/bvh_import.h"
#include "analysis/io/fastrak.h"
#include "analysis/io/take_csv.h"
#include "tests/analysis/io/io_test_support.h"

#include "tests/support/test_paths.h"

#include <catch2/catch.hpp>

#include <fstream>
#include <random>

using namespace bunraku::analysis;
using namespace bunraku::analysis::io;
using Catch::Matchers::Contains;

namespace {

/// `text` with a few characters replaced, deleted or duplicated.
std::string mutate(const std::string& text, std::mt19937& rng)
{
    std::string out = text;
    const char alphabet[] = "0123456789-+.eE \t\r\n{}#,;:xXnanif";
    std::uniform_int_distribution<int> edits(1, 4), kind(0, 2), letter(0, int(sizeof alphabet) - 2);
    for (int e = edits(rng); e > 0 && !out.empty(); --e) {
        std::uniform_int_distribution<std::size_t> at(0, out.size() - 1);
        const std::size_t i = at(rng);
        switch (kind(rng)) {
        case 0: out[i] = alphabet[letter(rng)]; break;
        case 1: out.erase(i, 1); break;
        default: out.insert(i, 1, out[i]); break;
        }
    }
    return out;
}

} // namespace

TEST_CASE("damaged csv, bvh and fastrak files are read or rejected with their name")
{
    std::mt19937 rng(7);
    const std::string csv = bunraku::test::fileBytes(bunraku::test::ioDataDir() / "semicolon_crlf.csv");
    const std::string bvh = bunraku::test::fileBytes(bunraku::test::ioDataDir() / "two_joint_chain.bvh");
    const std::string fastrak = bunraku::test::fileBytes(bunraku::test::ioDataDir() / "fastrak_sample.txt");
    REQUIRE_FALSE(csv.empty());
    REQUIRE_FALSE(bvh.empty());
    REQUIRE_FALSE(fastrak.empty());
    int rejected = 0;
    for (int trial = 0; trial < 400; ++trial) {
        auto take = parseTakeCsv(mutate(csv, rng), "m.csv");
        if (take.ok()) CHECK(validateTake(*take).ok());
        else {
            ++rejected;
            CHECK_THAT(take.error().message, Contains("m.csv"));
        }
        auto file = parseBvh(mutate(bvh, rng), "m.bvh");
        if (file.ok()) {
            BvhImportOptions options;
            options.jointMap = JointMap{{"Base", "Base", "Elbow", "Elbow"}};
            auto puppet = bvhToPuppetTake(*file, options);
            if (puppet.ok()) CHECK(validateTake(*puppet).ok());
        } else {
            ++rejected;
            CHECK_THAT(file.error().message, Contains("m.bvh"));
        }
        auto tracked = parseFastrak(mutate(fastrak, rng), "m.txt");
        if (tracked.ok()) CHECK(validateTake(*tracked).ok());
        else {
            ++rejected;
            CHECK_THAT(tracked.error().message, Contains("m.txt"));
        }
    }
    CHECK(rejected > 100); // the damage is real
}
