#include "tests/app/app_test_support.h"
#include "tests/app/bandai_corpus_support.h"

#include "app/commands.h"
#include "app/design_controller.h"
#include "app/design_panel.h"
#include "app/normalise_panel.h"
#include "app/analysis_controller.h"
#include "app/commands.h"

#include "widgets/gain_table.h"
#include "widgets/graph_grid.h"
#include "widgets/graph_panel.h"
#include "widgets/take_series.h"
#include "widgets/scale_error_plot.h"
#include "widgets/scrub_bar.h"
#include "widgets/timeline_widget.h"
#include "widgets/warp_curve_editor.h"

#include <catch2/catch.hpp>
#include <qcustomplot.h>

#include <QDockWidget>
#include <QScrollBar>
#include <QLabel>
#include <QMenu>
#include <QPushButton>
#include <QSignalSpy>
#include <QSlider>
#include <QTableWidget>

#include <algorithm>
#include <cmath>
#include <memory>

using namespace bunraku;
using app::TakeSlot;

namespace {

bool waitForDesign(app::MainWindow& window)
{
    return QTest::qWaitFor([&] { return window.design().ready() && !window.analysis().scheduler().busy(); }, 60000);
}

/// The Design dock's warp editor, shown and drawn once the design is ready; null if it never is.
widgets::WarpCurveEditor* shownWarpEditor(app::MainWindow& window)
{
    if (!waitForDesign(window)) return nullptr;
    window.dock("designDock")->show();
    window.dock("designDock")->raise();
    auto* editor = window.designPanel()->editor();
    if (!QTest::qWaitForWindowExposed(editor)) return nullptr;
    editor->plot()->replot();
    return editor;
}

/// A left-button drag in 5 moves from `from` to `to` (widget coordinates), with `modifiers` held.
void dragIn(QWidget* widget, QPoint from, QPoint to, Qt::KeyboardModifiers modifiers = Qt::NoModifier)
{
    QTest::mousePress(widget, Qt::LeftButton, modifiers, from);
    for (int step = 1; step <= 5; ++step) {
        const QPoint at = from + (to - from) * step / 5;
        QMouseEvent move(QEvent::MouseMove, QPointF(at), widget->mapToGlobal(QPointF(at)), Qt::NoButton, Qt::LeftButton, modifiers);
        QCoreApplication::sendEvent(widget, &move);
    }
    QTest::mouseRelease(widget, Qt::LeftButton, modifiers, to);
}

} // namespace

TEST_CASE("the design is prepared in the background and the designed take is listed", "[app][design]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    REQUIRE(waitForDesign(*window));
    INFO(window->analysis().scheduler().error(app::AnalysisController::kAxesSlot).toStdString());
    const auto designed = window->document().take(app::TakeId::live(QStringLiteral("designed")));
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
    auto* editor = shownWarpEditor(*window);
    REQUIRE(editor);
    auto& document = window->document();
    const auto before = window->design().designedTake();
    const Eigen::MatrixXd valuesBefore = before->values;
    const auto curveBefore = editor->curve();
    REQUIRE(curveBefore.points.size() > 4);

    const std::size_t index = curveBefore.points.size() / 2;
    const QPoint from = editor->plot()->mapFrom(editor, editor->pointPosition(index));
    // Up by 3 functional frames (less than the spacing of the points).
    const int up = int(editor->plot()->yAxis->coordToPixel(curveBefore.points[index].source + 3.0));
    dragIn(editor->plot(), from, QPoint(from.x(), up));

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
    dragIn(editor->plot(), again, again + QPoint(0, -400));
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

TEST_CASE("a Shift drag of a warp point pushes the points it meets, as one undo step", "[app][design]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    auto* editor = shownWarpEditor(*window);
    REQUIRE(editor);
    auto& document = window->document();
    const auto curveBefore = editor->curve();
    const std::size_t index = curveBefore.points.size() / 2;
    REQUIRE(index + 3 < curveBefore.points.size());
    // Up past the next two points' functional frames.
    const double target = curveBefore.points[index + 2].source + 4.0;
    const QPoint from = editor->plot()->mapFrom(editor, editor->pointPosition(index));
    const QPoint to(from.x(), int(editor->plot()->yAxis->coordToPixel(target)));
    dragIn(editor->plot(), from, to, Qt::ShiftModifier);
    REQUIRE(document.undoStack()->count() == 1);
    const auto curve = editor->curve();
    const double reached = curve.points[index].source;
    CHECK(reached > curveBefore.points[index + 2].source); // a plain drag stops at the next point's
    CHECK(curve.points[index + 1].source == reached);
    CHECK(curve.points[index + 2].source == reached);
    for (std::size_t i = 0; i < index; ++i) CHECK(curve.points[i] == curveBefore.points[i]);
    for (std::size_t i = index + 3; i < curve.points.size(); ++i)
        CHECK(curve.points[i].source == std::max(curveBefore.points[i].source, reached));
    const Eigen::VectorXd samples = analysis::sampleWarp(curve);
    for (Eigen::Index i = 1; i < samples.size(); ++i) REQUIRE(samples[i] >= samples[i - 1]);
    document.undoStack()->undo();
    CHECK(editor->curve().points == curveBefore.points);
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
    dragIn(bar, from, from + QPoint(12, 0));
    REQUIRE(document.undoStack()->count() == 2); // the whole drag is one step
    REQUIRE(design.boundaries()[1] > framesBefore[1]);
    REQUIRE((design.designedTake()->values - valuesBefore).cwiseAbs().maxCoeff() > 1e-6);
    REQUIRE(design.gains().phrases[0].end == design.boundaries()[1]);

    // Far past the next boundary and past the end: clamped, still ordered and inside the take.
    const QPoint again(bar->xOfTime(bar->boundaries()[0]), y);
    dragIn(bar, again, QPoint(bar->width() + 50, y));
    REQUIRE(document.undoStack()->count() == 3);
    const auto clamped = design.boundaries();
    REQUIRE(clamped.size() == framesBefore.size());
    for (std::size_t i = 1; i < clamped.size(); ++i) REQUIRE(clamped[i] > clamped[i - 1]);
    REQUIRE(clamped.front() == 0);
    REQUIRE(clamped.back() == framesBefore.back());
    REQUIRE(clamped[1] == clamped[2] - 2); // phrases stay at least 2 frames long

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
        const app::TakeId id = app::TakeId::corpus(i);
        if (id == design.sourceId()) continue;
        window->document().selectTake(TakeSlot::A, id);
        break;
    }
    REQUIRE_FALSE(window->timeline()->scrubBar()->boundariesEditable());
    window->document().selectTake(TakeSlot::A, app::TakeId::live(QStringLiteral("designed")));
    REQUIRE(window->timeline()->scrubBar()->boundariesEditable());
}

namespace {

/// g0 and g1 of every phrase and DOF.
std::vector<std::vector<std::pair<double, double>>> gainValues(const analysis::GainSet& gains)
{
    std::vector<std::vector<std::pair<double, double>>> values;
    for (const auto& phrase : gains.phrases) {
        values.emplace_back();
        for (const auto& dof : phrase.dofs) values.back().emplace_back(dof.g0, dof.g1);
    }
    return values;
}

} // namespace

TEST_CASE("phrase boundaries are added and removed one at a time, each one undo step with the gains", "[app][design]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    REQUIRE(waitForDesign(*window));
    auto& document = window->document();
    auto& design = window->design();
    document.selectTake(TakeSlot::A, design.sourceId());
    design.useExtractedGains(); // distinct gains per phrase, so their remapping shows
    REQUIRE(document.undoStack()->count() == 1);
    auto* bar = window->timeline()->scrubBar();
    auto* table = window->designPanel()->gainTable();
    const double rate = design.functionalRateHz();
    const auto framesBefore = design.boundaries();
    const auto gainsBefore = gainValues(design.gains());
    REQUIRE(framesBefore.size() >= 3);
    REQUIRE(gainsBefore.size() == framesBefore.size() - 1);
    const int y = bar->height() / 2;

    // Double click in the middle of the first phrase: a new boundary there, the first phrase's
    // gains copied to both halves.
    const double middle = 0.5 * double(framesBefore[0] + framesBefore[1]) / rate;
    QTest::mouseDClick(bar, Qt::LeftButton, Qt::NoModifier, QPoint(bar->xOfTime(middle), y));
    REQUIRE(document.undoStack()->count() == 2);
    auto frames = design.boundaries();
    REQUIRE(frames.size() == framesBefore.size() + 1);
    REQUIRE(double(frames[1]) == Approx(middle * rate).margin(1.0 + rate * bar->duration() / bar->width()));
    REQUIRE(bar->boundaries().size() == frames.size() - 2);
    auto gains = gainValues(design.gains());
    REQUIRE(gains.size() == gainsBefore.size() + 1);
    REQUIRE(gains[0] == gainsBefore[0]);
    REQUIRE(gains[1] == gainsBefore[0]);
    for (std::size_t p = 1; p < gainsBefore.size(); ++p) REQUIRE(gains[p + 1] == gainsBefore[p]);
    REQUIRE(table->gains().phrases.size() == gains.size());
    REQUIRE(table->table()->rowCount() == int(gains.size()));

    // Undo restores the boundaries and the gains, redo brings them back.
    document.undoStack()->undo();
    REQUIRE(design.boundaries() == framesBefore);
    REQUIRE(gainValues(design.gains()) == gainsBefore);
    REQUIRE(table->table()->rowCount() == int(gainsBefore.size()));
    document.undoStack()->redo();
    REQUIRE(design.boundaries() == frames);

    // The context menu on the new tick removes it: the halves merge back.
    std::unique_ptr<QMenu> menu(bar->createContextMenu(QPoint(bar->xOfTime(bar->boundaries()[0]), y)));
    REQUIRE(menu);
    REQUIRE(menu->actions()[0]->text() == QStringLiteral("Remove phrase boundary"));
    menu->actions()[0]->trigger();
    REQUIRE(document.undoStack()->count() == 3);
    REQUIRE(design.boundaries() == framesBefore);
    REQUIRE(gainValues(design.gains()) == gainsBefore);

    // Delete on the pressed tick: the first inner boundary goes, the merged phrase keeps the
    // gains of the longer of its two phrases.
    const QPoint first(bar->xOfTime(bar->boundaries()[0]), y);
    QTest::mousePress(bar, Qt::LeftButton, Qt::NoModifier, first);
    QTest::mouseRelease(bar, Qt::LeftButton, Qt::NoModifier, first);
    REQUIRE(document.undoStack()->count() == 3); // pressing a tick moves nothing
    QTest::keyClick(bar, Qt::Key_Delete);
    REQUIRE(document.undoStack()->count() == 4);
    frames = design.boundaries();
    REQUIRE(frames.size() == framesBefore.size() - 1);
    REQUIRE(frames[1] == framesBefore[2]);
    const bool rightLonger = framesBefore[2] - framesBefore[1] > framesBefore[1] - framesBefore[0];
    gains = gainValues(design.gains());
    REQUIRE(gains[0] == gainsBefore[rightLonger ? 1 : 0]);
    for (std::size_t p = 1; p < gains.size(); ++p) REQUIRE(gains[p] == gainsBefore[p + 1]);
    document.undoStack()->undo();
    REQUIRE(design.boundaries() == framesBefore);
    REQUIRE(gainValues(design.gains()) == gainsBefore);

    // Without the mouse: the design panel's buttons add at the time cursor and remove the nearest.
    auto* add = window->designPanel()->findChild<QPushButton*>(QStringLiteral("addBoundary"));
    auto* remove = window->designPanel()->findChild<QPushButton*>(QStringLiteral("removeBoundary"));
    REQUIRE(add);
    REQUIRE(remove);
    const Eigen::Index at = framesBefore[framesBefore.size() - 2] + 3; // inside the last phrase
    REQUIRE(at < framesBefore.back());
    document.setCurrentTime(double(at) / rate);
    add->click();
    frames = design.boundaries();
    REQUIRE(frames.size() == framesBefore.size() + 1);
    REQUIRE(frames[frames.size() - 2] == at);
    REQUIRE(table->table()->rowCount() == int(frames.size() - 1));
    add->click(); // on a boundary: nothing to add
    REQUIRE(design.boundaries() == frames);
    remove->click();
    REQUIRE(design.boundaries() == framesBefore);
    REQUIRE(gainValues(design.gains()) == gainsBefore);

    // Every inner boundary removed: one phrase, stored as such (not "suggested").
    while (design.boundaries().size() > 2) REQUIRE(design.removeBoundary(0));
    REQUIRE(design.boundaries() == std::vector<Eigen::Index>{0, framesBefore.back()});
    REQUIRE(design.gains().phrases.size() == 1);
    REQUIRE(bar->boundaries().empty());
    REQUIRE_FALSE(design.removeBoundary(0));
    REQUIRE(design.addBoundary(double(at)));
    REQUIRE(design.boundaries() == std::vector<Eigen::Index>{0, at, framesBefore.back()});
}

TEST_CASE("the extracted gains follow the phrase boundaries in use", "[app][design]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    REQUIRE(waitForDesign(*window));
    auto& design = window->design();
    auto* table = window->designPanel()->gainTable();
    const auto suggested = design.boundaries();
    const analysis::GainSet extractedBefore = design.extractedGains();
    REQUIRE(extractedBefore.phrases.size() == suggested.size() - 1);
    REQUIRE(gainValues(table->extracted()) == gainValues(extractedBefore));

    // Split the last phrase.
    const std::size_t last = suggested.size() - 2; // index of the last phrase
    const Eigen::Index split = (suggested[last] + suggested[last + 1]) / 2;
    REQUIRE(design.addBoundary(double(split)));
    const analysis::GainSet extracted = design.extractedGains();
    INFO("re-extraction took " << design.lastExtractionMilliseconds() << " ms");
    REQUIRE(extracted.phrases.size() == suggested.size());
    const auto frames = design.boundaries();
    for (std::size_t p = 0; p < extracted.phrases.size(); ++p) {
        REQUIRE(extracted.phrases[p].begin == frames[p]);
        REQUIRE(extracted.phrases[p].end == frames[p + 1]);
    }
    // Phrases before the split are extracted as before; the halves are extracted on their own.
    for (std::size_t p = 0; p < last; ++p) REQUIRE(gainValues(extracted)[p] == gainValues(extractedBefore)[p]);
    // (the demo's last phrase is ill-conditioned on every DOF, its g1 regularised to 10 in the
    // whole and in both halves: compare the first-harmonic amplitudes the gains came from)
    bool halvesDiffer = false;
    for (std::size_t d = 0; d < extracted.phrases[last].dofs.size(); ++d) {
        const double whole = extractedBefore.phrases[last].dofs[d].a1Functional;
        halvesDiffer = halvesDiffer || std::abs(extracted.phrases[last].dofs[d].a1Functional - whole) > 1e-6 ||
                       std::abs(extracted.phrases[last + 1].dofs[d].a1Functional - whole) > 1e-6;
    }
    REQUIRE(halvesDiffer);
    // The table shows them, and "Use extracted gains" uses them.
    REQUIRE(gainValues(table->extracted()) == gainValues(extracted));
    table->selectCell(int(last) + 1, 0);
    REQUIRE(table->selectionText().contains(QStringLiteral("extracted")));
    design.useExtractedGains();
    REQUIRE(gainValues(design.gains()) == gainValues(extracted));
    // Undoing the boundary goes back to the suggested phrases' extraction.
    window->document().undoStack()->undo();
    window->document().undoStack()->undo();
    REQUIRE(design.boundaries() == suggested);
    REQUIRE(gainValues(design.extractedGains()) == gainValues(extractedBefore));
    REQUIRE(gainValues(table->extracted()) == gainValues(extractedBefore));
}

TEST_CASE("on the warped designed take the ticks sit at the inverse-warped boundaries and drag back through the warp",
          "[app][design]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    REQUIRE(waitForDesign(*window));
    auto& document = window->document();
    auto& design = window->design();
    const double rate = design.functionalRateHz();
    const Eigen::Index frames = design.designedTake()->frameCount();
    // A non-identity warp over the same frames: slow start, fast end.
    analysis::WarpCurve curve = analysis::identityWarp(frames);
    const double last = double(frames - 1);
    for (auto& point : curve.points) point.source = last * std::pow(point.output / last, 1.5);
    REQUIRE(analysis::validateWarpCurve(curve).ok());
    design.editWarp(curve);
    document.selectTake(TakeSlot::A, app::TakeId::live(QStringLiteral("designed")));
    auto* bar = window->timeline()->scrubBar();
    REQUIRE(bar->boundariesEditable());
    const auto boundaries = design.boundaries();
    REQUIRE(bar->boundaries().size() == boundaries.size() - 2);
    bool moved = false;
    for (std::size_t i = 0; i < bar->boundaries().size(); ++i) {
        const double tick = bar->boundaries()[i];
        const double frame = double(boundaries[i + 1]);
        REQUIRE(tick == Approx(analysis::inverseWarp(curve, frame) / rate).margin(1e-9));
        REQUIRE(analysis::evaluateWarp(curve, tick * rate) == Approx(frame).margin(1e-6));
        moved = moved || std::abs(tick * rate - frame) > 2.0;
    }
    REQUIRE(moved); // the warp is not the identity where the ticks are

    // Dragging a tick: the boundary moves to the functional frame the designed time shows.
    const QPoint from(bar->xOfTime(bar->boundaries()[0]), bar->height() / 2);
    // To where the designed time shows three functional frames later (a fixed number of pixels
    // may stay within one frame where the warp is slow, depending on the bar's width).
    const QPoint to(bar->xOfTime(analysis::inverseWarp(curve, double(boundaries[1]) + 3.0) / rate), from.y());
    REQUIRE(to.x() > from.x());
    dragIn(bar, from, to);
    const double shown = analysis::evaluateWarp(curve, bar->timeAtX(to.x()) * rate);
    const double low = double(boundaries[0] + 1);
    const double high = double(boundaries[2] - 1);
    REQUIRE(design.boundaries()[1] == std::lround(std::clamp(shown, low, high)));
    REQUIRE(design.boundaries()[1] != boundaries[1]);
    REQUIRE(bar->boundaries()[0] == Approx(analysis::inverseWarp(curve, double(design.boundaries()[1])) / rate).margin(1e-9));

    // Adding on the designed take splits at the functional frame shown there.
    const double seconds = 0.5 * (bar->boundaries()[0] + bar->boundaries()[1]);
    QTest::mouseDClick(bar, Qt::LeftButton, Qt::NoModifier, QPoint(bar->xOfTime(seconds), bar->height() / 2));
    REQUIRE(design.boundaries().size() == boundaries.size() + 1);
    const double expected = analysis::evaluateWarp(curve, bar->timeAtX(bar->xOfTime(seconds)) * rate);
    REQUIRE(double(design.boundaries()[2]) == Approx(expected).margin(0.5 + 1e-9));
}

TEST_CASE("key steps of one gain slider are one undo step, another cell's steps another", "[app][design]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    REQUIRE(waitForDesign(*window));
    auto& document = window->document();
    auto* table = window->designPanel()->gainTable();
    REQUIRE(table->gains().phrases.size() >= 2);
    table->selectCell(1, 2);
    for (int step = 0; step < 3; ++step) QTest::keyClick(table->g1Slider(), Qt::Key_Up);
    REQUIRE(document.undoStack()->count() == 1);
    REQUIRE(table->gains().phrases[1].dofs[2].g1 == Approx(widgets::GainTable::gainOfPosition(3)));
    table->selectCell(0, 2);
    for (int step = 0; step < 2; ++step) QTest::keyClick(table->g1Slider(), Qt::Key_Up);
    REQUIRE(document.undoStack()->count() == 2);
    document.undoStack()->undo();
    REQUIRE(table->gains().phrases[0].dofs[2].g1 == 1.0);
    REQUIRE(table->gains().phrases[1].dofs[2].g1 == Approx(widgets::GainTable::gainOfPosition(3)));
    document.undoStack()->undo();
    REQUIRE(table->gains().phrases[1].dofs[2].g1 == 1.0);
}

TEST_CASE("dragging a boundary keeps phrases 2 frames long, and missing extracted gains are explained", "[app][design]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    REQUIRE(waitForDesign(*window));
    auto& design = window->design();
    const auto suggested = design.boundaries();
    REQUIRE(suggested.size() >= 3);
    // Dragged onto its left neighbour: it stops 2 frames after it, and extraction still works.
    window->document().beginInteraction();
    design.moveBoundary(0, double(suggested[0]));
    window->document().endInteraction();
    REQUIRE(design.boundaries()[1] == suggested[0] + 2);
    REQUIRE(design.extractedGains().phrases.size() == suggested.size() - 1);
    REQUIRE(design.extractionError().isEmpty());
    REQUIRE_FALSE(window->designPanel()->statusText().contains(QStringLiteral("No extracted gains")));
    // A project can still hold a 1-frame phrase: the panel says why there are no extracted gains.
    analysis::pipeline::PhraseBoundaries inner{false, {1}};
    for (std::size_t i = 2; i + 1 < suggested.size(); ++i) inner.inner.push_back(suggested[i]);
    app::changeStageParameters(window->document(), [&](app::AnalysisParameters& p) { p.design.boundaries = inner; }, QStringLiteral("test"));
    REQUIRE(design.boundaries()[1] == 1);
    REQUIRE(design.extractedGains().phrases.empty());
    REQUIRE_FALSE(design.extractionError().isEmpty());
    QTest::qWait(50);
    const QString status = window->designPanel()->statusText();
    INFO(status.toStdString());
    REQUIRE(status.contains(QStringLiteral("No extracted gains")));
}

TEST_CASE("the Design dock plots the extracted cell's approximation error per scale (Fig. 5.16)", "[app][design]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    REQUIRE(waitForDesign(*window));
    auto* plot = window->designPanel()->scaleErrorPlot();
    REQUIRE(plot);
    const auto error = window->design().approximationError();
    REQUIRE(error.scales.size() == 16);
    REQUIRE(plot->curveCount() == 7); // six axis DOF and the mean
    for (int c : {1, 8, 16}) CHECK(plot->value(6, c) == Approx(error.meanRelativeError(c - 1)));
    CHECK(plot->value(6, 16) < plot->value(6, 1));
}

TEST_CASE("the Design dock names the ill-conditioned gains, shades their cells and shows every gain legibly at 1366x768",
          "[app][design]")
{
    // The demo's design extracts from greeting/friendly, whose warp ends at functional frame 96:
    // its last phrase has A1_em ~ 0 on all 6 DOF (g1 was 100, the clamp).
    auto window = test::demoWindow();
    REQUIRE(window);
    REQUIRE(waitForDesign(*window));
    auto& design = window->design();
    window->resetLayout();
    window->resize(1366, 768);
    REQUIRE(QTest::qWaitFor([&] { return window->size() == QSize(1366, 768); }, 5000));
    window->dock("designDock")->show();
    window->dock("designDock")->raise();
    for (int pass = 0; pass < 4; ++pass) QCoreApplication::processEvents();

    const analysis::GainSet extracted = design.extractedGains();
    const auto ill = analysis::illConditionedGains(extracted);
    INFO("cell " << design.targetCell().toStdString());
    REQUIRE_FALSE(ill.empty());
    auto* panel = window->designPanel();
    auto* table = panel->gainTable();
    // The notice names each phrase with its DOF; the shaded cells are exactly the flagged ones.
    CHECK(panel->illConditionedNoticeShown());
    const QString notice = panel->illConditionedNotice();
    INFO(notice.toStdString());
    CHECK(notice.startsWith(
        QStringLiteral("Ill-conditioned g1, regularised to 10 (emotional amplitude below 10 % of the functional one): ")));
    for (const auto& gain : ill) {
        CHECK(notice.contains(QStringLiteral("phrase %1 (").arg(gain.phrase + 1)));
        CHECK(table->isIllConditioned(int(gain.phrase), int(gain.dof)));
        CHECK(table->table()->item(int(gain.phrase), int(gain.dof))->toolTip().contains(QStringLiteral("ill-conditioned")));
        CHECK(panel->findChild<QLabel*>(QStringLiteral("illConditionedNotice"))->toolTip().contains(QString::fromStdString(gain.reason)));
    }
    int shaded = 0;
    for (int p = 0; p < table->table()->rowCount(); ++p)
        for (int d = 0; d < table->table()->columnCount(); ++d) shaded += table->isIllConditioned(p, d) ? 1 : 0;
    CHECK(shaded == int(ill.size()));

    // Use extracted gains: every g1 positive, the ill-conditioned ones regularised to 10.
    design.useExtractedGains();
    const analysis::GainSet used = design.gains();
    for (const auto& phrase : used.phrases)
        for (const auto& gain : phrase.dofs) {
            CHECK(gain.g0 > 0.0);
            CHECK(gain.g1 > 0.0);
        }
    for (const auto& gain : ill) CHECK(used.phrases[gain.phrase].dofs[gain.dof].g1 == Approx(10.0));

    // Legible at 1366 pixels: every cell's numbers whole (no "1.00 / ..."), without scrolling sideways.
    for (int pass = 0; pass < 4; ++pass) QCoreApplication::processEvents();
    INFO("table " << table->table()->viewport()->width() << " px wide, column 0 " << table->table()->columnWidth(0) << " px");
    CHECK(table->table()->horizontalScrollBar()->maximum() == 0);
    for (int p = 0; p < table->table()->rowCount(); ++p)
        for (int d = 0; d < table->table()->columnCount(); ++d) {
            INFO("cell " << p << "," << d << ": " << table->table()->item(p, d)->text().toStdString());
            CHECK(table->cellTextFits(p, d));
        }
}

TEST_CASE("on the Bandai bye takes, where no extracted gain is ill-conditioned, the Design dock shows no notice", "[app][design][bandai]")
{
    const auto corpus = test::bandaiCorpusFolder({"bye_normal_001.bvh", "bye_happy_001.bvh", "bye_angry_001.bvh"},
                                                 "design_well_conditioned", "bye");
    if (corpus.empty()) return;
    auto window = test::windowOnCorpus(corpus);
    REQUIRE(window);
    REQUIRE(waitForDesign(*window));
    REQUIRE_FALSE(window->design().extractedGains().phrases.empty());
    CHECK(analysis::illConditionedGains(window->design().extractedGains()).empty());
    CHECK_FALSE(window->designPanel()->illConditionedNoticeShown());
    CHECK(window->designPanel()->illConditionedNotice().isEmpty());
}

TEST_CASE("on a whole-body corpus the Design dock designs every joint on the performer's segments", "[app][design][bandai][wholebody]")
{
    // Issue 25: the Bandai bye takes with all 22 joints; the motion axes integrate the
    // performer's segments (de Leva 1996), so the design runs on the whole body.
    const auto corpus = test::bandaiCorpusFolder({"bye_normal_001.bvh", "bye_happy_001.bvh", "bye_angry_001.bvh"},
                                                 "design_wholebody", "bye", true);
    if (corpus.empty()) return;
    auto window = test::windowOnCorpus(corpus);
    REQUIRE(window);
    auto* editor = shownWarpEditor(*window);
    INFO(window->analysis().scheduler().error(app::AnalysisController::kAxesSlot).toStdString());
    REQUIRE(editor);
    const auto before = window->design().designedTake();
    REQUIRE(before);
    CHECK(before->channels.size() == 132);
    REQUIRE(before->skeleton);
    CHECK(before->skeleton->skeleton->jointCount() == 22);
    REQUIRE_FALSE(window->design().extractedGains().phrases.empty());
    // The Normalisation dock says which coupling `auto` chose for the joints.
    REQUIRE(QTest::qWaitFor([&] { return window->normalisePanel()->summaryText().contains(QStringLiteral("normalised to")); }, 60000));
    INFO(window->normalisePanel()->summaryText().toStdString());
    CHECK(window->normalisePanel()->summaryText().contains(QStringLiteral("coupling auto (chains)")));
    // A warp drag re-times every joint: the waving hand's channels change.
    const Eigen::MatrixXd valuesBefore = before->values;
    const auto curve = editor->curve();
    REQUIRE(curve.points.size() > 4);
    const std::size_t index = curve.points.size() / 2;
    const QPoint from = editor->plot()->mapFrom(editor, editor->pointPosition(index));
    const int up = int(editor->plot()->yAxis->coordToPixel(curve.points[index].source + 3.0));
    dragIn(editor->plot(), from, QPoint(from.x(), up));
    REQUIRE(QTest::qWaitFor([&] { return window->design().designedTake() != before; }, 10000));
    const auto after = window->design().designedTake();
    REQUIRE(after->values.rows() == valuesBefore.rows());
    Eigen::Index hand = -1;
    for (std::size_t c = 0; c < after->channels.size(); ++c)
        if (after->channels[c].name() == "Hand_R.z") hand = Eigen::Index(c);
    REQUIRE(hand >= 0);
    CHECK((after->values.col(hand) - valuesBefore.col(hand)).cwiseAbs().maxCoeff() > 0.1);
    CHECK(window->document().undoStack()->count() == 1);
}

TEST_CASE("a warp drag on the designed take shown as A replaces the take, not the choice: the weighted take is kept and the views show each step",
          "[app][design]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    auto* editor = shownWarpEditor(*window);
    REQUIRE(editor);
    auto& document = window->document();
    document.selectTake(TakeSlot::A, app::TakeId::live(QStringLiteral("designed")));
    REQUIRE(waitForDesign(*window));
    document.setCurrentTime(1.0);
    const auto weighted = document.take(app::TakeId::live(QStringLiteral("weighted")));
    REQUIRE(weighted);
    auto* grid = window->graphPanel()->grid();
    const int graphs = grid->graphCount();
    REQUIRE(graphs > 0);
    QSignalSpy chosen(&document, &app::Document::selectionChanged);
    QSignalSpy replaced(&document, &app::Document::selectedTakeReplaced);
    std::vector<std::shared_ptr<const analysis::Take>> steps;
    QObject::connect(&document, &app::Document::takeChanged, [&](const app::TakeId& id) {
        if (id == QStringLiteral("live/designed")) steps.push_back(document.take(id));
    });

    const auto curve = editor->curve();
    const std::size_t index = curve.points.size() / 2;
    const QPoint from = editor->plot()->mapFrom(editor, editor->pointPosition(index));
    const int up = int(editor->plot()->yAxis->coordToPixel(curve.points[index].source + 3.0));
    dragIn(editor->plot(), from, QPoint(from.x(), up));

    REQUIRE(steps.size() >= 2);
    CHECK(chosen.count() == 0);
    CHECK(replaced.count() == int(steps.size()));
    // Its cell did not change, so neither did the weighted take (it was made again on every
    // step before, on the GUI thread).
    CHECK(document.take(app::TakeId::live(QStringLiteral("weighted"))) == weighted);
    CHECK(document.selectedTake(TakeSlot::A) == steps.back());
    // The graphs keep their layout and show the last step's values at the cursor.
    REQUIRE(grid->graphCount() == graphs);
    int checked = 0;
    for (int g = 0; g < graphs; ++g) {
        const auto& cell = grid->graphCell(g);
        if (cell.dof != "x" && cell.dof != "y" && cell.dof != "z") continue; // positions: the same in any angle display
        const auto channel = widgets::findChannel(*steps.back(), cell.part, cell.dof);
        REQUIRE(channel);
        const auto expected = widgets::valueAt(*steps.back(), *channel, document.currentTime());
        REQUIRE(expected);
        REQUIRE(grid->graphPointValue(g, 0));
        CHECK(*grid->graphPointValue(g, 0) == Approx(*expected));
        ++checked;
    }
    CHECK(checked > 0);
}
