#pragma once
/// Shared set-up of the app tests: settings and autosaves go to a scratch folder, never to the
/// user's; windows open without dialogs and with the default layout.

#include "app/file_controller.h"
#include "app/export_controller.h"
#include "app/main_window.h"

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
    window->files().openDemoCorpus();
    window->resize(1400, 900);
    window->show();
    if (!QTest::qWaitForWindowExposed(window.get())) return nullptr;
    return window;
}

} // namespace bunraku::test
