// Keys and files as a person meets them: focus returns to the window once a control is set, so
// Space plays (unless a text is being typed) and Home goes to the start (or resets the camera in
// the focused 3D view); F frames the view; Help > Keyboard Shortcuts lists the keys; file
// dialogs start in the folder last used for their purpose with a name made of what is shown;
// projects bring back the graphs' part and DOF and the camera.
#include "tests/app/app_test_support.h"

#include "app/normalise_panel.h"

#include "app/analysis_controller.h"
#include "app/file_dialogs.h"
#include "app/playback_controller.h"
#include "app/shortcuts_dialog.h"
#include "app/video_export_dialog.h"
#include "app/viewport_panel.h"

#include "widgets/graph_panel.h"
#include "widgets/timeline_widget.h"
#include "widgets/viewport_widget.h"

#include <catch2/catch.hpp>

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QStandardPaths>
#include <QStyle>
#include <QStyleOptionSpinBox>
#include <QTableWidget>
#include <QTimer>
#include <QTreeWidget>
#include <QWheelEvent>

#include <set>

using namespace bunraku;

namespace {

/// Stands in for every file dialog while it lives: records what each one was asked (its purpose
/// and the path it would start at) and answers `answer` ("" = cancelled).
struct RecordedChooser {
    std::vector<std::pair<app::FilePurpose, QString>> asked;
    QString answer;
    RecordedChooser()
    {
        app::setFileChooser([this](app::FilePurpose purpose, const QString& start) {
            asked.emplace_back(purpose, start);
            return answer;
        });
    }
    ~RecordedChooser() { app::setFileChooser({}); }
    RecordedChooser(const RecordedChooser&) = delete;
    RecordedChooser& operator=(const RecordedChooser&) = delete;
};

/// Presses `key` where the keyboard focus is (the window when nothing has it), as a keyboard would.
void press(app::MainWindow& window, Qt::Key key, Qt::KeyboardModifiers modifiers = Qt::NoModifier)
{
    QWidget* focus = QApplication::focusWidget();
    QTest::keyClick(focus ? focus : &window, key, modifiers);
}

/// Lets deferred work (the focus returning) run.
void settle()
{
    for (int pass = 0; pass < 3; ++pass) QCoreApplication::processEvents();
}

bool focusInside(const QWidget* widget)
{
    const QWidget* focus = QApplication::focusWidget();
    return focus && (focus == widget || widget->isAncestorOf(focus));
}

QAction* menuAction(app::MainWindow& window, const QString& text)
{
    for (QAction* action : window.findChildren<QAction*>())
        if (action->text().remove(QLatin1Char('&')).startsWith(text)) return action;
    return nullptr;
}

} // namespace

TEST_CASE("two clicks on a spin box's arrow merge into one undo step though the focus returns after each", "[app][keys][focus][undo]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    window->activateWindow();
    REQUIRE(QTest::qWaitForWindowActive(window.get()));
    auto& document = window->document();
    qint64 now = 0;
    document.setClock([&now] { return now; });
    auto* tau = window->normalisePanel()->tauSpin();
    window->dock("normaliseDock")->raise();
    settle();
    REQUIRE(tau->isVisible());
    QStyleOptionSpinBox option;
    option.initFrom(tau);
    option.subControls = QStyle::SC_SpinBoxUp;
    const QPoint up = tau->style()->subControlRect(QStyle::CC_SpinBox, &option, QStyle::SC_SpinBoxUp, tau).center();
    const int before = document.undoStack()->count();
    QTest::mouseClick(tau, Qt::LeftButton, Qt::NoModifier, up);
    settle();
    CHECK_FALSE(focusInside(tau)); // the keys went back to the window
    now += 300;
    QTest::mouseClick(tau, Qt::LeftButton, Qt::NoModifier, up);
    settle();
    CHECK(tau->value() == 6);
    CHECK(document.undoStack()->count() == before + 1);
    CHECK(document.undoStack()->undoText() == QStringLiteral("Set tau to 6 frames"));
    // Later, typed and entered: its own step; Enter ends the series, so a click 300 ms after it
    // is its own step too.
    now += 2000;
    auto* text = tau->findChild<QLineEdit*>();
    REQUIRE(text);
    QTest::mouseClick(text, Qt::LeftButton, Qt::NoModifier, text->rect().center());
    settle();
    tau->selectAll();
    QTest::keyClicks(text, QStringLiteral("8"));
    QTest::keyClick(text, Qt::Key_Return);
    settle();
    CHECK(tau->value() == 8);
    now += 300;
    QTest::mouseClick(tau, Qt::LeftButton, Qt::NoModifier, up);
    settle();
    CHECK(tau->value() == 9);
    CHECK(document.undoStack()->count() == before + 3);
}

TEST_CASE("after a control is set the focus returns to the window and Space plays", "[app][keys][focus]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    window->activateWindow();
    REQUIRE(QTest::qWaitForWindowActive(window.get()));
    auto& playback = window->playback();
    auto* speed = window->timeline()->speedBox();

    // The speed box's up arrow: the speed changes and the box does not keep the focus.
    QStyleOptionSpinBox option;
    option.initFrom(speed);
    option.subControls = QStyle::SC_SpinBoxUp;
    const QRect up = speed->style()->subControlRect(QStyle::CC_SpinBox, &option, QStyle::SC_SpinBoxUp, speed);
    QTest::mouseClick(speed, Qt::LeftButton, Qt::NoModifier, up.center());
    settle();
    CHECK(speed->value() == Approx(1.1));
    CHECK_FALSE(focusInside(speed));
    press(*window, Qt::Key_Space);
    CHECK(playback.playing());
    press(*window, Qt::Key_Space);
    CHECK_FALSE(playback.playing());

    // Typing into it: Space goes to the text, not to playback; Enter sets it and gives the keys back.
    auto* text = speed->findChild<QLineEdit*>();
    REQUIRE(text != nullptr);
    QTest::mouseClick(text, Qt::LeftButton, Qt::NoModifier, text->rect().center());
    settle();
    REQUIRE(focusInside(speed));
    speed->selectAll();
    QTest::keyClicks(text, QStringLiteral("2"));
    press(*window, Qt::Key_Space);
    CHECK_FALSE(playback.playing());
    press(*window, Qt::Key_Return);
    settle();
    CHECK(speed->value() == Approx(2.0));
    CHECK_FALSE(focusInside(speed));
    press(*window, Qt::Key_Space);
    CHECK(playback.playing());
    press(*window, Qt::Key_Space);

    // A check box clicked, a take clicked in the corpus tree: Space still plays.
    auto* partner = window->findChild<QCheckBox*>("showPartner");
    REQUIRE(partner != nullptr);
    QTest::mouseClick(partner, Qt::LeftButton, Qt::NoModifier, QPoint(6, partner->height() / 2));
    settle();
    CHECK_FALSE(partner->isChecked());
    press(*window, Qt::Key_Space);
    CHECK(playback.playing());
    press(*window, Qt::Key_Space);
    auto* tree = window->findChild<QTreeWidget*>("corpusTree");
    REQUIRE(tree != nullptr);
    QTest::mouseClick(tree->viewport(), Qt::LeftButton, Qt::NoModifier, tree->visualItemRect(tree->topLevelItem(0)).center());
    press(*window, Qt::Key_Space);
    CHECK(playback.playing());
    press(*window, Qt::Key_Space);
    CHECK_FALSE(playback.playing());
}

TEST_CASE("Home resets the camera in the focused 3D view and goes to the start elsewhere, F frames the view", "[app][keys][camera]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    window->activateWindow();
    REQUIRE(QTest::qWaitForWindowActive(window.get()));
    auto& document = window->document();
    auto* viewport = window->viewportPanel()->viewport();
    (void)viewport->grabFramebuffer(); // the scene uploaded and framed
    // The first view at the view's size now (the docks may have widened it since the first paint).
    viewport->resetCamera();
    const render::Camera first = viewport->camera();

    // Orbit with the mouse (the view takes the focus), then Home: the camera, not the time.
    document.setCurrentTime(2.0);
    const QPoint centre = viewport->rect().center();
    QTest::mousePress(viewport, Qt::LeftButton, Qt::NoModifier, centre);
    for (int step = 1; step <= 5; ++step) {
        QMouseEvent move(QEvent::MouseMove, QPointF(centre + QPoint(20 * step, 0)), viewport->mapToGlobal(QPointF(centre + QPoint(20 * step, 0))),
                         Qt::NoButton, Qt::LeftButton, Qt::NoModifier);
        QCoreApplication::sendEvent(viewport, &move);
    }
    QTest::mouseRelease(viewport, Qt::LeftButton, Qt::NoModifier, centre + QPoint(100, 0));
    QWheelEvent wheel(QPointF(centre), viewport->mapToGlobal(QPointF(centre)), QPoint(), QPoint(0, 480), Qt::NoButton, Qt::NoModifier,
                      Qt::NoScrollPhase, false);
    QCoreApplication::sendEvent(viewport, &wheel); // zoomed in
    REQUIRE(viewport->camera().angleDeg != Approx(first.angleDeg));
    REQUIRE(viewport->camera().distance < 0.8f * first.distance);
    viewport->setFocus();
    press(*window, Qt::Key_Home);
    CHECK(viewport->camera().angleDeg == Approx(first.angleDeg));
    CHECK(viewport->camera().elevationDeg == Approx(first.elevationDeg));
    // (The view may have been resized or the motion axis added since the first framing.)
    CHECK(viewport->camera().distance == Approx(first.distance).epsilon(0.05));
    CHECK(document.currentTime() == Approx(2.0));

    // F anywhere: Frame All (the partner marker included: farther than the figures' framing).
    window->setFocus();
    press(*window, Qt::Key_F);
    CHECK(viewport->camera().distance > first.distance);
    // Shift+F after clicking the head: the head fills the view.
    (void)viewport->grabFramebuffer();
    const glm::mat4 world_T_head = viewport->renderer()->displayedPartTransforms(0, viewport->camera())[0];
    const QSize pixels(viewport->width(), viewport->height());
    const QPoint head = viewport->camera().project(glm::vec3(world_T_head[3]), pixels).pixel.toPoint();
    QTest::mouseClick(viewport, Qt::LeftButton, Qt::NoModifier, head);
    REQUIRE(window->viewportPanel()->selectedPart() == QStringLiteral("head"));
    press(*window, Qt::Key_F, Qt::ShiftModifier);
    CHECK(viewport->camera().distance < 0.6f * first.distance);

    // Home with the focus elsewhere: the start.
    window->setFocus();
    press(*window, Qt::Key_Home);
    CHECK(document.currentTime() == 0.0);
}

TEST_CASE("Help > Keyboard Shortcuts lists every key of the window, none used twice", "[app][keys][help]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    QAction* shortcuts = window->findChild<QAction*>("keyboardShortcutsAction");
    REQUIRE(shortcuts != nullptr);
    // The Help menu holds it.
    bool inHelp = false;
    for (QAction* menu : window->menuBar()->actions())
        if (menu->menu() && menu->text().remove(QLatin1Char('&')) == QStringLiteral("Help"))
            inHelp = menu->menu()->actions().contains(shortcuts);
    CHECK(inHelp);

    app::ShortcutsDialog dialog(*window);
    CHECK(dialog.keysOf(QStringLiteral("Play")) == QStringLiteral("Space"));
    CHECK(dialog.keysOf(QStringLiteral("Go to start")) == QStringLiteral("Home"));
    CHECK(dialog.keysOf(QStringLiteral("Frame All")) == QStringLiteral("F"));
    CHECK(dialog.keysOf(QStringLiteral("Frame Selected")) == QStringLiteral("Shift+F"));
    CHECK(dialog.keysOf(QStringLiteral("Reset Camera")).startsWith(QStringLiteral("Home")));
    CHECK(dialog.keysOf(QStringLiteral("Undo")) == QStringLiteral("Ctrl+Z"));
    CHECK(dialog.keysOf(QStringLiteral("Save Project")) == QStringLiteral("Ctrl+S"));
    CHECK(dialog.keysOf(QStringLiteral("Keyboard Shortcuts")) == QStringLiteral("Ctrl+/"));
    // Filtering by a key leaves the rows that use it.
    dialog.filter()->setText(QStringLiteral("Shift+F"));
    int shown = 0;
    for (int row = 0; row < dialog.table()->rowCount(); ++row) shown += dialog.table()->isRowHidden(row) ? 0 : 1;
    CHECK(shown == 1);

    // No key is bound to two window-wide actions.
    std::set<QString> keys;
    for (QAction* action : window->findChildren<QAction*>()) {
        if (action->shortcutContext() != Qt::WindowShortcut) continue;
        for (const QKeySequence& key : action->shortcuts()) {
            INFO(action->text().toStdString() << ": " << key.toString().toStdString());
            CHECK(keys.insert(key.toString()).second);
        }
    }

    // The menu item opens the dialog.
    bool opened = false;
    QTimer::singleShot(0, window.get(), [&] {
        if (auto* modal = qobject_cast<app::ShortcutsDialog*>(QApplication::activeModalWidget())) {
            opened = modal->table()->rowCount() > 20;
            modal->reject();
        }
    });
    shortcuts->trigger();
    CHECK(opened);
}

TEST_CASE("file dialogs start in the folder last used for their purpose, with a suggested name", "[app][files]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    const auto root = test::scratchDir("file-dialogs");
    const QString shots = QString::fromStdString((root / "shots").string());
    const QString reports = QString::fromStdString((root / "reports").string());
    QDir().mkpath(shots);
    QDir().mkpath(reports);
    QSettings().remove(QStringLiteral("folders"));
    RecordedChooser chooser;
    auto& asked = chooser.asked;
    auto& answer = chooser.answer;

    // First screenshot: the home folder (nothing chosen yet), named after the corpus and take A.
    const QString takeA = window->document().takeLabel(window->document().selectedId(app::TakeSlot::A));
    const QString name = QStringLiteral("demo-") + QString(takeA).replace(QLatin1Char('/'), QLatin1Char('-')) + QStringLiteral(".png");
    answer = shots + QStringLiteral("/first.png");
    menuAction(*window, QStringLiteral("Save Screenshot"))->trigger();
    REQUIRE(asked.size() == 1);
    CHECK(asked.back().first == app::FilePurpose::Screenshot);
    CHECK(asked.back().second == QDir(QDir::homePath()).filePath(name));
    CHECK(QFileInfo::exists(answer));

    // The report: a folder never chosen for it starts where the person last was, then its own.
    answer = reports + QStringLiteral("/demo-report.html");
    menuAction(*window, QStringLiteral("Export Report"))->trigger();
    CHECK(asked.back().second == shots + QStringLiteral("/demo-report.html"));
    // The next screenshot goes back to the screenshots' folder, named after the take shown now.
    window->document().selectTake(app::TakeSlot::A, app::TakeId::corpus(7));
    const QString other = window->document().takeLabel(app::TakeId::corpus(7)).replace(QLatin1Char('/'), QLatin1Char('-'));
    answer.clear(); // cancelled
    menuAction(*window, QStringLiteral("Save Screenshot"))->trigger();
    CHECK(asked.back().second == shots + QStringLiteral("/demo-") + other + QStringLiteral(".png"));
    CHECK(app::rememberedFolder(app::FilePurpose::Report) == reports);

    // The video: not a ~/Videos the person never went to; the folder last used, a name of what is
    // shown. As MP4: a video export of an earlier case in this process may have left PNG frames as
    // the remembered format.
    QSettings().remove(QStringLiteral("videoExport"));
    app::VideoExportDialog dialog(app::VideoExportLimits{20, 5.0, QSize(320, 240)}, window.get());
    dialog.suggestOutput(app::suggestedFileName(window->document(), {}));
    const QString video = dialog.options().output;
    CHECK(QFileInfo(video).absolutePath() == reports);
    CHECK(QFileInfo(video).fileName() == QStringLiteral("demo-") + other + QStringLiteral(".mp4"));
    CHECK_FALSE(video.startsWith(QStandardPaths::writableLocation(QStandardPaths::MoviesLocation)));
}

TEST_CASE("File > Export Take A (Ctrl+E) suggests a name from the take and opens where the last export went", "[app][files][export]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    const auto root = test::scratchDir("export-take-dialog");
    const QString first = QString::fromStdString((root / "first").string());
    QDir().mkpath(first);
    QSettings().remove(QStringLiteral("folders"));
    RecordedChooser chooser;
    auto& asked = chooser.asked;
    auto& answer = chooser.answer;
    const auto named = [&](int take) {
        return QStringLiteral("demo-") + window->document().takeLabel(app::TakeId::corpus(take)).replace(QLatin1Char('/'), QLatin1Char('-')) +
               QStringLiteral(".bvh");
    };
    window->document().selectTake(app::TakeSlot::A, app::TakeId::corpus(3));
    // Ctrl+E, as a user presses it.
    window->activateWindow();
    REQUIRE(QTest::qWaitForWindowActive(window.get()));
    answer = first + QStringLiteral("/mine.bvh");
    press(*window, Qt::Key_E, Qt::ControlModifier);
    REQUIRE(asked.size() == 1);
    CHECK(asked.back().first == app::FilePurpose::ExportTake);
    CHECK(asked.back().second == QDir(QDir::homePath()).filePath(named(3))); // nothing chosen yet: home, a name of the take
    CHECK(QFileInfo::exists(answer));
    // The second export starts in the folder of the first, named after the take shown now.
    window->document().selectTake(app::TakeSlot::A, app::TakeId::corpus(5));
    answer.clear(); // cancelled: nothing written
    press(*window, Qt::Key_E, Qt::ControlModifier);
    REQUIRE(asked.size() == 2);
    CHECK(asked.back().second == first + QLatin1Char('/') + named(5));
    // A screenshot meanwhile does not move the exports' folder.
    const QString shots = QString::fromStdString((root / "shots").string());
    QDir().mkpath(shots);
    answer = shots + QStringLiteral("/shot.png");
    menuAction(*window, QStringLiteral("Save Screenshot"))->trigger();
    answer.clear();
    window->exports().exportAction(app::TakeSlot::B)->trigger();
    CHECK(asked.back().first == app::FilePurpose::ExportTake);
    CHECK(QFileInfo(asked.back().second).absolutePath() == first);
}

TEST_CASE("a project brings back the graphs' part and DOF, the camera and the emotion picked", "[app][files][project]")
{
    const auto folder = test::scratchDir("project-view");
    const QString file = QString::fromStdString((folder / "view.bunraku.json").string());
    render::Camera saved;
    {
        auto window = test::demoWindow();
        REQUIRE(window);
        window->graphPanel()->setGraphLayout(widgets::GraphLayout::Single);
        window->graphPanel()->selectPart(QStringLiteral("hand"));
        window->graphPanel()->selectDof(QStringLiteral("pitch"));
        auto* viewport = window->viewportPanel()->viewport();
        (void)viewport->grabFramebuffer();
        render::Camera camera = viewport->camera();
        camera.angleDeg = 123.0f;
        camera.elevationDeg = 33.0f;
        camera.distance = 321.0f;
        camera.target = {5.0f, -7.0f, 60.0f};
        viewport->setCamera(camera);
        saved = camera;
        window->analysis().setWeightEmotion(QStringLiteral("hostile"));
        REQUIRE(window->files().projects().saveProject(file));
    }
    auto window = test::demoWindow();
    REQUIRE(window);
    REQUIRE(window->files().projects().openProject(file));
    CHECK(window->graphPanel()->grid()->graphLayout() == widgets::GraphLayout::Single);
    CHECK(window->graphPanel()->selectedPart() == QStringLiteral("hand"));
    CHECK(window->graphPanel()->selectedDof() == QStringLiteral("pitch"));
    REQUIRE(window->graphPanel()->grid()->graphCount() == 1);
    CHECK(window->graphPanel()->grid()->graphCell(0).dof == "pitch");
    auto* viewport = window->viewportPanel()->viewport();
    (void)viewport->grabFramebuffer(); // the project's scene shown: the camera stays as saved
    CHECK(viewport->camera().angleDeg == Approx(saved.angleDeg));
    CHECK(viewport->camera().elevationDeg == Approx(saved.elevationDeg));
    CHECK(viewport->camera().distance == Approx(saved.distance));
    CHECK(viewport->camera().target.x == Approx(saved.target.x));
    CHECK(viewport->camera().target.z == Approx(saved.target.z));
    CHECK(window->analysis().weightEmotion() == QStringLiteral("hostile"));

    // A camera out of range in the file is refused, naming it, and changes nothing.
    QFile project(file);
    REQUIRE(project.open(QIODevice::ReadOnly));
    QJsonObject root = QJsonDocument::fromJson(project.readAll()).object();
    project.close();
    QJsonObject view = root["view"].toObject();
    QJsonObject camera = view["camera"].toObject();
    camera["distance"] = 1e9;
    view["camera"] = camera;
    root["view"] = view;
    const QString broken = QString::fromStdString((folder / "broken.bunraku.json").string());
    QFile out(broken);
    REQUIRE(out.open(QIODevice::WriteOnly));
    out.write(QJsonDocument(root).toJson());
    out.close();
    window->graphPanel()->selectDof(QStringLiteral("x"));
    CHECK_FALSE(window->files().projects().openProject(broken));
    CHECK(window->files().lastError().contains(QStringLiteral("\"view\".\"camera\"")));
    CHECK(window->graphPanel()->selectedDof() == QStringLiteral("x"));
}

TEST_CASE("the 3D view's Shadows and Follow boxes reach the view", "[app][viewport]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    widgets::ViewportWidget* viewport = window->viewportPanel()->viewport();
    auto* shadows = window->findChild<QCheckBox*>("showShadows");
    auto* follow = window->findChild<QCheckBox*>("followFigures");
    REQUIRE(shadows != nullptr);
    REQUIRE(follow != nullptr);
    // Shadows on and Follow off by default, as the view starts.
    CHECK(shadows->isChecked());
    CHECK(viewport->visibility().shadows);
    CHECK_FALSE(follow->isChecked());
    CHECK_FALSE(viewport->follow());
    QTest::mouseClick(shadows, Qt::LeftButton, Qt::NoModifier, QPoint(6, shadows->height() / 2));
    QTest::mouseClick(follow, Qt::LeftButton, Qt::NoModifier, QPoint(6, follow->height() / 2));
    CHECK_FALSE(viewport->visibility().shadows);
    CHECK(viewport->follow());
    // The figure boxes offer the performer's body, and choosing it reaches the view.
    QComboBox* figure = window->viewportPanel()->figureBox(0);
    const int body = figure->findData(int(render::FigureStyle::Body));
    REQUIRE(body >= 0);
    CHECK(figure->itemText(body) == QStringLiteral("Body"));
    figure->setCurrentIndex(body);
    CHECK(viewport->visibility().figures[0] == render::FigureStyle::Body);
}
