#include "scene/shapes/Cylinder.h"

#include <algorithm>
#include <cmath>

#include "scene/shapes/QuadricMath.h"

namespace bxdflab {

using quadric::solveQuadratic;
using quadric::sweepRadians;

Cylinder::Cylinder(float radius, float zmin, float zmax, float thetaMaxDegrees, Mat4 const& toWorld, bool reverse)
    : Quadric(toWorld, reverse),
      m_radius(radius),
      m_zMin(std::min(zmin, zmax)),
      m_zMax(std::max(zmin, zmax)),
      m_phiMax(sweepRadians(thetaMaxDegrees)) {}

std::optional<Quadric::LocalHit> Cylinder::intersectLocal(DVec3 const& o, DVec3 const& d, double tnear,
                                                          double tfar) const {
    double a = d.x * d.x + d.y * d.y;
    if (a == 0.0) return std::nullopt;
    double t0, t1;
    if (!solveQuadratic(a, 2.0 * (o.x * d.x + o.y * d.y), o.x * o.x + o.y * o.y - m_radius * m_radius, t0, t1))
        return std::nullopt;
    for (double t : {t0, t1}) {
        if (t <= tnear || t >= tfar) continue;
        DVec3 p = o + t * d;
        double phi = azimuth(p.x, p.y);
        if (p.z < m_zMin || p.z > m_zMax || phi > m_phiMax) continue;
        double height = m_zMax - m_zMin;
        double v = height > 0.0 ? (p.z - m_zMin) / height : 0.0;
        return LocalHit{t, static_cast<float>(phi / m_phiMax), static_cast<float>(v)};
    }
    return std::nullopt;
}

Quadric::LocalSurface Cylinder::surfaceLocal(float u, float v) const {
    double phi = u * m_phiMax;
    double cosPhi = std::cos(phi), sinPhi = std::sin(phi);
    DVec3 p(m_radius * cosPhi, m_radius * sinPhi, m_zMin + v * (m_zMax - m_zMin));
    LocalSurface s;
    s.P = Vec3(p);
    s.N = Vec3(static_cast<float>(cosPhi), static_cast<float>(sinPhi), 0.0f);
    s.dPdu = Vec3(-m_phiMax * p.y, m_phiMax * p.x, 0.0);
    s.dPdv = Vec3(0.0f, 0.0f, static_cast<float>(m_zMax - m_zMin));
    return s;
}

void Cylinder::boundsLocal(Vec3& lower, Vec3& upper) const {
    float r = static_cast<float>(m_radius);
    lower = Vec3(-r, -r, static_cast<float>(m_zMin));
    upper = Vec3(r, r, static_cast<float>(m_zMax));
}

}  // namespace bxdflab
