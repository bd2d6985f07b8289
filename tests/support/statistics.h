#pragma once
// Hypothesis tests for Monte Carlo estimates, the way Nori's ttest and chi2test judge a renderer:
// a p-value against a closed form instead of a loose tolerance.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace lightpath::test {

// Regularised incomplete beta I_x(a, b) by Lentz's continued fraction (Numerical Recipes 6.4).
inline double incompleteBeta(double a, double b, double x) {
    if (x <= 0.0) return 0.0;
    if (x >= 1.0) return 1.0;
    if (x > (a + 1.0) / (a + b + 2.0)) return 1.0 - incompleteBeta(b, a, 1.0 - x);
    const double front = std::exp(std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) + a * std::log(x) + b * std::log(1.0 - x)) / a;
    constexpr double kTiny = 1e-300;
    double f = 1.0, c = 1.0, d = 0.0;
    for (int i = 0; i <= 400; ++i) {
        const int m = i / 2;
        double numerator;
        if (i == 0) numerator = 1.0;
        else if (i % 2 == 0) numerator = (m * (b - m) * x) / ((a + 2.0 * m - 1.0) * (a + 2.0 * m));
        else numerator = -((a + m) * (a + b + m) * x) / ((a + 2.0 * m) * (a + 2.0 * m + 1.0));
        d = 1.0 + numerator * d;
        d = 1.0 / (std::fabs(d) < kTiny ? kTiny : d);
        c = 1.0 + numerator / (std::fabs(c) < kTiny ? kTiny : c);
        const double cd = c * d;
        f *= cd;
        if (std::fabs(1.0 - cd) < 1e-12) break;
    }
    return front * (f - 1.0);
}

// Regularised upper incomplete gamma Q(a, x) (Numerical Recipes 6.2): series or continued fraction.
inline double upperIncompleteGamma(double a, double x) {
    if (x <= 0.0) return 1.0;
    const double logFront = -x + a * std::log(x) - std::lgamma(a);
    if (x < a + 1.0) {
        double sum = 1.0 / a, term = sum;
        for (int n = 1; n < 1000; ++n) {
            term *= x / (a + n);
            sum += term;
            if (std::fabs(term) < std::fabs(sum) * 1e-14) break;
        }
        return 1.0 - sum * std::exp(logFront);
    }
    constexpr double kTiny = 1e-300;
    double b = x + 1.0 - a, c = 1.0 / kTiny, d = 1.0 / b, h = d;
    for (int i = 1; i < 1000; ++i) {
        const double an = -i * (i - a);
        b += 2.0;
        d = an * d + b;
        d = 1.0 / (std::fabs(d) < kTiny ? kTiny : d);
        c = b + an / c;
        if (std::fabs(c) < kTiny) c = kTiny;
        const double delta = d * c;
        h *= delta;
        if (std::fabs(delta - 1.0) < 1e-14) break;
    }
    return std::exp(logFront) * h;
}

// Two-sided p-value of Student's t-test that the samples' mean equals `expected`. The variance is
// floored at float rounding (relative 1e-6 of the expected value): an estimator that happens to
// have no variance would otherwise be judged on its last bits.
inline double studentTTest(const std::vector<double>& samples, double expected) {
    const double n = static_cast<double>(samples.size());
    double mean = 0.0;
    for (double s : samples) mean += s;
    mean /= n;
    double variance = 0.0;
    for (double s : samples) variance += (s - mean) * (s - mean);
    variance /= (n - 1.0);
    const double roundingFloor = 1e-6 * std::fabs(expected);
    variance = std::max(variance, roundingFloor * roundingFloor);
    if (variance == 0.0) return mean == expected ? 1.0 : 0.0;
    const double t = (mean - expected) / std::sqrt(variance / n);
    const double dof = n - 1.0;
    return incompleteBeta(dof / 2.0, 0.5, dof / (dof + t * t));
}

// Two-sided p-value of Welch's t-test that two estimates have the same expectation, from their
// means, sample variances and sample counts. Variances are floored at float rounding (relative
// 1e-5 of the larger mean), so two deterministic estimates are compared on more than their last bits.
inline double welchTTest(double meanA, double varianceA, double countA, double meanB, double varianceB, double countB) {
    const double roundingFloor = 1e-5 * std::max(std::fabs(meanA), std::fabs(meanB));
    const double a = std::max(varianceA, roundingFloor * roundingFloor) / countA;
    const double b = std::max(varianceB, roundingFloor * roundingFloor) / countB;
    if (a + b == 0.0) return meanA == meanB ? 1.0 : 0.0;
    const double t = (meanA - meanB) / std::sqrt(a + b);
    // Welch-Satterthwaite degrees of freedom.
    const double dof = (a + b) * (a + b) / (a * a / (countA - 1.0) + b * b / (countB - 1.0));
    return incompleteBeta(dof / 2.0, 0.5, dof / (dof + t * t));
}

// p-value of Pearson's chi-square statistic with `dof` degrees of freedom.
inline double chiSquarePValue(double statistic, double dof) { return upperIncompleteGamma(dof / 2.0, statistic / 2.0); }

}  // namespace lightpath::test
