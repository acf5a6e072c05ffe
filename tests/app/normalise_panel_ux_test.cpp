// The Normalisation panel says what it shows: a variance table per take, DOF family and part in
// cm^2 and deg^2 (never summed together), one notation, rows made worse marked; a legend naming
// each correspondence curve; limits in the tool tips; a typed value beyond them clamped and said
// in the status bar; undo steps named after the value they set.
#include "tests/app/app_test_support.h"

#include "analysis/pipeline/stage_parameters.h"

#include "app/analysis_controller.h"
#include "app/emotion_panel.h"
#include "app/normalise_panel.h"
#include "app/variance_tree.h"

#include <catch2/catch.hpp>
#include <qcustomplot.h>

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QRegularExpression>
#include <QStatusBar>
#include <QHeaderView>
#include <QTreeWidget>

#include <map>

using namespace bunraku;

namespace {

bool idle(app::MainWindow& window)
{
    return QTest::qWaitFor([&] { return !window.analysis().scheduler().busy() && window.analysis().axes(); }, 120000);
}

QString statusText(app::MainWindow& window)
{
    QStringList texts;
    for (auto* label : window.statusBar()->findChildren<QLabel*>()) texts << label->text();
    return texts.join(QLatin1Char('\n'));
}

/// Two takes x four channels: head.x (cm), head.yaw (deg), hand.x (cm), hand.yaw (deg).
analysis::VarianceTable smallTable()
{
    analysis::VarianceTable table;
    table.takeNames = {"g/n/1", "g/n/2"};
    table.before.resize(2, 4);
    table.after.resize(2, 4);
    table.before << 100, 2000, 50, 400, //
        10, 30, 20, 40;
    table.after << 40, 500, 60, 100, // hand.x worse
        5, 10, 10, 20;
    table.totalBefore = table.before.rowwise().sum();
    table.totalAfter = table.after.rowwise().sum();
    return table;
}

std::vector<analysis::Channel> smallChannels()
{
    return {{"head", "x", "cm"}, {"head", "yaw", "deg"}, {"hand", "x", "cm"}, {"hand", "yaw", "deg"}};
}

} // namespace

TEST_CASE("variance rows sum one DOF family's channels per part, never centimetres with degrees", "[app][normalise][variance]")
{
    const auto rows = app::varianceRows(smallTable(), smallChannels());
    // Per take: position total, head, hand, rotation total, head, hand.
    REQUIRE(rows.size() == 12);
    const app::VarianceRow& position = rows[0];
    CHECK(position.family == "position");
    CHECK(position.unit == "cm\u00b2");
    CHECK(position.part.empty());
    CHECK(position.before == 150.0); // head.x + hand.x only
    CHECK(position.after == 100.0);
    CHECK(rows[1].part == "head");
    CHECK(rows[2].part == "hand");
    CHECK(rows[2].worse()); // 50 -> 60
    // The reference take against itself: exactly 0 before and after (take_normalisation_test).
    app::VarianceRow reference;
    CHECK_FALSE(reference.worse());
    CHECK(rows[3].family == "rotation");
    CHECK(rows[3].unit == "deg\u00b2");
    CHECK(rows[3].before == 2400.0);
    for (const auto& row : rows) CHECK((row.unit == "cm\u00b2") == (row.family == "position"));

    QTreeWidget tree;
    app::fillVarianceTree(&tree, smallTable(), smallChannels(), {QStringLiteral("take 1"), QStringLiteral("take 2")});
    REQUIRE(tree.topLevelItemCount() == 2);
    QTreeWidgetItem* first = tree.topLevelItem(0);
    CHECK(first->text(0) == QStringLiteral("take 1"));
    CHECK(app::isMarkedWorse(first)); // a part of it got worse
    CHECK_FALSE(app::isMarkedWorse(tree.topLevelItem(1)));
    QTreeWidgetItem* positions = first->child(0);
    CHECK(positions->text(0) == QStringLiteral("pos. cm\u00b2"));
    CHECK(positions->text(1) == QStringLiteral("150.0"));
    CHECK_FALSE(app::isMarkedWorse(positions)); // 150 -> 100 overall
    QTreeWidgetItem* hand = positions->child(1);
    CHECK(hand->text(0) == QStringLiteral("hand"));
    CHECK(app::isMarkedWorse(hand));
    CHECK(hand->text(3) == QStringLiteral("\u25b2 +20 %"));
    CHECK(first->child(1)->text(0) == QStringLiteral("rot. deg\u00b2"));
    CHECK(first->child(1)->text(1) == QStringLiteral("2,400.0")); // the same notation for every number
}

TEST_CASE("the normalisation panel's table, legend and summary say what was computed", "[app][normalise][variance]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    REQUIRE(idle(*window));
    auto* panel = window->normalisePanel();
    const auto cell = window->analysis().normalised()->cell("greeting", "none");
    REQUIRE(cell != nullptr);
    const auto rows = app::varianceRows(cell->variance, cell->referenceTake.channels);

    QTreeWidget* tree = panel->varianceTree();
    REQUIRE(tree->topLevelItemCount() == int(cell->takeIndices.size()));
    const QRegularExpression notation(QStringLiteral("^-?\\d{1,3}(,\\d{3})*\\.\\d$"));
    std::size_t row = 0;
    int worse = 0;
    for (int k = 0; k < tree->topLevelItemCount(); ++k) {
        QTreeWidgetItem* take = tree->topLevelItem(k);
        CHECK(take->text(0).startsWith(QStringLiteral("take %1").arg(cell->takeIndices[std::size_t(k)])));
        REQUIRE(take->childCount() == 2); // position and rotation
        for (int f = 0; f < take->childCount(); ++f) {
            QTreeWidgetItem* family = take->child(f);
            for (QTreeWidgetItem* item : [&] {
                     std::vector<QTreeWidgetItem*> items{family};
                     for (int p = 0; p < family->childCount(); ++p) items.push_back(family->child(p));
                     return items;
                 }()) {
                REQUIRE(row < rows.size());
                const app::VarianceRow& expected = rows[row++];
                INFO(take->text(0).toStdString() << " / " << item->text(0).toStdString());
                CHECK(item->text(1) == app::varianceText(expected.before));
                CHECK(item->text(2) == app::varianceText(expected.after));
                CHECK(notation.match(item->text(1)).hasMatch());
                CHECK(notation.match(item->text(2)).hasMatch());
                CHECK(app::isMarkedWorse(item) == expected.worse());
                worse += expected.worse() ? 1 : 0;
            }
            CHECK(family->text(0).endsWith(f == 0 ? QStringLiteral("cm\u00b2") : QStringLiteral("deg\u00b2")));
            CHECK(family->childCount() == 4); // head, shoulder, arm, hand
        }
    }
    CHECK(row == rows.size());
    INFO(worse << " rows worse than before");

    // Every take's correspondence curve is named in the legend.
    QCustomPlot* plot = panel->correspondencePlot();
    CHECK(plot->legend->visible());
    REQUIRE(plot->legend->itemCount() == int(cell->takeIndices.size()));
    for (int k = 0; k < plot->graphCount(); ++k)
        CHECK(plot->graph(k)->name() == QString::fromStdString(cell->variance.takeNames[std::size_t(k)]));
    // The summary names the reference and the parameters.
    CHECK(panel->summaryText().contains(QString::fromStdString(cell->referenceName).toHtmlEscaped()));
    CHECK(panel->summaryText().contains(QStringLiteral("tau 4, T_cmp 20, scales 1-16, optimal path")));

    // At a laptop's size no name in the first column is cut: the column is as wide as its
    // widest text (the tree scrolls sideways in a narrow dock), the header's too.
    window->resize(1366, 768);
    QCoreApplication::processEvents();
    const QFontMetrics metrics(tree->font());
    for (int k = 0; k < tree->topLevelItemCount(); ++k) {
        QTreeWidgetItem* take = tree->topLevelItem(k);
        INFO(take->text(0).toStdString());
        CHECK(tree->columnWidth(0) >= metrics.horizontalAdvance(take->text(0)) + tree->indentation());
    }
    CHECK(tree->columnWidth(0) >= tree->header()->sectionSizeHint(0));
}

TEST_CASE("limits are in the tool tips and are the analysis's: 200000 typed into T_cmp becomes 16000 and the status bar says so",
          "[app][normalise][limits]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    auto& document = window->document();
    auto* panel = window->normalisePanel();
    CHECK(panel->tauSpin()->toolTip().endsWith(QStringLiteral("From 0 to 200 frames.")));
    CHECK(panel->searchBandSpin()->toolTip().endsWith(QStringLiteral("From 0 to 16000 frames.")));
    // The largest scale that fits the demo corpus's shortest take.
    const int largestScale = analysis::pipeline::usableMaxScale(document.corpus());
    CHECK(largestScale < analysis::pipeline::kMaxScale);
    CHECK(panel->maxScaleSpin()->toolTip().endsWith(QStringLiteral("From 1 to %1.").arg(largestScale)));
    // The panel's limits are those the analysis enforces: the matcher's own for T_cmp.
    CHECK(panel->tauSpin()->maximum() == analysis::pipeline::kMaxTau);
    CHECK(panel->searchBandSpin()->maximum() == analysis::kMaxSearchBand);
    CHECK(panel->maxScaleSpin()->maximum() == largestScale);
    app::AnalysisParameters parameters = document.parameters();
    parameters.normalise.maxScale = 10;
    parameters.normalise.searchBand = 90;
    document.restoreParameters(parameters);
    CHECK(panel->maxScaleSpin()->value() == 10);
    CHECK(panel->searchBandSpin()->value() == 90);

    auto* band = panel->searchBandSpin();
    band->setFocus();
    band->selectAll();
    QTest::keyClicks(band, QStringLiteral("200000"));
    QTest::keyClick(band, Qt::Key_Return);
    CHECK(band->value() == 16000);
    CHECK(document.parameters().normalise.searchBand == 16000);
    CHECK(statusText(*window).contains(QStringLiteral("T_cmp 200000 frames is above the limit: set to 16000 frames")));
    CHECK(document.undoStack()->undoText() == QStringLiteral("Set T_cmp to 16000 frames"));
}

TEST_CASE("each analysis dock control at its maximum gives a value the analysis accepts", "[app][normalise][emotion][limits]")
{
    // Normalisation used to fail with "the search band T_cmp must be in 0..16000 frames" for a
    // T_cmp the dock allowed (up to 100000).
    auto window = test::demoWindow();
    REQUIRE(window);
    REQUIRE(idle(*window));
    auto& document = window->document();
    const auto& scheduler = window->analysis().scheduler();
    const app::AnalysisParameters defaults = document.parameters();
    struct Control {
        const char* name;
        QSpinBox* box;
        int slot;
    };
    const std::vector<Control> controls = {
        {"tau", window->normalisePanel()->tauSpin(), app::AnalysisController::kNormaliseSlot},
        {"T_cmp", window->normalisePanel()->searchBandSpin(), app::AnalysisController::kNormaliseSlot},
        {"largest scale", window->normalisePanel()->maxScaleSpin(), app::AnalysisController::kNormaliseSlot},
        {"M", window->emotionPanel()->orderBox(), app::AnalysisController::kDecomposeSlot},
    };
    for (const Control& control : controls) {
        INFO(control.name << " at its maximum " << control.box->maximum());
        document.restoreParameters(defaults);
        REQUIRE(idle(*window));
        control.box->setValue(control.box->maximum());
        REQUIRE(control.box->value() == control.box->maximum());
        CHECK(analysis::pipeline::validate(document.parameters()).ok());
        REQUIRE(idle(*window));
        INFO(scheduler.error(control.slot).toStdString());
        CHECK(scheduler.state(control.slot) == app::SlotState::Finished);
    }
    // The emotion weight's number field at its maximum: a weighted take.
    document.restoreParameters(defaults);
    auto* weight = window->emotionPanel()->weightBox();
    weight->setValue(weight->maximum());
    CHECK(document.parameters().design.emotionWeight == weight->maximum());
    CHECK(analysis::pipeline::validate(document.parameters()).ok());
    REQUIRE(idle(*window));
    CHECK(window->analysis().weightError().isEmpty());
    CHECK(window->emotionPanel()->weightedTake());
}

TEST_CASE("undo steps are named after the value they set", "[app][normalise][undo]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    auto& document = window->document();
    qint64 now = 0;
    document.setClock([&now] { return now; });
    auto* band = window->normalisePanel()->searchBandSpin();
    for (int step = 0; step < 10; ++step) {
        QTest::keyClick(band, Qt::Key_Up);
        now += 100; // steps 0.1 s apart: one undo step
    }
    REQUIRE(document.undoStack()->count() == 1);
    CHECK(document.undoStack()->undoText() == QStringLiteral("Set T_cmp to 30 frames"));
    QTest::keyClick(window->normalisePanel()->tauSpin(), Qt::Key_Down);
    CHECK(document.undoStack()->undoText() == QStringLiteral("Set tau to 3 frames"));
    auto* method = window->findChild<QComboBox*>("emotionMethod");
    REQUIRE(method != nullptr);
    method->setCurrentIndex(method->findData(QStringLiteral("least-squares")));
    CHECK(document.undoStack()->undoText() == QStringLiteral("Set the decomposition method to least squares (thesis 4.3.1)"));
    // The history lists them as they read.
    QStringList history;
    for (int i = 0; i < document.undoStack()->count(); ++i) history << document.undoStack()->text(i);
    CHECK(history == QStringList{QStringLiteral("Set T_cmp to 30 frames"), QStringLiteral("Set tau to 3 frames"),
                                 QStringLiteral("Set the decomposition method to least squares (thesis 4.3.1)")});
}
