#pragma once
/// Results of pipeline stages by key (stage_key.h), shared between threads: a stage whose key is
/// in the cache is not recomputed. Each stage keeps its few most recently used results (an undo
/// of a parameter change finds the previous result). Results that are no stage's (no `stage`:
/// the workbench's take axes, kimonos and live bodies, app/stage_scheduler.h) are kept apart, more
/// of them. Counters say how often each stage really ran, for benchmarks and tests.

#include "analysis/pipeline/stage_key.h"
#include "analysis/pipeline/stages.h"

#include <array>
#include <atomic>
#include <map>
#include <memory>
#include <mutex>
#include <optional>

namespace bunraku::analysis::pipeline {

class StageCache {
public:
    /// Results kept per stage, and of the results that are no stage's (least recently used
    /// dropped first).
    explicit StageCache(std::size_t entriesPerStage = 4, std::size_t otherEntries = 32)
        : m_entriesPerStage(entriesPerStage), m_otherEntries(otherEntries)
    {
    }

    /// `stage` none: a result that is no stage's.
    template <class T> Shared<T> find(std::optional<Stage> stage, StageKey key) const
    {
        return std::static_pointer_cast<const T>(findAny(group(stage), key));
    }
    template <class T> void store(std::optional<Stage> stage, StageKey key, Shared<T> value)
    {
        storeAny(group(stage), key, std::static_pointer_cast<const void>(std::move(value)));
    }

    void countRun(Stage stage) { ++m_runs[std::size_t(stage)]; }
    /// Times `stage` was computed (not found in the cache) since the last reset.
    int runs(Stage stage) const { return m_runs[std::size_t(stage)].load(); }
    void resetCounters();
    void clear();

private:
    struct Entry {
        std::shared_ptr<const void> value;
        std::uint64_t lastUse = 0;
    };
    static int group(std::optional<Stage> stage) { return stage ? int(*stage) : int(kStageCount); }
    std::shared_ptr<const void> findAny(int group, StageKey key) const;
    void storeAny(int group, StageKey key, std::shared_ptr<const void> value);

    std::size_t m_entriesPerStage;
    std::size_t m_otherEntries;
    mutable std::mutex m_mutex;
    mutable std::map<std::pair<int, std::uint64_t>, Entry> m_entries;
    mutable std::uint64_t m_clock = 0;
    std::array<std::atomic<int>, kStageCount> m_runs{};
};

} // namespace bunraku::analysis::pipeline
