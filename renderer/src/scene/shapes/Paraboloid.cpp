#include "scene/shapes/Paraboloid.h"

#include <algorithm>
#include <cmath>

#include "scene/shapes/QuadricMath.h"

namespace bxdflab {

using quadric::solveQuadratic;

Paraboloid::Paraboloid(float rmax, float zmin, float zmax, float thetaMaxDegrees, Mat4 const& toWorld, bool reverse)
    : Quadric(toWorld, reverse, thetaMaxDegrees),
      m_rmax(rmax),
      m_zMin(std::min(zmin, zmax)),
      m_zMax(std::max(zmin, zmax)) {}

std::optional<Quadric::LocalHit> Paraboloid::intersectLocal(DVec3 const& o, DVec3 const& d, double tnear,
                                                            double tfar) const {
    double k = m_zMax / (m_rmax * m_rmax);  // k (x^2 + y^2) = z
    double t0, t1;
    if (!solveQuadratic(k * (d.x * d.x + d.y * d.y), 2.0 * k * (o.x * d.x + o.y * d.y) - d.z,
                        k * (o.x * o.x + o.y * o.y) - o.z, t0, t1))
        return std::nullopt;
    return firstRootBetweenHeights(t0, t1, tnear, tfar, o, d, m_zMin, m_zMax);
}

Quadric::LocalSurface Paraboloid::surfaceLocal(float u, float v) const {
    double phi = u * phiMax(), cosPhi = std::cos(phi), sinPhi = std::sin(phi);
    double z = m_zMin + v * (m_zMax - m_zMin);
    double rho = m_rmax * std::sqrt(std::max(0.0, z / m_zMax));
    DVec3 p(rho * cosPhi, rho * sinPhi, z);
    LocalSurface s;
    s.P = Vec3(p);
    s.dPdu = sweepTangent(p);
    // d rho / dz = rho / (2 z); at the tip (z = 0) the tangent is horizontal.
    double slope = z > 1e-12 ? 0.5 / z : 0.0;
    s.dPdv = Vec3((m_zMax - m_zMin) * DVec3(p.x * slope, p.y * slope, 1.0));
    // Outward normal of k rho^2 - z = 0: (2 k x, 2 k y, -1), flipped to point away from the axis.
    double k = m_zMax / (m_rmax * m_rmax);
    s.N = safeNormalize(Vec3(DVec3(2.0 * k * p.x, 2.0 * k * p.y, -1.0)));
    return s;
}

void Paraboloid::boundsLocal(Vec3& lower, Vec3& upper) const {
    boundsOfRevolution(m_rmax, m_zMin, m_zMax, lower, upper);
}

}  // namespace bxdflab
