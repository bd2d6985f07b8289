#pragma once
// A progress bar on stderr for long renders: tiles done, elapsed time and an estimate of the time
// left. It appears only when stderr is a terminal and the render has run for a second, redraws a
// few times a second from its own thread (workers only bump a counter) and erases itself at the end.
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>

namespace lightpath {

// Steps done out of a total, read by another thread while they are counted: serve shows
// radiosity's solve as a fraction of it (the bar below draws only on a terminal).
struct StepCounter {
    std::atomic<int> done{0};
    std::atomic<int> total{0};
};

class ProgressBar {
public:
    // `enabled` false (e.g. --quiet) or stderr not a terminal: does nothing at all. `unit` names
    // what is counted ("tiles" of a render, "radiosity steps" of a solve). `counter`, if given,
    // counts the same steps for a reader elsewhere, whether or not the bar is drawn.
    ProgressBar(int totalTiles, bool enabled, const char* unit = "tiles", StepCounter* counter = nullptr);
    ~ProgressBar();
    ProgressBar(const ProgressBar&) = delete;
    ProgressBar& operator=(const ProgressBar&) = delete;

    void tileDone() {
        done_.fetch_add(1, std::memory_order_relaxed);
        if (counter_) counter_->done.fetch_add(1, std::memory_order_relaxed);
    }

private:
    void run();
    void draw(double elapsedSeconds) const;

    const int total_;
    const char* unit_;
    StepCounter* const counter_;
    alignas(64) std::atomic<int> done_{0};  // bumped by every worker: a cache line of its own
    alignas(64) std::chrono::steady_clock::time_point started_;  // (the drawing thread's data from here)
    std::mutex mutex_;
    std::condition_variable wake_;
    bool stopping_ = false;
    bool drawn_ = false;
    std::thread thread_;
};

}  // namespace lightpath
