#pragma once
// Small pieces of Monte Carlo estimation the statistical tests share: a sample's mean and variance,
// and directions uniform over the sphere drawn with the tests' own generator (independent of the
// renderer's samplers and warps).
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "math/types.h"
#include "uniform_real.h"

namespace lightpath::test {

struct Moments {
    double mean = 0.0, variance = 0.0, count = 0.0;  // variance: the unbiased sample variance
};

inline Moments momentsOf(const std::vector<double>& values) {
    Moments m;
    m.count = double(values.size());
    for (double v : values) m.mean += v / m.count;
    for (double v : values) m.variance += (v - m.mean) * (v - m.mean) / (m.count - 1.0);
    return m;
}

// A unit direction uniform over the sphere (Archimedes: z uniform in [-1, 1]).
inline Vec3 uniformSphereDirection(std::mt19937_64& rng) {
    test::UniformReal<float> uniform(0.0f, 1.0f);
    const float z = 2.0f * uniform(rng) - 1.0f, phi = 2.0f * kPi * uniform(rng);
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    return {r * std::cos(phi), r * std::sin(phi), z};
}

}  // namespace lightpath::test
