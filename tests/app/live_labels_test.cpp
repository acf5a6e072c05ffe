// Labels and panel texts say what they were computed from: a live take's name in the corpus tree
// names its take and parameters (and changes when they change), the emotion panel agrees with the
// document after another corpus is opened, a fixed stage's error leaves the status bar, and a
// neutral take is weighted against the emotion the person picks.
#include "tests/app/app_test_support.h"

#include "app/analysis_controller.h"
#include "app/design_controller.h"
#include "app/emotion_panel.h"
#include "app/normalise_panel.h"

#include "widgets/corpus_browser.h"

#include "analysis/io/corpus_io.h"
#include "analysis/pipeline/stages.h"
#include "analysis/synth/demo_corpus.h"
#include "tests/analysis/io/io_test_support.h"
#include "tests/support/bvh_fixtures.h"

#include "analysis/core/skeleton_take.h"

#include <catch2/catch.hpp>

#include <QComboBox>
#include <QLabel>
#include <QSlider>
#include <QStatusBar>

using namespace bunraku;
using app::TakeSlot;

namespace {

bool idle(app::MainWindow& window)
{
    return QTest::qWaitFor([&] { return !window.analysis().scheduler().busy() && window.analysis().axes(); }, 120000);
}

/// The id of corpus take function/emotion/index.
app::TakeId takeId(const app::Document& document, const std::string& function, const std::string& emotion, int index)
{
    const auto& takes = document.corpus().takes;
    for (std::size_t i = 0; i < takes.size(); ++i)
        if (takes[i].labels.function == function && takes[i].labels.emotion == emotion && takes[i].labels.takeIndex == index)
            return app::TakeId::corpus(i);
    return {};
}

QString statusText(app::MainWindow& window)
{
    QStringList texts;
    for (auto* label : window.statusBar()->findChildren<QLabel*>()) texts << label->text();
    return texts.join(QLatin1Char('\n'));
}

} // namespace

TEST_CASE("the normalised take's label names its take, reference and parameters, and follows them", "[app][labels]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    auto& document = window->document();
    const app::TakeId two = takeId(document, "greeting", "none", 2);
    const app::TakeId one = takeId(document, "greeting", "none", 1);
    document.selectTake(TakeSlot::A, two);
    REQUIRE(idle(*window));
    const auto labelled = [&] { return window->browser()->entryText(QStringLiteral("live/normalised")); };
    CHECK(labelled().startsWith(QStringLiteral("greeting/none/2 normalised to ")));
    CHECK(labelled().contains(QStringLiteral("tau 4, T_cmp 20")));

    // Take 1 shown: the entry holds take 1's result and says so (it said take 2 before).
    document.selectTake(TakeSlot::A, one);
    REQUIRE(QTest::qWaitFor([&] { return labelled().startsWith(QStringLiteral("greeting/none/1 normalised")); }, 10000));
    const auto cell = window->analysis().normalised()->cell("greeting", "none");
    REQUIRE(cell != nullptr);
    const auto position = std::find(cell->takeIndices.begin(), cell->takeIndices.end(), 1) - cell->takeIndices.begin();
    // shown as its body (the per-channel result beside it)
    CHECK(document.take(app::TakeId::live(QStringLiteral("normalised")))->values ==
          analysis::bodyTake(cell->normalisations[std::size_t(position)].normalised).values);
    CHECK(document.perChannelGhostOf(app::TakeId::live(QStringLiteral("normalised")))->values == cell->normalisations[std::size_t(position)].normalised.values);

    // Another tau: once recomputed, the label says tau 5 (and the window title too, with it shown).
    document.selectTake(TakeSlot::A, app::TakeId::live(QStringLiteral("normalised")));
    window->normalisePanel()->tauSpin()->setValue(5);
    REQUIRE(QTest::qWaitFor([&] { return labelled().contains(QStringLiteral("tau 5, T_cmp 20")); }, 120000));
    CHECK(window->windowTitle().contains(QStringLiteral("tau 5")));
    CHECK(window->normalisePanel()->summaryText().contains(QStringLiteral("tau 5, T_cmp 20")));
}

TEST_CASE("the normalised take follows the parameters while another derived take is shown as A", "[app][labels]")
{
    // A GUI walk found a project reopened with tau 6 and a derived take as A listing a normalised
    // take "... (tau 4, ...)": computed with the defaults while it opened, then kept.
    auto window = test::demoWindow();
    REQUIRE(window);
    auto& document = window->document();
    document.selectTake(TakeSlot::A, takeId(document, "greeting", "none", 1));
    REQUIRE(idle(*window));
    const auto normalised = app::TakeId::live(QStringLiteral("normalised"));
    const auto labelled = [&] { return window->browser()->entryText(normalised.toString()); };
    REQUIRE(labelled().contains(QStringLiteral("tau 4, T_cmp 20")));
    REQUIRE(QTest::qWaitFor([&] { return bool(document.take(app::TakeId::live(QStringLiteral("weighted")))); }, 120000));
    document.selectTake(TakeSlot::A, app::TakeId::live(QStringLiteral("weighted")));

    window->normalisePanel()->tauSpin()->setValue(6);
    REQUIRE(QTest::qWaitFor([&] { return labelled().contains(QStringLiteral("tau 6, T_cmp 20")); }, 120000));
    CHECK(labelled().startsWith(QStringLiteral("greeting/none/1 normalised")));
    CHECK(document.selectedId(TakeSlot::A) == "live/weighted"); // A stays
    const auto cell = window->analysis().normalised()->cell("greeting", "none");
    REQUIRE(cell != nullptr);
    const auto position = std::size_t(std::find(cell->takeIndices.begin(), cell->takeIndices.end(), 1) - cell->takeIndices.begin());
    REQUIRE(position < cell->takeIndices.size());
    CHECK(document.perChannelGhostOf(normalised)->values == cell->normalisations[position].normalised.values);
}

TEST_CASE("the weighted take's label follows the emotion weight and names the method", "[app][labels][emotion]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    auto& document = window->document();
    document.selectTake(TakeSlot::A, takeId(document, "greeting", "friendly", 1));
    auto* panel = window->emotionPanel();
    REQUIRE(QTest::qWaitFor([&] { return panel->ready() && panel->weightedTake(); }, 120000));
    const auto labelled = [&] { return window->browser()->entryText(QStringLiteral("live/weighted")); };
    CHECK(labelled().startsWith(QStringLiteral("greeting/friendly a=1.00 (KM2O, M = ")));
    // A drag to 2.80: the tree says 2.80 at every step, and the panel's text too.
    auto* slider = panel->weightSlider();
    emit slider->sliderPressed();
    for (int position = 110; position <= 280; position += 10) {
        slider->setValue(position);
        CHECK(labelled().startsWith(QStringLiteral("greeting/friendly a=%1 ").arg(position / 100.0, 0, 'f', 2)));
    }
    emit slider->sliderReleased();
    CHECK(panel->statusText().contains(QStringLiteral("a = 2.80")));
    CHECK(document.undoStack()->undoText() == QStringLiteral("Set emotion weight a to 2.80"));
}

TEST_CASE("after another corpus opens, the emotion panel's controls and text agree with its parameters", "[app][labels][emotion]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    auto& document = window->document();
    auto* panel = window->emotionPanel();
    REQUIRE(idle(*window));
    panel->orderBox()->setValue(2);
    panel->weightSlider()->setValue(280);
    panel->methodBox()->setCurrentIndex(panel->methodBox()->findData(QStringLiteral("least-squares")));
    REQUIRE(QTest::qWaitFor([&] { return panel->statusText().contains(QStringLiteral("least squares")) && idle(*window); }, 120000));

    // The demo corpus written to a folder and opened as another corpus.
    const auto folder = test::scratchDir("labels-other-corpus");
    REQUIRE(analysis::io::writeCorpus(analysis::synth::generateDemoCorpus().corpus, folder).ok());
    REQUIRE(window->files().corpora().openCorpusFolder(QString::fromStdString(folder.string())));
    // Its parameters are the defaults, and every control shows them at once...
    CHECK(document.parameters().design.emotionWeight == 1.0);
    CHECK(panel->weightSlider()->value() == 100);
    CHECK(panel->orderBox()->value() == 0);
    CHECK(panel->methodBox()->currentData().toString() == QStringLiteral("km2o"));
    // ...and the text claims no result until the new corpus is decomposed, then names it.
    CHECK_FALSE(panel->statusText().contains(QStringLiteral("a = 2.80")));
    CHECK_FALSE(panel->statusText().contains(QStringLiteral("least squares")));
    // (Every stage of the new corpus runs: a while on a busy machine.)
    REQUIRE(QTest::qWaitFor([&] { return panel->statusText().contains(QStringLiteral("a = 1.00")); }, 600000));
    CHECK(panel->statusText().contains(QStringLiteral("KM2O")));
    // A nudge of the slider moves a by one step from 1.00, not from where it was before.
    panel->weightSlider()->setFocus();
    QTest::keyClick(panel->weightSlider(), Qt::Key_Right);
    CHECK(document.parameters().design.emotionWeight == Approx(1.01));
}

TEST_CASE("a stage's error leaves the status bar once the parameter is fixed", "[app][labels][status]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    REQUIRE(idle(*window));
    auto* panel = window->emotionPanel();
    // Above M_max for the demo's 102 frames: the dock cannot set it (its limit is M_max), a
    // project can.
    CHECK(panel->orderBox()->maximum() < 40);
    app::AnalysisParameters parameters = window->document().parameters();
    parameters.decompose.correlationLength = 40;
    window->document().restoreParameters(parameters);
    REQUIRE(QTest::qWaitFor([&] { return statusText(*window).contains(QStringLiteral("Decomposition failed")); }, 120000));
    CHECK(panel->statusText().contains(QStringLiteral("cannot be decomposed")));
    panel->orderBox()->setValue(2);
    REQUIRE(QTest::qWaitFor([&] { return panel->decomposedOrder() == 2 && idle(*window); }, 120000));
    CHECK_FALSE(statusText(*window).contains(QStringLiteral("failed")));
    CHECK(panel->statusText().contains(QStringLiteral("M = 2")));
}

TEST_CASE("a neutral take is weighted against the emotion picked, an emotional one against its own", "[app][labels][emotion]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    auto& document = window->document();
    auto* panel = window->emotionPanel();
    document.selectTake(TakeSlot::A, takeId(document, "greeting", "none", 3));
    REQUIRE(idle(*window));
    REQUIRE(QTest::qWaitFor([&] { return panel->weightedTake() != nullptr; }, 10000));
    auto* picker = panel->emotionBox();
    CHECK(picker->isEnabled());
    REQUIRE(picker->count() == 2);
    CHECK(picker->currentText() == QStringLiteral("friendly"));

    // Picked with the keyboard, as a person would.
    picker->setFocus();
    QTest::keyClick(picker, Qt::Key_Down);
    CHECK(picker->currentText() == QStringLiteral("hostile"));
    CHECK(window->analysis().weightedCell() == std::pair<std::string, std::string>("greeting", "hostile"));
    const auto expected = analysis::pipeline::weightedTake(*window->analysis().decomposed(), "greeting", "hostile", 1.0);
    REQUIRE(expected.ok());
    CHECK(panel->weightedTake()->values == analysis::bodyTake(expected.value()).values); // shown as its body
    CHECK(window->browser()->entryText(QStringLiteral("live/weighted")).startsWith(QStringLiteral("greeting/hostile a=1.00")));
    CHECK(panel->statusText().contains(QStringLiteral("greeting/hostile")));

    // An emotional take A: its own emotion, not to be picked.
    document.selectTake(TakeSlot::A, takeId(document, "greeting", "friendly", 2));
    CHECK_FALSE(picker->isEnabled());
    CHECK(picker->currentText() == QStringLiteral("friendly"));
    CHECK(window->analysis().weightedCell().second == "friendly");
    // Back on a neutral take: the pick is remembered.
    document.selectTake(TakeSlot::A, takeId(document, "greeting", "none", 1));
    CHECK(picker->currentText() == QStringLiteral("hostile"));
}

TEST_CASE("the designed take's label names its warp, gains and phrases, and the axis take names and counts the take it was computed from",
          "[app][labels][design]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    auto& document = window->document();
    auto& design = window->design();
    document.selectTake(TakeSlot::A, takeId(document, "greeting", "none", 2));
    REQUIRE(idle(*window));
    REQUIRE(QTest::qWaitFor([&] { return bool(document.take(app::TakeId::live(QStringLiteral("designed")))); }, 60000));
    const auto listed = [&](const app::TakeId& id) { return window->browser()->entryText(id.toString()); };
    const app::TakeId designed = app::TakeId::live(QStringLiteral("designed")), axis = app::TakeId::live(QStringLiteral("axis"));
    CHECK(listed(designed).startsWith(QStringLiteral("designed from greeting functional (identity warp; no gains; ")));
    CHECK(listed(designed).contains(QStringLiteral("suggested phrase")));

    // A warp point moved, then a gain set: the label says so at once.
    analysis::WarpCurve curve = design.warpCurve();
    REQUIRE(curve.points.size() >= 4);
    curve.points[2].source += 0.5 * (curve.points[3].source - curve.points[2].source);
    design.editWarp(curve);
    CHECK(listed(designed).contains(QStringLiteral("warp: 1 of %1 points moved").arg(curve.points.size())));
    design.editGain(0, 0, 1.5, 1.2);
    CHECK(listed(designed).contains(QStringLiteral("1 phrase gain set")));
    document.undoStack()->undo();
    CHECK(listed(designed).contains(QStringLiteral("no gains")));
    design.editGain(0, 0, 1.5, 1.2);
    CHECK(listed(designed) == document.takeLabel(designed));

    // The designed take as A: its axis is named as it is listed (not "greeting/none/0") and
    // counts its frames.
    const auto axisNames = [&](const app::TakeId& id) {
        return listed(axis) == QStringLiteral("motion axis of ") + document.takeLabel(id) &&
               window->browser()->entryFrames(axis.toString()) == int(document.take(id)->frameCount());
    };
    document.selectTake(TakeSlot::A, designed);
    REQUIRE(QTest::qWaitFor([&] { return axisNames(designed); }, 60000));
    CHECK_FALSE(listed(axis).contains(QStringLiteral("/0")));
    CHECK(int(document.take(axis)->frameCount()) == int(document.take(designed)->frameCount()));
    // Exported as glTF, the recipe it is listed with is in the file (its description).
    const auto dir = test::scratchDir("designed-labels");
    REQUIRE(window->exports().exportTake(TakeSlot::A, QString::fromStdString((dir / "designed.glb").string())));
    const std::string glb = test::fileBytes(dir / "designed.glb");
    CHECK(glb.find("\"" + document.takeLabel(designed).toStdString() + "\"") != std::string::npos);
    CHECK(glb.find("greeting/none/0") == std::string::npos);

    // Corpus takes of other lengths in turn: the axis entry's label and frame count follow.
    for (const auto& [emotion, index] : std::vector<std::pair<std::string, int>>{{"hostile", 1}, {"none", 1}, {"friendly", 2}}) {
        const app::TakeId id = takeId(document, "greeting", emotion, index);
        REQUIRE(!id.isEmpty());
        document.selectTake(TakeSlot::A, id);
        INFO(document.takeLabel(id).toStdString() << " of " << document.take(id)->frameCount() << " frames");
        REQUIRE(QTest::qWaitFor([&] { return axisNames(id); }, 60000));
        CHECK(window->browser()->entryFrames(axis.toString()) == int(document.take(axis)->frameCount()));
    }

    // An imported file: named as it is listed (the file's name), not by its full path.
    const auto families = test::bvhFamilies();
    const auto file = test::writeText(dir / "imported-wave.bvh", test::fixtureBvh(families[3], 40));
    REQUIRE(window->files().imports().importTakeFile(QString::fromStdString(file.string())));
    app::TakeId imported;
    for (const auto& derived : document.derivedTakes())
        if (derived.id.isImported()) imported = derived.id;
    REQUIRE(!imported.isEmpty());
    document.selectTake(TakeSlot::A, imported);
    REQUIRE(QTest::qWaitFor([&] { return axisNames(imported); }, 60000));
    CHECK_FALSE(listed(axis).contains(QString::fromStdString(dir.string())));
}
