#include "widgets/timeline_widget.h"

#include "widgets/scrub_bar.h"

#include <QAction>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QStyle>
#include <QToolButton>
#include <QVBoxLayout>

#include <cmath>

namespace bunraku::widgets {
namespace {

QAction* makeAction(QWidget* owner, const QString& text, QStyle::StandardPixmap icon, const QKeySequence& key)
{
    auto* action = new QAction(owner->style()->standardIcon(icon), text, owner);
    action->setShortcut(key);
    action->setShortcutContext(Qt::WindowShortcut);
    action->setToolTip(QStringLiteral("%1 (%2)").arg(text, key.toString(QKeySequence::NativeText)));
    owner->addAction(action);
    return action;
}

QToolButton* buttonFor(QAction* action)
{
    auto* button = new QToolButton;
    button->setDefaultAction(action);
    button->setFocusPolicy(Qt::NoFocus);
    button->setAutoRaise(true);
    return button;
}

} // namespace

TimelineWidget::TimelineWidget(QWidget* parent) : QWidget(parent)
{
    m_home = makeAction(this, tr("Go to start"), QStyle::SP_MediaSkipBackward, QKeySequence(Qt::Key_Home));
    m_stepBack = makeAction(this, tr("Previous frame"), QStyle::SP_MediaSeekBackward, QKeySequence(Qt::Key_Left));
    m_play = makeAction(this, tr("Play"), QStyle::SP_MediaPlay, QKeySequence(Qt::Key_Space));
    m_play->setCheckable(true);
    m_stepForward = makeAction(this, tr("Next frame"), QStyle::SP_MediaSeekForward, QKeySequence(Qt::Key_Right));
    m_end = makeAction(this, tr("Go to end"), QStyle::SP_MediaSkipForward, QKeySequence(Qt::Key_End));
    m_loop = makeAction(this, tr("Loop"), QStyle::SP_BrowserReload, QKeySequence(Qt::Key_L));
    m_loop->setCheckable(true);
    m_loop->setChecked(true);

    m_bar = new ScrubBar(this);
    m_label = new QLabel(this);
    m_label->setMinimumWidth(170);
    m_label->setObjectName("timeLabel");
    m_speed = new QDoubleSpinBox(this);
    m_speed->setRange(0.1, 4.0);
    m_speed->setSingleStep(0.1);
    m_speed->setDecimals(1);
    m_speed->setValue(1.0);
    m_speed->setSuffix(QStringLiteral("x"));
    m_speed->setToolTip(tr("Playback speed"));

    auto* row = new QHBoxLayout;
    row->setContentsMargins(0, 0, 0, 0);
    for (auto* action : {m_home, m_stepBack, m_play, m_stepForward, m_end, m_loop}) row->addWidget(buttonFor(action));
    row->addWidget(m_speed);
    row->addWidget(m_bar, 1);
    row->addWidget(m_label);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 2, 4, 2);
    layout->addLayout(row);
    setSizePolicy(QSizePolicy::Preferred, QSizePolicy::Fixed);

    connect(m_play, &QAction::toggled, this, [this](bool play) {
        m_play->setIcon(style()->standardIcon(play ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
        m_play->setText(play ? tr("Pause") : tr("Play"));
        emit playToggled(play);
    });
    connect(m_stepBack, &QAction::triggered, this, [this] { emit stepRequested(-1); });
    connect(m_stepForward, &QAction::triggered, this, [this] { emit stepRequested(1); });
    connect(m_home, &QAction::triggered, this, &TimelineWidget::homeRequested);
    connect(m_end, &QAction::triggered, this, &TimelineWidget::endRequested);
    connect(m_loop, &QAction::toggled, this, &TimelineWidget::loopToggled);
    connect(m_speed, &QDoubleSpinBox::valueChanged, this, &TimelineWidget::speedChanged);
    connect(m_bar, &ScrubBar::scrubbed, this, &TimelineWidget::timeScrubbed);
    updateLabel();
}

void TimelineWidget::setDuration(double seconds, double rateHz)
{
    m_duration = seconds;
    m_rateHz = rateHz > 0.0 ? rateHz : 1.0;
    m_bar->setDuration(seconds);
    updateLabel();
}

void TimelineWidget::setTime(double seconds)
{
    m_time = seconds;
    m_bar->setTime(seconds);
    updateLabel();
}

void TimelineWidget::setPlaying(bool playing)
{
    if (m_play->isChecked() == playing) return;
    const QSignalBlocker block(m_play);
    m_play->setChecked(playing);
    m_play->setIcon(style()->standardIcon(playing ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
    m_play->setText(playing ? tr("Pause") : tr("Play"));
}

void TimelineWidget::setBoundaries(std::vector<double> seconds) { m_bar->setBoundaries(std::move(seconds)); }

void TimelineWidget::setSpeed(double factor) { m_speed->setValue(factor); }
void TimelineWidget::setLooping(bool loop) { m_loop->setChecked(loop); }
double TimelineWidget::speed() const { return m_speed->value(); }
bool TimelineWidget::looping() const { return m_loop->isChecked(); }

void TimelineWidget::updateLabel()
{
    const auto frame = std::lround(m_time * m_rateHz);
    const auto last = std::lround(m_duration * m_rateHz);
    m_label->setText(tr("%1 s / %2 s   frame %3 / %4")
                         .arg(m_time, 0, 'f', 2)
                         .arg(m_duration, 0, 'f', 2)
                         .arg(frame)
                         .arg(last));
}

} // namespace bunraku::widgets
