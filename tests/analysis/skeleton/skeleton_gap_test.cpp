// A derived take's 24 channels and its skeleton: equal where the channels are posed from the
// skeleton, measured where the thesis computes the channels otherwise (analysis/core/skeleton_take.h).
#include "analysis/core/puppet_layout.h"
#include "analysis/core/skeleton_take.h"
#include "analysis/pipeline/stages.h"
#include "tests/support/bandai_data.h"

#include <catch2/catch.hpp>

using namespace bunraku;
using namespace bunraku::analysis;

namespace {

/// The largest distance between a part's position channels and the same part posed by the
/// take's skeleton through the importer's own path (puppetTakeFromSkeleton), cm.
double positionGapByImport(const Take& take)
{
    auto posed = puppetTakeFromSkeleton(take.skeleton, take.rateHz);
    REQUIRE(posed);
    double worst = 0.0;
    for (const auto part : kPuppetParts) {
        const Eigen::Index a = *take.channelIndex(part, "x");
        const Eigen::Index b = *posed->channelIndex(part, "x");
        worst = std::max(worst, (take.values.middleCols(a, 3) - posed->values.middleCols(b, 3)).rowwise().norm().maxCoeff());
    }
    return worst;
}

struct NormalisedCells {
    pipeline::PreprocessOutput preprocessed;
    pipeline::NormaliseOutput normalised;
};

NormalisedCells normaliseBandai(const std::string& coupling)
{
    NormalisedCells out;
    auto pre = pipeline::runPreprocess(test::bandaiWaveCorpus(), {});
    REQUIRE(pre);
    out.preprocessed = std::move(pre).value();
    pipeline::NormaliseParameters parameters;
    parameters.coupling = coupling;
    auto normalised = pipeline::runNormalise(out.preprocessed.corpus, parameters);
    REQUIRE(normalised);
    out.normalised = std::move(normalised).value();
    return out;
}

} // namespace

TEST_CASE("imported, preprocessed and wholly coupled normalised takes have their skeleton's channels but for the floor", "[skeleton][gap]")
{
    if (!test::bandaiAvailable(test::bandaiWaveFiles())) return;
    const NormalisedCells cells = normaliseBandai("all");
    const Corpus raw = test::bandaiWaveCorpus();
    std::vector<const Take*> takes;
    for (const auto& take : raw.takes) takes.push_back(&take);
    for (const auto& take : cells.preprocessed.corpus.takes) takes.push_back(&take);
    for (const auto& take : cells.normalised.normalised.takes) takes.push_back(&take);
    REQUIRE(takes.size() == 45);
    for (std::size_t k = 0; k < takes.size(); ++k) {
        const Take& take = *takes[k];
        INFO(take.displayName());
        if (k < raw.takes.size()) {
            const auto gap = skeletonChannelGap(take);
            REQUIRE(gap);
            CHECK(gap->maxPositionCm < 1e-9);
            CHECK(gap->maxAngleDeg < 1e-9);
            CHECK_FALSE(noticeableSkeletonGap(take));
            continue;
        }
        // The thesis's start-position alignment (2.2) moves the channels up or down too; the
        // performer stays on the floor: the body differs from the channels by one vertical offset.
        const Take body = bodyTake(take);
        const Eigen::MatrixXd difference = body.values - take.values;
        for (const auto part : kPuppetParts) {
            const Eigen::Index x = *take.channelIndex(part, "x");
            CHECK(difference.middleCols(x, 2).cwiseAbs().maxCoeff() < 1e-9);
            const Eigen::VectorXd z = difference.col(x + 2);
            CHECK(z.maxCoeff() - z.minCoeff() < 1e-9);
            CHECK(std::abs(z(0) - difference(0, *take.channelIndex("shoulder", "z"))) < 1e-9);
            CHECK(difference.middleCols(x + 3, 3).cwiseAbs().maxCoeff() < 1e-6);
        }
    }
}

TEST_CASE("the gap of a derived take is how far its channels are from the parts its skeleton poses", "[skeleton][gap]")
{
    if (!test::bandaiAvailable(test::bandaiWaveFiles())) return;
    // The thesis's coupling (method2: each coordinate its own warp) and 3.7 average of positions.
    const NormalisedCells cells = normaliseBandai("method2");
    int noticed = 0;
    for (const auto& cell : cells.normalised.cells) {
        std::vector<const Take*> derived{&cell.average};
        for (const auto& n : cell.normalisations) derived.push_back(&n.normalised);
        for (const Take* take : derived) {
            INFO(cell.emotion << ": " << take->displayName());
            const auto gap = skeletonChannelGap(*take);
            REQUIRE(gap);
            CHECK(gap->maxPositionCm == Approx(positionGapByImport(*take)).margin(1e-9));
            CHECK(gap->maxPositionCm == *std::max_element(gap->positionCm.begin(), gap->positionCm.end()));
            CHECK(gap->maxAngleDeg == *std::max_element(gap->angleDeg.begin(), gap->angleDeg.end()));
            if (noticeableSkeletonGap(*take)) ++noticed;
        }
        // The average of positions is not the parts of the averaged rotations.
        const auto average = noticeableSkeletonGap(cell.average);
        REQUIRE(average);
        CHECK(average->maxPositionCm > 1.0);
        CHECK(describeSkeletonChannelGap(*average).find("cm (" + average->worstPart + ", frame " + std::to_string(average->worstFrame)) !=
              std::string::npos);
    }
    CHECK(noticed >= 3);
}

TEST_CASE("a take without a skeleton or with another frame count has no gap to measure", "[skeleton][gap]")
{
    Take take;
    take.channels = puppetChannels();
    take.rateHz = 30.0;
    take.values = Eigen::MatrixXd::Zero(4, kPuppetChannelCount);
    const auto none = skeletonChannelGap(take);
    REQUIRE_FALSE(none);
    CHECK(none.error().code == ErrorCode::InvalidArgument);
    CHECK_FALSE(noticeableSkeletonGap(take));
    if (!test::bandaiAvailable({test::bandaiWaveFile("normal", 1)})) return;
    Take bandai = test::readBandai(test::bandaiWaveFile("normal", 1));
    bandai.values.conservativeResize(bandai.frameCount() - 1, Eigen::NoChange);
    const auto shorter = skeletonChannelGap(bandai);
    REQUIRE_FALSE(shorter);
    CHECK(shorter.error().message.find("frames") != std::string::npos);
}
