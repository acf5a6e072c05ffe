// widgets/flow_layout.h: items left to right, a new row when the next would not fit, the height
// following the width.
#include "widgets/flow_layout.h"

#include <catch2/catch.hpp>

#include <QWidget>

using bunraku::widgets::FlowLayout;

namespace {

QWidget* fixedBox(QWidget* parent, int width, int height)
{
    auto* box = new QWidget(parent);
    box->setFixedSize(width, height);
    return box;
}

} // namespace

TEST_CASE("a flow layout wraps its items into rows that fit the width", "[widgets][flow]")
{
    QWidget host;
    auto* flow = new FlowLayout(&host, 4);
    std::vector<QWidget*> boxes;
    for (int k = 0; k < 5; ++k) {
        boxes.push_back(fixedBox(&host, 100, k == 2 ? 30 : 20));
        flow->addWidget(boxes.back());
    }
    // Five of 100 px with 4 px between: 516 px in one row.
    CHECK(flow->sizeHint() == QSize(516, 30));
    CHECK(flow->minimumSize() == QSize(100, 30));
    CHECK(flow->rowCount(516) == 1);
    CHECK(flow->rowCount(515) == 2);
    CHECK(flow->rowCount(208) == 3);
    CHECK(flow->rowCount(100) == 5);
    // Rows as tall as their tallest item, 4 px apart: 20 + 4 + 30 + 4 + 20 at 208 px.
    CHECK(flow->heightForWidth(208) == 78);

    flow->setGeometry(QRect(0, 0, 208, 78));
    CHECK(boxes[0]->geometry() == QRect(0, 0, 100, 20));
    CHECK(boxes[1]->geometry() == QRect(104, 0, 100, 20));
    CHECK(boxes[2]->geometry() == QRect(0, 24, 100, 30));
    CHECK(boxes[3]->geometry() == QRect(104, 24, 100, 20));
    CHECK(boxes[4]->geometry() == QRect(0, 58, 100, 20));
    // A hidden item takes no place.
    boxes[1]->hide();
    CHECK(flow->rowCount(208) == 2);
}
