#include "stats/ChiSquared.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace bxdflab {
namespace {

// Regularised lower incomplete gamma P(a, x) by its power series, and the
// upper Q(a, x) by Lentz's continued fraction; each where it converges fast.
double lowerGammaSeries(double a, double x) {
    double term = 1.0 / a, sum = term;
    for (int n = 1; n < 1000; ++n) {
        term *= x / (a + n);
        sum += term;
        if (std::fabs(term) < std::fabs(sum) * 1e-15) break;
    }
    return sum * std::exp(-x + a * std::log(x) - std::lgamma(a));
}

double upperGammaFraction(double a, double x) {
    const double tiny = 1e-300;
    double b = x + 1.0 - a, c = 1.0 / tiny, d = 1.0 / b, h = d;
    for (int i = 1; i < 1000; ++i) {
        double an = -i * (i - a);
        b += 2.0;
        d = an * d + b;
        if (std::fabs(d) < tiny) d = tiny;
        c = b + an / c;
        if (std::fabs(c) < tiny) c = tiny;
        d = 1.0 / d;
        double delta = d * c;
        h *= delta;
        if (std::fabs(delta - 1.0) < 1e-15) break;
    }
    return std::exp(-x + a * std::log(x) - std::lgamma(a)) * h;
}

}  // namespace

double chiSquaredSurvival(double x, double dof) {
    if (x <= 0.0) return 1.0;
    double a = 0.5 * dof, half = 0.5 * x;
    return half < a + 1.0 ? 1.0 - lowerGammaSeries(a, half) : upperGammaFraction(a, half);
}

ChiSquaredResult chiSquaredTest(std::vector<double> const& observed, std::vector<double> const& expected) {
    ChiSquaredResult result;
    // Cells expecting fewer than 5 are pooled; a pool that still expects fewer
    // than 5 joins the smallest regular cell, so no term has a tiny denominator.
    double pooledObserved = 0.0, pooledExpected = 0.0;
    std::vector<std::pair<double, double>> terms;  // (observed, expected)
    for (size_t i = 0; i < observed.size(); ++i) {
        if (expected[i] <= 0.0) {
            result.impossibleSamples += static_cast<long>(observed[i]);
            continue;
        }
        if (expected[i] < 5.0) {
            pooledObserved += observed[i];
            pooledExpected += expected[i];
            continue;
        }
        terms.emplace_back(observed[i], expected[i]);
    }
    if (pooledExpected > 0.0) {
        if (pooledExpected >= 5.0 || terms.empty()) {
            terms.emplace_back(pooledObserved, pooledExpected);
        } else {
            auto smallest = std::min_element(terms.begin(), terms.end(),
                                             [](auto const& a, auto const& b) { return a.second < b.second; });
            smallest->first += pooledObserved;
            smallest->second += pooledExpected;
        }
    }
    for (auto const& [o, e] : terms) result.statistic += (o - e) * (o - e) / e;
    result.degreesOfFreedom = static_cast<int>(terms.size()) - 1;
    result.pValue = result.degreesOfFreedom > 0 ? chiSquaredSurvival(result.statistic, result.degreesOfFreedom) : 1.0;
    return result;
}

double sidak(double alpha, int tests) { return 1.0 - std::pow(1.0 - alpha, 1.0 / tests); }

}  // namespace bxdflab
