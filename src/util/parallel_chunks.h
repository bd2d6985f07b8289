#pragma once
// Runs body(begin, end) over [0, count) in chunks of `grain` items on up to `threads` threads,
// the caller's among them. The chunks depend on count and grain alone, so work that writes only
// its own chunk's results gives the same answer on any number of threads. An exception thrown by
// body on any thread stops the others taking chunks and is rethrown on the caller's (worker_threads.h).
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <thread>

#include "util/worker_threads.h"

namespace lightpath {

// A requested thread count, where 0 (or less) means all the hardware has.
inline unsigned threadsOrAll(long requested) {
    return requested > 0 ? static_cast<unsigned>(requested) : std::max(1u, std::thread::hardware_concurrency());
}

template <typename Body>
void parallelChunks(std::size_t count, std::size_t grain, unsigned threads, const Body& body) {
    const std::size_t chunks = (count + grain - 1) / grain;
    std::atomic<std::size_t> next{0};
    WorkerErrors errors;
    const auto run = [&](unsigned) {
        for (std::size_t chunk; !errors.failed() && (chunk = next.fetch_add(1, std::memory_order_relaxed)) < chunks;)
            body(chunk * grain, std::min(count, (chunk + 1) * grain));
    };
    runWorkers(static_cast<unsigned>(std::clamp<std::size_t>(chunks, 1, std::max(1u, threads))), errors, run);
}

}  // namespace lightpath
