#include "analysis/synth/demo_corpus.h"

#include "analysis/core/puppet_layout.h"
#include "analysis/synth/motion_curves.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <map>

using namespace bunraku::analysis;
using namespace bunraku::analysis::synth;

namespace {

const DemoCorpus& demo()
{
    static const DemoCorpus corpus = generateDemoCorpus();
    return corpus;
}

const CellTruth& cellOf(const std::string& function, const std::string& emotion)
{
    const CellTruth* cell = demo().truth.cell(function, emotion);
    REQUIRE(cell != nullptr);
    return *cell;
}

double column(const Eigen::MatrixXd& m, int part, Dof dof, bool maximum)
{
    const auto c = m.col(puppetChannel(part, dof));
    return maximum ? c.maxCoeff() : c.minCoeff();
}

constexpr int kHead = 0, kShoulder = 1, kArm = 2, kHand = 3;

} // namespace

TEST_CASE("demo corpus has the thesis's shape: 2 functions x 3 emotions x 5 takes, 24 channels, 5 Hz", "[synth]")
{
    const Corpus& corpus = demo().corpus;
    REQUIRE(validateCorpus(corpus).ok());
    CHECK(corpus.functions() == std::vector<std::string>{"greeting", "serving-tea"});
    CHECK(corpus.emotions() == std::vector<std::string>{"none", "friendly", "hostile"});
    CHECK(corpus.takes.size() == 30);
    CHECK(corpus.rateHz == 5.0);
    Eigen::Index longest = 0;
    int longestCount = 0;
    for (const Take& take : corpus.takes) {
        CHECK(hasPuppetLayout(take));
        CHECK(take.rateHz == 5.0);
        CHECK(take.frameCount() >= 100);
        CHECK(take.frameCount() <= 106);
        if (take.frameCount() == 106) ++longestCount;
        longest = std::max(longest, take.frameCount());
    }
    CHECK(longest == 106);
    CHECK(longestCount == 1); // the others are a few frames shorter
    for (const auto& f : corpus.functions())
        for (const auto& e : corpus.emotions()) CHECK(corpus.cell(f, e).size() == 5);
}

TEST_CASE("demo corpus is deterministic per seed and differs between seeds", "[synth]")
{
    DemoOptions options;
    options.seed = 7;
    const DemoCorpus a = generateDemoCorpus(options);
    const DemoCorpus b = generateDemoCorpus(options);
    options.seed = 8;
    const DemoCorpus c = generateDemoCorpus(options);
    REQUIRE(a.corpus.takes.size() == b.corpus.takes.size());
    bool anyDifference = false;
    for (std::size_t i = 0; i < a.corpus.takes.size(); ++i) {
        CHECK(a.corpus.takes[i].values == b.corpus.takes[i].values);
        CHECK(a.truth.takes[i].takeToCell == b.truth.takes[i].takeToCell);
        const auto& x = a.corpus.takes[i].values;
        const auto& y = c.corpus.takes[i].values;
        anyDifference = anyDifference || x.rows() != y.rows() || x != y;
    }
    CHECK(anyDifference);
    // The design (cells) does not depend on the seed; only the takes do.
    CHECK(a.truth.cells[4].motion == c.truth.cells[4].motion);
}

TEST_CASE("each cell has exactly one late start that holds still before moving", "[synth]")
{
    const DemoGroundTruth& truth = demo().truth;
    std::map<std::pair<std::string, std::string>, int> lateCount;
    for (std::size_t i = 0; i < truth.takes.size(); ++i) {
        const TakeTruth& t = truth.takes[i];
        const Take& take = demo().corpus.takes[i];
        REQUIRE(take.labels == t.labels);
        if (t.lateStartFrames == 0) {
            CHECK(t.takeToCell(1) > 0.0);
            continue;
        }
        ++lateCount[{t.labels.function, t.labels.emotion}];
        CHECK(t.lateStartFrames >= 5);
        CHECK(t.lateStartFrames <= 10);
        CHECK(t.takeToCell.head(t.lateStartFrames + 1).isZero());
        CHECK(t.takeToCell(t.lateStartFrames + 1) > 0.0);
        // The raw take holds still (up to the sensor noise) during the late start.
        for (int f = 1; f <= t.lateStartFrames; ++f)
            for (int c = 0; c < kPuppetChannelCount; ++c) {
                const double sigma = isAngleDof(c % kDofCount) ? truth.angleNoiseDeg : truth.positionNoiseCm;
                CHECK(std::abs(wrapDegrees(take.values(f, c) - take.values(0, c))) < 8.0 * sigma);
            }
    }
    CHECK(lateCount.size() == 6);
    for (const auto& [cell, count] : lateCount) CHECK(count == 1);
}

TEST_CASE("take warps are monotone, end on the last cell frame and stay within about 15 percent speed", "[synth]")
{
    for (const TakeTruth& t : demo().truth.takes) {
        const Eigen::Index n = t.takeToCell.size();
        CHECK(t.takeToCell(n - 1) == 105.0);
        for (Eigen::Index f = t.lateStartFrames + 1; f < n; ++f) {
            const double speed = t.takeToCell(f) - t.takeToCell(f - 1);
            CHECK(speed > 0.75);
            CHECK(speed < 1.3);
        }
    }
}

TEST_CASE("some raw takes have yaw channels crossing +-180 and every angle is wrapped", "[synth]")
{
    int crossingTakes = 0;
    for (std::size_t i = 0; i < demo().corpus.takes.size(); ++i) {
        const Take& take = demo().corpus.takes[i];
        bool crosses = false;
        for (int part = 0; part < kPuppetPartCount; ++part) {
            const auto yaw = take.values.col(puppetChannel(part, Dof::Yaw));
            for (Eigen::Index f = 1; f < yaw.size(); ++f) crosses = crosses || std::abs(yaw(f) - yaw(f - 1)) > 300.0;
        }
        CHECK(crosses == demo().truth.takes[i].yawWraps);
        if (crosses) ++crossingTakes;
        for (int c = 0; c < kPuppetChannelCount; ++c)
            if (isAngleDof(c % kDofCount)) {
                CHECK(take.values.col(c).maxCoeff() <= 180.0);
                CHECK(take.values.col(c).minCoeff() > -180.0);
            }
    }
    CHECK(crossingTakes == 6); // one per cell
}

TEST_CASE("residual of each take against its stored expected value has the stated noise level", "[synth]")
{
    const DemoGroundTruth& truth = demo().truth;
    double positionSum = 0.0, angleSum = 0.0;
    long positionCount = 0, angleCount = 0;
    for (const Take& take : demo().corpus.takes) {
        const auto expected = noiselessTake(truth, take.labels);
        REQUIRE(expected.ok());
        REQUIRE(expected->rows() == take.frameCount());
        for (Eigen::Index f = 0; f < take.frameCount(); ++f)
            for (int c = 0; c < kPuppetChannelCount; ++c) {
                const double r = wrapDegrees(take.values(f, c) - (*expected)(f, c)); // also fine for cm: |r| << 180
                if (isAngleDof(c % kDofCount)) {
                    angleSum += r * r;
                    ++angleCount;
                } else {
                    positionSum += r * r;
                    ++positionCount;
                }
            }
    }
    CHECK(std::sqrt(positionSum / double(positionCount)) == Approx(0.1).epsilon(0.05));
    CHECK(std::sqrt(angleSum / double(angleCount)) == Approx(0.2).epsilon(0.05));
}

TEST_CASE("un-warping a take by its stored warp, jitter and offsets reproduces the cell's motion within the noise",
          "[synth]")
{
    const DemoGroundTruth& truth = demo().truth;
    for (const Take& take : demo().corpus.takes) {
        const TakeTruth& t = *truth.take(take.labels);
        const CellTruth& cell = *truth.cell(take.labels.function, take.labels.emotion);
        const Eigen::MatrixXd shown = resampleMotion(cell.motion, t.takeToCell); // the cell at the take's times
        const Eigen::RowVectorXd start = cell.motion.row(0);
        const Eigen::Vector3d pivot = headingPivot(cell);
        const Eigen::Matrix3d turn = headingTurn(t);
        double worst = 0.0;
        for (Eigen::Index f = 0; f < take.frameCount(); ++f)
            for (int c = 0; c < kPuppetChannelCount; ++c) {
                const int dof = c % kDofCount;
                double value = take.values(f, c);
                if (dof < 3) {
                    // Undo the rigid heading turn and the translation of the part's position.
                    const Eigen::Vector3d position = take.values.row(f).segment<3>(c - dof).transpose();
                    value = (turn.transpose() * (position - t.positionOffset - pivot) + pivot)(dof);
                }
                if (dof == int(Dof::Yaw)) value -= t.yawOffsetDeg;
                // Undo the wrap: the angle closest to the cell's value.
                if (isAngleDof(dof)) value = shown(f, c) + wrapDegrees(value - shown(f, c));
                const double unjittered = start(c) + (value - start(c)) / t.amplitudeGain;
                const double sigma = isAngleDof(dof) ? truth.angleNoiseDeg : truth.positionNoiseCm;
                worst = std::max(worst, std::abs(unjittered - shown(f, c)) / sigma);
            }
        CHECK(worst < 5.5); // about 2500 samples per take: 5.5 sigma is never reached by chance
        CHECK(worst > 1.0); // and there is noise
    }
}

TEST_CASE("function plus emotion components equal the noiseless cell motion, and z is zero for none", "[synth]")
{
    const DemoGroundTruth& truth = demo().truth;
    REQUIRE(truth.cells.size() == 6);
    for (const CellTruth& cell : truth.cells) {
        const FunctionTruth* f = truth.function(cell.function);
        REQUIRE(f != nullptr);
        CHECK(cell.motion.rows() == 106);
        CHECK(cell.motion.cols() == 24);
        CHECK((f->motion + cell.emotionComponent - cell.motion).cwiseAbs().maxCoeff() < 1e-12);
        if (cell.emotion == truth.neutralEmotion) {
            CHECK(cell.emotionComponent.isZero(0.0));
            CHECK(cell.motion == f->motion);
            CHECK(cell.phaseWarp == Eigen::VectorXd::LinSpaced(106, 0.0, 105.0));
            CHECK((cell.phraseGains.array() == 1.0).all());
        } else {
            CHECK(cell.emotionComponent.cwiseAbs().maxCoeff() > 5.0);
        }
    }
}

TEST_CASE("phase warps map the cell's phrase boundaries onto the function's and invert", "[synth]")
{
    const DemoGroundTruth& truth = demo().truth;
    for (const CellTruth& cell : truth.cells) {
        const FunctionTruth& f = *truth.function(cell.function);
        REQUIRE(cell.phraseBoundaries.size() == f.phraseBoundaries.size());
        CHECK(cell.phraseGains.rows() == Eigen::Index(f.phraseNames.size()));
        CHECK(cell.phraseGains.cols() == Eigen::Index(truth.parameterNames.size()));
        for (std::size_t k = 0; k < f.phraseBoundaries.size(); ++k) {
            const double u = cell.phraseBoundaries[k];
            REQUIRE(u == std::floor(u)); // boundaries are whole frames
            CHECK(cell.phaseWarp(Eigen::Index(u)) == Approx(f.phraseBoundaries[k]).margin(1e-9));
        }
        for (Eigen::Index s = 1; s < 106; ++s) {
            CHECK(cell.phaseWarp(s) > cell.phaseWarp(s - 1));
            CHECK(cell.functionalToEmotional(s) > cell.functionalToEmotional(s - 1));
        }
        // functionalToEmotional is the inverse of the (continuous) phase warp at whole frames.
        for (Eigen::Index u = 0; u < 106; ++u) {
            const double s = cell.phaseWarp(u);
            const Eigen::Index k = std::min<Eigen::Index>(Eigen::Index(s), 104);
            const double back = cell.functionalToEmotional(k) + (s - double(k)) *
                                                                   (cell.functionalToEmotional(k + 1) - cell.functionalToEmotional(k));
            CHECK(back == Approx(double(u)).margin(0.05));
        }
    }
}

TEST_CASE("friendly greeting bows deeper than none and hostile less", "[synth]")
{
    for (int part : {kHead, kShoulder}) {
        const double none = column(cellOf("greeting", "none").motion, part, Dof::Pitch, true);
        const double friendly = column(cellOf("greeting", "friendly").motion, part, Dof::Pitch, true);
        const double hostile = column(cellOf("greeting", "hostile").motion, part, Dof::Pitch, true);
        CHECK(friendly > none + 5.0);
        CHECK(hostile < none - 10.0);
    }
    // The bow also lowers the shoulder: deepest for friendly.
    CHECK(column(cellOf("greeting", "friendly").motion, kShoulder, Dof::Z, false) <
          column(cellOf("greeting", "none").motion, kShoulder, Dof::Z, false));
}

TEST_CASE("friendly tea travels further and stays low, hostile tea turns the head away and travels less", "[synth]")
{
    const auto& none = cellOf("serving-tea", "none").motion;
    const auto& friendly = cellOf("serving-tea", "friendly").motion;
    const auto& hostile = cellOf("serving-tea", "hostile").motion;
    const int x = puppetChannel(kShoulder, Dof::X);
    CHECK(friendly.col(x).maxCoeff() - friendly(0, x) > none.col(x).maxCoeff() - none(0, x) + 5.0);
    CHECK(hostile.col(x).maxCoeff() - hostile(0, x) < none.col(x).maxCoeff() - none(0, x) - 5.0);
    const int z = puppetChannel(kShoulder, Dof::Z);
    CHECK(friendly(105, z) < none(105, z) - 2.0);
    const int pitch = puppetChannel(kShoulder, Dof::Pitch);
    CHECK(friendly(105, pitch) > none(105, pitch) + 5.0);
    // Head yaw relative to the shoulder, averaged over the motion.
    auto headTurn = [](const Eigen::MatrixXd& m) {
        return (m.col(puppetChannel(kHead, Dof::Yaw)) - m.col(puppetChannel(kShoulder, Dof::Yaw))).mean();
    };
    CHECK(headTurn(hostile) > headTurn(none) + 15.0);
    CHECK(headTurn(cellOf("greeting", "hostile").motion) > headTurn(cellOf("greeting", "none").motion) + 15.0);
}

TEST_CASE("noiseless motions are physically plausible: rigid distances, no gimbal lock, smooth", "[synth]")
{
    for (const CellTruth& cell : demo().truth.cells) {
        const auto& m = cell.motion;
        for (Eigen::Index f = 0; f < m.rows(); ++f) {
            auto position = [&](int part) { return Eigen::Vector3d(m.row(f).segment<3>(part * kDofCount).transpose()); };
            const double neck = (position(kHead) - position(kShoulder)).norm();
            CHECK(neck > 10.0);
            CHECK(neck < 20.0);
            CHECK((position(kHand) - position(kArm)).norm() < 25.0);
            CHECK((position(kArm) - position(kShoulder)).norm() < 35.0);
            for (int part = 0; part < kPuppetPartCount; ++part)
                CHECK(std::abs(m(f, puppetChannel(part, Dof::Pitch))) < 80.0);
        }
        // Smooth at 5 Hz: no channel moves more than 6 cm or 15 degrees between frames.
        const Eigen::MatrixXd step = (m.bottomRows(105) - m.topRows(105)).cwiseAbs();
        for (int c = 0; c < kPuppetChannelCount; ++c)
            CHECK(step.col(c).maxCoeff() < (isAngleDof(c % kDofCount) ? 15.0 : 6.0));
        // Never a pure plateau: every part keeps moving during holds (sway).
        for (Eigen::Index f = 20; f < 105; f += 5)
            CHECK((m.row(f) - m.row(f - 5)).cwiseAbs().maxCoeff() > 0.3);
    }
}

TEST_CASE("a demo take is named demo:FUNCTION/EMOTION/K, and a name that names none says what there is", "[synth][demo]")
{
    const synth::DemoCorpus demo = synth::generateDemoCorpus();
    CHECK(synth::isDemoTakeName("demo:greeting/friendly/1"));
    CHECK_FALSE(synth::isDemoTakeName("greeting/friendly/1"));
    CHECK_FALSE(synth::isDemoTakeName("takes/demo:1.bvh"));
    auto take = synth::demoTake("demo:serving-tea/hostile/3");
    REQUIRE(take.ok());
    const Take* peer = demo.corpus.find("serving-tea", "hostile", 3);
    REQUIRE(peer != nullptr);
    CHECK(take->labels.takeIndex == 3);
    CHECK(take->values == peer->values);

    for (const char* malformed : {"demo:", "demo:greeting/friendly", "demo:greeting/friendly/0", "demo:greeting/friendly/x",
                                  "demo:a/b/1/2", "model.bvh"}) {
        INFO(malformed);
        auto refused = synth::demoTake(malformed);
        REQUIRE_FALSE(refused.ok());
        CHECK(refused.error().code == ErrorCode::InvalidArgument);
        CHECK(refused.error().message == "'" + std::string(malformed) + "': expected demo:FUNCTION/EMOTION/K, e.g. demo:greeting/friendly/1");
    }
    auto missing = synth::demoTake("demo:greeting/joyful/6");
    REQUIRE_FALSE(missing.ok());
    CHECK(missing.error().code == ErrorCode::NotFound);
    CHECK(missing.error().message == "'demo:greeting/joyful/6': no such demo take (functions: greeting, serving-tea; emotions: "
                                     "none, friendly, hostile; K = 1..5)");
}
