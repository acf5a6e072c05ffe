#pragma once
/// The playback clock: advances the document's time in real time times the speed factor,
/// loops or stops at the end, steps whole frames. Driven by the timeline's signals.

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

namespace bunraku::app {

class Document;

class PlaybackController : public QObject {
    Q_OBJECT
public:
    explicit PlaybackController(Document& document, QObject* parent = nullptr);

    void setPlaying(bool playing);
    bool playing() const { return m_timer.isActive(); }
    /// 0.1 to 4 (clamped).
    void setSpeed(double factor);
    double speed() const { return m_speed; }
    void setLooping(bool loop) { m_loop = loop; }
    bool looping() const { return m_loop; }

    /// Moves by whole frames of take A, from the frame nearest the current time.
    void step(int frames);
    void goToStart();
    void goToEnd();
    /// Advances the clock by `seconds` of wall time (what each timer tick does).
    void advance(double seconds);

signals:
    void playingChanged(bool playing);

private:
    void tick();

    Document& m_document;
    QTimer m_timer;
    QElapsedTimer m_clock;
    double m_speed = 1.0;
    bool m_loop = true;
};

} // namespace bunraku::app
