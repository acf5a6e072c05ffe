#include "analysis/design/phrase_gains.h"

#include "tests/support/test_paths.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>

using namespace bunraku::analysis;

namespace {

/// Two DOF over 106 frames: a "height" around 80 (large DC) and a "sway" around 0.
Eigen::MatrixXd functionalSignal()
{
    Eigen::MatrixXd x(106, 2);
    for (int t = 0; t < 106; ++t) {
        x(t, 0) = 80.0 + 6.0 * std::sin(t / 7.0) + 0.05 * t;
        x(t, 1) = 4.0 * std::sin(t / 5.0 + 0.3);
    }
    return x;
}

} // namespace

TEST_CASE("gains recover known per-phrase scalings")
{
    const Eigen::MatrixXd functional = functionalSignal();
    const std::vector<Eigen::Index> boundaries{0, 30, 70, 105};
    const std::vector<std::string> names{"h", "s"};
    // truth: per phrase, the emotional DC is the functional DC / g0 and the AC is divided by g1
    const double trueG0[3] = {1.0, 0.9, 1.1};
    const double trueG1[3] = {0.5, 2.0, 0.8};
    GainSet truth = unitGains(boundaries, names);
    truth.blendFrames = 0;
    for (int p = 0; p < 3; ++p) {
        truth.phrases[std::size_t(p)].dofs[0].g0 = trueG0[p];
        truth.phrases[std::size_t(p)].dofs[0].g1 = trueG1[p];
        truth.phrases[std::size_t(p)].dofs[1].dcMode = DcMode::Offset;
        truth.phrases[std::size_t(p)].dofs[1].offset = 1.5 * p;
        truth.phrases[std::size_t(p)].dofs[1].g1 = trueG1[2 - p];
    }
    // phrases share their boundary frames: each phrase's emotional rows are its own map of the functional rows
    std::vector<Eigen::MatrixXd> emotional;
    for (int p = 0; p < 3; ++p) {
        const Eigen::Index b = boundaries[std::size_t(p)], n = boundaries[std::size_t(p) + 1] - b + 1;
        GainSet one = truth;
        one.phrases = {truth.phrases[std::size_t(p)]};
        one.phrases[0].begin = 0;
        one.phrases[0].end = n - 1;
        emotional.push_back(applyGains(functional.middleRows(b, n), one));
    }
    GainOptions options;
    options.blendFrames = 0;
    // phrases share boundary frames: compare on each phrase's own rows
    for (int p = 0; p < 3; ++p) {
        const Eigen::Index b = boundaries[std::size_t(p)], n = boundaries[std::size_t(p) + 1] - b + 1;
        const auto gains = extractGains(functional.middleRows(b, n), emotional[std::size_t(p)], {0, n - 1}, names, options);
        REQUIRE(gains.ok());
        const DofGain& height = gains->phrases[0].dofs[0];
        CHECK(height.dcMode == DcMode::Scale);
        CHECK(height.g0 == Approx(trueG0[p]).epsilon(1e-9));
        CHECK(height.g1 == Approx(trueG1[p]).epsilon(1e-9));
        const DofGain& sway = gains->phrases[0].dofs[1];
        CHECK(sway.dcMode == DcMode::Offset);
        CHECK(sway.reason.find("near zero") != std::string::npos);
        CHECK(sway.offset == Approx(1.5 * p).margin(1e-9));
        CHECK(sway.g1 == Approx(trueG1[2 - p]).epsilon(1e-9));
        // and designing with them reproduces the emotional phrase exactly
        CHECK((applyGains(functional.middleRows(b, n), *gains) - emotional[std::size_t(p)]).cwiseAbs().maxCoeff() < 1e-9);
    }
}

TEST_CASE("blended phrases join smoothly and a zero DC never blows up")
{
    Eigen::MatrixXd functional = functionalSignal();
    functional.col(1).setZero(); // a DOF that never moves: its DC and A1 are zero
    const std::vector<Eigen::Index> boundaries{0, 50, 105};
    Eigen::MatrixXd emotional = functional;
    emotional.col(1).array() += 2.0;
    emotional.col(0).head(51).array() *= 1.2;
    const auto gains = extractGains(functional, emotional, boundaries, {"h", "s"});
    REQUIRE(gains.ok());
    const DofGain& flat = gains->phrases[0].dofs[1];
    CHECK(flat.dcMode == DcMode::Offset);
    CHECK(flat.g1 == 1.0);
    CHECK(flat.reason.find("flat") != std::string::npos);
    const Eigen::MatrixXd designed = applyGains(functional, *gains);
    CHECK(designed.allFinite());
    CHECK((designed.col(1).array() - 2.0).abs().maxCoeff() < 1e-9);
    // the emotional signal jumps by ~16 at the boundary; the spline blend spreads the change
    // over +-3 frames, so no single step of the design comes near it
    const double jump = std::abs(emotional(50, 0) - emotional(51, 0));
    REQUIRE(jump > 10.0);
    const Eigen::VectorXd steps = (designed.col(0).tail(105) - designed.col(0).head(105)).cwiseAbs();
    CHECK(steps.maxCoeff() < 0.5 * jump);
}

TEST_CASE("phrase boundaries are suggested at minima of the axis speed")
{
    // a centre that moves in three strokes with rests at frames 35 and 70
    Eigen::MatrixXd axis = Eigen::MatrixXd::Zero(106, 6);
    for (int t = 0; t < 106; ++t) {
        const double phase = t < 35 ? t / 35.0 : t < 70 ? (t - 35) / 35.0 : (t - 70) / 35.0;
        axis(t, 0) = 10.0 * (t < 35 ? 0 : t < 70 ? 1 : 2) + 10.0 * (phase - std::sin(2 * M_PI * phase) / (2 * M_PI));  // cycloid: speed zero at each rest
    }
    const auto boundaries = suggestPhraseBoundaries(axis);
    REQUIRE(boundaries.size() == 4);
    CHECK(boundaries.front() == 0);
    CHECK(std::abs(boundaries[1] - 35) <= 2);
    CHECK(std::abs(boundaries[2] - 70) <= 2);
    CHECK(boundaries.back() == 105);
}

TEST_CASE("phrase lists and gain files are checked")
{
    CHECK(parsePhraseBoundaries("0,40,105", 106).ok());
    CHECK_FALSE(parsePhraseBoundaries("0,40,100", 106).ok());
    CHECK_FALSE(parsePhraseBoundaries("0,x,105", 106).ok());
    const auto dir = bunraku::test::scratchDir("gains-json");
    const auto gains = extractGains(functionalSignal(), functionalSignal() * 1.1, {0, 40, 105}, {"h", "s"});
    REQUIRE(gains.ok());
    REQUIRE(writeGainsJson(*gains, dir / "gains.json").ok());
    const auto read = readGainsJson(dir / "gains.json");
    REQUIRE(read.ok());
    REQUIRE(read->phrases.size() == 2);
    CHECK(read->phrases[1].dofs[0].g1 == Approx(gains->phrases[1].dofs[0].g1));
    CHECK(read->phrases[1].end == 105);
    std::ofstream(dir / "bad.json") << R"({"dofs": ["h"], "phrases": [{"begin": 0, "end": 5, "gains": []}]})";
    const auto bad = readGainsJson(dir / "bad.json");
    REQUIRE_FALSE(bad.ok());
    CHECK(bad.error().message.find("one entry per DOF") != std::string::npos);
}

TEST_CASE("a first harmonic opposite to the functional one gives a non-negative g1 and is added, not mirrored")
{
    // thesis eq. 5.23: g1 = A1_no / A1_em is a ratio of magnitudes. The emotional phrase swings
    // the other way at half the amplitude: the old extraction gave g1 = -2.
    const Eigen::MatrixXd functional = functionalSignal();
    Eigen::MatrixXd emotional = functional;
    const Eigen::RowVectorXd mean = functional.colwise().mean();
    for (Eigen::Index t = 0; t < functional.rows(); ++t)
        emotional.row(t) = mean - 0.5 * (functional.row(t) - mean);
    GainOptions options;
    options.blendFrames = 0;
    const auto gains = extractGains(functional, emotional, {0, 105}, {"h", "s"}, options);
    REQUIRE(gains.ok());
    for (const DofGain& gain : gains->phrases[0].dofs) {
        CHECK(gain.g0 > 0.0);
        CHECK(gain.g1 > 0.0);
        CHECK_FALSE(gain.illConditioned);
        CHECK(gain.acMode == AcMode::Additive);
        CHECK(gain.reason.find("out of phase") != std::string::npos);
    }
}

TEST_CASE("an emotional first harmonic below a tenth of the functional one is flagged ill-conditioned and g1 regularised to 10")
{
    const Eigen::MatrixXd functional = functionalSignal();
    const std::vector<Eigen::Index> boundaries{0, 50, 105};
    // phrase 1: the emotion keeps 1 % of the functional wiggle (g1 would be 100, the old clamp);
    // phrase 2: 20 % of it (g1 = 5, well conditioned)
    Eigen::MatrixXd emotional = functional;
    for (int p = 0; p < 2; ++p) {
        const Eigen::Index b = boundaries[std::size_t(p)], n = boundaries[std::size_t(p) + 1] - b + 1;
        const Eigen::RowVectorXd mean = functional.middleRows(b, n).colwise().mean();
        // the shared boundary frame 50 stays phrase 1's
        for (Eigen::Index t = p == 0 ? b : b + 1; t < b + n; ++t)
            emotional.row(t) = mean + (p == 0 ? 0.01 : 0.2) * (functional.row(t) - mean);
    }
    const auto gains = extractGains(functional, emotional, boundaries, {"h", "s"});
    REQUIRE(gains.ok());
    for (std::size_t d = 0; d < 2; ++d) {
        const DofGain& ill = gains->phrases[0].dofs[d];
        CHECK(ill.illConditioned);
        CHECK(ill.g1 == Approx(1.0 / kIllConditionedAmplitudeFraction)); // not the old clamp at 100
        CHECK(ill.acMode == AcMode::Scale);
        CHECK(ill.a1Emotional < kIllConditionedAmplitudeFraction * ill.a1Functional);
        CHECK(ill.illConditionedReason.find("below 0.1 x A1_no") != std::string::npos);
        CHECK(ill.reason.find("ill-conditioned") != std::string::npos);
        const DofGain& fine = gains->phrases[1].dofs[d];
        CHECK_FALSE(fine.illConditioned);
        CHECK(fine.illConditionedReason.empty());
        CHECK(fine.g1 > 3.0); // about 5 (frame 50 is phrase 1's)
        CHECK(fine.g1 < 8.0);
    }
    const auto listed = illConditionedGains(*gains);
    REQUIRE(listed.size() == 2);
    CHECK(listed[0].phrase == 0);
    CHECK(listed[0].dof == 0);
    CHECK(listed[0].dofName == "h");
    CHECK(listed[1].dofName == "s");
    CHECK(listed[1].begin == 0);
    CHECK(listed[1].end == 50);
    CHECK(listed[1].reason == gains->phrases[0].dofs[1].illConditionedReason);

    // gains.json keeps the flag and its reason
    const auto dir = bunraku::test::scratchDir("gains-ill-conditioned");
    REQUIRE(writeGainsJson(*gains, dir / "gains.json").ok());
    const auto read = readGainsJson(dir / "gains.json");
    REQUIRE(read.ok());
    CHECK(read->phrases[0].dofs[1].illConditioned);
    CHECK(read->phrases[0].dofs[1].illConditionedReason == gains->phrases[0].dofs[1].illConditionedReason);
    CHECK_FALSE(read->phrases[1].dofs[1].illConditioned);
}

TEST_CASE("means on opposite sides of zero give an additive offset, never a negative g0")
{
    Eigen::MatrixXd functional = functionalSignal();
    Eigen::MatrixXd emotional = functional;
    emotional.col(0).array() -= 160.0; // the height's mean moves from about +83 to about -77
    const auto gains = extractGains(functional, emotional, {0, 105}, {"h", "s"});
    REQUIRE(gains.ok());
    const DofGain& height = gains->phrases[0].dofs[0];
    CHECK(height.dcMode == DcMode::Offset);
    CHECK(height.g0 == 1.0);
    CHECK(height.offset == Approx(-160.0));
    CHECK(height.reason.find("opposite signs") != std::string::npos);
}
