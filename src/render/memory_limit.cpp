#include "render/memory_limit.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <fstream>

namespace lightpath {
namespace {

// /proc/self/statm (proc(5)): sizes in pages; field 1 is the address space (VmSize), field 6
// "data" (data + stack), what RLIMIT_AS and RLIMIT_DATA are measured against.
struct Usage {
    std::uint64_t addressSpace = 0, data = 0;
};

Usage currentUsage() {
    std::ifstream statm("/proc/self/statm");
    std::uint64_t size = 0, resident = 0, shared = 0, text = 0, lib = 0, data = 0;
    if (!(statm >> size >> resident >> shared >> text >> lib >> data)) return {};
    const auto page = static_cast<std::uint64_t>(sysconf(_SC_PAGESIZE));
    return {size * page, data * page};
}

// A set soft limit less what is already used; nothing when the limit is not set.
std::optional<std::uint64_t> headroom(int resource, std::uint64_t used) {
    rlimit limit{};
    if (getrlimit(resource, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return std::nullopt;
    const auto bound = static_cast<std::uint64_t>(limit.rlim_cur);
    return bound > used ? bound - used : 0;
}

}  // namespace

MemoryLimit memoryLimit() {
    const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
    MemoryLimit tightest{pages > 0 && page > 0 ? static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(page)
                                               : UINT64_MAX,
                         "physical memory"};
    const Usage used = currentUsage();
    const auto consider = [&](std::optional<std::uint64_t> bytes, const char* bound) {
        if (bytes && *bytes < tightest.bytes) tightest = {*bytes, bound};
    };
    consider(headroom(RLIMIT_AS, used.addressSpace), "the address-space limit (ulimit -v, RLIMIT_AS)");
    consider(headroom(RLIMIT_DATA, used.data), "the data limit (ulimit -d, RLIMIT_DATA)");
    return tightest;
}

std::string formatBytes(std::uint64_t bytes) {
    constexpr double kMiB = 1024.0 * 1024.0, kGiB = 1024.0 * kMiB;
    char text[32];
    if (static_cast<double>(bytes) >= kGiB) std::snprintf(text, sizeof text, "%.1f GiB", static_cast<double>(bytes) / kGiB);
    else std::snprintf(text, sizeof text, "%.1f MiB", static_cast<double>(bytes) / kMiB);
    return text;
}

void refuseBeyondMemory(std::uint64_t bytes, const std::string& what) {
    const MemoryLimit limit = memoryLimit();
    if (bytes <= limit.bytes) return;
    throw MemoryLimitError(what + " needs " + formatBytes(bytes) + ", more than the " + formatBytes(limit.bytes) +
                               " that " + limit.bound + " leaves this process",
                           bytes, limit);
}

}  // namespace lightpath
