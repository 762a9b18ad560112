// Where a Bxdf's GenerateSample sends directions, against where its FPdf
// says they should go: both binned over equal-area cells of the hemisphere
// (cos(theta) x phi). The chi-squared test, the sample-vs-pdf viewer and the
// autograder all start from this.
#pragma once

#include <vector>

#include "probe/BxdfProbe.h"
#include "probe/ChiSquared.h"

namespace bxdflab {

struct SamplingHistogram {
    int cosCells = 0, phiCells = 0;  ///< cell (c, p) is index c * phiCells + p
    std::vector<double> observed;    ///< valid samples per cell
    std::vector<double> expected;    ///< FPdf integrated over each cell, scaled to the valid samples
    double pdfIntegral = 0.0;        ///< FPdf integrated over the hemisphere (1, or less when samples can be rejected)
    long samples = 0;
    long validSamples = 0;
    long nonFiniteSamples = 0;       ///< valid samples with a NaN/infinite direction or pdf
    ChiSquaredResult test() const { return chiSquaredTest(observed, expected); }
};

/// Draws `samples` independent directions at `point` (with the given seed)
/// and integrates FPdf over each cell with sub x sub points per cell.
SamplingHistogram sampleHistogram(BxdfProbe& probe, ProbePoint const& point, int samples, int cosCells = 16,
                                  int phiCells = 32, int sub = 12, uint32_t seed = 7u);

}  // namespace bxdflab
