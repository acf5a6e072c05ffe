#include "analysis/design/motion_design.h"

#include "tests/analysis/axis/puppet_fixture.h"

#include <catch2/catch.hpp>

#include <cmath>

using namespace bunraku::analysis;

namespace {

const AxisModel& model()
{
    static const AxisModel m = makeAxisModel(defaultBodyDescription(), {{2.0}});
    return m;
}

/// A smooth monotone warp 0 -> 0, 105 -> 105 that runs slow then fast: emotional frame -> functional frame.
double knownWarp(double u)
{
    return u + 6.0 * std::sin(M_PI * u / 105.0) * std::sin(M_PI * u / 105.0 * 2.0) + 4.0 * std::sin(M_PI * u / 105.0);
}

} // namespace

TEST_CASE("designing with unit gains and the identity warp returns the functional take")
{
    const Take functional = bunraku::test::livelyTake(106);
    const auto basis = prepareDesign(model(), functional);
    REQUIRE(basis.ok());
    const DesignedMotion designed = designMotion(*basis, identityWarp(106), unitGains({0, 50, 105}, {"x", "y", "z", "rx", "ry", "rz"}));
    REQUIRE(designed.take.frameCount() == 106);
    CHECK((designed.take.values - functional.values).cwiseAbs().maxCoeff() < 1e-9);
    CHECK((designed.axisCoordinates - basis->coordinates).cwiseAbs().maxCoeff() < 1e-9);
}

TEST_CASE("a designed time warp shows the functional motion at the warped times")
{
    const Take functional = bunraku::test::livelyTake(106);
    const auto basis = prepareDesign(model(), functional);
    REQUIRE(basis.ok());
    Eigen::VectorXd dense(106);
    for (int u = 0; u < 106; ++u) dense[u] = knownWarp(u);
    const WarpCurve warp = warpCurveFromSamples(dense, 4);
    const DesignedMotion designed = designMotion(*basis, warp, GainSet{});
    const Eigen::VectorXd at = sampleWarp(warp);
    for (int u : {10, 33, 64, 90}) {
        // the designed head position is the functional one interpolated at warp(u)
        const double s = at[u];
        const auto k = Eigen::Index(std::floor(s));
        const double w = s - double(k);
        const Eigen::Vector3d expected = (1 - w) * functional.values.row(k).head(3).transpose() + w * functional.values.row(k + 1).head(3).transpose();
        CHECK((designed.take.values.row(u).head(3).transpose() - expected).norm() < 1e-9);
    }
}

TEST_CASE("scaling the axis moves the whole puppet rigidly with it")
{
    const Take functional = bunraku::test::livelyTake(106);
    const auto basis = prepareDesign(model(), functional);
    REQUIRE(basis.ok());
    GainSet gains = unitGains({0, 105}, {"x", "y", "z", "rx", "ry", "rz"});
    gains.phrases[0].dofs[2].g1 = 0.5; // twice the vertical motion of the axis
    const DesignedMotion designed = designMotion(*basis, identityWarp(106), gains);
    const auto axis = computeMotionAxis(model(), designed.take);
    REQUIRE(axis.ok());
    const Eigen::MatrixXd coordinates = axisCoordinates(axis->world_T_axis);
    const Eigen::VectorXd z = basis->coordinates.col(2);
    const Eigen::VectorXd expected = z.mean() + 2.0 * (z.array() - z.mean()).matrix().array();
    CHECK((coordinates.col(2) - expected).cwiseAbs().maxCoeff() < 1e-6);
    // the parts keep their places relative to the axis
    const auto relative = relativeMotion(designed.take, axis->world_T_axis);
    REQUIRE(relative.ok());
    CHECK((relative->axis_T_part[40][3].translation - basis->relative.axis_T_part[40][3].translation).norm() < 1e-6);
}

TEST_CASE("phase extraction recovers a known warp")
{
    const Take functional = bunraku::test::livelyTake(106);
    const auto basis = prepareDesign(model(), functional);
    REQUIRE(basis.ok());
    Eigen::VectorXd truth(106);
    for (int u = 0; u < 106; ++u) truth[u] = knownWarp(u);
    const Eigen::MatrixXd emotional = resampleRows(basis->coordinates, truth);
    const auto phase = extractPhase(basis->coordinates, emotional);
    REQUIRE(phase.ok());
    const double meanError = (phase->emotionalToFunctional - truth).cwiseAbs().mean();
    INFO("mean abs phase error " << meanError << " frames");
    CHECK(meanError < 1.0);
    const double curveError = (sampleWarp(phase->curve) - truth).cwiseAbs().mean();
    CHECK(curveError < 1.0);
    for (Eigen::Index i = 1; i < phase->correspondence.size(); ++i) CHECK(phase->correspondence[i] >= phase->correspondence[i - 1]);
}

TEST_CASE("design with the extracted parameters reproduces the emotional axis")
{
    const Take functional = bunraku::test::livelyTake(106);
    const auto basis = prepareDesign(model(), functional);
    REQUIRE(basis.ok());
    // emotional axis: per phrase scaled functional axis shown at warped times
    GainSet truthGains = unitGains({0, 40, 105}, {"x", "y", "z", "rx", "ry", "rz"});
    truthGains.phrases[0].dofs[2].g1 = 0.7;
    truthGains.phrases[1].dofs[2].g1 = 1.3;
    truthGains.phrases[1].dofs[0].g1 = 0.8;
    Eigen::VectorXd truth(106);
    for (int u = 0; u < 106; ++u) truth[u] = knownWarp(u);
    const Eigen::MatrixXd emotional = resampleRows(applyGains(basis->coordinates, truthGains), truth);
    ExtractionOptions options;
    options.boundaries = {0, 40, 105};
    const auto parameters = extractDesign(basis->coordinates, emotional, options);
    REQUIRE(parameters.ok());
    CHECK(parameters->gains.phrases[0].dofs[2].g1 == Approx(0.7).epsilon(0.1));
    CHECK(parameters->gains.phrases[1].dofs[2].g1 == Approx(1.3).epsilon(0.1));
    const DesignedMotion designed = designMotion(*basis, parameters->phase.curve, parameters->gains);
    const double error = relativeError(designed.axisCoordinates, emotional);
    const double before = relativeError(basis->coordinates, emotional);
    INFO("relative error designed " << error << ", undesigned " << before);
    CHECK(error < 0.25 * before);
}

TEST_CASE("gains re-extracted for edited phrase boundaries keep the phase and follow the new phrases")
{
    const Take functional = bunraku::test::livelyTake(106);
    const auto basis = prepareDesign(model(), functional);
    REQUIRE(basis.ok());
    GainSet truthGains = unitGains({0, 40, 105}, {"x", "y", "z", "rx", "ry", "rz"});
    truthGains.phrases[0].dofs[2].g1 = 0.7;
    truthGains.phrases[1].dofs[2].g1 = 1.3;
    Eigen::VectorXd truth(106);
    for (int u = 0; u < 106; ++u) truth[u] = knownWarp(u);
    const Eigen::MatrixXd emotional = resampleRows(applyGains(basis->coordinates, truthGains), truth);
    ExtractionOptions options;
    options.boundaries = {0, 40, 105};
    const auto parameters = extractDesign(basis->coordinates, emotional, options);
    REQUIRE(parameters.ok());

    // the boundaries of the extraction: the same gains
    const auto same = extractGainsForBoundaries(basis->coordinates, *parameters, {0, 40, 105});
    REQUIRE(same.ok());
    REQUIRE(same->phrases.size() == parameters->gains.phrases.size());
    for (std::size_t p = 0; p < same->phrases.size(); ++p)
        for (std::size_t d = 0; d < same->phrases[p].dofs.size(); ++d) {
            CHECK(same->phrases[p].dofs[d].g0 == parameters->gains.phrases[p].dofs[d].g0);
            CHECK(same->phrases[p].dofs[d].g1 == parameters->gains.phrases[p].dofs[d].g1);
        }

    // the second phrase split in two: phrase 0 unchanged, both halves carry the second phrase's scaling
    const auto split = extractGainsForBoundaries(basis->coordinates, *parameters, {0, 40, 72, 105});
    REQUIRE(split.ok());
    REQUIRE(split->phrases.size() == 3);
    CHECK(split->phrases[1].begin == 40);
    CHECK(split->phrases[1].end == 72);
    CHECK(split->phrases[2].begin == 72);
    CHECK(split->dofNames == parameters->gains.dofNames);
    CHECK(split->phrases[0].dofs[2].g1 == parameters->gains.phrases[0].dofs[2].g1);
    CHECK(split->phrases[1].dofs[2].g1 == Approx(1.3).epsilon(0.15));
    CHECK(split->phrases[2].dofs[2].g1 == Approx(1.3).epsilon(0.15));

    // bad boundaries and a mismatched extraction are errors, not crashes
    CHECK_FALSE(extractGainsForBoundaries(basis->coordinates, *parameters, {0, 60, 40, 105}).ok());
    CHECK_FALSE(extractGainsForBoundaries(basis->coordinates.topRows(50), *parameters, {0, 49}).ok());
}
