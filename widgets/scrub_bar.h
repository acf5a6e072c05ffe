#pragma once
/// A horizontal time bar: the take's duration, the current time as a handle, phrase boundaries
/// as ticks. Pressing or dragging on it requests a time (scrubbed); it never sets its own time.

#include <QWidget>

#include <vector>

namespace bunraku::widgets {

class ScrubBar : public QWidget {
    Q_OBJECT
public:
    explicit ScrubBar(QWidget* parent = nullptr);

    void setDuration(double seconds);
    void setTime(double seconds);
    /// Phrase boundaries, seconds, drawn as ticks above the bar.
    void setBoundaries(std::vector<double> seconds);

    double duration() const { return m_duration; }
    double time() const { return m_time; }
    const std::vector<double>& boundaries() const { return m_boundaries; }
    /// The time under the x pixel coordinate `x`, clamped to [0, duration].
    double timeAtX(int x) const;
    /// The x pixel coordinate of `seconds`.
    int xOfTime(double seconds) const;

    QSize sizeHint() const override { return {400, 34}; }

signals:
    void scrubbed(double seconds);

protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;

private:
    double m_duration = 1.0;
    double m_time = 0.0;
    std::vector<double> m_boundaries;
};

} // namespace bunraku::widgets
