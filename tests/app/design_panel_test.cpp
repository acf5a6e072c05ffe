#include "tests/app/app_test_support.h"

#include "app/design_controller.h"
#include "app/design_panel.h"
#include "app/parameters.h"

#include "widgets/gain_table.h"
#include "widgets/scrub_bar.h"
#include "widgets/timeline_widget.h"
#include "widgets/warp_curve_editor.h"

#include <catch2/catch.hpp>
#include <qcustomplot.h>

#include <QDockWidget>
#include <QPushButton>
#include <QSlider>

using namespace bunraku;
using app::TakeSlot;

namespace {

bool waitForDesign(app::MainWindow& window)
{
    return QTest::qWaitFor([&] { return window.design().ready() && !window.design().recomputer()->busy(); }, 60000);
}

void dragInPlot(QCustomPlot* plot, QPoint from, QPoint to)
{
    QTest::mousePress(plot, Qt::LeftButton, Qt::NoModifier, from);
    for (int step = 1; step <= 5; ++step) {
        const QPoint at = from + (to - from) * step / 5;
        QMouseEvent move(QEvent::MouseMove, QPointF(at), plot->mapToGlobal(QPointF(at)), Qt::NoButton, Qt::LeftButton,
                         Qt::NoModifier);
        QCoreApplication::sendEvent(plot, &move);
    }
    QTest::mouseRelease(plot, Qt::LeftButton, Qt::NoModifier, to);
}

} // namespace

TEST_CASE("the design is prepared in the background and the designed take is listed", "[app][design]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    REQUIRE(waitForDesign(*window));
    INFO(window->design().recomputer()->lastError().toStdString());
    const auto designed = window->document().take(QStringLiteral("live/designed"));
    REQUIRE(designed);
    const auto source = window->document().take(window->design().sourceId());
    REQUIRE(source->labels.emotion == "none");
    // With the identity warp and unit gains the design reproduces the functional take's frames.
    REQUIRE(designed->frameCount() == source->frameCount());
    REQUIRE(window->design().extractedWarp().size() > 0);
}

TEST_CASE("dragging a warp control point changes the designed take, stays monotone and undoes in one step", "[app][design]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    REQUIRE(waitForDesign(*window));
    auto& document = window->document();
    window->dock("designDock")->show();
    window->dock("designDock")->raise();
    auto* editor = window->designPanel()->editor();
    REQUIRE(QTest::qWaitForWindowExposed(editor));
    editor->plot()->replot();
    const auto before = window->design().designedTake();
    const Eigen::MatrixXd valuesBefore = before->values;
    const auto curveBefore = editor->curve();
    REQUIRE(curveBefore.points.size() > 4);

    const std::size_t index = curveBefore.points.size() / 2;
    const QPoint from = editor->plot()->mapFrom(editor, editor->pointPosition(index));
    // Up by 3 functional frames (less than the spacing of the points).
    const int up = int(editor->plot()->yAxis->coordToPixel(curveBefore.points[index].source + 3.0));
    dragInPlot(editor->plot(), from, QPoint(from.x(), up));

    REQUIRE(document.undoStack()->count() == 1); // the whole drag is one step
    const auto after = window->design().designedTake();
    REQUIRE(after != before);
    REQUIRE((after->values - valuesBefore).cwiseAbs().maxCoeff() > 1e-3);
    const auto curve = editor->curve();
    REQUIRE(curve.points[index].source > curveBefore.points[index].source);
    const Eigen::VectorXd samples = analysis::sampleWarp(curve);
    for (Eigen::Index i = 1; i < samples.size(); ++i) REQUIRE(samples[i] >= samples[i - 1]);
    for (std::size_t i = 1; i < curve.points.size(); ++i) {
        REQUIRE(curve.points[i].output > curve.points[i - 1].output);
        REQUIRE(curve.points[i].source >= curve.points[i - 1].source);
    }

    // Dragging far beyond the next point is clamped: still monotone.
    const QPoint again = editor->plot()->mapFrom(editor, editor->pointPosition(index));
    dragInPlot(editor->plot(), again, again + QPoint(0, -400));
    const Eigen::VectorXd clamped = analysis::sampleWarp(editor->curve());
    for (Eigen::Index i = 1; i < clamped.size(); ++i) REQUIRE(clamped[i] >= clamped[i - 1]);
    REQUIRE(document.undoStack()->count() == 2);

    document.undoStack()->undo();
    document.undoStack()->undo();
    REQUIRE(editor->curve().points == curveBefore.points);
    REQUIRE((window->design().designedTake()->values - valuesBefore).cwiseAbs().maxCoeff() < 1e-12);
    document.undoStack()->redo();
    REQUIRE(editor->curve().points[index].source > curveBefore.points[index].source);
}

TEST_CASE("a gain slider drag changes the designed take as one undo step", "[app][design]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    REQUIRE(waitForDesign(*window));
    auto* table = window->designPanel()->gainTable();
    REQUIRE(table->gains().phrases.size() >= 2);
    table->selectCell(1, 2); // second phrase, axis z
    const Eigen::MatrixXd before = window->design().designedTake()->values;
    auto* slider = table->g1Slider();
    REQUIRE(slider->isEnabled());
    emit slider->sliderPressed();
    for (int position = 10; position <= 100; position += 10) slider->setValue(position);
    emit slider->sliderReleased();
    REQUIRE(window->document().undoStack()->count() == 1);
    REQUIRE(table->gains().phrases[1].dofs[2].g1 == Approx(2.0));
    REQUIRE((window->design().designedTake()->values - before).cwiseAbs().maxCoeff() > 1e-3);
    window->document().undoStack()->undo();
    REQUIRE(table->gains().phrases[1].dofs[2].g1 == 1.0);
    REQUIRE((window->design().designedTake()->values - before).cwiseAbs().maxCoeff() < 1e-12);
}

TEST_CASE("the warp editor adds and deletes points and resets to identity and extracted", "[app][design]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    REQUIRE(waitForDesign(*window));
    auto* editor = window->designPanel()->editor();
    auto& design = window->design();
    const std::size_t count = editor->curve().points.size();
    design.editWarp(editor->withPointAdded(editor->curve().points[1].output + 3.0));
    REQUIRE(editor->curve().points.size() == count + 1);
    design.editWarp(editor->withPointRemoved(2));
    REQUIRE(editor->curve().points.size() == count);
    REQUIRE(editor->withPointRemoved(0).points.size() == count); // the ends stay
    design.resetWarpToExtracted();
    REQUIRE(editor->curve().points == design.extractedCurve().points);
    design.resetWarpToIdentity();
    for (const auto& point : editor->curve().points) REQUIRE(point.source == Approx(point.output));
}

namespace {

void dragOnBar(QWidget* bar, QPoint from, QPoint to)
{
    QTest::mousePress(bar, Qt::LeftButton, Qt::NoModifier, from);
    for (int step = 1; step <= 5; ++step) {
        const QPoint at = from + (to - from) * step / 5;
        QMouseEvent move(QEvent::MouseMove, QPointF(at), bar->mapToGlobal(QPointF(at)), Qt::NoButton, Qt::LeftButton,
                         Qt::NoModifier);
        QCoreApplication::sendEvent(bar, &move);
    }
    QTest::mouseRelease(bar, Qt::LeftButton, Qt::NoModifier, to);
}

} // namespace

TEST_CASE("dragging a phrase mark on the timeline moves the design's boundary as one undo step", "[app][design]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    REQUIRE(waitForDesign(*window));
    auto& document = window->document();
    auto& design = window->design();
    document.selectTake(TakeSlot::A, design.sourceId());
    design.useExtractedGains(); // with unit gains the phrases change nothing
    REQUIRE(document.undoStack()->count() == 1);
    auto* bar = window->timeline()->scrubBar();
    REQUIRE(bar->boundariesEditable());
    const auto framesBefore = design.boundaries();
    REQUIRE(framesBefore.size() >= 4); // at least two inner boundaries
    REQUIRE(bar->boundaries() == design.boundarySeconds());
    const Eigen::MatrixXd valuesBefore = design.designedTake()->values;

    // A short drag to the right: the first inner boundary moves later.
    const int y = bar->height() / 2;
    const QPoint from(bar->xOfTime(bar->boundaries()[0]), y);
    dragOnBar(bar, from, from + QPoint(12, 0));
    REQUIRE(document.undoStack()->count() == 2); // the whole drag is one step
    REQUIRE(design.boundaries()[1] > framesBefore[1]);
    REQUIRE((design.designedTake()->values - valuesBefore).cwiseAbs().maxCoeff() > 1e-6);
    REQUIRE(design.gains().phrases[0].end == design.boundaries()[1]);

    // Far past the next boundary and past the end: clamped, still ordered and inside the take.
    const QPoint again(bar->xOfTime(bar->boundaries()[0]), y);
    dragOnBar(bar, again, QPoint(bar->width() + 50, y));
    REQUIRE(document.undoStack()->count() == 3);
    const auto clamped = design.boundaries();
    REQUIRE(clamped.size() == framesBefore.size());
    for (std::size_t i = 1; i < clamped.size(); ++i) REQUIRE(clamped[i] > clamped[i - 1]);
    REQUIRE(clamped.front() == 0);
    REQUIRE(clamped.back() == framesBefore.back());
    REQUIRE(clamped[1] == clamped[2] - 1);

    document.undoStack()->undo();
    document.undoStack()->undo();
    REQUIRE(design.boundaries() == framesBefore);
    REQUIRE(bar->boundaries() == design.boundarySeconds());
    REQUIRE((design.designedTake()->values - valuesBefore).cwiseAbs().maxCoeff() < 1e-12);
    document.undoStack()->redo();
    REQUIRE(design.boundaries()[1] > framesBefore[1]);

    // "Reset phrases" in the design panel brings back the suggested boundaries as one step.
    auto* reset = window->designPanel()->findChild<QPushButton*>(QStringLiteral("resetBoundaries"));
    REQUIRE(reset);
    reset->click();
    REQUIRE(design.boundaries() == framesBefore);
    REQUIRE(bar->boundaries() == design.boundarySeconds());
    REQUIRE(document.undoStack()->count() == 3);
}

TEST_CASE("phrase marks of takes other than the design's cannot be dragged", "[app][design]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    REQUIRE(waitForDesign(*window));
    auto& design = window->design();
    for (std::size_t i = 0; i < window->document().corpus().takes.size(); ++i) {
        const QString id = app::Document::corpusTakeId(i);
        if (id == design.sourceId()) continue;
        window->document().selectTake(TakeSlot::A, id);
        break;
    }
    REQUIRE_FALSE(window->timeline()->scrubBar()->boundariesEditable());
    window->document().selectTake(TakeSlot::A, QStringLiteral("live/designed"));
    REQUIRE(window->timeline()->scrubBar()->boundariesEditable());
}
