// The statistical tests must themselves be right before they judge the renderer: checked against
// tabulated values.
#include <doctest/doctest.h>

#include "../support/statistics.h"

namespace lightpath::test {

TEST_CASE("incomplete gamma and beta against tabulated chi-square and t quantiles") {
    // chi-square: P(X > 3.841) = 0.05 for 1 dof; P(X > 18.307) = 0.05 for 10 dof.
    CHECK(chiSquarePValue(3.841458820694124, 1) == doctest::Approx(0.05).epsilon(1e-6));
    CHECK(chiSquarePValue(18.307038053275146, 10) == doctest::Approx(0.05).epsilon(1e-6));
    CHECK(chiSquarePValue(124.3421134, 100) == doctest::Approx(0.05).epsilon(1e-5));
    // Student t two-sided: |T| > 2.228 with 10 dof has p = 0.05.
    const double t = 2.2281388519649385, dof = 10;
    CHECK(incompleteBeta(dof / 2, 0.5, dof / (dof + t * t)) == doctest::Approx(0.05).epsilon(1e-6));
}

TEST_CASE("the t-test accepts a true mean and rejects a shifted one") {
    std::vector<double> samples;
    for (int i = 0; i < 1000; ++i) samples.push_back((i % 10) * 0.1);  // mean 0.45
    CHECK(studentTTest(samples, 0.45) > 0.5);
    CHECK(studentTTest(samples, 0.45 * 1.1) < 1e-6);
}

}  // namespace lightpath::test
