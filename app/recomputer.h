#pragma once
/// Background recomputation of one derived result (OpenSim Creator's cancellable worker with
/// version ids; PlotJuggler's delayed callback). Triggers are coalesced by a single-shot timer;
/// on firing, the inputs are snapshotted together with the document version and the job runs
/// on QtConcurrent::run with a QPromise. A newer request cancels the running one through its
/// std::stop_source (seen by analysis code as RunControl::stop), and a result whose request is
/// no longer the latest, or whose document version is stale, is dropped.

#include "analysis/core/run_control.h"

#include <QFutureWatcher>
#include <QObject>
#include <QTimer>

#include <any>
#include <functional>
#include <stop_token>

namespace bunraku::app {

class Document;

/// What a job returns: a value for the consumer, or an error message for the user.
struct JobOutput {
    std::any value;
    QString error; ///< empty on success
};

/// The work, with its inputs already copied in: runs on a worker thread.
using Job = std::function<JobOutput(const analysis::RunControl& control)>;

class Recomputer : public QObject {
    Q_OBJECT
public:
    enum class State { Idle, Pending, Running, Finished, Cancelled, Failed };

    /// `snapshot` (GUI thread) copies the inputs into a Job, or returns an empty Job when there
    /// is nothing to compute; `consume` (GUI thread) receives the current results. `version`
    /// tags the inputs (default: Document::version()); a result whose tag changed while it ran
    /// is dropped and the work rescheduled.
    Recomputer(Document& document, std::function<Job()> snapshot, std::function<void(const JobOutput&)> consume,
               QObject* parent = nullptr, int delayMs = 40, std::function<quint64()> version = {});
    /// Stops running jobs (their stop token) without waiting for them: a job ends at its next
    /// cancellation check, on its own, and its result is dropped.
    ~Recomputer() override;

    /// Asks for a recomputation after the coalescing delay (restarts the delay).
    void schedule();
    /// Starts now, cancelling any running job.
    void runNow();
    /// Cancels the pending and running work; its result will be dropped.
    void cancel();

    State state() const { return m_state; }
    bool busy() const { return m_state == State::Pending || m_state == State::Running; }
    /// Results delivered to the consumer so far (tests wait on it).
    int deliveredCount() const { return m_delivered; }
    QString lastError() const { return m_lastError; }

signals:
    void stateChanged(bunraku::app::Recomputer::State state);
    /// Fraction in [0, 1] of the running job.
    void progressChanged(double fraction);

private:
    void setState(State state);
    void finish(QFutureWatcher<JobOutput>* watcher, quint64 request, quint64 version);

    std::function<quint64()> m_version;
    std::function<Job()> m_snapshot;
    std::function<void(const JobOutput&)> m_consume;
    QTimer m_timer;
    std::stop_source m_stop;
    quint64 m_request = 0;
    State m_state = State::Idle;
    int m_delivered = 0;
    int m_running = 0;
    QString m_lastError;
};

} // namespace bunraku::app
