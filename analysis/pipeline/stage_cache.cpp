#include "analysis/pipeline/stage_cache.h"

namespace bunraku::analysis::pipeline {

std::shared_ptr<const void> StageCache::findAny(Stage stage, StageKey key) const
{
    const std::lock_guard lock(m_mutex);
    const auto found = m_entries.find({int(stage), key.value});
    if (found == m_entries.end()) return nullptr;
    found->second.lastUse = ++m_clock;
    return found->second.value;
}

void StageCache::storeAny(Stage stage, StageKey key, std::shared_ptr<const void> value)
{
    const std::lock_guard lock(m_mutex);
    m_entries[{int(stage), key.value}] = Entry{std::move(value), ++m_clock};
    // Drop the least recently used results of this stage beyond the limit.
    for (;;) {
        std::size_t count = 0;
        auto oldest = m_entries.end();
        for (auto it = m_entries.begin(); it != m_entries.end(); ++it) {
            if (it->first.first != int(stage)) continue;
            ++count;
            if (oldest == m_entries.end() || it->second.lastUse < oldest->second.lastUse) oldest = it;
        }
        if (count <= m_entriesPerStage || oldest == m_entries.end()) return;
        m_entries.erase(oldest);
    }
}

void StageCache::resetCounters()
{
    for (auto& runs : m_runs) runs = 0;
}

void StageCache::clear()
{
    const std::lock_guard lock(m_mutex);
    m_entries.clear();
}

} // namespace bunraku::analysis::pipeline
