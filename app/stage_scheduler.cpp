#include "app/stage_scheduler.h"

#include "analysis/core/parallel.h"

#include <QMetaObject>
#include <QPointer>
#include <QRunnable>
#include <QThreadPool>

#include <algorithm>
#include <exception>
#include <memory>
#include <vector>

namespace bunraku::app {

using analysis::pipeline::StageKey;

#if defined(__has_feature)
#if __has_feature(thread_sanitizer)
#define BUNRAKU_STAGE_TSAN 1
#endif
#endif
#ifdef BUNRAKU_STAGE_TSAN
extern "C" void __tsan_acquire(void* address);
extern "C" void __tsan_release(void* address);
#endif

void ThreadPoolExecutor::run(std::function<void()> work)
{
    // The job goes to the worker through QThreadPool's queue, ordered by a futex mutex inside Qt
    // that ThreadSanitizer does not see (Qt is not instrumented): the release and acquire tell it
    // of that order, so the job's inputs made here are not reported as racing with the worker
    // reading them (scripts/tsan.sh, tests/tsan_qt.supp). No code in other builds.
    auto* job = new std::function<void()>(std::move(work));
#ifdef BUNRAKU_STAGE_TSAN
    __tsan_release(job);
#endif
    QThreadPool::globalInstance()->start([job] {
#ifdef BUNRAKU_STAGE_TSAN
        __tsan_acquire(job);
#endif
        const std::unique_ptr<std::function<void()>> owned(job);
        (*owned)();
    });
}

StageScheduler::StageScheduler(QObject* parent, std::shared_ptr<Executor> executor,
                               std::shared_ptr<analysis::pipeline::StageCache> cache)
    : QObject(parent),
      m_executor(executor ? std::move(executor) : std::make_shared<ThreadPoolExecutor>()),
      m_cache(cache ? std::move(cache) : std::make_shared<analysis::pipeline::StageCache>()),
      m_alive(std::make_shared<std::atomic<bool>>(true)),
      m_threads(analysis::resolveThreads(0))
{
}

void StageScheduler::setThreads(int threads)
{
    m_threads = analysis::resolveThreads(threads);
}

StageScheduler::~StageScheduler()
{
    // Running jobs hold copies of their inputs only; they see the stop request at their next
    // check and their results are dropped. Closing never waits for them.
    cancelAll();
    *m_alive = false;
}

void StageScheduler::release(int slotId, Slot& slot)
{
    // The job's inputs are no longer this slot's: it stops unless another slot still waits for it.
    if (slot.job != 0 && slot.stop) {
        const bool shared = std::any_of(m_slots.begin(), m_slots.end(),
                                        [&](const auto& other) { return other.first != slotId && other.second.job == slot.job; });
        if (!shared) slot.stop->request_stop();
    }
    slot.job = 0;
    slot.stop.reset();
}

void StageScheduler::request(int slotId, StageKey key, StageWork work, std::optional<analysis::pipeline::Stage> stage)
{
    Slot& slot = m_slots[slotId];
    if (slot.key == key && (slot.job != 0 || slot.state == SlotState::Finished || slot.state == SlotState::Failed)) return;
    release(slotId, slot); // its inputs changed: the running job is of no use to it
    slot.key = key;
    slot.stage = stage;
    slot.value.reset();
    slot.error.clear();
    slot.progress = 0.0;
    // A key names its result (a stage's key is seeded with the stage's name): any slot asking
    // for a key finds what any slot, or the stage run elsewhere on the same cache, computed.
    if (StageValue cached = m_cache->find<void>(stage, key)) {
        slot.value = std::move(cached);
        slot.state = SlotState::Finished;
        slot.progress = 1.0;
        // Announced from the event loop, as computed results are: the caller may be in the
        // middle of requesting several slots.
        QPointer<StageScheduler> self(this);
        QMetaObject::invokeMethod(
            this,
            [self, slotId, key] {
                if (!self) return;
                const auto found = self->m_slots.find(slotId);
                if (found == self->m_slots.end() || !(found->second.key == key) || found->second.state != SlotState::Finished) return;
                emit self->stateChanged(slotId);
                emit self->finished(slotId);
            },
            Qt::QueuedConnection);
        return;
    }
    // Another slot computing the same key already: wait for its job instead of starting one.
    for (auto& [otherId, other] : m_slots) {
        if (otherId == slotId || other.job == 0 || !(other.key == key)) continue;
        slot.job = other.job;
        slot.stop = other.stop;
        slot.state = SlotState::Running;
        slot.progress = other.progress;
        emit stateChanged(slotId);
        emit progressChanged(slotId, slot.progress);
        return;
    }
    const quint64 job = ++m_nextJob;
    slot.job = job;
    slot.stop = std::make_shared<std::stop_source>();
    slot.state = SlotState::Running;
    ++slot.starts;
    emit stateChanged(slotId);
    emit progressChanged(slotId, 0.0);
    QPointer<StageScheduler> self(this);
    auto alive = m_alive;
    auto stop = slot.stop;
    m_executor->run([self, alive, stop, job, key, stage, threads = m_threads, work = std::move(work)] {
        analysis::RunControl control{stop->get_token(), [self, alive, job](double fraction) {
                                         if (!*alive) return;
                                         QMetaObject::invokeMethod(
                                             self.data(),
                                             [self, job, fraction] {
                                                 if (!self) return;
                                                 for (auto& [id, waiting] : self->m_slots) {
                                                     if (waiting.job != job) continue;
                                                     waiting.progress = fraction;
                                                     emit self->progressChanged(id, fraction);
                                                 }
                                             },
                                             Qt::QueuedConnection);
                                     },
                                     threads};
        analysis::Result<StageValue> result = analysis::makeError(analysis::ErrorCode::Cancelled, "not run");
        try {
            result = work(control);
        } catch (const std::exception& error) {
            result = analysis::makeError(analysis::ErrorCode::Numerical, error.what());
        } catch (...) {
            result = analysis::makeError(analysis::ErrorCode::Numerical, "unknown error");
        }
        if (!*alive) return;
        QMetaObject::invokeMethod(
            self.data(),
            [self, job, key, stage, result = std::move(result)]() mutable {
                if (self) self->deliver(job, key, stage, std::move(result));
            },
            Qt::QueuedConnection);
    });
}

void StageScheduler::deliver(quint64 job, StageKey key, std::optional<analysis::pipeline::Stage> stage, analysis::Result<StageValue> result)
{
    // A stage function stored its result already; storing it again marks it the most recent.
    if (result.ok()) m_cache->store<void>(stage, key, *result);
    // Every slot still waiting for this job; a job whose inputs changed meanwhile (or that was
    // cleared) has none and is never shown.
    std::vector<int> waiting;
    for (const auto& [id, slot] : m_slots)
        if (slot.job == job && slot.key == key) waiting.push_back(id);
    for (int slotId : waiting) {
        Slot& slot = m_slots[slotId];
        slot.job = 0;
        slot.stop.reset();
        if (!result.ok()) {
            slot.state = SlotState::Failed;
            slot.error = QString::fromStdString(result.error().message);
        } else {
            slot.value = *result;
            slot.state = SlotState::Finished;
            slot.progress = 1.0;
        }
    }
    // Signals after every waiting slot is updated: a receiver may request again.
    for (int slotId : waiting) {
        const auto found = m_slots.find(slotId);
        if (found == m_slots.end() || !(found->second.key == key)) continue;
        if (found->second.state == SlotState::Failed) {
            emit stateChanged(slotId);
            emit failed(slotId, found->second.error);
        } else if (found->second.state == SlotState::Finished) {
            emit progressChanged(slotId, 1.0);
            emit stateChanged(slotId);
            emit finished(slotId);
        }
    }
}

void StageScheduler::clear(int slotId)
{
    auto found = m_slots.find(slotId);
    if (found == m_slots.end()) return;
    Slot& slot = found->second;
    release(slotId, slot);
    const bool wasShown = slot.state != SlotState::Idle;
    const int starts = slot.starts; // kept: counts every job the slot started
    slot = Slot{};
    slot.starts = starts;
    if (wasShown) emit stateChanged(slotId);
}

void StageScheduler::cancelAll()
{
    for (auto& [id, slot] : m_slots) {
        if (slot.stop) slot.stop->request_stop();
        slot.job = 0;
        slot.stop.reset();
        if (slot.state == SlotState::Running) slot.state = SlotState::Idle;
    }
}

StageValue StageScheduler::value(int slot) const
{
    const auto found = m_slots.find(slot);
    return found == m_slots.end() || found->second.state != SlotState::Finished ? nullptr : found->second.value;
}

StageKey StageScheduler::key(int slot) const
{
    const auto found = m_slots.find(slot);
    return found == m_slots.end() ? StageKey{} : found->second.key;
}

SlotState StageScheduler::state(int slot) const
{
    const auto found = m_slots.find(slot);
    return found == m_slots.end() ? SlotState::Idle : found->second.state;
}

QString StageScheduler::error(int slot) const
{
    const auto found = m_slots.find(slot);
    return found == m_slots.end() ? QString() : found->second.error;
}

double StageScheduler::progress(int slot) const
{
    const auto found = m_slots.find(slot);
    return found == m_slots.end() ? 0.0 : found->second.progress;
}

bool StageScheduler::busy() const
{
    for (const auto& [id, slot] : m_slots)
        if (slot.state == SlotState::Running) return true;
    return false;
}

int StageScheduler::starts(int slot) const
{
    const auto found = m_slots.find(slot);
    return found == m_slots.end() ? 0 : found->second.starts;
}

} // namespace bunraku::app
