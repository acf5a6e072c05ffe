// Widgets draw what the pixels can show, whatever the span of the data: a take of 1e8 s or a
// design warp reaching output frame 1e8 paints at once, with as many ticks or curve samples as
// the widget's width holds (they used to loop over every second, or allocate 4 samples per frame).
#include "widgets/scrub_bar.h"
#include "widgets/warp_curve_editor.h"

#include <catch2/catch.hpp>

#include <QElapsedTimer>
#include <QImage>
#include <QTest>

#include <qcustomplot.h>

using namespace bunraku;

namespace {

/// Runs of pixels along row `y` of the widget's image clearly darker than its background (the
/// ticks, drawn antialiased).
int tickRuns(const QImage& image, int y, QRgb background)
{
    int runs = 0;
    bool inRun = false;
    for (int x = 0; x < image.width(); ++x) {
        const bool dark = qGray(image.pixel(x, y)) < qGray(background) - 40;
        runs += dark && !inRun;
        inRun = dark;
    }
    return runs;
}

} // namespace

TEST_CASE("a scrub bar over 1e8 seconds draws no more ticks than its pixels hold", "[widgets][timeline]")
{
    for (const double seconds : {20.0, 1e8, 1e300}) {
        INFO(seconds << " s");
        widgets::ScrubBar bar;
        bar.resize(400, 34);
        bar.setDuration(seconds);
        bar.show();
        REQUIRE(QTest::qWaitForWindowExposed(&bar));
        const int span = bar.width() - 16;
        const double step = bar.tickSeconds();
        CHECK(step >= seconds * widgets::ScrubBar::kMinTickPixels / span);
        if (seconds == 20.0) CHECK(step == 1.0); // short takes keep a tick per second
        QElapsedTimer timer;
        timer.start();
        const QImage image = bar.grab().toImage();
        CHECK(timer.elapsed() < 2000);
        // the ticks hang below the track (rows 24..27 of a 34 px bar)
        const int runs = tickRuns(image, 25, bar.palette().color(QPalette::Window).rgb());
        CHECK(runs >= 10);
        CHECK(runs <= span / widgets::ScrubBar::kMinTickPixels + 2);
    }
}

TEST_CASE("the warp editor samples a warp reaching output frame 1e8 by its pixels", "[widgets][warp]")
{
    widgets::WarpCurveEditor editor;
    editor.resize(600, 400);
    editor.show();
    REQUIRE(QTest::qWaitForWindowExposed(&editor));
    auto* plot = editor.findChild<QCustomPlot*>();
    REQUIRE(plot != nullptr);
    analysis::WarpCurve curve;
    curve.points = {{0.0, 0.0}, {3.0, 1.0}, {1e8, 1e8}};
    editor.setCurve(curve); // used to allocate 4e8 samples and die of bad_alloc
    int longest = 0;
    QCPGraph* curveGraph = nullptr;
    for (int g = 0; g < plot->graphCount(); ++g)
        if (plot->graph(g)->dataCount() > longest) {
            longest = plot->graph(g)->dataCount();
            curveGraph = plot->graph(g);
        }
    REQUIRE(curveGraph != nullptr);
    CHECK(longest > 100);
    CHECK(longest <= 4 * std::max(100, plot->width()) + 4);
    // the control points are samples: the kink at output 3 is drawn
    bool kink = false;
    for (auto it = curveGraph->data()->constBegin(); it != curveGraph->data()->constEnd(); ++it)
        kink = kink || (it->key == 3.0 && it->value == 1.0);
    CHECK(kink);
    CHECK((curveGraph->data()->constEnd() - 1)->value == Approx(1e8));
    // a short warp keeps 4 samples per output frame
    curve.points = {{0.0, 0.0}, {10.0, 12.0}};
    editor.setCurve(curve);
    CHECK(curveGraph->dataCount() == 41);
}
