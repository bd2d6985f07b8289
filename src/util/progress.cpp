#include "util/progress.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <string>

namespace lightpath {
namespace {

constexpr auto kDelay = std::chrono::seconds(1);              // short renders never show a bar
constexpr auto kInterval = std::chrono::milliseconds(250);    // at most four redraws a second
constexpr int kBarWidth = 30;

std::string formatSeconds(double seconds) {
    char text[32];
    if (seconds < 60.0) {
        std::snprintf(text, sizeof text, "%.1f s", seconds);
    } else {
        const int whole = static_cast<int>(seconds);
        std::snprintf(text, sizeof text, "%d:%02d min", whole / 60, whole % 60);
    }
    return text;
}

}  // namespace

ProgressBar::ProgressBar(int totalTiles, bool enabled, const char* unit, StepCounter* counter)
    : total_(std::max(totalTiles, 1)), unit_(unit), counter_(counter), started_(std::chrono::steady_clock::now()) {
    if (counter_) counter_->total.fetch_add(totalTiles, std::memory_order_relaxed);
    if (enabled && isatty(STDERR_FILENO)) thread_ = std::thread([this] { run(); });
}

ProgressBar::~ProgressBar() {
    if (!thread_.joinable()) return;
    {
        const std::lock_guard lock(mutex_);
        stopping_ = true;
    }
    wake_.notify_one();
    thread_.join();
    if (drawn_) std::fputs("\r\033[K", stderr);  // leave the terminal line as it was
}

void ProgressBar::run() {
    std::unique_lock lock(mutex_);
    if (wake_.wait_for(lock, kDelay, [this] { return stopping_; })) return;
    for (;;) {
        draw(std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count());
        drawn_ = true;
        if (wake_.wait_for(lock, kInterval, [this] { return stopping_; })) return;
    }
}

void ProgressBar::draw(double elapsed) const {
    const int done = std::min(done_.load(std::memory_order_relaxed), total_);
    const double fraction = static_cast<double>(done) / total_;
    const int filled = static_cast<int>(fraction * kBarWidth);
    const std::string bar = std::string(static_cast<std::size_t>(filled), '#') +
                            std::string(static_cast<std::size_t>(kBarWidth - filled), '.');
    // The estimate assumes the remaining tiles cost what the finished ones did on average.
    const std::string eta = done > 0 ? formatSeconds(elapsed * (1.0 - fraction) / fraction) : "?";
    std::fprintf(stderr, "\r\033[K[%s] %d/%d %s  %s elapsed  ETA %s", bar.c_str(), done, total_, unit_,
                 formatSeconds(elapsed).c_str(), eta.c_str());
    std::fflush(stderr);
}

}  // namespace lightpath
