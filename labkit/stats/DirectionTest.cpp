#include "stats/DirectionTest.h"

#include <cmath>
#include <cstdio>

namespace bxdflab {

void DirectionCounts::add(bool valid, Vec3 const& local, float pdf) {
    ++total;
    if (!valid) {
        ++invalid;
        return;
    }
    float length = glm::length(local);
    if (!isFinite(local) || !std::isfinite(pdf) || !(length > 0.0f)) {
        ++nonFinite;
        return;
    }
    int cell = cells.cellOf(local / length);
    if (cell < 0) {
        ++outside;
        return;
    }
    auto const index = static_cast<size_t>(cell);
    if (observed[index] == 0.0) example[index] = local / length;
    observed[index] += 1.0;
}

DirectionTestResult testDirections(DirectionCounts const& counts, std::vector<double> const& cellMass) {
    DirectionTestResult result;
    double const n = static_cast<double>(counts.total);
    std::vector<double> observed = counts.observed, expected(cellMass.size());
    for (size_t i = 0; i < cellMass.size(); ++i) {
        expected[i] = n * cellMass[i];
        result.pdfMass += cellMass[i];
    }
    // The draws that are not valid directions carry the pdf's missing mass.
    observed.push_back(static_cast<double>(counts.invalid));
    expected.push_back(n * std::max(0.0, 1.0 - result.pdfMass));
    result.chi = chiSquaredTest(observed, expected);
    result.impossible = result.chi.impossibleSamples + counts.outside;

    // The cell furthest from its expectation, in standard deviations.
    double worst = 0.0;
    int worstIndex = -1;
    for (size_t i = 0; i + 1 < observed.size(); ++i) {
        double sigma = std::sqrt(std::max(expected[i], 1.0));
        double z = std::fabs(observed[i] - expected[i]) / sigma;
        if (z > worst) {
            worst = z;
            worstIndex = static_cast<int>(i);
        }
    }
    if (worstIndex >= 0) {
        double z0, z1, phi0, phi1;
        counts.cells.bounds(worstIndex, z0, z1, phi0, phi1);
        char text[256];
        std::snprintf(text, sizeof text,
                      "the cell theta %.0f-%.0f deg, phi %.0f-%.0f deg got %.0f samples where the pdf expects %.1f",
                      std::acos(std::min(1.0, z1)) * 180 / M_PI, std::acos(std::max(-1.0, z0)) * 180 / M_PI,
                      phi0 * 180 / M_PI, phi1 * 180 / M_PI, observed[static_cast<size_t>(worstIndex)],
                      expected[static_cast<size_t>(worstIndex)]);
        result.worstCell = text;
    }
    return result;
}

}  // namespace bxdflab
