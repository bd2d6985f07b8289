#pragma once
// std::uniform_real_distribution as libstdc++ computes it, number for number, without its cost
// under clang: libstdc++'s std::generate_canonical takes log2 of the engine's range with two calls
// of std::log on long double at every draw, which GCC folds and clang does not. In the sanitizer
// build (clang) that was a quarter of conformance/materials' weight check, more than the materials
// themselves. Here the number of engine calls per draw is a constant; the arithmetic is
// libstdc++'s (bits/random.tcc, generate_canonical; bits/random.h, uniform_real_distribution), so
// every test draws the very numbers it drew before (test_uniform_real.cpp holds them equal).
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <limits>

namespace lightpath::test {

// generate_canonical<Real, digits of Real>(engine), for an engine of 0 to 2^bits - 1 (mt19937,
// mt19937_64).
template <typename Real, typename Engine>
Real generateCanonical(Engine& engine) {
    static_assert(Engine::min() == 0 && (Engine::max() & (Engine::max() + 1)) == 0, "a range of 2^bits");
    constexpr std::size_t bits = std::bit_width(Engine::max());  // log2 of the range
    constexpr std::size_t calls = std::max<std::size_t>(1, (std::numeric_limits<Real>::digits + bits - 1) / bits);
    constexpr long double range = static_cast<long double>(Engine::max()) + 1.0L;
    Real sum = Real(0), scale = Real(1);
    for (std::size_t k = calls; k != 0; --k) {
        sum += Real(engine()) * scale;
        scale *= range;
    }
    Real result = sum / scale;
    if (result >= Real(1)) result = std::nextafter(Real(1), Real(0));
    return result;
}

// A drop-in for std::uniform_real_distribution<Real>(a, b): uniform on [a, b).
template <typename Real>
class UniformReal {
public:
    UniformReal(Real a, Real b) : a_(a), b_(b) {}
    template <typename Engine>
    Real operator()(Engine& engine) const {
        return generateCanonical<Real>(engine) * (b_ - a_) + a_;
    }

private:
    Real a_, b_;
};

}  // namespace lightpath::test
