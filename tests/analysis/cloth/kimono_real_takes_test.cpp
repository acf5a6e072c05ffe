// The kimono on real and synthetic takes (issue "The kimono", Done when): no cloth particle lies
// more than 0.5 cm inside the body's capsules, and the hem stays below the dō-wa, at sampled
// frames of every Bandai take (the puppet fitted to the performer) and of the demo corpus.
#include "analysis/cloth/kimono_cloth.h"

#include "analysis/body/body_description.h"
#include "analysis/io/take_reader.h"
#include "analysis/synth/demo_corpus.h"
#include "tests/analysis/cloth/cloth_depth.h"
#include "tests/support/bandai_files.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <string>
#include <vector>

using namespace bunraku::analysis;

namespace {

struct Depth {
    double deepest = 0.0; ///< cm inside a capsule
    double hemAboveDowa = -1e9; ///< cm: the highest hem point above the dō-wa (negative: below)
    int frames = 0;
};

Depth sample(const Take& take, int samples)
{
    const auto simulation = simulateKimono(take);
    INFO(take.displayName() << ": " << (simulation.ok() ? std::string() : simulation.error().message));
    REQUIRE(simulation.ok());
    const auto colliders = kimonoColliders(simulation->body);
    REQUIRE(colliders.size() == 3);
    Depth depth;
    for (int k = 0; k < samples; ++k) {
        const Eigen::Index frame = Eigen::Index(double(k) / double(samples - 1) * double(take.frameCount() - 1));
        const auto x = kimonoFrame(*simulation, take, frame);
        REQUIRE(x.ok());
        const auto holders = kimonoHolderPoses(simulation->body, take, frame);
        REQUIRE(holders.ok());
        depth.deepest = std::max(depth.deepest, bunraku::test::deepestInsideBody(*simulation->cloth, *x, colliders, *holders));
        // The hem's points against the dō-wa (24 cm below the shoulder sensor, in its frame,
        // scaled by the shoulder's fit like the cloth).
        const Eigen::Vector3d dowa = (*holders)[0].apply(simulation->body.parts[std::size_t(simulation->body.partIndex("shoulder"))].fit *
                                                         Eigen::Vector3d(0.0, 0.0, -24.0));
        const Eigen::Vector3d up = (*holders)[0].rotation * Eigen::Vector3d::UnitZ();
        for (int point = 2; point < kKimonoPointCount; ++point)
            depth.hemAboveDowa = std::max(depth.hemAboveDowa, ((*x)[simulation->cloth->measured[std::size_t(point)]] - dowa).dot(up));
        ++depth.frames;
    }
    return depth;
}

} // namespace

TEST_CASE("no cloth particle lies more than 0.5 cm inside the body at sampled frames of every Bandai take", "[kimono][bandai]")
{
    const auto files = bunraku::test::bandaiFilesOrSkip();
    for (const auto& path : files) {
        auto take = io::readTakeFile(path);
        INFO(path.string() << ": " << (take.ok() ? std::string() : take.error().message));
        REQUIRE(take.ok());
        const Depth depth = sample(*take, 12);
        INFO(path.filename().string() << ": deepest " << depth.deepest << " cm inside, hem at most " << depth.hemAboveDowa
                                      << " cm above the do-wa over " << depth.frames << " frames");
        CHECK(depth.deepest <= 0.5);
        CHECK(depth.hemAboveDowa < 0.0);
    }
}

TEST_CASE("no cloth particle lies more than 0.5 cm inside the body at sampled frames of the demo corpus", "[kimono]")
{
    const synth::DemoCorpus demo = synth::generateDemoCorpus();
    int takes = 0;
    for (std::size_t t = 0; t < demo.corpus.takes.size(); t += 5) { // every cell's first take
        const Depth depth = sample(demo.corpus.takes[t], 8);
        INFO(demo.corpus.takes[t].displayName() << ": deepest " << depth.deepest << " cm inside, hem at most " << depth.hemAboveDowa
                                                 << " cm above the do-wa");
        CHECK(depth.deepest <= 0.5);
        CHECK(depth.hemAboveDowa < 0.0);
        ++takes;
    }
    CHECK(takes == 6);
}
