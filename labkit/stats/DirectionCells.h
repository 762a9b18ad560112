// Cells of equal solid angle over the hemisphere (or the sphere), in
// (cos theta, phi) about a frame's z axis: the bins of every chi-squared test
// of sampled directions. Because dw = d(cos theta) dphi, a cell's probability
// is the integral of the pdf over a rectangle in (cos theta, phi), which
// integrateCells computes adaptively to an accuracy set by the sample count.
#pragma once

#include <functional>
#include <vector>

#include "core/Math.h"

namespace bxdflab {

struct DirectionCells {
    int cosCells = 16, phiCells = 32;
    bool fullSphere = false;  ///< false: z > 0 only (reflection)

    int count() const { return cosCells * phiCells; }
    double zMin() const { return fullSphere ? -1.0 : 0.0; }
    /// The cell of a unit local direction, or -1 when it lies outside (below the horizon).
    int cellOf(Vec3 const& w) const;
    /// A cell's rectangle in (z = cos theta, phi).
    void bounds(int cell, double& z0, double& z1, double& phi0, double& phi1) const;
};

/// The unit direction at (z = cos theta, phi).
Vec3 directionAt(double z, double phi);

/// pdf of a batch of local unit directions (per unit solid angle).
using BatchPdf = std::function<std::vector<double>(std::vector<Vec3> const&)>;

/// The pdf's integral over every cell. Each cell is integrated with a 3 x 3
/// Gauss-Legendre rule and split into four until the split changes the
/// estimate by less than `tolerance(estimate)` (or after maxDepth splits).
/// Evaluations are batched level by level.
std::vector<double> integrateCells(DirectionCells const& cells, BatchPdf const& pdf,
                                   std::function<double(double)> const& tolerance, int maxDepth = 7);

/// Cells whose adaptive integral came out zero although samples fell in them
/// are integrated again by the midpoint rule on a fine grid (resolution^2
/// points): the pdf may be non-zero only in a sliver of such a cell (the edge of
/// the directions a refraction can reach, a geometric horizon tilted across the
/// cell) that every node of the rule missed. Where even the fine grid finds
/// nothing and `examples` gives a draw that fell in the cell, the pdf at that
/// draw decides: non-zero there, the cell gets one grid node's share of mass
/// (a sliver thinner than the grid); zero, the draw is where the pdf says none can be.
void integrateEmptyCellsFinely(DirectionCells const& cells, std::vector<double> const& observed, BatchPdf const& pdf,
                               std::vector<double>& mass, int resolution = 64,
                               std::vector<Vec3> const* examples = nullptr);

/// For a chi-squared test on `samples` draws: splitting stops when the cell's
/// error is below a twentieth of the sampling noise of its count.
std::function<double(double)> toleranceForSamples(double samples);

}  // namespace bxdflab
