#pragma once
/// Keyboard focus goes back to the window once a control has been set, so the window's keys
/// (Space plays, Home goes to the start, F frames the 3D view...) work again at once, as in
/// Blender or MotionBuilder. A text field keeps the focus while it is being edited: clicking
/// into a spin box's text to type keeps it there until Enter (or Escape, or a click elsewhere).
///
///  - buttons, check boxes, sliders, tab bars and closed combo boxes: after a click (and after
///    a combo box's list closes);
///  - spin boxes: after a click on their arrows, a wheel step, or Enter in their text;
///  - editable combo boxes and line edits of the window: after Enter.
/// Dialogs are left alone. It filters the application's events for one window.

#include <QObject>
#include <QPointer>

#include <functional>

class QAbstractSpinBox;
class QWidget;

namespace bunraku::app {

/// Calls `endSeries` (Document::endStepSeries) when `box`'s editing is finished by the person -
/// Enter, or a move to another control - and not when the focus was only given back to the
/// window after a step of it: two arrow clicks merge into one undo step as two key presses do.
/// Connected for `box`'s lifetime.
void endSeriesWhenEdited(QAbstractSpinBox* box, std::function<void()> endSeries);

class FocusReturn : public QObject {
    Q_OBJECT
public:
    /// Watches the controls of `window` (now and later); focus returns to `window`.
    explicit FocusReturn(QWidget* window);
    ~FocusReturn() override;

    /// Gives the focus back to the window now when `control` (or a child of it) holds it.
    void returnFrom(QWidget* control);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    /// returnFrom(control) once the current event has been handled.
    void returnLater(QWidget* control);

    QPointer<QWidget> m_window;
};

} // namespace bunraku::app
