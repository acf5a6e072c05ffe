#include "analysis/core/parallel.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

namespace bunraku::analysis {

int resolveThreads(int requested)
{
    if (requested <= 0) requested = int(std::max(1u, std::thread::hardware_concurrency()));
    return std::clamp(requested, 1, kMaxThreads);
}

Status parallelFor(std::size_t count, int threads, const std::function<Status(std::size_t)>& body, std::stop_token stop)
{
    std::atomic<std::size_t> next{0};
    std::atomic<std::size_t> completed{0};
    std::atomic<bool> failed{false};
    std::mutex mutex;
    std::size_t failedIndex = count;
    std::optional<Error> error;
    std::exception_ptr exception;

    auto work = [&] {
        while (!failed.load(std::memory_order_relaxed) && !stop.stop_requested()) {
            const std::size_t index = next.fetch_add(1);
            if (index >= count) return;
            std::optional<Error> itemError;
            std::exception_ptr itemException;
            try {
                Status status = body(index);
                if (!status.ok()) itemError = status.error();
            } catch (...) {
                itemException = std::current_exception();
            }
            completed.fetch_add(1);
            if (itemError || itemException) {
                const std::lock_guard lock(mutex);
                if (index < failedIndex) {
                    failedIndex = index;
                    error = std::move(itemError);
                    exception = itemException;
                }
                failed = true;
            }
        }
    };

    const std::size_t workers = std::min<std::size_t>(std::size_t(resolveThreads(threads)), count);
    {
        std::vector<std::jthread> helpers;
        for (std::size_t k = 1; k < workers; ++k) helpers.emplace_back(work);
        work();
    } // joins the helpers
    if (exception) std::rethrow_exception(exception);
    if (error) return *error;
    if (completed.load() < count) return makeError(ErrorCode::Cancelled, "cancelled");
    return okStatus();
}

} // namespace bunraku::analysis
