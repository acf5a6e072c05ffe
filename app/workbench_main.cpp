#include "app/workbench_main.h"

#include "app/file_controller.h"
#include "app/export_controller.h"
#include "app/main_window.h"
#include "app/viewport_panel.h"
#include "render/scene.h"

#include <QApplication>
#include <QComboBox>
#include <QCommandLineParser>
#include <QFileInfo>
#include <QTimer>

#include <cstdio>

namespace bunraku::app {

int runWorkbench(int argc, char** argv)
{
    QApplication application(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("Bunraku"));
    QApplication::setApplicationName(QStringLiteral("Motion Workbench"));
    QApplication::setApplicationDisplayName(QStringLiteral("Bunraku Motion Workbench"));
    QApplication::setApplicationVersion(QStringLiteral(BUNRAKU_VERSION));

    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral("Bunraku Motion Workbench: view, normalise, decompose and design puppet motion."));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument(QStringLiteral("path"), QStringLiteral("A corpus folder, a project file (.json) or a take file; default: the demo corpus."), QStringLiteral("[path]"));
    const QCommandLineOption screenshot(QStringLiteral("screenshot"), QStringLiteral("Save a PNG of the window once shown, then quit."), QStringLiteral("file"));
    const QCommandLineOption defaultLayout(QStringLiteral("default-layout"), QStringLiteral("Ignore the saved window layout."));
    const QCommandLineOption figure(QStringLiteral("figure"),
                                    QStringLiteral("The 3D view's figure for takes A and B: puppet, skeleton (the performer's, for takes read from BVH) or both."),
                                    QStringLiteral("figure"));
    parser.addOption(screenshot);
    parser.addOption(defaultLayout);
    parser.addOption(figure);
    parser.process(application);

    MainWindow window;
    if (parser.isSet(figure)) {
        const QString value = parser.value(figure);
        const int style = value == QStringLiteral("puppet")     ? int(render::FigureStyle::Puppet)
                          : value == QStringLiteral("skeleton") ? int(render::FigureStyle::Skeleton)
                          : value == QStringLiteral("both")     ? int(render::FigureStyle::PuppetAndSkeleton)
                                                                : -1;
        if (style < 0) {
            std::fprintf(stderr, "bunraku-workbench: --figure '%s': expected puppet, skeleton or both\n", qPrintable(value));
            return 1;
        }
        for (int slot = 0; slot < 2; ++slot) {
            QComboBox* box = window.viewportPanel()->figureBox(slot);
            box->setCurrentIndex(box->findData(style));
        }
    }
    const bool batch = parser.isSet(screenshot);
    window.files().setDialogsEnabled(!batch);
    window.exports().setDialogsEnabled(!batch);
    if (!batch && !parser.isSet(defaultLayout)) window.restoreSavedLayout();

    const QStringList paths = parser.positionalArguments();
    bool opened = false;
    if (!paths.isEmpty()) {
        const QString& path = paths.front();
        // A take file opens over the demo corpus, as an imported take.
        const bool isTake = QFileInfo(path).isFile() && !path.endsWith(QStringLiteral(".json"));
        if (isTake) window.files().openDemoCorpus();
        opened = window.files().openPath(path);
        if (!opened && batch) {
            std::fprintf(stderr, "bunraku-workbench: %s\n", qPrintable(window.files().lastError()));
            return 1;
        }
    }
    if (!opened && paths.isEmpty()) window.files().openDemoCorpus();
    if (!opened && !paths.isEmpty() && window.document().corpus().takes.empty()) window.files().openDemoCorpus();
    window.show();

    if (batch) {
        const QString file = parser.value(screenshot);
        QTimer::singleShot(1200, &window, [&window, file] {
            const bool saved = window.saveScreenshot(file);
            if (!saved) std::fprintf(stderr, "bunraku-workbench: cannot write %s\n", qPrintable(file));
            QApplication::exit(saved ? 0 : 1);
        });
    } else {
        window.files().offerRecovery();
    }
    return application.exec();
}

} // namespace bunraku::app
