// File > Export Take A / B: a Bandai take written as BVH on its own 22-joint skeleton, as glTF
// and as CSV; a take without a skeleton as the puppet; bad names refused. And the 3D view's
// figure per take: the skeleton drawn, a click on a bone selecting its part's graphs.
#include "app_test_support.h"
#include "tests/app/bandai_corpus_support.h"

#include "app/design_controller.h"
#include "app/export_controller.h"
#include "app/file_dialogs.h"
#include "app/viewport_panel.h"
#include "analysis/core/skeleton.h"
#include "analysis/io/bvh.h"
#include "analysis/io/take_csv.h"
#include "analysis/io/corpus_builder.h"
#include "analysis/io/corpus_io.h"
#include "tests/support/peer.h"
#include "tests/support/shared_data.h"

#include "tests/support/test_paths.h"

#include <catch2/catch.hpp>
#include "widgets/graph_panel.h"
#include "widgets/viewport_widget.h"

#include <QComboBox>
#include <QMenuBar>
#include <QSignalSpy>
#include <QTest>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

using namespace bunraku;
using app::TakeSlot;

namespace {

/// Imports two Bandai files and shows them as A and B; false (the test returns) when absent.
bool showBandaiTakes(app::MainWindow& window)
{
    const auto normal = test::bandaiDir() / "bye_normal_001.bvh", angry = test::bandaiDir() / "bye_angry_001.bvh";
    if (!test::requireBandaiData(std::filesystem::exists(normal) && std::filesystem::exists(angry)))
        return false;
    REQUIRE(window.files().imports().importTakeFile(QString::fromStdString(normal.string())));
    REQUIRE(window.files().imports().importTakeFile(QString::fromStdString(angry.string())));
    QList<app::TakeId> imported;
    for (const auto& derived : window.document().derivedTakes())
        if (derived.id.isImported()) imported << derived.id;
    REQUIRE(imported.size() == 2);
    window.document().selectTake(TakeSlot::A, imported[0]);
    window.document().selectTake(TakeSlot::B, imported[1]);
    return true;
}

/// The JSON chunk of a .glb (glTF 2.0 binary: a 12-byte header, then the JSON chunk).
nlohmann::json glbJson(const std::filesystem::path& file)
{
    const std::string bytes = bunraku::test::fileBytes(file);
    if (bytes.size() < 20 || bytes.compare(0, 4, "glTF") != 0 || bytes.compare(16, 4, "JSON") != 0) return {};
    std::uint32_t length = 0;
    std::memcpy(&length, bytes.data() + 12, 4);
    return nlohmann::json::parse(bytes.substr(20, length));
}

} // namespace

TEST_CASE("an exported designed take is named short and stable, its recipe kept in the file's metadata", "[app][export][design]")
{
    // The .glb's mesh and animation were a 63-character cut of the recipe ("designed from bow
    // functional (warp: 15 of 18 points moved; 20 p"), and so was the suggested file name.
    auto window = test::demoWindow();
    REQUIRE(window);
    REQUIRE(QTest::qWaitFor([&] { return window->design().designedTake() && !window->analysis().scheduler().busy(); }, 120000));
    auto& document = window->document();
    document.selectTake(TakeSlot::A, app::TakeId::live(QStringLiteral("designed")));
    const QString recipe = document.takeLabel(app::TakeId::live(QStringLiteral("designed")));
    const QString name = document.takeName(app::TakeId::live(QStringLiteral("designed")));
    REQUIRE(recipe.startsWith(QStringLiteral("designed from ")));
    CHECK(recipe.size() > 63);
    const std::string function = window->design().designedTake()->labels.function;
    CHECK(name == (function.empty() ? QStringLiteral("designed") : QString::fromStdString(function) + QStringLiteral(" designed")));

    // The suggested file name is the corpus and the take's name.
    const QString suggested = app::suggestedFileName(document, QStringLiteral(".glb"), app::NameParts::CorpusAndTakeA);
    CHECK(suggested == QStringLiteral("demo-") + QString(name).replace(QLatin1Char(' '), QLatin1Char('-')) + QStringLiteral(".glb"));

    const auto dir = test::scratchDir("export_names");
    REQUIRE(window->exports().exportTake(TakeSlot::A, QString::fromStdString((dir / "designed.glb").string())));
    const auto gltf = glbJson(dir / "designed.glb");
    REQUIRE(gltf.is_object());
    REQUIRE(gltf["animations"].size() == 1);
    CHECK(gltf["animations"][0]["name"] == name.toStdString());
    CHECK(gltf["scenes"][0]["name"] == name.toStdString());
    for (const auto& mesh : gltf["meshes"]) CHECK(mesh["name"] == name.toStdString());
    CHECK(gltf["scenes"][0]["extras"]["description"] == recipe.toStdString());
    CHECK(gltf["animations"][0]["extras"]["description"] == recipe.toStdString());

    // CSV: the recipe as the comment line the reader skips.
    REQUIRE(window->exports().exportTake(TakeSlot::A, QString::fromStdString((dir / "designed.csv").string())));
    const std::string csv = bunraku::test::fileBytes(dir / "designed.csv");
    CHECK(csv.rfind("# " + recipe.toStdString() + "\n", 0) == 0);
    auto read = analysis::io::readTakeCsv(dir / "designed.csv");
    REQUIRE(read.ok());
    CHECK(read->frameCount() == document.selectedTake(TakeSlot::A)->frameCount());
    // BVH: its reader takes no comments, so the file holds the motion alone and reads back.
    REQUIRE(window->exports().exportTake(TakeSlot::A, QString::fromStdString((dir / "designed.bvh").string())));
    CHECK(analysis::io::readBvh(dir / "designed.bvh").ok());

    // A corpus take: its own name, and no description.
    document.selectTake(TakeSlot::A, app::TakeId::corpus(0));
    REQUIRE(window->exports().exportTake(TakeSlot::A, QString::fromStdString((dir / "corpus.glb").string())));
    const auto corpusGltf = glbJson(dir / "corpus.glb");
    CHECK(corpusGltf["animations"][0]["name"] == document.corpus().takes[0].displayName());
    CHECK_FALSE(corpusGltf["scenes"][0].contains("extras"));
}

TEST_CASE("File > Export Take A and B write BVH on the take's skeleton, glTF and CSV", "[app][export]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    // Both actions are in the File menu.
    QStringList fileActions;
    for (QAction* menu : window->menuBar()->actions())
        if (menu->menu() && menu->text().contains(QStringLiteral("File")))
            for (QAction* action : menu->menu()->actions()) fileActions << action->objectName();
    CHECK(fileActions.contains(QStringLiteral("exportTakeAAction")));
    CHECK(fileActions.contains(QStringLiteral("exportTakeBAction")));

    const auto dir = test::scratchDir("export_controller");
    // A corpus take has no skeleton: BVH in the part layout, glTF as the modelled puppet (its
    // nine joints under a root, one mesh skinned to them with four weights per vertex).
    REQUIRE(window->exports().exportTake(TakeSlot::A, QString::fromStdString((dir / "demo.glb").string())));
    CHECK(bunraku::test::fileBytes(dir / "demo.glb").substr(0, 4) == "glTF");
    const auto demoGltf = glbJson(dir / "demo.glb");
    REQUIRE(demoGltf["skins"].size() == 1);
    CHECK(demoGltf["skins"][0]["joints"].size() == 10);
    std::set<std::string> nodes;
    for (const auto& node : demoGltf["nodes"]) nodes.insert(node.value("name", ""));
    for (const char* joint : {"puppet", "head", "shoulder", "right_hand", "left_arm", "kimono", "right_sleeve", "left_sleeve"})
        CHECK(nodes.count(joint) == 1);
    REQUIRE(demoGltf["meshes"].size() == 1);
    CHECK(demoGltf["meshes"][0]["primitives"][0]["attributes"].contains("WEIGHTS_0"));
    // A file that cannot be written is refused with its name, and nothing appears.
    CHECK_FALSE(window->exports().exportTake(TakeSlot::A, QString::fromStdString((dir / "take.fbx").string())));
    CHECK(window->exports().lastError().contains(QStringLiteral("take.fbx")));
    CHECK_FALSE(std::filesystem::exists(dir / "take.fbx"));

    if (!showBandaiTakes(*window)) return;
    const auto takeA = window->document().selectedTake(TakeSlot::A);
    const auto takeB = window->document().selectedTake(TakeSlot::B);
    REQUIRE(takeA->skeleton);
    REQUIRE(window->exports().exportTake(TakeSlot::A, QString::fromStdString((dir / "a.bvh").string())));
    REQUIRE(window->exports().exportTake(TakeSlot::B, QString::fromStdString((dir / "b.bvh").string())));
    REQUIRE(window->exports().exportTake(TakeSlot::B, QString::fromStdString((dir / "b.glb").string())));
    REQUIRE(window->exports().exportTake(TakeSlot::A, QString::fromStdString((dir / "a.csv").string())));
    auto a = analysis::io::readBvh(dir / "a.bvh");
    auto b = analysis::io::readBvh(dir / "b.bvh");
    REQUIRE(a.ok());
    REQUIRE(b.ok());
    CHECK(a->skeleton.jointCount() == 22);
    CHECK(a->motion.values.rows() == takeA->frameCount());
    CHECK(b->motion.values.rows() == takeB->frameCount());
    CHECK(a->skeleton.joints[std::size_t(a->skeleton.find("Hand_R"))].name == "Hand_R");
    CHECK(bunraku::test::fileBytes(dir / "b.glb").find("\"LowerArm_R\"") != std::string::npos); // the joints' names in the glTF's JSON
    auto csv = analysis::io::readTakeCsv(dir / "a.csv");
    REQUIRE(csv.ok());
    CHECK((csv->values - takeA->values).cwiseAbs().maxCoeff() < 1e-6);
}

TEST_CASE("the 3D view draws take A's skeleton and a click on its hand bone shows the hand's graphs", "[app][export][viewport]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    if (!showBandaiTakes(*window)) return;
    app::ViewportPanel* panel = window->viewportPanel();
    widgets::ViewportWidget* viewport = panel->viewport();
    panel->figureBox(0)->setCurrentIndex(panel->figureBox(0)->findData(int(render::FigureStyle::Skeleton)));
    panel->figureBox(1)->setCurrentIndex(panel->figureBox(1)->findData(int(render::FigureStyle::PuppetAndSkeleton)));
    CHECK(viewport->visibility().figures[0] == render::FigureStyle::Skeleton);
    CHECK(viewport->visibility().figures[1] == render::FigureStyle::PuppetAndSkeleton);
    REQUIRE_FALSE(viewport->grabFramebuffer().isNull());
    REQUIRE(viewport->renderer() != nullptr);
    CHECK(viewport->renderer()->skeletonDrawn(0));
    CHECK_FALSE(viewport->renderer()->puppetDrawn(0));
    CHECK(viewport->renderer()->puppetDrawn(1));

    // From the performer's right (the waving right hand nearest the camera), Hand_R's joint (its
    // sphere, drawn with its bone to the End Site), where the camera projects it.
    render::Camera fromRight = viewport->camera();
    fromRight.angleDeg = 180.0f;
    fromRight.elevationDeg = 0.0f;
    viewport->setCamera(fromRight);
    REQUIRE_FALSE(viewport->grabFramebuffer().isNull());
    const auto skeleton = window->document().selectedTake(TakeSlot::A)->skeleton->skeleton;
    const int hand = skeleton->find("Hand_R");
    REQUIRE(hand >= 0);
    const auto joints = viewport->renderer()->displayedJointTransforms(0, viewport->camera());
    const glm::vec3 middle = glm::vec3(joints[std::size_t(hand)][3]);
    const qreal ratio = viewport->devicePixelRatioF();
    const QSize pixels(int(viewport->width() * ratio), int(viewport->height() * ratio));
    const QPointF pixel = viewport->camera().project(middle, pixels).pixel / ratio;
    window->graphPanel()->selectPart(QStringLiteral("head"));
    QSignalSpy bones(panel, &app::ViewportPanel::bonePicked);
    QTest::mouseClick(viewport, Qt::LeftButton, Qt::NoModifier, pixel.toPoint());
    REQUIRE(bones.count() == 1);
    CHECK(bones.at(0).at(1).toString() == QStringLiteral("Hand_R"));
    CHECK(bones.at(0).at(2).toString() == QStringLiteral("hand"));
    CHECK(window->graphPanel()->selectedPart() == QStringLiteral("hand"));
}

TEST_CASE("on a whole-body corpus a bone picked in the 3D view shows that joint's graphs", "[app][wholebody][bandai]")
{
    // Issue 25: the takes' parts are the skeleton's joints; a click on Hand_R selects Hand_R's
    // graphs (a puppet take's click selects the part the joint drives, as above).
    const auto corpus = test::bandaiCorpusFolder({"bye_normal_001.bvh", "bye_happy_001.bvh", "bye_angry_001.bvh"},
                                                 "pick_wholebody", "bye", true);
    if (corpus.empty()) return;
    auto window = test::windowOnCorpus(corpus);
    REQUIRE(window);
    const auto take = window->document().selectedTake(TakeSlot::A);
    REQUIRE(take);
    REQUIRE(take->channels.size() == 132);
    app::ViewportPanel* panel = window->viewportPanel();
    widgets::ViewportWidget* viewport = panel->viewport();
    QSignalSpy errors(viewport, &widgets::ViewportWidget::renderError);
    panel->figureBox(0)->setCurrentIndex(panel->figureBox(0)->findData(int(render::FigureStyle::Skeleton)));
    REQUIRE_FALSE(viewport->grabFramebuffer().isNull());
    INFO((errors.isEmpty() ? QString() : errors.front().front().toString()).toStdString());
    CHECK(errors.isEmpty());
    render::Camera fromRight = viewport->camera();
    fromRight.angleDeg = 180.0f;
    fromRight.elevationDeg = 0.0f;
    viewport->setCamera(fromRight);
    REQUIRE_FALSE(viewport->grabFramebuffer().isNull());
    REQUIRE(viewport->renderer() != nullptr);
    const int hand = take->skeleton->skeleton->find("Hand_R");
    REQUIRE(hand >= 0);
    CHECK(viewport->renderer()->skeletonDrawn(0));
    const auto joints = viewport->renderer()->displayedJointTransforms(0, viewport->camera());
    REQUIRE(joints.size() > std::size_t(hand));
    const glm::vec3 middle = glm::vec3(joints[std::size_t(hand)][3]);
    const qreal ratio = viewport->devicePixelRatioF();
    const QSize pixels(int(viewport->width() * ratio), int(viewport->height() * ratio));
    const QPointF pixel = viewport->camera().project(middle, pixels).pixel / ratio;
    window->graphPanel()->selectPart(QStringLiteral("Head"));
    REQUIRE(window->graphPanel()->selectedPart() == QStringLiteral("Head"));
    QSignalSpy bones(panel, &app::ViewportPanel::bonePicked);
    QTest::mouseClick(viewport, Qt::LeftButton, Qt::NoModifier, pixel.toPoint());
    REQUIRE(bones.count() == 1);
    CHECK(bones.at(0).at(1).toString() == QStringLiteral("Hand_R"));
    CHECK(window->graphPanel()->selectedPart() == QStringLiteral("Hand_R"));
}

TEST_CASE("a timing designed on a corpus of Bandai waves exports on the performer's 22-joint skeleton", "[app][export][design]")
{
    // File > New Corpus from Files (the same builder), the Design dock's designed take shown as
    // A, File > Export Take A as BVH.
    std::vector<std::filesystem::path> files;
    for (const char* style : {"normal", "active"})
        for (int k = 1; k <= 3; ++k) files.push_back(test::bandaiDir() / ("wave-right-hand_" + std::string(style) + "_00" + std::to_string(k) + ".bvh"));
    const bool present = std::all_of(files.begin(), files.end(), [](const auto& f) { return std::filesystem::exists(f); });
    if (!test::requireBandaiData(present))
        return;
    auto sources = analysis::io::labelTakeFiles(files, "{function}_{emotion}_{take}");
    REQUIRE(sources.ok());
    analysis::io::CorpusBuildOptions options;
    options.import.bvh.guessUnits = true;
    options.name = "waves";
    auto built = analysis::io::buildCorpus(*sources, options);
    REQUIRE(built.ok());
    const auto dir = test::scratchDir("export_designed_waves");
    REQUIRE(analysis::io::writeCorpus(built->corpus, dir / "corpus").ok());

    auto window = test::demoWindow();
    REQUIRE(window);
    REQUIRE(window->files().corpora().openCorpusFolder(QString::fromStdString((dir / "corpus").string())));
    REQUIRE(QTest::qWaitFor([&] { return window->design().ready() && !window->analysis().scheduler().busy(); }, 120000));
    const auto designed = window->design().designedTake();
    REQUIRE(designed);
    REQUIRE(designed->skeleton); // the functional take's whole skeleton, at the designed timing
    window->document().selectTake(TakeSlot::A, app::TakeId::live(QStringLiteral("designed")));
    REQUIRE(window->exports().exportTake(TakeSlot::A, QString::fromStdString((dir / "designed.bvh").string())));
    auto file = analysis::io::readBvh(dir / "designed.bvh");
    REQUIRE(file.ok());
    CHECK(file->skeleton.jointCount() == 22);
    CHECK(file->motion.values.rows() == designed->frameCount());
    CHECK(file->skeleton.joints[std::size_t(file->skeleton.find("Hand_R"))].name == "Hand_R");
}

TEST_CASE("File > Export Take A with the kimono writes the simulated cloth into the glb and the csv", "[app][export][kimono]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    const auto dir = test::scratchDir("export_controller_kimono");
    auto& exports = window->exports();
    // The command line's defaults until the view's cloth settings are handed over.
    CHECK(exports.clothParameters().drag == analysis::ClothParameters{}.drag);
    REQUIRE(exports.exportTake(TakeSlot::A, QString::fromStdString((dir / "kimono.glb").string()), true));
    const auto gltf = glbJson(dir / "kimono.glb");
    REQUIRE(gltf["meshes"].size() == 2); // the figure, then the cloth
    int cloth = -1;
    for (std::size_t n = 0; n < gltf["nodes"].size(); ++n)
        if (gltf["nodes"][n].value("name", "") == "kimono_cloth") cloth = int(n);
    REQUIRE(cloth >= 0);
    bool weights = false;
    for (const auto& channel : gltf["animations"][0]["channels"])
        weights = weights || (channel["target"]["node"] == cloth && channel["target"]["path"] == "weights");
    CHECK(weights);
    const std::size_t frames = std::size_t(window->document().selectedTake(TakeSlot::A)->frameCount());
    CHECK(gltf["meshes"][1]["primitives"][0]["targets"].size() == frames - 1);
    CHECK(window->exports().lastError().isEmpty());

    // Other cloth parameters move the cloth elsewhere; a .csv gets the 18 channels; a .bvh is refused.
    analysis::ClothParameters stiff;
    stiff.drag = 20.0;
    exports.setClothParameters(stiff);
    REQUIRE(exports.exportTake(TakeSlot::A, QString::fromStdString((dir / "stiff.glb").string()), true));
    CHECK(bunraku::test::fileBytes(dir / "stiff.glb") != bunraku::test::fileBytes(dir / "kimono.glb"));
    REQUIRE(exports.exportTake(TakeSlot::A, QString::fromStdString((dir / "kimono.csv").string()), true));
    auto csv = analysis::io::readTakeCsv(dir / "kimono.csv");
    REQUIRE(csv.ok());
    CHECK(csv->channelCount() == window->document().selectedTake(TakeSlot::A)->channelCount() + 18);
    CHECK_FALSE(exports.exportTake(TakeSlot::A, QString::fromStdString((dir / "kimono.bvh").string()), true));
    CHECK(exports.lastError().contains(QStringLiteral("cannot hold the kimono")));
    CHECK_FALSE(std::filesystem::exists(dir / "kimono.bvh"));
}
