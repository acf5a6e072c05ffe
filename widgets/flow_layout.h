#pragma once
/// A layout that places its items left to right at their preferred sizes and wraps onto the next
/// row when the width runs out, as words wrap in a paragraph: a row of buttons in a narrow dock
/// becomes two or three rows instead of clipping its last buttons or forcing the dock to scroll
/// sideways. Its minimum width is its widest item's; its height follows its width
/// (heightForWidth), so a scroll area or a dock gives it the rows it needs.

#include <QLayout>
#include <QList>

namespace bunraku::widgets {

class FlowLayout : public QLayout {
public:
    explicit FlowLayout(QWidget* parent = nullptr, int spacing = -1);
    ~FlowLayout() override;

    void addItem(QLayoutItem* item) override;
    int count() const override { return int(m_items.size()); }
    QLayoutItem* itemAt(int index) const override;
    QLayoutItem* takeAt(int index) override;

    Qt::Orientations expandingDirections() const override { return {}; }
    bool hasHeightForWidth() const override { return true; }
    int heightForWidth(int width) const override;
    QSize minimumSize() const override;
    QSize sizeHint() const override;
    void setGeometry(const QRect& rect) override;

    /// The gap between items (the style's when not set).
    int itemSpacing() const;

private:
    /// Lays the items out in `rect` (only measures when `apply` is false); returns the height used.
    int place(const QRect& rect, bool apply) const;

    QList<QLayoutItem*> m_items;
    int m_spacing = -1;
};

} // namespace bunraku::widgets
