#include "app/progress_task.h"

#include <QEventLoop>
#include <QFutureWatcher>
#include <QProgressDialog>
#include <QTimer>
#include <QtConcurrent/QtConcurrentRun>

#include <atomic>
#include <stop_token>

namespace bunraku::app {

void runProgressTask(QWidget* parent, const QString& label, const std::function<void(const analysis::RunControl&)>& work,
                     const ProgressTaskOptions& options)
{
    if (parent == nullptr) {
        work(analysis::RunControl{{}, options.observe});
        return;
    }
    QProgressDialog progress(label, QObject::tr("Cancel"), 0, 1000, parent);
    progress.setWindowModality(Qt::WindowModal);
    progress.setMinimumDuration(options.showAfterMs);
    progress.setAutoReset(false);
    progress.setAutoClose(false);
    if (options.showAfterMs <= 0) progress.show();
    std::stop_source stop;
    std::atomic<double> done{0.0};
    QObject::connect(&progress, &QProgressDialog::canceled, &progress, [&stop] { stop.request_stop(); });
    QTimer poll;
    QObject::connect(&poll, &QTimer::timeout, &progress, [&] {
        if (!progress.wasCanceled()) progress.setValue(int(1000.0 * done.load()));
    });
    poll.start(100);
    QFutureWatcher<void> watcher;
    QEventLoop loop;
    QObject::connect(&watcher, &QFutureWatcherBase::finished, &loop, &QEventLoop::quit);
    watcher.setFuture(QtConcurrent::run([&] {
        const auto report = [&](double fraction) {
            done.store(fraction);
            if (options.observe) options.observe(fraction);
        };
        work(analysis::RunControl{stop.get_token(), report});
    }));
    loop.exec();
}

} // namespace bunraku::app
