#pragma once
// Timing for benchmarks on a shared, noisy machine: configurations are run interleaved (A B A B
// ...) so a burst of load hits all of them alike, each is summarised by its median, and the clock
// is the process's CPU time, which other processes' load disturbs far less than wall time.
#include <functional>
#include <vector>

namespace lightpath {

double median(std::vector<double> values);

// CPU seconds used by this process so far (all its threads).
double processCpuSeconds();
// CPU seconds used by the calling thread so far.
double threadCpuSeconds();

// Runs every job `repetitions` times, interleaved; returns each job's median CPU time in seconds.
std::vector<double> medianSeconds(const std::vector<std::function<void()>>& jobs, int repetitions);

}  // namespace lightpath
