#include "analysis/core/parallel.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <atomic>
#include <mutex>
#include <numeric>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

using namespace bunraku::analysis;

TEST_CASE("parallelFor runs every item once on up to the threads asked for", "[core][parallel]")
{
    const int threads = GENERATE(1, 2, 3, 8);
    const std::size_t count = GENERATE(0u, 1u, 7u, 1000u);
    std::vector<int> runs(count, 0);
    std::mutex mutex;
    std::set<std::thread::id> workers;
    const Status status = parallelFor(count, threads, [&](std::size_t i) -> Status {
        ++runs[i]; // each index once: no two threads share a slot
        const std::lock_guard lock(mutex);
        workers.insert(std::this_thread::get_id());
        return okStatus();
    });
    REQUIRE(status.ok());
    REQUIRE(std::all_of(runs.begin(), runs.end(), [](int n) { return n == 1; }));
    REQUIRE(workers.size() <= std::size_t(threads));
    if (threads == 1 && count > 0) REQUIRE(*workers.begin() == std::this_thread::get_id());
}

TEST_CASE("parallelFor with one thread runs the items in order on the calling thread", "[core][parallel]")
{
    std::vector<std::size_t> order;
    REQUIRE(parallelFor(5, 1, [&](std::size_t i) -> Status {
                order.push_back(i);
                return okStatus();
            }).ok());
    REQUIRE(order == std::vector<std::size_t>{0, 1, 2, 3, 4});
}

TEST_CASE("parallelFor returns the error of the lowest failing item and rethrows exceptions", "[core][parallel]")
{
    const int threads = GENERATE(1, 2, 4);
    const Status status = parallelFor(50, threads, [](std::size_t i) -> Status {
        if (i == 17 || i == 31) return makeError(ErrorCode::Numerical, "item " + std::to_string(i));
        return okStatus();
    });
    REQUIRE_FALSE(status.ok());
    // Items start in index order and every started item finishes, so 17 has failed whenever 31
    // did: the lowest failing index is reported whatever the threads' timing.
    REQUIRE(status.error().message == "item 17");
    REQUIRE(status.error().code == ErrorCode::Numerical);
    REQUIRE_THROWS_AS(parallelFor(10, threads,
                                  [](std::size_t i) -> Status {
                                      if (i == 3) throw std::runtime_error("three");
                                      return okStatus();
                                  }),
                      std::runtime_error);
}

TEST_CASE("parallelFor stops starting items once stopped and says it was cancelled", "[core][parallel]")
{
    std::stop_source stop;
    std::atomic<int> started{0};
    const Status status = parallelFor(
        1000, 2,
        [&](std::size_t i) -> Status {
            ++started;
            if (i == 10) stop.request_stop();
            return okStatus();
        },
        stop.get_token());
    REQUIRE_FALSE(status.ok());
    REQUIRE(status.error().code == ErrorCode::Cancelled);
    REQUIRE(started.load() < 1000);
    REQUIRE(resolveThreads(0) >= 1);
    REQUIRE(resolveThreads(3) == 3);
    REQUIRE(resolveThreads(100000) == kMaxThreads);
}
