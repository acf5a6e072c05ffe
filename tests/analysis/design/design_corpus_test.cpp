#include "analysis/design/design_experiment.h"

#include "analysis/core/puppet_layout.h"
#include "analysis/synth/demo_corpus.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace bunraku::analysis;

namespace {

Take motionTake(const Eigen::MatrixXd& motion, const std::string& function, const std::string& emotion)
{
    Take take;
    take.values = motion;
    take.channels = puppetChannels();
    take.labels.function = function;
    take.labels.emotion = emotion;
    take.labels.source = "synthetic truth";
    return take;
}

} // namespace

TEST_CASE("on the synthetic corpus the designed axis is within 10 % of the measured emotional axis")
{
    static const synth::DemoCorpus demo = synth::generateDemoCorpus();
    const AxisModel model = makeAxisModel(defaultBodyDescription());
    int cells = 0;
    for (const synth::CellTruth& truth : demo.truth.cells) {
        const synth::FunctionTruth* function = demo.truth.function(truth.function);
        REQUIRE(function != nullptr);
        DesignCell cell{truth.function, truth.emotion, motionTake(function->motion, truth.function, "none"),
                        motionTake(truth.motion, truth.function, truth.emotion), truth.phaseWarp};
        const auto result = evaluateDesignCell(model, cell);
        REQUIRE(result.ok());
        INFO(truth.function << "/" << truth.emotion << ": designed " << result->axisRelativeError << ", undesigned "
                            << result->functionalRelativeError << ", phase error " << result->phaseMeanAbsErrorFrames
                            << " frames, per DOF " << result->dofRelativeError.transpose());
        CHECK(result->axisRelativeError < 0.10);
        CHECK(result->axisRelativeError <= result->functionalRelativeError + 1e-12);
        CHECK(result->phaseMeanAbsErrorFrames < 4.0);
        ++cells;
    }
    CHECK(cells == 6);
}
