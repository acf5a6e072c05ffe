#include "app/workbench_main.h"

#include "app/file_controller.h"
#include "app/analysis_controller.h"
#include "app/main_window.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QFileInfo>
#include <QDockWidget>
#include <QElapsedTimer>
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
    const QCommandLineOption windowSize(QStringLiteral("window-size"), QStringLiteral("Open the window at this size, e.g. 1366x768."),
                                        QStringLiteral("WxH"));
    const QCommandLineOption raise(QStringLiteral("raise"), QStringLiteral("Bring a dock to the front (its title, e.g. Normalisation)."),
                                   QStringLiteral("dock"));
    parser.addOption(screenshot);
    parser.addOption(defaultLayout);
    parser.addOption(windowSize);
    parser.addOption(raise);
    parser.process(application);
    QSize size;
    if (parser.isSet(windowSize)) {
        const QStringList parts = parser.value(windowSize).split(QLatin1Char('x'));
        bool okWidth = false, okHeight = false;
        if (parts.size() == 2) size = QSize(parts[0].toInt(&okWidth), parts[1].toInt(&okHeight));
        if (!okWidth || !okHeight || size.width() < 320 || size.height() < 240 || size.width() > 16384 || size.height() > 16384) {
            std::fprintf(stderr, "bunraku-workbench: --window-size expects WxH between 320x240 and 16384x16384, got '%s'\n",
                         qPrintable(parser.value(windowSize)));
            return 2;
        }
    }

    MainWindow window;
    const bool batch = parser.isSet(screenshot);
    window.files().setDialogsEnabled(!batch);
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
    if (size.isValid()) window.resize(size);
    window.show();
    if (parser.isSet(raise)) {
        QDockWidget* dock = nullptr;
        for (QDockWidget* candidate : window.docks())
            if (candidate->windowTitle().compare(parser.value(raise), Qt::CaseInsensitive) == 0 ||
                candidate->objectName() == parser.value(raise))
                dock = candidate;
        if (!dock) {
            std::fprintf(stderr, "bunraku-workbench: no dock named '%s'\n", qPrintable(parser.value(raise)));
            return 2;
        }
        dock->show();
        dock->raise();
    }

    if (batch) {
        // Once the analysis has finished (the panels show their results), at least 1.5 s after
        // showing and at most 2 minutes.
        const QString file = parser.value(screenshot);
        auto* poll = new QTimer(&window);
        auto* since = new QElapsedTimer;
        since->start();
        QObject::connect(poll, &QTimer::timeout, &window, [&window, file, poll, since] {
            const qint64 elapsed = since->elapsed();
            if (elapsed < 1500 || (window.analysis().scheduler().busy() && elapsed < 120000)) return;
            poll->stop();
            delete since;
            const bool saved = window.saveScreenshot(file);
            if (!saved) std::fprintf(stderr, "bunraku-workbench: cannot write %s\n", qPrintable(file));
            QApplication::exit(saved ? 0 : 1);
        });
        poll->start(250);
    } else {
        window.files().offerRecovery();
    }
    return application.exec();
}

} // namespace bunraku::app
