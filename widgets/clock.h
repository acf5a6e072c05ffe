#pragma once
/// Time for views that react to how quickly things follow each other (the 3D view's still frame
/// after 150 ms, the graphs' 250 ms burst of data changes, undo steps of one control merging
/// within 1 s): they read a Clock and wait with a ClockTimer, so tests inject a ManualClock and
/// move time by hand instead of depending on wall-clock windows.

#include <QObject>
#include <QPointer>
#include <QTimer>

#include <vector>

namespace bunraku::widgets {

class ClockTimer;

class Clock {
public:
    virtual ~Clock() = default;
    /// Milliseconds of a monotonic time line (any origin).
    virtual qint64 milliseconds() const = 0;

protected:
    friend class ClockTimer;
    /// ClockTimer's hooks: arm `timer` to fire `delayMs` from now, or disarm it.
    virtual void arm(ClockTimer* timer, int delayMs) = 0;
    virtual void disarm(ClockTimer* timer) = 0;
};

/// The process's monotonic clock; timers are precise QTimers.
Clock& steadyClock();

/// A clock that stands still until advance(): its timers fire inside advance(), in due order.
class ManualClock final : public Clock {
public:
    qint64 milliseconds() const override { return m_now; }
    /// Moves time forward by `ms`, firing every timer that falls due on the way.
    void advance(qint64 ms);

protected:
    void arm(ClockTimer* timer, int delayMs) override;
    void disarm(ClockTimer* timer) override;

private:
    struct Armed {
        QPointer<ClockTimer> timer;
        qint64 due = 0;
    };
    qint64 m_now = 0;
    std::vector<Armed> m_armed;
};

/// A single-shot timer on a Clock (the steady clock unless setClock is called).
class ClockTimer : public QObject {
    Q_OBJECT
public:
    explicit ClockTimer(QObject* parent = nullptr);
    ~ClockTimer() override;

    void setClock(Clock* clock);
    void setInterval(int milliseconds) { m_interval = milliseconds; }
    int interval() const { return m_interval; }
    /// (Re)starts: timeout() after interval() on the clock.
    void start();
    void stop();
    bool isActive() const { return m_active; }

signals:
    void timeout();

private:
    friend class ManualClock;
    friend class SteadyClock;
    void fire();

    Clock* m_clock;
    QTimer m_timer; ///< the steady clock's
    int m_interval = 0;
    bool m_active = false;
};

} // namespace bunraku::widgets
