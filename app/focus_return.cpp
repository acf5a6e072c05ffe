#include "app/focus_return.h"

#include <QAbstractButton>
#include <QAbstractItemView>
#include <QAbstractSlider>
#include <QAbstractSpinBox>
#include <QApplication>
#include <QComboBox>
#include <QFocusEvent>
#include <QKeyEvent>
#include <QLineEdit>
#include <QMouseEvent>
#include <QTabBar>
#include <QTimer>

namespace bunraku::app {

namespace {

/// The control `widget` belongs to: itself, or the spin box or combo box whose line edit it is.
QWidget* controlOf(QWidget* widget)
{
    if (auto* spin = qobject_cast<QAbstractSpinBox*>(widget->parentWidget()); spin && qobject_cast<QLineEdit*>(widget)) return spin;
    if (auto* combo = qobject_cast<QComboBox*>(widget->parentWidget()); combo && qobject_cast<QLineEdit*>(widget)) return combo;
    return widget;
}

bool isClickControl(QWidget* widget)
{
    if (qobject_cast<QAbstractButton*>(widget) || qobject_cast<QAbstractSlider*>(widget) || qobject_cast<QTabBar*>(widget))
        return true;
    const auto* combo = qobject_cast<QComboBox*>(widget);
    return combo && !combo->isEditable();
}

/// Whether `control` just lost the focus to its own window (given back after a step of it) rather
/// than to another control the person went to.
bool focusReturnedToWindow(const QWidget* control)
{
    // When the focus moves, QApplication::focusWidget() is the new holder before the old one
    // sees its focus-out (where a spin box emits editingFinished).
    return control && QApplication::focusWidget() == control->window();
}

} // namespace

void endSeriesWhenEdited(QAbstractSpinBox* box, std::function<void()> endSeries)
{
    QObject::connect(box, &QAbstractSpinBox::editingFinished, box, [box, endSeries = std::move(endSeries)] {
        if (!focusReturnedToWindow(box)) endSeries();
    });
}

FocusReturn::FocusReturn(QWidget* window) : QObject(window), m_window(window) { qApp->installEventFilter(this); }

FocusReturn::~FocusReturn() { qApp->removeEventFilter(this); }

void FocusReturn::returnFrom(QWidget* control)
{
    if (!m_window || !control) return;
    QWidget* focus = QApplication::focusWidget();
    if (!focus || (focus != control && !control->isAncestorOf(focus))) return;
    if (auto* combo = qobject_cast<QComboBox*>(control); combo && combo->view() && combo->view()->isVisible()) return;
    m_window->setFocus(Qt::OtherFocusReason);
}

void FocusReturn::returnLater(QWidget* control)
{
    QTimer::singleShot(0, this, [this, guarded = QPointer<QWidget>(control)] { returnFrom(guarded); });
}

bool FocusReturn::eventFilter(QObject* watched, QEvent* event)
{
    const QEvent::Type type = event->type();
    if (type != QEvent::MouseButtonRelease && type != QEvent::Wheel && type != QEvent::KeyPress && type != QEvent::FocusIn)
        return false;
    auto* widget = qobject_cast<QWidget*>(watched);
    if (!widget || !m_window || widget->window() != m_window) return false; // dialogs and popups keep their focus
    QWidget* control = controlOf(widget);
    switch (type) {
    case QEvent::MouseButtonRelease:
        // A spin box's arrows (the release reaches the box; a click into its text reaches the
        // line edit, and the person is about to type).
        if (isClickControl(control) || (qobject_cast<QAbstractSpinBox*>(widget) != nullptr)) returnLater(control);
        break;
    case QEvent::Wheel:
        if (qobject_cast<QAbstractSpinBox*>(control) || isClickControl(control)) returnLater(control);
        break;
    case QEvent::KeyPress: {
        const int key = static_cast<QKeyEvent*>(event)->key();
        if ((key == Qt::Key_Return || key == Qt::Key_Enter || key == Qt::Key_Escape) &&
            (qobject_cast<QAbstractSpinBox*>(control) || qobject_cast<QComboBox*>(control) || qobject_cast<QLineEdit*>(control)))
            returnLater(control);
        break;
    }
    case QEvent::FocusIn:
        // A combo box's list closed: the choice is made.
        if (static_cast<QFocusEvent*>(event)->reason() == Qt::PopupFocusReason && qobject_cast<QComboBox*>(control))
            returnLater(control);
        break;
    default: break;
    }
    return false;
}

} // namespace bunraku::app
