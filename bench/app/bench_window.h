#pragma once
/// The workbench window the app benchmarks measure: the demo corpus open, no dialogs, 1600 x 1000,
/// shown and exposed.

#include "app/file_controller.h"
#include "app/main_window.h"

#include <QTest>

#include <memory>

namespace bunraku::bench {

inline std::unique_ptr<app::MainWindow> shownDemoWindow()
{
    auto window = std::make_unique<app::MainWindow>();
    window->files().setDialogsEnabled(false);
    window->files().corpora().openDemoCorpus();
    window->resize(1600, 1000);
    window->show();
    (void)QTest::qWaitForWindowExposed(window.get());
    return window;
}

} // namespace bunraku::bench
