#pragma once
// Worker threads whose exceptions reach the caller. An exception escaping a std::jthread's function
// calls std::terminate (in `serve` that takes the server down), so each worker runs inside a
// catch-all that keeps the first exception and tells the others to stop; the caller rethrows it once
// every worker has joined.
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace lightpath {

class WorkerErrors {
public:
    // Runs f(), keeping what it throws if it is the first.
    template <typename F>
    void capture(const F& f) noexcept {
        try {
            f();
        } catch (...) {
            const std::lock_guard lock(mutex_);
            if (!first_) first_ = std::current_exception();
            failed_.store(true, std::memory_order_relaxed);
        }
    }
    // A worker threw: the others should stop at their next check (one relaxed load).
    bool failed() const { return failed_.load(std::memory_order_relaxed); }
    void rethrow() const {
        if (first_) std::rethrow_exception(first_);
    }

private:
    std::atomic<bool> failed_{false};
    std::mutex mutex_;
    std::exception_ptr first_;
};

// Runs work(0) on the calling thread and work(1) ... work(count - 1) on their own threads, joins
// them, and rethrows the first exception any of them threw. Workers see errors.failed() once one
// has thrown, and should stop.
template <typename Work>
void runWorkers(unsigned count, WorkerErrors& errors, const Work& work) {
    {
        std::vector<std::jthread> helpers;
        helpers.reserve(count > 0 ? count - 1 : 0);
        for (unsigned w = 1; w < count; ++w) helpers.emplace_back([&errors, &work, w] { errors.capture([&] { work(w); }); });
        errors.capture([&] { work(0u); });
    }
    errors.rethrow();
}

}  // namespace lightpath
