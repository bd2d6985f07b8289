#pragma once
// The outcome of one conformance check: passed, or the first failures in words. Checks return it
// instead of asserting, so that any test framework (this kit's doctest suite, an example plugin's
// own) can run them.
#include <sstream>
#include <string>

namespace lightpath::conformance {

struct CheckResult {
    bool passed = true;
    std::string failures;  // one line per failure, at most kMaxLines of them
    int failureCount = 0;

    static constexpr int kMaxLines = 5;

    // Records a failure; returns false, so a check can `return result.fail(...)` in a predicate.
    template <typename... Parts>
    bool fail(const Parts&... parts) {
        passed = false;
        if (++failureCount <= kMaxLines) {
            std::ostringstream line;
            (line << ... << parts);
            failures += line.str() + "\n";
        }
        return false;
    }
    void merge(const CheckResult& other) {
        if (other.passed) return;
        passed = false;
        if (failureCount < kMaxLines) failures += other.failures;
        failureCount += other.failureCount;
    }
};

}  // namespace lightpath::conformance
