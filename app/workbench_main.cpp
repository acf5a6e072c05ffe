#include "app/workbench_main.h"

#include "app/build_info.h"
#include "app/file_controller.h"
#include "app/export_controller.h"
#include "app/installed_files.h"
#include "app/launch_paths.h"
#include "app/main_window.h"
#include "app/screenshot_run.h"
#include "app/viewport_panel.h"
#include "app/window_placement.h"
#include "render/scene.h"

#include "analysis/body/puppet_model.h"

#include <QApplication>
#include <QComboBox>
#include <QCommandLineParser>
#include <QMessageBox>
#include <QtConcurrent/QtConcurrentRun>

#include <cstdio>
#include <cstring>

namespace bunraku::app {
namespace {

void describeOptions(QCommandLineParser& parser)
{
    parser.setApplicationDescription(
        QStringLiteral("Bunraku Motion Workbench: view, normalise, decompose and design puppet motion.\n"
                       "Opens the corpus, project or take files given (several take files are imported\n"
                       "together), or the embedded demo corpus when none is given."));
    parser.addHelpOption();
    parser.addOption({{QStringLiteral("v"), QStringLiteral("version")}, QStringLiteral("Display version information.")});
    parser.addPositionalArgument(
        QStringLiteral("paths"),
        QStringLiteral("A corpus folder or its corpus.json, a project file (.bunraku.json), or take files (.csv, .bvh, "
                       ".fbx, .glb/.gltf, .dae, .txt/.fastrak/.fst); default: the demo corpus."),
        QStringLiteral("[paths...]"));
    parser.addOption({QStringLiteral("screenshot"), QStringLiteral("Save a PNG of the window once shown, then quit."), QStringLiteral("file")});
    parser.addOption({QStringLiteral("default-layout"), QStringLiteral("Ignore the saved window layout.")});
    parser.addOption({QStringLiteral("figure"),
                      QStringLiteral("The 3D view's figure for takes A and B: puppet, skeleton (the performer's, for takes read from BVH), both, body (the performer's body on that skeleton) or mesh (the skinned mesh of an FBX, glTF or Collada take's file; the skeleton for a take without one)."),
                      QStringLiteral("figure")});
    addScreenshotOptions(parser);
}

/// --help and --version need no display: they are answered before the GUI starts.
bool asksOnlyForText(int argc, char** argv, bool& version)
{
    for (int i = 1; i < argc; ++i) {
        const char* word = argv[i];
        if (std::strcmp(word, "--") == 0) return false;
        if (std::strcmp(word, "-v") == 0 || std::strcmp(word, "--version") == 0) {
            version = true;
            return true;
        }
        if (std::strcmp(word, "-h") == 0 || std::strcmp(word, "--help") == 0 || std::strcmp(word, "--help-all") == 0
            || std::strcmp(word, "-?") == 0)
            return true;
    }
    return false;
}

void nameApplication()
{
    QCoreApplication::setOrganizationName(QStringLiteral("Bunraku"));
    QCoreApplication::setApplicationName(QStringLiteral("Motion Workbench"));
    QCoreApplication::setApplicationVersion(QStringLiteral(BUNRAKU_VERSION));
}

} // namespace

int runWorkbench(int argc, char** argv)
{
    bool version = false;
    if (asksOnlyForText(argc, argv, version)) {
        if (version) {
            std::printf("%s\n", versionText("bunraku-workbench").c_str());
            return 0;
        }
        QCoreApplication core(argc, argv);
        nameApplication();
        QCommandLineParser parser;
        describeOptions(parser);
        parser.process(core); // prints the help and exits
        return 0;
    }

    QApplication application(argc, argv);
    nameApplication();
    QApplication::setApplicationDisplayName(QStringLiteral("Bunraku Motion Workbench"));
    QApplication::setDesktopFileName(QLatin1String(kDesktopId));
    QApplication::setWindowIcon(applicationIcon());

    QCommandLineParser parser;
    describeOptions(parser);
    parser.process(application);
    const bool batch = parser.isSet(QStringLiteral("screenshot"));
    QString optionError;
    const QSize size = requestedWindowSize(parser, optionError);
    if (!optionError.isEmpty()) {
        std::fprintf(stderr, "bunraku-workbench: %s\n", qPrintable(optionError));
        return 2;
    }

    if (userGuidePath().isEmpty())
        std::fprintf(stderr, "bunraku-workbench: warning: the user guide is not installed (expected %s)\n",
                     qPrintable(expectedUserGuidePath()));

    // The modelled puppet's mesh (about 1.2 s of CPU, made once per process) starts on a pool
    // thread while the window is built: the first scene waits only for what is left of it.
    (void)QtConcurrent::run([] { (void)analysis::shippedPuppetMesh(); });

    MainWindow window;
    if (parser.isSet(QStringLiteral("figure"))) {
        const QString value = parser.value(QStringLiteral("figure"));
        const auto figure = render::figureStyleFromName(value.toStdString());
        const int style = figure ? int(*figure) : -1;
        if (style < 0) {
            std::fprintf(stderr, "bunraku-workbench: --figure '%s': expected puppet, skeleton, both, body or mesh\n", qPrintable(value));
            return 1;
        }
        for (int slot = 0; slot < 2; ++slot) {
            QComboBox* box = window.viewportPanel()->figureBox(slot);
            box->setCurrentIndex(box->findData(style));
        }
    }
    window.files().setDialogsEnabled(!batch);
    window.exports().setDialogsEnabled(!batch);
    if (!batch && !parser.isSet(QStringLiteral("default-layout"))) window.restoreSavedLayout();

    // The corpus or project, then the window (inside the available screen area, whatever
    // --window-size asks for), then the take files: their dialog opens over the window.
    bool shown = false;
    const auto show = [&] {
        showInsideScreen(window, size);
        shown = true;
    };
    const QString error = openLaunchPaths(window.files(), window.document(), parser.positionalArguments(), show);
    if (!error.isEmpty() && batch) {
        std::fprintf(stderr, "bunraku-workbench: %s\n", qPrintable(error));
        return 1;
    }
    if (!shown) show();
    if (!raiseRequestedDock(window, parser, optionError)) {
        std::fprintf(stderr, "bunraku-workbench: %s\n", qPrintable(optionError));
        return 2;
    }
    // The file controller has shown its own errors; this one is about the arguments.
    if (!error.isEmpty() && error != window.files().lastError()) QMessageBox::warning(&window, QObject::tr("Cannot open"), error);

    if (batch) {
        screenshotWhenIdle(window, parser.value(QStringLiteral("screenshot")));
    } else {
        window.files().projects().offerRecovery();
    }
    return application.exec();
}

} // namespace bunraku::app
