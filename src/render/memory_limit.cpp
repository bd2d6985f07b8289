#include "render/memory_limit.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <string>

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

// The first number in a file, if it holds one ("max" in cgroup v2 means no limit).
std::optional<std::uint64_t> numberIn(const std::string& path) {
    std::ifstream file(path);
    std::uint64_t value = 0;
    if (file >> value) return value;
    return std::nullopt;
}

// A container's memory limit less its current use, from the process's own group in
// /proc/self/cgroup: cgroup v2 ("0::PATH": memory.max, memory.current) or v1's memory controller
// ("N:memory:PATH": memory.limit_in_bytes, memory.usage_in_bytes). A shared CI runner or a
// container often has far less than the machine's physical memory. "No limit" reads as "max" (v2)
// or a huge number (v1), which the physical memory then undercuts.
std::optional<std::uint64_t> cgroupHeadroom() {
    std::ifstream groups("/proc/self/cgroup");
    std::string line;
    std::optional<std::uint64_t> limit, used;
    while (std::getline(groups, line)) {
        const std::size_t first = line.find(':'), second = line.find(':', first + 1);
        if (first == std::string::npos || second == std::string::npos) continue;
        const std::string controllers = line.substr(first + 1, second - first - 1);
        const std::string path = line.substr(second + 1);
        if (line.rfind("0::", 0) == 0) {
            const std::string dir = "/sys/fs/cgroup" + path;
            if (auto bytes = numberIn(dir + "/memory.max")) limit = bytes, used = numberIn(dir + "/memory.current");
        } else if (controllers == "memory") {
            const std::string dir = "/sys/fs/cgroup/memory" + path;
            if (auto bytes = numberIn(dir + "/memory.limit_in_bytes"))
                limit = bytes, used = numberIn(dir + "/memory.usage_in_bytes");
        }
        if (limit) break;
    }
    if (!limit) return std::nullopt;
    const std::uint64_t current = used.value_or(0);
    return *limit > current ? *limit - current : 0;
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
    consider(cgroupHeadroom(), "the container's memory limit (its cgroup)");
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
