#include "app/recomputer.h"

#include "app/document.h"

#include <QtConcurrent/QtConcurrentRun>

#include <exception>

namespace bunraku::app {

Recomputer::Recomputer(Document& document, std::function<Job()> snapshot, std::function<void(const JobOutput&)> consume,
                       QObject* parent, int delayMs, std::function<quint64()> version)
    : QObject(parent), m_version(std::move(version)), m_snapshot(std::move(snapshot)), m_consume(std::move(consume))
{
    if (!m_version) m_version = [&document] { return document.version(); };
    m_timer.setSingleShot(true);
    m_timer.setInterval(delayMs);
    connect(&m_timer, &QTimer::timeout, this, &Recomputer::runNow);
}

Recomputer::~Recomputer()
{
    // Running jobs hold copies of their inputs only (never this object): they are told to stop
    // and left to end at their next cancellation check, unwaited for, so closing a panel or the
    // window never blocks on a long job. Their results go nowhere: the watchers go with us.
    m_stop.request_stop();
    for (auto* watcher : findChildren<QFutureWatcher<JobOutput>*>()) watcher->disconnect(this);
}

void Recomputer::schedule()
{
    m_timer.start();
    if (m_state != State::Running) setState(State::Pending);
}

void Recomputer::cancel()
{
    m_timer.stop();
    m_stop.request_stop();
    ++m_request;
    setState(State::Cancelled);
}

void Recomputer::runNow()
{
    m_timer.stop();
    m_stop.request_stop();
    Job job = m_snapshot();
    const quint64 request = ++m_request;
    if (!job) {
        setState(State::Idle);
        return;
    }
    m_stop = std::stop_source();
    const quint64 version = m_version();
    auto* watcher = new QFutureWatcher<JobOutput>(this);
    connect(watcher, &QFutureWatcher<JobOutput>::progressValueChanged, this, [this, watcher, request](int value) {
        if (request == m_request && watcher->progressMaximum() > 0)
            emit progressChanged(double(value) / watcher->progressMaximum());
    });
    connect(watcher, &QFutureWatcher<JobOutput>::finished, this,
            [this, watcher, request, version] { finish(watcher, request, version); });
    ++m_running;
    watcher->setFuture(QtConcurrent::run(
        [](QPromise<JobOutput>& promise, Job work, std::stop_token stop) {
            promise.setProgressRange(0, 1000);
            analysis::RunControl control{stop, [&promise](double fraction) {
                                             promise.setProgressValue(int(std::clamp(fraction, 0.0, 1.0) * 1000));
                                         }};
            // Exceptions must not cross into the event loop: turn them into an error message.
            try {
                promise.addResult(work(control));
            } catch (const std::exception& error) {
                promise.addResult(JobOutput{{}, QString::fromUtf8(error.what())});
            } catch (...) {
                promise.addResult(JobOutput{{}, QStringLiteral("unknown error")});
            }
        },
        std::move(job), m_stop.get_token()));
    setState(State::Running);
}

void Recomputer::finish(QFutureWatcher<JobOutput>* watcher, quint64 request, quint64 version)
{
    watcher->deleteLater();
    --m_running;
    const bool latest = request == m_request;
    if (!latest) return; // a newer request owns the state
    if (version != m_version() || watcher->future().resultCount() == 0) {
        // The inputs changed while computing: the result is stale, ask again.
        schedule();
        return;
    }
    const JobOutput output = watcher->future().result();
    m_lastError = output.error;
    if (!output.error.isEmpty() && !output.value.has_value()) {
        setState(State::Failed);
    } else {
        setState(State::Finished);
    }
    ++m_delivered;
    m_consume(output);
    emit progressChanged(1.0);
}

void Recomputer::setState(State state)
{
    if (m_state == state) return;
    m_state = state;
    emit stateChanged(state);
}

} // namespace bunraku::app
