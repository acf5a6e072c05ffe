#include "app/commands.h"
#include "app/document.h"

#include "tests/app/take_id_text.h"
#include "tests/widgets/synthetic_take.h"

#include <catch2/catch.hpp>

#include <QSignalSpy>

#include <type_traits>

using namespace bunraku;
using namespace bunraku::app;

namespace {

analysis::Corpus smallCorpus()
{
    analysis::Corpus corpus;
    for (int k = 1; k <= 3; ++k) {
        auto take = *test::syntheticPuppetTake(20 + k, k);
        take.labels = {"greeting", "none", k, "synthetic"};
        corpus.takes.push_back(take);
    }
    return corpus;
}

} // namespace

namespace {

bool setTau(Document& document, int tau, const QString& step = {})
{
    return changeStageParameters(document, [tau](AnalysisParameters& p) { p.normalise.tau = tau; }, QStringLiteral("tau"), step);
}

} // namespace

TEST_CASE("a parameter change redoes, undoes and redoes to the same model", "[app][commands]")
{
    Document document;
    QSignalSpy changed(&document, &Document::parametersChanged);
    REQUIRE(setTau(document, 7));
    REQUIRE(document.parameters().normalise.tau == 7);
    document.undoStack()->undo();
    REQUIRE(document.parameters() == AnalysisParameters{});
    document.undoStack()->redo();
    REQUIRE(document.parameters().normalise.tau == 7);
    REQUIRE(changed.count() == 3);
    REQUIRE(changed[0][0].toInt() == kNormaliseSection); // typed: only the normalisation changed
    REQUIRE_FALSE(setTau(document, 7));                   // unchanged: nothing pushed
}

TEST_CASE("a drag of many changes is one undo step back to the value before the drag", "[app][commands]")
{
    Document document;
    document.beginInteraction();
    for (int step = 1; step <= 20; ++step) setEmotionWeight(document, 0.1 * step);
    document.endInteraction();
    REQUIRE(document.undoStack()->count() == 1);
    REQUIRE(document.parameters().design.emotionWeight == Approx(2.0));
    document.beginInteraction(); // a drag that returns to its start leaves no undo step
    setEmotionWeight(document, 0.5);
    setEmotionWeight(document, 2.0);
    document.endInteraction();
    REQUIRE(document.undoStack()->count() == 1);
    document.undoStack()->undo();
    REQUIRE(document.parameters().design.emotionWeight == 1.0);
}

TEST_CASE("commands of different verbs never merge, even inside one drag", "[app][commands]")
{
    Document document;
    document.beginInteraction();
    setEmotionWeight(document, 1.5);
    pushParameters(document, new MoveWarpPoint(&document, editedParameters(document, [](AnalysisParameters& p) {
                                                   p.design.warp = analysis::identityWarp(30);
                                               })));
    setEmotionWeight(document, 1.7);
    document.endInteraction();
    REQUIRE(document.undoStack()->count() == 3);
    pushParameters(document, new AddPhraseBoundary(&document, editedParameters(document, [](AnalysisParameters& p) {
                                                       p.design.boundaries = {false, {10}};
                                                   })));
    pushParameters(document, new AddPhraseBoundary(&document, editedParameters(document, [](AnalysisParameters& p) {
                                                       p.design.boundaries = {false, {10, 20}};
                                                   })));
    REQUIRE(document.undoStack()->count() == 5); // adding boundaries never merges
    document.undoStack()->undo();
    REQUIRE(document.parameters().design.boundaries.inner == std::vector<Eigen::Index>{10});
}

TEST_CASE("importing a take redoes, undoes and redoes its place and the selection", "[app][commands]")
{
    Document document;
    document.setCorpus(smallCorpus(), "synthetic");
    REQUIRE(document.selectedId(TakeSlot::A) == TakeId::corpus(0));
    auto* command = new ImportTake(&document, test::syntheticPuppetTake(33), "file.csv", "/tmp/file.csv");
    const TakeId id = command->takeId();
    document.undoStack()->push(command);
    REQUIRE(document.derivedTakes().size() == 1);
    REQUIRE(document.selectedId(TakeSlot::A) == id);
    REQUIRE(document.selectedTake(TakeSlot::A)->frameCount() == 33);
    document.undoStack()->undo();
    REQUIRE(document.derivedTakes().empty());
    REQUIRE_FALSE(document.take(id));
    REQUIRE(document.selectedId(TakeSlot::A) == TakeId::corpus(0));
    document.undoStack()->redo();
    REQUIRE(document.take(id)->frameCount() == 33);
    REQUIRE(document.selectedId(TakeSlot::A) == id);
    REQUIRE(document.derivedTakes().size() == 1);
}

TEST_CASE("removing an imported take is undone back into its place", "[app][commands]")
{
    Document document;
    document.setCorpus(smallCorpus(), "synthetic");
    document.undoStack()->push(new ImportTake(&document, test::syntheticPuppetTake(30), "one.csv", "/tmp/one.csv"));
    document.undoStack()->push(new ImportTake(&document, test::syntheticPuppetTake(31), "two.csv", "/tmp/two.csv"));
    const TakeId first = document.derivedTakes()[0].id;
    document.undoStack()->push(new RemoveImportedTake(&document, first));
    REQUIRE(document.derivedTakes().size() == 1);
    document.undoStack()->undo();
    REQUIRE(document.derivedTakes().size() == 2);
    REQUIRE(document.derivedTakes()[0].id == first);
}

TEST_CASE("the current time is clamped to the shown takes and live takes are not undoable", "[app][document]")
{
    Document document;
    document.setCorpus(smallCorpus(), "synthetic");
    document.setCurrentTime(100.0);
    REQUIRE(document.currentTime() == Approx(20.0 / 5.0));
    document.selectTake(TakeSlot::B, TakeId::corpus(2));
    REQUIRE(document.duration() == Approx(22.0 / 5.0));
    document.setLiveTake("designed", "designed", test::syntheticPuppetTake(50));
    REQUIRE(document.take(app::TakeId::live(QStringLiteral("designed")))->frameCount() == 50);
    REQUIRE(document.undoStack()->count() == 0);
    document.selectTake(TakeSlot::A, TakeId::live(QStringLiteral("nosuchtake")));
    REQUIRE(document.selectedId(TakeSlot::A) == TakeId::corpus(0));
}

TEST_CASE("consecutive steps of one control are one undo step until the control loses the focus", "[app][commands]")
{
    Document document;
    qint64 now = 1000;
    document.setClock([&now] { return now; }); // no wall clock: the test moves time
    for (int tau = 5; tau <= 9; ++tau) REQUIRE(setTau(document, tau, QStringLiteral("tau box")));
    REQUIRE(document.undoStack()->count() == 1);
    REQUIRE(document.parameters().normalise.tau == 9);
    document.undoStack()->undo();
    REQUIRE(document.parameters().normalise.tau == 4);
    document.undoStack()->redo();
    REQUIRE(document.parameters().normalise.tau == 9);

    document.endStepSeries(); // the box lost the focus: a new step
    setTau(document, 10, QStringLiteral("tau box"));
    REQUIRE(document.undoStack()->count() == 2);
    now += kStepMergeMilliseconds + 1; // too long after the previous step: a new step
    setTau(document, 11, QStringLiteral("tau box"));
    REQUIRE(document.undoStack()->count() == 3);
    now += 10;
    changeStageParameters(document, [](AnalysisParameters& p) { p.normalise.searchBand = 21; }, QStringLiteral("band"),
                          QStringLiteral("band box")); // another control
    REQUIRE(document.undoStack()->count() == 4);
    setTau(document, 12); // not a step: its own undo step
    REQUIRE(document.undoStack()->count() == 5);
}

// Only the undo commands can call the document's mutators: outside them no key can be made.
static_assert(!std::is_default_constructible_v<bunraku::app::Document::CommandKey>);
static_assert(!std::is_invocable_v<decltype(&bunraku::app::Document::applyParameters), bunraku::app::Document&,
                                   const bunraku::app::AnalysisParameters&>);

TEST_CASE("a project's imported takes and parameters are restored at once, outside the undo stack", "[app][document]")
{
    Document document;
    document.setCorpus(smallCorpus(), QStringLiteral("test"));
    AnalysisParameters parameters;
    parameters.normalise.tau = 7;
    std::vector<DerivedTake> imported(1);
    imported[0].id = document.nextImportedId();
    imported[0].label = QStringLiteral("a take");
    imported[0].take = test::syntheticPuppetTake(30);
    QSignalSpy listed(&document, &Document::derivedTakesChanged);
    QSignalSpy changed(&document, &Document::parametersChanged);
    document.restoreProject(std::move(imported), parameters);
    CHECK(listed.count() == 1);
    CHECK(changed.count() == 1);
    CHECK(document.take(app::TakeId::imported(1)));
    CHECK(document.parameters().normalise.tau == 7);
    CHECK(document.undoStack()->count() == 0);
}

TEST_CASE("a shown live take replaced by a shorter one keeps the current time inside the takes shown", "[app][document]")
{
    Document document;
    document.setCorpus(smallCorpus(), QStringLiteral("test"));
    document.setLiveTake(QStringLiteral("axis"), QStringLiteral("long"), test::syntheticPuppetTake(200));
    document.selectTake(TakeSlot::B, app::TakeId::live(QStringLiteral("axis")));
    document.setCurrentTime(document.duration());
    const double longEnd = document.currentTime();
    QSignalSpy replaced(&document, &Document::selectedTakeReplaced);
    QSignalSpy moved(&document, &Document::currentTimeChanged);
    document.setLiveTake(QStringLiteral("axis"), QStringLiteral("long"), test::syntheticPuppetTake(30));
    CHECK(replaced.count() == 1);
    CHECK(document.duration() < longEnd);
    CHECK(document.currentTime() <= document.duration()); // a monkey seed found it past the end
    CHECK(moved.count() == 1);
}

TEST_CASE("a parameter command holds the sections it changes and nothing else, merged steps too", "[app][commands]")
{
    Document document;
    auto commandAt = [&](int index) { return static_cast<const ParameterCommand*>(document.undoStack()->command(index)); };
    REQUIRE(setTau(document, 7));
    CHECK(commandAt(0)->sections() == ParameterSections(kNormaliseSection));
    REQUIRE(setEmotionWeight(document, 0.4));
    CHECK(commandAt(1)->sections() == ParameterSections(kWeightSection));

    // A warp drag: one step holding the warp alone, back to no warp on undo.
    analysis::WarpCurve curve;
    curve.points = {{0.0, 0.0}, {10.0, 12.0}, {20.0, 20.0}};
    document.beginInteraction();
    for (int step = 0; step < 5; ++step) {
        curve.points[1].source = 12.0 + step;
        auto after = editedParameters(document, [&](AnalysisParameters& p) { p.design.warp = curve; });
        pushParameters(document, new MoveWarpPoint(&document, after));
    }
    document.endInteraction();
    REQUIRE(document.undoStack()->count() == 3);
    CHECK(commandAt(2)->sections() == ParameterSections(kWarpSection));
    const AnalysisParameters edited = document.parameters();
    REQUIRE(document.parameters().design.warp);
    CHECK(document.parameters().design.warp->points[1].source == 16.0);

    // Each undo takes back its own section only; redo brings the same parameters back.
    document.undoStack()->undo();
    CHECK_FALSE(document.parameters().design.warp);
    CHECK(document.parameters().design.emotionWeight == 0.4);
    CHECK(document.parameters().normalise.tau == 7);
    document.undoStack()->undo();
    CHECK(document.parameters().design.emotionWeight == AnalysisParameters{}.design.emotionWeight);
    CHECK(document.parameters().normalise.tau == 7);
    document.undoStack()->undo();
    CHECK(document.parameters() == AnalysisParameters{});
    for (int k = 0; k < 3; ++k) document.undoStack()->redo();
    CHECK(document.parameters() == edited);
}
