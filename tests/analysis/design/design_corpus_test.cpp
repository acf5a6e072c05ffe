#include "analysis/design/design_corpus.h"

#include "analysis/design/design_experiment.h"
#include "analysis/synth/demo_corpus.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace bunraku::analysis;

namespace {

const synth::DemoCorpus& demoCorpus()
{
    static const synth::DemoCorpus demo = synth::generateDemoCorpus();
    return demo;
}

/// Runs the design experiment on every cell and checks the criterion.
void checkEveryCell(DesignMeans means)
{
    const synth::DemoCorpus& demo = demoCorpus();
    DesignCorpusOptions options;
    options.means = means;
    const auto cells = syntheticDesignCells(demo.corpus, demo.truth, options);
    REQUIRE(cells.ok());
    REQUIRE(cells->size() == 6);
    const AxisModel model = makeAxisModel(defaultBodyDescription());
    for (const SyntheticDesignCell& designCell : *cells) {
        const DesignCell& cell = designCell.cell;
        const auto result = evaluateDesignCell(model, cell);
        REQUIRE(result.ok());
        INFO(cell.function << "/" << cell.emotion << ": designed " << result->axisRelativeError << ", undesigned "
                           << result->functionalRelativeError << ", phase error " << result->phaseMeanAbsErrorFrames
                           << " frames, per DOF " << result->dofRelativeError.transpose() << ", means vs truth "
                           << designCell.functionalMean.truthShapeError << " / " << designCell.emotionalMean.truthShapeError);
        CHECK(result->axisRelativeError < 0.10);
        CHECK(result->axisRelativeError <= result->functionalRelativeError + 1e-12);
        CHECK(result->phaseMeanAbsErrorFrames < 4.0);
        // the averages are close to the truth cell motion at the mapped cell time (a single
        // take is off by up to its 6 % amplitude jitter)
        CHECK(designCell.functionalMean.truthShapeError < 0.08);
        CHECK(designCell.emotionalMean.truthShapeError < 0.08);
        if (cell.emotion == demo.truth.neutralEmotion) {
            // the functional mean against itself: identity warp, exact design, and a true map
            // that is the identity too (so the cell-time mapping of the means is consistent)
            CHECK(result->axisRelativeError < 1e-6);
            CHECK(result->phaseMeanAbsErrorFrames < 0.25);
        }
    }
}

} // namespace

TEST_CASE("with measured means the designed axis is within 10 % of the measured emotional axis for every cell")
{
    checkEveryCell(DesignMeans::Measured);
}

TEST_CASE("with the truth cell motions as means the designed axis is within 10 % for every cell")
{
    checkEveryCell(DesignMeans::Truth);
}

TEST_CASE("measured means are averages of the preprocessed takes on the base take's frames")
{
    const synth::DemoCorpus& demo = demoCorpus();
    const auto cells = syntheticDesignCells(demo.corpus, demo.truth);
    REQUIRE(cells.ok());
    for (const SyntheticDesignCell& cell : *cells) {
        CHECK(cell.functionalMean.take.labels.source.find("average of takes") == 0);
        CHECK(cell.emotionalMean.take.labels.emotion == cell.cell.emotion);
        CHECK(cell.cell.trueEmotionalToFunctional.size() == cell.cell.emotional.frameCount());
        CHECK(cell.emotionalMean.cellTime.size() == cell.emotionalMean.take.frameCount());
        // cell time never runs backwards and spans the cell (start alignment may drop a few
        // frames of the base take's start)
        const Eigen::VectorXd& time = cell.emotionalMean.cellTime;
        CHECK((time.tail(time.size() - 1) - time.head(time.size() - 1)).minCoeff() >= 0.0);
        CHECK(time[0] < 5.0);
        CHECK(cell.emotionalMean.cellTime.maxCoeff() > 100.0);
    }
}

TEST_CASE("the average take's cell time follows the members' mean timing")
{
    // base: frame t shows cell time t; member: twice as slow (frame t shows t / 2). Base frame
    // t_b is matched to member frame 2 t_b, so the average places cell time t_b at 1.5 t_b.
    const Eigen::VectorXd base = Eigen::VectorXd::LinSpaced(100, 0.0, 99.0);
    const Eigen::VectorXd slow = Eigen::VectorXd::LinSpaced(200, 0.0, 99.5);
    AverageOptions options;
    const Eigen::VectorXd time = averageTakeCellTime({base, slow}, options, 100);
    REQUIRE(time.size() == 100);
    for (Eigen::Index t = 0; t < 100; ++t) CHECK(time[t] == Approx(double(t) / 1.5).margin(1e-9));

    options.excludedTakes = {1};
    const Eigen::VectorXd alone = averageTakeCellTime({base, slow}, options, 100);
    CHECK((alone - base).cwiseAbs().maxCoeff() < 1e-12);
}

TEST_CASE("first frame reaching a value interpolates and skips holds")
{
    Eigen::VectorXd map(6);
    map << 0.0, 0.0, 0.0, 1.0, 3.0, 3.0;
    CHECK(firstFrameReaching(map, -1.0) == 0.0);
    CHECK(firstFrameReaching(map, 0.0) == 0.0);
    CHECK(firstFrameReaching(map, 0.5) == Approx(2.5));
    CHECK(firstFrameReaching(map, 2.0) == Approx(3.5));
    CHECK(firstFrameReaching(map, 3.0) == Approx(4.0));
    CHECK(firstFrameReaching(map, 9.0) == 5.0);
}
