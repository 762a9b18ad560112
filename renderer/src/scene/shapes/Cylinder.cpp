#include "scene/shapes/Cylinder.h"

#include <algorithm>
#include <cmath>

#include "scene/shapes/QuadricMath.h"

namespace bxdflab {

using quadric::solveQuadratic;

Cylinder::Cylinder(float radius, float zmin, float zmax, float thetaMaxDegrees, Mat4 const& toWorld, bool reverse)
    : Quadric(toWorld, reverse, thetaMaxDegrees),
      m_radius(radius),
      m_zMin(std::min(zmin, zmax)),
      m_zMax(std::max(zmin, zmax)) {}

std::optional<Quadric::LocalHit> Cylinder::intersectLocal(DVec3 const& o, DVec3 const& d, double tnear,
                                                          double tfar) const {
    double a = d.x * d.x + d.y * d.y;
    if (a == 0.0) return std::nullopt;
    double t0, t1;
    if (!solveQuadratic(a, 2.0 * (o.x * d.x + o.y * d.y), o.x * o.x + o.y * o.y - m_radius * m_radius, t0, t1))
        return std::nullopt;
    return firstRootBetweenHeights(t0, t1, tnear, tfar, o, d, m_zMin, m_zMax);
}

Quadric::LocalSurface Cylinder::surfaceLocal(float u, float v) const {
    double phi = u * phiMax();
    double cosPhi = std::cos(phi), sinPhi = std::sin(phi);
    DVec3 p(m_radius * cosPhi, m_radius * sinPhi, m_zMin + v * (m_zMax - m_zMin));
    LocalSurface s;
    s.P = Vec3(p);
    s.N = Vec3(static_cast<float>(cosPhi), static_cast<float>(sinPhi), 0.0f);
    s.dPdu = sweepTangent(p);
    s.dPdv = Vec3(0.0f, 0.0f, static_cast<float>(m_zMax - m_zMin));
    return s;
}

void Cylinder::boundsLocal(Vec3& lower, Vec3& upper) const {
    boundsOfRevolution(m_radius, m_zMin, m_zMax, lower, upper);
}

}  // namespace bxdflab
