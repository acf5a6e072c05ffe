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
    m_label->setObjectName("timeLabel");
    m_speed = new QDoubleSpinBox(this);
    m_speed->setRange(0.1, 4.0);
    m_speed->setSingleStep(0.1);
    m_speed->setDecimals(1);
    m_speed->setValue(1.0);
    m_speed->setSuffix(QStringLiteral("x"));
    m_speed->setObjectName("playbackSpeed");
    m_speed->setToolTip(tr("Playback speed, %1x to %2x").arg(m_speed->minimum(), 0, 'f', 1).arg(m_speed->maximum(), 0, 'f', 1));

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
    fitLabelWidth();
    updateLabel();
}

void TimelineWidget::setDuration(double seconds, double rateHz)
{
    m_duration = seconds;
    m_rateHz = rateHz > 0.0 ? rateHz : 1.0;
    m_bar->setDuration(seconds);
    fitLabelWidth();
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

QString TimelineWidget::timeText(double seconds) const
{
    return tr("%1 s / %2 s   frame %3 / %4")
        .arg(seconds, 0, 'f', 2)
        .arg(m_duration, 0, 'f', 2)
        .arg(std::lround(seconds * m_rateHz))
        .arg(std::lround(m_duration * m_rateHz));
}

void TimelineWidget::updateLabel()
{
    m_label->setText(timeText(m_time));
}

void TimelineWidget::fitLabelWidth()
{
    // As wide as the widest text of this duration (every digit of the longest read-out made the
    // widest digit): the scrub bar beside it, and its ticks, never move while the time changes.
    const QFontMetrics metrics(m_label->font());
    QChar widest = QLatin1Char('0');
    for (char digit = '0'; digit <= '9'; ++digit)
        if (metrics.horizontalAdvance(QLatin1Char(digit)) > metrics.horizontalAdvance(widest)) widest = QLatin1Char(digit);
    QString longest = timeText(m_duration);
    for (QChar& c : longest)
        if (c.isDigit()) c = widest;
    m_label->setFixedWidth(metrics.horizontalAdvance(longest) + m_label->contentsMargins().left() +
                           m_label->contentsMargins().right() + 4);
}

} // namespace bunraku::widgets
