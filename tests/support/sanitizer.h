#pragma once
// Whether this test binary runs under AddressSanitizer: the sanitizer tree of scripts/test's
// second stage (CMakePresets.json, preset "sanitize"), where every instruction costs several times
// its Release cost. A few tests draw many random cases to find a logic error rarely hit; the
// Release stage runs them all and proves that. Under the sanitizers the same code is run for its
// memory errors and undefined behaviour, which the first cases already reach: those tests run one
// case in kSanitizedDivisor there. Likewise a few exact checks (counts, bit-identity) whose size
// (a radiosity mesh's elements) only makes them slow. One constant for every such test, seen in
// one place.
namespace lightpath::test {

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define LIGHTPATH_TEST_SANITIZED 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)  // GCC's name for the same
#define LIGHTPATH_TEST_SANITIZED 1
#endif

#ifdef LIGHTPATH_TEST_SANITIZED
inline constexpr bool kSanitized = true;
#else
inline constexpr bool kSanitized = false;
#endif

// The sanitizer stage runs one in this many of such a test's random cases or elements (all in Release).
inline constexpr int kSanitizedDivisor = kSanitized ? 5 : 1;

// `count` random cases (or elements), or the first count / kSanitizedDivisor of them under the sanitizers.
constexpr int sanitizedCount(int count) { return count / kSanitizedDivisor; }

}  // namespace lightpath::test
