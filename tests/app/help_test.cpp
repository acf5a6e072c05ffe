// Help > User Guide and Help > About in the real window, the application icon, and the paths
// the workbench opens from its command line (and from a desktop double click).
#include "tests/app/app_test_support.h"
#include "tests/support/peer.h"

#include "app/about_dialog.h"
#include "app/build_info.h"
#include "app/help_controller.h"
#include "app/installed_files.h"
#include "app/launch_paths.h"
#include "app/library_versions.h"

#include "analysis/io/corpus_io.h"

#include <catch2/catch.hpp>

#include <QAction>
#include <QDialog>
#include <QDialogButtonBox>
#include <QPushButton>
#include <QFile>
#include <QImage>
#include <QLabel>
#include <QRegularExpression>
#include <QTextBlock>
#include <QTextBrowser>

#include <cstdio>
#include <memory>

using namespace bunraku;

namespace {

QAction* menuAction(app::MainWindow& window, const QString& name) { return window.findChild<QAction*>(name); }

/// The first line a shell command prints, empty when it fails.
QString commandOutput(const std::string& command)
{
    std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen((command + " 2>/dev/null").c_str(), "r"), pclose);
    if (!pipe) return {};
    char buffer[256] = {};
    const size_t read = fread(buffer, 1, sizeof(buffer) - 1, pipe.get());
    return QString::fromLatin1(buffer, qsizetype(read)).section(QLatin1Char('\n'), 0, 0).trimmed();
}

QString scratchPath(const std::string& folder, const std::string& name = {})
{
    const auto dir = test::scratchDir(folder);
    return QString::fromStdString((name.empty() ? dir : dir / name).string());
}

} // namespace

TEST_CASE("every image the installed guide and tutorial link is installed beside them", "[app][help]")
{
    const QString folder = QString::fromStdString(BUNRAKU_BINARY_DIR) + QStringLiteral("/share/bunraku/doc/");
    const QRegularExpression image(QStringLiteral("!\\[[^\\]]*\\]\\(([^)\\s]+)\\)"));
    int linked = 0;
    for (const QString& name : {QStringLiteral("USER-GUIDE.md"), QStringLiteral("TUTORIAL.md")}) {
        QFile file(folder + name);
        REQUIRE(file.open(QIODevice::ReadOnly));
        const QString text = QString::fromUtf8(file.readAll());
        for (auto match = image.globalMatch(text); match.hasNext();) {
            const QString link = match.next().captured(1);
            INFO(name.toStdString() << " links " << link.toStdString());
            CHECK(QFile::exists(folder + link));
            ++linked;
        }
    }
    CHECK(linked >= 10);
}

TEST_CASE("Help > User Guide shows the installed guide rendered from its Markdown, with its screenshot", "[app][help]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    // The build tree mirrors the installed layout: build/bin/.. /share/bunraku/doc.
    const QString guide = QString::fromStdString(BUNRAKU_BINARY_DIR) + QStringLiteral("/share/bunraku/doc/USER-GUIDE.md");
    REQUIRE(app::userGuidePath() == guide);
    QAction* action = menuAction(*window, QStringLiteral("userGuideAction"));
    REQUIRE(action);
    REQUIRE(action->isEnabled());
    REQUIRE(action->shortcut() == QKeySequence(QKeySequence::HelpContents));
    action->trigger();
    auto* viewer = window->findChild<QDialog*>(QStringLiteral("userGuideViewer"));
    REQUIRE(viewer);
    REQUIRE(QTest::qWaitForWindowExposed(viewer));
    auto* browser = viewer->findChild<QTextBrowser*>(QStringLiteral("userGuideBrowser"));
    REQUIRE(browser);

    // Every heading of the Markdown file is a heading of the shown text (rendered, not raw).
    QFile file(guide);
    REQUIRE(file.open(QIODevice::ReadOnly));
    const QString markdown = QString::fromUtf8(file.readAll());
    const QString shown = browser->toPlainText();
    int headings = 0;
    auto matches = QRegularExpression(QStringLiteral("^#+ (.+)$"), QRegularExpression::MultilineOption).globalMatch(markdown);
    while (matches.hasNext()) {
        const auto match = matches.next();
        INFO(match.captured(1).toStdString());
        CHECK(shown.contains(match.captured(1)));
        ++headings;
    }
    CHECK(headings >= 3);
    CHECK_FALSE(shown.contains(QStringLiteral("## "))); // no Markdown syntax left
    const QVariant image = browser->document()->resource(QTextDocument::ImageResource, QUrl(QStringLiteral("screenshot.png")));
    CHECK(!image.value<QImage>().isNull());
    // The whole-window screenshot is scaled to the viewer's width.
    bool fitted = false;
    for (QTextBlock block = browser->document()->begin(); block.isValid(); block = block.next())
        for (auto fragment = block.begin(); !fragment.atEnd(); ++fragment)
            if (fragment.fragment().charFormat().isImageFormat())
                fitted = fragment.fragment().charFormat().toImageFormat().width() <= viewer->width();
    CHECK(fitted);

    // A second trigger raises the same viewer.
    action->trigger();
    CHECK(window->findChildren<QDialog*>(QStringLiteral("userGuideViewer")).size() == 1);
    viewer->close();
}

TEST_CASE("Help > User Guide fits a 1366x768 screen: the viewer and its Close button are inside the screen's free area", "[app][help]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    auto* help = window->findChild<app::HelpController*>();
    REQUIRE(help);
    // A 1366 x 768 laptop with a 32-pixel panel at the top.
    const QRect area(0, 32, 1366, 736);
    help->setAvailableGeometryForTesting(area);
    QAction* action = menuAction(*window, QStringLiteral("userGuideAction"));
    REQUIRE(action);
    action->trigger();
    auto* viewer = window->findChild<QDialog*>(QStringLiteral("userGuideViewer"));
    REQUIRE(viewer);
    REQUIRE(QTest::qWaitForWindowExposed(viewer));
    INFO("viewer " << viewer->frameGeometry().x() << "," << viewer->frameGeometry().y() << " " << viewer->frameGeometry().width() << "x"
                   << viewer->frameGeometry().height());
    CHECK(viewer->height() < 800); // the old fixed 900 x 800 did not fit
    CHECK(area.contains(viewer->frameGeometry()));
    auto* buttons = viewer->findChild<QDialogButtonBox*>();
    REQUIRE(buttons);
    QPushButton* close = buttons->button(QDialogButtonBox::Close);
    REQUIRE(close);
    REQUIRE(close->isVisible());
    CHECK(area.contains(QRect(close->mapToGlobal(QPoint(0, 0)), close->size())));
    // The screenshot in the guide is scaled to the smaller viewer.
    auto* browser = viewer->findChild<QTextBrowser*>(QStringLiteral("userGuideBrowser"));
    REQUIRE(browser);
    for (QTextBlock block = browser->document()->begin(); block.isValid(); block = block.next())
        for (auto fragment = block.begin(); !fragment.atEnd(); ++fragment)
            if (fragment.fragment().charFormat().isImageFormat())
                CHECK(fragment.fragment().charFormat().toImageFormat().width() <= viewer->width());
    // On a large screen the viewer keeps its 900 x 800.
    CHECK(app::HelpController::guideViewerSize(QRect(0, 0, 1920, 1080)) == QSize(900, 800));
    viewer->close();
}

TEST_CASE("Help > About shows the version, the commit, the licence and the versions of the libraries in use", "[app][help]")
{
    auto window = test::demoWindow();
    REQUIRE(window);
    QAction* action = menuAction(*window, QStringLiteral("aboutAction"));
    REQUIRE(action);
    action->trigger();
    auto* dialog = window->findChild<app::AboutDialog*>(QStringLiteral("aboutDialog"));
    REQUIRE(dialog);
    REQUIRE(QTest::qWaitForWindowExposed(dialog));
    const QString text = dialog->findChild<QLabel*>(QStringLiteral("aboutText"))->text();
    CHECK(text.contains(QStringLiteral("Version " BUNRAKU_TEST_PROJECT_VERSION)));
    CHECK(text.contains(QString::fromStdString(std::string(app::buildCommit()))));
    CHECK(text.contains(QStringLiteral("GPL-3.0-or-later")));
    CHECK(text.contains(QStringLiteral("NO WARRANTY")));
    CHECK(app::buildCommit() != "unknown"); // built from a git checkout

    // Each library's version is the one its development files declare (pkg-config), or for
    // QCustomPlot, which has none, Debian's package version (which begins with it).
    const QString plain = dialog->plainText();
    const std::pair<const char*, std::string> libraries[] = {
        {"Qt", "pkg-config --modversion Qt6Core"},
        {"QCustomPlot", "dpkg-query -W -f='${Version}' libqcustomplot2.1-qt6"},
        {"Eigen", "pkg-config --modversion eigen3"},
        {"FFTW", "pkg-config --modversion fftw3"},
        {"assimp", "pkg-config --modversion assimp"},
    };
    for (const auto& [name, command] : libraries) {
        const QString peer = commandOutput(command);
        INFO(name << ": `" << command << "` says " << peer.toStdString() << "\n" << plain.toStdString());
        // The version is compared with what the machine's package tools say: without their
        // answer the check cannot be made, which fails under CI=true (tests/support/peer.h).
        if (!bunraku::test::requirePeer(!peer.isEmpty(), std::string("the version of ") + name + " from `" + command + "`",
                                        "apt-get install pkg-config, and the library's development package"))
            return;
        QString shown;
        for (const auto& library : app::libraryVersions())
            if (library.name == QLatin1String(name)) shown = library.version;
        REQUIRE(!shown.isEmpty());
        CHECK(peer.startsWith(shown.section(QLatin1Char(' '), 0, 0)));
        CHECK(plain.contains(QStringLiteral("%1 %2").arg(QLatin1String(name), shown)));
    }
    dialog->close();
}

TEST_CASE("the window icon is the application icon at every size, as rendered for the hicolor theme", "[app][help]")
{
    const QIcon icon = app::applicationIcon();
    for (int size : {16, 24, 32, 48, 64, 128, 256}) {
        INFO(size);
        const QString file = QStringLiteral(BUNRAKU_BINARY_DIR "/share/icons/hicolor/%1x%1/apps/org.bunraku.MotionWorkbench.png").arg(size);
        const QImage installed = QImage(file).convertToFormat(QImage::Format_ARGB32_Premultiplied);
        REQUIRE(installed.size() == QSize(size, size));
        CHECK(icon.availableSizes().contains(QSize(size, size)));
        CHECK(icon.pixmap(QSize(size, size)).toImage().convertToFormat(QImage::Format_ARGB32_Premultiplied) == installed);
    }
}

TEST_CASE("command-line paths: a corpus.json opens its corpus, a project its state, take files import over the demo corpus",
          "[app][help][launch]")
{
    using app::LaunchPathKind;
    CHECK(app::classifyLaunchPath(QStringLiteral("/data/demo/corpus.json")).kind == LaunchPathKind::Corpus);
    CHECK(app::classifyLaunchPath(QStringLiteral("/data/demo/corpus.json")).path == QStringLiteral("/data/demo"));
    CHECK(app::classifyLaunchPath(QStringLiteral("/data/session.bunraku.json")).kind == LaunchPathKind::Project);
    CHECK(app::classifyLaunchPath(QStringLiteral("/data/take.bvh")).kind == LaunchPathKind::Take);

    const QString folder = scratchPath("launch-corpus") + QStringLiteral("/demo");
    const QString bvh = scratchPath("launch-take", "greeting.bvh");
    const QString project = scratchPath("launch-project", "session.bunraku.json");
    {
        auto window = test::demoWindow();
        REQUIRE(window);
        REQUIRE(analysis::io::writeCorpus(window->document().corpus(), folder.toStdString()).ok());
        REQUIRE(window->exports().exportTake(app::TakeSlot::A, bvh));
        window->document().setCurrentTime(2.0);
        REQUIRE(window->files().projects().saveProject(project));
    }

    test::isolateSettings();
    {
        app::MainWindow window;
        window.files().setDialogsEnabled(false);
        REQUIRE(app::openLaunchPaths(window.files(), window.document(), {folder + QStringLiteral("/corpus.json")}).isEmpty());
        CHECK(window.document().corpusSource() == folder);
        CHECK(window.document().corpus().takes.size() == 30);
    }
    {
        app::MainWindow window;
        window.files().setDialogsEnabled(false);
        REQUIRE(app::openLaunchPaths(window.files(), window.document(), {project}).isEmpty());
        CHECK(window.files().projects().projectPath() == project);
        CHECK(window.document().currentTime() == Approx(2.0));
    }
    {
        app::MainWindow window;
        window.files().setDialogsEnabled(false);
        REQUIRE(app::openLaunchPaths(window.files(), window.document(), {bvh, bvh}).isEmpty());
        CHECK(window.document().corpusSource() == QStringLiteral("demo"));
        int imported = 0;
        for (const auto& derived : window.document().derivedTakes())
            if (derived.sourcePath == bvh) ++imported;
        CHECK(imported == 2);
    }
    {
        app::MainWindow window;
        window.files().setDialogsEnabled(false);
        const QString error = app::openLaunchPaths(window.files(), window.document(), {project, folder});
        CHECK(error.contains(QStringLiteral("one corpus or project at a time")));
        CHECK(window.document().corpusSource() == QStringLiteral("demo")); // something is shown
        const QString missing = scratchPath("launch-missing", "absent.bvh");
        const QString missingError = app::openLaunchPaths(window.files(), window.document(), {missing});
        CHECK(missingError.contains(QStringLiteral("absent.bvh")));
    }
}
