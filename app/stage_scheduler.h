#pragma once
/// The one scheduler of the workbench's background analysis (OpenSim Creator's cancellable
/// workers with version ids, keyed by content instead of a document version). Every job is a
/// slot - a pipeline stage (analysis/pipeline/stages.h) or another derived result - asked for
/// with the key of its inputs and parameters (stage_key.h):
///  - a slot asked for the key it is already computing or showing does nothing, so a stage is
///    cancelled only when its own inputs change (an emotion-weight drag never restarts a running
///    normalisation);
///  - a new key cancels the slot's running job (its std::stop_token) and starts the new one,
///    or takes the result from the cache (pipeline::StageCache) at once. The cache is the one
///    the pipeline's stage functions fill (a stage slot's result is filed with its stage's
///    results, the others apart), shared with whoever runs the stages outside the scheduler;
///  - a key names its result, whichever slot asks: a slot asking for a key another slot
///    computed takes it from the cache, one asking for a key another slot is computing waits for
///    that job (a job is cancelled only when no slot waits for it any more);
///  - a finished job whose key is no longer the slot's is dropped (cached, never shown);
///  - results reach the GUI thread only, through queued calls; exceptions never cross.
/// Jobs run on an Executor: the thread pool by default, a manual one in tests (no wall clock).

#include "analysis/core/result.h"
#include "analysis/core/run_control.h"
#include "analysis/pipeline/stage_cache.h"
#include "analysis/pipeline/stage_key.h"

#include <QObject>
#include <QString>

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <stop_token>
#include <type_traits>

namespace bunraku::app {

/// Runs work off the GUI thread.
class Executor {
public:
    virtual ~Executor() = default;
    virtual void run(std::function<void()> work) = 0;
};

/// QThreadPool::globalInstance().
class ThreadPoolExecutor : public Executor {
public:
    void run(std::function<void()> work) override;
};

using StageValue = std::shared_ptr<const void>;
/// A job: computes the slot's value from inputs it captured, off the GUI thread.
using StageWork = std::function<analysis::Result<StageValue>(const analysis::RunControl& control)>;

enum class SlotState { Idle, Running, Finished, Failed };

/// A slot with the type of its result: what it computes cannot be read as another type.
/// `stage`: the pipeline stage its jobs run (their results are filed in the cache with that
/// stage's); none for the other results (a take's motion axis or kimono, a live take's body).
template <class T> struct TypedSlot {
    int id = 0;
    std::optional<analysis::pipeline::Stage> stage;
};
/// A typed slot's job.
template <class T> using TypedWork = std::function<analysis::Result<analysis::pipeline::Shared<T>>(const analysis::RunControl& control)>;

class StageScheduler : public QObject {
    Q_OBJECT
public:
    /// `executor` null: the thread pool. `cache` null: a cache of its own (StageCache's sizes).
    explicit StageScheduler(QObject* parent = nullptr, std::shared_ptr<Executor> executor = {},
                            std::shared_ptr<analysis::pipeline::StageCache> cache = {});
    ~StageScheduler() override;

    /// Asks for `slot` computed under `key` by `work`. Nothing happens when the slot already
    /// computes or shows `key`; a cached result is delivered at once (finished() emitted).
    /// `stage`: see TypedSlot.
    void request(int slot, analysis::pipeline::StageKey key, StageWork work, std::optional<analysis::pipeline::Stage> stage = std::nullopt);
    template <class T> void request(TypedSlot<T> slot, analysis::pipeline::StageKey key, std::type_identity_t<TypedWork<T>> work)
    {
        request(
            slot.id, key,
            [work = std::move(work)](const analysis::RunControl& control) -> analysis::Result<StageValue> {
                auto result = work(control);
                if (!result) return result.error();
                return StageValue(std::move(result).value());
            },
            slot.stage);
    }
    /// Nothing to compute for `slot` (no input): cancels it and forgets its result.
    void clear(int slot);
    /// Cancels every job (closing): nothing more is delivered.
    void cancelAll();

    /// The slot's result for its current key, null while computing or after a failure.
    template <class T> std::shared_ptr<const T> result(int slot) const { return std::static_pointer_cast<const T>(value(slot)); }
    template <class T> std::shared_ptr<const T> result(TypedSlot<T> slot) const { return result<T>(slot.id); }
    StageValue value(int slot) const;
    analysis::pipeline::StageKey key(int slot) const;
    SlotState state(int slot) const;
    QString error(int slot) const;
    double progress(int slot) const;
    bool busy() const;
    /// Threads each job may use where its stage splits into cells or channels
    /// (analysis::RunControl::threads); default one per hardware thread, as `bunraku analyse`.
    void setThreads(int threads);
    int threads() const { return m_threads; }
    /// Jobs started per slot (tests: a slot that was not restarted; a slot that waited for
    /// another's job or took a cached result started none).
    int starts(int slot) const;
    analysis::pipeline::StageCache& cache() { return *m_cache; }

signals:
    void finished(int slot);
    void failed(int slot, const QString& message);
    void stateChanged(int slot);
    void progressChanged(int slot, double fraction);

private:
    struct Slot {
        analysis::pipeline::StageKey key;
        std::optional<analysis::pipeline::Stage> stage; ///< where its results are filed in the cache
        quint64 job = 0; ///< id of the job computing `key`, 0 when none runs
        std::shared_ptr<std::stop_source> stop;
        StageValue value;
        SlotState state = SlotState::Idle;
        QString error;
        double progress = 0.0;
        int starts = 0;
    };
    void deliver(quint64 job, analysis::pipeline::StageKey key, std::optional<analysis::pipeline::Stage> stage,
                 analysis::Result<StageValue> result);
    /// Leaves the slot's job (stopped when no other slot waits for it).
    void release(int slotId, Slot& slot);

    std::shared_ptr<Executor> m_executor;
    std::shared_ptr<analysis::pipeline::StageCache> m_cache;
    std::map<int, Slot> m_slots;
    quint64 m_nextJob = 0;
    /// Shared with running jobs: false once this scheduler is gone (their results are dropped).
    std::shared_ptr<std::atomic<bool>> m_alive;
    int m_threads = 1;
};

} // namespace bunraku::app
