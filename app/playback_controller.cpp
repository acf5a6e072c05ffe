#include "app/playback_controller.h"

#include "app/document.h"

#include <algorithm>
#include <cmath>

namespace bunraku::app {

PlaybackController::PlaybackController(Document& document, QObject* parent) : QObject(parent), m_document(document)
{
    m_timer.setInterval(15);
    m_timer.setTimerType(Qt::PreciseTimer);
    connect(&m_timer, &QTimer::timeout, this, &PlaybackController::tick);
}

void PlaybackController::setPlaying(bool playing)
{
    if (playing == this->playing()) return;
    if (playing) {
        if (m_document.duration() <= 0.0) return;
        if (m_document.currentTime() >= m_document.duration()) m_document.setCurrentTime(0.0);
        m_clock.start();
        m_timer.start();
    } else {
        m_timer.stop();
    }
    emit playingChanged(playing);
}

void PlaybackController::setSpeed(double factor) { m_speed = std::clamp(factor, 0.1, 4.0); }

void PlaybackController::step(int frames)
{
    const double rate = m_document.rateHz();
    const double frame = std::round(m_document.currentTime() * rate) + frames;
    m_document.setCurrentTime(std::max(0.0, frame) / rate);
}

void PlaybackController::goToStart() { m_document.setCurrentTime(0.0); }

void PlaybackController::goToEnd() { m_document.setCurrentTime(m_document.duration()); }

void PlaybackController::advance(double seconds)
{
    const double duration = m_document.duration();
    double time = m_document.currentTime() + seconds * m_speed;
    if (time >= duration) {
        if (m_loop && duration > 0.0) {
            time = std::fmod(time, duration);
        } else {
            m_document.setCurrentTime(duration);
            setPlaying(false);
            return;
        }
    }
    m_document.setCurrentTime(time);
}

void PlaybackController::tick() { advance(double(m_clock.restart()) / 1000.0); }

} // namespace bunraku::app
