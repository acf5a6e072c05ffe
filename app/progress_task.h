#pragma once
/// Work a person waits for (reading a long take, building a corpus) run off the GUI thread behind
/// a window-modal progress dialog whose Cancel stops it through the work's RunControl. The GUI
/// thread keeps processing events (the window repaints, timers run) until the work returns.

#include "analysis/core/run_control.h"

#include <QString>

#include <functional>

class QWidget;

namespace bunraku::app {

struct ProgressTaskOptions {
    int showAfterMs = 300; ///< the dialog appears when the work takes longer than this
    /// Called on the worker thread after every progress report (tests hold the work there).
    std::function<void(double)> observe;
};

/// Runs `work` on a pool thread behind a progress dialog titled `label` on `parent` and returns
/// once it has returned; whether it was cancelled is for `work`'s result to say (its control's
/// stop token is triggered by Cancel). Without a parent the work runs here, with no stop or
/// progress beyond `options.observe`.
void runProgressTask(QWidget* parent, const QString& label, const std::function<void(const analysis::RunControl&)>& work,
                     const ProgressTaskOptions& options = {});

} // namespace bunraku::app
