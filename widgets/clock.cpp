#include "widgets/clock.h"

#include <QElapsedTimer>

#include <algorithm>

namespace bunraku::widgets {

class SteadyClock final : public Clock {
public:
    SteadyClock() { m_elapsed.start(); }
    qint64 milliseconds() const override { return m_elapsed.elapsed(); }

protected:
    void arm(ClockTimer* timer, int delayMs) override { timer->m_timer.start(delayMs); }
    void disarm(ClockTimer* timer) override { timer->m_timer.stop(); }

private:
    QElapsedTimer m_elapsed;
};

Clock& steadyClock()
{
    static SteadyClock clock;
    return clock;
}

void ManualClock::advance(qint64 ms)
{
    const qint64 end = m_now + ms;
    while (true) {
        m_armed.erase(std::remove_if(m_armed.begin(), m_armed.end(), [](const Armed& a) { return a.timer.isNull(); }), m_armed.end());
        auto next = std::min_element(m_armed.begin(), m_armed.end(), [](const Armed& a, const Armed& b) { return a.due < b.due; });
        if (next == m_armed.end() || next->due > end) break;
        m_now = std::max(m_now, next->due);
        const QPointer<ClockTimer> timer = next->timer;
        m_armed.erase(next);
        if (timer) timer->fire();
    }
    m_now = end;
}

void ManualClock::arm(ClockTimer* timer, int delayMs)
{
    disarm(timer);
    m_armed.push_back({timer, m_now + delayMs});
}

void ManualClock::disarm(ClockTimer* timer)
{
    m_armed.erase(std::remove_if(m_armed.begin(), m_armed.end(), [timer](const Armed& a) { return a.timer == timer; }),
                  m_armed.end());
}

ClockTimer::ClockTimer(QObject* parent) : QObject(parent), m_clock(&steadyClock())
{
    m_timer.setSingleShot(true);
    // Precise: a coarse timer may fire a few milliseconds early, before the clock says it is due.
    m_timer.setTimerType(Qt::PreciseTimer);
    connect(&m_timer, &QTimer::timeout, this, &ClockTimer::fire);
}

ClockTimer::~ClockTimer()
{
    if (m_active) m_clock->disarm(this);
}

void ClockTimer::setClock(Clock* clock)
{
    if (clock == nullptr) clock = &steadyClock();
    if (clock == m_clock) return;
    const bool active = m_active;
    stop();
    m_clock = clock;
    if (active) start();
}

void ClockTimer::start()
{
    m_active = true;
    m_clock->arm(this, m_interval);
}

void ClockTimer::stop()
{
    if (!m_active) return;
    m_active = false;
    m_clock->disarm(this);
}

void ClockTimer::fire()
{
    if (!m_active) return;
    m_active = false;
    emit timeout();
}

} // namespace bunraku::widgets
