// The 3D view's "File's mesh" figure in the workbench: offered for a take whose file carries a
// skinned mesh (here a .glb the workbench itself writes: the performer's body skinned to a
// fixture skeleton), reaching the view when chosen, kept by a saved project (figureA 4) that
// re-reads the file, and falling back to the skeleton - with a line saying so - for a take
// without one.
#include "tests/app/app_test_support.h"
#include "app/viewport_panel.h"

#include "analysis/body/body_description.h"
#include "analysis/core/skeleton.h"
#include "analysis/core/skeleton_mesh.h"
#include "analysis/io/bvh_import.h"
#include "analysis/io/take_reader.h"
#include "render/take_export.h"
#include "tests/support/bvh_fixtures.h"
#include "tests/support/shared_data.h"
#include "tests/support/test_paths.h"
#include "widgets/viewport_widget.h"

#include <catch2/catch.hpp>

#include <QComboBox>
#include <QLabel>
#include <QImage>
#include <QStandardItemModel>

#include <cstdlib>
#include <sys/wait.h>

using namespace bunraku;
using app::TakeSlot;

namespace {

bool meshItemEnabled(QComboBox* box)
{
    auto* model = qobject_cast<QStandardItemModel*>(box->model());
    REQUIRE(model != nullptr);
    return model->item(box->findData(int(render::FigureStyle::FileMesh)))->isEnabled();
}

} // namespace

TEST_CASE("the File's mesh figure is offered for a take whose file carries one and a project keeps it", "[app][mesh]")
{
    const auto dir = test::scratchDir("file_mesh_figure");
    const auto family = test::bvhFamilies().front();
    auto bvh = analysis::io::parseBvh(test::fixtureBvh(family, 12), family.id + ".bvh");
    REQUIRE(bvh.ok());
    analysis::io::BvhImportOptions options;
    options.guessUnits = true;
    auto take = analysis::io::bvhToPuppetTake(*bvh, options);
    REQUIRE(take.ok());
    const auto glb = dir / "character.glb";
    REQUIRE(render::exportTake(*take, analysis::defaultBodyDescription(), glb).ok());
    const QString project = QString::fromStdString((dir / "mesh.bunraku.json").string());
    {
        auto window = test::demoWindow();
        REQUIRE(window);
        QComboBox* figure = window->viewportPanel()->figureBox(0);
        const int mesh = figure->findData(int(render::FigureStyle::FileMesh));
        REQUIRE(mesh == 4);
        CHECK(figure->itemText(mesh) == QStringLiteral("File's mesh"));
        CHECK_FALSE(meshItemEnabled(figure)); // a demo take: no file, no mesh
        // The round trip keeps the moving joints (the fixture's still head and hands are End Sites).
        const bool imported = window->files().imports().importTakeFile(QString::fromStdString(glb.string()),
                                                             QStringLiteral("head=Neck,shoulder=Chest,arm=UpperArm_R,hand=LowerArm_R"));
        INFO(window->files().lastError().toStdString());
        REQUIRE(imported);
        const auto shown = window->document().selectedTake(TakeSlot::A);
        REQUIRE(shown);
        REQUIRE(shown->skeleton);
        REQUIRE(shown->skeleton->skeleton->mesh);
        CHECK(shown->skeleton->skeleton->mesh->vertexCount() > 500);
        CHECK(meshItemEnabled(figure));
        figure->setCurrentIndex(mesh);
        CHECK(window->viewportPanel()->viewport()->visibility().figures[0] == render::FigureStyle::FileMesh);
        REQUIRE(window->files().projects().saveProject(project));
    }
    auto window = test::demoWindow();
    REQUIRE(window);
    REQUIRE(window->files().projects().openProject(project));
    QComboBox* figure = window->viewportPanel()->figureBox(0);
    CHECK(figure->currentIndex() == 4);
    const auto shown = window->document().selectedTake(TakeSlot::A);
    REQUIRE(shown);
    REQUIRE(shown->skeleton);
    CHECK(shown->skeleton->skeleton->mesh); // the project re-read the file: its mesh is back
    CHECK(meshItemEnabled(figure));
    CHECK(window->viewportPanel()->viewport()->visibility().figures[0] == render::FigureStyle::FileMesh);
    // A take without a mesh: the skeleton (or its puppet), and the view says why.
    window->document().selectTake(TakeSlot::A, app::TakeId::corpus(3));
    CHECK_FALSE(meshItemEnabled(figure));
    CHECK(window->viewportPanel()->viewport()->visibility().figures[0] == render::FigureStyle::Skeleton);
    auto* label = window->findChild<QLabel*>("skeletonGap");
    REQUIRE(label != nullptr);
    CHECK(label->text().contains(QStringLiteral("carries no skinned mesh")));
}

TEST_CASE("bunraku-workbench --figure mesh shows the file's mesh of a Bandai take's glTF", "[app][mesh]")
{
    const auto source = test::bandaiDir() / "bye_angry_001.bvh";
    if (!test::requireBandaiData(std::filesystem::exists(source))) return;
    const auto dir = test::scratchDir("workbench_figure_mesh");
    auto take = analysis::io::readTakeFile(source);
    REQUIRE(take.ok());
    const auto glb = dir / "bye_angry_001.glb";
    REQUIRE(render::exportTake(*take, analysis::defaultBodyDescription(), glb).ok());
    const auto run = [&](const std::string& figure) {
        const auto png = dir / (figure + ".png");
        const std::string command = "'" + std::string(BUNRAKU_WORKBENCH) + "' '" + glb.string() + "' --figure " + figure +
                                    " --default-layout --screenshot '" + png.string() + "' >/dev/null 2>'" + (dir / "err.txt").string() +
                                    "' </dev/null";
        const int status = std::system(command.c_str());
        INFO(figure << ": " << test::fileBytes(dir / "err.txt"));
        REQUIRE(WIFEXITED(status));
        REQUIRE(WEXITSTATUS(status) == 0);
        return QImage(QString::fromStdString(png.string()));
    };
    const QImage mesh = run("mesh");
    const QImage skeleton = run("skeleton");
    REQUIRE(!mesh.isNull());
    REQUIRE(mesh.size() == skeleton.size());
    CHECK(mesh != skeleton);
}
