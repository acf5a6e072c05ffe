#pragma once
/// The workbench's screenshot run (`--screenshot FILE`, as the docs' pictures are made):
/// `--window-size WxH` opens the window at that size (1366x768: a laptop screen) and `--raise
/// DOCK` brings a dock to the front (its title, e.g. Normalisation); the picture is taken once
/// the analysis has finished, so the panels show their results.

#include <QSize>
#include <QString>

class QCommandLineParser;

namespace bunraku::app {

class MainWindow;

/// Adds --window-size and --raise.
void addScreenshotOptions(QCommandLineParser& parser);

/// The size asked for by --window-size (invalid when not given); `error` set when it is not
/// WxH between 320x240 and 16384x16384.
QSize requestedWindowSize(const QCommandLineParser& parser, QString& error);

/// Brings the dock named by --raise to the front; false (and `error`) when no dock has that
/// title or object name.
bool raiseRequestedDock(MainWindow& window, const QCommandLineParser& parser, QString& error);

/// Saves the window to `file` once the analysis is idle (at least 1.5 s after now and at most
/// 2 minutes), then quits the application with 0, or 1 when the file cannot be written.
void screenshotWhenIdle(MainWindow& window, const QString& file);

} // namespace bunraku::app
