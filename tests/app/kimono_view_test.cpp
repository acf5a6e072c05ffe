// The kimono as cloth in the workbench (issue "The kimono", item 2): the 3D view's Cloth box and
// Cloth Settings dialog reach the scheduler's kimono jobs, the dressed view draws the cloth the
// analysis function simulates, and a project keeps the box and the settings (values outside
// their documented range are refused with the key named).
#include "tests/app/app_test_support.h"
#include "app/analysis_controller.h"
#include "app/export_controller.h"
#include "app/viewport_panel.h"
#include "widgets/graph_grid.h"
#include "widgets/graph_panel.h"

#include "analysis/body/body_description.h"
#include "analysis/cloth/kimono_cloth.h"
#include "tests/support/test_paths.h"

#include <catch2/catch.hpp>

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QTimer>

using namespace bunraku;
using app::TakeSlot;

TEST_CASE("the Cloth box and Cloth Settings dress the view and a project keeps them", "[app][kimono]")
{
    const auto dir = test::scratchDir("kimono_view");
    const QString project = QString::fromStdString((dir / "cloth.bunraku.json").string());
    {
        auto window = test::demoWindow();
        REQUIRE(window);
        app::ViewportPanel* panel = window->viewportPanel();
        REQUIRE(panel->clothBox() == window->findChild<QCheckBox*>("showCloth"));
        panel->clothBox()->setChecked(true);
        REQUIRE(test::waitUntilIdle(*window));
        REQUIRE_FALSE(panel->drawnKimonos().empty());
        REQUIRE(panel->drawnKimonos()[0]);
        const auto takeA = window->document().selectedTake(TakeSlot::A);
        const auto truth = analysis::simulateKimono(*takeA, analysis::defaultBodyDescription());
        REQUIRE(truth.ok());
        CHECK((panel->drawnKimonos()[0]->points.array() == truth->points.array()).all());
        // The measured points graphed: the "kimono" take shown as A fills the Graphs dock with
        // its 18 channels, values in cm, the moving points at the simulation's values.
        const app::TakeId original = window->document().selectedId(TakeSlot::A);
        window->document().selectTake(TakeSlot::A, app::TakeId::live(QStringLiteral("kimono")));
        widgets::GraphGrid* grid = window->graphPanel()->grid();
        REQUIRE(grid->graphCount() == 18);
        CHECK(grid->graphValueLabel(0) == QStringLiteral("cm"));
        window->document().setCurrentTime(0.0);
        const auto value = grid->graphPointValue(0, 0);
        REQUIRE(value);
        CHECK(*value == Approx(truth->points(0, 0)));
        window->document().selectTake(TakeSlot::A, original);
        REQUIRE(test::waitUntilIdle(*window));

        // The settings dialog: a softer, less damped cloth, simulated again.
        bool sawDialog = false;
        QTimer::singleShot(0, [&] {
            auto* dialog = qobject_cast<QDialog*>(QApplication::activeModalWidget());
            REQUIRE(dialog);
            CHECK(dialog->objectName() == QStringLiteral("clothSettingsDialog"));
            sawDialog = true;
            auto* damping = dialog->findChild<QDoubleSpinBox*>("damping");
            REQUIRE(damping);
            CHECK(damping->value() == 1.5);
            damping->setValue(0.25);
            dialog->findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok)->click();
        });
        CHECK(panel->editClothSettings());
        CHECK(sawDialog);
        CHECK(window->analysis().clothParameters().damping == 0.25);
        CHECK(window->exports().clothParameters().damping == 0.25); // what File > Export Take's kimono simulates
        REQUIRE(test::waitUntilIdle(*window));
        REQUIRE(panel->drawnKimonos()[0]);
        CHECK(panel->drawnKimonos()[0]->parameters.damping == 0.25);
        REQUIRE(window->files().projects().saveProject(project));
    }
    auto window = test::demoWindow();
    REQUIRE(window);
    REQUIRE(window->files().projects().openProject(project));
    CHECK(window->viewportPanel()->clothBox()->isChecked());
    CHECK(window->analysis().clothParameters().damping == 0.25);
    REQUIRE(test::waitUntilIdle(*window));
    REQUIRE(window->viewportPanel()->drawnKimonos()[0]);

    // A project whose cloth damping is outside 0..100 is refused, naming the key.
    QFile file(project);
    REQUIRE(file.open(QIODevice::ReadOnly));
    QByteArray text = file.readAll();
    file.close();
    REQUIRE(text.contains("\"damping\": 0.25"));
    text.replace("\"damping\": 0.25", "\"damping\": -3");
    const QString bad = QString::fromStdString((dir / "bad.bunraku.json").string());
    QFile out(bad);
    REQUIRE(out.open(QIODevice::WriteOnly));
    out.write(text);
    out.close();
    CHECK_FALSE(window->files().projects().openProject(bad));
    CHECK(window->files().lastError().contains(QStringLiteral("clothParameters")));
    CHECK(window->files().lastError().contains(QStringLiteral("damping")));
}
