// The chi-squared goodness-of-fit test, for checking sampled directions
// against the pdf a Bxdf declares.
#pragma once

#include <vector>

namespace bxdflab {

/// P(X >= x) for X chi-squared with `dof` degrees of freedom (the test's p-value).
double chiSquaredSurvival(double x, double dof);

struct ChiSquaredResult {
    double statistic = 0.0;
    int degreesOfFreedom = 0;
    double pValue = 1.0;
    /// Observed samples in cells the pdf says are impossible.
    long impossibleSamples = 0;
};

/// Pearson's test of observed counts against expected counts. Cells with an
/// expected count below 5 are pooled together (the approximation needs it).
ChiSquaredResult chiSquaredTest(std::vector<double> const& observed, std::vector<double> const& expected);

/// The per-test significance that keeps the family-wise level `alpha` over
/// `tests` independent tests (Sidak's correction).
double sidak(double alpha, int tests);

}  // namespace bxdflab
