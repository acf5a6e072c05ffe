// The chain split across threads (cells, channels) gives the same data files, byte for byte,
// as on one thread: every number of every stage is written with shortest round-trip digits, so
// equal text is equal doubles.
#include "analysis/pipeline/chain.h"
#include "analysis/report/analysis_files.h"
#include "analysis/synth/demo_corpus.h"

#include <catch2/catch.hpp>

#include <map>

using namespace bunraku::analysis;

namespace {

std::map<std::string, std::string> dataFiles(const pipeline::CorpusInput& corpus, int threads)
{
    pipeline::ChainOptions options;
    options.threads = threads;
    int calls = 0;
    options.progress = [&calls](pipeline::Stage, double) { ++calls; }; // one call at a time
    auto chain = pipeline::runChain(corpus, {}, nullptr, options);
    REQUIRE(chain.ok());
    auto files = report::analysisDataFiles(*chain, {});
    REQUIRE(files.ok());
    std::map<std::string, std::string> byName;
    for (auto& file : *files) byName[file.name] = std::move(file.content);
    REQUIRE(calls > 0);
    return byName;
}

} // namespace

TEST_CASE("the chain's results are the same bits on 1, 2 and 3 threads", "[report][threads]")
{
    auto input = pipeline::makeCorpusInput(synth::generateDemoCorpus().corpus);
    REQUIRE(input.ok());
    const auto one = dataFiles(*input, 1);
    REQUIRE(one.size() > 100);
    for (int threads : {2, 3}) {
        CAPTURE(threads);
        const auto many = dataFiles(*input, threads);
        REQUIRE(many.size() == one.size());
        for (const auto& [name, content] : one) {
            CAPTURE(name);
            REQUIRE(many.count(name) == 1);
            REQUIRE(many.at(name) == content);
        }
    }
}
