#include "scene/shapes/Cone.h"

#include <algorithm>
#include <cmath>

#include "scene/shapes/QuadricMath.h"

namespace bxdflab {

using quadric::solveQuadratic;

Cone::Cone(float height, float radius, float thetaMaxDegrees, Mat4 const& toWorld, bool reverse)
    : Quadric(toWorld, reverse, thetaMaxDegrees), m_height(height), m_radius(radius) {}

std::optional<Quadric::LocalHit> Cone::intersectLocal(DVec3 const& o, DVec3 const& d, double tnear, double tfar) const {
    // x^2 + y^2 = (r (1 - z/h))^2
    double k = (m_radius / m_height) * (m_radius / m_height);
    double a = d.x * d.x + d.y * d.y - k * d.z * d.z;
    double b = 2.0 * (o.x * d.x + o.y * d.y - k * d.z * (o.z - m_height));
    double c = o.x * o.x + o.y * o.y - k * (o.z - m_height) * (o.z - m_height);
    double t0, t1;
    if (!solveQuadratic(a, b, c, t0, t1)) return std::nullopt;
    return firstRoot(t0, t1, tnear, tfar, [&](double t) -> std::optional<Uv> {
        DVec3 p = o + t * d;
        double v = p.z / m_height;
        if (v < 0.0 || v > 1.0) return std::nullopt;
        return swept(azimuth(p.x, p.y), v);
    });
}

Quadric::LocalSurface Cone::surfaceLocal(float u, float v) const {
    double phi = u * phiMax(), cosPhi = std::cos(phi), sinPhi = std::sin(phi);
    double rho = m_radius * (1.0 - v);
    DVec3 p(rho * cosPhi, rho * sinPhi, v * m_height);
    LocalSurface s;
    s.P = Vec3(p);
    s.dPdu = sweepTangent(p);
    s.dPdv = Vec3(DVec3(-m_radius * cosPhi, -m_radius * sinPhi, m_height));
    // The outward normal does not depend on v (so it is defined at the apex too).
    s.N = safeNormalize(Vec3(DVec3(m_height * cosPhi, m_height * sinPhi, m_radius)));
    return s;
}

void Cone::boundsLocal(Vec3& lower, Vec3& upper) const {
    boundsOfRevolution(m_radius, std::min(0.0, m_height), std::max(0.0, m_height), lower, upper);
}

}  // namespace bxdflab
