#include "tests/app/app_test_support.h"
#include "tests/app/bandai_corpus_support.h"

#include "app/analysis_controller.h"
#include "app/commands.h"
#include "app/design_panel.h"
#include "app/emotion_panel.h"
#include "app/normalise_panel.h"

#include "analysis/core/angle_channels.h"
#include "analysis/decompose/emotion_weight.h"
#include "tests/support/test_paths.h"

#include "analysis/core/skeleton_take.h"

#include <catch2/catch.hpp>

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QPushButton>
#include <QSlider>
#include <QSpinBox>
#include <QTreeWidget>

#include <algorithm>
#include <filesystem>

using namespace bunraku;
using app::TakeSlot;

namespace {

bool idle(app::MainWindow& window)
{
    return QTest::qWaitFor([&] { return !window.analysis().scheduler().busy() && window.analysis().axes(); }, 60000);
}

/// The demo window with a friendly take as A once its weighted take (y + a z) is computed; null
/// when the window did not show or the weighted take did not come.
std::unique_ptr<app::MainWindow> windowWithWeightedFriendlyTake()
{
    auto window = test::demoWindow();
    if (!window) return nullptr;
    window->document().selectTake(TakeSlot::A, app::TakeId::corpus(7)); // a friendly take
    auto* panel = window->emotionPanel();
    if (!QTest::qWaitFor([&] { return panel->ready() && panel->weightedTake(); }, 60000)) return nullptr;
    return window;
}

} // namespace

TEST_CASE("changing tau recomputes the normalised take in the background, undo restores it from the cache", "[app][normalise]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    auto* panel = window->normalisePanel();
    auto& document = window->document();
    REQUIRE(idle(*window));
    const auto first = panel->normalisedTake();
    REQUIRE(first);
    REQUIRE(panel->varianceTree()->topLevelItemCount() == 5); // the cell's 5 takes
    const Eigen::MatrixXd before = first->values;
    const int starts = window->analysis().scheduler().starts(app::AnalysisController::kNormaliseSlot);

    panel->tauSpin()->setValue(0); // through the GUI: one ChangeStageParameters
    REQUIRE(document.parameters().normalise.tau == 0);
    REQUIRE(QTest::qWaitFor([&] { return panel->normalisedTake() != first && idle(*window); }, 60000));
    const auto second = panel->normalisedTake();
    REQUIRE(second->frameCount() == first->frameCount());
    REQUIRE((second->values - before).cwiseAbs().maxCoeff() > 1e-6);

    document.undoStack()->undo();
    REQUIRE(panel->tauSpin()->value() == 4);
    REQUIRE(QTest::qWaitFor([&] { return panel->normalisedTake() != second && idle(*window); }, 60000));
    REQUIRE(panel->normalisedTake()->values == before);
    // tau = 4 again: taken from the cache, not recomputed
    REQUIRE(window->analysis().scheduler().starts(app::AnalysisController::kNormaliseSlot) == starts + 1);
}

TEST_CASE("the emotion weight slider re-synthesises y + a z live as one undo step", "[app][emotion]")
{
    auto window = windowWithWeightedFriendlyTake();
    REQUIRE(window);
    auto* panel = window->emotionPanel();
    auto& document = window->document();
    // The shown take is the weighted body's motion; its per-channel result (the thesis's
    // x = y + a z) is kept beside it.
    const auto perChannel = [&] { return document.perChannelGhostOf(app::TakeId::live(QStringLiteral("weighted"))); };
    REQUIRE(perChannel());
    const Eigen::MatrixXd atOne = perChannel()->values;

    auto* slider = panel->weightSlider();
    emit slider->sliderPressed();
    for (int position = 110; position <= 200; position += 10) slider->setValue(position);
    emit slider->sliderReleased();
    REQUIRE(document.undoStack()->count() == 1);
    REQUIRE(document.parameters().design.emotionWeight == Approx(2.0));
    const Eigen::MatrixXd atTwo = perChannel()->values;
    REQUIRE(document.take(app::TakeId::live(QStringLiteral("weighted"))) == panel->weightedTake());
    REQUIRE(document.take(app::TakeId::live(QStringLiteral("weighted")))->values == analysis::bodyTake(*document.take(app::TakeId::live(QStringLiteral("weighted")))).values);

    slider->setValue(0);
    const Eigen::MatrixXd atZero = perChannel() ? perChannel()->values : panel->weightedTake()->values;
    // x(a) = y + a z is linear in a in the decomposition's coordinates (angles as rotation
    // coordinates about the function's chart): x(2) - x(1) = x(1) - x(0) = z, and z is not zero.
    const auto& decomposition = window->analysis().decomposed()->components;
    std::size_t function = 0;
    while (decomposition.functions[function].function != panel->weightedTake()->labels.function) ++function;
    auto coordinates = [&](const Eigen::MatrixXd& values) {
        analysis::Take take = *panel->weightedTake();
        take.values = values;
        return analysis::rotationCoordinates(take, decomposition.charts[function]);
    };
    const Eigen::MatrixXd zero = coordinates(atZero), one = coordinates(atOne), two = coordinates(atTwo);
    REQUIRE(((two - one) - (one - zero)).cwiseAbs().maxCoeff() < 1e-9);
    REQUIRE((one - zero).cwiseAbs().maxCoeff() > 0.1);

    document.undoStack()->undo(); // back to a = 2
    document.undoStack()->undo(); // back to a = 1
    REQUIRE(slider->value() == 100);
    REQUIRE((perChannel()->values - atOne).cwiseAbs().maxCoeff() < 1e-12);
}

TEST_CASE("the emotion weight has a number field beside its slider: 2 typed is a = 2.00, and its steps are one undo step",
          "[app][emotion][undo]")
{
    // A drag of the slider alone lands on 2.03, never 2.00.
    auto window = windowWithWeightedFriendlyTake();
    REQUIRE(window);
    auto& document = window->document();
    qint64 now = 0;
    document.setClock([&now] { return now; });
    auto* panel = window->emotionPanel();
    auto* box = panel->weightBox();
    REQUIRE(box != nullptr);
    CHECK(box->isVisibleTo(window.get()));
    // Beside the slider, in its row.
    const QPoint boxAt = box->mapTo(window.get(), QPoint(0, box->height() / 2));
    const QPoint sliderAt = panel->weightSlider()->mapTo(window.get(), QPoint(0, panel->weightSlider()->height() / 2));
    CHECK(std::abs(boxAt.y() - sliderAt.y()) < box->height());
    CHECK(boxAt.x() > sliderAt.x());
    CHECK(box->minimum() == analysis::kMinEmotionWeight);
    CHECK(box->maximum() == analysis::kMaxEmotionWeight);
    CHECK(box->value() == 1.0);

    // Typed, applied on Enter: exactly 2, one undo step, the slider follows.
    box->setFocus();
    box->selectAll();
    QTest::keyClicks(box, QStringLiteral("2"));
    QTest::keyClick(box, Qt::Key_Return);
    CHECK(document.parameters().design.emotionWeight == 2.0);
    CHECK(panel->weightSlider()->value() == 200);
    CHECK(document.undoStack()->count() == 1);
    REQUIRE(QTest::qWaitFor([&] { return panel->weightedTake() && panel->statusText().contains(QStringLiteral("a = 2.00")); }, 60000));

    // Arrow steps in one series merge into one undo step, as the Normalisation dock's boxes do.
    for (int step = 0; step < 4; ++step) {
        QTest::keyClick(box, Qt::Key_Down);
        now += 100;
    }
    CHECK(document.parameters().design.emotionWeight == Approx(1.8));
    CHECK(document.undoStack()->count() == 2);
    document.undoStack()->undo();
    CHECK(document.parameters().design.emotionWeight == 2.0);
    CHECK(box->value() == 2.0);
    CHECK(panel->weightSlider()->value() == 200);
    document.undoStack()->undo();
    CHECK(box->value() == 1.0);
    CHECK(panel->weightSlider()->value() == 100);
    // The slider moved shows in the box.
    panel->weightSlider()->setValue(150);
    CHECK(box->value() == 1.5);
}

TEST_CASE("Show weighted as A shows the weighted take, which follows the weight while shown", "[app][emotion]")
{
    auto window = windowWithWeightedFriendlyTake();
    REQUIRE(window);
    auto* panel = window->emotionPanel();
    auto& document = window->document();
    QPushButton* show = nullptr;
    for (auto* button : panel->findChildren<QPushButton*>())
        if (button->text() == QStringLiteral("Show weighted as A")) show = button;
    REQUIRE(show);
    QTest::mouseClick(show, Qt::LeftButton);
    REQUIRE(document.selectedId(TakeSlot::A) == QStringLiteral("live/weighted"));
    const auto atOne = document.selectedTake(TakeSlot::A);
    REQUIRE(atOne == panel->weightedTake());
    // While shown, a new weight replaces it once (the replacement announces a new selection,
    // which must not synthesise it again), and A shows the new one.
    int replaced = 0;
    QObject::connect(&document, &app::Document::takeChanged, [&](const app::TakeId& id) { replaced += id == QStringLiteral("live/weighted"); });
    panel->weightSlider()->setValue(200);
    CHECK(replaced == 1);
    CHECK(document.selectedId(TakeSlot::A) == QStringLiteral("live/weighted"));
    CHECK(document.selectedTake(TakeSlot::A) == panel->weightedTake());
    CHECK(document.selectedTake(TakeSlot::A) != atOne);
    CHECK(document.takeLabel(app::TakeId::live(QStringLiteral("weighted"))).contains(QStringLiteral("a=2.00")));
}

TEST_CASE("chapter 4 defaults to the thesis: KM2O on the normalised takes with M chosen by P", "[app][emotion]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    auto* panel = window->emotionPanel();
    auto& document = window->document();
    document.selectTake(TakeSlot::A, app::TakeId::corpus(7));
    REQUIRE(idle(*window));
    REQUIRE(panel->decomposedMethod() == QStringLiteral("km2o"));
    const auto decomposed = window->analysis().decomposed();
    REQUIRE(decomposed->parameters.input == analysis::pipeline::DecomposeInput::Normalised);
    REQUIRE(decomposed->km2o->candidateLengths.size() > 5); // M searched over 1..M_max
    REQUIRE(panel->statusText().contains(QStringLiteral("chosen by P")));
    const auto byP = panel->weightedTake();

    panel->orderBox()->setValue(3); // a given M
    REQUIRE(QTest::qWaitFor([&] { return panel->decomposedOrder() == 3 && idle(*window); }, 60000));
    REQUIRE(window->analysis().decomposed()->km2o->candidateLengths == std::vector<int>{3});
    panel->methodBox()->setCurrentIndex(panel->methodBox()->findData(QStringLiteral("least-squares")));
    REQUIRE_FALSE(panel->orderBox()->isEnabled());
    REQUIRE(QTest::qWaitFor([&] { return panel->decomposedMethod() == QStringLiteral("least-squares") && idle(*window); }, 60000));
    REQUIRE((panel->weightedTake()->values - byP->values).cwiseAbs().maxCoeff() > 1e-9);

    document.undoStack()->undo(); // KM2O with M = 3
    document.undoStack()->undo(); // KM2O with M by P
    REQUIRE(QTest::qWaitFor([&] { return panel->decomposedOrder() == decomposed->km2o->correlationLength &&
                                         panel->decomposedMethod() == QStringLiteral("km2o") && idle(*window); },
                            60000));
    REQUIRE(panel->weightedTake()->values == byP->values);
}

TEST_CASE("steps of tau, T_cmp, M and the emotion weight slider merge per control", "[app][normalise][emotion]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    auto& document = window->document();
    qint64 now = 0;
    document.setClock([&now] { return now; });
    auto* tau = window->normalisePanel()->tauSpin();
    auto* band = window->normalisePanel()->searchBandSpin();
    for (int step = 0; step < 3; ++step) QTest::keyClick(tau, Qt::Key_Up);
    REQUIRE(document.parameters().normalise.tau == 7);
    REQUIRE(document.undoStack()->count() == 1);
    for (int step = 0; step < 4; ++step) QTest::keyClick(band, Qt::Key_Down);
    REQUIRE(document.parameters().normalise.searchBand == 16);
    REQUIRE(document.undoStack()->count() == 2); // another control: its own step

    auto* slider = window->emotionPanel()->weightSlider();
    for (int step = 0; step < 3; ++step) QTest::keyClick(slider, Qt::Key_Up);
    REQUIRE(document.parameters().design.emotionWeight == Approx(1.03));
    REQUIRE(document.undoStack()->count() == 3);
    auto* order = window->emotionPanel()->orderBox();
    for (int step = 0; step < 5; ++step) QTest::keyClick(order, Qt::Key_Up);
    REQUIRE(document.parameters().decompose.correlationLength == 5);
    REQUIRE(document.undoStack()->count() == 4);

    document.undoStack()->undo();
    REQUIRE(order->value() == 0);
    document.undoStack()->undo();
    REQUIRE(document.parameters().design.emotionWeight == 1.0);
    REQUIRE(slider->value() == 100);
    document.undoStack()->undo();
    REQUIRE(band->value() == 20);
    document.undoStack()->undo();
    REQUIRE(tau->value() == 4);
    REQUIRE(idle(*window));
}

TEST_CASE("the Emotion dock says KM2O is not estimable on the Bandai bye takes and shows their least-squares weighting",
          "[app][emotion][one-take]")
{
    // One take per emotion (docs/KM2O.md, "Cells with one take"): the default chain runs through.
    const auto corpus = test::bandaiCorpusFolder({"bye_normal_001.bvh", "bye_happy_001.bvh", "bye_angry_001.bvh"}, "emotion_one_take", "bye");
    if (corpus.empty()) return;

    auto window = test::windowOnCorpus(corpus);
    REQUIRE(window);
    auto& document = window->document();
    const auto& takes = document.corpus().takes;
    const auto happy = std::find_if(takes.begin(), takes.end(), [](const analysis::Take& t) { return t.labels.emotion == "happy"; });
    REQUIRE(happy != takes.end());
    document.selectTake(TakeSlot::A, app::TakeId::corpus(std::size_t(happy - takes.begin())));
    REQUIRE(idle(*window));
    auto* panel = window->emotionPanel();
    REQUIRE(QTest::qWaitFor([&] { return panel->weightedTake() != nullptr; }, 60000));
    CHECK(panel->decomposedMethod() == QStringLiteral("km2o"));
    CHECK(panel->decomposedOrder() == 0); // no M chosen
    const auto decomposed = window->analysis().decomposed();
    REQUIRE(decomposed->km2o);
    CHECK_FALSE(decomposed->km2o->estimable());
    for (const auto& cell : decomposed->km2o->cells) CHECK(cell.source == analysis::Km2oCellSource::LeastSquares);
    const QString text = panel->statusText();
    INFO(text.toStdString());
    CHECK(text.contains(QStringLiteral("Weighted take <b>bye/happy</b>")));
    CHECK(text.contains(QStringLiteral("least squares (KM2O not estimable: no cell has two takes)")));
    CHECK(text.contains(QStringLiteral("<li>function 'bye': KM2O not estimable")));
    CHECK_FALSE(text.contains(QStringLiteral("mean P")));
    // The components are least squares's, not left empty: y + z is the cell's one (normalised) take.
    const auto& d = decomposed->components;
    const auto* y = d.function("bye");
    const auto* z = d.emotion("bye", "happy");
    REQUIRE(y);
    REQUIRE(z);
    const int cell = d.cellIndex("bye", "happy");
    REQUIRE(cell >= 0);
    CHECK(((y->values + z->values) - d.cellMeans[std::size_t(cell)]).cwiseAbs().maxCoeff() < 1e-9);
}

TEST_CASE("the Normalisation panel normalises with the optimal path by default, and with the greedy scan it names the takes "
          "normalisation moved away and suggests the optimal path, as the CLI does",
          "[app][normalise][variance]")
{
    const auto corpus = test::bandaiCorpusFolder(test::bandaiWaveNames("active"), "normalise_worse_takes", "active");
    if (corpus.empty()) return;

    auto window = test::windowOnCorpus(corpus);
    REQUIRE(window);
    auto* panel = window->normalisePanel();
    auto* path = panel->findChild<QComboBox*>(QStringLiteral("normalisePath"));
    REQUIRE(path);
    // The default: the optimal path, shown in the dock; no take comes out further (tests_cli "normalise prints*").
    CHECK(window->document().parameters().normalise.path == analysis::PathMethod::Optimal);
    CHECK(path->currentData().toString() == QStringLiteral("optimal"));
    CHECK(path->currentText() == QStringLiteral("optimal (DP)"));
    REQUIRE(QTest::qWaitFor([&] { return idle(*window) && panel->summaryText().contains(QStringLiteral("wave-right-hand/active</b> normalised to")); }, 60000));
    INFO(panel->summaryText().toStdString());
    CHECK(panel->summaryText().contains(QStringLiteral("optimal path")));
    CHECK_FALSE(panel->summaryText().contains(QStringLiteral("came out further")));

    // The thesis's greedy scan, one choice away: takes 2 and 4 come out further in both families.
    path->setCurrentIndex(path->findData(QStringLiteral("greedy"))); // as a user picks it
    REQUIRE(window->document().parameters().normalise.path == analysis::PathMethod::Greedy);
    REQUIRE(QTest::qWaitFor([&] { return idle(*window) && panel->summaryText().contains(QStringLiteral("greedy path")); }, 60000));
    INFO(panel->summaryText().toStdString());
    CHECK(panel->summaryText().contains(QStringLiteral("Take(s) 2, 4 came out further from the reference in a DOF family")));
    CHECK(panel->summaryText().contains(QStringLiteral("optimal (DP)")));
}

TEST_CASE("the analysis docks say they analyse the corpus while take A is an imported take", "[app][import]")
{
    const auto file = test::bandaiDir() / "bye_angry_001.bvh";
    if (!test::requireBandaiData(std::filesystem::exists(file))) return;
    auto window = test::demoWindow();
    REQUIRE(window);
    std::vector<QWidget*> docks{window->normalisePanel(), window->emotionPanel(), window->designPanel()};
    const auto notices = [&] {
        std::vector<QLabel*> found;
        for (QWidget* dock : docks) found.push_back(dock->findChild<QLabel*>(QStringLiteral("analysisScopeNotice")));
        return found;
    };
    for (QLabel* notice : notices()) {
        REQUIRE(notice);
        CHECK_FALSE(notice->isVisibleTo(notice->parentWidget()));
    }
    REQUIRE(window->files().imports().importTakeFile(QString::fromStdString(file.string())));
    REQUIRE(window->document().selectedId(TakeSlot::A).isImported());
    for (QLabel* notice : notices()) {
        CHECK(notice->isVisibleTo(notice->parentWidget()));
        CHECK(notice->text().contains(QStringLiteral("Take A (bye_angry_001.bvh) is imported beside the corpus")));
        CHECK(notice->text().contains(QStringLiteral("the demo corpus (30 takes)")));
        CHECK(notice->text().contains(QStringLiteral("File &gt; New Corpus from Files")));
    }
    window->document().selectTake(TakeSlot::A, app::TakeId::corpus(2));
    for (QLabel* notice : notices()) CHECK_FALSE(notice->isVisibleTo(notice->parentWidget()));
}
