#pragma once
/// A one-line label that never widens its window: a text longer than the label is drawn cut
/// with an ellipsis at the end, and shown whole in the tool tip. text() stays the whole text.
/// The status bar's message line (a long export note no longer runs off the window's edge).

#include <QLabel>

namespace bunraku::widgets {

class ElidedLabel : public QLabel {
    Q_OBJECT
public:
    explicit ElidedLabel(QWidget* parent = nullptr);

    /// The text as drawn at the label's current width (text() with "..." when it does not fit).
    QString shownText() const;
    /// Any width: the label takes what its layout gives it.
    QSize minimumSizeHint() const override;

protected:
    void paintEvent(QPaintEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;

private:
    void updateToolTip();
};

} // namespace bunraku::widgets
