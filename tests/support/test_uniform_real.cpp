// test::UniformReal draws the numbers std::uniform_real_distribution draws (support/uniform_real.h):
// the tests that use it keep their numbers, so their statistics and their verdicts.
#include <doctest/doctest.h>

#include <cstring>
#include <random>

#include "uniform_real.h"

namespace lightpath {
namespace {

// How many of `count` draws differ in a bit, and whether the engines are left in one state.
template <typename Real, typename Engine>
int differences(Real a, Real b, typename Engine::result_type seed, int count) {
    Engine reference(seed), ours(seed);
    std::uniform_real_distribution<Real> standard(a, b);
    const test::UniformReal<Real> replica(a, b);
    int differ = 0;
    for (int i = 0; i < count; ++i) {
        const Real x = standard(reference), y = replica(ours);
        differ += std::memcmp(&x, &y, sizeof x) != 0;
    }
    return differ + (reference() != ours());
}

}  // namespace

TEST_CASE("uniform_real: the very numbers of std::uniform_real_distribution, float and double, mt19937 and mt19937_64") {
    constexpr int kDraws = 200000;
    CHECK(differences<float, std::mt19937_64>(0.0f, 1.0f, 99, kDraws) == 0);
    CHECK(differences<float, std::mt19937_64>(-1.1f, 1.1f, 3, kDraws) == 0);
    CHECK(differences<float, std::mt19937_64>(0.0f, 6.2831853f, 5, kDraws) == 0);
    CHECK(differences<double, std::mt19937_64>(0.0, 1.0, 7, kDraws) == 0);
    CHECK(differences<double, std::mt19937>(0.0, 1.0, 11, kDraws) == 0);
    CHECK(differences<float, std::mt19937>(0.05f, 1.0f, 13, kDraws) == 0);
}

}  // namespace lightpath
