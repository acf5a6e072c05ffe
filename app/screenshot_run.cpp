#include "app/screenshot_run.h"

#include "app/analysis_controller.h"
#include "app/main_window.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QTimer>

#include <cstdio>
#include <memory>

namespace bunraku::app {

void addScreenshotOptions(QCommandLineParser& parser)
{
    parser.addOption({QStringLiteral("window-size"), QStringLiteral("Open the window at this size, e.g. 1366x768."), QStringLiteral("WxH")});
    parser.addOption({QStringLiteral("raise"), QStringLiteral("Bring a dock to the front (its title, e.g. Normalisation)."),
                      QStringLiteral("dock")});
}

QSize requestedWindowSize(const QCommandLineParser& parser, QString& error)
{
    if (!parser.isSet(QStringLiteral("window-size"))) return {};
    const QString text = parser.value(QStringLiteral("window-size"));
    const QStringList parts = text.split(QLatin1Char('x'));
    bool okWidth = false;
    bool okHeight = false;
    QSize size;
    if (parts.size() == 2) size = QSize(parts[0].toInt(&okWidth), parts[1].toInt(&okHeight));
    if (!okWidth || !okHeight || size.width() < 320 || size.height() < 240 || size.width() > 16384 || size.height() > 16384) {
        error = QStringLiteral("--window-size expects WxH between 320x240 and 16384x16384, got '%1'").arg(text);
        return {};
    }
    return size;
}

bool raiseRequestedDock(MainWindow& window, const QCommandLineParser& parser, QString& error)
{
    if (!parser.isSet(QStringLiteral("raise"))) return true;
    const QString name = parser.value(QStringLiteral("raise"));
    for (QDockWidget* dock : window.docks())
        if (dock->windowTitle().compare(name, Qt::CaseInsensitive) == 0 || dock->objectName() == name) {
            dock->show();
            dock->raise();
            return true;
        }
    error = QStringLiteral("no dock named '%1'").arg(name);
    return false;
}

void screenshotWhenIdle(MainWindow& window, const QString& file)
{
    auto* poll = new QTimer(&window);
    auto since = std::make_shared<QElapsedTimer>();
    since->start();
    QObject::connect(poll, &QTimer::timeout, &window, [&window, file, poll, since] {
        const qint64 elapsed = since->elapsed();
        if (elapsed < 1500 || (window.analysis().scheduler().busy() && elapsed < 120000)) return;
        poll->stop();
        const bool saved = window.saveScreenshot(file);
        if (!saved) std::fprintf(stderr, "bunraku-workbench: cannot write %s\n", qPrintable(file));
        QApplication::exit(saved ? 0 : 1);
    });
    poll->start(250);
}

} // namespace bunraku::app
