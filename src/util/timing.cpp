#include "util/timing.h"

#include <algorithm>
#include <ctime>

namespace lightpath {

double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    const std::size_t mid = values.size() / 2;
    return values.size() % 2 == 1 ? values[mid] : 0.5 * (values[mid - 1] + values[mid]);
}

double processCpuSeconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

double threadCpuSeconds() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

std::vector<double> medianSeconds(const std::vector<std::function<void()>>& jobs, int repetitions) {
    std::vector<std::vector<double>> times(jobs.size());
    for (int r = 0; r < repetitions; ++r) {
        for (std::size_t j = 0; j < jobs.size(); ++j) {
            const double start = processCpuSeconds();
            jobs[j]();
            times[j].push_back(processCpuSeconds() - start);
        }
    }
    std::vector<double> medians;
    for (auto& t : times) medians.push_back(median(std::move(t)));
    return medians;
}

}  // namespace lightpath
