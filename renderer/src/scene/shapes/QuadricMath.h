// Helpers the quadrics share: a cancellation-free quadratic solver and the
// sweep angle of a partial quadric.
#pragma once

#include <algorithm>
#include <cmath>
#include <utility>

namespace bxdflab::quadric {

constexpr double kTwoPi = 6.283185307179586;

/// Both roots of a t^2 + b t + c = 0 in increasing order, computed without
/// cancellation (the "citardauq" form); false when there is no real root.
inline bool solveQuadratic(double a, double b, double c, double& t0, double& t1) {
    if (a == 0.0) {
        if (b == 0.0) return false;
        t0 = t1 = -c / b;
        return true;
    }
    double discriminant = b * b - 4.0 * a * c;
    if (discriminant < 0.0) return false;
    double root = std::sqrt(discriminant);
    double q = b < 0.0 ? -0.5 * (b - root) : -0.5 * (b + root);
    t0 = q / a;
    t1 = q != 0.0 ? c / q : t0;
    if (t0 > t1) std::swap(t0, t1);
    return true;
}

inline double sweepRadians(float degrees) { return std::clamp(static_cast<double>(degrees), 0.0, 360.0) * kTwoPi / 360.0; }

}  // namespace bxdflab::quadric
