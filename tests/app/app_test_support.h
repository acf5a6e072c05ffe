#pragma once
/// Shared set-up of the app tests: settings and autosaves go to a scratch folder, never to the
/// user's; windows open without dialogs and with the default layout.

#include "app/analysis_controller.h"
#include "app/file_controller.h"
#include "app/export_controller.h"
#include "app/main_window.h"
#include "app/stage_scheduler.h"
#include "app/viewport_panel.h"

#include "tests/app/take_id_text.h"
#include "tests/support/test_paths.h"

#include <QCoreApplication>
#include <QSettings>
#include <QStandardPaths>
#include <QTest>

#include <memory>
#include <string>

namespace bunraku::test {

inline void isolateSettings()
{
    static const bool done = [] {
        QCoreApplication::setOrganizationName(QStringLiteral("BunrakuTests"));
        QCoreApplication::setApplicationName(QStringLiteral("tests_app"));
        QStandardPaths::setTestModeEnabled(true);
        // One folder per process: ctest may run cases in parallel processes.
        const auto dir = scratchDir("app-settings-" + std::to_string(QCoreApplication::applicationPid()));
        QSettings::setDefaultFormat(QSettings::IniFormat);
        QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, QString::fromStdString(dir.string()));
        return true;
    }();
    (void)done;
}

/// A shown main window on the demo corpus.
inline std::unique_ptr<app::MainWindow> demoWindow()
{
    isolateSettings();
    auto window = std::make_unique<app::MainWindow>();
    window->files().setDialogsEnabled(false);
    window->exports().setDialogsEnabled(false);
    window->files().corpora().openDemoCorpus();
    window->resize(1400, 900);
    window->show();
    if (!QTest::qWaitForWindowExposed(window.get())) return nullptr;
    return window;
}

/// Waits until the window's background computations are done and the layout has settled: the
/// status bar's progress bar comes and goes with them, resizing the views. Exports run the
/// event loop, so a test comparing an export with the view's size waits for this first.
inline bool waitUntilIdle(app::MainWindow& window, int timeoutMs = 60000)
{
    const auto idle = [&window] { return !window.analysis().scheduler().busy(); };
    if (!QTest::qWaitFor(idle, timeoutMs)) return false;
    QCoreApplication::sendPostedEvents(); // the layout requests the finished work posted
    QCoreApplication::processEvents();
    return idle();
}

} // namespace bunraku::test
