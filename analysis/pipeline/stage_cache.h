#pragma once
/// Results of pipeline stages by key (stage_key.h), shared between threads: a stage whose key is
/// in the cache is not recomputed. Each stage keeps its few most recently used results (an undo
/// of a parameter change finds the previous result). Counters say how often each stage really
/// ran, for benchmarks and tests.

#include "analysis/pipeline/stage_key.h"
#include "analysis/pipeline/stages.h"

#include <array>
#include <atomic>
#include <map>
#include <memory>
#include <mutex>

namespace bunraku::analysis::pipeline {

class StageCache {
public:
    /// Results kept per stage (least recently used dropped first).
    explicit StageCache(std::size_t entriesPerStage = 4) : m_entriesPerStage(entriesPerStage) {}

    template <class T> Shared<T> find(Stage stage, StageKey key) const
    {
        return std::static_pointer_cast<const T>(findAny(stage, key));
    }
    template <class T> void store(Stage stage, StageKey key, Shared<T> value)
    {
        storeAny(stage, key, std::static_pointer_cast<const void>(std::move(value)));
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
    std::shared_ptr<const void> findAny(Stage stage, StageKey key) const;
    void storeAny(Stage stage, StageKey key, std::shared_ptr<const void> value);

    std::size_t m_entriesPerStage;
    mutable std::mutex m_mutex;
    mutable std::map<std::pair<int, std::uint64_t>, Entry> m_entries;
    mutable std::uint64_t m_clock = 0;
    std::array<std::atomic<int>, kStageCount> m_runs{};
};

} // namespace bunraku::analysis::pipeline
