#pragma once
/// A layout that places its items left to right and starts a new row when the next one would
/// not fit: a dock's controls stay reachable however narrow the dock is (a tool bar hides what
/// does not fit behind an extension menu that cannot show combo boxes or check boxes). Items
/// keep their size hints; the height follows the width (heightForWidth).

#include <QLayout>
#include <QList>

namespace bunraku::widgets {

class FlowLayout : public QLayout {
public:
    /// `spacing`: pixels between items and between rows.
    explicit FlowLayout(QWidget* parent = nullptr, int spacing = 4);
    ~FlowLayout() override;

    void addItem(QLayoutItem* item) override;
    int count() const override { return int(m_items.size()); }
    QLayoutItem* itemAt(int index) const override;
    QLayoutItem* takeAt(int index) override;
    Qt::Orientations expandingDirections() const override { return {}; }
    bool hasHeightForWidth() const override { return true; }
    int heightForWidth(int width) const override;
    QSize sizeHint() const override;
    QSize minimumSize() const override;
    void setGeometry(const QRect& rect) override;

    /// Rows the items take at `width` (1 when they fit in one).
    int rowCount(int width) const;

private:
    /// Places the items in `rect` (only measures when `apply` is false); returns the height used.
    int arrange(const QRect& rect, bool apply, int* rows = nullptr) const;

    QList<QLayoutItem*> m_items;
    int m_gap;
};

} // namespace bunraku::widgets
