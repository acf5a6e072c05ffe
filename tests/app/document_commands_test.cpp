#include "app/commands.h"
#include "app/document.h"
#include "app/parameters.h"

#include "tests/widgets/synthetic_take.h"

#include <catch2/catch.hpp>

#include <QSignalSpy>

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

TEST_CASE("a parameter change redoes, undoes and redoes to the same model", "[app][commands]")
{
    Document document;
    document.setCorpus(smallCorpus(), "synthetic");
    QSignalSpy changed(&document, &Document::parameterChanged);
    const QVariant before = document.parameter(parameters::kNormaliseTau);
    REQUIRE(before.toInt() == 4);
    REQUIRE(changeParameter(document, parameters::kNormaliseTau, 7));
    REQUIRE(document.parameter(parameters::kNormaliseTau).toInt() == 7);
    document.undoStack()->undo();
    REQUIRE(document.parameter(parameters::kNormaliseTau) == before);
    document.undoStack()->redo();
    REQUIRE(document.parameter(parameters::kNormaliseTau).toInt() == 7);
    REQUIRE(changed.count() == 3);
    REQUIRE(changed[0][0].toString() == parameters::kNormaliseTau);
    // An unchanged value pushes nothing.
    REQUIRE_FALSE(changeParameter(document, parameters::kNormaliseTau, 7));
    REQUIRE(document.undoStack()->count() == 1);
}

TEST_CASE("a drag of many changes is one undo step back to the value before the drag", "[app][commands]")
{
    Document document;
    document.setCorpus(smallCorpus(), "synthetic");
    const quint64 version = document.version();
    document.beginInteraction();
    for (int step = 1; step <= 20; ++step) changeParameter(document, parameters::kEmotionWeight, 0.1 * step);
    document.endInteraction();
    REQUIRE(document.undoStack()->count() == 1);
    REQUIRE(document.parameter(parameters::kEmotionWeight).toDouble() == Approx(2.0));
    REQUIRE(document.version() > version);
    // A second drag is a second step.
    document.beginInteraction();
    changeParameter(document, parameters::kEmotionWeight, 0.5);
    changeParameter(document, parameters::kEmotionWeight, 0.6);
    document.endInteraction();
    REQUIRE(document.undoStack()->count() == 2);
    document.undoStack()->undo();
    REQUIRE(document.parameter(parameters::kEmotionWeight).toDouble() == Approx(2.0));
    document.undoStack()->undo();
    REQUIRE(document.parameter(parameters::kEmotionWeight).toDouble() == 1.0);
    // Changes outside an interaction never merge.
    changeParameter(document, parameters::kEmotionWeight, 0.3);
    changeParameter(document, parameters::kEmotionWeight, 0.4);
    REQUIRE(document.undoStack()->count() == 2);
}

TEST_CASE("importing a take redoes, undoes and redoes its place and the selection", "[app][commands]")
{
    Document document;
    document.setCorpus(smallCorpus(), "synthetic");
    REQUIRE(document.selectedId(TakeSlot::A) == Document::corpusTakeId(0));
    auto* command = new ImportTake(&document, test::syntheticPuppetTake(33), "file.csv", "/tmp/file.csv");
    const QString id = command->takeId();
    document.undoStack()->push(command);
    REQUIRE(document.derivedTakes().size() == 1);
    REQUIRE(document.selectedId(TakeSlot::A) == id);
    REQUIRE(document.selectedTake(TakeSlot::A)->frameCount() == 33);
    document.undoStack()->undo();
    REQUIRE(document.derivedTakes().empty());
    REQUIRE_FALSE(document.take(id));
    REQUIRE(document.selectedId(TakeSlot::A) == Document::corpusTakeId(0));
    document.undoStack()->redo();
    REQUIRE(document.take(id)->frameCount() == 33);
    REQUIRE(document.selectedId(TakeSlot::A) == id);
    REQUIRE(document.browserEntries().size() == 4);
}

TEST_CASE("removing an imported take is undone back into its place", "[app][commands]")
{
    Document document;
    document.setCorpus(smallCorpus(), "synthetic");
    document.undoStack()->push(new ImportTake(&document, test::syntheticPuppetTake(30), "one.csv", "/tmp/one.csv"));
    document.undoStack()->push(new ImportTake(&document, test::syntheticPuppetTake(31), "two.csv", "/tmp/two.csv"));
    const QString first = document.derivedTakes()[0].id;
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
    document.selectTake(TakeSlot::B, Document::corpusTakeId(2));
    REQUIRE(document.duration() == Approx(22.0 / 5.0));
    document.setLiveTake("designed", "designed", test::syntheticPuppetTake(50));
    REQUIRE(document.take("live/designed")->frameCount() == 50);
    REQUIRE(document.undoStack()->count() == 0);
    document.selectTake(TakeSlot::A, "no/such/take");
    REQUIRE(document.selectedId(TakeSlot::A) == Document::corpusTakeId(0));
}

TEST_CASE("consecutive steps of one control are one undo step until the control loses the focus", "[app][commands]")
{
    widgets::ManualClock clock; // steps follow each other at once however slow the machine is
    Document document;
    document.setClock(&clock);
    document.setCorpus(smallCorpus(), "synthetic");
    for (int tau = 5; tau <= 9; ++tau) REQUIRE(stepParameter(document, parameters::kNormaliseTau, tau));
    REQUIRE(document.undoStack()->count() == 1);
    REQUIRE(document.parameter(parameters::kNormaliseTau).toInt() == 9);
    document.undoStack()->undo();
    REQUIRE(document.parameter(parameters::kNormaliseTau).toInt() == 4);
    document.undoStack()->redo();
    REQUIRE(document.parameter(parameters::kNormaliseTau).toInt() == 9);

    // Stepping back to where the series began leaves nothing to undo.
    for (int tau = 8; tau >= 4; --tau) stepParameter(document, parameters::kNormaliseTau, tau);
    REQUIRE(document.undoStack()->count() == 0);
    REQUIRE(document.parameter(parameters::kNormaliseTau).toInt() == 4);

    // The focus leaves (the series ends): the next steps are a new undo step.
    stepParameter(document, parameters::kNormaliseTau, 5);
    document.endStepSeries();
    stepParameter(document, parameters::kNormaliseTau, 6);
    stepParameter(document, parameters::kNormaliseTau, 7);
    REQUIRE(document.undoStack()->count() == 2);
    // Another key, or another control of the same key, does not merge.
    stepParameter(document, parameters::kNormaliseSearchBand, 21);
    stepParameter(document, parameters::kNormaliseSearchBand, 22);
    REQUIRE(document.undoStack()->count() == 3);
    stepParameter(document, parameters::kNormaliseSearchBand, 23, {}, QStringLiteral("another control"));
    REQUIRE(document.undoStack()->count() == 4);
    // A plain change never merges, and a step does not merge into it.
    changeParameter(document, parameters::kNormaliseTau, 10);
    stepParameter(document, parameters::kNormaliseTau, 11);
    REQUIRE(document.undoStack()->count() == 6);
    // A drag after steps is its own undo step.
    document.beginInteraction();
    stepParameter(document, parameters::kNormaliseTau, 12);
    stepParameter(document, parameters::kNormaliseTau, 13);
    document.endInteraction();
    REQUIRE(document.undoStack()->count() == 7);
    document.undoStack()->undo();
    REQUIRE(document.parameter(parameters::kNormaliseTau).toInt() == 11);

    // Steps further apart than kStepMergeMilliseconds are undone one by one.
    document.undoStack()->clear();
    stepParameter(document, parameters::kNormaliseTau, 20);
    clock.advance(kStepMergeMilliseconds);
    stepParameter(document, parameters::kNormaliseTau, 21);
    REQUIRE(document.undoStack()->count() == 1); // within the window: merged
    clock.advance(kStepMergeMilliseconds + 1);
    stepParameter(document, parameters::kNormaliseTau, 22);
    REQUIRE(document.undoStack()->count() == 2);
}

TEST_CASE("several parameters set together are one undo step", "[app][commands]")
{
    Document document;
    document.setCorpus(smallCorpus(), "synthetic");
    QSignalSpy changed(&document, &Document::parameterChanged);
    const QVariantMap gains{{QStringLiteral("0/1"), QVariantList{1.5, 0.5}}};
    REQUIRE(changeParameters(document,
                             {{parameters::kDesignBoundaries, QVariantList{qlonglong(10)}}, {parameters::kDesignGains, gains}},
                             QStringLiteral("Add phrase boundary")));
    REQUIRE(document.undoStack()->count() == 1);
    REQUIRE(document.undoStack()->text(0) == QStringLiteral("Add phrase boundary"));
    REQUIRE(document.parameter(parameters::kDesignBoundaries).toList() == QVariantList{qlonglong(10)});
    REQUIRE(document.parameter(parameters::kDesignGains).toMap() == gains);
    REQUIRE(changed.count() == 2);
    document.undoStack()->undo();
    REQUIRE(document.parameter(parameters::kDesignBoundaries) == parameters::defaultValue(parameters::kDesignBoundaries));
    REQUIRE(document.parameter(parameters::kDesignGains) == parameters::defaultValue(parameters::kDesignGains));
    // Values equal to the current ones push nothing.
    REQUIRE_FALSE(changeParameters(document, {{parameters::kNormaliseTau, 4}}, QStringLiteral("nothing")));
    REQUIRE(document.undoStack()->count() == 1);
}
