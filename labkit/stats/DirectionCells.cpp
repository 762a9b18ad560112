#include "stats/DirectionCells.h"

#include <algorithm>
#include <cmath>

namespace bxdflab {

int DirectionCells::cellOf(Vec3 const& w) const {
    double z = w.z;
    if (!std::isfinite(z) || z < zMin() || z > 1.0) return -1;
    if (!fullSphere && z <= 0.0) return -1;
    int c = std::min(cosCells - 1, static_cast<int>((z - zMin()) / (1.0 - zMin()) * cosCells));
    double phi = std::atan2(static_cast<double>(w.y), static_cast<double>(w.x));
    if (phi < 0) phi += 2 * M_PI;
    int p = std::min(phiCells - 1, static_cast<int>(phi / (2 * M_PI) * phiCells));
    return c * phiCells + p;
}

void DirectionCells::bounds(int cell, double& z0, double& z1, double& phi0, double& phi1) const {
    int c = cell / phiCells, p = cell % phiCells;
    double dz = (1.0 - zMin()) / cosCells, dphi = 2 * M_PI / phiCells;
    z0 = zMin() + c * dz;
    z1 = z0 + dz;
    phi0 = p * dphi;
    phi1 = phi0 + dphi;
}

Vec3 directionAt(double z, double phi) {
    double s = std::sqrt(std::max(0.0, 1.0 - z * z));
    return Vec3(static_cast<float>(s * std::cos(phi)), static_cast<float>(s * std::sin(phi)), static_cast<float>(z));
}

namespace {

// Three-point Gauss-Legendre nodes and weights on [-1, 1].
constexpr double kNodes[3] = {-0.7745966692414834, 0.0, 0.7745966692414834};
constexpr double kWeights[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};

struct Rect {
    double z0, z1, phi0, phi1;
    int cell, depth;
    double whole;  ///< the rule's estimate over the whole rectangle
};

Rect quadrant(Rect const& r, int k) {
    double zm = 0.5 * (r.z0 + r.z1), pm = 0.5 * (r.phi0 + r.phi1);
    Rect q = r;
    (k & 1 ? q.z0 : q.z1) = zm;
    (k & 2 ? q.phi0 : q.phi1) = pm;
    q.depth = r.depth + 1;
    return q;
}

void appendNodes(Rect const& r, std::vector<Vec3>& points) {
    double zc = 0.5 * (r.z0 + r.z1), zh = 0.5 * (r.z1 - r.z0);
    double pc = 0.5 * (r.phi0 + r.phi1), ph = 0.5 * (r.phi1 - r.phi0);
    for (double a : kNodes)
        for (double b : kNodes) points.push_back(directionAt(zc + zh * a, pc + ph * b));
}

double rule(Rect const& r, double const* values) {
    double sum = 0.0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            double v = values[3 * i + j];
            sum += kWeights[i] * kWeights[j] * (std::isfinite(v) ? v : 0.0);
        }
    return sum * 0.25 * (r.z1 - r.z0) * (r.phi1 - r.phi0);
}

}  // namespace

std::vector<double> integrateCells(DirectionCells const& cells, BatchPdf const& pdf,
                                   std::function<double(double)> const& tolerance, int maxDepth) {
    std::vector<double> result(static_cast<size_t>(cells.count()), 0.0);
    // Level 0: the rule over each whole cell.
    std::vector<Rect> level;
    std::vector<Vec3> points;
    for (int c = 0; c < cells.count(); ++c) {
        Rect r{};
        cells.bounds(c, r.z0, r.z1, r.phi0, r.phi1);
        r.cell = c;
        level.push_back(r);
        appendNodes(r, points);
    }
    std::vector<double> values = pdf(points);
    for (size_t k = 0; k < level.size(); ++k) level[k].whole = rule(level[k], &values[9 * k]);

    // Each level: the rule over the four quadrants of every open rectangle;
    // a rectangle whose split agrees with its whole is done.
    while (!level.empty()) {
        std::vector<Rect> children;
        points.clear();
        for (Rect const& r : level)
            for (int k = 0; k < 4; ++k) {
                children.push_back(quadrant(r, k));
                appendNodes(children.back(), points);
            }
        values = pdf(points);
        std::vector<Rect> next;
        for (size_t k = 0; k < level.size(); ++k) {
            double split = 0.0;
            for (int q = 0; q < 4; ++q) {
                Rect& child = children[4 * k + static_cast<size_t>(q)];
                child.whole = rule(child, &values[9 * (4 * k + static_cast<size_t>(q))]);
                split += child.whole;
            }
            Rect const& r = level[k];
            if (std::fabs(split - r.whole) <= tolerance(std::fabs(split)) || r.depth + 1 >= maxDepth) {
                result[static_cast<size_t>(r.cell)] += split;
            } else {
                for (int q = 0; q < 4; ++q) next.push_back(children[4 * k + static_cast<size_t>(q)]);
            }
        }
        level = std::move(next);
    }
    return result;
}

void integrateEmptyCellsFinely(DirectionCells const& cells, std::vector<double> const& observed, BatchPdf const& pdf,
                               std::vector<double>& mass, int resolution, std::vector<Vec3> const* examples) {
    for (size_t cell = 0; cell < mass.size(); ++cell) {
        if (mass[cell] != 0.0 || !(observed[cell] > 0.0)) continue;
        double z0, z1, phi0, phi1;
        cells.bounds(static_cast<int>(cell), z0, z1, phi0, phi1);
        std::vector<Vec3> points;
        for (int i = 0; i < resolution; ++i)
            for (int j = 0; j < resolution; ++j)
                points.push_back(directionAt(z0 + (z1 - z0) * (i + 0.5) / resolution,
                                             phi0 + (phi1 - phi0) * (j + 0.5) / resolution));
        double sum = 0.0;
        for (double v : pdf(points)) sum += std::isfinite(v) ? v : 0.0;
        double const nodeShare = (z1 - z0) * (phi1 - phi0) / (static_cast<double>(resolution) * resolution);
        mass[cell] = sum * nodeShare;
        if (mass[cell] == 0.0 && examples) {
            double const atDraw = pdf({(*examples)[cell]}).front();
            if (std::isfinite(atDraw) && atDraw > 0.0) mass[cell] = atDraw * nodeShare;
        }
    }
}

std::function<double(double)> toleranceForSamples(double samples) {
    // A cell holding probability mass m expects samples*m draws, with noise
    // sqrt(samples*m): its probability need be known to 0.05 sqrt(m / samples).
    return [samples](double mass) { return 0.05 * std::sqrt(std::max(mass, 1.0 / samples) / samples); };
}

}  // namespace bxdflab
