#include "tests/app/app_test_support.h"

#include "app/emotion_panel.h"
#include "app/normalise_panel.h"
#include "app/parameters.h"
#include "app/recomputer.h"

#include <catch2/catch.hpp>

#include <QComboBox>
#include <QSlider>
#include <QSpinBox>
#include <QTableWidget>

using namespace bunraku;
using app::TakeSlot;

TEST_CASE("changing tau recomputes the normalised take in the background, undo restores it", "[app][normalise]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    auto* panel = window->normalisePanel();
    auto& document = window->document();
    REQUIRE(QTest::qWaitFor([&] { return panel->normalisedTake() && !panel->recomputer()->busy(); }, 60000));
    const auto first = panel->normalisedTake();
    REQUIRE(document.take(QStringLiteral("live/normalised")) == first);
    const auto reference = document.selectedTake(TakeSlot::A);
    REQUIRE(panel->varianceTable()->rowCount() == 5); // the cell's 5 takes
    const Eigen::MatrixXd before = first->values;

    panel->tauSpin()->setValue(0); // through the GUI: one ChangeParameter
    REQUIRE(document.parameter(app::parameters::kNormaliseTau).toInt() == 0);
    REQUIRE(QTest::qWaitFor([&] { return panel->normalisedTake() != first && !panel->recomputer()->busy(); }, 60000));
    const auto second = panel->normalisedTake();
    REQUIRE(second->frameCount() == first->frameCount());
    REQUIRE((second->values - before).cwiseAbs().maxCoeff() > 1e-6);

    document.undoStack()->undo();
    REQUIRE(panel->tauSpin()->value() == 4);
    REQUIRE(QTest::qWaitFor([&] { return panel->normalisedTake() != second && !panel->recomputer()->busy(); }, 60000));
    REQUIRE((panel->normalisedTake()->values - before).cwiseAbs().maxCoeff() < 1e-12);
}

TEST_CASE("the emotion weight slider re-synthesises y + a z live as one undo step", "[app][emotion]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    auto* panel = window->emotionPanel();
    auto& document = window->document();
    document.selectTake(TakeSlot::A, app::Document::corpusTakeId(7)); // a friendly take
    REQUIRE(QTest::qWaitFor([&] { return panel->ready() && panel->weightedTake(); }, 60000));
    const Eigen::MatrixXd atOne = panel->weightedTake()->values;

    auto* slider = panel->weightSlider();
    emit slider->sliderPressed();
    for (int position = 110; position <= 200; position += 10) slider->setValue(position);
    emit slider->sliderReleased();
    REQUIRE(document.undoStack()->count() == 1);
    REQUIRE(document.parameter(app::parameters::kEmotionWeight).toDouble() == Approx(2.0));
    const Eigen::MatrixXd atTwo = panel->weightedTake()->values;
    REQUIRE(document.take(QStringLiteral("live/weighted"))->values == atTwo);

    slider->setValue(0);
    const Eigen::MatrixXd atZero = panel->weightedTake()->values;
    // x(a) = y + a z is linear in a: x(2) - x(1) = x(1) - x(0) = z, and z is not zero.
    REQUIRE(((atTwo - atOne) - (atOne - atZero)).cwiseAbs().maxCoeff() < 1e-9);
    REQUIRE((atOne - atZero).cwiseAbs().maxCoeff() > 0.1);

    document.undoStack()->undo(); // back to a = 2
    document.undoStack()->undo(); // back to a = 1
    REQUIRE(slider->value() == 100);
    REQUIRE((panel->weightedTake()->values - atOne).cwiseAbs().maxCoeff() < 1e-12);
}

TEST_CASE("switching the emotion decomposition to KM2O with a given M changes the weighted take and undoes", "[app][emotion]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    auto* panel = window->emotionPanel();
    auto& document = window->document();
    document.selectTake(TakeSlot::A, app::Document::corpusTakeId(7)); // a friendly take
    REQUIRE(QTest::qWaitFor([&] { return panel->ready() && panel->weightedTake() && !panel->recomputer()->busy(); }, 60000));
    REQUIRE(panel->decomposedMethod() == QStringLiteral("least-squares"));
    REQUIRE_FALSE(panel->orderBox()->isEnabled());
    const auto leastSquares = panel->weightedTake();

    panel->orderBox()->setValue(3); // M alone does not re-decompose a least-squares model
    REQUIRE(document.undoStack()->count() == 1);
    REQUIRE_FALSE(panel->recomputer()->busy());
    panel->methodBox()->setCurrentIndex(panel->methodBox()->findData(QStringLiteral("km2o")));
    REQUIRE(document.undoStack()->count() == 2);
    REQUIRE(document.parameter(app::parameters::kEmotionMethod).toString() == QStringLiteral("km2o"));
    REQUIRE(panel->orderBox()->isEnabled());
    REQUIRE(QTest::qWaitFor([&] { return panel->decomposedMethod() == QStringLiteral("km2o") && !panel->recomputer()->busy(); },
                            60000));
    INFO(panel->recomputer()->lastError().toStdString());
    REQUIRE(panel->decomposedOrder() == 3); // the given M, not a search
    const auto km2o = panel->weightedTake();
    REQUIRE(km2o != leastSquares);
    REQUIRE(document.take(QStringLiteral("live/weighted")) == km2o);
    REQUIRE(km2o->frameCount() == leastSquares->frameCount());
    REQUIRE((km2o->values - leastSquares->values).cwiseAbs().maxCoeff() > 1e-6);

    panel->orderBox()->setValue(2); // another M re-decomposes
    REQUIRE(QTest::qWaitFor([&] { return panel->decomposedOrder() == 2 && !panel->recomputer()->busy(); }, 60000));
    const auto km2oTwo = panel->weightedTake();
    REQUIRE((km2oTwo->values - km2o->values).cwiseAbs().maxCoeff() > 1e-9);

    document.undoStack()->undo(); // M back to 3
    document.undoStack()->undo(); // back to least squares
    REQUIRE(panel->methodBox()->currentData().toString() == QStringLiteral("least-squares"));
    REQUIRE(QTest::qWaitFor([&] { return panel->decomposedMethod() == QStringLiteral("least-squares") && !panel->recomputer()->busy(); },
                            60000));
    REQUIRE((panel->weightedTake()->values - leastSquares->values).cwiseAbs().maxCoeff() < 1e-12);
}

TEST_CASE("consecutive steps of the M spin box are one undo step until it loses the focus", "[app][emotion]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    auto* panel = window->emotionPanel();
    auto& document = window->document();
    auto* box = panel->orderBox();
    panel->methodBox()->setCurrentIndex(panel->methodBox()->findData(QStringLiteral("km2o")));
    REQUIRE(box->isEnabled());
    box->setValue(2);
    emit box->editingFinished(); // the focus leaves: the next steps start a new undo step
    REQUIRE(document.undoStack()->count() == 2);

    for (int step = 0; step < 5; ++step) QTest::keyClick(box, Qt::Key_Up);
    REQUIRE(box->value() == 7);
    REQUIRE(document.parameter(app::parameters::kEmotionOrder).toInt() == 7);
    REQUIRE(document.undoStack()->count() == 3);
    document.undoStack()->undo(); // one Ctrl+Z: back to 2
    REQUIRE(box->value() == 2);
    REQUIRE(document.parameter(app::parameters::kEmotionOrder).toInt() == 2);
    document.undoStack()->redo();
    REQUIRE(box->value() == 7);

    // After the focus left, the next steps are a new undo step.
    emit box->editingFinished();
    QTest::keyClick(box, Qt::Key_Down);
    QTest::keyClick(box, Qt::Key_Down);
    REQUIRE(document.undoStack()->count() == 4);
    document.undoStack()->undo();
    REQUIRE(box->value() == 7);
    REQUIRE(QTest::qWaitFor([&] { return !panel->recomputer()->busy(); }, 60000));
}

TEST_CASE("steps of tau, T_cmp and the emotion weight slider merge per control", "[app][normalise][emotion]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    auto& document = window->document();
    widgets::ManualClock clock; // the key presses follow each other at once however slow the machine is
    document.setClock(&clock);
    auto* tau = window->normalisePanel()->tauSpin();
    auto* band = window->normalisePanel()->searchBandSpin();
    for (int step = 0; step < 3; ++step) QTest::keyClick(tau, Qt::Key_Up);
    REQUIRE(document.parameter(app::parameters::kNormaliseTau).toInt() == 7);
    REQUIRE(document.undoStack()->count() == 1);
    for (int step = 0; step < 4; ++step) QTest::keyClick(band, Qt::Key_Down);
    REQUIRE(document.parameter(app::parameters::kNormaliseSearchBand).toInt() == 16);
    REQUIRE(document.undoStack()->count() == 2); // another control: its own step

    auto* slider = window->emotionPanel()->weightSlider();
    for (int step = 0; step < 3; ++step) QTest::keyClick(slider, Qt::Key_Up); // Left/Right step the time
    REQUIRE(document.parameter(app::parameters::kEmotionWeight).toDouble() == Approx(1.03));
    REQUIRE(document.undoStack()->count() == 3);

    document.undoStack()->undo();
    REQUIRE(document.parameter(app::parameters::kEmotionWeight).toDouble() == 1.0);
    REQUIRE(slider->value() == 100);
    document.undoStack()->undo();
    REQUIRE(band->value() == 20);
    document.undoStack()->undo();
    REQUIRE(tau->value() == 4);
    REQUIRE(QTest::qWaitFor([&] { return !window->normalisePanel()->recomputer()->busy(); }, 60000));
}
