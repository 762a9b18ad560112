// A chi-squared goodness-of-fit test of sampled directions against the pdf
// that claims to describe them: counts per cell (DirectionCells) against
// samples x the pdf's mass in the cell, plus one category for the draws that
// came back invalid (which the pdf's missing mass must account for).
#pragma once

#include <string>
#include <vector>

#include "stats/ChiSquared.h"
#include "stats/DirectionCells.h"

namespace bxdflab {

struct DirectionCounts {
    explicit DirectionCounts(DirectionCells const& c)
        : cells(c), observed(static_cast<size_t>(c.count()), 0.0), example(observed.size(), Vec3(0.0f)) {}
    DirectionCells cells;
    std::vector<double> observed;  ///< valid samples per cell
    std::vector<Vec3> example;     ///< per cell, the first valid draw that fell there (unit; zero if none)
    long total = 0;       ///< draws
    long invalid = 0;     ///< draws that came back invalid (no direction)
    long outside = 0;     ///< valid draws outside the cells (below the horizon of a reflection model)
    long nonFinite = 0;   ///< valid draws with a non-finite direction or pdf, or a zero direction

    /// One draw: `local` is its direction in the cells' frame (need not be unit).
    void add(bool valid, Vec3 const& local, float pdf);
};

struct DirectionTestResult {
    ChiSquaredResult chi;
    double pdfMass = 0.0;     ///< the pdf's integral over the cells
    long impossible = 0;      ///< valid draws where the pdf is zero (including outside the cells)
    std::string worstCell;    ///< the cell that deviates most, in words
};

DirectionTestResult testDirections(DirectionCounts const& counts, std::vector<double> const& cellMass);

}  // namespace bxdflab
