#pragma once
/// An integer spin box that says when it clamps: a typed value outside [minimum, maximum] can
/// be typed in full ("100" with a maximum of 60, where QSpinBox would refuse the last key and
/// silently keep "10"), and on Enter or when the box loses the focus it becomes the nearest
/// limit and `clamped` reports what was asked for and what was applied (the app says so in the
/// status bar). Typed values apply on Enter only (no keyboard tracking): "100" never applies 1
/// and 10 on the way. Its tool tip ends with its limits (setDescription).

#include <QSpinBox>

namespace bunraku::widgets {

class BoundedSpinBox : public QSpinBox {
    Q_OBJECT
public:
    explicit BoundedSpinBox(QWidget* parent = nullptr);

    /// The tool tip: `description`, then "From <min> to <max><suffix>." (kept up to date with
    /// the range).
    void setDescription(const QString& description);
    QString description() const { return m_description; }
    /// The limits as the tool tip states them: "From 1 to 60 frames."
    QString limitsText() const;
    /// setRange, the tool tip following (limits that depend on the data: a corpus's takes).
    void setLimits(int minimum, int maximum);

signals:
    /// A typed value outside the limits was replaced by the nearest limit.
    void clamped(int requested, int applied);

protected:
    QValidator::State validate(QString& input, int& position) const override;
    void keyPressEvent(QKeyEvent* event) override;
    void focusOutEvent(QFocusEvent* event) override;

private:
    /// Clamps an out-of-range typed value (emits clamped); nothing for other text.
    void clampTyped();
    void updateToolTip();

    QString m_description;
};

} // namespace bunraku::widgets
