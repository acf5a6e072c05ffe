// A derived take of real takes: its puppet (the 24 channels) and its skeleton may differ; the 3D
// view says by how much while the skeleton is drawn, and File > Export Take says which of the two
// the file holds.
#include "tests/app/app_test_support.h"
#include "tests/app/bandai_corpus_support.h"

#include "analysis/core/skeleton_take.h"
#include "app/normalise_panel.h"
#include "render/scene.h"

#include <catch2/catch.hpp>

#include <QComboBox>
#include <QLabel>

using bunraku::app::TakeSlot;
using namespace bunraku;

TEST_CASE("the 3D view and the export say how far a normalised Bandai take's skeleton is from its channels", "[app][skeleton][gap]")
{
    const auto corpus = test::bandaiCorpusFolder(test::bandaiWaveNames("normal"), "app_skeleton_gap", "waves");
    if (corpus.empty()) return;
    auto window = test::windowOnCorpus(corpus);
    REQUIRE(window);
    auto& document = window->document();
    document.selectTake(TakeSlot::A, app::Document::corpusTakeId(0));
    auto* view = window->viewportPanel();
    QComboBox* figure = view->figureBox(0);
    QLabel* gap = view->skeletonGapLabel();
    figure->setCurrentIndex(figure->findData(int(render::FigureStyle::PuppetAndSkeleton)));
    // A take read from BVH: its channels are its skeleton's parts.
    CHECK(analysis::skeletonChannelGap(*document.selectedTake(TakeSlot::A))->maxPositionCm < 1e-9);
    CHECK_FALSE(gap->isVisibleTo(view));

    // Take 1 normalised to the cell's reference with the thesis's coupling (one warp per
    // coordinate) is no longer one body: its skeleton follows the mean time.
    REQUIRE(QTest::qWaitFor([&] { return window->normalisePanel()->normalisedTake() != nullptr; }, 60000));
    REQUIRE(test::waitUntilIdle(*window));
    const auto normalised = document.take(QStringLiteral("live/normalised"));
    REQUIRE(normalised);
    REQUIRE(normalised->skeleton);
    const auto expected = analysis::noticeableSkeletonGap(*normalised);
    REQUIRE(expected);
    document.selectTake(TakeSlot::A, QStringLiteral("live/normalised"));
    CHECK(gap->isVisibleTo(view));
    INFO(gap->text().toStdString());
    CHECK(gap->text() == QStringLiteral("A: skeleton off the channels by ") + QString::fromStdString(analysis::describeSkeletonChannelGap(*expected)));
    figure->setCurrentIndex(figure->findData(int(render::FigureStyle::Puppet)));
    CHECK_FALSE(gap->isVisibleTo(view)); // the puppet alone is the channels
    figure->setCurrentIndex(figure->findData(int(render::FigureStyle::Skeleton)));
    CHECK(gap->isVisibleTo(view));

    const auto dir = test::scratchDir("app_skeleton_gap_export");
    auto& exports = window->exports();
    REQUIRE(exports.exportTake(TakeSlot::A, QString::fromStdString((dir / "normalised.bvh").string())));
    CHECK(exports.lastNote().startsWith(QStringLiteral("normalised.bvh holds the take's skeleton; its 24 channels differ from that motion by ") +
                                        QString::fromStdString(analysis::describeSkeletonChannelGap(*expected))));
    REQUIRE(exports.exportTake(TakeSlot::A, QString::fromStdString((dir / "normalised.csv").string())));
    CHECK(exports.lastNote().startsWith(QStringLiteral("normalised.csv holds the take's 24 channels")));
    document.selectTake(TakeSlot::A, app::Document::corpusTakeId(0));
    CHECK_FALSE(gap->isVisibleTo(view));
    REQUIRE(exports.exportTake(TakeSlot::A, QString::fromStdString((dir / "take.bvh").string())));
    CHECK(exports.lastNote().isEmpty());
}
