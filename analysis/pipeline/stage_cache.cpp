#include "analysis/pipeline/stage_cache.h"

namespace bunraku::analysis::pipeline {

std::shared_ptr<const void> StageCache::findAny(int group, StageKey key) const
{
    const std::lock_guard lock(m_mutex);
    const auto found = m_entries.find({group, key.value});
    if (found == m_entries.end()) return nullptr;
    found->second.lastUse = ++m_clock;
    return found->second.value;
}

void StageCache::storeAny(int group, StageKey key, std::shared_ptr<const void> value)
{
    const std::lock_guard lock(m_mutex);
    m_entries[{group, key.value}] = Entry{std::move(value), ++m_clock};
    // Drop the least recently used results of this stage (or of the others) beyond the limit.
    const std::size_t limit = group == int(kStageCount) ? m_otherEntries : m_entriesPerStage;
    for (;;) {
        std::size_t count = 0;
        auto oldest = m_entries.end();
        for (auto it = m_entries.begin(); it != m_entries.end(); ++it) {
            if (it->first.first != group) continue;
            ++count;
            if (oldest == m_entries.end() || it->second.lastUse < oldest->second.lastUse) oldest = it;
        }
        if (count <= limit || oldest == m_entries.end()) return;
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
