#include "widgets/elided_label.h"

#include <QPainter>
#include <QStyle>

#include <algorithm>

namespace bunraku::widgets {

ElidedLabel::ElidedLabel(QWidget* parent) : QLabel(parent)
{
    setTextFormat(Qt::PlainText);
    setWordWrap(false);
    setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
}

QString ElidedLabel::shownText() const
{
    const int width = contentsRect().width() - 2 * margin() - 2 * std::max(0, indent());
    return fontMetrics().elidedText(text(), Qt::ElideRight, std::max(0, width));
}

QSize ElidedLabel::minimumSizeHint() const { return QSize(0, QLabel::minimumSizeHint().height()); }

void ElidedLabel::paintEvent(QPaintEvent*)
{
    updateToolTip(); // QLabel::setText is not virtual: a new text is first seen here
    QPainter painter(this);
    const QRect area = contentsRect().adjusted(margin(), margin(), -margin(), -margin());
    style()->drawItemText(&painter, area, int(alignment()) | Qt::TextSingleLine, palette(), isEnabled(), shownText(), foregroundRole());
}

void ElidedLabel::resizeEvent(QResizeEvent* event)
{
    QLabel::resizeEvent(event);
    updateToolTip();
}

void ElidedLabel::updateToolTip() { setToolTip(shownText() == text() ? QString() : text()); }

} // namespace bunraku::widgets
