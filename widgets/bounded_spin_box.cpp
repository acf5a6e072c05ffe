#include "widgets/bounded_spin_box.h"

#include <QKeyEvent>
#include <QLineEdit>
#include <QRegularExpression>

#include <algorithm>
#include <optional>

namespace bunraku::widgets {

namespace {

/// The integer typed in `text` (prefix and suffix removed), however large; nullopt otherwise.
std::optional<qlonglong> typedNumber(const QString& text)
{
    static const QRegularExpression number(QStringLiteral("^\\s*([+-]?\\d{1,12})\\s*$"));
    const auto match = number.match(text);
    if (!match.hasMatch()) return std::nullopt;
    return match.captured(1).toLongLong();
}

} // namespace

BoundedSpinBox::BoundedSpinBox(QWidget* parent) : QSpinBox(parent)
{
    setKeyboardTracking(false);
    connect(this, &QSpinBox::valueChanged, this, [this] { updateToolTip(); });
}

void BoundedSpinBox::setDescription(const QString& description)
{
    m_description = description;
    updateToolTip();
}

QString BoundedSpinBox::limitsText() const
{
    return tr("From %1 to %2%3.").arg(minimum()).arg(maximum()).arg(suffix());
}

void BoundedSpinBox::setLimits(int minimum, int maximum)
{
    setRange(minimum, maximum);
    updateToolTip();
}

void BoundedSpinBox::updateToolTip()
{
    setToolTip(m_description.isEmpty() ? limitsText() : m_description + QLatin1Char(' ') + limitsText());
}

QValidator::State BoundedSpinBox::validate(QString& input, int& position) const
{
    const QValidator::State state = QSpinBox::validate(input, position);
    if (state != QValidator::Invalid) return state;
    // A number beyond the limits may be typed in full; it is clamped when applied.
    QString text = input;
    if (!prefix().isEmpty() && text.startsWith(prefix())) text.remove(0, prefix().size());
    if (!suffix().isEmpty() && text.endsWith(suffix())) text.chop(suffix().size());
    return typedNumber(text) ? QValidator::Intermediate : QValidator::Invalid;
}

void BoundedSpinBox::clampTyped()
{
    const auto requested = typedNumber(cleanText());
    if (!requested || (*requested >= minimum() && *requested <= maximum())) return;
    const int applied = int(std::clamp<qlonglong>(*requested, minimum(), maximum()));
    setValue(applied);
    lineEdit()->setText(textFromValue(applied).prepend(prefix()).append(suffix()));
    emit clamped(int(std::clamp<qlonglong>(*requested, -2147483647LL, 2147483647LL)), applied);
}

void BoundedSpinBox::keyPressEvent(QKeyEvent* event)
{
    if (event->key() == Qt::Key_Return || event->key() == Qt::Key_Enter) clampTyped();
    QSpinBox::keyPressEvent(event);
}

void BoundedSpinBox::focusOutEvent(QFocusEvent* event)
{
    clampTyped();
    QSpinBox::focusOutEvent(event);
}

} // namespace bunraku::widgets
