#include "app/document.h"
#include "app/recomputer.h"

#include <catch2/catch.hpp>

#include <QTest>
#include <QThreadPool>

#include <atomic>
#include <chrono>
#include <memory>
#include <thread>

using namespace bunraku;
using namespace bunraku::app;

TEST_CASE("rapid requests coalesce into one computation of the latest inputs", "[app][recomputer]")
{
    Document document;
    std::atomic<int> runs{0};
    int input = 0;
    std::vector<int> delivered;
    Recomputer recomputer(
        document,
        [&]() -> Job {
            const int snapshot = input;
            return [&runs, snapshot](const analysis::RunControl&) {
                ++runs;
                return JobOutput{snapshot, {}};
            };
        },
        [&](const JobOutput& output) { delivered.push_back(std::any_cast<int>(output.value)); }, nullptr, 30);
    for (input = 1; input <= 10; ++input) recomputer.schedule();
    REQUIRE(QTest::qWaitFor([&] { return !recomputer.busy(); }, 5000));
    REQUIRE(runs == 1);
    REQUIRE(delivered == std::vector<int>{11});
    REQUIRE(recomputer.state() == Recomputer::State::Finished);
}

TEST_CASE("a newer request cancels the running job and its result is dropped", "[app][recomputer]")
{
    Document document;
    std::atomic<int> cancelledRuns{0};
    int input = 0;
    std::vector<int> delivered;
    Recomputer recomputer(
        document,
        [&]() -> Job {
            const int snapshot = input;
            return [&cancelledRuns, snapshot](const analysis::RunControl& control) {
                // The first job waits until it is cancelled; later ones finish at once.
                while (snapshot == 1 && !control.cancelled()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
                if (control.cancelled()) {
                    ++cancelledRuns;
                    return JobOutput{{}, QStringLiteral("cancelled")};
                }
                return JobOutput{snapshot, {}};
            };
        },
        [&](const JobOutput& output) {
            if (output.value.has_value()) delivered.push_back(std::any_cast<int>(output.value));
        },
        nullptr, 10);
    input = 1;
    recomputer.runNow();
    REQUIRE(recomputer.state() == Recomputer::State::Running);
    input = 2;
    recomputer.runNow();
    REQUIRE(QTest::qWaitFor([&] { return !recomputer.busy() && cancelledRuns == 1; }, 5000));
    REQUIRE(delivered == std::vector<int>{2});
}

TEST_CASE("a result computed from a stale document version is dropped and recomputed", "[app][recomputer]")
{
    Document document;
    std::atomic<bool> release{false};
    quint64 inputVersion = 1;
    std::vector<quint64> delivered;
    Recomputer recomputer(
        document,
        [&]() -> Job {
            const quint64 snapshot = inputVersion;
            return [&release, snapshot](const analysis::RunControl&) {
                while (!release) std::this_thread::sleep_for(std::chrono::milliseconds(1));
                return JobOutput{snapshot, {}};
            };
        },
        [&](const JobOutput& output) { delivered.push_back(std::any_cast<quint64>(output.value)); }, nullptr, 10,
        [&] { return inputVersion; });
    recomputer.runNow();
    inputVersion = 2; // the inputs change while the job runs
    release = true;
    REQUIRE(QTest::qWaitFor([&] { return !delivered.empty() && !recomputer.busy(); }, 5000));
    REQUIRE(delivered == std::vector<quint64>{2});
}

TEST_CASE("cancel stops the running job and delivers nothing", "[app][recomputer]")
{
    Document document;
    std::atomic<bool> sawStop{false};
    int deliveries = 0;
    Recomputer recomputer(
        document,
        [&]() -> Job {
            return [&sawStop](const analysis::RunControl& control) {
                while (!control.cancelled()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
                sawStop = true;
                return JobOutput{{}, QStringLiteral("cancelled")};
            };
        },
        [&](const JobOutput&) { ++deliveries; }, nullptr, 10);
    recomputer.runNow();
    recomputer.cancel();
    REQUIRE(QTest::qWaitFor([&] { return sawStop.load(); }, 5000));
    QTest::qWait(50);
    REQUIRE(deliveries == 0);
    REQUIRE(recomputer.state() == Recomputer::State::Cancelled);
}

TEST_CASE("destroying a recomputer does not wait for a job that ignores cancellation", "[app][recomputer]")
{
    Document document;
    // Shared with the job, which outlives the recomputer (it holds copies of its inputs only).
    auto started = std::make_shared<std::atomic<bool>>(false);
    auto release = std::make_shared<std::atomic<bool>>(false);
    auto finished = std::make_shared<std::atomic<bool>>(false);
    auto recomputer = std::make_unique<Recomputer>(
        document,
        [=]() -> Job {
            return [=](const analysis::RunControl&) { // a long analysis step with no cancellation check
                *started = true;
                for (int i = 0; i < 20000 && !*release; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(1));
                *finished = true;
                return JobOutput{};
            };
        },
        [](const JobOutput&) {}, nullptr, 10);
    recomputer->runNow();
    REQUIRE(QTest::qWaitFor([&] { return started->load(); }, 5000));
    recomputer.reset(); // a panel or the window closing
    CHECK_FALSE(finished->load()); // returned at once, while the job still runs
    *release = true;
    REQUIRE(QThreadPool::globalInstance()->waitForDone(20000));
    CHECK(finished->load());
}
