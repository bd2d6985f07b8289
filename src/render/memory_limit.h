#pragma once
// How many bytes this process can still get, and the refusal of a render that needs more (issue
// #28): a film larger than the machine's memory or the process's address-space limit (`ulimit -v`)
// is refused before it is allocated, with the amount, instead of ending in std::bad_alloc.
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

namespace lightpath {

struct MemoryLimit {
    std::uint64_t bytes = 0;  // what is left for new allocations under the tightest bound
    std::string bound;        // that bound, for messages: "physical memory", "ulimit -v (RLIMIT_AS)", ...
};

// The tightest of: physical memory; RLIMIT_AS less the address space already mapped; RLIMIT_DATA
// less the data already allocated; a cgroup's memory limit less its use (each limit only when set).
MemoryLimit memoryLimit();

// "22.5 GiB": bytes in GiB with one decimal (MiB below 1 GiB), for messages.
std::string formatBytes(std::uint64_t bytes);

// A render refused because what it would hold exceeds memoryLimit(). An invalid_argument, so
// every caller that turns bad options into exit code 2 (or HTTP 400) does so for this too.
class MemoryLimitError : public std::invalid_argument {
public:
    MemoryLimitError(const std::string& message, std::uint64_t needed, MemoryLimit limit)
        : std::invalid_argument(message), needed(needed), limit(std::move(limit)) {}
    std::uint64_t needed;
    MemoryLimit limit;
};

// Throws MemoryLimitError "<what> needs N GiB, more than the M GiB <bound> leaves" when `bytes`
// exceed memoryLimit().
void refuseBeyondMemory(std::uint64_t bytes, const std::string& what);

}  // namespace lightpath
