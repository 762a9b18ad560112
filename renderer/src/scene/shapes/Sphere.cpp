#include "scene/shapes/Sphere.h"

#include <algorithm>
#include <cmath>

#include "scene/shapes/QuadricMath.h"

namespace bxdflab {

using quadric::solveQuadratic;

Sphere::Sphere(float radius, float zmin, float zmax, float thetaMaxDegrees, Mat4 const& toWorld, bool reverse)
    : Quadric(toWorld, reverse, thetaMaxDegrees), m_radius(radius) {
    m_zMin = std::clamp(static_cast<double>(std::min(zmin, zmax)), -m_radius, m_radius);
    m_zMax = std::clamp(static_cast<double>(std::max(zmin, zmax)), -m_radius, m_radius);
    m_thetaZMin = std::acos(m_zMin / m_radius);
    m_thetaZMax = std::acos(m_zMax / m_radius);
    m_whole = m_zMin <= -m_radius && m_zMax >= m_radius && phiMax() >= quadric::kTwoPi;
}

bool Sphere::hitsLocal(DVec3 const& o, DVec3 const& d, double tnear, double tfar) const {
    // A whole sphere refuses no point of its surface, so a shadow ray needs none
    // of the angles (acos, atan2) that (u, v) cost; the same answer as intersectLocal's.
    if (!m_whole) return Quadric::hitsLocal(o, d, tnear, tfar);
    double t0, t1;
    if (!solveQuadratic(glm::dot(d, d), 2.0 * glm::dot(o, d), glm::dot(o, o) - m_radius * m_radius, t0, t1)) return false;
    return (t0 > tnear && t0 < tfar) || (t1 > tnear && t1 < tfar);
}

std::optional<Quadric::LocalHit> Sphere::intersectLocal(DVec3 const& o, DVec3 const& d, double tnear,
                                                        double tfar) const {
    double t0, t1;
    if (!solveQuadratic(glm::dot(d, d), 2.0 * glm::dot(o, d), glm::dot(o, o) - m_radius * m_radius, t0, t1))
        return std::nullopt;
    return firstRoot(t0, t1, tnear, tfar, [&](double t) -> std::optional<Uv> {
        DVec3 p = o + t * d;
        p *= m_radius / glm::length(p);  // reproject onto the surface
        if (p.x == 0.0 && p.y == 0.0) p.x = 1e-9 * m_radius;
        if ((m_zMin > -m_radius && p.z < m_zMin) || (m_zMax < m_radius && p.z > m_zMax)) return std::nullopt;
        double theta = std::acos(std::clamp(p.z / m_radius, -1.0, 1.0));
        double v = (theta - m_thetaZMin) / (m_thetaZMax - m_thetaZMin);
        return swept(azimuth(p.x, p.y), std::clamp(v, 0.0, 1.0));
    });
}

Quadric::LocalSurface Sphere::surfaceLocal(float u, float v) const {
    double phi = u * phiMax();
    double theta = m_thetaZMin + v * (m_thetaZMax - m_thetaZMin);
    double sinTheta = std::sin(theta), cosTheta = std::cos(theta);
    double cosPhi = std::cos(phi), sinPhi = std::sin(phi);
    return surfaceAt(DVec3(m_radius * sinTheta * cosPhi, m_radius * sinTheta * sinPhi, m_radius * cosTheta), cosPhi,
                     sinPhi);
}

Quadric::LocalSurface Sphere::surfaceAtHit(HitRecord const& hit) const {
    // The hit point put back on the sphere: no trigonometry, and as exact as
    // the point evaluated from (u, v).
    DVec3 p = hitPointLocal(hit);
    double length = glm::length(p);
    if (!(length > 0.0)) return surfaceLocal(hit.u, hit.v);
    p *= m_radius / length;
    double rho = std::sqrt(p.x * p.x + p.y * p.y);
    if (!(rho > 0.0)) {  // a pole: the azimuth is u's
        double phi = hit.u * phiMax();
        return surfaceAt(p, std::cos(phi), std::sin(phi));
    }
    return surfaceAt(p, p.x / rho, p.y / rho);
}

Quadric::LocalSurface Sphere::surfaceAt(DVec3 const& p, double cosPhi, double sinPhi) const {
    double sinTheta = std::sqrt(p.x * p.x + p.y * p.y) / m_radius;
    LocalSurface s;
    s.P = Vec3(p);
    s.N = Vec3(p / m_radius);
    s.dPdu = sweepTangent(p);
    s.dPdv = Vec3((m_thetaZMax - m_thetaZMin) * DVec3(p.z * cosPhi, p.z * sinPhi, -m_radius * sinTheta));
    return s;
}

void Sphere::boundsLocal(Vec3& lower, Vec3& upper) const {
    float r = static_cast<float>(m_radius);
    lower = Vec3(-r, -r, static_cast<float>(m_zMin));
    upper = Vec3(r, r, static_cast<float>(m_zMax));
}

}  // namespace bxdflab
