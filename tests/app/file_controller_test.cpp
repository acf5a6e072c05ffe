#include "tests/app/app_test_support.h"
#include "app/viewport_panel.h"

#include "app/commands.h"
#include "app/design_controller.h"
#include "app/emotion_panel.h"
#include "app/analysis_controller.h"
#include "app/commands.h"

#include "widgets/graph_panel.h"
#include "widgets/corpus_browser.h"

#include "analysis/core/pose.h"
#include "analysis/core/puppet_layout.h"
#include "analysis/io/corpus_io.h"
#include "analysis/io/take_csv.h"
#include "analysis/pipeline/parameters_json.h"
#include "app/project_file.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <QCheckBox>
#include <QComboBox>

#include <QFile>
#include <QFileInfo>

#include <filesystem>
#include <fstream>
#include <map>
#include <tuple>

#include <sys/stat.h>

using namespace bunraku;
using app::TakeSlot;

namespace {

QString scratchFile(const std::string& folder, const std::string& name)
{
    return QString::fromStdString((test::scratchDir(folder) / name).string());
}

/// The imported takes (live results, which come and go with background work, left out).
std::vector<app::DerivedTake> importedTakes(const app::Document& document)
{
    std::vector<app::DerivedTake> imported;
    for (const auto& derived : document.derivedTakes())
        if (!derived.sourcePath.isEmpty()) imported.push_back(derived);
    return imported;
}

} // namespace

TEST_CASE("take A exported to CSV re-imports with the same values", "[app][files]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    auto& files = window->files();
    const auto original = window->document().selectedTake(TakeSlot::A);
    const QString file = scratchFile("export-csv", "take.csv");
    REQUIRE(window->exports().exportTake(TakeSlot::A, file));
    REQUIRE(files.imports().importTakeFile(file));
    const auto imported = window->document().selectedTake(TakeSlot::A);
    REQUIRE(imported != original);
    REQUIRE(imported->channels == original->channels);
    REQUIRE(imported->rateHz == Approx(original->rateHz));
    REQUIRE(imported->frameCount() == original->frameCount());
    REQUIRE((imported->values - original->values).cwiseAbs().maxCoeff() < 1e-9);
    REQUIRE(window->browser()->takeCount() == 30 + int(window->document().derivedTakes().size()));
    REQUIRE(importedTakes(window->document()).size() == 1);
    REQUIRE(importedTakes(window->document()).front().sourcePath == QFileInfo(file).absoluteFilePath());
}

TEST_CASE("take A exported to BVH re-imports to the same part poses", "[app][files]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    auto& files = window->files();
    window->document().selectTake(TakeSlot::A, app::TakeId::corpus(4));
    const auto original = window->document().selectedTake(TakeSlot::A);
    const QString file = scratchFile("export-bvh", "take.bvh");
    REQUIRE(window->exports().exportTake(TakeSlot::A, file));
    REQUIRE(files.imports().importTakeFile(file, QStringLiteral("head=head,shoulder=shoulder,arm=arm,hand=hand")));
    const auto imported = window->document().selectedTake(TakeSlot::A);
    REQUIRE(imported->frameCount() == original->frameCount());
    REQUIRE(imported->rateHz == Approx(original->rateHz));
    REQUIRE(analysis::hasPuppetLayout(*imported));
    for (Eigen::Index frame = 0; frame < original->frameCount(); frame += 7) {
        for (int part = 0; part < analysis::kPuppetPartCount; ++part) {
            const auto a = analysis::partPose(*original, frame, part * 6);
            const auto b = analysis::partPose(*imported, frame, part * 6);
            REQUIRE((a.translation - b.translation).norm() < 1e-6);
            REQUIRE(a.rotation.angularDistance(b.rotation) < 1e-6);
        }
    }
}

TEST_CASE("a take file with a bad value is refused with its file and line, and nothing changes", "[app][files]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    const QString file = scratchFile("bad-import", "bad.csv");
    {
        std::ofstream out(file.toStdString());
        out << "time_s,head.x\n0,1\n0.2,nan\n";
    }
    REQUIRE_FALSE(window->files().imports().importTakeFile(file));
    REQUIRE(window->files().lastError().contains(QStringLiteral("bad.csv:3")));
    REQUIRE(importedTakes(window->document()).empty());
    REQUIRE(window->document().undoStack()->count() == 0);
}

TEST_CASE("a saved project reopens to the same state", "[app][files]")
{
    const QString project = scratchFile("project", "session.bunraku.json");
    const QString takeFile = scratchFile("project-take", "take.csv");
    app::TakeId takeB;
    {
        auto window = test::demoWindow();
        REQUIRE(window);
        auto& document = window->document();
        REQUIRE(window->exports().exportTake(TakeSlot::A, takeFile));
        REQUIRE(window->files().imports().importTakeFile(takeFile));
        app::changeStageParameters(document, [](app::AnalysisParameters& p) { p.normalise.tau = 6; }, QStringLiteral("tau"));
        app::setEmotionWeight(document, 1.75);
        takeB = app::TakeId::corpus(12);
        document.selectTake(TakeSlot::A, app::TakeId::corpus(3));
        document.selectTake(TakeSlot::B, takeB);
        document.setCurrentTime(5.4);
        window->graphPanel()->selectPart(QStringLiteral("arm"));
        window->graphPanel()->setTwoTakeMode(widgets::TwoTakeMode::SideBySide);
        window->graphPanel()->setAngleDisplay(widgets::AngleDisplay::RotationCoordinates);
        window->viewportPanel()->figureBox(1)->setCurrentIndex(2); // take B as both figures
        REQUIRE(window->graphPanel()->grid()->graphCount() == 12);
        REQUIRE(window->isWindowModified());
        REQUIRE(window->files().projects().saveProject(project));
        REQUIRE_FALSE(window->isWindowModified());
    }
    auto window = test::demoWindow();
    REQUIRE(window);
    REQUIRE(window->files().projects().openProject(project));
    const auto& document = window->document();
    REQUIRE(document.corpusSource() == QStringLiteral("demo"));
    REQUIRE(document.parameters().normalise.tau == 6);
    REQUIRE(document.parameters().design.emotionWeight == 1.75);
    REQUIRE(document.selectedId(TakeSlot::A) == app::TakeId::corpus(3));
    REQUIRE(document.selectedId(TakeSlot::B) == takeB);
    REQUIRE(document.currentTime() == Approx(5.4));
    REQUIRE(importedTakes(document).size() == 1);
    REQUIRE(importedTakes(document)[0].sourcePath == takeFile);
    REQUIRE(window->graphPanel()->selectedPart() == QStringLiteral("arm"));
    REQUIRE(window->graphPanel()->grid()->graphCount() == 12);
    REQUIRE(window->graphPanel()->angleDisplay() == widgets::AngleDisplay::RotationCoordinates);
    REQUIRE(window->viewportPanel()->figureBox(0)->currentIndex() == 0);
    REQUIRE(window->viewportPanel()->figureBox(1)->currentIndex() == 2);
    REQUIRE(window->graphPanel()->shownTakeA() != document.selectedTake(TakeSlot::A)); // the coordinates' copy
    REQUIRE(window->files().projects().projectPath() == project);
    REQUIRE_FALSE(window->isWindowModified());
}

TEST_CASE("a project saved while live takes are shown reopens showing them once recomputed", "[app][files]")
{
    const QString project = scratchFile("project-live", "live.bunraku.json");
    std::vector<Eigen::Index> boundaries;
    {
        auto window = test::demoWindow();
        REQUIRE(window);
        auto& document = window->document();
        REQUIRE(QTest::qWaitFor([&] { return window->design().ready() && window->emotionPanel()->weightedTake(); }, 60000));
        auto& design = window->design();
        design.moveBoundary(0, double(design.boundaries()[1] + 2)); // an edited phrase boundary
        boundaries = design.boundaries();
        document.selectTake(TakeSlot::A, app::TakeId::live(QStringLiteral("designed")));
        document.selectTake(TakeSlot::B, app::TakeId::live(QStringLiteral("weighted")));
        REQUIRE(document.selectedId(TakeSlot::A) == QStringLiteral("live/designed"));
        document.setCurrentTime(2.0);
        REQUIRE(window->files().projects().saveProject(project));
    }
    auto window = test::demoWindow();
    REQUIRE(window);
    REQUIRE(window->files().projects().openProject(project));
    const auto& document = window->document();
    const bool shown = QTest::qWaitFor(
        [&] {
            return document.selectedId(TakeSlot::A) == QStringLiteral("live/designed") &&
                   document.selectedId(TakeSlot::B) == QStringLiteral("live/weighted");
        },
        60000);
    INFO("A " << document.selectedId(TakeSlot::A).toString().toStdString() << ", B " << document.selectedId(TakeSlot::B).toString().toStdString()
              << ", pending A " << window->files().projects().pendingLiveTake(TakeSlot::A).toString().toStdString() << ", pending B "
              << window->files().projects().pendingLiveTake(TakeSlot::B).toString().toStdString() << ", designed "
              << (document.take(app::TakeId::live(QStringLiteral("designed"))) != nullptr) << ", weighted "
              << (document.take(app::TakeId::live(QStringLiteral("weighted"))) != nullptr));
    REQUIRE(shown);
    REQUIRE(window->files().projects().pendingLiveTake(TakeSlot::A).isEmpty());
    REQUIRE(window->files().projects().pendingLiveTake(TakeSlot::B).isEmpty());
    REQUIRE(document.currentTime() == Approx(2.0));
    REQUIRE(window->design().boundaries() == boundaries);
    REQUIRE(document.selectedTake(TakeSlot::A) == window->design().designedTake());
}

TEST_CASE("a project saved with a live take of another cell as A reopens it computed for that cell", "[app][files]")
{
    // A GUI walk found a designed take of serving-tea reopened as one of greeting (the corpus's
    // first cell): the project did not say which cell the live results were computed for.
    const QString project = scratchFile("project-live-cell", "cell.bunraku.json");
    QString designedLabel, weightedLabel;
    std::vector<Eigen::Index> boundaries;
    {
        auto window = test::demoWindow();
        REQUIRE(window);
        auto& document = window->document();
        const auto& takes = document.corpus().takes;
        const auto other = std::find_if(takes.begin(), takes.end(), [&](const analysis::Take& take) {
            return take.labels.function != takes.front().labels.function && take.labels.emotion == "hostile";
        });
        REQUIRE(other != takes.end());
        document.selectTake(TakeSlot::A, app::TakeId::corpus(std::size_t(other - takes.begin())));
        REQUIRE(test::waitUntilIdle(*window));
        REQUIRE(window->analysis().cellFunction() == other->labels.function);
        REQUIRE(QTest::qWaitFor([&] { return window->design().ready() && window->emotionPanel()->weightedTake(); }, 60000));
        document.selectTake(TakeSlot::A, app::TakeId::live(QStringLiteral("designed")));
        REQUIRE(test::waitUntilIdle(*window));
        designedLabel = document.takeLabel(app::TakeId::live(QStringLiteral("designed")));
        weightedLabel = document.takeLabel(app::TakeId::live(QStringLiteral("weighted")));
        boundaries = window->design().boundaries();
        REQUIRE(designedLabel.contains(QString::fromStdString(other->labels.function)));
        REQUIRE(window->files().projects().saveProject(project));
    }
    auto window = test::demoWindow();
    REQUIRE(window);
    REQUIRE(window->files().projects().openProject(project));
    const auto& document = window->document();
    REQUIRE(QTest::qWaitFor([&] { return document.selectedId(TakeSlot::A) == QStringLiteral("live/designed"); }, 60000));
    REQUIRE(test::waitUntilIdle(*window));
    CHECK(document.takeLabel(app::TakeId::live(QStringLiteral("designed"))).toStdString() == designedLabel.toStdString());
    CHECK(document.takeLabel(app::TakeId::live(QStringLiteral("weighted"))).toStdString() == weightedLabel.toStdString());
    CHECK(window->design().boundaries() == boundaries);
}

TEST_CASE("a broken project file is reported with its line and what was expected", "[app][files]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    const QString file = scratchFile("broken-project", "broken.bunraku.json");
    {
        std::ofstream out(file.toStdString());
        out << "{\n  \"format\": \"bunraku-project\",\n  \"version\": 1,\n  oops\n}\n";
    }
    REQUIRE_FALSE(window->files().projects().openProject(file));
    REQUIRE(window->files().lastError().contains(QStringLiteral("broken.bunraku.json:4")));
    {
        std::ofstream out(file.toStdString());
        out << "{\"format\": \"something-else\"}";
    }
    REQUIRE_FALSE(window->files().projects().openProject(file));
    REQUIRE(window->files().lastError().contains(QStringLiteral("bunraku-project")));
    REQUIRE(window->document().corpusSource() == QStringLiteral("demo")); // unchanged
}

TEST_CASE("autosave writes the unsaved work and a saved project removes it", "[app][files]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    auto& files = window->files();
    QFile::remove(files.projects().autosavePath());
    REQUIRE_FALSE(files.projects().autosave()); // nothing to save
    app::changeStageParameters(window->document(), [](app::AnalysisParameters& p) { p.normalise.searchBand = 12; }, QStringLiteral("band"));
    REQUIRE(files.projects().autosave());
    const auto recovered = app::readProject(files.projects().autosavePath());
    REQUIRE(recovered.ok());
    REQUIRE(recovered->parameters.normalise.searchBand == 12);
    REQUIRE(files.projects().saveProject(scratchFile("autosave-project", "p.bunraku.json")));
    REQUIRE_FALSE(QFile::exists(files.projects().autosavePath()));
}

TEST_CASE("opening a missing corpus folder is an error message, not a crash", "[app][files]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    REQUIRE_FALSE(window->files().corpora().openCorpusFolder(QStringLiteral("/nonexistent/corpus")));
    REQUIRE(window->files().lastError().contains(QStringLiteral("/nonexistent/corpus")));
    REQUIRE(window->document().corpus().takes.size() == 30);
}

TEST_CASE("projects with out-of-range parameters, take ids, times or view values are refused and change nothing", "[app][files]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    const QString file = scratchFile("invalid-project", "invalid.bunraku.json");
    const std::string head = R"({"format": "bunraku-project", "version": 2, "corpus": "demo", )";
    const std::vector<std::pair<std::string, std::string>> cases{
        {R"("parameters": {"normalise": {"maxScale": 2e9}})", "parameters.normalise.maxScale"},
        {R"("parameters": {"normalise": {"maxScale": 100000}})", "parameters.normalise.maxScale"},
        {R"("parameters": {"normalise": {"tau": -4}})", "parameters.normalise.tau"},
        {R"("parameters": {"design": {"emotionWeight": "heavy"}})", "parameters.design.emotionWeight"},
        {R"("parameters": {"design": {"warp": [[0, 0], [1e300, 5]]}})", "parameters.design.warp[1]"},
        {R"("takeA": "corpus/../../etc")", "takeA"},
        {R"("time_s": -3)", "time_s"},
        {R"("view": {"graphLayout": 99})", "graphLayout"},
        {R"("view": {"speed": 1e308})", "speed"},
    };
    for (const auto& [body, named] : cases) {
        INFO(body);
        {
            std::ofstream out(file.toStdString());
            out << head << body << "}\n";
        }
        changeStageParameters(window->document(), [](app::AnalysisParameters& p) { p.normalise.tau = 5; }, QStringLiteral("tau"));
        REQUIRE_FALSE(window->files().projects().openProject(file));
        CHECK(window->files().lastError().contains(QStringLiteral("invalid.bunraku.json")));
        CHECK(window->files().lastError().contains(QString::fromStdString(named)));
        CHECK(window->document().parameters().normalise.tau == 5); // nothing changed
    }
    // Version 1's flat keys are still read, into the typed parameters.
    {
        std::ofstream out(file.toStdString());
        out << R"({"format": "bunraku-project", "version": 1, "corpus": "demo", "parameters": {"normalise.tau": 6, )"
            << R"("emotion.weight": 1.5, "design.boundaries": [0], "design.gains": {"1/2": [0.5, 2.0]}}})";
    }
    REQUIRE(window->files().projects().openProject(file));
    const auto& p = window->document().parameters();
    CHECK(p.normalise.tau == 6);
    CHECK(p.design.emotionWeight == 1.5);
    CHECK(p.design.boundaries == analysis::pipeline::PhraseBoundaries{false, {}}); // "no inner boundary"
    REQUIRE(p.design.gain(1, 2));
    CHECK(p.design.gain(1, 2)->g1 == 2.0);
    CHECK(p.decompose.method == analysis::pipeline::DecomposeMethod::LeastSquares); // as version 1 decomposed
}

TEST_CASE("a take id is written as its text and read back by the project file as the same id", "[app][files][ids]")
{
    using app::TakeId;
    // The values: kind, index and name, and ids of different kinds are different ids.
    CHECK(TakeId::corpus(3).kind() == TakeId::Kind::Corpus);
    CHECK(TakeId::corpus(3).index() == 3);
    CHECK(TakeId::imported(2).kind() == TakeId::Kind::Imported);
    CHECK(TakeId::live(QStringLiteral("designed")).name() == QStringLiteral("designed"));
    CHECK(TakeId().isEmpty());
    CHECK(TakeId::corpus(1) != TakeId::imported(1));
    CHECK(TakeId::live(QStringLiteral("axis")) != TakeId::live(QStringLiteral("kimono")));
    CHECK(TakeId::corpus(0) != TakeId());

    // Each id is written as its text and read back as the same id.
    const QString file = scratchFile("take-ids", "ids.bunraku.json");
    const std::vector<std::pair<TakeId, std::string>> ids{
        {TakeId::corpus(0), "corpus/0"},           {TakeId::corpus(123456789), "corpus/123456789"},
        {TakeId::imported(1), "imported/1"},       {TakeId::imported(42), "imported/42"},
        {TakeId::live(QStringLiteral("designed")), "live/designed"},
        {TakeId::live(QStringLiteral("kimono")), "live/kimono"},
        {TakeId(), ""},
    };
    for (const auto& [id, text] : ids) {
        INFO(text);
        app::ProjectState state;
        state.corpus = QStringLiteral("demo");
        state.takeA = id;
        state.takeB = TakeId::live(QStringLiteral("weighted"));
        REQUIRE(app::writeProject(state, file).ok());
        QFile written(file);
        REQUIRE(written.open(QIODevice::ReadOnly));
        const auto root = nlohmann::json::parse(written.readAll().toStdString());
        CHECK(root["takeA"] == text);
        CHECK(root["takeB"] == "live/weighted");
        const auto read = app::readProject(file);
        REQUIRE(read.ok());
        CHECK(read->takeA == id);
        CHECK(read->takeB == TakeId::live(QStringLiteral("weighted")));
    }

    // Text that names no take is refused with the key it was found under.
    for (const std::string bad : {R"("corpus/x")", R"("corpus/")", R"("corpus/1/2")", R"("live/Designed")", R"("live/")",
                                  R"("imported/1234567890")", R"("Corpus/1")", R"(" corpus/1")", "5", "[]"}) {
        INFO(bad);
        const std::string text = R"({"format": "bunraku-project", "version": 2, "corpus": "demo", "takeB": )" + bad + "}";
        const auto read = app::parseProject(QByteArray::fromStdString(text), QStringLiteral("ids.bunraku.json"));
        REQUIRE_FALSE(read.ok());
        CHECK(read.error().message.find("takeB") != std::string::npos);
        CHECK(read.error().message.find("a take id (corpus/N, imported/N or live/name), got " + bad) != std::string::npos);
    }
    // On a line of its own, the error names that line.
    const auto read = app::parseProject("{\"format\": \"bunraku-project\", \"version\": 2,\n\"corpus\": \"demo\",\n\n  \"takeA\" : \"live/Designed\"\n}",
                                        QStringLiteral("ids.bunraku.json"));
    REQUIRE_FALSE(read.ok());
    CHECK(read.error().message ==
          "ids.bunraku.json:4: expected \"takeA\": a take id (corpus/N, imported/N or live/name), got \"live/Designed\"");
}

TEST_CASE("a project whose imported takes cannot be read opens saying which takes and why", "[app][files]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    const auto dir = test::scratchDir("project-unreadable-takes");
    const std::string fifo = (dir / "fifo.csv").string();
    std::filesystem::remove(fifo);
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
    {
        std::ofstream out(dir / "damaged.bvh");
        out << "HIERARCHY\nROOT Hips\n{\n  OFFSET 0 0 zero\n}\n";
    }
    const QString file = QString::fromStdString((dir / "p.bunraku.json").string());
    {
        std::ofstream out(file.toStdString());
        out << R"({"format": "bunraku-project", "version": 2, "corpus": "demo", "imported": [)"
            << R"({"path": "/dev/zero", "label": "zero"}, {"path": ")" << fifo << R"(", "label": "fifo"}, )"
            << R"({"path": ")" << (dir / "missing.bvh").string() << R"(", "label": "missing"}, )"
            << R"({"path": ")" << (dir / "damaged.bvh").string() << R"(", "label": "damaged"}]})";
    }
    QStringList messages;
    QObject::connect(&window->files(), &app::FileController::statusMessage, [&](const QString& m) { messages.append(m); });
    REQUIRE(window->files().projects().openProject(file)); // the corpus and the rest of the project open
    REQUIRE_FALSE(messages.isEmpty());
    const QString last = messages.back();
    INFO(last.toStdString());
    CHECK(last.contains(QStringLiteral("p.bunraku.json")));
    CHECK(last.contains(QStringLiteral("without 4")));
    for (const char* named : {"'zero'", "/dev/zero", "'fifo'", "fifo.csv", "'missing'", "missing.bvh", "'damaged'", "damaged.bvh:4"})
        CHECK(last.contains(QString::fromUtf8(named)));
    CHECK(importedTakes(window->document()).empty());
    std::filesystem::remove(fifo);
}

TEST_CASE("a project names its imported takes by their place in it, and says when a take it shows is not there",
          "[app][files][ids]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    auto& document = window->document();
    const auto dir = test::scratchDir("project-imported-places");
    for (int k = 1; k <= 3; ++k) {
        std::ofstream out(dir / ("t" + std::to_string(k) + ".csv"));
        out << "time_s,a.x\n0," << k << "\n0.2," << 2 * k << "\n0.4," << 3 * k << "\n";
    }
    const auto path = [&](const char* name) { return QString::fromStdString((dir / name).string()); };
    const auto writeProject = [&](const QString& file, const std::string& fields) {
        std::ofstream out(file.toStdString());
        out << R"({"format": "bunraku-project", "version": 2, "corpus": "demo", )" << fields << "}";
    };
    const auto labelOf = [&](TakeSlot slot) { return document.takeLabel(document.selectedId(slot)).toStdString(); };

    SECTION("an imported take that cannot be read shifts no other") {
        const QString file = path("unread-first.bunraku.json");
        writeProject(file, R"("imported": [{"path": ")" + (dir / "gone.csv").string() + R"(", "label": "gone"}, {"path": ")" +
                               (dir / "t2.csv").string() + R"(", "label": "two"}], "takeA": "imported/2", "takeB": "imported/1")");
        REQUIRE(window->files().projects().openProject(file));
        CHECK(labelOf(TakeSlot::A) == "two");
        CHECK(document.selectedId(TakeSlot::B).isEmpty());
        INFO(window->files().lastError().toStdString());
        CHECK(window->files().lastError().contains(QStringLiteral("gone.csv")));
        CHECK(window->files().lastError().contains(QStringLiteral("its take B, imported/1, is not in it (B shows no take)")));
    }
    SECTION("a take A the corpus does not have is said, with the take shown instead") {
        const QString file = path("no-such-take.bunraku.json");
        writeProject(file, R"("takeA": "corpus/999")");
        REQUIRE(window->files().projects().openProject(file));
        CHECK(document.selectedId(TakeSlot::A).isCorpus()); // the take the corpus opens with
        const std::string expected = "its take A, corpus/999, is not in it (A shows " + labelOf(TakeSlot::A) + ")";
        CHECK(window->files().lastError().toStdString().find(expected) != std::string::npos);
    }
    SECTION("saved after a take was removed, the takes shown reopen as they were") {
        for (const char* name : {"t1.csv", "t2.csv", "t3.csv"}) REQUIRE(window->files().imports().importTakeFile(path(name)));
        auto imported = importedTakes(document);
        REQUIRE(imported.size() == 3);
        document.undoStack()->push(new app::RemoveImportedTake(&document, imported[0].id));
        imported = importedTakes(document);
        REQUIRE(imported.size() == 2);
        REQUIRE(imported[0].id != app::TakeId::imported(1)); // the session's serials no longer start at 1
        document.selectTake(TakeSlot::A, imported[1].id);
        document.selectTake(TakeSlot::B, imported[0].id);
        const std::string shownA = labelOf(TakeSlot::A), shownB = labelOf(TakeSlot::B);
        REQUIRE(shownA != shownB);
        const QString file = path("after-removal.bunraku.json");
        REQUIRE(window->files().projects().saveProject(file));
        QFile saved(file);
        REQUIRE(saved.open(QIODevice::ReadOnly));
        const auto root = nlohmann::json::parse(saved.readAll().toStdString());
        CHECK(root["takeA"] == "imported/2");
        CHECK(root["takeB"] == "imported/1");

        auto reopened = test::demoWindow();
        REQUIRE(reopened);
        REQUIRE(reopened->files().projects().openProject(file));
        auto& again = reopened->document();
        CHECK(again.takeLabel(again.selectedId(TakeSlot::A)).toStdString() == shownA);
        CHECK(again.takeLabel(again.selectedId(TakeSlot::B)).toStdString() == shownB);
        CHECK(again.selectedTake(TakeSlot::A)->values == document.selectedTake(TakeSlot::A)->values);
    }
}

TEST_CASE("a project of 2000 imported takes adds them to the document in one change", "[app][files]")
{
    // Issue 30: a project of 10,000 imported takes took 300 s to open - each take added was one
    // document change and one rebuild of the corpus browser (n^2). Now they come in one change.
    auto window = test::demoWindow();
    REQUIRE(window);
    const auto dir = test::scratchDir("project-many-takes");
    const std::string take = (dir / "t.csv").string();
    {
        std::ofstream out(take);
        out << "time_s,a.x\n0,1\n0.2,2\n0.4,3\n";
    }
    const QString file = QString::fromStdString((dir / "p.bunraku.json").string());
    {
        std::ofstream out(file.toStdString());
        out << R"({"format": "bunraku-project", "version": 2, "corpus": "demo", "imported": [)";
        for (int i = 0; i < 2000; ++i) out << (i ? ", " : "") << R"({"path": ")" << take << R"(", "label": "t)" << i << R"("})";
        out << "]}";
    }
    int changes = 0;
    QObject::connect(&window->document(), &app::Document::derivedTakesChanged, [&] { ++changes; });
    REQUIRE(window->files().projects().openProject(file));
    const auto imported = importedTakes(window->document());
    REQUIRE(imported.size() == 2000);
    CHECK(imported.front().label == QStringLiteral("t0"));
    CHECK(imported.back().label == QStringLiteral("t1999"));
    CHECK(imported.front().id != imported.back().id);
    CHECK(changes <= 3); // the corpus, the imported takes, the live takes: not one per take
    auto* browser = window->findChild<widgets::CorpusBrowser*>();
    REQUIRE(browser);
}

TEST_CASE("a project holding a number beyond a double is refused naming the file and line", "[app][files]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    const QString file = scratchFile("project-1e400", "huge.bunraku.json");
    {
        std::ofstream out(file.toStdString());
        out << "{\"format\": \"bunraku-project\", \"version\": 2, \"corpus\": \"demo\",\n"
               "\"parameters\": {\"normalise\": {\"tau\": 1e400}}}\n";
    }
    REQUIRE_FALSE(window->files().projects().openProject(file));
    INFO(window->files().lastError().toStdString());
    CHECK(window->files().lastError().contains(QStringLiteral("huge.bunraku.json:2")));
    CHECK(window->files().lastError().contains(QStringLiteral("1e400")));
}

TEST_CASE("projects keep their stored path: version 1 without one meant greedy, version 2 always stores it", "[app][files]")
{
    using analysis::PathMethod;
    const auto parsed = [](const std::string& text) {
        auto state = app::parseProject(QByteArray::fromStdString(text), QStringLiteral("old.bunraku.json"));
        REQUIRE(state.ok());
        return state->parameters.normalise.path;
    };
    // Version 1 stored only what differed from the defaults of its day (the greedy scan).
    CHECK(parsed(R"({"format": "bunraku-project", "version": 1, "corpus": "demo", "parameters": {"normalise.tau": 6}})") == PathMethod::Greedy);
    CHECK(parsed(R"({"format": "bunraku-project", "version": 1, "corpus": "demo"})") == PathMethod::Greedy);
    CHECK(parsed(R"({"format": "bunraku-project", "version": 1, "corpus": "demo", "parameters": {"normalise.path": "optimal"}})") ==
          PathMethod::Optimal);
    // Version 2 writes every parameter: a saved project keeps either choice ...
    for (const PathMethod path : {PathMethod::Greedy, PathMethod::Optimal}) {
        app::ProjectState state;
        state.corpus = QStringLiteral("demo");
        state.parameters.normalise.path = path;
        const QString file = scratchFile("stored-path", "p.bunraku.json");
        REQUIRE(app::writeProject(state, file));
        QFile saved(file);
        REQUIRE(saved.open(QIODevice::ReadOnly));
        const QByteArray text = saved.readAll();
        const auto stored = nlohmann::json::parse(text.toStdString())["parameters"]["normalise"];
        REQUIRE(stored.contains("path"));
        CHECK(stored["path"] == analysis::pipeline::pathName(path));
        CHECK(parsed(text.toStdString()) == path);
    }
    // ... and one written by hand without a path gets today's default, the optimal path.
    CHECK(parsed(R"({"format": "bunraku-project", "version": 2, "corpus": "demo", "parameters": {"normalise": {"tau": 6}}})") ==
          PathMethod::Optimal);
    CHECK(analysis::pipeline::NormaliseParameters{}.path == PathMethod::Optimal);
}

TEST_CASE("a project's view state is written and read back typed, value for value", "[app][files][project]")
{
    app::ProjectState state;
    state.corpus = QStringLiteral("demo");
    app::ViewState& view = state.view;
    view.graphLayout = 2;
    view.twoTakeMode = 1;
    view.valueScale = 0;
    view.angleDisplay = 1;
    view.thesisTicks = true;
    view.part = QStringLiteral("hand");
    view.dof = QStringLiteral("yaw");
    view.camera = app::CameraState{30.0, -12.5, 420.0, {1.5, -2.0, 90.25}, 50.0};
    view.figureA = 3;
    view.cloth = true;
    analysis::ClothParameters cloth;
    cloth.damping = 2.25;
    view.clothParameters = cloth;
    view.weightEmotion = QStringLiteral("hostile");
    view.speed = 0.5;
    view.windowState = QByteArray("\x00\x01layout\xff", 9);
    view.leftWidth = 321;
    const QString file = scratchFile("view-state", "p.bunraku.json");
    REQUIRE(app::writeProject(state, file));
    const auto read = app::readProject(file);
    REQUIRE(read);
    const app::ViewState& back = read->view;
    CHECK(back.graphLayout == 2);
    CHECK(back.twoTakeMode == 1);
    CHECK(back.valueScale == 0);
    CHECK(back.angleDisplay == 1);
    CHECK(back.thesisTicks == true);
    CHECK(back.part == QStringLiteral("hand"));
    CHECK(back.dof == QStringLiteral("yaw"));
    REQUIRE(back.camera);
    CHECK(back.camera->angle == 30.0);
    CHECK(back.camera->elevation == -12.5);
    CHECK(back.camera->distance == 420.0);
    CHECK(back.camera->target == std::array<double, 3>{1.5, -2.0, 90.25});
    CHECK(back.camera->fov == 50.0);
    CHECK(back.figureA == 3);
    CHECK_FALSE(back.figureB); // not stored: the view keeps its own
    CHECK(back.cloth == true);
    REQUIRE(back.clothParameters);
    CHECK(back.clothParameters->damping == 2.25);
    CHECK(back.clothParameters->drag == analysis::ClothParameters{}.drag);
    CHECK(back.weightEmotion == QStringLiteral("hostile"));
    CHECK(back.speed == 0.5);
    CHECK(back.windowState == view.windowState);
    CHECK(back.leftWidth == 321);
}

TEST_CASE("a project keeps what the 3D view draws and Follow, and refuses a show object it does not know", "[app][files][project]")
{
    const QString file = scratchFile("view-boxes", "boxes.bunraku.json");
    // Each box the other way round from its default, so a box not restored shows.
    std::map<QString, bool> saved;
    {
        auto window = test::demoWindow();
        REQUIRE(window);
        for (const char* name : {"showPuppet", "showAxis", "showOrbits", "showGrid", "showShadows", "showPartner", "followFigures"}) {
            auto* box = window->findChild<QCheckBox*>(name);
            REQUIRE(box);
            box->setChecked(!box->isChecked());
            saved[name] = box->isChecked();
        }
        REQUIRE(window->files().projects().saveProject(file));
    }
    auto window = test::demoWindow();
    REQUIRE(window);
    for (const auto& [name, checked] : saved) REQUIRE(window->findChild<QCheckBox*>(name)->isChecked() != checked);
    REQUIRE(window->files().projects().openProject(file));
    for (const auto& [name, checked] : saved) {
        INFO(name.toStdString());
        CHECK(window->findChild<QCheckBox*>(name)->isChecked() == checked);
    }
    // The file holds them by name; a value that is not true or false, or an unknown name, is refused naming it.
    QFile text(file);
    REQUIRE(text.open(QIODevice::ReadOnly));
    auto project = nlohmann::json::parse(text.readAll().toStdString());
    CHECK(project["view"]["show"]["orbits"] == saved["showOrbits"]);
    CHECK(project["view"]["show"]["follow"] == saved["followFigures"]);
    for (const auto& [key, value, expected] : std::vector<std::tuple<std::string, nlohmann::json, std::string>>{
             {"orbits", 1, "\"view\".\"show\".\"orbits\": true or false"}, {"sleeves", true, "unknown object \"sleeves\""}}) {
        auto changed = project;
        changed["view"]["show"][key] = value;
        const QString bad = scratchFile("view-boxes", "bad.bunraku.json");
        QFile out(bad);
        REQUIRE(out.open(QIODevice::WriteOnly | QIODevice::Truncate));
        out.write(QByteArray::fromStdString(changed.dump()));
        out.close();
        const auto read = app::readProject(bad);
        REQUIRE_FALSE(read);
        INFO(read.error().message);
        CHECK(read.error().message.find(expected) != std::string::npos);
    }
}

TEST_CASE("a corpus opened again while it is open is analysed again: its weighted and designed takes come back",
          "[app][files][corpus]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    REQUIRE(test::waitUntilIdle(*window));
    const auto derivedIds = [&] {
        QStringList ids;
        for (const auto& derived : window->document().derivedTakes()) ids << derived.id.toString();
        ids.sort(); // published in the order the stages finish
        return ids.join(QStringLiteral(", ")).toStdString();
    };
    REQUIRE(window->analysis().decomposed());
    const std::string before = derivedIds();
    REQUIRE(before.find(app::TakeId::live(QStringLiteral("weighted")).toString().toStdString()) != std::string::npos);
    // The demo corpus again, then a corpus folder opened twice.
    REQUIRE(window->files().corpora().openDemoCorpus());
    REQUIRE(test::waitUntilIdle(*window));
    CHECK(window->analysis().decomposed());
    CHECK(derivedIds() == before);
    const auto folder = test::scratchDir("corpus-opened-again");
    REQUIRE(analysis::io::writeCorpus(window->document().corpus(), folder / "demo"));
    const QString path = QString::fromStdString((folder / "demo").string());
    for (int pass = 0; pass < 2; ++pass) {
        INFO("opened " << pass + 1 << " time(s)");
        REQUIRE(window->files().corpora().openCorpusFolder(path));
        REQUIRE(test::waitUntilIdle(*window));
        CHECK(window->analysis().decomposed());
        CHECK(derivedIds() == before);
    }
}
