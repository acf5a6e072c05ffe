// The workbench and the command line compute the same bits: the GUI's stage results against the
// data files `bunraku analyse` writes for the same corpus and parameters, per stage; the CLI on
// one thread, the workbench on one per hardware thread (its default).
#include "tests/app/app_test_support.h"
#include "tests/app/bandai_corpus_support.h"

#include "app/analysis_controller.h"
#include "app/commands.h"
#include "app/design_controller.h"

#include "analysis/core/parallel.h"
#include "analysis/decompose/emotion_weight.h"
#include "analysis/io/take_csv.h"
#include "analysis/io/text_format.h"
#include "analysis/pipeline/parameters_json.h"
#include "analysis/report/analysis_files.h"

#include <catch2/catch.hpp>

#include <QProcess>

#include <fstream>
#include <sstream>

using namespace bunraku;

namespace {

Eigen::MatrixXd csvValues(const std::filesystem::path& file)
{
    auto take = analysis::io::readTakeCsv(file);
    INFO(file.string() << ": " << (take ? "" : take.error().message));
    REQUIRE(take.ok());
    return take->values;
}

std::string text(const std::filesystem::path& file)
{
    std::ifstream in(file);
    std::stringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
}

/// The Emotion dock's weighted take (y + a z of take A's cell, eq. 4.45) against `bunraku emotion
/// CORPUS ... -o X.csv` run with the window's parameters: the same values bit for bit (the take
/// CSV prints the shortest text that reads back to the same double).
void checkWeightedTakeEqualsCli(app::MainWindow& window, const std::string& corpus, std::size_t takeA, double weight,
                                const std::filesystem::path& dir)
{
    auto& document = window.document();
    document.selectTake(app::TakeSlot::A, app::TakeId::corpus(takeA));
    REQUIRE(app::setEmotionWeight(document, weight));
    auto& analysis = window.analysis();
    REQUIRE(QTest::qWaitFor([&] { return !analysis.scheduler().busy() && analysis.decomposed() && analysis.weightedTake(); }, 120000));
    const auto weighted = analysis.weightedTake();
    REQUIRE(document.take(app::TakeId::live(QStringLiteral("weighted"))) == weighted);
    const auto [function, emotion] = analysis.weightedCell();
    // The window's parameters (the thesis's defaults here) as a --parameters file.
    const auto parameters = dir / "parameters.json";
    {
        std::ofstream out(parameters);
        out << analysis::pipeline::toJson(document.parameters()).dump(2);
    }
    const auto file = dir / "weighted.csv";
    QProcess cli;
    cli.start(QStringLiteral(BUNRAKU_CLI),
              {QStringLiteral("emotion"), QString::fromStdString(corpus), QStringLiteral("--function"), QString::fromStdString(function),
               QStringLiteral("--emotion"), QString::fromStdString(emotion), QStringLiteral("--weight"),
               QString::fromStdString(analysis::io::shortestNumber(weight)), QStringLiteral("--parameters"),
               QString::fromStdString(parameters.string()), QStringLiteral("-o"), QString::fromStdString(file.string()),
               QStringLiteral("--json")});
    REQUIRE(cli.waitForFinished(300000));
    INFO(cli.readAllStandardError().toStdString());
    REQUIRE(cli.exitCode() == 0);
    const auto summary = nlohmann::json::parse(cli.readAllStandardOutput().toStdString());
    CHECK(summary.at("input") == "normalised");
    CHECK(summary.at("method") == "km2o");
    CHECK(summary.at("frames") == weighted->frameCount());
    INFO(function << "/" << emotion << " a = " << weight);
    CHECK(csvValues(file) == weighted->values);
}

} // namespace

TEST_CASE("the Emotion dock's weighted take equals bunraku emotion's on the demo corpus bit for bit", "[app][pipeline][cli][emotion]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    const auto dir = test::scratchDir("peer-emotion-demo");
    SECTION("an emotional take A: its own cell") { checkWeightedTakeEqualsCli(*window, "demo", 7, 1.75, dir); }
    SECTION("a neutral take A: its function's first emotion") { checkWeightedTakeEqualsCli(*window, "demo", 0, 0.5, dir); }
}

TEST_CASE("the Emotion dock's weighted take equals bunraku emotion's on Bandai takes bit for bit", "[app][pipeline][cli][emotion][bandai]")
{
    const auto corpus = test::bandaiCorpusFolder({"wave-right-hand_normal_001.bvh", "wave-right-hand_normal_002.bvh",
                                                  "wave-right-hand_exhausted_001.bvh", "wave-right-hand_exhausted_002.bvh"},
                                                 "peer-emotion-bandai", "waves");
    if (corpus.empty()) return;
    auto window = test::windowOnCorpus(corpus);
    REQUIRE(window);
    const auto& takes = window->document().corpus().takes;
    const auto exhausted = std::find_if(takes.begin(), takes.end(), [](const analysis::Take& t) { return t.labels.emotion == "exhausted"; });
    REQUIRE(exhausted != takes.end());
    checkWeightedTakeEqualsCli(*window, corpus.string(), std::size_t(exhausted - takes.begin()), 2.0, corpus.parent_path());
}

TEST_CASE("the workbench's stage results equal bunraku analyse's data files bit for bit", "[app][pipeline][cli]")
{
    const auto dir = test::scratchDir("peer-analyse");
    QProcess cli;
    cli.start(QStringLiteral(BUNRAKU_CLI), {QStringLiteral("analyse"), QStringLiteral("demo"), QStringLiteral("-o"),
                                            QString::fromStdString((dir / "out").string()), QStringLiteral("--json"),
                                            QStringLiteral("--threads"), QStringLiteral("1")});
    REQUIRE(cli.waitForFinished(120000));
    INFO(cli.readAllStandardError().toStdString());
    REQUIRE(cli.exitCode() == 0);
    const auto out = dir / "out";

    auto window = test::demoWindow();
    REQUIRE(window);
    auto& analysis = window->analysis();
    CHECK(analysis.scheduler().threads() == bunraku::analysis::resolveThreads(0));
    REQUIRE(QTest::qWaitFor([&] { return !analysis.scheduler().busy() && analysis.axes() && analysis.decomposed(); }, 120000));

    SECTION("preprocess (2.2): the same takes - the GUI no longer normalises raw takes")
    {
        for (const auto& take : analysis.preprocessed()->corpus.takes)
            CHECK(csvValues(out / ("preprocessed_" + analysis::report::takeStem(take.labels) + ".csv")) == take.values);
    }
    SECTION("normalise (3): every cell's normalised takes, reference and variance table")
    {
        for (const auto& cell : analysis.normalised()->cells) {
            const std::string stem = analysis::report::cellStem(cell.function, cell.emotion);
            for (std::size_t k = 0; k < cell.normalisations.size(); ++k)
                CHECK(csvValues(out / ("normalised_" + stem + "_" + std::to_string(cell.takeIndices[k]) + ".csv")) ==
                      cell.normalisations[k].normalised.values);
            CHECK(csvValues(out / ("reference_" + stem + ".csv")) == cell.referenceTake.values);
            CHECK(csvValues(out / ("average_" + stem + ".csv")) == cell.average.values);
        }
        // and what the Normalisation panel shows is take A's row of that cell
        const auto takeA = window->document().selectedTake(app::TakeSlot::A);
        const auto* cell = analysis.normalised()->cell(takeA->labels.function, takeA->labels.emotion);
        REQUIRE(cell);
        // (shown as its body; the analysis's per-channel take is kept beside it)
        const auto live = window->document().perChannelGhostOf(app::TakeId::live(QStringLiteral("normalised")));
        REQUIRE(live);
        CHECK(csvValues(out / ("normalised_" + analysis::report::takeStem(takeA->labels) + ".csv")) == live->values);
    }
    SECTION("decompose (4): KM2O with M chosen by P, y and z")
    {
        const auto& d = analysis.decomposed()->components;
        // y is written as a pose (Euler angles), z as it is (angles in rotation coordinates)
        for (const auto& y : d.functions)
            CHECK(csvValues(out / ("y_" + y.function + ".csv")) == analysis::functionComponentTake(d, y.function)->values);
        for (const auto& z : d.emotions) CHECK(csvValues(out / ("z_" + analysis::report::cellStem(z.function, z.emotion) + ".csv")) == z.values);
        REQUIRE(analysis.decomposed()->km2o);
        std::ostringstream byM;
        byM << "M,mean_P_percent\n";
        const auto& km2o = *analysis.decomposed()->km2o;
        for (std::size_t i = 0; i < km2o.candidateLengths.size(); ++i)
            byM << km2o.candidateLengths[i] << ',' << analysis::io::shortestNumber(km2o.meanErrorPercent[i]) << '\n';
        CHECK(text(out / "km2o_by_M.csv") == byM.str());
    }
    SECTION("motion axes, phase and gains (5)")
    {
        for (const auto& function : analysis.axes()->functions)
            CHECK(csvValues(out / ("axis_functional_" + function.function + ".csv")) == function.basis->coordinates);
        for (const auto& cell : analysis.axes()->cells) {
            const std::string stem = analysis::report::cellStem(cell.function, cell.emotion);
            CHECK(csvValues(out / ("axis_emotional_" + stem + ".csv")) == cell.coordinates);
            std::string warp = "output_frame,source_frame\n";
            for (const auto& point : cell.extracted.phase.curve.points)
                warp += analysis::io::shortestNumber(point.output) + "," + analysis::io::shortestNumber(point.source) + "\n";
            CHECK(text(out / ("warp_" + stem + ".csv")) == warp);
        }
        // The design panel's functional take is the neutral cell's average take the CLI wrote.
        REQUIRE(QTest::qWaitFor([&] { return window->design().ready(); }, 60000));
        const auto shown = window->document().take(window->design().sourceId());
        REQUIRE(shown);
        const auto ghost = window->document().perChannelGhostOf(window->design().sourceId());
        const auto functional = ghost ? ghost : shown;
        CHECK(csvValues(out / ("average_" + analysis::report::cellStem(functional->labels.function, "none") + ".csv")) ==
              functional->values);
    }
}

TEST_CASE("File > Export Report writes the open corpus's report", "[app][report]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    REQUIRE(QTest::qWaitFor([&] { return !window->analysis().scheduler().busy() && window->analysis().axes(); }, 120000));
    const auto dir = test::scratchDir("gui-report");
    const QString file = QString::fromStdString((dir / "report.html").string());
    REQUIRE(window->exportReport(file));
    const std::string html = text(dir / "report.html");
    for (const std::string id : {"overview", "normalise", "km2o", "gains"}) CHECK(html.find("<section id=\"" + id + "\">") != std::string::npos);
    CHECK(html.find("<script") == std::string::npos);
}
