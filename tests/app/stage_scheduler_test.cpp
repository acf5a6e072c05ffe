// The scheduler, the analysis controller and the 3D view with a manual executor: jobs run when the test says,
// on the test's thread, and results arrive through the event loop - no wall-clock windows.
#include "app/analysis_controller.h"
#include "app/commands.h"
#include "app/document.h"
#include "app/stage_scheduler.h"
#include "app/viewport_panel.h"

#include "tests/app/take_id_text.h"

#include "analysis/axis/axis_channels.h"
#include "analysis/axis/inertia_axis.h"
#include "analysis/body/body_description.h"
#include "analysis/cloth/kimono_cloth.h"
#include "analysis/synth/demo_corpus.h"

#include <catch2/catch.hpp>

#include <QCheckBox>
#include <QCoreApplication>
#include <QLabel>

#include <algorithm>
#include <deque>

using namespace bunraku;
using namespace bunraku::app;
using analysis::pipeline::StageKey;

namespace {

class ManualExecutor : public Executor {
public:
    void run(std::function<void()> work) override { m_jobs.push_back(std::move(work)); }
    std::size_t pending() const { return m_jobs.size(); }
    /// Runs the oldest job, then delivers what it posted.
    void runNext()
    {
        REQUIRE_FALSE(m_jobs.empty());
        auto job = std::move(m_jobs.front());
        m_jobs.pop_front();
        job();
        QCoreApplication::processEvents();
    }
    /// Runs jobs until none is left.
    void drain()
    {
        while (!m_jobs.empty()) runNext();
        QCoreApplication::processEvents();
    }

private:
    std::deque<std::function<void()>> m_jobs;
};

StageWork returning(int value)
{
    return [value](const analysis::RunControl&) -> analysis::Result<StageValue> { return StageValue(std::make_shared<const int>(value)); };
}

} // namespace

TEST_CASE("a finished job whose inputs changed meanwhile is never shown", "[app][scheduler]")
{
    auto executor = std::make_shared<ManualExecutor>();
    StageScheduler scheduler(nullptr, executor);
    int shown = 0;
    QObject::connect(&scheduler, &StageScheduler::finished, [&](int) { ++shown; });
    scheduler.request(1, StageKey{11}, returning(1));
    scheduler.request(1, StageKey{22}, returning(2)); // the inputs changed while the first job waits
    REQUIRE(executor->pending() == 2);
    executor->runNext(); // the first job finishes anyway (it ignores its stop token)
    CHECK(shown == 0);
    CHECK(scheduler.result<int>(1) == nullptr);
    CHECK(scheduler.state(1) == SlotState::Running);
    executor->runNext();
    CHECK(shown == 1);
    REQUIRE(scheduler.result<int>(1));
    CHECK(*scheduler.result<int>(1) == 2);

    scheduler.request(1, StageKey{22}, returning(3)); // the same key: nothing starts
    CHECK(executor->pending() == 0);
    CHECK(scheduler.starts(1) == 2);
    scheduler.request(1, StageKey{11}, returning(4)); // back to the first key: its result was cached
    CHECK(executor->pending() == 0);
    CHECK(*scheduler.result<int>(1) == 1);
    QCoreApplication::processEvents();
    CHECK(shown == 2);
}

TEST_CASE("a slot's new key cancels its running job, other slots keep running", "[app][scheduler]")
{
    auto executor = std::make_shared<ManualExecutor>();
    StageScheduler scheduler(nullptr, executor);
    std::vector<bool> stopped;
    auto watching = [&](int value) {
        return [&stopped, value](const analysis::RunControl& control) -> analysis::Result<StageValue> {
            stopped.push_back(control.cancelled());
            return StageValue(std::make_shared<const int>(value));
        };
    };
    scheduler.request(1, StageKey{1}, watching(1));
    scheduler.request(2, StageKey{2}, watching(2));
    scheduler.request(1, StageKey{3}, watching(3));
    executor->drain();
    REQUIRE(stopped == std::vector<bool>{true, false, false}); // slot 1's first job saw its stop; slot 2's did not
    CHECK(*scheduler.result<int>(1) == 3);
    CHECK(*scheduler.result<int>(2) == 2);
}

TEST_CASE("an emotion-weight drag during a running normalisation does not restart it", "[app][scheduler][emotion]")
{
    auto executor = std::make_shared<ManualExecutor>();
    Document document;
    AnalysisController analysis(document, nullptr, executor);
    document.setCorpus(analysis::synth::generateDemoCorpus().corpus, QStringLiteral("demo"));
    auto& scheduler = analysis.scheduler();
    // Run until the normalisation is the job waiting to run.
    while (scheduler.state(AnalysisController::kNormaliseSlot) != SlotState::Running) executor->runNext();
    REQUIRE(scheduler.starts(AnalysisController::kNormaliseSlot) == 1);
    const StageKey normaliseKey = scheduler.key(AnalysisController::kNormaliseSlot);

    document.beginInteraction();
    for (int step = 1; step <= 30; ++step) setEmotionWeight(document, 1.0 + 0.05 * step);
    document.endInteraction();
    CHECK(document.undoStack()->count() == 1);
    CHECK(scheduler.starts(AnalysisController::kNormaliseSlot) == 1); // not restarted
    CHECK(scheduler.key(AnalysisController::kNormaliseSlot) == normaliseKey);

    executor->drain();
    CHECK(scheduler.starts(AnalysisController::kNormaliseSlot) == 1);
    REQUIRE(analysis.normalised());
    REQUIRE(analysis.decomposed());
    REQUIRE(analysis.weightedTake());
    CHECK(analysis.weightedTake()->labels.source.find("2.5") != std::string::npos); // the drag's last weight
}

TEST_CASE("a long take's weighted body is made off the GUI thread with progress and is the body made at once", "[app][scheduler][emotion][body]")
{
    // Synchronous first: the reference.
    TakePointer atOnce;
    {
        auto executor = std::make_shared<ManualExecutor>();
        Document document;
        AnalysisController analysis(document, nullptr, executor);
        document.setCorpus(analysis::synth::generateDemoCorpus().corpus, QStringLiteral("demo"));
        executor->drain();
        setEmotionWeight(document, 2.0);
        executor->drain();
        atOnce = analysis.weightedTake();
        REQUIRE(atOnce);
        CHECK(analysis.scheduler().starts(AnalysisController::kWeightedSlot) == 0);
    }
    // Every take counts as long: the weighted take waits for its job.
    auto executor = std::make_shared<ManualExecutor>();
    Document document;
    AnalysisController analysis(document, nullptr, executor);
    analysis.setBackgroundBodyFrames(0);
    std::vector<double> progress;
    QObject::connect(&analysis.scheduler(), &StageScheduler::progressChanged, [&](int slot, double fraction) {
        if (slot == AnalysisController::kWeightedSlot) progress.push_back(fraction);
    });
    document.setCorpus(analysis::synth::generateDemoCorpus().corpus, QStringLiteral("demo"));
    executor->drain();
    const int starts = analysis.scheduler().starts(AnalysisController::kWeightedSlot);
    CHECK(starts >= 1);
    setEmotionWeight(document, 2.0);
    // Asked for, not yet made: the weight change returned without computing the take.
    REQUIRE(executor->pending() == 1);
    CHECK(analysis.scheduler().state(AnalysisController::kWeightedSlot) == SlotState::Running);
    CHECK(analysis.weightedTake() != nullptr); // the previous weight's take is still shown
    CHECK(analysis.weightedTake()->labels.source.find("a = 2") == std::string::npos);
    executor->drain();
    CHECK(analysis.scheduler().starts(AnalysisController::kWeightedSlot) == starts + 1);
    REQUIRE(analysis.weightedTake());
    CHECK(document.take(app::TakeId::live(QStringLiteral("weighted"))) == analysis.weightedTake());
    CHECK(analysis.weightedTake()->values == atOnce->values);
    CHECK(analysis.weightedTake()->labels.source == atOnce->labels.source);
    REQUIRE(document.perChannelGhostOf(app::TakeId::live(QStringLiteral("weighted"))));
    CHECK_FALSE(progress.empty());
    CHECK(std::find_if(progress.begin(), progress.end(), [](double f) { return f >= 0.5 && f < 1.0; }) != progress.end());
}

TEST_CASE("a changed tau recomputes normalisation and what depends on it, nothing upstream", "[app][scheduler][normalise]")
{
    auto executor = std::make_shared<ManualExecutor>();
    Document document;
    AnalysisController analysis(document, nullptr, executor);
    document.setCorpus(analysis::synth::generateDemoCorpus().corpus, QStringLiteral("demo"));
    executor->drain();
    auto& scheduler = analysis.scheduler();
    REQUIRE(analysis.axes());
    const auto oldNormalised = analysis.normalised();

    changeStageParameters(document, [](AnalysisParameters& p) { p.normalise.tau = 5; }, QStringLiteral("tau"));
    // The old normalisation stays shown until the new one arrives; it is no longer current.
    CHECK(analysis.normalised() == oldNormalised);
    CHECK_FALSE(analysis.isCurrent(AnalysisController::kNormaliseSlot));
    executor->drain();
    CHECK(scheduler.starts(AnalysisController::kPreprocessSlot) == 1);
    CHECK(scheduler.starts(AnalysisController::kNormaliseSlot) == 2);
    CHECK(scheduler.starts(AnalysisController::kDecomposeSlot) == 2);
    CHECK(scheduler.starts(AnalysisController::kAxesSlot) == 2);
    CHECK(analysis.normalised() != oldNormalised);

    changeStageParameters(document, [](AnalysisParameters& p) { p.decompose.correlationLength = 2; }, QStringLiteral("M"));
    executor->drain();
    CHECK(scheduler.starts(AnalysisController::kNormaliseSlot) == 2);
    CHECK(scheduler.starts(AnalysisController::kAxesSlot) == 2);
    CHECK(scheduler.starts(AnalysisController::kDecomposeSlot) == 3);
    CHECK(analysis.decomposed()->km2o->correlationLength == 2);

    // A normalisation that changes again before its job runs: the first job's result is never shown.
    changeStageParameters(document, [](AnalysisParameters& p) { p.normalise.tau = 6; }, QStringLiteral("tau"));
    const auto stale = analysis.normalised();
    changeStageParameters(document, [](AnalysisParameters& p) { p.normalise.tau = 3; }, QStringLiteral("tau"));
    executor->runNext(); // the tau = 6 job (cancelled: it stops at its first check)
    CHECK(analysis.normalised() == stale);
    executor->drain();
    REQUIRE(analysis.normalised() != stale);
    CHECK(analysis.isCurrent(AnalysisController::kNormaliseSlot));
    CHECK(scheduler.key(AnalysisController::kNormaliseSlot) == analysis.keys().normalise);
}

TEST_CASE("the scheduler's cache is the stages' own: each stage runs once, the report and an undo find them there",
          "[app][scheduler][cache]")
{
    namespace pl = analysis::pipeline;
    auto executor = std::make_shared<ManualExecutor>();
    Document document;
    AnalysisController analysis(document, nullptr, executor);
    document.setCorpus(analysis::synth::generateDemoCorpus().corpus, QStringLiteral("demo"));
    executor->drain();
    pl::StageCache& cache = analysis.scheduler().cache();
    // The stage functions counted their runs in the scheduler's cache: it is theirs.
    for (pl::Stage stage : {pl::Stage::Preprocess, pl::Stage::Normalise, pl::Stage::Decompose, pl::Stage::Axes}) {
        INFO(pl::stageName(stage));
        CHECK(cache.runs(stage) == 1);
        CHECK(cache.find<void>(stage, analysis.keys().of(stage)));
    }
    CHECK(cache.find<pl::NormaliseOutput>(pl::Stage::Normalise, analysis.keys().normalise) == analysis.normalised());
    // The report runs the whole chain on the GUI thread: every stage the jobs ran is found, only
    // the fluctuations (no slot) are computed.
    REQUIRE(analysis.reportHtml());
    CHECK(cache.runs(pl::Stage::Normalise) == 1);
    CHECK(cache.runs(pl::Stage::Decompose) == 1);
    CHECK(cache.runs(pl::Stage::Fluctuations) == 1);
    // A changed tau and its undo: the first normalisation comes back from the cache, no job.
    auto& scheduler = analysis.scheduler();
    const auto first = analysis.normalised();
    changeStageParameters(document, [](AnalysisParameters& p) { p.normalise.tau = 5; }, QStringLiteral("tau"));
    executor->drain();
    CHECK(cache.runs(pl::Stage::Normalise) == 2);
    const int starts = scheduler.starts(AnalysisController::kNormaliseSlot);
    document.undoStack()->undo();
    executor->drain();
    CHECK(analysis.normalised() == first);
    CHECK(scheduler.starts(AnalysisController::kNormaliseSlot) == starts);
    CHECK(cache.runs(pl::Stage::Normalise) == 2);
}

TEST_CASE("slots asking for one key share one job and its result", "[app][scheduler]")
{
    auto executor = std::make_shared<ManualExecutor>();
    StageScheduler scheduler(nullptr, executor);
    std::vector<bool> stopped;
    auto watching = [&](int value) {
        return [&stopped, value](const analysis::RunControl& control) -> analysis::Result<StageValue> {
            stopped.push_back(control.cancelled());
            return StageValue(std::make_shared<const int>(value));
        };
    };
    std::vector<int> finished;
    QObject::connect(&scheduler, &StageScheduler::finished, [&](int slot) { finished.push_back(slot); });
    scheduler.request(1, StageKey{7}, watching(7));
    scheduler.request(2, StageKey{7}, watching(70)); // the same key while slot 1 computes it: no second job
    CHECK(executor->pending() == 1);
    CHECK(scheduler.state(2) == SlotState::Running);
    scheduler.request(1, StageKey{8}, watching(8)); // slot 1 moves on; slot 2 still waits for key 7
    executor->drain();
    CHECK(stopped == std::vector<bool>{false, false}); // the shared job was not cancelled
    REQUIRE(scheduler.result<int>(2));
    CHECK(*scheduler.result<int>(2) == 7);
    CHECK(*scheduler.result<int>(1) == 8);
    CHECK(scheduler.starts(1) == 2);
    CHECK(scheduler.starts(2) == 0);

    scheduler.request(3, StageKey{8}, watching(80)); // computed by slot 1: from the cache
    CHECK(executor->pending() == 0);
    CHECK(scheduler.result<int>(3) == scheduler.result<int>(1));
    QCoreApplication::processEvents();
    CHECK(std::count(finished.begin(), finished.end(), 3) == 1);

    scheduler.request(1, StageKey{9}, watching(9));
    scheduler.request(2, StageKey{9}, watching(90));
    scheduler.clear(1);
    scheduler.clear(2); // nobody waits for key 9 any more: its job stops
    executor->drain();
    CHECK(stopped.back());
    CHECK(scheduler.result<int>(2) == nullptr);
}

TEST_CASE("the 3D view draws each shown take's motion axis from the scheduler, once per key, never a stale one",
          "[app][scheduler][viewport]")
{
    namespace pl = analysis::pipeline;
    auto executor = std::make_shared<ManualExecutor>();
    Document document;
    AnalysisController analysis(document, nullptr, executor);
    ViewportPanel panel(document, analysis);
    document.setCorpus(analysis::synth::generateDemoCorpus().corpus, QStringLiteral("demo"));
    executor->drain();
    auto& scheduler = analysis.scheduler();
    const int startsA = scheduler.starts(AnalysisController::kTakeAxisSlot);
    const int startsB = scheduler.starts(AnalysisController::kTakeAxisBSlot);
    document.selectTake(TakeSlot::A, TakeId::corpus(1));
    document.selectTake(TakeSlot::B, TakeId::corpus(7));
    const auto takeA = document.selectedTake(TakeSlot::A);
    const auto takeB = document.selectedTake(TakeSlot::B);
    // The takes show at once, their axes once computed.
    REQUIRE(panel.drawnAxes().size() == 2);
    CHECK(panel.drawnAxes()[0] == nullptr);
    CHECK(panel.drawnAxes()[1] == nullptr);
    executor->drain();
    REQUIRE(panel.drawnAxes().size() == 2);
    REQUIRE(panel.drawnAxes()[0]);
    REQUIRE(panel.drawnAxes()[1]);
    // The motion axis of the analysis functions on the default body (thesis 5.2.1).
    const analysis::AxisModel model = analysis::makeAxisModel(analysis::defaultBodyDescription());
    auto truthA = analysis::computeMotionAxis(model, *takeA);
    auto truthB = analysis::computeMotionAxis(model, *takeB);
    REQUIRE(truthA.ok());
    REQUIRE(truthB.ok());
    CHECK(panel.drawnAxes()[0]->coordinates.values == analysis::axisTake(*truthA).values);
    CHECK(panel.drawnAxes()[1]->coordinates.values == analysis::axisTake(*truthB).values);
    REQUIRE(panel.drawnAxes()[1]->world_T_axis.size() == truthB->world_T_axis.size());
    CHECK(panel.drawnAxes()[1]->world_T_axis.back().translation == truthB->world_T_axis.back().translation);
    // Take A's axis is the graphable "axis" take: the same computation.
    REQUIRE(document.take(app::TakeId::live(QStringLiteral("axis"))));
    CHECK(document.take(app::TakeId::live(QStringLiteral("axis")))->values == analysis::axisTake(*truthA).values);
    CHECK(scheduler.starts(AnalysisController::kTakeAxisSlot) == startsA + 1);
    CHECK(scheduler.starts(AnalysisController::kTakeAxisBSlot) == startsB + 1);

    // B shows A's take: its axis is reused, nothing is computed.
    document.selectTake(TakeSlot::B, TakeId::corpus(1));
    CHECK(executor->pending() == 0);
    QCoreApplication::processEvents();
    CHECK(panel.drawnAxes()[1] == panel.drawnAxes()[0]);
    CHECK(scheduler.starts(AnalysisController::kTakeAxisBSlot) == startsB + 1);

    // A changes twice before its first job runs: that job is cancelled and nothing of it drawn.
    document.selectTake(TakeSlot::A, TakeId::corpus(3));
    document.selectTake(TakeSlot::A, TakeId::corpus(4));
    REQUIRE(executor->pending() == 2);
    executor->runNext(); // take 3's axis, no longer wanted
    CHECK(panel.drawnAxes()[0] == nullptr);
    executor->runNext();
    REQUIRE(panel.drawnAxes()[0]);
    auto truth4 = pl::runTakeAxis(*document.selectedTake(TakeSlot::A), {});
    REQUIRE(truth4.ok());
    CHECK(panel.drawnAxes()[0]->coordinates.values == truth4->coordinates.values);
    CHECK(panel.drawnAxes()[0]->coordinates.labels.source == "axis of " + document.selectedTake(TakeSlot::A)->displayName());
    // Back to take 1: computed before, so drawn again without a job.
    document.selectTake(TakeSlot::A, TakeId::corpus(1));
    CHECK(executor->pending() == 0);
    QCoreApplication::processEvents();
    REQUIRE(panel.drawnAxes()[0]);
    CHECK(panel.drawnAxes()[0]->coordinates.values == analysis::axisTake(*truthA).values);
    CHECK(scheduler.starts(AnalysisController::kTakeAxisSlot) == startsA + 3);

    // Other axis parameters: the old axes are not drawn while the new ones are computed.
    changeStageParameters(document, [](AnalysisParameters& p) { p.axis.massSpacing = 2.0; }, QStringLiteral("spacing"));
    QCoreApplication::processEvents();
    CHECK(panel.drawnAxes()[0] == nullptr);
    CHECK(panel.drawnAxes()[1] == nullptr);
    executor->drain();
    REQUIRE(panel.drawnAxes()[0]);
    pl::AxisParameters coarse;
    coarse.massSpacing = 2.0;
    auto truthCoarse = pl::runTakeAxis(*document.selectedTake(TakeSlot::A), coarse);
    REQUIRE(truthCoarse.ok());
    CHECK(panel.drawnAxes()[0]->coordinates.values == truthCoarse->coordinates.values);
    CHECK(panel.drawnAxes()[0] == panel.drawnAxes()[1]); // A and B show one take: one job for both
    CHECK(scheduler.starts(AnalysisController::kTakeAxisSlot) + scheduler.starts(AnalysisController::kTakeAxisBSlot) ==
          startsA + 4 + startsB + 1);
}

TEST_CASE("destroying the scheduler does not wait for a job that ignores cancellation", "[app][scheduler]")
{
    auto executor = std::make_shared<ManualExecutor>();
    bool ran = false;
    bool stopRequested = false;
    auto scheduler = std::make_unique<StageScheduler>(nullptr, executor);
    scheduler->request(1, StageKey{7}, [&](const analysis::RunControl& control) -> analysis::Result<StageValue> {
        stopRequested = control.cancelled(); // a long step that never checks would run on regardless
        ran = true;
        return StageValue(std::make_shared<const int>(1));
    });
    REQUIRE(executor->pending() == 1);
    scheduler.reset(); // the window closing while its job is under way
    CHECK_FALSE(ran);  // the destructor returned without running or waiting for the job
    executor->runNext(); // the job ends after its scheduler is gone: told to stop, its result dropped
    CHECK(ran);
    CHECK(stopRequested);
}

TEST_CASE("the 3D view dresses each shown take in its kimono simulated by the scheduler and never in a stale one",
          "[app][scheduler][viewport][kimono]")
{
    auto executor = std::make_shared<ManualExecutor>();
    Document document;
    AnalysisController analysis(document, nullptr, executor);
    ViewportPanel panel(document, analysis);
    document.setCorpus(analysis::synth::generateDemoCorpus().corpus, QStringLiteral("demo"));
    document.selectTake(TakeSlot::A, TakeId::corpus(1));
    document.selectTake(TakeSlot::B, TakeId::corpus(7));
    executor->drain();
    auto& scheduler = analysis.scheduler();
    // Off by default: no cloth is simulated.
    CHECK_FALSE(panel.clothBox()->isChecked());
    CHECK(scheduler.starts(AnalysisController::kKimonoSlot) == 0);
    REQUIRE(panel.drawnKimonos().size() == 2);
    CHECK(panel.drawnKimonos()[0] == nullptr);

    // On: the skinned kimono shows (and the view says so) until the jobs finish.
    panel.clothBox()->setChecked(true);
    CHECK(panel.drawnKimonos()[0] == nullptr);
    CHECK(panel.skeletonGapLabel()->text().contains(QStringLiteral("A: simulating the kimono")));
    CHECK(panel.skeletonGapLabel()->text().contains(QStringLiteral("B: simulating the kimono")));
    executor->drain();
    REQUIRE(panel.drawnKimonos().size() == 2);
    REQUIRE(panel.drawnKimonos()[0]);
    REQUIRE(panel.drawnKimonos()[1]);
    CHECK_FALSE(panel.skeletonGapLabel()->text().contains(QStringLiteral("simulating")));
    // The same cloth as the analysis function on the take and the body it is drawn with.
    const auto takeA = document.selectedTake(TakeSlot::A);
    const auto truth = analysis::simulateKimono(*takeA, analysis::defaultBodyDescription());
    REQUIRE(truth.ok());
    CHECK((panel.drawnKimonos()[0]->points.array() == truth->points.array()).all());
    CHECK(scheduler.starts(AnalysisController::kKimonoSlot) == 1);
    CHECK(scheduler.starts(AnalysisController::kKimonoBSlot) == 1);
    // Take A's measured points are the graphable "kimono" take: the same simulation.
    const auto kimonoTake = document.take(app::TakeId::live(QStringLiteral("kimono")));
    REQUIRE(kimonoTake);
    CHECK(kimonoTake->channelCount() == 18);
    CHECK(kimonoTake->channels.front().name() == "sleeve_right_tip.x");
    CHECK(kimonoTake->values == truth->points);
    CHECK(document.takeLabel(app::TakeId::live(QStringLiteral("kimono"))).startsWith(QStringLiteral("kimono of")));

    // Another take A: its cloth is simulated, the old one never drawn on it.
    document.selectTake(TakeSlot::A, TakeId::corpus(2));
    CHECK(panel.drawnKimonos()[0] == nullptr);
    CHECK(analysis.kimono(TakeSlot::A, takeA) == nullptr);
    executor->drain();
    REQUIRE(panel.drawnKimonos()[0]);
    CHECK(panel.drawnKimonos()[0]->frameCount() == document.selectedTake(TakeSlot::A)->frameCount());

    // Other cloth parameters: simulated again; values out of the documented range refused.
    analysis::ClothParameters heavier = analysis.clothParameters();
    heavier.damping = 3.0;
    REQUIRE(analysis.setClothParameters(heavier).ok());
    CHECK(panel.drawnKimonos()[0] == nullptr);
    executor->drain();
    REQUIRE(panel.drawnKimonos()[0]);
    CHECK(panel.drawnKimonos()[0]->parameters.damping == 3.0);
    analysis::ClothParameters wrong = heavier;
    wrong.damping = -1.0;
    const auto refused = analysis.setClothParameters(wrong);
    REQUIRE_FALSE(refused.ok());
    CHECK(refused.error().message.find("cloth.damping") != std::string::npos);
    CHECK(analysis.clothParameters().damping == 3.0);

    // The design loop: a live take shown as A replaced at every step of a drag (the designed
    // take) shows the skinned kimono at once and its cloth when simulated, never the previous
    // step's.
    auto designed = std::make_shared<analysis::Take>(document.corpus().takes[3]);
    document.setLiveTake(QStringLiteral("designed"), QStringLiteral("designed"), designed);
    document.selectTake(TakeSlot::A, app::TakeId::live(QStringLiteral("designed")));
    executor->drain();
    REQUIRE(panel.drawnKimonos()[0]);
    const auto firstStep = panel.drawnKimonos()[0];
    for (int step = 1; step <= 3; ++step) {
        auto next = std::make_shared<analysis::Take>(*designed);
        next->values.col(12).array() += 2.0 * step; // the arm reaches further forward: another designed motion
        document.setLiveTake(QStringLiteral("designed"), QStringLiteral("designed"), next);
        REQUIRE(document.selectedTake(TakeSlot::A)->values(0, 12) == next->values(0, 12));
        CHECK(panel.drawnKimonos()[0] == nullptr); // the skinned kimono meanwhile
    }
    executor->drain();
    REQUIRE(panel.drawnKimonos()[0]);
    CHECK(panel.drawnKimonos()[0] != firstStep);
    CHECK_FALSE((panel.drawnKimonos()[0]->points.array() == firstStep->points.array()).all());
    const auto lastStep = analysis::simulateKimono(*document.selectedTake(TakeSlot::A), analysis::defaultBodyDescription(), heavier);
    REQUIRE(lastStep.ok());
    CHECK((panel.drawnKimonos()[0]->points.array() == lastStep->points.array()).all());

    // Off again: the jobs are cleared and the skinned kimono drawn.
    panel.clothBox()->setChecked(false);
    CHECK(panel.drawnKimonos()[0] == nullptr);
    CHECK(panel.drawnKimonos()[1] == nullptr);
    CHECK(document.take(app::TakeId::live(QStringLiteral("kimono"))) == nullptr);
}
