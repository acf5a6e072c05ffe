// The scheduler and the analysis controller with a manual executor: jobs run when the test says,
// on the test's thread, and results arrive through the event loop - no wall-clock windows.
#include "app/analysis_controller.h"
#include "app/commands.h"
#include "app/document.h"
#include "app/stage_scheduler.h"

#include "analysis/synth/demo_corpus.h"

#include <catch2/catch.hpp>

#include <QCoreApplication>

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
