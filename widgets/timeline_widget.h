#pragma once
/// The transport: play/pause (Space), step a frame (Left/Right), start/end (Home/End), loop,
/// speed 0.1x-4x, the scrub bar with phrase boundaries and the time read-out. It only shows
/// state and requests changes through signals; the playback clock lives in the app. Its
/// actions carry window-wide shortcuts so the main window can also put them in a menu.

#include <QWidget>

#include <vector>

class QAction;
class QDoubleSpinBox;
class QLabel;

namespace bunraku::widgets {

class ScrubBar;

class TimelineWidget : public QWidget {
    Q_OBJECT
public:
    explicit TimelineWidget(QWidget* parent = nullptr);

    /// The length of the longer shown take (seconds) and its frame rate (Hz).
    void setDuration(double seconds, double rateHz);
    void setTime(double seconds);
    void setPlaying(bool playing);
    void setBoundaries(std::vector<double> seconds);
    void setSpeed(double factor);
    void setLooping(bool loop);

    double speed() const;
    bool looping() const;
    ScrubBar* scrubBar() const { return m_bar; }
    QAction* playAction() const { return m_play; }
    QAction* stepBackAction() const { return m_stepBack; }
    QAction* stepForwardAction() const { return m_stepForward; }
    QAction* homeAction() const { return m_home; }
    QAction* endAction() const { return m_end; }
    QAction* loopAction() const { return m_loop; }

signals:
    void playToggled(bool play);
    /// Move by `frames` (negative: back).
    void stepRequested(int frames);
    void homeRequested();
    void endRequested();
    void loopToggled(bool loop);
    void speedChanged(double factor);
    void timeScrubbed(double seconds);

public:
    /// The time read-out (its width is fixed per duration, so the scrub bar never moves).
    QLabel* timeLabel() const { return m_label; }
    QDoubleSpinBox* speedBox() const { return m_speed; }

private:
    QString timeText(double seconds) const;
    void updateLabel();
    void fitLabelWidth();

    ScrubBar* m_bar = nullptr;
    QLabel* m_label = nullptr;
    QDoubleSpinBox* m_speed = nullptr;
    QAction* m_play = nullptr;
    QAction* m_stepBack = nullptr;
    QAction* m_stepForward = nullptr;
    QAction* m_home = nullptr;
    QAction* m_end = nullptr;
    QAction* m_loop = nullptr;
    double m_duration = 0.0;
    double m_rateHz = 5.0;
    double m_time = 0.0;
};

} // namespace bunraku::widgets
