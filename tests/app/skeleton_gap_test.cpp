// A derived take of real takes is shown as one body: the figure, the graphs and every export
// hold the body's motion (its skeleton and the 24 channels posed from it); the thesis's
// per-channel result is the graphs' ghost, and File > Export Take says how far it is.
#include "tests/app/app_test_support.h"
#include "tests/app/bandai_corpus_support.h"

#include "analysis/core/skeleton_take.h"
#include "analysis/io/take_csv.h"
#include "app/normalise_panel.h"
#include "widgets/graph_grid.h"
#include "widgets/graph_panel.h"
#include "render/scene.h"

#include <catch2/catch.hpp>

#include <QComboBox>

#include <algorithm>
#include <cstdlib>
#include <QLabel>

using bunraku::app::TakeId;
using bunraku::app::TakeSlot;
using namespace bunraku;

TEST_CASE("a normalised Bandai take is shown, graphed and exported as one body, its per-channel result as the ghost", "[app][skeleton][gap]")
{
    const auto corpus = test::bandaiCorpusFolder(test::bandaiWaveNames("normal"), "app_skeleton_gap", "waves");
    if (corpus.empty()) return;
    auto window = test::windowOnCorpus(corpus);
    REQUIRE(window);
    auto& document = window->document();
    document.selectTake(TakeSlot::A, app::TakeId::corpus(0));
    auto* view = window->viewportPanel();
    QComboBox* figure = view->figureBox(0);
    QLabel* gap = view->skeletonGapLabel();
    figure->setCurrentIndex(figure->findData(int(render::FigureStyle::PuppetAndSkeleton)));
    // A take read from BVH: its channels are its skeleton's parts.
    CHECK(analysis::skeletonChannelGap(*document.selectedTake(TakeSlot::A))->maxPositionCm < 1e-9);
    CHECK_FALSE(gap->isVisibleTo(view));
    CHECK_FALSE(document.ghostOf(app::TakeId::corpus(0)));

    // Take 1 normalised to the cell's reference with the thesis's coupling (one warp per
    // coordinate): the per-channel result is no body's motion; what is shown is its skeleton's.
    REQUIRE(QTest::qWaitFor([&] { return window->normalisePanel()->normalisedTake() != nullptr; }, 60000));
    REQUIRE(test::waitUntilIdle(*window));
    const auto normalised = document.take(app::TakeId::live(QStringLiteral("normalised")));
    REQUIRE(normalised);
    REQUIRE(normalised->skeleton);
    const auto shownGap = analysis::skeletonChannelGap(*normalised);
    REQUIRE(shownGap);
    CHECK(shownGap->maxPositionCm < 1e-6);
    CHECK(shownGap->maxAngleDeg < 1e-6);
    // The thesis's per-channel take is kept beside it (its graphs' ghost is the raw take).
    const int index = document.indexOfDerived(app::TakeId::live(QStringLiteral("normalised")));
    REQUIRE(index >= 0);
    const auto ghost = document.derivedTakes()[std::size_t(index)].perChannelGhost;
    REQUIRE(ghost);
    CHECK_FALSE(ghost->skeleton);
    CHECK(document.ghostOf(app::TakeId::live(QStringLiteral("normalised"))) == document.take(app::TakeId::corpus(0)));
    const auto distance = analysis::perChannelDistance(*normalised, ghost->values);
    REQUIRE(distance);
    CHECK(distance->maxPositionCm > 1.0); // method2 really moves the parts apart

    document.selectTake(TakeSlot::A, app::TakeId::live(QStringLiteral("normalised")));
    // The graphs draw the raw take as the ghost and the per-channel result beside it, and say how
    // far the per-channel result is from the body (measured as analysis::perChannelDistance does).
    auto* graphs = window->graphPanel();
    const QString caption = graphs->ghostCaption();
    INFO(caption.toStdString());
    CHECK(caption.startsWith(QStringLiteral("Purple line: the thesis's per-channel result")));
    // Both lines are named, and the per-channel line's colour is far in hue from both takes'.
    CHECK(caption.endsWith(QStringLiteral("Grey dashes: the take it was made from")));
    const widgets::GraphColours colours;
    for (const QColor& take : {colours.takeA, colours.takeB}) {
        const int hueApart = std::abs(colours.perChannel.hue() - take.hue());
        CHECK(std::min(hueApart, 360 - hueApart) > 60);
    }
    CHECK(caption.contains(QStringLiteral("up to %1 cm (%2)").arg(distance->maxPositionCm, 0, 'f', 1).arg(QString::fromStdString(distance->worstPart))));
    CHECK(caption.contains(QStringLiteral("and %1 deg").arg(distance->maxAngleDeg, 0, 'f', 1)));
    CHECK(graphs->grid()->ghostTakes()[0] == document.take(app::TakeId::corpus(0)));
    CHECK(graphs->grid()->ghostTakes()[1] == document.perChannelGhostOf(app::TakeId::live(QStringLiteral("normalised"))));
    for (const auto style : {render::FigureStyle::PuppetAndSkeleton, render::FigureStyle::Skeleton, render::FigureStyle::Puppet}) {
        figure->setCurrentIndex(figure->findData(int(style)));
        CHECK_FALSE(gap->isVisibleTo(view)); // one motion: nothing to warn about
    }

    const auto dir = test::scratchDir("app_skeleton_gap_export");
    auto& exports = window->exports();
    REQUIRE(exports.exportTake(TakeSlot::A, QString::fromStdString((dir / "normalised.bvh").string())));
    CHECK(exports.lastNote().startsWith(QStringLiteral("normalised.bvh holds the take as one body moves")));
    REQUIRE(exports.exportTake(TakeSlot::A, QString::fromStdString((dir / "normalised.csv").string())));
    CHECK(exports.lastNote().startsWith(QStringLiteral("normalised.csv holds the take as one body moves")));
    // The exported channels are the graphed ones.
    auto written = analysis::io::readTakeCsv(dir / "normalised.csv");
    REQUIRE(written);
    CHECK((written->values - normalised->values).cwiseAbs().maxCoeff() < 1e-6);
    document.selectTake(TakeSlot::A, app::TakeId::corpus(0));
    CHECK_FALSE(gap->isVisibleTo(view));
    CHECK(graphs->ghostCaption().isEmpty()); // a take read from a file is its own body
    CHECK_FALSE(graphs->grid()->ghostTakes()[1]);
    REQUIRE(exports.exportTake(TakeSlot::A, QString::fromStdString((dir / "take.bvh").string())));
    CHECK(exports.lastNote().isEmpty());
}

TEST_CASE("a take with no figure to draw is said in the 3D view, as A and as B", "[app][gap]")
{
    // A GUI walk saw the motion axis as A leave the 3D view empty without a word, and as B
    // nothing of it anywhere.
    auto window = test::demoWindow();
    REQUIRE(window);
    auto& document = window->document();
    const auto axis = app::TakeId::live(QStringLiteral("axis"));
    REQUIRE(QTest::qWaitFor([&] { return document.take(axis) != nullptr; }, 60000));
    REQUIRE_FALSE(render::drawableTake(*document.take(axis)));
    auto* view = window->viewportPanel();
    QLabel* said = view->skeletonGapLabel();
    CHECK_FALSE(said->isVisibleTo(view));

    const TakeId corpusA = document.selectedId(TakeSlot::A);
    document.selectTake(TakeSlot::B, axis);
    QCoreApplication::processEvents();
    CHECK(said->isVisibleTo(view));
    CHECK(said->text() == QStringLiteral("B: ") + document.takeLabel(axis) + QStringLiteral(" has no figure to draw: its channels are in the graphs"));

    document.selectTake(TakeSlot::B, {});
    document.selectTake(TakeSlot::A, axis);
    QCoreApplication::processEvents();
    CHECK(said->isVisibleTo(view));
    CHECK(said->text().startsWith(QStringLiteral("A: motion axis of ")));

    document.selectTake(TakeSlot::A, corpusA);
    QCoreApplication::processEvents();
    CHECK_FALSE(said->isVisibleTo(view));
}
